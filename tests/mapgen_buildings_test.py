#!/usr/bin/python3
"""aco_mapgen's building families (office, 8room, doors): written only when named, the same
files on a second run, every free cell of every map in one 4-connected part (the doors keep every
room reachable), and 20 scenarios each.
    tests/mapgen_buildings_test.py ACO_MAPGEN WORK_DIR"""
import filecmp
import shutil
import subprocess
import sys
from pathlib import Path

mapgen, work = sys.argv[1], Path(sys.argv[2])
shutil.rmtree(work, ignore_errors=True)
for run in ("a", "b"):
    subprocess.run([mapgen, "--benchmark", str(work / run), "1", "office,8room,doors"], check=True, stdout=subprocess.DEVNULL)
maps = sorted((work / "a").glob("*.map"))
names = sorted(m.stem for m in maps)
expected = ["8room512-s1", "8room512-s2", "doors256-16-s1", "doors256-16-s2", "doors512-32-s1", "doors512-32-s2",
            "office256-12-s1", "office256-12-s2", "office512-25-s1", "office512-25-s2"]
if names != expected:
    sys.exit(f"maps written: {names}, expected {expected}")
same, differ, missing = filecmp.cmpfiles(work / "a", work / "b", [p.name for p in (work / "a").iterdir()], shallow=False)
if differ or missing:
    sys.exit(f"a second run wrote other files: {differ + missing}")
for m in maps:
    rows = m.read_text().split("\n")[4:]
    rows = [r for r in rows if r]
    free = {(x, y) for y, row in enumerate(rows) for x, c in enumerate(row) if c == "."}
    seen = {next(iter(free))}
    stack = list(seen)
    while stack:
        x, y = stack.pop()
        for n in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
            if n in free and n not in seen:
                seen.add(n)
                stack.append(n)
    if len(seen) != len(free):
        sys.exit(f"{m.name}: {len(free) - len(seen)} of {len(free)} free cells cut off from the rest")
    blocked = sum(row.count("@") for row in rows)
    if not 0.01 < blocked / (len(rows) * len(rows[0])) < 0.5:
        sys.exit(f"{m.name}: {blocked} blocked cells, not a building")
    scenarios = (work / "a" / (m.name + ".scen")).read_text().split("\n")[1:]
    if len([s for s in scenarios if s]) != 20:
        sys.exit(f"{m.name}: not 20 scenarios")
print(f"{len(maps)} building maps: deterministic, connected, 20 scenarios each")
