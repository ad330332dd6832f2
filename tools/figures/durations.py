"""How long the example experiments and the fast tests take, as the pages say it."""
from __future__ import annotations

import re
import tempfile
import time
from pathlib import Path

from .formatting import about
from .project import ACOBENCH, GETTING_STARTED, ROOT, STUDIES, FiguresError
from .run import Run
from .sections import section


def timed_experiment(run: Run, experiment: Path, tmp: Path) -> tuple[int, float]:
    """(trials, seconds) of a fresh acobench run of EXPERIMENT on 2 threads."""
    began = time.monotonic()
    out = run.tool(ACOBENCH, "run", experiment, "--db", tmp / (experiment.stem + ".db"), "--threads", "2")
    seconds = time.monotonic() - began
    m = re.search(r"(\d+) trials, 0 already in", out)
    if not m:
        raise FiguresError(f"acobench run {experiment}: no 'N trials, 0 already in' in its output; "
                           "update tools/figures/durations.py")
    return int(m[1]), seconds


STUDIES_EXAMPLE = "name: my-study"  # the first line of docs/studies.md's example experiment


@section("durations", "6 min", "how long the example experiments and the fast tests take",
         [(STUDIES, "paper003-time"), (STUDIES, "paper001-time"), (STUDIES, "example-time"), (GETTING_STARTED, "fast-tests"),
          (Path("data/experiments/README.md"), "paper003-time"), (Path("docs/learning.md"), "learning-time")])
def durations(run: Run):
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        times = {name: timed_experiment(run, Path(f"data/experiments/{name}.yaml"), tmp)
                 for name in ("paper003", "paper001", "learning")}
        # docs/studies.md's example names its maps relative to data/experiments/: run it from a copy of
        # that layout.
        block = re.search(r"^```yaml\n(" + re.escape(STUDIES_EXAMPLE) + r"\n.*?)^```", (ROOT / STUDIES).read_text(), re.M | re.S)
        if not block:
            raise FiguresError(f"{STUDIES}: no yaml block starting '{STUDIES_EXAMPLE}'; update tools/figures/durations.py")
        (tmp / "experiments").mkdir()
        for folder in ("maps", "presets", "scenarios", "terrain"):
            (tmp / folder).symlink_to(ROOT / "data" / folder)
        example = tmp / "experiments" / "my-study.yaml"
        example.write_text(block[1])
        times["example"] = timed_experiment(run, example, tmp)
    began = time.monotonic()
    tests = run.tool("ctest", "--preset", "release", "-L", "fast", "-j2")
    seconds = time.monotonic() - began
    passed = re.search(r"tests passed, (\d+) tests failed out of (\d+)", tests)
    if not passed or passed[1] != "0":
        raise FiguresError("ctest -L fast: not every test passed")
    said = {name: f"{trials:,} trials, {about(seconds)} on 2 threads" for name, (trials, seconds) in times.items()}
    return {(STUDIES, "paper003-time"): said["paper003"], (STUDIES, "paper001-time"): said["paper001"],
            (STUDIES, "example-time"): said["example"], (Path("data/experiments/README.md"), "paper003-time"): said["paper003"],
            (Path("docs/learning.md"), "learning-time"): said["learning"],
            (GETTING_STARTED, "fast-tests"): f"{int(passed[2])} tests, {about(seconds)} with `-j2`"}
