#!/usr/bin/env python3
"""Colony vs its two null-model twins (docs/learning.md) on a set of Moving AI scenarios.

Runs acoplan --json for every (problem, seed, variant), caches each run's result in a JSON-lines
file (so a re-run with more variants only runs what is new), and prints per variant: solved,
mean and worst gap of the grid path (grid_length / optimal_length - 1), mean and longest time
(acoplan's time_ms: planning and smoothing); then, for
each variant against the first, sign counts and a Wilcoxon signed-rank test over the
(problem, seed) pairs; then where the final paths went: the share in the exact any-angle
optimum's corridor, the others split into never explored and explored then lost (acoplan's
optimal_corridor_walked), the final path against the any-angle optimum and the corridors walked.

  tools/learning/compare.py --scen-dir /tmp/tune --per-scen 4 --seeds 1,2 \
      --config data/presets/robust.ini -v colony= -v nolearn=--null-model=no-learning \
      -v restarts=--null-model=restarts

A variant is NAME=ARGS (ARGS split on spaces, each --key=value passed as given); --twins adds the
two null models of every variant given.
Temporary until acobench's `null-models: true` experiments replace it.
"""
import argparse
import concurrent.futures
import glob
import hashlib
import json
import math
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# ACOPLAN: another acoplan, e.g. an installed copy (cmake --install) while the tree is rebuilt.
ACOPLAN = os.environ.get("ACOPLAN", os.path.join(ROOT, "build/release/hosts/acoplan/acoplan"))
PLUGINS = (os.path.join(os.path.dirname(os.path.dirname(ACOPLAN)), "lib/aco/plugins") if "ACOPLAN" in os.environ
           else os.path.join(ROOT, "build/release/plugins"))


def problems(scen_dir, per_scen, pattern):
    """Up to per_scen scenarios of each .scen or .3dscen file, evenly spread over its list (which the
    generators order from short to long)."""
    out = []
    for scen in sorted(glob.glob(os.path.join(scen_dir, "**", pattern), recursive=True)):
        with open(scen) as f:
            # A scenario line has 9 fields (.scen) or 8 (.3dscen); the headers ("version 1", and
            # the world's name in a .3dscen) have fewer.
            count = sum(1 for line in f if len(line.split()) >= 8)
        picks = sorted({round(i * (count - 1) / max(per_scen - 1, 1)) for i in range(per_scen)}) if per_scen > 1 else [count - 1]
        out += [(scen, i) for i in picks if i < count]
    return out


def run(args_tuple):
    scen, index, seed, extra, threads = args_tuple
    cmd = [ACOPLAN, "--scen", scen, "--scen-index", str(index), "--seed", str(seed), "--threads", str(threads), "--json"] + extra
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        return {"error": p.stderr.strip()[-300:]}
    j = json.loads(p.stdout)
    keep = {k: j.get(k) for k in ("solved", "grid_length", "optimal_length", "time_ms", "best_iteration", "iterations",
                                  "length", "any_angle_length", "optimal_corridor", "optimal_corridor_walked", "corridors")}
    if keep["time_ms"] is None:
        keep["time_ms"] = j.get("time", {}).get("total_ms") if isinstance(j.get("time"), dict) else None
    return keep


def gap(r):
    if not r.get("solved") or not r.get("optimal_length"):
        return None
    return r["grid_length"] / r["optimal_length"] - 1.0


def wilcoxon(diffs):
    """Two-sided Wilcoxon signed-rank test, normal approximation with tie correction; zeros dropped."""
    d = [x for x in diffs if abs(x) > 1e-12]
    n = len(d)
    if n < 5:
        return float("nan")
    order = sorted(range(n), key=lambda i: abs(d[i]))
    ranks = [0.0] * n
    i = 0
    ties = 0.0
    while i < n:
        j = i
        while j + 1 < n and abs(abs(d[order[j + 1]]) - abs(d[order[i]])) < 1e-12:
            j += 1
        for k in range(i, j + 1):
            ranks[order[k]] = (i + j) / 2 + 1
        t = j - i + 1
        ties += t ** 3 - t
        i = j + 1
    w = sum(r for r, x in zip(ranks, d) if x > 0)
    mean = n * (n + 1) / 4
    sd = math.sqrt(n * (n + 1) * (2 * n + 1) / 24 - ties / 48)
    z = (w - mean) / sd if sd > 0 else 0.0
    return math.erfc(abs(z) / math.sqrt(2))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scen-dir", required=True)
    ap.add_argument("--pattern", default="*.scen")
    ap.add_argument("--per-scen", type=int, default=4)
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--config", default=os.path.join(ROOT, "data/presets/robust.ini"))
    ap.add_argument("-v", "--variant", action="append", default=[], help="NAME=ARGS")
    ap.add_argument("--twins", action="store_true", help="add no-learning and restarts twins of each variant")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--by-type", action="store_true", help="also one table per map type")
    ap.add_argument("--type-by", choices=("name", "folder"), default="name",
                    help="a map's type: its file name up to the first digit after its first letter "
                         "(generated maps: 8room, maze, ...), or its folder (Moving AI's sets)")
    ap.add_argument("--cache", default="/tmp/learning-cache.jsonl")
    a = ap.parse_args()

    variants = []
    for v in a.variant or ["colony="]:
        name, _, args = v.partition("=")
        variants.append((name, args.split()))
        if a.twins:
            variants.append((name + "/nolearn", args.split() + ["--null-model=no-learning"]))
            variants.append((name + "/restarts", args.split() + ["--null-model=restarts"]))
    probs = problems(a.scen_dir, a.per_scen, a.pattern)
    seeds = [int(s) for s in a.seeds.split(",")]
    config = ["--config", a.config] if a.config else []

    cache = {}
    if os.path.exists(a.cache):
        with open(a.cache) as f:
            for line in f:
                e = json.loads(line)
                cache[e["key"]] = e["result"]
    # A rebuilt acoplan or plugin invalidates the cache.
    binary = max(os.stat(f).st_mtime_ns for f in [ACOPLAN] + glob.glob(os.path.join(PLUGINS, "*.so")))
    jobs = {}
    for name, extra in variants:
        for scen, index in probs:
            for seed in seeds:
                full = config + extra
                key = hashlib.sha1(json.dumps([os.path.abspath(scen), index, seed, full, binary, a.threads]).encode()).hexdigest()
                jobs[(name, scen, index, seed)] = (key, (scen, index, seed, full, a.threads))
    todo = {k: v for k, v in jobs.items() if v[0] not in cache}
    print(f"{len(probs)} problems x {len(seeds)} seeds x {len(variants)} variants; {len(todo)} runs to do", file=sys.stderr)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool, open(a.cache, "a") as out:
        futures = {pool.submit(run, v[1]): v[0] for v in todo.values()}
        for done, fut in enumerate(concurrent.futures.as_completed(futures), 1):
            cache[futures[fut]] = fut.result()
            if "error" in fut.result():
                continue  # not cached: a mistaken option is fixed and run again
            out.write(json.dumps({"key": futures[fut], "result": fut.result()}) + "\n")
            out.flush()
            if done % 50 == 0:
                print(f"  {done}/{len(todo)}", file=sys.stderr)

    results = {k: cache[v[0]] for k, v in jobs.items()}
    errors = [r["error"] for r in results.values() if "error" in r]
    if errors:
        print(f"{len(errors)} runs failed, e.g.: {errors[0]}", file=sys.stderr)
    pairs = [(scen, index, seed) for scen, index in probs for seed in seeds]
    if a.by_type:
        # One table per map type: the file name up to its first digit after a letter (8room, maze,
        # random, ...), or the folder it is in (dao, maze, room, street, ... of data/maps/movingai).
        if a.type_by == "folder":
            kind = lambda scen: os.path.basename(os.path.dirname(scen))
        else:
            kind = lambda scen: re.match(r"[0-9]*[^0-9]*", os.path.basename(scen)).group(0)
        for t in sorted({kind(p[0]) for p in pairs}):
            print(f"\n{t}:")
            table(variants, results, [p for p in pairs if kind(p[0]) == t])
        print("\nall:")
    table(variants, results, pairs)


def table(variants, results, pairs):
    first = variants[0][0]
    print(f"| variant | solved | mean gap % | worst gap % | mean time ms | slowest ms | vs {first}: better/equal/worse | Wilcoxon p |")
    print("|---|---|---|---|---|---|---|---|")
    for name, _ in variants:
        gaps = [gap(results[(name,) + p]) for p in pairs]
        solved = [g for g in gaps if g is not None]
        times = [results[(name,) + p].get("time_ms") or 0 for p in pairs]
        mean = 100 * sum(solved) / len(solved) if solved else float("nan")
        worst = 100 * max(solved) if solved else float("nan")
        cmp = ""
        pval = ""
        if name != first:
            base = [gap(results[(first,) + p]) for p in pairs]
            diffs = [(g if g is not None else 1.0) - (b if b is not None else 1.0) for g, b in zip(gaps, base)]
            cmp = f"{sum(d < -1e-12 for d in diffs)}/{sum(abs(d) <= 1e-12 for d in diffs)}/{sum(d > 1e-12 for d in diffs)}"
            pval = f"{wilcoxon(diffs):.3g}"
        print(f"| {name} | {len(solved)}/{len(pairs)} | {mean:.3f} | {worst:.2f} | {sum(times) / len(times):.0f} | {max(times):.0f} | {cmp} | {pval} |")
    corridor_table(variants, results, pairs)


def corridor_table(variants, results, pairs):
    """Where the final paths went: in the exact any-angle optimum's corridor, or in another one that
    no walk of the run took (never explored) or that the colony settled in after walking the right
    one (explored, then lost); the final path against the any-angle optimum; corridors walked."""
    rows = []
    for name, _ in variants:
        runs = [results[(name,) + p] for p in pairs]
        known = [r for r in runs if r.get("solved") and r.get("optimal_corridor") is not None]
        if not known:
            continue
        outside = [r for r in known if not r["optimal_corridor"]]
        never = sum(1 for r in outside if r.get("optimal_corridor_walked") == 0)
        lost = sum(1 for r in outside if r.get("optimal_corridor_walked") == 1)
        ratios = [r["length"] / r["any_angle_length"] for r in known if r.get("any_angle_length")]
        walked = [r["corridors"] for r in runs if r.get("corridors") is not None]
        rows.append(f"| {name} | {100 * (len(known) - len(outside)) / len(known):.1f} % | {never} | {lost} | "
                    f"{sum(ratios) / len(ratios):.4f} | {max(ratios):.4f} | "
                    + (f"{sum(walked) / len(walked):.0f} |" if walked else "- |"))
    if rows:
        print("\n| variant | in the optimum's corridor | other corridor, never walked | other corridor, walked then lost "
              "| final / any-angle, mean | worst | corridors walked, mean |")
        print("|---|---|---|---|---|---|---|")
        print("\n".join(rows))


if __name__ == "__main__":
    main()
