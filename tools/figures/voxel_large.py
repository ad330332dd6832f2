"""Voxel worlds of millions of voxels, planned coarse to fine: Warframe's Complex and DB1 under a
4 GiB limit, and a generated 256x256x128 city's memory."""
from __future__ import annotations

import json
import statistics
import subprocess
from pathlib import Path

from .formatting import table
from .project import ACOPLAN, BUILD, ROOT, VOXEL
from .run import Run
from .sections import section
from .voxel import stored_voxel_optimum

WARFRAME = [  # (label, scenario file)
    ("Complex (246x154x205)", "data/maps/voxel/warframe/Complex.3dmap.3dscen"),
    ("DB1 (409x261x462)", "data/maps/voxel/warframe/DB1.3dmap.3dscen"),
]
INDICES = list(range(0, 10000, 500))  # 20 of each world's 10,000 scenarios, spread over the file
ONE_LEVEL_INDICES = INDICES[::4]  # the whole graph is slow: five of them
LIMIT = ["--max-memory", "4G", "--threads", "2"]
UNSOLVED = 3  # acoplan's exit status for a run that found no path


def free_voxels(scen: str) -> int:
    """A .3dmap's voxels less its blocked ones (one line each after the header)."""
    lines = (ROOT / scen).with_suffix("").read_text().splitlines()
    width, height, depth = (int(word) for word in lines[0].split()[1:4])
    return width * height * depth - sum(1 for line in lines[1:] if line.strip())


def summarise(label: str, name: str, runs: list[tuple[dict, float, float, float]], free: int) -> list[str]:
    """One table row: RUNS are (record, optimum, wall seconds, peak MiB)."""
    gaps = [100 * (r["grid_length"] / optimum - 1) for r, optimum, _, _ in runs if r["solved"]]
    peak = max(p for _, _, _, p in runs)
    return [label, name, f"{len(gaps)}/{len(runs)}", f"{statistics.mean(gaps):.2f}" if gaps else "-",
            f"{max(gaps):.2f}" if gaps else "-", f"{statistics.median(r['time_ms'] for r, _, _, _ in runs) / 1000:.2f} s",
            f"{max(w for _, _, w, _ in runs):.1f} s", f"{peak:.0f} MiB", f"{peak * 2**20 / free:.0f} B"]


def verdict(world: str, gaps: dict[str, list[float]]) -> str:
    """Whether the preset beats both twins on the mean and on the worst gap (issue 43's test)."""
    def mean(values):
        return sum(values) / len(values)
    preset, twins = gaps["preset"], [g for name, g in gaps.items() if name != "preset"]
    on_mean = all(mean(preset) < mean(twin) for twin in twins)
    on_worst = all(max(preset) < max(twin) for twin in twins)
    if on_mean and on_worst:
        return f"On {world} the preset beats both twins on the mean and on the worst gap."
    said = "on the mean, not on the worst gap" if on_mean else "on the worst gap, not on the mean" if on_worst else \
        "neither on the mean nor on the worst gap"
    return (f"On {world} the preset beats both twins {said}: there its length comes from the corridor, the "
            "progress heuristic and the straightened walks more than from the pheromone.")


def refusal(run: Run, *args) -> str:
    """The error acoplan exits with (status 1), from its stderr."""
    words = [str(a) for a in args]
    run.commands.append(" ".join(words))
    done = subprocess.run(words, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    if done.returncode != 1:
        raise RuntimeError(f"expected {' '.join(words)} to be refused, it exited {done.returncode}")
    return done.stderr.strip().splitlines()[-1].removeprefix("acoplan: error: ")


@section("voxel-large", "5-7 min", "Warframe's Complex and DB1 planned coarse to fine under 4 GiB, beside the twins "
         "and one level; a 256x256x128 city's memory", [(VOXEL, "voxel-warframe"), (VOXEL, "voxel-memory")])
def voxel_large(run: Run):
    twins = {"preset": [], "no-learning twin": ["--null-model", "no-learning"],
             "restarts twin": ["--null-model", "restarts"]}
    rows, refused, verdicts = [], "", []
    for label, scen in WARFRAME:
        free = free_voxels(scen)
        gaps = {}
        for name, extra in twins.items():
            runs = []
            for index in INDICES:
                out, wall, peak = run.timed(ACOPLAN, "--scen", scen, "--scen-index", index, *LIMIT, *extra, "--json",
                                            ok=(0, UNSOLVED))
                runs.append((json.loads(out), stored_voxel_optimum(scen, index), wall, peak))
            rows.append(summarise(label if name == "preset" else "", name, runs, free))
            gaps[name] = [100 * (r["grid_length"] / optimum - 1) if r["solved"] else float("inf")
                          for r, optimum, _, _ in runs]
        verdicts.append(verdict(label.split(" (")[0], gaps))
        if label.startswith("Complex"):
            runs = []
            for index in ONE_LEVEL_INDICES:
                out, wall, peak = run.timed(ACOPLAN, "--scen", scen, "--scen-index", index, "--max-memory", "8G",
                                            "--threads", "2", "--coarse-to-fine", "0", "--json", ok=(0, UNSOLVED))
                runs.append((json.loads(out), stored_voxel_optimum(scen, index), wall, peak))
            rows.append(summarise("", f"one level (`--coarse-to-fine 0`), {len(runs)} of the scenarios, "
                                  "`--max-memory 8G`", runs, free))
        else:
            refused = refusal(run, ACOPLAN, "--scen", scen, "--scen-index", INDICES[0], *LIMIT, "--coarse-to-fine", "0")
    warframe = (run.stamp() + "\n\nScenarios 0, 500, ..., 9500 of each world's `.3dscen` (20 of 10,000), the voxel "
                "preset (chosen by default) and its twins, seed 1, under `--max-memory 4G`, 2 threads. Gap: the grid "
                "path over the `.3dscen`'s optimal length, in %; time: acoplan's `time_ms` (the coarse levels, building "
                "the corridor's graph and the colony), median; wall and peak memory (GNU time): the whole process, "
                "loading the world included, the slowest and the largest run; per free voxel: that peak over the "
                "world's free voxels.\n\n"
                + table(["world", "pipeline", "solved", "grid gap % (mean)", "grid gap % (worst)", "time (median)",
                         "wall (slowest)", "peak memory", "peak per free voxel"], rows)
                + "\n\n" + " ".join(verdicts)
                + f"\n\nDB1 on one level (`--coarse-to-fine 0`) under the same limit: \"{refused}\".")
    run.commands.clear()  # the memory region's stamp lists its own commands only
    return {(VOXEL, "voxel-warframe"): warframe, (VOXEL, "voxel-memory"): city_memory(run)}


def city_memory(run: Run) -> str:
    """A 256x256x128 city planned under a 4 GiB limit: peak memory and time, from GNU time."""
    folder = Path("build/results/voxel")  # from the project's root, as the tools run
    (ROOT / folder).mkdir(parents=True, exist_ok=True)
    run.tool(BUILD / "tools/aco_mapgen", "--voxel", "city", "256x256x128", "7", folder, "3")
    scen = folder / "city256x256x128-s7.3dmap.3dscen"
    rows, optimum = [], None
    for label, extra in [("A\\*", ["--planner", "astar"]),
                         ("voxel preset, 20 ants x 20 iterations", ["--ants", "20", "--iterations", "20"]),
                         ("voxel preset, 50 ants x 100 iterations", []),
                         ("voxel preset on one level (`--coarse-to-fine 0`)", ["--coarse-to-fine", "0"])]:
        out, wall, peak = run.timed(ACOPLAN, "--scen", scen, "--scen-index", "2", "--max-memory", "4G", *extra, "--json")
        r = json.loads(out)
        optimum = optimum or r["optimal_length"]
        rows.append([label, "yes" if r["solved"] else "no", f"{r['grid_length']:.2f}" if r["solved"] else "-",
                     f"{optimum:.2f}", f"{peak / 1024:.2f} GiB", f"{wall:.1f} s", f"{r['time_ms'] / 1000:.1f} s"])
    return (run.stamp() + "\n\nA generated city of 256x256x128 voxels (`aco_mapgen --voxel city 256x256x128 7`), its "
            "third (longest) scenario, 26-neighbourhood, under `--max-memory 4G`, 2 threads; the preset plans it coarse "
            "to fine (8.4 million voxels), the last row on its whole graph; optimum: A\\*'s on the whole graph; peak = "
            "maximum resident set size (GNU time), wall = the whole process (loading the map and building the graph "
            "included), run = the planner's own time:\n\n"
            + table(["planner", "solved", "grid length", "optimum", "peak memory", "wall", "run"], rows))
