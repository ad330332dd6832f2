"""The project's layout as the sections see it, and the error they raise."""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
BUILD = Path("build/release")
ACOPLAN = BUILD / "hosts/acoplan/acoplan"
ACOBENCH = BUILD / "hosts/acobench/acobench"
ACOSIM = BUILD / "hosts/acosim/acosim"
ACO_BENCH = BUILD / "bench/aco_bench"
# The pages whose figures the sections write (and data/experiments/README.md, docs/learning.md).
BENCHMARKS = Path("docs/benchmarks.md")
LARGE_MAPS = Path("docs/large-maps.md")
BASELINES = Path("docs/baseline-planners.md")
STUDIES = Path("docs/studies.md")
GETTING_STARTED = Path("docs/getting-started.md")
RESULTS = Path("docs/results.md")
IMAGES = Path("docs/images")
VOXEL = Path("docs/voxel-worlds.md")
CORRIDORS = Path("docs/corridors.md")
ROS = Path("docs/ros.md")


class FiguresError(Exception):
    """A mistake in the files or the command line: printed as one message, exit status 1."""
