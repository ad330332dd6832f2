"""aco_bench's text output, read."""
from __future__ import annotations

import re

from .project import FiguresError


def parse_classic(text: str) -> dict:
    updates = {m[1]: dict(zip(("median", "min", "ns", "length"), map(float, m.groups()[1:])))
               for m in re.finditer(r"^(ant_system|max_min|acs)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$", text, re.M)}
    plugins = {m[1]: {"ns": float(m[2]), "ratio": float(m[3]), "length": float(m[4])}
               for m in re.finditer(r"^(\(baseline\)|\w+/\w+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$", text, re.M)}
    prune = re.search(r"^smoother/prune\s+([\d.]+) us per call on the best map1 path \((\d+) cells -> (\d+) waypoints\)",
                      text, re.M)
    if len(updates) != 3 or "(baseline)" not in plugins or not prune:
        raise FiguresError("aco_bench --only classic: its output has changed; "
                           "update parse_classic in tools/figures/bench_output.py")
    return {"updates": updates, "plugins": plugins, "prune_us": float(prune[1]), "prune_cells": int(prune[2])}


def parse_terrain(text: str) -> dict:
    rows = [{"map": m[1], "optimum": float(m[2]), "pipeline": m[3], "threads": int(m[4]), "median": float(m[5]),
             "ns": float(m[7]), "length": float(m[8])}
            for m in re.finditer(r"^(epf\d+)\s+([\d.]+)\s+(plain|EPF)\s+(\d+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$",
                                 text, re.M)]
    fireworks = re.search(r"median ([\d.]+) ms, min ([\d.]+) ms, ([\d.]+) us per evaluation, mean best length ([\d.]+)", text)
    identical = re.search(r"threads identical .*: (yes|NO)", text)
    if not rows or not fireworks or not identical:
        raise FiguresError("aco_bench --only terrain,fireworks: its output has changed; update tools/figures/bench_output.py")
    return {"rows": rows, "fireworks": dict(zip(("median", "min", "us", "length"), map(float, fireworks.groups()))),
            "identical": identical[1] == "yes"}


def parse_large(text: str) -> dict:
    head = re.search(r"^== (\S+) \((\d+)x(\d+), (\d+) edges\), scenario (\d+): .* optimum ([\d.]+)", text, re.M)
    rows = {int(m[1]): {"median": float(m[2]), "ns": float(m[4]), "length": float(m[5])}
            for m in re.finditer(r"^([12])\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+(\S+)$", text, re.M)}
    identical = re.search(r"threads identical .*: (yes|NO)", text)
    if not head or set(rows) != {1, 2} or not identical:
        raise FiguresError("aco_bench --only large: its output has changed; update tools/figures/bench_output.py")
    return {"map": head[1], "edges": int(head[4]), "scenario": int(head[5]), "optimum": float(head[6]), "rows": rows,
            "identical": identical[1] == "yes"}
