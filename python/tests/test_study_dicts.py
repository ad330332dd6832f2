"""Studies from Python objects: an experiment as a dict, configurations holding Python plugin
objects, and compare() refusing a baseline the frame does not have."""
import sys

import pandas as pd
import pytest

import aco
from conftest import MAP1, SOURCE

sys.path.insert(0, str(SOURCE / "examples" / "python"))
from ant_system import AntSystem  # noqa: E402  (Ant System in numpy, bit for bit update/ant_system)

EXPERIMENT = {
    "name": "dict",
    "seed": 3,
    "repetitions": 2,
    "problems": [{"name": "down", "map": str(MAP1), "start": [0, 0], "goal": [19, 19]}],
    "settings": {"preset": "ant-system", "ants": 8, "iterations": 6},
    "baseline": {"name": "ant system"},
    "configurations": [{"name": "max-min", "update": "max_min", "update.rho": 0.2}],
}
MEASURES = ["problem", "configuration", "repetition", "seed", "length", "iterations", "ant_steps"]


def yaml_of(experiment):
    import json
    return json.dumps(experiment)  # JSON is YAML


def test_a_dict_is_the_experiment_its_file_would_be(tmp_path):
    (tmp_path / "dict.yaml").write_text(yaml_of(EXPERIMENT))
    by_file = aco.run_experiment(tmp_path / "dict.yaml", tmp_path / "file.db", progress=False)
    by_dict = aco.run_experiment(EXPERIMENT, tmp_path / "dict.db", progress=False)
    assert by_dict["trials"] == by_file["trials"] == 4 and not by_dict["failures"]
    pd.testing.assert_frame_equal(aco.read_database(tmp_path / "dict.db")[MEASURES],
                                  aco.read_database(tmp_path / "file.db")[MEASURES])
    assert aco.run_experiment(EXPERIMENT, tmp_path / "dict.db", progress=False)["skipped"] == 4  # it continues


def test_relative_paths_of_a_dict_start_from_the_current_directory(tmp_path, monkeypatch):
    monkeypatch.chdir(MAP1.parent)
    relative = {**EXPERIMENT, "problems": [{"name": "down", "map": MAP1.name, "start": [0, 0], "goal": [19, 19]}]}
    assert aco.run_experiment(relative, tmp_path / "relative.db", progress=False)["ran"] == 4


def test_a_configuration_may_hold_a_python_plugin_object(tmp_path):
    experiment = {**EXPERIMENT, "configurations": [{"name": "numpy ant system", "update": AntSystem()}]}
    summary = aco.run_experiment(experiment, tmp_path / "live.db", progress=False)
    assert summary["trials"] == 4 and not summary["failures"]
    runs = aco.read_database(tmp_path / "live.db")
    assert set(runs["config.update"]) == {"ant_system", "python"}
    native = runs[runs["configuration"] == "ant system"].reset_index(drop=True)
    python = runs[runs["configuration"] == "numpy ant system"].reset_index(drop=True)
    for column in ("length", "ant_steps", "best_iteration"):
        assert list(python[column]) == list(native[column]), column
    assert not [name for name in dir(aco._live) if not name.startswith("__")]  # let go after the call
    again = {**EXPERIMENT, "configurations": [{"name": "numpy ant system", "update": AntSystem()}]}
    assert aco.run_experiment(again, tmp_path / "live.db", progress=False)["skipped"] == 4


def test_a_configuration_given_a_class_makes_an_object_per_trial(tmp_path):
    made = []

    class Counted(AntSystem):
        def __init__(self):
            super().__init__()
            made.append(self)

    experiment = {**EXPERIMENT, "configurations": [{"name": "counted", "update": Counted}]}
    assert aco.run_experiment(experiment, tmp_path / "class.db", progress=False)["ran"] == 4
    assert len(made) == EXPERIMENT["repetitions"]  # the trials of "counted"; the baseline's are native


@pytest.mark.parametrize("change, message", [
    ({"configurations": [{"update": "max_min"}]}, "the experiment dict: every configuration needs a 'name'"),
    ({"configurations": [{"name": "x", "deadlock": AntSystem()}]}, "a Python object can fill the slots"),
    ({"repetitions": AntSystem()}, "in the experiment dict: its values are text, numbers, lists and dicts"),
    ({"problems": []}, "the experiment dict: 'problems' must be a non-empty list"),
])
def test_a_wrong_dict_is_an_error_naming_it(tmp_path, change, message):
    with pytest.raises(aco.Error) as error:
        aco.run_experiment({**EXPERIMENT, **change}, tmp_path / "wrong.db", progress=False)
    assert message in str(error.value)


def test_a_negative_thread_count_is_refused(tmp_path):
    with pytest.raises(aco.Error, match=r"threads: -1 is outside the range \[0, 1024\]"):
        aco.run_experiment(EXPERIMENT, tmp_path / "threads.db", threads=-1)


def test_compare_refuses_a_baseline_the_frame_does_not_have():
    frame = pd.DataFrame({"problem": ["p"] * 4, "configuration": ["max-min", "max-min", "ant system", "ant system"],
                          "solved": [True] * 4, "length": [1.0, 2.0, 3.0, 4.0]})
    with pytest.raises(aco.Error) as error:
        aco.stats.compare(frame, baseline="maxmin")
    assert str(error.value) == ("baseline 'maxmin' is not a configuration of the frame; its configurations: "
                                "'max-min', 'ant system'")
    assert list(aco.stats.compare(frame, baseline="max-min")["configuration"]) == ["ant system"]
