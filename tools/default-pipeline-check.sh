#!/usr/bin/env bash
# What a bare command runs, measured on maps nobody tuned on: acoplan with no pipeline named
# against the preset it stands for (robust on 2D maps, terrain on height maps; the figures must
# be equal), against the classic Ant System setting that was the default before
# (--preset ant-system), and against its null models (docs/learning.md): the same walks with the
# pheromone ignored (--null-model no-learning) and as independent restarts (--null-model
# restarts; the slowest, since a restart walk has no walk limit). Fresh maps: aco_mapgen --benchmark SEED (random, room, maze, cave and hall maps,
# 32x32 to 512x512; scenarios first, middle and last of each map) and aco_terraingen terrains
# (20x20 to 128x128, corner to corner). Gap = grid path / A* optimum on the same graph - 1.
#   tools/default-pipeline-check.sh [SEED] [OUTDIR]      (default seed 7321; 2-3 minutes on 2 cores, half of it the restart twin)
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh release >/dev/null
seed=${1:-7321}
out=${2:-$(mktemp -d)}
bin=build/release
mkdir -p "$out/maps" "$out/terrain"
[ -e "$out/maps/random512-20-s$seed.map.scen" ] || "$bin/tools/aco_mapgen" --benchmark "$out/maps" "$seed" >/dev/null
runs="$out/runs.jsonl"
: > "$runs"
plan() {  # KIND LABEL acoplan-args...
  local kind=$1 label=$2
  shift 2
  "$bin/hosts/acoplan/acoplan" --json --threads 2 "$@" 2>/dev/null |
    python3 -c 'import json, sys; j = json.load(sys.stdin); print(json.dumps({"kind": sys.argv[1], "run": sys.argv[2],
      "solved": j["solved"], "gap": j["grid_length"] / j["optimal_length"] - 1 if j["solved"] else None}))' "$kind" "$label" >> "$runs" || true
}
for scen in "$out"/maps/*.map.scen; do
  count=$(($(wc -l < "$scen") - 1))
  for index in 0 $((count / 2)) $((count - 1)); do
    plan 2d bare --scen "$scen" --scen-index "$index"
    plan 2d preset --scen "$scen" --scen-index "$index" --preset robust
    plan 2d ant-system --scen "$scen" --scen-index "$index" --preset ant-system
    plan 2d no-learning --scen "$scen" --scen-index "$index" --null-model no-learning
    plan 2d restarts --scen "$scen" --scen-index "$index" --null-model restarts
  done
done
for size in 20 40 64 128; do
  terrain="$out/terrain/hills$size-s$seed.asc"
  [ -e "$terrain" ] || "$bin/tools/aco_terraingen" --width "$size" --height "$size" --seed "$((seed + size))" \
    --hills "$((size / 3))" --out "$terrain" >/dev/null
  for goal in "$((size - 1)),$((size - 1))" "$((size - 1)),0"; do
    problem=(--map "$terrain" --start 0,0 --goal "$goal")
    plan terrain bare "${problem[@]}"
    plan terrain preset "${problem[@]}" --preset terrain
    plan terrain ant-system "${problem[@]}" --preset ant-system
    plan terrain no-learning "${problem[@]}" --null-model no-learning
    plan terrain restarts "${problem[@]}" --null-model restarts
  done
done
python3 - "$runs" "$seed" <<'PY'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
print(f"Fresh maps of seed {sys.argv[2]}: the bare command, the preset it stands for, the former default, and the bare command's null models")
print("| maps | run | problems | solved | mean gap | worst gap |")
print("|---|---|---|---|---|---|")
for kind, preset in (("2d", "robust"), ("terrain", "terrain")):
    for run in ("bare", "preset", "ant-system", "no-learning", "restarts"):
        rs = [r for r in rows if r["kind"] == kind and r["run"] == run]
        gaps = [r["gap"] for r in rs if r["solved"]]
        name = {"bare": "no pipeline named", "preset": "--preset " + preset, "ant-system": "--preset ant-system",
                "no-learning": "no pipeline named, --null-model no-learning", "restarts": "no pipeline named, --null-model restarts"}[run]
        mean = f"{100 * sum(gaps) / len(gaps):.2f} %" if gaps else "-"
        worst = f"{100 * max(gaps):.2f} %" if gaps else "-"
        print(f"| {'2D (random, room, maze, cave, hall)' if kind == '2d' else 'terrain'} | {name} | {len(rs)} | {len(gaps)} | {mean} | {worst} |")
PY
