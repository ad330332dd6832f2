"""Ant-colony path planning with runtime plugins, from Python.

    import numpy as np, aco
    grid = np.zeros((20, 20), dtype=bool); grid[5:15, 10] = True
    result = aco.plan(grid, (0, 0), (19, 19), update="max_min", update_rho=0.1)
    result.path, result.length, result.gap_percent

Maps: aco.Map (numpy arrays, map files). Runs: aco.plan(), aco.astar(). Plugins: aco.plugins(),
aco.describe(), aco.add_plugin_dir(), aco.presets(); a slot may be a Python object (update=MyUpdate()),
run inside the native colony. Studies: aco.run_experiment(), aco.read_database(); aco.stats has the
report's statistics. Pictures: aco.plot(), plan(svg=...), results and maps show themselves in
Jupyter. Simulation: aco.simulate() (acosim). Errors raise aco.Error (a ValueError) with the command line's message.
"""
from __future__ import annotations

import os
from typing import Union

from . import _aco, stats
from ._pictures import plot
from ._planning import Error, Map, Result, astar, plan
from ._simulation import Simulation, simulate
from ._studies import read_database, run_experiment

__all__ = ["Error", "Map", "Result", "plan", "astar", "plugins", "describe", "add_plugin_dir", "presets",
           "run_experiment", "read_database", "stats", "plot", "simulate", "Simulation"]

_extra_dirs: list = []


def plugins() -> list:
    """Every plugin found: dicts with slot, name, version, summary, file, unusable (why it cannot
    be loaded, or "") and parameters (name, type, default, range, help)."""
    return _aco.plugins()


def describe(name: str) -> str:
    """A plugin's description as ``acoplan --describe SLOT/NAME`` prints it ("update/max_min"; "max_min" alone
    when one slot only has a plugin so called, else aco.Error lists the SLOT/NAME forms)."""
    return _aco.describe(name)


def add_plugin_dir(folder: Union[str, os.PathLike]) -> None:
    """Also searches ``folder`` for plugins (before ACO_PLUGIN_PATH and the default folders), as
    ``acoplan --plugin-dir`` does."""
    _aco.set_plugin_dirs(_extra_dirs + [os.fspath(folder)])
    try:
        _aco.search_dirs()  # a missing folder, or a file given as one, is refused now, not at the next plan
    except Error:
        _aco.set_plugin_dirs(_extra_dirs)
        raise
    _extra_dirs.append(os.fspath(folder))


def presets() -> dict:
    """The named presets (pipelines): name -> the first line of its file."""
    return dict(_aco.presets())
