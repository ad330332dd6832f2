"""Maps and single runs: aco.Map, aco.plan(), aco.astar() and their result."""
from __future__ import annotations

import itertools
import json
import os
from typing import Any, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _aco, _live

Cell = Tuple[int, int]
_SCOPES = frozenset(_aco.key_scopes())
_SLOTS = ("init", "heuristic", "update", "deadlock", "smoother", "local")
_live_names = itertools.count()


class Map:
    """A map to plan on: an occupancy grid or a terrain of heights.

    Make one from a numpy array with ``aco.Map(array)``: a bool or integer array is an occupancy
    grid (nonzero = blocked), a float array holds terrain heights (NaN = no data) with
    ``cell_size`` the horizontal size of a cell. Rows are y from the top, columns x: cell (x, y)
    is ``array[y, x]``, as on the command line. Or load a file with ``aco.Map.load(path)``.
    """

    def __init__(self, array: Any, cell_size: float = 1.0, name: Optional[str] = None):
        array = np.asarray(array)
        if array.ndim != 2 or array.shape[0] == 0 or array.shape[1] == 0:
            raise ValueError(f"a map array must be 2D and not empty, not of shape {array.shape}")
        if np.issubdtype(array.dtype, np.floating):
            self.kind = "terrain"
            self.array = np.ascontiguousarray(array, dtype=np.float64)
        elif np.issubdtype(array.dtype, np.integer) or array.dtype == np.bool_:
            self.kind = "grid"
            self.array = np.ascontiguousarray(array != 0)
        else:
            raise ValueError(f"a map array holds bools or integers (occupancy) or floats (heights), not {array.dtype}")
        self.cell_size = float(cell_size)
        self.name = name or f"numpy {self.kind} {array.shape[1]}x{array.shape[0]}"
        self.file: Optional[str] = None
        self.terrain_keys: dict = {}

    @classmethod
    def load(cls, path: Union[str, os.PathLike], **terrain_keys: Any) -> "Map":
        """Loads any map file acoplan reads (Moving AI .map, ROS .yaml, ESRI .asc, PGM .pgm, 0/1
        text). Terrain keys (``height_scale``, ``cell_size`` for PGM images) are applied here and
        to every plan on this map."""
        keys = _keys(terrain_keys)
        kind, array, cell_size, name = _aco.map_arrays(os.fspath(path), keys)
        loaded = cls(array, cell_size, name)
        loaded.file = os.fspath(path)
        loaded.terrain_keys = keys
        return loaded

    @property
    def width(self) -> int:
        return self.array.shape[1]

    @property
    def height(self) -> int:
        return self.array.shape[0]

    def __array__(self, dtype=None):
        return self.array if dtype is None else self.array.astype(dtype)

    def __repr__(self) -> str:
        return f"aco.Map({self.name!r}, {self.kind}, {self.width}x{self.height})"

    def _native(self) -> Any:
        """What the native module plans on: the map's file, or its array."""
        if self.file is not None:
            return self.file
        return _aco.ArrayMap(self.array if self.kind == "grid" else None, self.array if self.kind == "terrain" else None,
                             self.cell_size, self.name)

    def _repr_svg_(self) -> str:
        """The map as acoplan draws it, for Jupyter."""
        from ._pictures import map_svg
        return map_svg(self)


class Result:
    """One planning run: the same content as ``acoplan --json`` (``result.json``), with arrays.

    path            the final path (after the smoother) as an (n, 2) or (n, 3) float array
    grid_path       the planner's best grid path as an (n, 2) int array of cells (x, y)
    solved, reason  whether a path was found, and why not
    length          length of ``path``; grid_length of ``grid_path`` (None for a continuous planner,
                    ``planner="ompl"``, whose grid_path is empty and whose path is its own)
    optimal_length  the exact A* optimum on the same graph (None if unreachable)
    gap_percent     100 * (grid_length / optimal_length - 1): the grid path's excess over the optimum
                    (None without a grid path)
    convergence     best-so-far length per iteration (NaN before the first solution)
    iterations, best_iteration, time_ms, seed
    config          the resolved run keys (what ``--print-config`` shows); plugins: which binary
                    filled each slot (name, version, file, sha256)
    preset          the pipeline the keys were laid over
    figures         what the run's plugins recorded (Context::record(), add()), by
                    "<slot>/<plugin>.<name>": {"update/max_min.restarts": 0, ...}; the planner's own
                    properties (ant_steps, stopped_by; evaluations of ifwa and pso) are in ``json``
    """

    def __init__(self, record: dict, preset: str):
        self.json = record
        self.preset = preset
        self.solved: bool = record["solved"]
        self.reason: str = record.get("reason", "")
        self.length = record["length"]
        self.grid_length = record["grid_length"]
        self.optimal_length = record["optimal_length"]
        self.path = np.array(record["path"], dtype=np.float64).reshape(-1, 3 if record["path"] and len(record["path"][0]) == 3 else 2)
        self.grid_path = np.array(record["grid_path"], dtype=np.int64).reshape(-1, 2)
        self.convergence = np.array([np.nan if v is None else v for v in record["convergence"]], dtype=np.float64)
        self.iterations: int = record["iterations"]
        self.best_iteration: int = record["best_iteration"]
        self.time_ms: float = record["time_ms"]
        self.seed: int = record["seed"]
        self.config: dict = record["config"]
        self.plugins: dict = record["plugins"]
        # acoplan's --json writes every property of the run at its top level, the plugins' figures
        # by their "<slot>/<plugin>.<name>" keys (or "plugin.<name>" of a strategy outside the registry).
        self.figures: dict = {key: value for key, value in record.items() if "/" in key or key.startswith("plugin.")}
        self.gap_percent = (100.0 * (self.grid_length / self.optimal_length - 1.0)
                            if self.solved and self.optimal_length and self.grid_length is not None else None)

    def __repr__(self) -> str:
        if not self.solved:
            return f"<aco.Result not solved: {self.reason}>"
        gap = "" if self.gap_percent is None else f", gap {self.gap_percent:.2f} %"
        optimum = "none" if self.optimal_length is None else f"{self.optimal_length:.4f}"
        if self.grid_length is None:  # a continuous planner: no grid path
            return (f"<aco.Result length {self.length:.4f} (continuous, optimum {optimum}), {len(self.path)} waypoints, "
                    f"{self.iterations} iterations, {self.time_ms:.1f} ms, preset {self.preset}>")
        return (f"<aco.Result length {self.length:.4f} (grid {self.grid_length:.4f}, optimum {optimum}{gap}), "
                f"{len(self.grid_path)} cells, {self.iterations} iterations, {self.time_ms:.1f} ms, preset {self.preset}>")

    def _repr_svg_(self) -> Optional[str]:
        """acoplan's picture of the run, for Jupyter (None for a result not made by aco.plan())."""
        from ._pictures import run_svg
        return run_svg(self) if hasattr(self, "_planned") else None


def _key(name: str) -> str:
    """A Python keyword as a run key: update_rho -> update.rho, max_slope -> max-slope."""
    if "." in name or "-" in name:
        return name
    scope, _, rest = name.partition("_")
    if rest and scope in _SCOPES:
        return scope + "." + rest
    return name.replace("_", "-")


def _text(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)  # the shortest text that reads back as the same double
    return str(value)


def _keys(keys: Mapping[str, Any]) -> dict:
    return {_key(name): _text(value) for name, value in keys.items()}


class _LiveObjects:
    """Python objects given as plugins (``update=MyUpdate()``) are reached by the python bridge
    plugin as ``aco._live:<name>`` for the length of the call."""

    def __init__(self, keys: dict):
        self.keys, self.names = dict(keys), []
        for slot in _SLOTS:
            value = self.keys.get(slot)
            if value is None or isinstance(value, str):
                continue
            name = f"o{next(_live_names)}"
            setattr(_live, name, value)
            self.names.append(name)
            self.keys[slot] = "python"
            self.keys[slot + ".class"] = f"aco._live:{name}"

    def __enter__(self) -> dict:
        return self.keys

    def __exit__(self, *_: Any) -> None:
        for name in self.names:
            delattr(_live, name)


def plan(map: Union[Map, np.ndarray, str, os.PathLike], start: Sequence[int], goal: Sequence[int], *,
         preset: Optional[str] = None, config: Optional[Union[str, os.PathLike]] = None,
         keys: Optional[Mapping[str, Any]] = None, threads: int = 0, svg: Optional[Union[str, os.PathLike]] = None,
         svg_pheromone: bool = False, **run_keys: Any) -> Result:
    """Plans a path from start to goal with the ant colony (or another planner), as acoplan does.

    map       an aco.Map, a numpy array (see aco.Map) or a map file's path
    start     the start cell (x, y): x the column, y the row from the top, 0-based
    goal      the goal cell (x, y)
    preset    the named pipeline the keys are laid over (aco.presets()); default: robust on
              occupancy grids, terrain on height maps, as acoplan's
    config    an acoplan config file instead of a preset
    keys      run keys as acoplan's options without dashes: {"update.rho": 0.1, "max-slope": 30}
    threads   worker threads, 0 = all cores; results do not depend on it
    svg       writes acoplan's picture of the run to this file (as ``acoplan --svg``); the
              result shows the same picture in Jupyter
    svg_pheromone  the picture also shows the final pheromone field (``--svg-pheromone``)
    run_keys  the same keys as Python keywords: update="max_min", update_rho=0.1, ants=20,
              max_slope=30, seed=7, planner="pso" (a slot's keyword ``update_rho`` is the key
              ``update.rho``; other underscores are dashes). A slot may also be given a Python
              object implementing the slot's interface (update=MyUpdate()): it runs inside the
              native colony through the python bridge plugin.

    Returns an aco.Result; an unsolved run is a result with ``solved`` False and its reason. A
    bad key, value, map or cell raises aco.Error with acoplan's message.
    """
    if preset is not None and config is not None:
        raise Error("preset and config: give one of them")
    given = dict(run_keys)
    given.update(keys or {})
    given_keys = {_key(k) for k in given}
    for name in ("map", "start", "goal", "scen", "preset", "config"):
        if _key(name) in given_keys:
            raise Error(f"'{name}' is an argument of plan(), not a run key")
    # A file is read once, by the planner (as acoplan reads it); an array is handed over as it is.
    if isinstance(map, (str, os.PathLike)):
        source, text_keys = os.fspath(map), {}
    else:
        if not isinstance(map, Map):
            map = Map(map)
        text_keys = dict(map.terrain_keys)
        source = map._native()
    with _LiveObjects(given) as live:
        for name, value in live.items():
            text_keys[_key(name)] = _text(value)
        record, used, iteration_best, pheromone = _aco.plan(
            source, _cell(start, "start"), _cell(goal, "goal"), text_keys, preset or "",
            os.fspath(config) if config is not None else "", int(threads), bool(svg_pheromone))
    result = Result(json.loads(record), used)
    # What the picture needs besides the result (aco._pictures); a map file is read again only to plot.
    result._planned = {"source": source, "map": map if isinstance(map, Map) else None,
                       "iteration_best": iteration_best, "pheromone": pheromone}
    if svg is not None:
        from ._pictures import write_svg
        write_svg(result, svg)
    return result


def astar(map: Union[Map, np.ndarray, str, os.PathLike], start: Sequence[int], goal: Sequence[int],
          **run_keys: Any) -> Result:
    """The exact shortest path on the same graph (the A* planner of aco.plan()); graph keys such as
    neighbourhood, corner_cutting and max_slope apply."""
    return plan(map, start, goal, planner="astar", **run_keys)


def _cell(cell: Sequence[int], what: str) -> Cell:
    try:
        x, y = (int(v) for v in cell)
    except (TypeError, ValueError):
        raise Error(f"{what} must be a cell (x, y), not {cell!r}") from None
    return x, y


Error = _aco.Error
