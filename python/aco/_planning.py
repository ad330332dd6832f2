"""Maps and single runs: aco.Map, aco.plan(), aco.astar(), aco.load_scenarios() and their results."""
from __future__ import annotations

import contextlib
import dataclasses
import functools
import itertools
import math
import operator
import os
from typing import Any, Callable, Iterator, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _aco, _live

Cell = Tuple[int, ...]  # (x, y); (x, y, z) in a voxel world
Error = _aco.Error
_SCOPES = frozenset(_aco.key_scopes())
_SLOTS = ("init", "heuristic", "update", "deadlock", "smoother", "local")
_KINDS = ("occupancy", "terrain")
_MAX_CELLS = 2**31 - 1  # the graph's node ids are 32-bit (aco/graph.hpp)
_live_names = itertools.count()
# The ESRI grid's usual marker of a cell without data; Map.save() picks another if a height is it.
_NODATA = -9999.0


class Map:
    """A map to plan on: an occupancy grid, a terrain of heights or a voxel world.

    Make one from a numpy array with ``aco.Map(array)``. ``kind="occupancy"``: every cell that is
    not ``free`` (default 0) is blocked; ``kind="terrain"``: the values are heights (NaN = no data)
    with ``cell_size`` the horizontal size of a cell, in the heights' units. Without ``kind``, a
    bool or integer array is an occupancy grid and a float array a terrain, but a float array of
    only 0 and 1 is refused: it could be either, so say which. Rows are y from the top, columns
    x: cell (x, y) is ``array[y, x]``, as on the command line. ``map.array`` holds the cells: True
    = blocked for an occupancy grid, the heights for a terrain.

    A 3D array is a voxel world (``volumetric`` True), occupancy only: voxel (x, y, z) is
    ``array[z, y, x]``, layers z from the ground up, each layer a grid as above, so
    ``array.shape`` is (depth, height, width). A float array of only 0 and 1 needs no ``kind``
    here (a terrain is 2D); ``free`` works as on a grid.

    Load a map file with ``aco.Map.load(path)``; write one with ``map.save(path)``.
    """

    def __init__(self, array: Any, cell_size: float = 1.0, name: Optional[str] = None, *,
                 kind: Optional[str] = None, free: Any = None):
        if isinstance(array, (str, bytes, os.PathLike)):
            raise Error(f"aco.Map takes an array; load the map file {os.fsdecode(array)!r} with aco.Map.load(path)")
        array = np.asarray(array)
        if array.ndim not in (2, 3) or 0 in array.shape:
            raise Error(f"a map array must be 2D (a grid, a terrain) or 3D (a voxel world, [z, y, x]) and not empty, "
                        f"not of shape {array.shape}")
        if not (np.issubdtype(array.dtype, np.number) or array.dtype == np.bool_):
            raise Error(f"a map array holds bools or integers (occupancy) or floats (heights), not {array.dtype}")
        # Before anything is computed over it: a strided view of a small array can be of any size,
        # and numpy would allocate its cells (gigabytes) to compare them.
        cells = math.prod(array.shape)
        if cells > _MAX_CELLS:
            raise Error(f"a map array of shape {array.shape} has {cells} cells, more than the graph's 32-bit node "
                        f"ids allow ({_MAX_CELLS})")
        if kind is not None and kind not in _KINDS:
            raise Error(f"kind must be 'occupancy' or 'terrain', not {kind!r}")
        if array.ndim == 3:
            self.kind = _voxel_kind(array, kind, free)
        else:
            self.kind = _kind_of(array) if kind is None else kind
        if self.kind == "terrain":
            if free is not None:
                raise Error("free= says which value of an occupancy grid is free; a terrain holds heights (NaN = no data)")
            self.array = np.ascontiguousarray(array, dtype=np.float64)
        else:
            self.array = np.ascontiguousarray(array != (0 if free is None else free))
        self.cell_size = float(cell_size)
        if self.volumetric and self.cell_size != 1.0:
            raise Error("a voxel world plans in voxels: its cell_size is 1")
        self.name = name or (f"numpy voxel world {self.width}x{self.height}x{self.depth}" if self.volumetric
                             else f"numpy {self.kind} {self.width}x{self.height}")
        self.file: Optional[str] = None
        self.terrain_keys: dict = {}

    @classmethod
    def load(cls, path: Union[str, os.PathLike], **terrain_keys: Any) -> "Map":
        """Loads any map file acoplan reads (Moving AI .map, ROS .yaml, ESRI .asc, PGM .pgm, 0/1
        text; the voxel worlds of Moving AI .3dmap and, through the map plugin, OctoMap .bt/.ot).
        Terrain keys (``height_scale``, ``cell_size`` for PGM images) and a map plugin's keys
        (``map_format``, ``map_...``) are applied here and to every plan on this map."""
        keys = _keys(terrain_keys)
        kind, array, cell_size, name = _aco.map_arrays(os.fspath(path), keys)
        loaded = cls(array, cell_size, name, kind=kind)
        loaded.file = os.fspath(path)
        loaded.terrain_keys = keys
        return loaded

    def save(self, path: Union[str, os.PathLike]) -> None:
        """Writes the map as a file that aco.Map.load() and acoplan read, in the format of its
        ending: an occupancy grid as a Moving AI map (.map: '.' free, '@' blocked) or, with any
        other ending but a terrain format's, a 0/1 matrix (.txt); a terrain as an ESRI ASCII grid
        (.asc, with its cell size; NaN cells as NODATA); a voxel world as a Moving AI .3dmap (its
        blocked voxels). Heights are written exactly."""
        path = os.fspath(path)
        ending = os.path.splitext(path)[1].lower()
        if self.volumetric:
            if ending != ".3dmap":
                raise Error(f"{path}: a voxel world is saved as a Moving AI voxel map, a file ending in .3dmap")
            text = _aco.voxel_map_text(_aco.ArrayMap(self.array, None, 1.0, self.name))
        elif ending == ".3dmap":
            raise Error(f"{path}: a .3dmap is a voxel world's file; this map is 2D (a voxel world is a 3D array)")
        elif self.kind == "terrain":
            if ending != ".asc":
                raise Error(f"{path}: a terrain is saved as an ESRI ASCII grid, a file ending in .asc")
            text = self._esri_ascii()
        elif ending in (".asc", ".pgm", ".yaml", ".yml"):
            raise Error(f"{path}: an occupancy grid is saved as a Moving AI .map or a 0/1 matrix (.txt), not {ending}")
        elif ending == ".map":
            rows = ("".join("@" if blocked else "." for blocked in row) for row in self.array)
            text = f"type octile\nheight {self.height}\nwidth {self.width}\nmap\n" + "\n".join(rows) + "\n"
        else:
            text = "\n".join(" ".join("1" if blocked else "0" for blocked in row) for row in self.array) + "\n"
        with open(path, "w") as file:
            file.write(text)

    def _esri_ascii(self) -> str:
        heights = self.array
        nodata = _NODATA
        if (heights == nodata).any():
            nodata = float(np.floor(np.nanmin(heights))) - 1.0
        header = (f"ncols {self.width}\nnrows {self.height}\nxllcorner 0\nyllcorner 0\n"
                  f"cellsize {self.cell_size!r}\nNODATA_value {nodata!r}\n")
        rows = (" ".join(repr(nodata if np.isnan(h) else float(h)) for h in row) for row in heights)
        return header + "\n".join(rows) + "\n"

    @property
    def width(self) -> int:
        """Columns: x."""
        return self.array.shape[-1]

    @property
    def height(self) -> int:
        """Rows: y."""
        return self.array.shape[-2]

    @property
    def depth(self) -> int:
        """Layers: z; 1 for a grid or a terrain."""
        return self.array.shape[0] if self.array.ndim == 3 else 1

    @property
    def volumetric(self) -> bool:
        """A voxel world: cells are (x, y, z), ``array[z, y, x]``."""
        return self.array.ndim == 3

    def __array__(self, dtype=None):
        return self.array if dtype is None else self.array.astype(dtype)

    def __repr__(self) -> str:
        if self.volumetric:
            return f"aco.Map({self.name!r}, voxel world, {self.width}x{self.height}x{self.depth})"
        return f"aco.Map({self.name!r}, {self.kind}, {self.width}x{self.height})"

    def _native(self) -> Any:
        """What the native module plans on: the map's file, or its array."""
        if self.file is not None:
            return self.file
        return _aco.ArrayMap(self.array if self.kind == "occupancy" else None, self.array if self.kind == "terrain" else None,
                             self.cell_size, self.name)

    def _repr_svg_(self) -> str:
        """The map as acoplan draws it, for Jupyter."""
        from ._pictures import map_svg
        return map_svg(self)


def _kind_of(array: np.ndarray) -> str:
    """The kind an array's type says: integers and bools occupancy, floats heights."""
    if not np.issubdtype(array.dtype, np.floating):
        return "occupancy"
    if np.isin(array, (0.0, 1.0)).all():
        raise Error("a float array of only 0 and 1 may be an occupancy grid or a flat terrain: say which with "
                    "kind='occupancy' (0 free, 1 blocked; free=1 for the other way round) or kind='terrain' "
                    "(heights), or pass a bool array (True = blocked)")
    return "terrain"


def _voxel_kind(array: np.ndarray, kind: Optional[str], free: Any) -> str:
    """A 3D array's kind: a voxel world is occupancy only; floats without kind only 0 and 1."""
    if kind == "terrain":
        raise Error("a 3D array is a voxel world of free and blocked voxels, kind='occupancy'; a terrain's heights "
                    "are a 2D array")
    if kind is None and free is None and np.issubdtype(array.dtype, np.floating) and not np.isin(array, (0.0, 1.0)).all():
        raise Error("a 3D float array is a voxel world: only 0 (free) and 1 (blocked), or say kind='occupancy' "
                    "(every value but free= blocked)")
    return "occupancy"


@dataclasses.dataclass(frozen=True)
class Scenario:
    """One problem of a Moving AI scenario file (.scen, or .3dscen of a voxel world), as acoplan
    --scen plans it: ``aco.plan(s.map, s.start, s.goal)``.

    map             the map file: the scenario file's name without .scen (arena.map for
                    arena.map.scen; Simple.3dmap for Simple.3dmap.3dscen)
    start, goal     cells (x, y); voxels (x, y, z) from a .3dscen
    optimal_length  the file's optimum: octile distance with 8 moves and no corner cutting
                    (acoplan's defaults: ``aco.astar`` finds the same length); in a voxel world
                    with 26 moves (1, sqrt 2, sqrt 3), every voxel of a step's box free (the
                    voxel preset's graph)
    bucket          Moving AI's difficulty bucket (0 in a .3dscen, which has none)
    width, height   the size of the map the scenario is for (0 in a .3dscen, which states none)
    """

    map: str
    start: Cell
    goal: Cell
    optimal_length: float
    bucket: int
    width: int
    height: int


def load_scenarios(path: Union[str, os.PathLike]) -> List[Scenario]:
    """The problems of a Moving AI scenario file (.scen), in the file's order."""
    return [Scenario(**{**s, "map": os.fspath(s["map"]), "start": tuple(s["start"]), "goal": tuple(s["goal"])})
            for s in _aco.scenarios(os.fspath(path))]


class Result:
    """One planning run: the same content as ``acoplan --json`` (``result.json``), with arrays.

    Positions and lengths are in world units: a cell is ``cell_size`` wide (1 on an occupancy
    grid; a terrain's own, as aco.Map and .asc files give it), cell (x, y) is at
    (x * cell_size, y * cell_size). Cells are counted in columns and rows.

    path            the final path (after the smoother) as an (n, 2) float array of world x, y,
                    on a terrain (n, 3) with the height as z; world units. In a voxel world
                    (n, 3): x, y and z in voxels
    path_cells      ``path``'s x and y in cells, an (n, 2) float array: over ``imshow(map.array)``
                    draw it with ``plot(*result.path_cells.T)``, on a terrain as on a grid; in a
                    voxel world (n, 3), x, y and z (the same as ``path``)
    grid_path       the planner's best grid path as an (n, 2) int array of cells (x, y); in a
                    voxel world (n, 3), voxels (x, y, z)
    volumetric      planned in a voxel world (``depth`` its layers; start, goal in ``json`` (x, y, z))
    cell_size       the world size of a cell
    solved, reason  whether a path was found, and why not
    length          length of ``path``; grid_length of ``grid_path``, both in world units (None for a
                    continuous planner, ``planner="ompl"``, whose grid_path is empty and whose path
                    is its own)
    optimal_length  the exact A* optimum on the same graph, in world units (None if unreachable)
    gap_percent     100 * (grid_length / optimal_length - 1): the grid path's excess over the optimum
                    (None without a grid path; exactly 0 for a path as long as the optimum to
                    within rounding, relative 1e-11, as acoplan's irace cost)
    convergence     best-so-far length per iteration (NaN before the first solution)
    iterations, best_iteration, time_ms, seed
    config          the resolved run keys (what ``--print-config`` shows); plugins: which binary
                    filled each slot (name, version, file, sha256)
    preset          the pipeline the keys were laid over
    figures         what the run's plugins recorded (Context::record(), add()), by
                    "<slot>/<plugin>.<name>": {"update/max_min.restarts": 0, ...}; the planner's own
                    properties (ant_steps, stopped_by; evaluations of ifwa and pso) are in ``json``
    """

    def __init__(self, record: dict, preset: str, cell_size: float = 1.0):
        self.json = record
        self.preset = preset
        self.cell_size = cell_size
        # What its picture needs besides the fields (aco._pictures), set by aco.plan().
        self._planned: Optional[dict] = None
        self.solved: bool = record["solved"]
        self.reason: str = record.get("reason", "")
        self.length = record["length"]
        self.grid_length = record["grid_length"]
        self.optimal_length = record["optimal_length"]
        # acoplan's JSON gives a voxel world's depth (and its cells x, y, z); grids and terrains have none.
        self.volumetric: bool = "depth" in record
        self.depth: int = record.get("depth", 1)
        three_d = self.volumetric or bool(record["path"] and len(record["path"][0]) == 3)
        self.path = np.array(record["path"], dtype=np.float64).reshape(-1, 3 if three_d else 2)
        self.path_cells = self.path / cell_size if self.volumetric else self.path[:, :2] / cell_size
        self.grid_path = np.array(record["grid_path"], dtype=np.int64).reshape(-1, 3 if self.volumetric else 2)
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
        self.gap_percent: Optional[float] = None
        if self.solved and self.optimal_length and self.grid_length is not None:
            gap = _aco.gap_percent(self.grid_length, self.optimal_length)
            # A path as long as the optimum may differ from it in the last bits (another order of the sums).
            self.gap_percent = 0.0 if abs(gap) < 1e-9 else gap

    def __repr__(self) -> str:
        if not self.solved:
            return f"<aco.Result not solved: {self.reason}>"
        planner = self.config.get("planner", "aco")
        gap = "" if self.gap_percent is None else f", gap {self.gap_percent:.2f} %"
        optimum = "none" if self.optimal_length is None else f"{self.optimal_length:.4f}"
        if self.grid_length is None:  # a continuous planner: no grid path
            shape = f"(continuous, optimum {optimum}), {len(self.path)} waypoints"
        else:
            shape = f"(grid {self.grid_length:.4f}, optimum {optimum}{gap}), {len(self.grid_path)} cells"
        # A* searches once, and only the colony runs the preset's pipeline.
        iterations = "" if planner == "astar" else f", {self.iterations} iterations"
        pipeline = f"preset {self.preset}" if planner == "aco" else f"planner {planner}"
        return f"<aco.Result length {self.length:.4f} {shape}{iterations}, {self.time_ms:.1f} ms, {pipeline}>"

    def _repr_svg_(self) -> Optional[str]:
        """acoplan's picture of the run, for Jupyter (None for a result not made by aco.plan())."""
        from ._pictures import run_svg
        return run_svg(self) if self._planned is not None else None


@functools.lru_cache(maxsize=None)
def _plain_keys() -> frozenset:
    """The run keys of acoplan's tables without a scope ("local-search", "max-slope")."""
    return frozenset(key["name"] for key in _aco.run_key_tables() if "." not in key["name"])


def _key(name: str) -> str:
    """A Python keyword as a run key: update_rho -> update.rho, max_slope -> max-slope, and
    local_search -> local-search (a key of its own, not the local slot's "search")."""
    if "." in name or "-" in name:
        return name
    if name.replace("_", "-") in _plain_keys():
        return name.replace("_", "-")
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


@contextlib.contextmanager
def _reworded(reword: Callable[[str], str]) -> Iterator[None]:
    """An aco.Error raised inside with its message reworded, and otherwise as it was raised (its
    class, cause and traceback)."""
    try:
        yield
    except Error as error:
        if error.args and isinstance(error.args[0], str):
            error.args = (reword(error.args[0]),) + error.args[1:]
        raise


def _takes_python_objects(slot: str) -> bool:
    """Whether the slot has a python bridge plugin (asking for that plugin alone: listing them all
    would load every plugin)."""
    try:
        _aco.describe(f"{slot}/python")
    except Error:
        return False
    return True


class _LiveObjects:
    """Python objects given as plugins (``update=MyUpdate()``) are reached by the python bridge
    plugin as ``aco._live:<name>`` for the length of the call."""

    def __init__(self) -> None:
        self.names: List[str] = []

    def keys(self, keys: Mapping[str, Any], name: str) -> dict:
        """``keys`` with each slot's Python object replaced by the python plugin, which reaches
        it as aco._live.<name>_<slot>."""
        keys = dict(keys)
        for slot in _SLOTS:
            value = keys.get(slot)
            if value is None or isinstance(value, (str, Mapping)):  # a plugin's name, or YAML's {plugin: ...}
                continue
            if not _takes_python_objects(slot):
                python_slots = [s for s in _SLOTS if _takes_python_objects(s)]
                raise Error(f"{slot}={value!r}: a Python object can fill the slots "
                            f"{', '.join(python_slots) or '(none: the python plugins are missing)'} only; "
                            f"give the {slot} plugin's name (aco.plugins() lists them)")
            attribute = f"{name}_{slot}"
            if hasattr(_live, attribute):
                raise Error(f"two Python plugin objects would both be aco._live.{attribute}: rename a configuration")
            setattr(_live, attribute, value)
            self.names.append(attribute)
            keys[slot] = "python"
            keys[slot + ".class"] = f"aco._live:{attribute}"
        return keys

    def __enter__(self) -> "_LiveObjects":
        return self

    def __exit__(self, *_: Any) -> None:
        for name in self.names:
            delattr(_live, name)


def _given(keys: Optional[Mapping[str, Any]], run_keys: Mapping[str, Any]) -> dict:
    """The run keys a call gives: keywords, then ``keys=``."""
    given = dict(run_keys)
    given.update(keys or {})
    return given


# plan()'s own arguments, which are no run keys.
_ARGUMENTS = ("map", "start", "goal", "preset", "config", "threads", "max_memory", "kind", "free", "svg",
              "svg_pheromone")


def plan(map: Union[Map, np.ndarray, str, os.PathLike], start: Sequence[int], goal: Sequence[int], *,
         preset: Optional[str] = None, config: Optional[Union[str, os.PathLike]] = None,
         keys: Optional[Mapping[str, Any]] = None, threads: int = 0, max_memory: Optional[Union[int, str]] = None,
         kind: Optional[str] = None, free: Any = None, svg: Optional[Union[str, os.PathLike]] = None,
         svg_pheromone: bool = False, **run_keys: Any) -> Result:
    """Plans a path from start to goal with the ant colony (or another planner), as acoplan does.

    map         an aco.Map, a numpy array (see aco.Map) or a map file's path
    start       the start cell (x, y): x the column, y the row from the top, 0-based, whole numbers;
                in a voxel world (x, y, z), z the layer from the ground (a 3D array's [z, y, x])
    goal        the goal cell (x, y), or (x, y, z)
    preset      the named pipeline the keys are laid over (aco.presets()); default: robust on
                occupancy grids, terrain on height maps, voxel in voxel worlds, as acoplan's
    config      an acoplan config file instead of a preset
    keys        run keys as acoplan's options without dashes: {"update.rho": 0.1, "max-slope": 30}
    threads     worker threads, 0 = all cores (at most 1024, as acoplan); results do not depend on it
    max_memory  refuse maps whose planning would need more memory: bytes, or a size such as
                "512M" or "4G" (acoplan's --max-memory); default 3/4 of the available memory
    kind, free  for a numpy array: what it holds, "occupancy" or "terrain", and which value is
                free in an occupancy array (see aco.Map)
    svg         writes acoplan's picture of the run to this file (as ``acoplan --svg``); the
                result shows the same picture in Jupyter
    svg_pheromone  the picture also shows the final pheromone field (``--svg-pheromone``)
    run_keys    the same keys as Python keywords: update="max_min", update_rho=0.1, ants=20,
                max_slope=30, seed=7, planner="pso" (a slot's keyword ``update_rho`` is the key
                ``update.rho``; other underscores are dashes). A slot may also be given a Python
                object implementing the slot's interface (update=MyUpdate()): it runs inside the
                native colony through the python bridge plugin.

    Returns an aco.Result; an unsolved run is a result with ``solved`` False and its reason. A
    bad key, value, map or cell raises aco.Error with acoplan's message, its keys spelled as
    keywords (``did you mean 'ants'?``).
    """
    given = _given(keys, run_keys)
    given_keys = {_key(k) for k in given}
    if given_keys & {"scen", "scen-index"}:
        raise Error("plan() takes no scenario file: read one with aco.load_scenarios(path) and plan its problems, "
                    "s = aco.load_scenarios(path)[0]; aco.plan(s.map, s.start, s.goal)")
    for name in _ARGUMENTS:
        if _key(name) in given_keys:
            raise Error(f"'{name}' is an argument of plan(), not a run key")
    _check_threads(threads)
    # A file is read once, by the planner (as acoplan reads it); an array is handed over as it is.
    if isinstance(map, (str, os.PathLike)) or isinstance(map, Map):
        if kind is not None or free is not None:
            raise Error("kind= and free= describe a numpy array; this map's kind is known (aco.Map(array, kind=...) "
                        "gives an array's)")
    if isinstance(map, (str, os.PathLike)):
        source, text_keys = os.fspath(map), {}
    else:
        if not isinstance(map, Map):
            map = Map(map, kind=kind, free=free)
        text_keys = dict(map.terrain_keys)
        source = map._native()
    with _LiveObjects() as live:
        for name, value in live.keys(given, f"o{next(_live_names)}").items():
            text_keys[_key(name)] = _text(value)
        record, used, cell_size, planned = _aco.plan(
            source, _cell(start, "start"), _cell(goal, "goal"), text_keys, preset or "",
            os.fspath(config) if config is not None else "", int(threads),
            None if max_memory is None else _text(max_memory), bool(svg_pheromone))
    result = Result(record, used, cell_size)
    # The native run, which draws the picture from the map it planned on (aco._pictures).
    result._planned = {"run": planned, "source": source, "map": map if isinstance(map, Map) else None}
    if svg is not None:
        from ._pictures import write_svg
        write_svg(result, svg)
    return result


def _check_threads(threads: Any) -> None:
    """acoplan's checks of --threads."""
    if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)):
        raise Error(f"threads: {threads!r} is not a whole number")
    if not 0 <= threads <= 1024:
        raise Error(f"threads: {threads} is outside the range [0, 1024] (0 = all cores)")


def astar(map: Union[Map, np.ndarray, str, os.PathLike], start: Sequence[int], goal: Sequence[int],
          **run_keys: Any) -> Result:
    """The exact shortest path on the same graph (the A* planner of aco.plan(), whose arguments it
    takes: kind= for an array, max_memory=); graph keys such as neighbourhood, corner_cutting and
    max_slope apply."""
    return plan(map, start, goal, planner="astar", **run_keys)


def _cell(cell: Sequence[int], what: str) -> Cell:
    """(x, y) or (x, y, z); which of them the map needs, the native module says (it knows the map)."""
    if isinstance(cell, (str, bytes)) or not hasattr(cell, "__len__") or len(cell) not in (2, 3):
        raise Error(f"{what} must be a cell (x, y), or (x, y, z) in a voxel world, not {cell!r}")
    return tuple(_whole(v, what, cell) for v in cell)


def _whole(value: Any, what: str, cell: Sequence[int]) -> int:
    """A cell's coordinate: an integer, or a float with no fraction; a fraction is refused, not cut off."""
    try:
        return operator.index(value)
    except TypeError:
        if isinstance(value, (float, np.floating)) and float(value).is_integer():
            return int(value)
    raise Error(f"{what} {tuple(cell)!r} is not a cell: x and y count columns and rows, in whole numbers")
