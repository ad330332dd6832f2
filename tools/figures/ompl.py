"""The recommended pipeline against OMPL's planners at equal time (data/experiments/ompl.yaml)."""
from __future__ import annotations

import math
import re
import sqlite3
import statistics
from pathlib import Path

from .formatting import table
from .project import ACOBENCH, BUILD, RESULTS, ROOT
from .run import Run
from .sections import section


OMPL_BUDGETS = ("0.1 s", "0.5 s", "2 s")
OMPL_CAVE = "cave2048-16-s1"


def planner_and_budget(config: str) -> tuple[str, str]:
    """('colony (no learning)', '0.1 s') of 'colony 0.1 s (no learning)'; A*'s budget is ''."""
    m = re.match(r"(.*?) (\d+(?:\.\d+)? s)( \(.*\))?$", config)
    return (m[1] + (m[3] or ""), m[2]) if m else (config, "")


def any_angle_check(run: Run, problems: list[str]) -> tuple[str, bool]:
    """The any-angle optimum against Theta* and the octile optimum on the scenario problems."""
    by_map: dict[str, list[str]] = {}
    for name in problems:
        if "#" in name:
            by_map.setdefault(name.split("#")[0], []).append(name.split("#")[1])
    scen_files = {p.name.removesuffix(".map.scen"): p for p in (ROOT / "data/maps/movingai").rglob("*.map.scen")}
    rows, holds = [], True
    for map_name, indices in by_map.items():
        scen = scen_files[map_name].relative_to(ROOT)
        out = run.tool(BUILD / "bin/aco-any-angle", scen, *[a for i in indices for a in ("--index", i)])
        for line in out.splitlines():
            cells = line.split()
            if line.startswith("#") or not cells or not cells[0].isdigit():
                continue
            octile, theta, any_angle = float(cells[-4]), float(cells[-3]), float(cells[-2])
            # The .scen files keep 8 significant digits of the octile optimum.
            ok = any_angle <= theta + 1e-9 and theta <= octile * (1 + 1e-7)
            holds = holds and ok
            rows.append([f"{map_name} #{cells[0]}", f"{octile:.4f}", f"{theta:.4f}", f"{any_angle:.4f}",
                         f"{any_angle / octile:.4f}", "yes" if ok else "**no**"])
    return table(["scenario", "octile (A*, .scen)", "Theta*", "any-angle optimum", "any-angle / octile",
                  "any-angle <= Theta* <= octile"], rows), holds


@section("ompl", "15-20 min", "the recommended pipeline against OMPL's planners at equal time (data/experiments/ompl.yaml)",
         [(RESULTS, "ompl")])
def ompl_comparison(run: Run):
    db = Path("build/results") / "ompl.db"
    db.parent.mkdir(parents=True, exist_ok=True)
    ran = run.tool(ACOBENCH, "run", "data/experiments/ompl.yaml", "--db", db, "--threads", "2")
    resumed = re.search(r"(\d+) trials, (\d+) already in", ran)
    if resumed and int(resumed[2]) > 0:
        run.note = (f" ({resumed[2]} of the {resumed[1]} trials were stored by an earlier run of the section; "
                    f"delete {db} to measure them all again)")
    run.tool(ACOBENCH, "report", db, "--out", Path("build/results") / "ompl")
    with sqlite3.connect(ROOT / db) as con:
        trials = con.execute(
            "SELECT e.name, r.repetition, e.anyangle_length, c.name, r.solved, r.solution_length, r.time FROM runs r "
            "JOIN experiments e ON e.id = r.experimentid JOIN plannerConfigs c ON c.id = r.plannerid "
            "WHERE e.version LIKE 'aco %' ORDER BY r.id").fetchall()
    problems = list(dict.fromkeys(t[0] for t in trials))
    # (group, planner, budget) -> {(problem, repetition): (solved, excess %, time s)}
    cells: dict[tuple[str, str, str], dict[tuple[str, int], tuple[bool, float, float]]] = {}
    planners: list[str] = []
    for problem, repetition, any_angle, config, solved, length, seconds in trials:
        planner, budget = planner_and_budget(config)
        planners.append(planner)
        group = "2048x2048 cave" if problem == OMPL_CAVE else "Moving AI"
        excess = 100 * (length / any_angle - 1) if solved and any_angle else math.nan
        cells.setdefault((group, planner, budget), {})[(problem, repetition)] = (bool(solved), excess, seconds)
    planners = list(dict.fromkeys(planners))
    sampling = [p for p in planners if p != "A*" and not p.startswith("colony")]

    def measures(group: str, planner: str, budget: str) -> tuple[float, float, float, float]:
        """(solved share, mean excess %, worst excess %, median time s)"""
        runs = list(cells.get((group, planner, budget), {}).values())
        excesses = [e for solved, e, _ in runs if solved]
        return (sum(s for s, _, _ in runs) / len(runs) if runs else math.nan,
                statistics.mean(excesses) if excesses else math.nan, max(excesses) if excesses else math.nan,
                statistics.median(t for _, _, t in runs) if runs else math.nan)

    def cell(group: str, planner: str, budget: str) -> str:
        solved, mean, worst, seconds = measures(group, planner, budget)
        if math.isnan(solved):
            return ""
        lengths = f"+{mean:.1f} / +{worst:.1f} %" if not math.isnan(mean) else "no path"
        return f"{100 * solved:.0f} % · {lengths} · {seconds:.2f} s"

    def shorter(group: str, planner: str, budget: str, ours: str) -> tuple[int, int]:
        """Of the runs (problem, repetition) both solved, how many the planner's path is the shorter in."""
        theirs, mine = cells.get((group, planner, budget), {}), cells.get((group, ours, budget), {})
        both = [k for k in theirs if k in mine and theirs[k][0] and mine[k][0]]
        return sum(theirs[k][1] < mine[k][1] for k in both), len(both)

    text = [(ROOT / "data/experiments/ompl.md").read_text().strip(), run.stamp()]
    for group in ("Moving AI", "2048x2048 cave"):
        count = len([p for p in problems if (p == OMPL_CAVE) == (group != "Moving AI")])
        text.append(f"**{group}** ({count} problem{'s' if count > 1 else ''} x 3 repetitions). Each cell: solved share · "
                    "mean / worst excess of the final path over the any-angle optimum (solved runs) · median wall "
                    "time of a run:")
        rows = []
        for planner in planners:
            if planner == "A*":
                rows.append(["exact A\\* (8-connected grid; no budget)", cell(group, planner, ""), "", ""])
            else:
                rows.append([planner] + [cell(group, planner, b) for b in OMPL_BUDGETS])
        text.append(table(["planner"] + [f"budget {b}" for b in OMPL_BUDGETS], rows))
        verdicts = []
        for budget in OMPL_BUDGETS:
            ours = measures(group, "colony + prune", budget)
            likeliest = max(sampling, key=lambda p: (measures(group, p, budget)[0], -measures(group, p, budget)[1]))
            best = measures(group, likeliest, budget)
            pairs = [(p, *shorter(group, p, budget, "colony + prune")) for p in sampling]
            pairs = ", ".join(f"{p} {n} of {m}" for p, n, m in pairs if m)
            overrun = (f"; the colony overran the budget (median {ours[3]:.2f} s: its set-up and first iteration on "
                       "this map take longer), so this is not equal time" if ours[3] > 1.5 * float(budget.split()[0])
                       else "")
            verdicts.append(
                f"at {budget} the colony + prune solves {100 * ours[0]:.0f} % of the runs, OMPL's most reliable planner, "
                f"{likeliest}, {100 * best[0]:.0f} %" +
                (f"; of the runs both solved, OMPL's path is the shorter in {pairs}" if pairs else
                 "; no OMPL planner solved a run") + overrun)
        text.append(f"Verdict on {group}: " + "; ".join(verdicts) + ".")
        twins = []
        for budget in OMPL_BUDGETS:
            colony = measures(group, "colony", budget)
            others = [measures(group, f"colony ({kind})", budget) for kind in ("no learning", "restarts")]
            if math.isnan(colony[1]) or any(math.isnan(o[1]) for o in others):
                twins.append(f"at {budget} not every twin found paths to compare")
                continue
            beats = all(colony[1] < o[1] and colony[0] >= o[0] for o in others)
            twins.append(f"at {budget} the colony {'beats' if beats else 'does not beat'} both twins "
                         f"(+{colony[1]:.1f} % against +{others[0][1]:.1f} % without learning and "
                         f"+{others[1][1]:.1f} % as restarts)")
        text.append(f"Null models on {group}: " + "; ".join(twins) + ".")
    check, holds = any_angle_check(run, problems)
    text.append("The yardstick checked against Theta\\* and the octile optimum on every scenario problem "
                "(`aco-any-angle`; the cave's Theta\\* takes about 10 s and is left out): "
                + ("every any-angle optimum lies between them" if holds else "**the ordering fails somewhere**")
                + ".\n\n" + check)
    return {(RESULTS, "ompl"): "\n\n".join(text)}
