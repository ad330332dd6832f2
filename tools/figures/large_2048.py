"""docs/large-maps.md's 2048x2048 table: the bare command, its no-learning twin and time limits on
maps the project does not ship (bundled maps drawn four times larger)."""
from __future__ import annotations

import json
from pathlib import Path

from .formatting import table
from .project import ACOPLAN, BUILD, LARGE_MAPS, ROOT
from .run import Run
from .sections import section

# (label, bundled map): each is drawn 4x larger (every cell a 4x4 block) by aco_mapgen --upsample.
MAPS_X4 = [
    ("city (Berlin_0_512 x4)", "data/maps/movingai/street/Berlin_0_512.map"),
    ("cave (cave512-8-s2 x4)", "data/maps/generated/cave512-8-s2.map"),
    ("rooms (64room_000 x4)", "data/maps/movingai/room/64room_000.map"),
]
UNSOLVED = 3  # acoplan's exit status for a run that found no path


def longest_scenario(scen: Path) -> int:
    """The index of the scenario with the longest optimal path."""
    lengths = [float(line.split()[8]) for line in (ROOT / scen).read_text().splitlines()[1:] if line.strip()]
    return max(range(len(lengths)), key=lambda i: lengths[i])


def timed_plan(run: Run, words: list[str]) -> tuple[dict, float, float]:
    """acoplan --json under GNU time: its record, the wall seconds and the peak memory in MiB."""
    out, wall, peak = run.timed(*words, ok=(0, UNSOLVED))
    return json.loads(out), wall, peak


def gap(record: dict) -> str:
    if not record["solved"]:
        return "unsolved"
    return f"{100 * (record['grid_length'] / record['optimal_length'] - 1):.2f} %"


@section("large-2048", "2-4 min", "docs/large-maps.md's 2048x2048 table: the bare command, its no-learning twin, "
         "one level, time limits", [(LARGE_MAPS, "large-2048")])
def large_2048(run: Run):
    folder = Path("build/results/large-2048")  # from the project's root, as the tools run
    (ROOT / folder).mkdir(parents=True, exist_ok=True)
    rows = []
    twin_as_short = []  # the maps where the no-learning twin ends as short as the bare command
    for label, source in MAPS_X4:
        run.tool(BUILD / "tools/aco_mapgen", "--upsample", source, "4", folder, "10")
        scen = folder / (Path(source).stem + "-x4.map.scen")
        problem = [str(ACOPLAN), "--scen", str(scen), "--scen-index", str(longest_scenario(scen)), "--threads", "2",
                   "--json"]
        bare, wall, peak = timed_plan(run, problem)
        twin, _, _ = timed_plan(run, problem + ["--null-model", "no-learning"])
        one_level, _, _ = timed_plan(run, problem + ["--coarse-to-fine", "0"])
        cut, _, _ = timed_plan(run, problem + ["--time-limit", "0.5"])
        two, _, _ = timed_plan(run, problem + ["--time-limit", "2"])
        if twin["solved"] and bare["solved"] and twin["grid_length"] <= bare["grid_length"]:
            twin_as_short.append(label.split(" (")[0])
        rows.append([label, f"{bare['optimal_length']:.0f}", gap(bare), f"{bare['time_ms'] / 1000:.2f} s",
                     f"{wall:.1f} s", f"{peak:.0f} MiB", gap(twin),
                     f"{gap(one_level)}, {one_level['time_ms'] / 1000:.2f} s",
                     f"{gap(cut)}, {cut['time_ms'] / 1000:.3f} s, {cut['iterations']} it.", gap(two)])
    return {(LARGE_MAPS, "large-2048"): run.stamp() + (
        "\n\nThe longest of 10 scenarios on each map, 2 threads, seed 1. Gap: the grid path's over the exact A\\* "
        "optimum. Search: acoplan's search time (`time_ms`: the reachability test, the colony's set-up and walks, "
        "the smoother); wall and peak memory (GNU time): the whole "
        "process, loading the map, building the graph and the yardsticks included. The time-limit columns give the "
        "gap, the search time and the iterations run:\n\n"
        + table(["map (2048x2048)", "optimum", "bare: gap", "search", "wall", "peak memory", "no-learning twin: gap",
                 "one level (`--coarse-to-fine 0`): gap, search", "`--time-limit 0.5`", "`--time-limit 2`: gap"],
                rows)
        + "\n\n" + (f"The no-learning twin ends as short as the bare command on the {', '.join(twin_as_short)} map"
                     f"{'s' if len(twin_as_short) > 1 else ''}: there the coarse colony's corridor, the band search "
                     "and the straightened walks find the path, not the pheromone."
                     if twin_as_short else "The bare command ends shorter than its no-learning twin on every map."))}
