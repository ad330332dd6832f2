"""aco.plugins(), describe(), add_plugin_dir(), presets()."""
import os
import subprocess

import pytest

import aco


def test_every_bundled_plugin_is_listed_with_its_parameter_table():
    plugins = {(p["slot"], p["name"]): p for p in aco.plugins()}
    assert ("update", "max_min") in plugins and ("heuristic", "direction") in plugins
    rho = next(p for p in plugins[("update", "ant_system")]["parameters"] if p["name"] == "rho")
    assert rho["type"] == "real" and rho["default"] == 0.3 and rho["range"] == "0:1"


def test_describe_is_acoplans(build):
    cli = subprocess.run([str(build / "hosts" / "acoplan" / "acoplan"), "--describe", "max_min"], capture_output=True,
                         text=True, check=True)
    assert aco.describe("max_min") == cli.stdout
    with pytest.raises(aco.Error, match="no plugin named 'max_mn'; did you mean 'update/max_min'"):
        aco.describe("max_mn")


def test_describe_takes_slot_and_name_and_names_the_slots_of_a_shared_name():
    assert aco.describe("init/potential_field").startswith("init/potential_field ")
    assert aco.describe("heuristic/potential_field").startswith("heuristic/potential_field ")
    with pytest.raises(aco.Error, match="give its slot too, as SLOT/NAME: init/potential_field or heuristic/potential_field"):
        aco.describe("potential_field")


def test_a_plugin_folder_added_is_searched():
    folder = os.environ.get("ACO_TEST_HOSTILE_PLUGIN_DIR")
    if not folder:
        pytest.skip("ACO_TEST_HOSTILE_PLUGIN_DIR not set (ctest sets it)")
    assert "crashing" not in {p["name"] for p in aco.plugins()}
    aco.add_plugin_dir(folder)
    assert "crashing" in {p["name"] for p in aco.plugins()}


def test_presets_are_listed():
    presets = aco.presets()
    assert {"robust", "terrain", "paper001", "ant-system"} <= set(presets)
    assert all(presets.values())


def test_a_missing_plugin_folder_is_refused_at_once():
    with pytest.raises(aco.Error, match="--plugin-dir /no/such/dir: no such folder"):
        aco.add_plugin_dir("/no/such/dir")
    assert aco.plugins()  # the folders before it still serve
