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


def free_cells(map_file: Path) -> int:
    """The passable cells of a Moving AI .map ('.', 'G' and 'S'), after its four header lines."""
    rows = (ROOT / map_file).read_text().splitlines()[4:]
    return sum(row.count(".") + row.count("G") + row.count("S") for row in rows)


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
    threads_rows = []
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
        one_thread, _, _ = timed_plan(run, problem[:-3] + ["--threads", "1", "--json"])
        per_step = [record["time_ms"] * 1e6 / record["ant_steps"] for record in (one_thread, bare)]
        same = one_thread["grid_path"] == bare["grid_path"] and one_thread["ant_steps"] == bare["ant_steps"]
        free = free_cells(scen.with_suffix(""))
        threads_rows.append([label, f"{free / 1e6:.2f} M", f"{peak * 2**20 / free:.0f} B",
                             f"{one_thread['time_ms'] / 1000:.2f} s", f"{bare['time_ms'] / 1000:.2f} s",
                             f"{one_thread['time_ms'] / bare['time_ms']:.2f}x", f"{bare['ant_steps'] / 1e6:.1f} M",
                             f"{per_step[0]:.0f} ns", f"{per_step[1]:.0f} ns", "yes" if same else "NO"])
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
                     if twin_as_short else "The bare command ends shorter than its no-learning twin on every map.")
        + "\n\nThe bare command with 1 and 2 threads (`--threads 1`): peak memory per free cell (the whole "
        "process's peak over the map's free cells), the search time and its speed-up, the ant steps of the run "
        "(every level's) and the search time per ant step (set-up, coarse levels, band search and smoother "
        "included), and whether both runs made the same steps and found the same path:\n\n"
        + table(["map (2048x2048)", "free cells", "peak per free cell", "search, 1 thread", "search, 2 threads",
                 "speed-up", "ant steps", "per step, 1 thread", "per step, 2 threads", "same run"], threads_rows))}


@section("large-8192", "5-6 min", "docs/large-maps.md's 8192x8192 row: the bare command on a rooms map drawn 16 "
         "times larger", [(LARGE_MAPS, "large-8192")])
def large_8192(run: Run):
    folder = Path("build/results/large-8192")
    (ROOT / folder).mkdir(parents=True, exist_ok=True)
    source = "data/maps/movingai/room/64room_000.map"
    run.tool(BUILD / "tools/aco_mapgen", "--upsample", source, "16", folder, "10")
    scen = folder / (Path(source).stem + "-x16.map.scen")
    index = longest_scenario(scen)
    bare, wall, peak = timed_plan(run, [str(ACOPLAN), "--scen", str(scen), "--scen-index", str(index), "--threads", "2",
                                        "--json"])
    free = free_cells(scen.with_suffix(""))
    row = ["rooms (64room_000 x16)", f"{bare['optimal_length']:.0f}", gap(bare), f"{bare['time_ms'] / 1000:.1f} s",
           f"{wall:.1f} s", f"{peak / 1024:.2f} GiB", f"{peak * 2**20 / free:.0f} B",
           f"{bare['ant_steps'] / 1e6:.1f} M", f"{bare['time_ms'] * 1e6 / bare['ant_steps']:.0f} ns"]
    return {(LARGE_MAPS, "large-8192"): run.stamp() + (
        f"\n\nThe longest of 10 scenarios (index {index}), 2 threads, seed 1; the columns as in the 2048x2048 "
        "tables:\n\n"
        + table(["map (8192x8192)", "optimum", "bare: gap", "search", "wall", "peak memory", "peak per free cell",
                 "ant steps", "per step"], [row]))}
