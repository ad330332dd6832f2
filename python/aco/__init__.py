"""Ant-colony path planning with runtime plugins, from Python."""
from . import _aco  # noqa: F401
