"""The package under test is the build tree's (ctest sets PYTHONPATH); ACO_BUILD_DIR and
ACO_SOURCE_DIR name the build and the checkout, for the command-line tools it is compared with."""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("ACO_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BUILD = pathlib.Path(os.environ.get("ACO_BUILD_DIR", SOURCE / "build" / "release"))
MAP1 = SOURCE / "data" / "maps" / "classic20" / "map1.txt"


def without_times(record):
    """A run's JSON without what varies from run to run (times)."""
    if isinstance(record, dict):
        return {k: without_times(v) for k, v in record.items() if k not in ("time_ms", "convergence_time_s")}
    if isinstance(record, list):
        return [without_times(v) for v in record]
    return record


def acoplan_json(*args):
    out = subprocess.run([str(BUILD / "hosts" / "acoplan" / "acoplan"), *map(str, args), "--json"], check=False,
                         capture_output=True, text=True)
    assert out.returncode in (0, 3), out.stderr
    return json.loads(out.stdout)


@pytest.fixture
def source():
    return SOURCE


@pytest.fixture
def build():
    return BUILD
