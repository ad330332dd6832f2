"""Pictures of runs and maps: acoplan's SVG (aco.plan(svg=...), Result and Map in Jupyter) and
aco.plot() for matplotlib."""
from __future__ import annotations

import os
from typing import Any, Optional, Union

import numpy as np

from . import _aco
from ._planning import Error, Map, Result, _keys


def _planned(result: Result) -> dict:
    planned = result._planned
    if planned is None:
        raise Error("this result has no picture: only a result of aco.plan() or aco.astar() knows its map")
    return planned


def run_svg(result: Result) -> str:
    """acoplan's picture of the run (``acoplan --svg``): the map, the grid path and the final path,
    start and goal, the convergence curve against the optimum; the pheromone field too when
    planned with ``svg_pheromone=True``. A voxel world's is isometric (the drawing library's
    voxel SVG), with a slice at the start's, the goal's and the path's highest layer."""
    return _planned(result)["run"].svg()


def map_svg(map: Map) -> str:
    """The map alone as acoplan draws it: blocked cells, on terrain the heights and contours; a
    voxel world isometric, with slices at its lowest, middle and highest layer."""
    return _aco.map_svg(map._native(), dict(map.terrain_keys))


def write_svg(result: Result, path: Union[str, os.PathLike]) -> None:
    with open(path, "w", encoding="utf-8") as out:
        out.write(run_svg(result))


def run_map(result: Result) -> Map:
    """The aco.Map the run planned on (a map file's as the run read it, with the run's terrain keys)."""
    planned = _planned(result)
    map = planned["map"]
    if map is None:
        terrain = {key: value for key, value in result.config.items()
                   if key in ("max-slope", "height-scale", "cell-size", "map-format") or key.startswith("map.")}
        kind, array, cell_size, name = planned["run"].map_arrays()
        map = planned["map"] = Map(array, cell_size, name, kind=kind)
        map.file = planned["source"]
        map.terrain_keys = _keys(terrain)
    return map


def plot(subject: Union[Result, Map], ax: Optional[Any] = None) -> Any:
    """Draws a run (its map, grid path, final path, start and goal) or a map alone on matplotlib axes
    (new ones if ``ax`` is None) and returns the axes.

    Everything is drawn in world units, as ``result.path`` is: a cell (x, y) is centred at
    (x * cell_size, y * cell_size), so ``grid_path`` is scaled by the map's cell size, and y grows
    downwards as in the map's rows. Occupancy grids are drawn black (blocked) on white, terrains
    by height (no-data cells left blank).

    A voxel world is drawn on 3D axes (``ax`` one, made with ``projection="3d"``): its surface's
    blocked voxels as points coloured by layer (at most ``_MAX_VOXEL_POINTS``, evenly thinned),
    the paths as 3D lines, y growing away from the viewer as rows do. ``_repr_svg_()`` (and
    ``svg=``) draw it isometric with its cubes.
    """
    import matplotlib.pyplot as plt  # only plot() needs matplotlib

    map = subject if isinstance(subject, Map) else run_map(subject)
    if map.volumetric:
        return _plot_voxels(subject, map, ax)
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


# Blocked voxels plot() draws at most in a voxel world: matplotlib's 3D scatter slows beyond.
_MAX_VOXEL_POINTS = 20000


def _surface_voxels(blocked: np.ndarray) -> np.ndarray:
    """The blocked voxels with a free 6-neighbour or on the world's boundary (the rest cannot be
    seen), as an (n, 3) array of (x, y, z)."""
    padded = np.pad(blocked, 1, constant_values=False)
    inner = padded[1:-1, 1:-1, 1:-1]
    hidden = inner.copy()
    for axis in range(3):
        for step in (-1, 1):
            hidden &= np.roll(padded, step, axis=axis)[1:-1, 1:-1, 1:-1]
    z, y, x = np.nonzero(blocked & ~hidden)
    return np.stack([x, y, z], axis=1)


def _plot_voxels(subject: Union[Result, Map], map: Map, ax: Optional[Any]) -> Any:
    import matplotlib.pyplot as plt

    if ax is None:
        ax = plt.figure().add_subplot(projection="3d")
    elif not hasattr(ax, "zaxis"):
        raise Error(f"{map.name} is a voxel world: plot() draws it on 3D axes, "
                    "fig.add_subplot(projection='3d'), or give no ax")
    voxels = _surface_voxels(map.array)
    if len(voxels) > _MAX_VOXEL_POINTS:
        voxels = voxels[np.linspace(0, len(voxels) - 1, _MAX_VOXEL_POINTS).astype(np.int64)]
    ax.scatter(voxels[:, 0], voxels[:, 1], voxels[:, 2], c=voxels[:, 2], cmap="viridis", marker="s", s=10,
               alpha=0.4, depthshade=False)
    ax.set_xlim(-0.5, map.width - 0.5)
    ax.set_ylim(map.height - 0.5, -0.5)  # rows grow away from the viewer, as y grows down in 2D
    ax.set_zlim(-0.5, map.depth - 0.5)
    ax.set_xlabel("x (voxels)")
    ax.set_ylabel("y (voxels)")
    ax.set_zlabel("z (layer)")
    ax.set_title(map.name)
    if isinstance(subject, Result):
        if len(subject.grid_path):
            ax.plot(*subject.grid_path.T, color="#1565c0", lw=1.5, label="grid path")
        if len(subject.path):
            ax.plot(*subject.path.T, color="#d32f2f", lw=1.5, ls="--", label="path")
        for end, colour in (("start", "#43a047"), ("goal", "#e53935")):
            x, y, z = subject.json[end]
            ax.plot([x], [y], [z], "o", color=colour, label=end)
        ax.legend(loc="best", fontsize="small")
    return ax
