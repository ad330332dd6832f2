"""aco.plan() and aco.Map: the same runs as acoplan, on files and on numpy arrays."""
import inspect

import numpy as np
import pytest

import aco
from conftest import MAP1, SOURCE, acoplan_json, without_times


def test_a_run_from_python_is_acoplans_run_on_the_same_keys():
    result = aco.plan(MAP1, (0, 0), (19, 19), update="max_min", update_rho=0.05, ants=12, iterations=8, seed=5)
    cli = acoplan_json("--map", MAP1, "--start", "0,0", "--goal", "19,19", "--update", "max_min", "--update.rho", "0.05",
                       "--ants", "12", "--iterations", "8", "--seed", "5")
    assert without_times(result.json) == without_times(cli)
    assert result.preset == "robust"
    assert result.config["update.rho"] == 0.05
    assert result.figures["update/max_min.restarts"] == 0  # MAX-MIN's own figure: no restart asked for
    assert result.json["ant_steps"] > 0


def test_keywords_and_the_keys_dict_are_the_same_keys():
    by_keyword = aco.plan(MAP1, (0, 0), (19, 19), update="max_min", update_rho=0.2, fill_dead_ends=False, seed=2, iterations=5)
    by_dict = aco.plan(MAP1, (0, 0), (19, 19), keys={"update": "max_min", "update.rho": 0.2, "fill-dead-ends": False},
                       seed=2, iterations=5)
    assert without_times(by_keyword.json) == without_times(by_dict.json)
    assert by_keyword.config["fill-dead-ends"] is False


def test_a_time_limit_stops_the_colony_inside_an_iteration():
    # Every colony's setup outlasts a nanosecond: each ant sees the limit passed before its first
    # move, on any machine, and the run ends unsolved in its first iteration.
    result = aco.plan(MAP1, (0, 0), (19, 19), time_limit=1e-9, iterations=50, seed=3)
    assert result.json["stopped_by"] == "time"
    assert result.json["iterations"] == 1 and result.json["ant_steps"] == 0
    assert not result.solved
    assert "the time limit (1e-09 s) ended the search in iteration 1" in result.reason
    assert result.config["time-limit"] == 1e-9
    assert aco.plan(MAP1, (0, 0), (19, 19), iterations=5, seed=3).json["stopped_by"] == "iterations"


def test_a_preset_is_acoplans_preset():
    result = aco.plan(MAP1, (0, 0), (19, 19), preset="paper001", seed=4)
    cli = acoplan_json("--preset", "paper001", "--map", MAP1, "--start", "0,0", "--goal", "19,19", "--seed", "4")
    assert without_times(result.json) == without_times(cli)
    assert result.preset == "paper001"


def test_a_numpy_grid_plans_as_its_map_file_does():
    loaded = aco.Map.load(MAP1)
    assert loaded.kind == "occupancy" and loaded.array.shape == (20, 20) and loaded.array.dtype == np.bool_
    from_array = aco.plan(loaded.array.astype(np.uint8), (0, 0), (19, 19), seed=9, iterations=20)
    from_file = aco.plan(loaded, (0, 0), (19, 19), seed=9, iterations=20)
    assert np.array_equal(from_array.grid_path, from_file.grid_path)
    assert from_array.length == from_file.length
    assert from_array.optimal_length == from_file.optimal_length
    assert from_array.solved and from_array.gap_percent >= 0


def test_the_result_holds_arrays():
    grid = np.zeros((12, 16), dtype=bool)
    grid[2:10, 7] = True
    result = aco.plan(grid, (0, 5), (15, 5), seed=1)
    assert result.solved
    assert result.path.shape[1] == 2 and result.path.dtype == np.float64
    assert result.grid_path.shape[1] == 2 and tuple(result.grid_path[0]) == (0, 5) and tuple(result.grid_path[-1]) == (15, 5)
    assert not grid[result.grid_path[:, 1], result.grid_path[:, 0]].any()  # x the column, y the row
    assert result.convergence.shape == (result.iterations,)
    assert result.grid_length >= result.optimal_length - 1e-9 and result.length <= result.grid_length + 1e-9
    assert set(result.plugins) == {"init", "heuristic", "update", "deadlock", "smoother", "local"}


def test_a_float_array_is_a_terrain_with_its_cell_size_and_the_run_keys_slope_limit():
    y, x = np.mgrid[0:30, 0:30]
    heights = 3.0 * np.exp(-((x - 15) ** 2 + (y - 15) ** 2) / 30.0)
    terrain = aco.Map(heights, cell_size=2.0)
    assert terrain.kind == "terrain"
    result = aco.plan(terrain, (0, 15), (29, 15), seed=3)
    assert result.preset == "terrain"
    assert result.path.shape[1] == 3
    assert result.optimal_length > 2.0 * 29 - 1e-9  # cells are 2 units apart
    heights[10:20, :] = np.nan  # a band without data: unreachable
    assert not aco.plan(aco.Map(heights), (0, 0), (0, 29), seed=3).solved


def test_astar_is_the_exact_reference():
    exact = aco.astar(MAP1, (0, 0), (19, 19))
    assert exact.solved and exact.grid_length == pytest.approx(exact.optimal_length)
    assert exact.config["planner"] == "astar"


def test_a_continuous_planner_has_a_path_and_no_grid_path():
    try:
        result = aco.plan(MAP1, (0, 0), (19, 19), planner="ompl", ompl_planner="rrtconnect", ompl_time_limit=10, seed=3)
    except aco.Error as error:  # a build without OMPL has no 'ompl' planner
        pytest.skip(str(error))
    assert result.config["planner"] == "ompl" and result.config["ompl.time_limit"] == 10
    assert result.solved and result.grid_length is None and result.gap_percent is None
    assert result.grid_path.shape == (0, 2) and result.path.shape[1] == 2
    assert list(result.path[0]) == [0, 0] and list(result.path[-1]) == [19, 19]
    assert result.length >= np.hypot(19, 19)
    assert "continuous" in repr(result)
    with pytest.raises(aco.Error, match="ompl.planner"):
        aco.plan(MAP1, (0, 0), (19, 19), planner="ompl", ompl_planner="rrt")


def test_results_do_not_depend_on_the_thread_count():
    one = aco.plan(MAP1, (0, 0), (19, 19), seed=11, threads=1)
    two = aco.plan(MAP1, (0, 0), (19, 19), seed=11, threads=2)
    assert without_times(one.json) == without_times(two.json)


@pytest.mark.parametrize("call, message", [
    (lambda: aco.plan(MAP1, (0, 0), (19, 19), update_rho=3), "update_rho: 3 is outside the range [1e-06, 1]"),
    (lambda: aco.plan(MAP1, (0, 0), (19, 19), update="nope"), "unknown update plugin 'nope'"),
    (lambda: aco.plan(MAP1, (0, 0), (19, 19), preset="robst"), "unknown preset 'robst'; did you mean 'robust'?"),
    (lambda: aco.plan(MAP1, (0, 0), (40, 40)), "goal (40,40) is outside the 20x20 map"),
    (lambda: aco.plan(np.ones((5, 5), dtype=bool), (0, 0), (4, 4)), "start (0,0) is blocked"),
    (lambda: aco.plan(SOURCE / "nowhere.map", (0, 0), (1, 1)), "nowhere.map"),
    (lambda: aco.plan(MAP1, (0, 0), (19, 19), seed=1, keys={"threads": 2}), "'threads' is an argument of plan()"),
    (lambda: aco.plan(MAP1, (0, 0), "19,19"), "goal must be a cell (x, y)"),
    (lambda: aco.Map.load(MAP1, ants=5), "'ants' is not a key of a problem"),
    (lambda: aco.Map.load(MAP1, max_slop=5), "did you mean 'max_slope'?"),
])
def test_mistakes_raise_aco_error_with_the_command_lines_message(call, message):
    with pytest.raises(aco.Error) as error:
        call()
    assert message in str(error.value)


def test_the_same_mistake_gives_acoplans_words_with_the_keyword(build):
    import subprocess
    cli = subprocess.run([str(build / "hosts" / "acoplan" / "acoplan"), "--map", str(MAP1), "--start", "0,0", "--goal",
                          "19,19", "--ants", "0"], capture_output=True, text=True)
    with pytest.raises(aco.Error) as error:
        aco.plan(MAP1, (0, 0), (19, 19), ants=0)
    assert str(error.value).startswith("ants: ")
    assert cli.stderr.strip() == "acoplan: error: --" + str(error.value)


@pytest.mark.parametrize("array", [np.zeros((0, 3)), np.zeros(5), np.array([["a"]])])
def test_a_bad_array_is_refused(array):
    with pytest.raises(ValueError):
        aco.Map(array)


def test_help_explains_every_argument():
    doc = inspect.getdoc(aco.plan)
    for name in inspect.signature(aco.plan).parameters:
        assert name in doc, name
    assert "x the column" in doc
