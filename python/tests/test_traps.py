"""No silent traps: the kind of an array, units, messages in Python's spelling, maps and scenarios
saved and read, and the small wrongs of a result's repr and gap."""
import numpy as np
import pytest

import aco
from conftest import MAP1, SOURCE

SCENARIOS = SOURCE / "data" / "maps" / "generated" / "maze64-2-s1.map.scen"


def wall_grid():
    """A 0/1 grid with a wall that leaves a gap at the bottom: a straight line would cross it."""
    grid = np.zeros((12, 16), dtype=np.uint8)
    grid[0:10, 7] = 1
    return grid


# The kind of an array.

def test_a_float_array_of_0_and_1_is_refused_until_its_kind_is_said():
    grid = wall_grid()
    with pytest.raises(aco.Error, match="kind='occupancy'"):
        aco.plan(grid.astype(float), (0, 5), (15, 5), seed=1)
    explicit = aco.plan(grid.astype(float), (0, 5), (15, 5), kind="occupancy", seed=1)
    assert explicit.preset == "robust"
    assert not grid[explicit.grid_path[:, 1], explicit.grid_path[:, 0]].any()  # no cell of the wall
    assert explicit.json["grid_path"] == aco.plan(grid.astype(bool), (0, 5), (15, 5), seed=1).json["grid_path"]
    assert aco.Map(grid.astype(float), kind="terrain").kind == "terrain"
    assert aco.plan(grid.astype(float), (0, 5), (15, 5), kind="terrain", seed=1).preset == "terrain"


def test_free_says_which_value_is_free():
    grid = wall_grid()
    inverted = aco.Map(1 - grid, free=1)
    assert inverted.kind == "occupancy"
    assert np.array_equal(inverted.array, grid == 1)
    assert np.array_equal(aco.Map(grid.astype(float), kind="occupancy").array, grid == 1)


@pytest.mark.parametrize("call, message", [
    (lambda: aco.Map(wall_grid(), kind="grid"), "kind must be 'occupancy' or 'terrain', not 'grid'"),
    (lambda: aco.Map(np.ones((3, 3)) * 2.5, kind="terrain", free=0), "free= says which value of an occupancy grid"),
    (lambda: aco.plan(MAP1, (0, 0), (19, 19), kind="occupancy"), "kind= and free= describe a numpy array"),
    (lambda: aco.Map(str(MAP1)), "aco.Map.load(path)"),
])
def test_a_kind_that_cannot_be_is_refused(call, message):
    with pytest.raises(aco.Error) as error:
        call()
    assert message in str(error.value)


def test_a_heights_array_is_still_a_terrain_without_kind():
    assert aco.Map(np.array([[0.0, 1.0], [0.5, 1.0]])).kind == "terrain"
    assert aco.Map(np.array([[0.0, 1.0], [np.nan, 1.0]])).kind == "terrain"  # no data: heights


# Units.

def test_path_cells_are_the_path_in_cells_on_a_terrain_of_any_cell_size():
    y, x = np.mgrid[0:20, 0:20]
    heights = np.exp(-((x - 10) ** 2 + (y - 10) ** 2) / 20.0)
    result = aco.plan(aco.Map(heights, cell_size=2.5), (0, 3), (19, 15), seed=2)
    assert result.cell_size == 2.5
    assert result.path.shape[1] == 3
    assert np.allclose(result.path_cells, result.path[:, :2] / 2.5)
    assert tuple(result.path_cells[0]) == (0, 3) and tuple(result.path_cells[-1]) == (19, 15)
    grid = aco.plan(MAP1, (0, 0), (19, 19), seed=2)
    assert grid.cell_size == 1.0 and np.array_equal(grid.path_cells, grid.path)


def test_a_terrain_files_cell_size_comes_with_the_result():
    file = SOURCE / "data" / "terrain" / "epf20.asc"
    result = aco.plan(file, (0, 10), (19, 8), seed=1)
    assert result.cell_size == aco.Map.load(file).cell_size != 1.0
    assert tuple(result.path_cells[-1]) == (19, 8)


# Messages in Python's spelling.

@pytest.mark.parametrize("keys, message", [
    (dict(ant=10), "unknown key 'ant'; did you mean 'ants'?"),
    (dict(update_rh=0.1), "did you mean 'update_rho'?"),
    (dict(update_rho=3), "update_rho: 3 is outside the range [1e-06, 1]"),
    (dict(max_slop=3), "did you mean 'max_slope'?"),
    (dict(threads=-1), "threads: -1 is outside the range [0, 1024]"),
    (dict(threads=2000), "threads: 2000 is outside the range [0, 1024]"),
    (dict(threads=0.5), "threads: 0.5 is not a whole number"),
    (dict(max_memory="1K"), "max_memory"),
    (dict(max_memory="lots"), "max_memory: 'lots'"),
    (dict(map_format="zzz"), "map_format: unknown map format 'zzz'"),
    (dict(map_format="zzz"), "aco.plugins() shows them as map/NAME"),
    (dict(colonies=2, search="bidirectional"), "the single search only (search single)"),
    (dict(preset="robust", config="my.ini"), "config and preset: give one of them"),
])
def test_keys_are_spelled_as_keywords(keys, message):
    with pytest.raises(aco.Error) as error:
        aco.plan(MAP1, (0, 0), (19, 19), **keys)
    assert message in str(error.value)
    assert "--" not in str(error.value)


def test_the_huge_map_message_names_max_memory(tmp_path):
    huge = tmp_path / "huge.map"
    huge.write_text("type octile\nheight 100000\nwidth 100000\nmap\n")
    with pytest.raises(aco.Error, match="change it with max_memory="):
        aco.plan(huge, (0, 0), (1, 1))
    with pytest.raises(aco.Error, match="set by max_memory="):
        aco.plan(huge, (0, 0), (1, 1), max_memory="1G")


@pytest.mark.parametrize("shape", [(100000, 100000), (2000, 2000, 2000)])
def test_a_huge_strided_view_is_refused_before_numpy_computes_over_it(shape):
    # Every cell the same byte: numpy would allocate the whole view to compare it (issue 56).
    view = np.lib.stride_tricks.as_strided(np.zeros(1, dtype=bool), shape=shape, strides=(0,) * len(shape))
    with pytest.raises(aco.Error, match=r"a map array of shape .* cells, more than the graph's 32-bit node ids allow"):
        aco.plan(view, (0,) * len(shape), (1,) * len(shape))


def test_max_memory_lets_a_map_that_fits_plan():
    assert aco.plan(MAP1, (0, 0), (19, 19), seed=1, max_memory="1G").solved
    assert aco.plan(MAP1, (0, 0), (19, 19), seed=1, max_memory=1 << 30).solved


def test_a_scenario_key_points_to_load_scenarios():
    with pytest.raises(aco.Error) as error:
        aco.plan(MAP1, (0, 0), (19, 19), scen="x.map.scen")
    assert "aco.load_scenarios(path)" in str(error.value) and "argument of plan()" not in str(error.value)


def test_a_python_object_in_a_slot_without_python_plugin_names_the_slots_that_take_one():
    class Deadlock:
        pass

    with pytest.raises(aco.Error) as error:
        aco.plan(MAP1, (0, 0), (19, 19), deadlock=Deadlock())
    message = str(error.value)
    assert "a Python object can fill the slots init, heuristic, update only" in message
    assert "give the deadlock plugin's name" in message and "unknown deadlock plugin" not in message


@pytest.mark.parametrize("start", [(0.7, 0), (0, np.float64(2.5))])
def test_a_fractional_cell_is_refused_not_cut_off(start):
    with pytest.raises(aco.Error, match="is not a cell: x and y count columns and rows, in whole numbers"):
        aco.plan(MAP1, start, (19, 19))


def test_whole_numbers_of_any_type_are_cells():
    whole = aco.plan(MAP1, (0.0, np.int64(0)), (np.float32(19), 19), seed=4, iterations=3)
    assert whole.json["grid_path"] == aco.plan(MAP1, (0, 0), (19, 19), seed=4, iterations=3).json["grid_path"]


# Maps and scenarios saved and read.

@pytest.mark.parametrize("name", ["grid.map", "grid.txt"])
def test_an_occupancy_grid_saved_loads_as_it_was(tmp_path, name):
    grid = aco.Map(wall_grid())
    grid.save(tmp_path / name)
    loaded = aco.Map.load(tmp_path / name)
    assert loaded.kind == "occupancy" and np.array_equal(loaded.array, grid.array)
    on_file = aco.plan(tmp_path / name, (0, 5), (15, 5), seed=3, iterations=5)
    assert on_file.json["grid_path"] == aco.plan(grid, (0, 5), (15, 5), seed=3, iterations=5).json["grid_path"]


def test_a_terrain_saved_loads_as_it_was(tmp_path):
    rng = np.random.default_rng(5)
    heights = rng.uniform(-10000.0, 10.0, (6, 9))
    heights[2, 3] = np.nan
    heights[4, 4] = -9999.0  # the usual NODATA marker, here a height
    terrain = aco.Map(heights, cell_size=0.3)
    terrain.save(tmp_path / "hill.asc")
    loaded = aco.Map.load(tmp_path / "hill.asc")
    assert loaded.kind == "terrain" and loaded.cell_size == 0.3
    assert np.array_equal(loaded.array, heights, equal_nan=True)


@pytest.mark.parametrize("array, name, message", [
    (wall_grid(), "grid.asc", "an occupancy grid is saved as a Moving AI .map or a 0/1 matrix (.txt), not .asc"),
    (np.ones((3, 3)) * 2.5, "hill.map", "a terrain is saved as an ESRI ASCII grid, a file ending in .asc"),
])
def test_a_map_is_saved_in_a_format_of_its_kind_only(tmp_path, array, name, message):
    with pytest.raises(aco.Error, match=message.replace(".", r"\.").replace("(", r"\(").replace(")", r"\)")):
        aco.Map(array).save(tmp_path / name)


def test_scenarios_are_the_files_problems_with_astars_optimum():
    scenarios = aco.load_scenarios(SCENARIOS)
    lines = SCENARIOS.read_text().splitlines()[1:]
    assert len(scenarios) == len(lines) == 20
    first = scenarios[0]
    bucket, _, width, height, sx, sy, gx, gy, optimum = lines[0].split("\t")
    assert first.map == str(SCENARIOS)[:-len(".scen")]
    assert (first.bucket, first.width, first.height) == (int(bucket), int(width), int(height))
    assert first.start == (int(sx), int(sy)) and first.goal == (int(gx), int(gy))
    for scenario in scenarios[:5]:
        exact = aco.astar(scenario.map, scenario.start, scenario.goal)
        assert exact.optimal_length == pytest.approx(scenario.optimal_length, abs=1e-6)


def test_a_missing_scenario_file_is_an_error():
    with pytest.raises(aco.Error, match="nowhere.map.scen"):
        aco.load_scenarios(SOURCE / "nowhere.map.scen")


# A result's repr and gap.

def test_an_astar_result_shows_no_iterations_or_preset_and_has_no_gap():
    exact = aco.astar(MAP1, (0, 0), (19, 19))
    assert "iterations" not in repr(exact) and "preset" not in repr(exact)
    assert repr(exact).startswith("<aco.Result length") and repr(exact).endswith("ms, planner astar>")
    assert exact.gap_percent == 0.0
    colony = aco.plan(MAP1, (0, 0), (19, 19), seed=1, iterations=4)
    assert "4 iterations" in repr(colony) and "preset robust" in repr(colony)


def test_a_gap_is_exactly_zero_within_rounding_only():
    record = aco.astar(MAP1, (0, 0), (19, 19)).json
    optimum = record["optimal_length"]
    assert aco.Result({**record, "grid_length": optimum * (1 + 1e-15)}, "robust").gap_percent == 0.0
    assert aco.Result({**record, "grid_length": optimum * (1 + 1e-6)}, "robust").gap_percent == pytest.approx(1e-4)
