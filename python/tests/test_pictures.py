"""Pictures: plan(svg=...) and Result._repr_svg_ are acoplan's SVG, Map._repr_svg_ the map alone,
aco.plot() draws in one frame of world units."""
import re
import shutil
import subprocess

import matplotlib
import numpy as np
import pytest

import aco
from conftest import BUILD, MAP1

matplotlib.use("Agg")

KEYS = {"update": "max_min", "ants": 10, "iterations": 12, "seed": 3}


def acoplan_svg(tmp_path, *args):
    file = tmp_path / "acoplan.svg"
    out = subprocess.run([str(BUILD / "hosts" / "acoplan" / "acoplan"), "--map", str(MAP1), "--start", "0,0", "--goal",
                          "19,19", "--update", "max_min", "--ants", "10", "--iterations", "12", "--seed", "3",
                          "--svg", str(file), *args], capture_output=True, text=True, check=False)
    assert out.returncode == 0, out.stderr
    return file.read_text()


def test_plan_writes_acoplans_picture_of_the_same_run(tmp_path):
    result = aco.plan(MAP1, (0, 0), (19, 19), svg=tmp_path / "python.svg", **KEYS)
    written = (tmp_path / "python.svg").read_text()
    assert written == acoplan_svg(tmp_path)
    assert result._repr_svg_() == written  # Jupyter shows the same picture
    assert 'id="grid-path"' in written and 'class="best-so-far"' in written and 'id="pheromone"' not in written

    with_pheromone = aco.plan(MAP1, (0, 0), (19, 19), svg=tmp_path / "tau.svg", svg_pheromone=True, **KEYS)
    assert (tmp_path / "tau.svg").read_text() == acoplan_svg(tmp_path, "--svg-pheromone")
    assert 'id="pheromone"' in with_pheromone._repr_svg_()


def test_a_numpy_maps_picture_shows_its_path_in_cells_whatever_its_cell_size():
    heights = np.add.outer(np.arange(6.0), np.arange(8.0))
    result = aco.plan(aco.Map(heights, cell_size=4.0), (0, 0), (7, 5), ants=5, iterations=5, seed=1)
    svg = result._repr_svg_()
    # The goal's mark at cell (7, 5), not at its world position (28, 20).
    assert '<circle cx="7" cy="5"' in svg
    assert 'id="height-legend"' in svg


def test_a_map_shows_itself_alone():
    grid = np.zeros((5, 9), dtype=bool)
    grid[1, 2:6] = True  # one run of blocked cells
    grid[3, 0] = grid[3, 8] = True  # two single ones
    svg = aco.Map(grid, name="three runs")._repr_svg_()
    obstacles = svg[svg.index('<g id="obstacles"'):]
    obstacles = obstacles[:obstacles.index("</g>")]
    assert obstacles.count("<rect") == 3
    assert ">three runs</text>" in svg
    assert "<circle" not in svg and "convergence" not in svg  # no start, goal or run

    terrain = aco.Map(np.add.outer(np.arange(10.0), np.arange(40.0)), cell_size=2.0)._repr_svg_()
    picture_height = float(re.search(r'<svg [^>]*height="([0-9.]+)"', terrain).group(1))
    legend_top = float(re.search(r'id="height-legend" transform="translate\([0-9.]+,([0-9.]+)\)', terrain).group(1))
    assert legend_top + 28 < picture_height  # the legend's values inside the picture


def test_plot_draws_terrain_and_paths_in_the_same_world_units():
    # A terrain of cell size 2.5 whose column 5 has no data but in row 7: every path passes (5, 7).
    heights = np.ones((10, 12))
    heights[:, 5] = np.nan
    heights[7, 5] = 1.0
    terrain = aco.Map(heights, cell_size=2.5)
    result = aco.plan(terrain, (0, 0), (11, 0), ants=5, iterations=5, seed=1)
    ax = aco.plot(result)
    image = ax.get_images()[0]
    left, right, bottom, top = image.get_extent()
    assert (left, right, bottom, top) == (-1.25, 28.75, 23.75, -1.25)
    lines = {line.get_label(): np.column_stack(line.get_xydata().T) for line in ax.get_lines()}
    assert np.allclose(lines["path"], result.path[:, :2])
    assert np.allclose(lines["goal"], [[11 * 2.5, 0]])
    # Each drawn vertex of the grid path, read back through the image's extent, is a cell with data.
    columns = np.floor((lines["grid path"][:, 0] - left) / (right - left) * heights.shape[1]).astype(int)
    rows = np.floor((lines["grid path"][:, 1] - top) / (bottom - top) * heights.shape[0]).astype(int)
    assert np.isfinite(heights[rows, columns]).all()
    assert (5, 7) in set(zip(columns.tolist(), rows.tolist()))


def test_plot_draws_the_map_a_run_planned_on_and_a_map_alone():
    result = aco.plan(MAP1, (0, 0), (19, 19), iterations=3, seed=1)
    ax = aco.plot(result)
    assert np.array_equal(ax.get_images()[0].get_array(), aco.Map.load(MAP1).array)
    ax = aco.plot(aco.Map.load(MAP1))
    assert len(ax.get_images()) == 1 and not ax.get_lines()


def test_a_result_not_planned_here_has_no_picture():
    planned = aco.plan(MAP1, (0, 0), (19, 19), iterations=3, seed=1)
    copy = aco.Result(planned.json, planned.preset)
    assert copy._repr_svg_() is None
    with pytest.raises(aco.Error, match="only a result of aco.plan"):
        aco.plot(copy)


def test_pictures_and_the_map_come_from_the_run_not_from_the_file_again(tmp_path):
    copy = tmp_path / "map1.txt"
    shutil.copy(MAP1, copy)
    result = aco.plan(copy, (0, 0), (19, 19), iterations=3, seed=1, svg=tmp_path / "plan.svg", svg_pheromone=True)
    copy.unlink()  # what the run read is all its pictures need
    assert result._repr_svg_() == (tmp_path / "plan.svg").read_text()
    assert "pheromone" in result._repr_svg_()
    planned_on = aco.plot(result).get_images()[0].get_array()
    assert np.array_equal(planned_on, aco.Map.load(MAP1).array)
    assert aco._pictures.run_map(result).file == str(copy)