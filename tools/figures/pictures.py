"""The pictures of docs/images/."""
from __future__ import annotations

import shutil
from pathlib import Path

from .project import ACOBENCH, ACOPLAN, ACOSIM, BENCHMARKS, BUILD, IMAGES, ROOT, FiguresError
from .run import Run
from .sections import section


@section("pictures", "15 s", "the SVGs of docs/images/: a route, a terrain, an acosim run, report plots, a voxel world",
         [(BENCHMARKS, "pictures")])
def pictures(run: Run):
    (ROOT / IMAGES).mkdir(parents=True, exist_ok=True)
    # A scenario whose best length falls over the iterations, so that the convergence chart shows it.
    route = ["--scen", "data/maps/generated/random64-25-s1.map.scen", "--scen-index", "19"]
    run.tool(ACOPLAN, *route, "--svg", IMAGES / "route.svg", "--svg-pheromone")
    run.tool(ACOPLAN, "--scen", "data/terrain/epf50.asc.scen", "--svg", IMAGES / "terrain.svg")
    run.tool(ACOSIM, "data/scenarios/paper003_moving.yaml", "--svg", IMAGES / "acosim.svg")
    # docs/maps.md's voxel world: the test program's small world (its 3D page stays in the build).
    run.tool(BUILD / "tests/aco_voxel_sample", "small", BUILD / "voxel-world.html", IMAGES / "voxel-world.svg")
    db = Path("build/results/paper004.db")
    db.parent.mkdir(parents=True, exist_ok=True)
    run.tool(ACOBENCH, "run", "data/experiments/paper004.yaml", "--db", db)
    out = Path("build/results/paper004")
    run.tool(ACOBENCH, "report", db, "--out", out)
    for kind in ("box", "convergence"):
        plot = next((p for p in sorted((ROOT / out / "plots").glob(f"{kind}-*.svg"))), None)
        if not plot:
            raise FiguresError(f"acobench report wrote no {kind} plot into {out}/plots")
        shutil.copy(plot, ROOT / IMAGES / f"report-{kind}.svg")
    sizes = sorted((p.stat().st_size, p) for p in (ROOT / IMAGES).rglob("*.svg"))
    total = sum(s for s, _ in sizes)
    return {(BENCHMARKS, "pictures"): run.stamp() + f"\n\n{len(sizes)} pictures in `docs/images/`, {total / 1024:.0f} KiB in all."}
