#!/usr/bin/env bash
# aco_mapgen --upsample MAP FACTOR OUTDIR COUNT: the map drawn FACTOR times larger, cell for cell,
# with COUNT scenarios whose optimal lengths are A*'s on the upsampled map.
#   mapgen_upsample_test.sh ROOT ACO_MAPGEN ACOPLAN OUT_DIR
set -euo pipefail
root="$1"
mapgen="$2"
acoplan="$3"
out="$4"
rm -rf "$out"
"$mapgen" --upsample "$root/data/maps/movingai/arena.map" 3 "$out" 4 > "$out.log"
grep -q "^arena-x3: 147x147, " "$out.log"
/usr/bin/python3 - "$root/data/maps/movingai/arena.map" "$out/arena-x3.map" <<'PY'
import sys
def rows(path):
    lines = open(path).read().split("\n")
    return lines[4:4 + int(lines[1].split()[1])]
small, big = rows(sys.argv[1]), rows(sys.argv[2])
assert len(big) == 3 * len(small) and all(len(r) == 3 * len(small[0]) for r in big), "size"
free = lambda c: c in ".GS"
for y, row in enumerate(big):
    for x, c in enumerate(row):
        assert free(c) == free(small[y // 3][x // 3]), f"cell ({x},{y})"
PY
[ "$(grep -vc '^version' "$out/arena-x3.map.scen")" -eq 4 ]
for index in 0 1 2 3; do
  expected="$(awk -F'\t' -v i=$((index + 2)) 'NR == i { print $9 }' "$out/arena-x3.map.scen")"
  "$acoplan" --planner astar --scen "$out/arena-x3.map.scen" --scen-index "$index" --json |
    /usr/bin/python3 -c 'import json, sys; l = json.load(sys.stdin)["grid_length"]; e = float(sys.argv[1]); assert abs(l - e) <= 1e-3 * e, (l, e)' "$expected"
done
# A bad factor is refused with a clear message.
if "$mapgen" --upsample "$root/data/maps/movingai/arena.map" 0 "$out" 2> "$out.err"; then exit 1; fi
grep -q "FACTOR must be 1 to 64" "$out.err"
# A number too large for one is named, not "stoi".
if "$mapgen" --upsample "$root/data/maps/movingai/arena.map" 99999999999 "$out" 2> "$out.err"; then exit 1; fi
grep -q "FACTOR must be a whole number" "$out.err"
if "$mapgen" --benchmark "$out" 99999999999 2> "$out.err"; then exit 1; fi
grep -q -- "--benchmark: FIRST_SEED must be a whole number" "$out.err"
echo "aco_mapgen --upsample: map and scenarios checked"
