"""aco.simulate(): acosim's engine from Python, with acosim's results and messages."""
import json
import subprocess

import numpy as np
import pytest

import aco
from conftest import BUILD, SOURCE

STATIC = SOURCE / "data" / "scenarios" / "paper003_static.yaml"


def acosim(*args):
    out = subprocess.run([str(BUILD / "hosts" / "acosim" / "acosim"), *map(str, args)], capture_output=True, text=True,
                         check=False)
    assert out.returncode in (0, 3), out.stderr
    return out.stdout


def test_a_simulation_from_python_is_acosims(tmp_path):
    simulation = aco.simulate(STATIC)
    assert simulation.json == json.loads(acosim(STATIC, "--json"))
    assert simulation.reached and simulation.outcome == "reached"
    # The trajectory's columns are acosim --csv's, one row per control step and the start.
    acosim(STATIC, "--csv", tmp_path / "trajectory.csv")
    csv = np.genfromtxt(tmp_path / "trajectory.csv", delimiter=",", names=True)
    assert list(csv.dtype.names) == list(simulation.trajectory)
    for column in csv.dtype.names:
        assert np.allclose(simulation.trajectory[column], csv[column], rtol=1e-9)
    assert len(simulation.trajectory["t"]) == simulation.steps + 1
    assert simulation.moving.shape == (simulation.steps + 1, 0, 2)  # the scenario has no moving obstacle
    assert simulation.sensed.shape == (3, 2) and simulation.plans[0].shape[1] == 2
    assert simulation._repr_svg_() == simulation.svg() and 'id="unknown"' in simulation.svg()


def test_run_keys_go_over_the_scenarios_as_on_acosims_command_line():
    blind = aco.simulate(STATIC, local="track")
    assert blind.json == json.loads(acosim(STATIC, "--local", "track", "--json"))
    assert blind.config["local"] == "track"


def test_a_dict_is_a_scenario_with_its_paths_from_the_current_folder(monkeypatch):
    monkeypatch.chdir(SOURCE / "data")
    scenario = {"run": {"config": "scenarios/paper003.ini", "map": "maps/papers/paper003_20.map", "start": [0, 0],
                        "goal": [19, 19]},
                "unknown": [[5, 6], [9, 10], [12, 15]]}
    from_dict = aco.simulate(scenario).json
    from_file = aco.simulate(STATIC).json
    assert from_dict.pop("scenario") != from_file.pop("scenario")
    assert from_dict == from_file


def test_a_bad_scenario_gets_acosims_message():
    with pytest.raises(aco.Error, match=r"^the scenario: unknown parameter 'robot.radiuss'; did you mean 'robot.radius'"):
        aco.simulate({"run": {"map": str(SOURCE / "data" / "maps" / "papers" / "paper003_20.map"), "start": [0, 0],
                              "goal": [19, 19]}, "robot": {"radiuss": 1}})
    with pytest.raises(aco.Error, match="'map' is the scenario's, not a run key to change"):
        aco.simulate(STATIC, map="other.map")
    with pytest.raises(aco.Error, match="no_such.yaml"):
        aco.simulate(SOURCE / "no_such.yaml")


def test_a_changed_key_is_named_as_python_writes_it_and_the_scenarios_own_as_yaml_does():
    with pytest.raises(aco.Error, match="unknown parameter 'local_horizn'; did you mean 'local_horizon'"):
        aco.simulate(STATIC, local_horizn=1.0)
    with pytest.raises(aco.Error, match=r"the scenario.*: unknown parameter 'local.horizn'"):
        aco.simulate({"run": {"map": str(SOURCE / "data" / "maps" / "papers" / "paper003_20.map"), "start": [0, 0],
                              "goal": [19, 19], "local": "dwa", "local.horizn": 1}}, ants=5)
