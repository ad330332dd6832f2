"""The package as Python sees it: its version, names, error class, run keys and typed defaults."""
import pickle
import subprocess
import traceback

import numpy as np
import pytest

import aco
from aco._planning import _key

PYTHON_TYPES = {"int": int, "real": float, "bool": bool, "categorical": str, "text": str}


def test_the_version_is_the_frameworks_as_acoplan_prints_it(build):
    printed = subprocess.run([str(build / "hosts" / "acoplan" / "acoplan"), "--version"], capture_output=True,
                             text=True, check=True).stdout
    assert printed.split()[:2] == ["acoplan", aco.__version__]


def test_the_public_names_are_those_of_all():
    assert {name for name in dir(aco) if not name.startswith("_")} == set(aco.__all__)
    assert all(hasattr(aco, name) for name in aco.__all__)


def test_errors_are_aco_errors_in_tracebacks_and_value_errors():
    assert aco.Error.__module__ == "aco" and issubclass(aco.Error, ValueError)
    assert "ValueError" in aco.Error.__doc__
    with pytest.raises(aco.Error) as raised:
        aco.plan(np.zeros((5, 5), bool), (0, 0), (4, 4), ants=0)
    assert traceback.format_exception_only(raised.type, raised.value)[0].startswith("aco.Error: ")
    assert str(pickle.loads(pickle.dumps(raised.value))) == str(raised.value)


def test_run_keys_are_acoplans_options_spelled_as_plan_takes_them(build):
    help_text = subprocess.run([str(build / "hosts" / "acoplan" / "acoplan"), "--help"], capture_output=True,
                               text=True, check=True).stdout
    keys = aco.run_keys()
    assert {"ants", "seed", "max-slope", "neighbourhood", "planner", "update", "ifwa.radius"} <= {k["key"] for k in keys}
    for key in keys:
        assert f"--{key['key']} " in help_text, key
        assert _key(key["keyword"]) == key["key"], key
    assert not {"map", "start", "goal", "scen"} & {k["key"] for k in keys}, "plan() takes these as arguments"


def test_run_key_defaults_are_typed_and_plan_takes_each_as_its_keyword():
    keys = aco.run_keys()
    for key in keys:
        assert type(key["default"]) is PYTHON_TYPES[key["type"]], key
    slot = next(k for k in keys if k["key"] == "update")
    assert slot["group"] == "slot" and slot["default"] in slot["range"].split(",")
    # Every default, given as its keyword, is taken and is the run's value (not the preset's).
    defaults = {k["keyword"]: k["default"] for k in keys if k["group"] in ("colony", "graph")}
    result = aco.plan(np.zeros((10, 10), bool), (0, 0), (9, 9), **defaults)
    for key in keys:
        if key["group"] in ("colony", "graph"):
            assert result.config[key["key"]] == key["default"], key


def test_plugin_parameter_defaults_are_typed():
    parameters = [p for plugin in aco.plugins() for p in plugin["parameters"]]
    assert parameters
    for parameter in parameters:
        assert type(parameter["default"]) is PYTHON_TYPES[parameter["type"]], parameter
        if parameter["type"] == "categorical":
            assert parameter["default"] in parameter["range"].split(","), parameter
