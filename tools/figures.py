#!/usr/bin/env python3
"""Regenerates the figures the pages of docs/ quote, and the pictures in docs/images/.

Each figure lives in a region of a tracked Markdown file between two markers,

    <!-- figures:NAME begin (tools/figures.sh SECTION) -->
    ...
    <!-- figures:NAME end -->

and a section replaces only its own regions, so running one section never touches another's
figures. A figure inside a sentence is an inline region on one line,

    about <!-- figures:NAME inline (STAMP) -->2 s<!-- figures:NAME end --> on 2 threads

whose short stamp the section rewrites with it. Every region starts with a stamp: the machine (cores, CPU model), the load average at
the section's start and end, the date, the commit and the exact commands, because times hold only
for the machine and the load they were taken on (ratios travel better, and are quoted where they
can be). The numbers are always read from the tools' own output, never typed.

Run through tools/figures.sh (which builds first); `tools/figures.sh --list` lists the sections.
"""
from __future__ import annotations

import datetime
import json
import math
import os
import re
import shlex
import shutil
import sqlite3
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

ROOT = Path(__file__).resolve().parent.parent
BUILD = Path("build/release")
ACOPLAN = BUILD / "hosts/acoplan/acoplan"
ACOBENCH = BUILD / "hosts/acobench/acobench"
ACOSIM = BUILD / "hosts/acosim/acosim"
ACO_BENCH = BUILD / "bench/aco_bench"
# The pages whose figures the sections write (and data/experiments/README.md, docs/learning.md).
BENCHMARKS = Path("docs/benchmarks.md")
LARGE_MAPS = Path("docs/large-maps.md")
BASELINES = Path("docs/baseline-planners.md")
STUDIES = Path("docs/studies.md")
GETTING_STARTED = Path("docs/getting-started.md")
RESULTS = Path("docs/results.md")
IMAGES = Path("docs/images")
VOXEL = Path("docs/voxel-worlds.md")


class FiguresError(Exception):
    """A mistake in the files or the command line: printed as one message, exit status 1."""


# ---------------------------------------------------------------------------------------------
# Regions


def _marker_re(name: str, which: str) -> re.Pattern:
    return re.compile(r"^<!-- figures:" + re.escape(name) + r" " + which + r"\b[^\n]*-->[ \t]*$", re.M)


def begin_marker(name: str, section: str) -> str:
    return f"<!-- figures:{name} begin (tools/figures.sh {section}) -->"


def end_marker(name: str) -> str:
    return f"<!-- figures:{name} end -->"


def find_region(text: str, name: str, section: str, file: str) -> tuple[int, int]:
    """The span of region NAME's body (between the end of its begin line and the start of its end
    line; for an inline region, between its markers). A region that is missing, doubled or
    unclosed is an error naming the section."""
    if is_inline(text, name):
        found = find_inline(text, name, section, file)
        return found.start(1), found.end(1)
    begins = list(_marker_re(name, "begin").finditer(text))
    ends = list(_marker_re(name, "end").finditer(text))
    how = (f"add the lines '{begin_marker(name, section)}' and '{end_marker(name)}' where its figures belong, or "
           f"inside a sentence '{inline_marker(name, 'tools/figures.sh ' + section)}...{end_marker(name)}' on one line")
    if not begins and not ends:
        raise FiguresError(f"{file}: no region 'figures:{name}' for section '{section}': {how}")
    if len(begins) != 1 or len(ends) != 1:
        raise FiguresError(f"{file}: region 'figures:{name}' of section '{section}' has {len(begins)} begin and "
                           f"{len(ends)} end markers; it needs one of each")
    if ends[0].start() < begins[0].end():
        raise FiguresError(f"{file}: region 'figures:{name}' of section '{section}' ends before it begins")
    return begins[0].end() + 1, ends[0].start()


def _inline_re(name: str) -> re.Pattern:
    return re.compile(r"<!-- figures:" + re.escape(name) + r" inline\b[^\n]*?-->([^\n]*?)<!-- figures:"
                      + re.escape(name) + r" end -->")


def inline_marker(name: str, stamp: str) -> str:
    return f"<!-- figures:{name} inline ({stamp}) -->"


def is_inline(text: str, name: str) -> bool:
    return bool(_inline_re(name).search(text)) and not _marker_re(name, "begin").search(text)


def find_inline(text: str, name: str, section: str, file: str) -> re.Match:
    """Inline region NAME, markers included (group 1: its body); an error unless it is there once."""
    found = list(_inline_re(name).finditer(text))
    if len(found) != 1:
        raise FiguresError(f"{file}: inline region 'figures:{name}' of section '{section}' is there "
                           f"{len(found)} times; it needs to be there once")
    return found[0]


def replace_regions(text: str, bodies: dict[str, str], section: str, file: str, inline_stamp: str = "") -> str:
    """TEXT with the body of each region in BODIES replaced; everything else is left as it was. An
    inline region's body must be one line; its marker gets INLINE_STAMP."""
    for name, body in bodies.items():
        if is_inline(text, name):
            m = find_inline(text, name, section, file)
            if "\n" in body.strip():
                raise FiguresError(f"section '{section}': the body of inline region 'figures:{name}' is not one line")
            text = (text[:m.start()] + inline_marker(name, inline_stamp or section) + body.strip()
                    + end_marker(name) + text[m.end():])
            continue
        start, end = find_region(text, name, section, file)
        body = body.strip("\n") + "\n"
        text = text[:start] + body + text[end:]
    return text


# ---------------------------------------------------------------------------------------------
# Running tools and stamping what they measured


def load_average() -> str:
    return Path("/proc/loadavg").read_text().split()[0]


def cpu_model() -> str:
    for line in Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("model name"):
            return " ".join(line.split(":", 1)[1].split())
    return "unknown CPU"


def commit() -> str:
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    # The generated files themselves change while the script runs; other changes mean the build
    # measured is not the commit named.
    generated = sorted({str(file) for s in SECTIONS.values() for file, _ in s.regions} | {"docs"})
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "--", "."] + [f":!{g}" for g in generated],
                           capture_output=True, text=True).stdout.strip()
    return (head or "unknown") + (" with uncommitted changes" if dirty else "")


@dataclass
class Run:
    """One section's run: the commands it ran, for the stamp."""
    section: str
    commands: list[str] = field(default_factory=list)
    load_start: str = ""
    started: float = 0.0
    note: str = ""  # said in the stamp after the commands

    def tool(self, *args) -> str:
        """Runs a command from the project's root; returns its stdout. Its stderr goes to ours."""
        words = [str(a) for a in args]
        self.commands.append(shlex.join(words))
        print(f"[{self.section}] {shlex.join(words)}", file=sys.stderr, flush=True)
        done = subprocess.run(words, stdout=subprocess.PIPE, stderr=sys.stderr, text=True, cwd=ROOT)
        if done.returncode != 0:
            raise FiguresError(f"section '{self.section}': '{shlex.join(words)}' exited {done.returncode}")
        return done.stdout

    def stamp(self) -> str:
        when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d")
        commands = "; ".join(f"`{c}`" for c in dict.fromkeys(self.commands))
        return (f"<sub>Generated by `tools/figures.sh {self.section}` on {when} at commit {commit()}, "
                f"{os.cpu_count()} cores ({cpu_model()}), load average {self.load_start} at the start and "
                f"{load_average()} at the end, in {self.elapsed()}; ran {commands}{self.note}.</sub>")

    def short_stamp(self) -> str:
        """The stamp of an inline region, in its marker: what the reader does not see."""
        when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d")
        return (f"tools/figures.sh {self.section}, {when}, commit {commit()}, {os.cpu_count()} cores ({cpu_model()}), "
                f"load {self.load_start}-{load_average()}")

    def elapsed(self) -> str:
        seconds = time.monotonic() - self.started
        return f"{seconds:.0f} s" if seconds < 120 else f"{seconds / 60:.1f} min"


def table(header: list[str], rows: list[list]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def span(values: list[float], digits: int = 2) -> str:
    """'1.23' or '1.20-1.35': the range over repeated measurements."""
    low, high = f"{min(values):.{digits}f}", f"{max(values):.{digits}f}"
    return low if low == high else f"{low}-{high}"


# ---------------------------------------------------------------------------------------------
# aco_bench's text output


def parse_classic(text: str) -> dict:
    updates = {m[1]: dict(zip(("median", "min", "ns", "length"), map(float, m.groups()[1:])))
               for m in re.finditer(r"^(ant_system|max_min|acs)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$", text, re.M)}
    plugins = {m[1]: {"ns": float(m[2]), "ratio": float(m[3]), "length": float(m[4])}
               for m in re.finditer(r"^(\(baseline\)|\w+/\w+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$", text, re.M)}
    prune = re.search(r"^smoother/prune\s+([\d.]+) us per call on the best map1 path \((\d+) cells -> (\d+) waypoints\)",
                      text, re.M)
    if len(updates) != 3 or "(baseline)" not in plugins or not prune:
        raise FiguresError("aco_bench --only classic: its output has changed; update tools/figures.py's parse_classic")
    return {"updates": updates, "plugins": plugins, "prune_us": float(prune[1]), "prune_cells": int(prune[2])}


def parse_terrain(text: str) -> dict:
    rows = [{"map": m[1], "optimum": float(m[2]), "pipeline": m[3], "threads": int(m[4]), "median": float(m[5]),
             "ns": float(m[7]), "length": float(m[8])}
            for m in re.finditer(r"^(epf\d+)\s+([\d.]+)\s+(plain|EPF)\s+(\d+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$",
                                 text, re.M)]
    fireworks = re.search(r"median ([\d.]+) ms, min ([\d.]+) ms, ([\d.]+) us per evaluation, mean best length ([\d.]+)", text)
    identical = re.search(r"threads identical .*: (yes|NO)", text)
    if not rows or not fireworks or not identical:
        raise FiguresError("aco_bench --only terrain,fireworks: its output has changed; update tools/figures.py")
    return {"rows": rows, "fireworks": dict(zip(("median", "min", "us", "length"), map(float, fireworks.groups()))),
            "identical": identical[1] == "yes"}


def parse_large(text: str) -> dict:
    head = re.search(r"^== (\S+) \((\d+)x(\d+), (\d+) edges\), scenario (\d+): .* optimum ([\d.]+)", text, re.M)
    rows = {int(m[1]): {"median": float(m[2]), "ns": float(m[4]), "length": float(m[5])}
            for m in re.finditer(r"^([12])\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+(\S+)$", text, re.M)}
    identical = re.search(r"threads identical .*: (yes|NO)", text)
    if not head or set(rows) != {1, 2} or not identical:
        raise FiguresError("aco_bench --only large: its output has changed; update tools/figures.py")
    return {"map": head[1], "edges": int(head[4]), "scenario": int(head[5]), "optimum": float(head[6]), "rows": rows,
            "identical": identical[1] == "yes"}


# ---------------------------------------------------------------------------------------------
# Sections


@dataclass
class Section:
    name: str
    estimate: str  # on a quiet 2-core machine
    summary: str
    regions: list[tuple[Path, str]]  # (file, region) it replaces
    make: Callable[[Run], dict[tuple[Path, str], str]]


SECTIONS: dict[str, Section] = {}


def section(name: str, estimate: str, summary: str, regions: list[tuple[Path, str]]):
    def register(make):
        SECTIONS[name] = Section(name, estimate, summary, regions, make)
        return make
    return register


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
        raise FiguresError("aco_bench --only large-plugins: its output has changed; update tools/figures.py")
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
                    raise FiguresError("acobench run: no 'trials/s' in its output; update tools/figures.py")
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


# The report's plots that go beside an experiment's tables (file names in build/results/NAME/plots/).
def chosen_plots(name: str, plots: list[str]) -> list[str]:
    def first(prefix: str, count: int) -> list[str]:
        return [p for p in plots if p.startswith(prefix)][:count]
    if name in ("movingai", "generated", "terrain", "anytime"):
        return first("ecdf-", 2)  # hundreds of problems: the fixed-target ECDFs over all of them
    if name == "dwa":
        return first("box-", 2) + first("ablation", 1)
    if name == "ablation":
        return first("box-", 1) + first("convergence-", 1) + first("ablation", 1)
    return first("box-", 3) + first("convergence-", 1)


def experiment(name: str):
    def make(run: Run):
        db = Path("build/results") / f"{name}.db"
        out = Path("build/results") / name
        db.parent.mkdir(parents=True, exist_ok=True)
        ran = run.tool(ACOBENCH, "run", f"data/experiments/{name}.yaml", "--db", db)
        # A resumed database keeps the trials an earlier run measured, on its machine and load.
        resumed = re.search(r"(\d+) trials, (\d+) already in", ran)
        if resumed and int(resumed[2]) > 0:
            run.note = (f" ({resumed[2]} of the {resumed[1]} trials were stored by an earlier run of the section; "
                        f"delete {db} to measure them all again)")
        if (out / "plots").exists():
            shutil.rmtree(out / "plots")
        run.tool(ACOBENCH, "report", db, "--out", out)
        report = (ROOT / out / "report.md").read_text()
        keep = {"movingai": ("Summary by problem set", "Gap by difficulty bucket"),
                "terrain": ("Summary by problem set", "Gap by difficulty bucket"),
                "generated": ("Summary by problem set", "Gap by difficulty bucket"),
                "dwa": ("Simulations", "Ablation path"),
                "anytime": ("Summary by problem set", "Does the pheromone matter?")}.get(name)
        parts = re.split(r"^(?=## )", report, flags=re.M)[1:]
        if keep:
            parts = [p for p in parts if p.removeprefix("## ").startswith(keep)]
        ours = re.sub(r"^## ", "#### ", "".join(parts), flags=re.M)
        images = ROOT / IMAGES / "results" / name
        if images.exists():
            shutil.rmtree(images)
        images.mkdir(parents=True)
        plots = sorted(p.name for p in (ROOT / out / "plots").glob("*.svg"))
        pictures = []
        for plot in chosen_plots(name, plots):
            shutil.copy(ROOT / out / "plots" / plot, images / plot)
            title = re.search(r"<text class=\"title\"[^>]*>([^<]*)<", (images / plot).read_text())
            alt = title[1] if title else plot
            pictures.append(f"![{alt}](images/results/{name}/{plot})")
        text = ((ROOT / f"data/experiments/{name}.md").read_text().strip() + "\n\n"
                + f"Ours (`acobench run data/experiments/{name}.yaml`):\n\n" + run.stamp() + "\n\n"
                + ("\n".join(pictures) + "\n\n" if pictures else "") + ours)
        return {(RESULTS, name): text}
    return make


EXPERIMENTS = {  # on the shared 2-core machine, with a fresh database
    "paper000": "30 s", "paper001": "10 s", "paper002": "10 s", "paper003": "30 s", "paper004": "15 s",
    "ablation": "3.5 min", "movingai": "15-30 min", "terrain": "1-2 min", "generated": "2-4 min", "dwa": "6 min",
    "anytime": "10-15 min",
}
for _name, _estimate in EXPERIMENTS.items():
    section(_name, _estimate, f"data/experiments/{_name}.yaml into docs/results.md, with its report's plots",
            [(RESULTS, _name)])(experiment(_name))


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


def about(seconds: float) -> str:
    """A duration as the prose says it: 'about 2 s', 'about 3 min'."""
    return f"about {seconds:.0f} s" if seconds < 100 else f"about {seconds / 60:.0f} min"


def timed_experiment(run: Run, experiment: Path, tmp: Path) -> tuple[int, float]:
    """(trials, seconds) of a fresh acobench run of EXPERIMENT on 2 threads."""
    began = time.monotonic()
    out = run.tool(ACOBENCH, "run", experiment, "--db", tmp / (experiment.stem + ".db"), "--threads", "2")
    seconds = time.monotonic() - began
    m = re.search(r"(\d+) trials, 0 already in", out)
    if not m:
        raise FiguresError(f"acobench run {experiment}: no 'N trials, 0 already in' in its output; update tools/figures.py")
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
            raise FiguresError(f"{STUDIES}: no yaml block starting '{STUDIES_EXAMPLE}'; update tools/figures.py")
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
    import csv
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


# Voxel worlds: the voxel preset against its null-model twins and exact A*, per world.
VOXEL_WORLDS = [  # (label, scenario file, scenario indices)
    ("Warframe Simple", "data/maps/voxel/warframe/Simple.3dmap.3dscen", [500, 2500, 4500, 6500, 8500]),
    ("city 64x64x32", "data/maps/voxel/generated/city64x64x32-s1.3dmap.3dscen", [0, 1, 2, 3, 4]),
    ("forest 64x64x32", "data/maps/voxel/generated/forest64x64x32-s1.3dmap.3dscen", [0, 1, 2, 3, 4]),
    ("caves 64x64x32", "data/maps/voxel/generated/caves64x64x32-s1.3dmap.3dscen", [0, 1, 2, 3, 4]),
]
VOXEL_SEEDS = 3


@section("voxel", "15-30 min", "the voxel preset, its null models and A* on voxel worlds; a 256x256x128 city's memory",
         [(VOXEL, "voxel-quality"), (VOXEL, "voxel-memory")])
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
    run.commands.clear()  # the memory region's stamp lists its own commands only
    memory = voxel_city_memory(run)
    return {(VOXEL, "voxel-quality"): quality, (VOXEL, "voxel-memory"): memory}


def stored_voxel_optimum(scen: str, index: int) -> float:
    lines = (ROOT / scen).read_text().splitlines()[2:]
    return float(lines[index].split()[6])


def voxel_city_memory(run: Run) -> str:
    """A 256x256x128 city planned under a 4 GiB limit: peak memory and time, from GNU time."""
    folder = Path("build/results/voxel")  # from the project's root, as the tools run
    (ROOT / folder).mkdir(parents=True, exist_ok=True)
    run.tool(BUILD / "tools/aco_mapgen", "--voxel", "city", "256x256x128", "7", folder, "3")
    scen = folder / "city256x256x128-s7.3dmap.3dscen"
    rows = []
    for label, extra in [("A\*", ["--planner", "astar"]), ("voxel preset, 20 ants x 20 iterations", ["--ants", "20", "--iterations", "20"]),
                         ("voxel preset, 50 ants x 100 iterations", [])]:
        words = ["/usr/bin/time", "-v", str(ACOPLAN), "--scen", str(scen), "--scen-index", "2", "--max-memory", "4G",
                 *extra, "--json"]
        run.commands.append(shlex.join(words))
        done = subprocess.run(words, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
        if done.returncode != 0:
            raise FiguresError(f"section '{run.section}': {shlex.join(words)} exited {done.returncode}: {done.stderr[-500:]}")
        peak_kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", done.stderr).group(1))
        wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([\d:.]+)", done.stderr).group(1)
        r = json.loads(done.stdout)
        rows.append([label, "yes" if r["solved"] else "no", f"{r['grid_length']:.2f}" if r["solved"] else "-",
                     f"{r['optimal_length']:.2f}", f"{peak_kb / 1024 / 1024:.2f} GiB", wall, f"{r['time_ms'] / 1000:.1f} s"])
    return (run.stamp() + "\n\nA generated city of 256x256x128 voxels (`aco_mapgen --voxel city 256x256x128 7`), its "
            "third (longest) scenario, 26-neighbourhood, under `--max-memory 4G`, 2 threads; peak = maximum resident set size "
            "(GNU time), wall = the whole process (loading the map and building the graph included), run = the planner's "
            "own time:\n\n" + table(["planner", "solved", "grid length", "optimum", "peak memory", "wall", "run"], rows))


# ---------------------------------------------------------------------------------------------


def run_section(s: Section) -> None:
    run = Run(s.name, load_start=load_average(), started=time.monotonic())
    bodies = s.make(run)
    stamp = run.short_stamp()  # before any file changes, which would read as uncommitted changes
    for (file, region), body in bodies.items():
        path = ROOT / file
        path.write_text(replace_regions(path.read_text(), {region: body}, s.name, str(file), stamp))
    print(f"[{s.name}] done in {run.elapsed()}: {', '.join(sorted({str(f) for f, _ in bodies}))}", file=sys.stderr)


def main(argv: list[str]) -> int:
    if argv[:1] in (["-h"], ["--help"]):
        print(__doc__.strip() + "\n\nUsage: tools/figures.sh [SECTION ...] | --list   (no section: every one)")
        return 0
    if argv[:1] == ["--list"]:
        for s in SECTIONS.values():
            print(f"{s.name:17} {s.estimate:>13}  {s.summary}")
        return 0
    names = argv or list(SECTIONS)
    unknown = [n for n in names if n not in SECTIONS]
    if unknown:
        raise FiguresError(f"unknown section {', '.join(unknown)} (sections: {', '.join(SECTIONS)}; --list says more)")
    # Every region must be there before anything runs: an hour of experiments should not end in a
    # missing marker.
    for n in names:
        for file, region in SECTIONS[n].regions:
            find_region((ROOT / file).read_text(), region, n, str(file))
    for n in names:
        run_section(SECTIONS[n])
    return 0


if __name__ == "__main__":
    os.chdir(ROOT)
    try:
        sys.exit(main(sys.argv[1:]))
    except FiguresError as e:
        print(f"figures: error: {e}", file=sys.stderr)
        sys.exit(1)
