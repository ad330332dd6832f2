"""Studies: run an acobench experiment file, read any results database into pandas."""
from __future__ import annotations

import json
import os
import sys
from typing import Callable, Optional, Union

import numpy as np

from . import _aco

Progress = Union[bool, Callable[[int, int], None]]


def _bar(done: int, total: int) -> None:
    width = 40
    filled = width * done // max(total, 1)
    sys.stderr.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} trials")
    if done == total:
        sys.stderr.write("\n")
    sys.stderr.flush()


def run_experiment(file: Union[str, os.PathLike], database: Union[str, os.PathLike], *, threads: int = 0,
                   progress: Progress = True) -> dict:
    """Runs an acobench experiment file into a results database, as ``acobench run`` does:
    every trial the database does not hold yet (call it again to continue), each stored as it
    ends. Trials run in this process, on ``threads`` threads (0 = all cores; results do not
    depend on it); ``acobench run`` also isolates each trial in a worker process.

    progress  True: a progress bar on stderr; False: none; a function f(done, total): called
              after every stored trial.

    Returns a dict: trials, skipped (already stored), ran, seconds; failures: every failed
    trial of the experiment, of this call or stored as failed by an earlier one, each a dict
    (configuration, reason, message, earlier); failures_by_reason: {reason: count}, the reasons
    those of ``acobench run``'s summary ("crashed", "timed out", "out of memory", "plugin error",
    "invalid value", "error"); same_runs: pairs of configuration names that resolve to the same
    run. Failed trials do not raise (they are results: check ``failures``, as ``acobench run``
    exits 3 on them); a bad experiment file, or a database whose stored trials the file would
    now run otherwise, raises aco.Error.
    """
    callback = _bar if progress is True else (progress or None)
    return _aco.run_experiment(os.fspath(file), "", os.fspath(database), int(threads), callback)


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
