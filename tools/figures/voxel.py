"""The voxel preset, its null models and A* on voxel worlds."""
from __future__ import annotations

import json
import statistics

from .formatting import table
from .project import ACOPLAN, ROOT, VOXEL
from .run import Run
from .sections import section


# Voxel worlds: the voxel preset against its null-model twins and exact A*, per world.
VOXEL_WORLDS = [  # (label, scenario file, scenario indices)
    ("Warframe Simple", "data/maps/voxel/warframe/Simple.3dmap.3dscen", [500, 2500, 4500, 6500, 8500]),
    ("city 64x64x32", "data/maps/voxel/generated/city64x64x32-s1.3dmap.3dscen", [0, 1, 2, 3, 4]),
    ("forest 64x64x32", "data/maps/voxel/generated/forest64x64x32-s1.3dmap.3dscen", [0, 1, 2, 3, 4]),
    ("caves 64x64x32", "data/maps/voxel/generated/caves64x64x32-s1.3dmap.3dscen", [0, 1, 2, 3, 4]),
]
VOXEL_SEEDS = 3


@section("voxel", "10-20 min", "the voxel preset, its null models and A* on voxel worlds",
         [(VOXEL, "voxel-quality")])
def voxel(run: Run):
    twins = {"preset": [], "no-learning": ["--null-model", "no-learning"], "restarts": ["--null-model", "restarts"]}
    rows = []
    for label, scen, indices in VOXEL_WORLDS:
        per = {name: {"solved": 0, "runs": 0, "gaps": [], "final": [], "ms": [], "steps": 0, "steps_ms": 0.0}
               for name in twins}
        astar_ms, scen_match = [], True
        for index in indices:
            problem = ["--scen", scen, "--scen-index", str(index)]
            exact = json.loads(run.tool(ACOPLAN, *problem, "--planner", "astar", "--json"))
            astar_ms.append(exact["time_ms"])
            optimum = exact["grid_length"]
            scen_match &= abs(optimum - stored_voxel_optimum(scen, index)) < 1e-6 * optimum
            for name, extra in twins.items():
                out = json.loads(run.tool(ACOPLAN, *problem, "--repeat", str(VOXEL_SEEDS), *extra, "--json"))
                for r in out["runs"]:
                    m = per[name]
                    m["runs"] += 1
                    m["ms"].append(r["time_ms"])
                    m["steps"] += r["ant_steps"]
                    m["steps_ms"] += r["time_ms"]
                    if r["solved"]:
                        m["solved"] += 1
                        m["gaps"].append(100 * (r["grid_length"] / optimum - 1))
                        m["final"].append(r["length"] / optimum)
        for name in twins:
            m = per[name]
            rows.append([label if name == "preset" else "", f"{len(indices)}", name, f"{m['solved']}/{m['runs']}",
                         f"{statistics.mean(m['gaps']):.2f}" if m["gaps"] else "-",
                         f"{max(m['gaps']):.2f}" if m["gaps"] else "-",
                         f"{statistics.mean(m['final']):.3f}" if m["final"] else "-",
                         f"{statistics.median(m['ms']):.0f} ms",
                         f"{1e6 * m['steps_ms'] / m['steps']:.0f}" if m["steps"] else "-"])
        rows.append(["", "", "exact A\*", f"{len(indices)}/{len(indices)}", "0", "0", "1",
                     f"{statistics.median(astar_ms):.0f} ms", "" if scen_match else "(differs from the .3dscen!)"])
    quality = (run.stamp() + f"\n\n`acoplan --scen FILE --scen-index I` with the voxel preset (chosen by default), seeds 1-"
               f"{VOXEL_SEEDS} (`--repeat {VOXEL_SEEDS}`), and its twins (`--null-model no-learning`: the pheromone ignored; "
               "`--null-model restarts`: as many walks as independent one-iteration runs); grid gap = the ants' grid path "
               "over A\*'s exact 3D optimum, in %; final / optimum = the pruned path's length over that optimum (under 1: "
               "line of sight cuts the grid's corners); time = median per run, the graph's building included; ns per ant "
               "step = run time / ant moves. A\*'s optimum equals the Moving AI `.3dscen` optimal lengths on every "
               "scenario unless the table says otherwise.\n\n"
               + table(["world", "scenarios", "pipeline", "solved", "grid gap % (mean)", "grid gap % (worst)",
                        "final / optimum (mean)", "time per run", "ns per ant step"], rows))
    return {(VOXEL, "voxel-quality"): quality}


def stored_voxel_optimum(scen: str, index: int) -> float:
    lines = (ROOT / scen).read_text().splitlines()[2:]
    return float(lines[index].split()[6])
