#!/usr/bin/python3
"""The colony against OMPL's BIT* at equal wall time, as a user runs both (issue 40).

For each scenario: the bare `acoplan` (the recommended pipeline, its defaults) with --json, then
`acoplan --planner ompl --ompl.planner bitstar` with the colony's measured time as its time limit.
Prints one line per run and the summary the issue asks for: all solved, the colony's final length
against BIT*'s (mean, worst) and against the exact any-angle optimum (mean, worst), the share of
runs in the optimum's corridor, and paired wins.

  tools/equal-time.py [--seeds N] [--per-file K] [--acoplan-args "..."] SCEN...
K scenarios spread over each file (the last, the longest of Moving AI's buckets, always among them).
"""
import argparse
import json
import os
import shlex
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(args):
    out = subprocess.run(args, cwd=ROOT, capture_output=True, text=True)
    if out.returncode not in (0, 3):  # 3: not solved, the JSON says why
        sys.exit(f"{' '.join(map(shlex.quote, args))} failed: {out.stderr.strip()}")
    return json.loads(out.stdout)


def indices(scen, k):
    with open(scen) as f:
        n = sum(1 for line in f) - 1
    if k >= n:
        return list(range(n))
    return sorted({round((i + 1) * (n - 1) / k) for i in range(k)})


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--seeds", type=int, default=2)
    p.add_argument("--per-file", type=int, default=2)
    p.add_argument("--acoplan-args", default="", help="added to the colony's command (default: none, the bare command)")
    p.add_argument("--bin", default="build/release/bin/acoplan")
    p.add_argument("scen", nargs="+")
    a = p.parse_args()
    rows = []
    print(f"{'scenario':34} {'idx':>6} {'seed':>4} {'colony':>10} {'bitstar':>10} {'any-angle':>10} "
          f"{'c/b':>7} {'c/aa':>7} {'b/aa':>7} {'corridor':>8} {'ms':>8}")
    for scen in a.scen:
        for idx in indices(scen, a.per_file):
            for seed in range(1, a.seeds + 1):
                problem = [a.bin, "--scen", scen, "--scen-index", str(idx), "--seed", str(seed), "--json"]
                colony = run(problem + shlex.split(a.acoplan_args))
                budget = max(colony["time_ms"] / 1000.0, 0.001)
                ompl = run(problem + ["--planner", "ompl", "--ompl.planner", "bitstar",
                                      "--ompl.time_limit", f"{budget:.6f}"])
                aa = colony["any_angle_length"]
                row = dict(scen=os.path.basename(scen).removesuffix(".map.scen"), idx=idx, seed=seed,
                           colony=colony["length"] if colony["solved"] else None,
                           bitstar=ompl["length"] if ompl["solved"] else None, any_angle=aa,
                           corridor=colony["optimal_corridor"], ms=colony["time_ms"])
                rows.append(row)
                fmt = lambda v, d=3: "-" if v is None else f"{v:.{d}f}"
                ratio = lambda x, y: None if x is None or y is None else x / y
                print(f"{row['scen']:34} {idx:6} {seed:4} {fmt(row['colony'])!s:>10} {fmt(row['bitstar'])!s:>10} "
                      f"{fmt(aa)!s:>10} {fmt(ratio(row['colony'], row['bitstar']), 4):>7} "
                      f"{fmt(ratio(row['colony'], aa), 4):>7} {fmt(ratio(row['bitstar'], aa), 4):>7} "
                      f"{str(row['corridor']):>8} {row['ms']:8.1f}", flush=True)
    n = len(rows)
    solved = sum(r["colony"] is not None for r in rows)
    bit_solved = sum(r["bitstar"] is not None for r in rows)
    both = [r for r in rows if r["colony"] is not None and r["bitstar"] is not None]
    vs_bit = [r["colony"] / r["bitstar"] for r in both]
    vs_aa = [r["colony"] / r["any_angle"] for r in rows if r["colony"] is not None and r["any_angle"]]
    bit_aa = [r["bitstar"] / r["any_angle"] for r in rows if r["bitstar"] is not None and r["any_angle"]]
    corridor = [r["corridor"] for r in rows if r["corridor"] is not None]
    print(f"\nruns {n}: colony solved {solved}/{n}, BIT* solved {bit_solved}/{n}")
    if vs_bit:
        wins = sum(v < 1 - 1e-9 for v in vs_bit)
        losses = sum(v > 1 + 1e-9 for v in vs_bit)
        print(f"colony / BIT* (both solved, {len(vs_bit)}): mean {statistics.mean(vs_bit):.4f} "
              f"worst {max(vs_bit):.4f}; colony shorter {wins}, BIT* shorter {losses}, ties {len(vs_bit) - wins - losses}")
    if vs_aa:
        print(f"colony / any-angle optimum: mean {statistics.mean(vs_aa):.4f} worst {max(vs_aa):.4f}")
    if bit_aa:
        print(f"BIT* / any-angle optimum: mean {statistics.mean(bit_aa):.4f} worst {max(bit_aa):.4f}")
    if corridor:
        print(f"colony in the optimum's corridor: {sum(corridor)}/{len(corridor)} "
              f"({100.0 * sum(corridor) / len(corridor):.0f} %)")
    print(f"colony time per run: mean {statistics.mean(r['ms'] for r in rows):.1f} ms")


if __name__ == "__main__":
    main()
