"""The benchmark sections: the engine's and the plugins' speed, threads, throughput, the baselines."""
from __future__ import annotations

import json
import os
import re
import statistics
import tempfile
from pathlib import Path

from .bench_output import parse_classic, parse_large, parse_terrain
from .formatting import span, table
from .project import ACO_BENCH, ACOBENCH, ACOPLAN, BASELINES, BENCHMARKS, LARGE_MAPS, FiguresError
from .run import Run
from .sections import section


def aco_bench(run: Run, only: str, *extra) -> str:
    return run.tool(ACO_BENCH, "--only", only, *extra)


@section("engine", "10 s", "the colony's speed on classic map1 against exact A*",
         [(BENCHMARKS, "engine")])
def engine(run: Run):
    c = parse_classic(aco_bench(run, "classic"))
    astar = json.loads(run.tool(ACOPLAN, "--planner", "astar", "--scen", "data/maps/classic20/map1.txt.scen",
                                "--corner-cutting", "--repeat", "30", "--json"))
    astar_ms = statistics.median(r["time_ms"] for r in astar["runs"])
    u = c["updates"]
    rows = [[f"`{name}`", f"{u[name]['median']:.2f} ms", f"{u[name]['ns']:.1f}",
             f"{u[name]['median'] / u['ant_system']['median']:.2f}", f"{u[name]['median'] / astar_ms:,.0f}",
             f"{u[name]['length']:.2f}"] for name in ("ant_system", "max_min", "acs")]
    rows.append(["exact A\\* (`--planner astar`)", f"{astar_ms:.3f} ms", "", f"{astar_ms / u['ant_system']['median']:.4f}",
                 "1", f"{astar['summary']['length']['mean']:.2f}"])
    text = (run.stamp() + "\n\nClassic map1, corner cutting, 50 ants x 100 iterations, alpha 1, beta 7, 1 thread, medians "
            "of 30 runs (seeds 1-30); ns per ant step = total time / moves made by all ants; A\\* on the same graph:\n\n"
            + table(["update", "median run", "ns per ant step", "time / Ant System", "time / A\\*", "mean length"], rows))
    return {(BENCHMARKS, "engine"): text}


@section("plugins", "20 s", "each plugin's cost per ant step against ant_system, two benchmark runs",
         [(BENCHMARKS, "plugins")])
def plugins(run: Run):
    runs = [parse_classic(aco_bench(run, "classic")) for _ in range(2)]
    names = [n for n in runs[0]["plugins"] if n != "(baseline)"]
    rows = [[f"`{n}`", span([r["plugins"][n]["ratio"] for r in runs]), f"{runs[0]['plugins'][n]['length']:.2f}"]
            for n in names]
    base = runs[0]["plugins"]["(baseline)"]
    text = (run.stamp() + "\n\nEach plugin swapped into the baseline pipeline (`ant_system`, rho 0.3, Q 1) on the classic "
            "map1 run above: ns per ant step relative to the baseline's, over two benchmark runs (the baseline: "
            f"{span([r['plugins']['(baseline)']['ns'] for r in runs], 1)} ns per step, mean length {base['length']:.2f}). "
            f"`smoother/prune` runs once per plan: {span([r['prune_us'] for r in runs], 1)} us on the "
            f"{runs[0]['prune_cells']}-cell map1 path.\n\n"
            + table(["slot/plugin", "ns per step / ant_system's", "mean length"], rows))
    return {(BENCHMARKS, "plugins"): text}


@section("terrain-fireworks", "15 s", "plain ACO and EPF on paper 000's terrains, fireworks seeding",
         [(BENCHMARKS, "terrain-fireworks")])
def terrain_fireworks(run: Run):
    t = parse_terrain(aco_bench(run, "terrain,fireworks"))
    rows = []
    for name in dict.fromkeys(r["map"] for r in t["rows"]):
        by = {(r["pipeline"], r["threads"]): r for r in t["rows"] if r["map"] == name}
        for pipeline in ("plain", "EPF"):
            one, two = by[(pipeline, 1)], by.get((pipeline, 2), by[(pipeline, 1)])
            optimum = one["optimum"]
            rows.append([f"{name} ({optimum:.2f})" if pipeline == "plain" else name, pipeline, f"{one['median']:.1f} ms",
                         f"{one['median'] / two['median']:.2f}", f"{one['ns']:.0f}",
                         f"{one['ns'] / by[('plain', 1)]['ns']:.2f}", f"{one['length']:.2f}",
                         f"{100 * (one['length'] / optimum - 1):.1f} %"])
    f = t["fireworks"]
    text = (run.stamp() + "\n\nMedians of 30 runs (seeds 1-30); ns per ant step = total time / total steps of the 30 runs "
            "(a stray slow run moves it more than the median); results with 1 and 2 threads "
            f"{'bit-identical' if t['identical'] else 'DIFFERENT (a bug)'}:\n\n"
            + table(["map (optimum)", "pipeline", "median, 1 thread", "speedup with 2 threads", "ns per ant step",
                     "step cost / plain's", "mean length", "mean gap"], rows)
            + f"\n\nFireworks seeding (IFWA with paper 004's settings on `data/terrain/paper004.map`, corner cutting, 1 "
            f"thread, median of 30): {f['median']:.1f} ms, {f['us']:.0f} us per evaluation, mean best length {f['length']:.2f}.")
    return {(BENCHMARKS, "terrain-fireworks"): text}


@section("large", "30 s", "1 against 2 threads on Moving AI's Berlin_0_512", [(BENCHMARKS, "large")])
def large(run: Run):
    d = parse_large(aco_bench(run, "large"))
    one, two = d["rows"][1], d["rows"][2]
    text = (run.stamp() + f"\n\n`{d['map']}` ({d['edges']:,} edges), scenario {d['scenario']} (optimum {d['optimum']:.2f}), "
            "the classic setting's defaults, the same seed 5 times per thread count, medians:\n\n"
            + table(["threads", "median run", "ns per ant step", "speedup"],
                    [[1, f"{one['median']:.0f} ms", f"{one['ns']:.0f}", "1.00"],
                     [2, f"{two['median']:.0f} ms", f"{two['ns']:.0f}", f"{one['median'] / two['median']:.2f}"]])
            + f"\n\nThe 1- and 2-thread results are {'bit-identical' if d['identical'] else 'DIFFERENT (a bug)'} "
            "(path, length, steps, curve, pheromone); the benchmark fails otherwise.")
    # The recommended pipeline on the slowest scenario of the generated 512x512 maps, as a user runs it.
    problem = ["--scen", "data/maps/generated/maze512-4-s1.map.scen", "--scen-index", "19", "--repeat", "3", "--json"]
    timed = {threads: json.loads(run.tool(ACOPLAN, *problem, "--threads", threads)) for threads in ("1", "2")}
    ms = {k: statistics.median(r["time_ms"] for r in v["runs"]) for k, v in timed.items()}
    same = [r["length"] for r in timed["1"]["runs"]] == [r["length"] for r in timed["2"]["runs"]]
    text += ("\n\nThe recommended pipeline (no pipeline named: `data/presets/robust.ini`) on `maze512-4-s1` scenario 19, "
             f"the slowest of the generated 512x512 scenarios, seeds 1-3: {ms['1'] / 1000:.2f} s per run with 1 thread, "
             f"{ms['2'] / 1000:.2f} s with 2 (median), speedup {ms['1'] / ms['2']:.2f}; the same lengths: "
             f"{'yes' if same else 'NO (a bug)'}.")
    return {(BENCHMARKS, "large"): text}


@section("large-plugins", "5 min", "every plugin and engine option per ant step on Berlin_0_512",
         [(LARGE_MAPS, "large-plugins")])
def large_plugins(run: Run):
    out = aco_bench(run, "large-plugins", "--large-plugin-repeats", "3")
    rows, bases, current = [], {}, ""
    # A plugin whose set-up outweighs the rest of its run (the fireworks search) can give a
    # negative difference: shown as measured.
    number = r"(-?[\d.]+|-?nan|-?inf)"
    row_re = re.compile(r"^(.+?)\s+" + r"\s+".join([number] * 5) + r"\s+(\d+)\s+([\d.]+)\s+(yes|no)$", re.M)
    for m in row_re.finditer(out):
        name, ns, ratio = m[1].strip(), float(m[2]), m[3]
        if name.startswith("baseline:"):
            current = name.removeprefix("baseline: ")
            bases[current] = ns
            continue
        rows.append((current, name, ns, ratio, m[9]))
    robust = re.search(r"1 thread ([\d.]+) ms, 2 threads ([\d.]+) ms \(median\), speedup ([\d.]+).*identical: (yes|NO)", out)
    if len(bases) != 2 or not robust:
        raise FiguresError("aco_bench --only large-plugins: its output has changed; update tools/figures/benchmarks.py")
    names = list(dict.fromkeys(r[1] for r in rows))
    ratio = {(r[0], r[1]): r[3] for r in rows}
    keys = list(bases)
    text = (run.stamp() + "\n\n1 thread, 3 runs each, per ant step with the per-run set-up apart (the first iteration's "
            f"time); relative to Ant System with `discard` ({bases[keys[0]]:.1f} ns) and with `backtrack` "
            f"({bases[keys[1]]:.1f} ns):\n\n"
            + table(["slot/plugin or option", "ns per step / Ant System + `discard`'s", "/ Ant System + `backtrack`'s"],
                    [[f"`{n}`", ratio.get((keys[0], n), "(the baseline)"), ratio.get((keys[1], n), "(the baseline)")]
                     for n in names])
            + f"\n\nThe recommended pipeline (`data/presets/robust.ini`): {robust[1]} ms with 1 thread, {robust[2]} ms with 2, "
            f"speedup {robust[3]}, results {'bit-identical' if robust[4] == 'yes' else 'DIFFERENT (a bug)'}.")
    return {(LARGE_MAPS, "large-plugins"): text}


@section("throughput", "2-4 min", "acobench trials per second, worker processes against --in-process",
         [(BENCHMARKS, "throughput")])
def throughput(run: Run):
    rates = {"workers": [], "in-process": []}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(2):
            for mode in rates:
                db = Path(tmp) / f"throughput-{mode}-{len(rates[mode])}.db"
                out = run.tool(ACOBENCH, "run", "bench/throughput.yaml", "--db", db,
                               *(["--in-process"] if mode == "in-process" else []))
                m = re.search(r"([\d.]+) trials/s", out)
                if not m:
                    raise FiguresError("acobench run: no 'trials/s' in its output; update tools/figures/benchmarks.py")
                rates[mode].append(float(m[1]))
    w, p = rates["workers"], rates["in-process"]
    text = (run.stamp() + "\n\n10,000 trials of the 20x20 paper setting (`bench/throughput.yaml`: classic map1, 50 ants x "
            f"100 iterations, Ant System) on {os.cpu_count()} threads, every trial committed to the results database, twice "
            f"in each mode, in turn: in worker processes (the default) {span(w, 0)} trials per second, `--in-process` "
            f"{span(p, 0)}: the workers run at {span([a / b for a, b in zip(w, p)], 2)} times the in-process rate.")
    return {(BENCHMARKS, "throughput"): text}


PAPER004 = ["--scen", "data/terrain/paper004.map.scen", "--corner-cutting", "--repeat", "10", "--json"]
# The paper's ACO alone, as data/experiments/paper004.yaml's baseline sets it.
PAPER004_ACO = ["--preset", "ant-system", "--ants", "50", "--iterations", "50", "--alpha", "1", "--beta", "3",
                "--update.rho", "0.5", "--update.q", "5"]


@section("baselines", "5 s", "IFWA, PSO, Ant System and the hybrid on paper004.map", [(BASELINES, "baselines")])
def baselines(run: Run):
    configs = {
        "ifwa": ("`--planner ifwa`", ["--planner", "ifwa"]),
        "pso": ("`--planner pso`", ["--planner", "pso"]),
        "as": ("Ant System with the paper's ACO settings (`" + " ".join(PAPER004_ACO) + "`)", PAPER004_ACO),
        "hybrid": ("the hybrid as `data/experiments/paper004.yaml` runs it, `--preset paper004`: fireworks-seeded "
                   "pheromone, alpha 2, beta 8, rho 0.9, Q 1, stuck ants die and cut the pheromone into their last "
                   "nodes (`backtrack_penalty`)", ["--preset", "paper004"]),
        "discard": ("the same hybrid with `--deadlock discard` (stuck ants dropped)", ["--preset", "paper004", "--deadlock", "discard"]),
    }
    s = {key: json.loads(run.tool(ACOPLAN, *args, *PAPER004))["summary"] for key, (_, args) in configs.items()}
    optimum = s["as"]["optimal_length"]
    rows = [[label, f"{s[k]['solved']}/{s[k]['runs']}", f"{s[k]['length']['mean']:.2f} +- {s[k]['length']['sd']:.2f}",
             f"{s[k]['best_iteration']['mean']:.1f}", f"{s[k]['time_ms']['mean']:.0f} ms",
             f"{s[k]['time_ms']['mean'] / s['as']['time_ms']['mean']:.1f}"] for k, (label, _) in configs.items()]
    length = {k: v["length"]["mean"] for k, v in s.items()}
    worst = max(length, key=length.get)
    earlier = s["hybrid"]["best_iteration"]["mean"] < s["as"]["best_iteration"]["mean"]
    shorter = length["hybrid"] < length["as"]
    verdict = (f"The hybrid reaches its best {'earlier' if earlier else 'no earlier'} than Ant System "
               f"(iteration {s['hybrid']['best_iteration']['mean']:.1f} against {s['as']['best_iteration']['mean']:.1f}); "
               f"its paths are {'shorter' if shorter else 'not shorter'} than Ant System's "
               f"({length['hybrid']:.2f} against {length['as']:.2f}; {length['discard']:.2f} with `discard`); the longest "
               f"paths are {configs[worst][0].split(' (')[0]}'s. The paper reports the hybrid both earlier and shorter, "
               "and IFWA alone the worst.")
    text = (run.stamp() + f"\n\n`data/terrain/paper004.map` with corner cutting (optimum {optimum:.2f}), seeds 1-10 each "
            "(`--repeat 10`); length mean +- standard deviation; time per run also as a multiple of Ant System's:\n\n"
            + table(["planner", "solved", "length", "best at iteration (mean)", "time per run", "time / Ant System's"], rows)
            + "\n\n" + verdict)
    return {(BASELINES, "baselines"): text}


@section("default-pipeline", "3-5 min", "the bare command on fresh maps (tools/default-pipeline-check.sh 7321)",
         [(LARGE_MAPS, "default-pipeline")])
def default_pipeline(run: Run):
    out = run.tool("tools/default-pipeline-check.sh", "7321")
    lines = [l for l in out.splitlines() if l.startswith("|")]
    if not lines:
        raise FiguresError("tools/default-pipeline-check.sh printed no table")
    # The check prints option names bare; the page writes them as code.
    lines = [re.sub(r"(?<![-\w])(--[a-z][a-z-]*(?: [a-z][a-z-]*)?)", r"`\1`", l) for l in lines]
    # The colony beats its null models where its mean and worst gap are below both twins'.
    cells = [[c.strip() for c in l.strip("|").split("|")] for l in lines[2:]]
    verdicts = []
    for kind in dict.fromkeys(c[0] for c in cells):
        gaps = {c[1]: (c[4], c[5]) for c in cells if c[0] == kind}
        bare = gaps["no pipeline named"]
        twins = [v for k, v in gaps.items() if "null-model" in k]
        beats = all(float(bare[i].split()[0]) < float(twin[i].split()[0]) for twin in twins for i in (0, 1))
        verdicts.append(f"on {kind} maps the bare command {'beats both' if beats else 'does not beat both'} of its null "
                        "models in mean and worst gap")
    verdict = "; ".join(verdicts)
    text = (run.stamp() + "\n\n" + "\n".join(lines) + "\n\n" + verdict[0].upper() + verdict[1:]
            + " (where it does, the pheromone matters on these maps; on other map shapes it may not: "
            "docs/learning-findings.md).")
    return {(LARGE_MAPS, "default-pipeline"): text}
