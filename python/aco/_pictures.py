"""Pictures of runs and maps: acoplan's SVG (aco.plan(svg=...), Result and Map in Jupyter) and
aco.plot() for matplotlib."""
from __future__ import annotations

import os
from typing import Any, Optional, Tuple, Union

from . import _aco
from ._planning import Error, Map, Result, _text


def _planned(result: Result) -> dict:
    planned = result._planned
    if planned is None:
        raise Error("this result has no picture: only a result of aco.plan() or aco.astar() knows its map")
    return planned


def _cell(xy: Any) -> Tuple[int, int]:
    return int(xy[0]), int(xy[1])


def run_svg(result: Result) -> str:
    """acoplan's picture of the run (``acoplan --svg``): the map, the grid path and the final path,
    start and goal, the convergence curve against the optimum; the pheromone field too when
    planned with ``svg_pheromone=True``."""
    planned = _planned(result)
    keys = {key: _text(value) for key, value in result.config.items()}
    return _aco.run_svg(planned["source"], keys, _cell(result.json["start"]), _cell(result.json["goal"]),
                        [_cell(cell) for cell in result.grid_path], result.path.tolist(), result.solved,
                        result.length or 0.0, result.seed, result.convergence.tolist(),
                        planned["iteration_best"], planned["pheromone"], result.optimal_length or 0.0)


def map_svg(map: Map) -> str:
    """The map alone as acoplan draws it: blocked cells, on terrain the heights and contours."""
    return _aco.map_svg(map._native(), dict(map.terrain_keys))


def write_svg(result: Result, path: Union[str, os.PathLike]) -> None:
    with open(path, "w", encoding="utf-8") as out:
        out.write(run_svg(result))


def run_map(result: Result) -> Map:
    """The aco.Map the run planned on (a map file read again, with the run's terrain keys)."""
    planned = _planned(result)
    map = planned["map"]
    if map is None:
        terrain = {key: value for key, value in result.config.items()
                   if key in ("max-slope", "height-scale", "cell-size", "map-format") or key.startswith("map.")}
        map = planned["map"] = Map.load(planned["source"], **terrain)
    return map


def plot(subject: Union[Result, Map], ax: Optional[Any] = None) -> Any:
    """Draws a run (its map, grid path, final path, start and goal) or a map alone on matplotlib axes
    (new ones if ``ax`` is None) and returns the axes.

    Everything is drawn in world units, as ``result.path`` is: a cell (x, y) is centred at
    (x * cell_size, y * cell_size), so ``grid_path`` is scaled by the map's cell size, and y grows
    downwards as in the map's rows. Occupancy grids are drawn black (blocked) on white, terrains
    by height (no-data cells left blank).
    """
    import matplotlib.pyplot as plt  # only plot() needs matplotlib

    map = subject if isinstance(subject, Map) else run_map(subject)
    if ax is None:
        _, ax = plt.subplots()
    size = map.cell_size
    extent = (-0.5 * size, (map.width - 0.5) * size, (map.height - 0.5) * size, -0.5 * size)
    if map.kind == "terrain":
        image = ax.imshow(map.array, cmap="terrain", extent=extent, interpolation="nearest")
        ax.figure.colorbar(image, ax=ax, label="height")
    else:
        ax.imshow(map.array, cmap="gray_r", vmin=0, vmax=1, extent=extent, interpolation="nearest")
    ax.set_xlabel("x (map units)" if size != 1.0 else "x (cells)")
    ax.set_ylabel("y (map units)" if size != 1.0 else "y (cells)")
    ax.set_title(map.name)
    if isinstance(subject, Result):
        if len(subject.grid_path):
            ax.plot(subject.grid_path[:, 0] * size, subject.grid_path[:, 1] * size, color="#1565c0", lw=1.5,
                    label="grid path")
        if len(subject.path):
            ax.plot(subject.path[:, 0], subject.path[:, 1], color="#d32f2f", lw=1.5, ls="--", label="path")
        for end, colour in (("start", "#43a047"), ("goal", "#e53935")):
            x, y = subject.json[end]
            ax.plot([x * size], [y * size], "o", color=colour, label=end)
        ax.legend(loc="best", fontsize="small")
    return ax
