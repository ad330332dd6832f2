"""docs/corridors.md's explorers table: the bare command with and without explorer ants, their twins
and the bare command given four times the iterations, on fresh maps nobody tuned on."""
from __future__ import annotations

import json
from pathlib import Path

from .formatting import table
from .project import ACOPLAN, BUILD, CORRIDORS, ROOT
from .run import Run
from .sections import section

SEED = 9001  # aco_mapgen --benchmark's maps of this seed: every family, 32x32 to 512x512
RUNS = [
    ("bare command", []),
    ("bare command, `--iterations 400`", ["--iterations", "400"]),
    ("`--explorers 0.1`", ["--explorers", "0.1"]),
    ("`--explorers 0.2`", ["--explorers", "0.2"]),
    ("`--explorers 0.2 --null-model no-learning`", ["--explorers", "0.2", "--null-model", "no-learning"]),
    ("`--explorers 0.2 --null-model restarts`", ["--explorers", "0.2", "--null-model", "restarts"]),
]


def problems(folder: Path) -> list[list[str]]:
    """The first, middle and last scenario of every map's file."""
    found = []
    for scen in sorted((ROOT / folder).glob("*.map.scen")):
        count = len([line for line in scen.read_text().splitlines()[1:] if line.strip()])
        for index in sorted({0, count // 2, count - 1}):
            found.append(["--scen", str(folder / scen.name), "--scen-index", str(index)])
    return found


@section("explorers", "8-10 min", "docs/corridors.md's explorers table: explorer ants against the bare command and "
         "their twins on fresh maps", [(CORRIDORS, "explorers")])
def explorers(run: Run):
    folder = Path("build/results/explorers")
    run.tool(BUILD / "tools/aco_mapgen", "--benchmark", folder, str(SEED))  # the same maps every time
    rows, summary = [], {}
    for label, words in RUNS:
        gaps, times, unsolved = [], [], 0
        for problem in problems(folder):
            pattern = " ".join([str(ACOPLAN), "--json", "--threads", "2", "--scen", "SCEN", "--scen-index", "I", *words])
            record = json.loads(run.tool(ACOPLAN, "--json", "--threads", "2", *problem, *words, stamped=pattern))
            times.append(record["time_ms"])
            if record["solved"]:
                gaps.append(100 * (record["grid_length"] / record["optimal_length"] - 1))
            else:
                unsolved += 1
        summary[label] = (sum(gaps) / len(gaps), max(gaps))
        rows.append([label, f"{len(gaps)}/{len(gaps) + unsolved}", f"{sum(gaps) / len(gaps):.2f} %",
                     f"{max(gaps):.2f} %", f"{sum(times) / len(times):.0f} ms"])
    colony = summary["`--explorers 0.2`"]
    twins = [summary[label] for label, words in RUNS if "--null-model" in words]
    beats = all(colony[i] < twin[i] for twin in twins for i in (0, 1))
    verdict = (f"With a fifth of the ants exploring, the colony {'beats' if beats else 'does not beat'} both of its "
               "null models on the mean and on the worst gap.")
    return {(CORRIDORS, "explorers"): run.stamp() + (
        f"\n\nFresh maps of `aco_mapgen --benchmark {SEED}` (random, room, maze, cave and hall maps, 32x32 to "
        "512x512; SCEN and I: the first, middle and last scenario of each), 2 threads, seed 1. Gap: the grid path's over the "
        "exact A\\* optimum; time: acoplan's search time (`time_ms`):\n\n"
        + table(["run", "solved", "mean gap", "worst gap", "time, mean"], rows) + "\n\n" + verdict)}
