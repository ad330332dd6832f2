"""docs/large-maps.md's table, from the large-map experiments' results."""
from __future__ import annotations

import csv
import statistics
from pathlib import Path

from .formatting import table
from .project import LARGE_MAPS, ROOT
from .run import Run
from .sections import section


# The configurations docs/large-maps.md's table shows, per experiment (None: every one).
LARGE_MAP_CONFIGS = {"movingai": ["default", "robust preset"], "generated": None, "terrain": None}


def map_group(experiment: str, problem: str) -> str:
    """The group a problem's map belongs to in docs/large-maps.md's table: the Moving AI map, the generated
    map's kind and size (random64-25-s2#3 -> random64), the terrain's size (hills40#s101a -> hills40)."""
    name = problem.split("#")[0]
    return name.split("-")[0] if experiment == "generated" else name


@section("large-maps", "1 s", "docs/large-maps.md's table, from the movingai, terrain and generated databases",
         [(LARGE_MAPS, "large-maps")])
def large_maps(run: Run):
    rows = []
    for experiment, configs in LARGE_MAP_CONFIGS.items():
        runs_csv = Path("build/results") / experiment / "runs.csv"
        if not (ROOT / runs_csv).exists():
            # Hours of trials are not worth an error: the table says what is missing and how to fill it.
            rows.append([f"`{experiment}.yaml`", f"not run yet: `tools/figures.sh {experiment} large-maps`", "", "", ""])
            continue
        run.commands.append(f"(reads {runs_csv})")
        trials = list(csv.DictReader((ROOT / runs_csv).open()))
        for config in configs or list(dict.fromkeys(r["configuration"] for r in trials)):
            mine = [r for r in trials if r["configuration"] == config]
            groups = list(dict.fromkeys(map_group(experiment, r["problem"]) for r in mine))
            gaps, times = [], []
            for g in groups:
                solved = [float(r["gap_percent"]) for r in mine if map_group(experiment, r["problem"]) == g and r["solved"] == "1"
                          and r["gap_percent"]]
                # + 0.0: an optimal path's gap rounds to -0.00 otherwise.
                gaps.append(f"{g} {round(statistics.mean(solved), 2) + 0.0:.2f}" if solved else f"{g} -")
                times.append(statistics.mean(float(r["time_s"]) for r in mine if map_group(experiment, r["problem"]) == g))
            solved = sum(r["solved"] == "1" for r in mine)
            rows.append([f"`{experiment}.yaml`", config, f"{solved}/{len(mine)}", ", ".join(gaps),
                         f"{1000 * min(times):.0f}-{1000 * max(times):.0f} ms / {max(float(r['time_s']) for r in mine):.2f} s"])
    text = (run.stamp() + "\n\nPer map (Moving AI), per kind and size (generated maps) or per size (terrains): solved runs, "
            "mean gap of the solved runs to the optimum in %, and time per run (the range of the maps' means / the "
            "slowest run), as the experiments measured them: their stamps in docs/results.md give the machine and its "
            "load then:\n\n" + table(["experiment", "configuration", "solved", "mean gap % by map", "time per run"], rows))
    return {(LARGE_MAPS, "large-maps"): text}
