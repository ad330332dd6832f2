"""Slots given Python objects (update=MyUpdate()) run inside the native colony through the python
bridge plugins, as `--update python --update.class module:Class` does in the hosts."""
import sys

import numpy as np
import pytest

import aco
from conftest import MAP1, SOURCE, without_times

sys.path.insert(0, str(SOURCE / "examples" / "python"))
from ant_system import AntSystem  # noqa: E402  (the bridge's example: Ant System in numpy)

SMALL = dict(preset="ant-system", ants=10, iterations=20, threads=1)


@pytest.mark.parametrize("seed", [1, 2])
def test_an_ant_system_object_is_bit_identical_to_the_cpp_plugin(seed):
    native = aco.plan(MAP1, (0, 0), (19, 19), update="ant_system", seed=seed, **SMALL)
    python = aco.plan(MAP1, (0, 0), (19, 19), update=AntSystem(), seed=seed, **SMALL)
    assert python.config["update"] == "python"
    for key in ("grid_path", "length", "convergence", "best_iteration", "ant_steps"):
        assert python.json[key] == native.json[key], key


def test_a_class_by_name_and_an_object_are_the_same_run():
    by_object = aco.plan(MAP1, (0, 0), (19, 19), update=AntSystem(), seed=3, **SMALL)
    by_name = aco.plan(MAP1, (0, 0), (19, 19), update="python", update_class="ant_system:AntSystem", seed=3, **SMALL)
    assert by_object.json["grid_path"] == by_name.json["grid_path"]
    assert by_object.json["convergence"] == by_name.json["convergence"]


def test_the_object_sees_the_pheromone_as_a_writable_view_and_the_ants_as_arrays():
    seen = {}

    class Probe:
        def update(self, context, iteration, tau):
            seen.setdefault("iterations", 0)
            seen["iterations"] += 1
            seen["dtype"], seen["writable"] = tau.dtype, tau.flags.writeable
            seen["ants"] = len(iteration.ants)
            ant = iteration.ants[0]
            seen["nodes"] = isinstance(ant.nodes, np.ndarray) and len(ant.edges) == len(ant.nodes) - 1
            tau *= 0.9

    result = aco.plan(MAP1, (0, 0), (19, 19), update=Probe(), seed=1, **SMALL)
    assert result.solved
    assert seen == {"iterations": 20, "dtype": np.float64, "writable": True, "ants": 10, "nodes": True}
    assert not [name for name in vars(aco._live) if name.startswith("o")]  # let go after the call


def test_an_exception_in_python_is_an_aco_error_naming_it():
    class Broken:
        def update(self, context, iteration, tau):
            raise RuntimeError("my rule is broken")

    with pytest.raises(aco.Error, match="my rule is broken"):
        aco.plan(MAP1, (0, 0), (19, 19), update=Broken(), seed=1, **SMALL)


def test_nan_written_by_a_python_update_stops_the_run_naming_plugin_hook_and_iteration():
    class WritesNan:
        def update(self, context, iteration, tau):
            if context.iteration == context.max_iterations - 1:  # the last: no ant would read it
                tau[0] = np.nan

    with pytest.raises(aco.Error, match=r"plugin update/python \(.*\) wrote nan to the pheromone of edge \(0,0\) -> \(1,0\) "
                                        r"in update\(\) in iteration 19 \(0-based, as Context::iteration\)"):
        aco.plan(MAP1, (0, 0), (19, 19), update=WritesNan(), seed=1, **SMALL)
