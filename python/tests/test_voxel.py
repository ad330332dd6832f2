"""Voxel worlds from Python: 3D arrays ([z, y, x]), .3dmap and OctoMap files, cells (x, y, z),
.3dscen scenarios, studies and pictures, as acoplan and acobench plan them."""
import numpy as np
import pytest

import aco
from conftest import MAP1, SOURCE, acoplan_json, without_times

SIMPLE = SOURCE / "data" / "maps" / "voxel" / "warframe" / "Simple.3dmap"
HALL = SOURCE / "data" / "maps" / "octomap" / "hall.bt"


def wall_world():
    """10 wide, 6 high, 5 layers: a wall across x = 5 on layers 0 to 3, so a path from (0, 3, 0) to
    (9, 3, 0) climbs over it on layer 4."""
    world = np.zeros((5, 6, 10), dtype=bool)  # [z, y, x]
    world[0:4, :, 5] = True
    return world


def test_a_3d_array_is_a_voxel_world_indexed_z_y_x():
    world = aco.Map(wall_world())
    assert world.volumetric and world.kind == "occupancy"
    assert (world.width, world.height, world.depth) == (10, 6, 5)
    assert repr(world) == "aco.Map('numpy voxel world 10x6x5', voxel world, 10x6x5)"
    flat = aco.Map(np.zeros((6, 10), dtype=bool))
    assert not flat.volumetric and flat.depth == 1
    # Voxel (5, 2, 3) is array[3, 2, 5]: blocked; (5, 2, 4) above the wall is free.
    with pytest.raises(aco.Error, match=r"start \(5,2,3\) is blocked"):
        aco.plan(world, (5, 2, 3), (9, 3, 0))
    assert aco.astar(world, (5, 2, 4), (9, 3, 0)).solved


def test_a_voxel_world_plans_in_3d_with_the_voxel_preset():
    result = aco.plan(wall_world(), (0, 3, 0), (9, 3, 0), seed=3, iterations=20)
    assert result.solved and result.volumetric and result.depth == 5
    assert result.preset == "voxel" and result.config["neighbourhood"] == "26"
    assert result.path.shape[1] == 3 and result.path_cells.shape == result.path.shape
    assert result.grid_path.shape[1] == 3
    assert tuple(result.grid_path[0]) == (0, 3, 0) and tuple(result.grid_path[-1]) == (9, 3, 0)
    over = result.grid_path[result.grid_path[:, 0] == 5]
    assert len(over) and (over[:, 2] == 4).all()  # over the wall, on its only free layer
    assert not wall_world()[result.grid_path[:, 2], result.grid_path[:, 1], result.grid_path[:, 0]].any()
    exact = aco.astar(wall_world(), (0, 3, 0), (9, 3, 0))
    assert exact.grid_length == pytest.approx(exact.optimal_length)
    assert result.grid_length >= exact.optimal_length - 1e-9 and result.gap_percent >= 0
    assert result.json["start"] == [0, 3, 0] and result.json["depth"] == 5


def test_an_unsolved_voxel_run_has_empty_3d_arrays():
    world = wall_world()
    world[4, :, 5] = True  # the wall reaches the top
    result = aco.plan(world, (0, 3, 0), (9, 3, 0), seed=1, iterations=3)
    assert not result.solved
    assert result.path.shape == (0, 3) and result.grid_path.shape == (0, 3)


def test_a_voxel_array_plans_as_its_3dmap_file_and_as_acoplan(tmp_path):
    world = aco.Map(wall_world())
    file = tmp_path / "wall.3dmap"
    world.save(file)
    loaded = aco.Map.load(file)
    assert loaded.volumetric and np.array_equal(loaded.array, world.array)
    from_array = aco.plan(world, (0, 3, 0), (9, 3, 0), seed=4, iterations=10)
    from_file = aco.plan(file, (0, 3, 0), (9, 3, 0), seed=4, iterations=10)
    assert np.array_equal(from_array.grid_path, from_file.grid_path) and from_array.length == from_file.length
    cli = acoplan_json("--map", file, "--start", "0,3,0", "--goal", "9,3,0", "--seed", "4", "--iterations", "10")
    assert without_times(from_file.json) == without_times(cli)
    assert from_file.preset == "voxel"


def test_the_bundled_voxel_files_load():
    simple = aco.Map.load(SIMPLE)
    assert simple.volumetric and simple.array.shape == (simple.depth, simple.height, simple.width)
    assert (simple.width, simple.height, simple.depth) == (105, 132, 105)
    assert "105x132x105" in repr(simple)
    try:
        hall = aco.Map.load(HALL)
    except aco.Error as error:  # a build without OctoMap has no map/octomap plugin
        pytest.skip(str(error))
    assert hall.volumetric and hall.array.any()
    free = np.argwhere(~hall.array)[:, ::-1]  # (x, y, z) of the free voxels, [z, y, x] reversed
    result = aco.astar(hall, tuple(free[0]), tuple(free[-1]))
    assert result.solved and result.preset == "voxel" and result.grid_path.shape[1] == 3


def test_scenarios_of_a_3dscen_have_voxels_and_their_optimum():
    scenarios = aco.load_scenarios(str(SIMPLE) + ".3dscen")
    assert len(scenarios) > 10
    s = scenarios[0]
    assert s.map == str(SIMPLE) and len(s.start) == 3 and len(s.goal) == 3
    assert s.bucket == 0 and s.width == 0
    exact = aco.astar(s.map, s.start, s.goal)
    assert exact.optimal_length == pytest.approx(s.optimal_length, abs=1e-6)


@pytest.mark.parametrize("map_kind", ["array", "file"])
def test_a_voxel_world_wants_three_coordinates_and_a_grid_two(map_kind, tmp_path):
    world = aco.Map(wall_world())
    if map_kind == "file":
        world.save(tmp_path / "wall.3dmap")
        world = tmp_path / "wall.3dmap"
    with pytest.raises(aco.Error, match=r"start \(0,3\) has no z, but .* is a 10x6x5 voxel world: give its cells "
                                        r"as \(x, y, z\)"):
        aco.plan(world, (0, 3), (9, 3, 0))
    with pytest.raises(aco.Error, match=r"goal \(9,3\) has no z"):
        aco.plan(world, (0, 3, 0), (9, 3))
    grid = MAP1 if map_kind == "file" else np.zeros((20, 20), dtype=bool)
    with pytest.raises(aco.Error, match=r"start \(0,0,0\) has a z, but .* is a 20x20 2D map: give its cells as "
                                        r"\(x, y\)"):
        aco.plan(grid, (0, 0, 0), (19, 19))
    with pytest.raises(aco.Error, match=r"goal \(9,3,5\) is outside the 10x6x5 voxel world"):
        aco.plan(world, (0, 3, 0), (9, 3, 5))
    with pytest.raises(aco.Error, match=r"start must be a cell \(x, y\), or \(x, y, z\)"):
        aco.plan(world, (0, 3, 0, 1), (9, 3, 0))


def test_planners_and_plugins_without_3d_are_refused_with_their_message():
    world = wall_world()
    with pytest.raises(aco.Error, match="is a voxel world") as error:
        aco.plan(world, (0, 3, 0), (9, 3, 0), planner="pso")
    assert "pso" in str(error.value)
    with pytest.raises(aco.Error, match="is a voxel world") as error:
        aco.plan(world, (0, 3, 0), (9, 3, 0), smoother="taut")
    assert "taut" in str(error.value)


@pytest.mark.parametrize("array, kind, message", [
    (np.full((2, 3, 4), 0.5), None, "a 3D float array is a voxel world"),
    (np.zeros((2, 3, 4)), "terrain", "a terrain's heights are a 2D array"),
    (np.zeros((2, 0, 4), dtype=bool), None, "must be 2D"),
    (np.zeros((2, 2, 2, 2), dtype=bool), None, "or 3D (a voxel world, [z, y, x])"),
])
def test_a_bad_3d_array_is_refused(array, kind, message):
    with pytest.raises(aco.Error, match=message.replace("(", r"\(").replace(")", r"\)").replace("[", r"\[")):
        aco.Map(array, kind=kind)


def test_a_3d_float_array_of_0_and_1_and_free_work_as_on_a_grid():
    assert np.array_equal(aco.Map(wall_world().astype(np.float64)).array, wall_world())
    assert np.array_equal(aco.Map(np.where(wall_world(), 7, 1), free=1).array, wall_world())
    with pytest.raises(aco.Error, match="cell_size is 1"):
        aco.Map(wall_world(), cell_size=2.0)
    with pytest.raises(aco.Error, match="saved as a Moving AI voxel map"):
        aco.Map(wall_world()).save("wall.map")


def test_a_study_plans_a_3dmap_problem_given_as_a_list_or_as_text(tmp_path):
    world = tmp_path / "wall.3dmap"
    aco.Map(wall_world()).save(world)
    experiment = {
        "name": "voxels",
        "problems": [{"name": "list", "map": str(world), "start": [0, 3, 0], "goal": [9, 3, 0]},
                     {"name": "text", "map": str(world), "start": "0,3,0", "goal": "9,3,4"}],
        "settings": {"iterations": 5, "ants": 5, "neighbourhood": 26},
        "configurations": [{"name": "mmas", "update": "max_min"}],
        "repetitions": 2,
    }
    summary = aco.run_experiment(experiment, tmp_path / "voxels.db", progress=False)
    assert summary["ran"] == 8 and not summary["failures"], summary["failures"]  # the baseline and mmas
    runs = aco.read_database(tmp_path / "voxels.db")
    assert set(runs["problem"]) == {"list", "text"} and runs["solved"].all()
    assert (runs["gap_percent"] >= 0).all()
    experiment["problems"][0]["start"] = [0, 3]
    with pytest.raises(aco.Error, match=r"'start' has no z, but the problem's map is a voxel world: give its cells as "
                                        r"\[x, y, z\]"):
        aco.run_experiment(experiment, tmp_path / "other.db", progress=False)
    experiment["problems"][0]["start"] = [0, 3, 0]
    experiment["problems"][0]["goal"] = [9, 3, 0, 1]
    with pytest.raises(aco.Error, match=r"'goal' must be a cell \[x, y, z\]"):
        aco.run_experiment(experiment, tmp_path / "other.db", progress=False)


def test_a_voxel_run_draws_the_voxel_svg(tmp_path):
    result = aco.plan(wall_world(), (0, 3, 0), (9, 3, 0), seed=2, iterations=5, svg=tmp_path / "run.svg")
    picture = (tmp_path / "run.svg").read_text()
    assert picture == result._repr_svg_()
    assert picture.startswith("<svg") and 'id="slices"' in picture
    assert "numpy voxel world 10x6x5: length" in picture
    world_picture = aco.Map(wall_world())._repr_svg_()
    assert world_picture.startswith("<svg") and 'id="slices"' in world_picture
    s = aco.load_scenarios(str(SIMPLE) + ".3dscen")[0]
    assert 'id="slices"' in aco.astar(s.map, s.start, s.goal)._repr_svg_()  # a map file read again
    with pytest.raises(aco.Error, match="draws no pheromone field"):
        aco.plan(wall_world(), (0, 3, 0), (9, 3, 0), svg_pheromone=True)


def test_plot_draws_a_voxel_world_on_3d_axes():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    result = aco.plan(wall_world(), (0, 3, 0), (9, 3, 0), seed=2, iterations=5)
    ax = aco.plot(result)
    assert hasattr(ax, "zaxis") and ax.get_zlabel() == "z (layer)"
    labels = [line.get_label() for line in ax.get_lines()]
    assert labels == ["grid path", "path", "start", "goal"]
    plt.close(ax.figure)
    _, flat = plt.subplots()
    with pytest.raises(aco.Error, match="is a voxel world: plot\\(\\) draws it on 3D axes"):
        aco.plot(aco.Map(wall_world()), ax=flat)
    plt.close("all")
