"""What a run can be made of: the plugins, the presets and the run keys."""
from __future__ import annotations

import os
from typing import Union

from . import _aco
from ._planning import Error

_extra_dirs: list = []
# plan()'s own arguments and the scenario keys, which plan() does not take as run keys.
_NOT_RUN_KEYWORDS = frozenset({"map", "start", "goal", "scen", "scen-index"})


def plugins() -> list:
    """Every plugin found: dicts with slot, name, version, summary, file, unusable (why it cannot
    be loaded, or "") and parameters (name, type, default, range, help; the default an int, float,
    bool or str as the type says)."""
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


def run_keys() -> list:
    """The run keys plan() takes, from the tables acoplan's options come from: dicts with keyword
    (plan()'s spelling: ``update_rho``), key (the run key: ``update.rho``, as in ``keys=`` and
    result.config), group (planner, problem, graph, colony, a baseline planner's name, slot),
    type, default (an int, float, bool or str as the type says), range and help. A slot's plugin
    has keys of its own, "<slot>.<parameter>": see plugins() and describe()."""
    keys = []
    for entry in _aco.run_key_tables():
        if entry["name"] in _NOT_RUN_KEYWORDS:
            continue
        key = entry.pop("name")
        keys.append({"keyword": key.replace(".", "_").replace("-", "_"), "key": key, **entry})
    return keys
