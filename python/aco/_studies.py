"""Studies: run an acobench experiment (a file or a dict), read any results database into pandas."""
from __future__ import annotations

import json
import os
import re
import sys
from typing import Any, Callable, Mapping, Union

import numpy as np

from . import _aco
from ._planning import Error, _check_threads, _LiveObjects, _reworded

Progress = Union[bool, Callable[[int, int], None]]


def _bar(done: int, total: int) -> None:
    width = 40
    filled = width * done // max(total, 1)
    sys.stderr.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} trials")
    if done == total:
        sys.stderr.write("\n")
    sys.stderr.flush()


def run_experiment(experiment: Union[str, os.PathLike, Mapping[str, Any]], database: Union[str, os.PathLike], *,
                   threads: int = 0, progress: Progress = True) -> dict:
    """Runs an acobench experiment into a results database, as ``acobench run`` does: every
    trial the database does not hold yet (call it again to continue), each stored as it ends.
    Trials run in this process, on ``threads`` threads (0 = all cores; results do not depend on
    it); ``acobench run`` also isolates each trial in a worker process.

    experiment  an experiment file (YAML, data/experiments/README.md), or the same as a dict:
                {"name": ..., "problems": [{"map": ..., "start": [x, y], "goal": [x, y]}],
                "configurations": [{"name": ..., "update": "max_min"}], ...}; its relative
                paths start from the current directory. In a dict, a slot of the settings, the
                baseline or a configuration may be a Python object (``"update": MyUpdate()``, as
                in aco.plan()), which runs in this process, one object for all the
                configuration's trials (keep no state between runs, or give the class: each
                trial then makes its own object). An untrusted plugin belongs in acobench's
                worker processes: its module named in an experiment file
                (``update: python, update.class: module:MyUpdate``) run by ``acobench run``.

    progress  True: a progress bar on stderr; False: none; a function f(done, total): called
              after every stored trial.

    Returns a dict: trials, skipped (already stored), ran, seconds; failures: every failed
    trial of the experiment, of this call or stored as failed by an earlier one, each a dict
    (configuration, reason, message, earlier); failures_by_reason: {reason: count}, the reasons
    those of ``acobench run``'s summary ("crashed", "timed out", "out of memory", "plugin error",
    "invalid value", "error"); same_runs: pairs of configuration names that resolve to the same
    run. Failed trials do not raise (they are results: check ``failures``, as ``acobench run``
    exits 3 on them); a bad experiment file, or a database whose stored trials the file would
    now run otherwise, raises aco.Error. Ctrl-C lets the trials running finish and be stored,
    starts no other, and raises KeyboardInterrupt: call again to continue.
    """
    _check_threads(threads)
    callback = _bar if progress is True else (progress or None)
    if not isinstance(experiment, Mapping):
        return _aco.run_experiment(os.fspath(experiment), "", os.fspath(database), int(threads), callback)
    # The dict stands for a file in the current directory (its relative paths start there);
    # messages name it as what it is.
    stand_in = os.path.join(os.getcwd(), "experiment")
    with _LiveObjects() as live, _reworded(lambda m: re.sub(re.escape(stand_in) + r":\d+", "the experiment dict", m)):
        text = json.dumps(_with_live_plugins(experiment, live), default=_json_value)
        return _aco.run_experiment(stand_in, text, os.fspath(database), int(threads), callback)


def _with_live_plugins(experiment: Mapping[str, Any], live: _LiveObjects) -> dict:
    """The experiment with every Python plugin object named by a run key the python plugin reads
    (the same name for the same configuration, so a database continues from call to call)."""
    def keys(entry: Any, name: str) -> Any:
        return live.keys(entry, re.sub(r"\W", "_", name)) if isinstance(entry, Mapping) else entry

    out = dict(experiment)
    for section in ("settings", "baseline"):
        if section in out:
            out[section] = keys(out[section], section)
    if isinstance(out.get("configurations"), list):
        out["configurations"] = [keys(c, f"configuration_{c.get('name')}") for c in out["configurations"]]
    return out


def _json_value(value: Any) -> Any:
    """A value of an experiment dict that json does not know: numpy's numbers and paths."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    raise Error(f"{value!r} in the experiment dict: its values are text, numbers, lists and dicts, and a Python "
                "object only as a slot's plugin of the settings, the baseline or a configuration")


def read_database(database: Union[str, os.PathLike], *, config_columns: bool = True):
    """A results database (``acobench run``'s) as a pandas DataFrame, one row per trial, in the
    order of the report's runs.csv, with the same columns first:

    problem, configuration, repetition, seed, solved, length, grid_length, gap_percent, turns,
    iterations, best_iteration, time_s, ant_steps, stopped_by, peak_memory_mib (MiB, NaN where not
    known: the trial's peak in acobench's worker processes, the process's peak so far in
    run_experiment()'s, which run in this process), one column per further property of
    the runs (the planners' and the plugins' figures, "update/max_min.restarts": NaN where a run
    has none), as runs.csv has them; then the simulation measures (outcome, time_to_goal,
    collisions, replans, clearance, control_steps: None, NaN or -1 for planning trials), error
    (None unless the trial failed), optimal_length, settings (the configuration as stored, JSON)
    and, with
    ``config_columns``, one column ``config.<key>`` per resolved run key of the configuration
    (``config.update``, ``config.update.rho``, ...), to group by.

    length, grid_length and gap_percent are NaN for unsolved trials; gap_percent is
    100 * (grid_length / optimal_length - 1), the report's gap.
    """
    import pandas as pd

    columns = _aco.read_trials(os.fspath(database))
    properties = columns.pop("properties")
    order = columns.pop("csv_columns")
    frame = pd.DataFrame(columns)
    for name in sorted(properties):
        frame[name] = properties[name]
    order += sorted(properties)
    frame = frame[order + [c for c in frame.columns if c not in order]]
    if config_columns and len(frame):
        runs = {settings: json.loads(settings).get("run", {}) for settings in frame["settings"].unique()}
        keys = sorted({key for run in runs.values() for key in run})
        for key in keys:
            frame["config." + key] = frame["settings"].map(lambda s, key=key: runs[s].get(key, np.nan))
    return frame
