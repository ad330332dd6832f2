"""The sections: what each replaces and the function that makes it."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Callable

if TYPE_CHECKING:
    from .run import Run


@dataclass
class Section:
    name: str
    estimate: str  # on a quiet 2-core machine
    summary: str
    regions: list[tuple[Path, str]]  # (file, region) it replaces
    make: Callable[[Run], dict[tuple[Path, str], str]]


SECTIONS: dict[str, Section] = {}


def section(name: str, estimate: str, summary: str, regions: list[tuple[Path, str]]):
    def register(make):
        SECTIONS[name] = Section(name, estimate, summary, regions, make)
        return make
    return register
