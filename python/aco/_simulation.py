"""acosim from Python: aco.simulate() drives a robot along the colony's path with a local planner."""
from __future__ import annotations

import json
import os
import re
import tempfile
from typing import Any, Mapping, Optional, Union

import numpy as np

from . import _aco
from ._planning import Error, _given, _keys, _live_names, _LiveObjects

# acosim --csv's columns: the trajectory, one row per control step (the start first).
_TRAJECTORY_COLUMNS = ("t", "x", "y", "heading", "v", "w", "plan", "goal_index")


class Simulation:
    """One simulation, as ``acosim SCENARIO --json`` reports it; map units are cells.

    reached, outcome   whether the robot reached the goal; "reached", "collision", "timeout",
                       "stuck" or "no path"; reason: why, for any other outcome than reached
    time, distance     seconds driven and distance driven
    min_clearance      the robot's smallest distance to an obstacle (None if it saw none)
    collisions, replans, steps   counts; steps: control periods
    trajectory         acosim --csv's columns as numpy arrays: t, x, y, heading (radians), v, w,
                       plan (which plan was followed), goal_index (its intermediate goal);
                       ``pandas.DataFrame(sim.trajectory)`` is the CSV
    moving             the moving obstacles' centres per step, an (steps + 1, k, 2) array
    plans              each global plan's intermediate goals, (n, 2) arrays, the start first
    sensed             the unknown cells the robot saw, an (n, 2) int array
    config, plugins    the resolved run keys and which plugin binary filled each slot
    json               the whole summary

    In Jupyter it shows acosim's picture (``svg()``); ``html()`` is the page that plays the run.
    """

    def __init__(self, native: Any):
        self._native = native
        record = json.loads(native.summary_json())
        self.json = record
        self.scenario: str = record["scenario"]
        self.reached: bool = record["reached"]
        self.outcome: str = record["outcome"]
        self.reason: str = record.get("reason", "")
        self.time: float = record["time"]
        self.distance: float = record["distance"]
        self.min_clearance: Optional[float] = record["min_clearance"]
        self.collisions: int = record["collisions"]
        self.replans: int = record["replans"]
        self.steps: int = record["steps"]
        self.config: dict = record["config"]
        self.plugins: dict = record["plugins"]
        frames = record.get("trajectory", [])
        self.trajectory = {column: np.array([frame[column] for frame in frames]) for column in _TRAJECTORY_COLUMNS}
        self.moving = np.array([frame["moving"] for frame in frames], dtype=np.float64).reshape(len(frames), -1, 2)
        self.plans = [np.array(plan, dtype=np.float64).reshape(-1, 2) for plan in record.get("plans", [])]
        self.sensed = np.array(record["sensed"], dtype=np.int64).reshape(-1, 2)

    def svg(self) -> str:
        """acosim --svg's picture: map, unknown cells, plans, trajectory, moving obstacles' tracks."""
        return self._native.svg()

    def html(self) -> str:
        """acosim --html's page: the run played with play/pause and a time slider."""
        return self._native.html()

    def _repr_svg_(self) -> str:
        return self.svg()

    def __repr__(self) -> str:
        why = f" ({self.reason})" if self.reason else ""
        return (f"<aco.Simulation {self.outcome}{why}: {self.time:.1f} s, distance {self.distance:.2f}, "
                f"{self.collisions} collisions, {self.replans} replans>")


def simulate(scenario: Union[str, os.PathLike, Mapping[str, Any]], *, preset: Optional[str] = None,
             config: Optional[Union[str, os.PathLike]] = None, keys: Optional[Mapping[str, Any]] = None,
             **run_keys: Any) -> Simulation:
    """Runs a scenario as acosim does: the colony plans the global path, the local planner drives.

    scenario  a scenario file (YAML, hosts/acosim/README.md), or a dict of the same schema
              ({"run": {"map": ..., "start": [0, 0], "goal": [19, 19], "local": "dwa"},
              "unknown": [[5, 6]], ...}); a dict's relative paths are from the current folder
    preset    a named pipeline over the scenario's run keys (``acosim --preset``)
    config    a config file's pipeline over them (``acosim --config``)
    keys, run_keys   run keys over the scenario's, as aco.plan() takes them (local="track",
              local_follow=0.5, ants=20); a slot may be a Python object. The scenario's own keys
              (map, start, goal, seed) are refused, as by acosim.

    Returns an aco.Simulation; a bad scenario or key raises aco.Error with acosim's message.
    """
    given = _given(keys, run_keys)
    config_text = os.fspath(config) if config is not None else ""
    with _LiveObjects() as live:
        keys = _keys(live.keys(given, f"o{next(_live_names)}"))
        if not isinstance(scenario, Mapping):
            return Simulation(_aco.simulate(os.fspath(scenario), keys, preset or "", config_text))
        with tempfile.TemporaryDirectory() as folder:
            file = os.path.join(folder, "scenario.yaml")
            with open(file, "w", encoding="utf-8") as out:
                json.dump(_from_current_folder(scenario), out, indent=1)  # JSON is YAML
            try:
                return Simulation(_aco.simulate(file, keys, preset or "", config_text))
            except Error as error:
                # Its lines are of the file written here, not of anything the caller wrote.
                raise Error(re.sub(re.escape(file) + r"(:\d+)?", "the scenario", str(error))) from None


def _from_current_folder(scenario: Mapping[str, Any]) -> dict:
    """The dict with its run's map and config paths made absolute (a file's are from its folder)."""
    scenario = dict(scenario)
    run = scenario.get("run")
    if isinstance(run, Mapping):
        run = dict(run)
        for key in ("map", "config"):
            if isinstance(run.get(key), (str, os.PathLike)):
                run[key] = os.path.abspath(os.fspath(run[key]))
        scenario["run"] = run
    return scenario
