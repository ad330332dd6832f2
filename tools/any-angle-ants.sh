#!/usr/bin/env bash
# Grid ants against line-of-sight walks, by final length (docs/any-angle-ants.md): the recommended
# pipeline (data/presets/robust.ini) with the prune smoother, on SAMPLE scenarios evenly spread
# over each bundled Moving AI file and each generated map named below, SEEDS seeds each, for every
# variant: 8- and 16-neighbourhood grid ants, and line-of-sight walks on both. Prints, per map
# family and variant, the mean and worst final (smoothed) length relative to the exact any-angle
# optimum and the mean time per run; then the same over everything.
#   tools/any-angle-ants.sh [SAMPLE [SEEDS]]     defaults 3 3
# Builds build/release first (tools/build.sh). Times are wall-clock on this machine, 1 thread.
set -euo pipefail
cd "$(dirname "$0")/.."
sample=${1:-3}
seeds=${2:-3}
tools/build.sh release >/dev/null
bin=build/release/bin
generated=(maze64-2-s1 random64-25-s1 room64-8-s1 cave256-4-s1 hall256-32-s1 random512-20-s1)
variants=("8, grid|--neighbourhood 8" "16, grid|--neighbourhood 16"
  "8, line-of-sight|--neighbourhood 8 --walk-length line-of-sight"
  "16, line-of-sight|--neighbourhood 16 --walk-length line-of-sight")
files=(data/maps/movingai/*.scen data/maps/movingai/*/*.scen)
for name in "${generated[@]}"; do
  [[ -f data/maps/generated/$name.map.scen ]] && files+=("data/maps/generated/$name.map.scen")
done
rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
for scen in "${files[@]}"; do
  family=movingai
  case $scen in data/maps/generated/*) family=generated ;; esac
  # aco-any-angle's rows: "79  (1,12)  (29,6)  30.485300  -  28.685150  0.94095" (index ... any-angle ratio)
  while read -r index optimum; do
    [[ $(awk -v o="$optimum" 'BEGIN { print (o < 10) }') == 1 ]] && continue  # too short to differ
    for variant in "${variants[@]}"; do
      label=${variant%%|*}
      # shellcheck disable=SC2086  # the options are words
      OMP_NUM_THREADS=1 "$bin/acoplan" --config data/presets/robust.ini --smoother prune --threads 1 \
        --scen "$scen" --scen-index "$index" --repeat "$seeds" --json ${variant#*|} |
        python3 -c '
import json, sys
runs = json.load(sys.stdin)["runs"]
for r in runs:
    print(sys.argv[1], sys.argv[2], sys.argv[3], r["length"] / float(sys.argv[4]), r["time_ms"], sep="\t")
' "$family" "$(basename "$scen" .map.scen)#$index" "$label" "$optimum" >>"$rows"
    done
  done < <("$bin/aco-any-angle" "$scen" --sample "$sample" --no-theta-star | awk '$1 ~ /^[0-9]+$/ { print $1, $(NF-1) }')
done
python3 - "$rows" "$sample" "$seeds" <<'EOF'
import collections, sys
rows = [line.rstrip("\n").split("\t") for line in open(sys.argv[1])]
order = ["8, grid", "16, grid", "8, line-of-sight", "16, line-of-sight"]
def table(title, keep):
    groups = collections.defaultdict(list)
    for family, problem, variant, ratio, ms in rows:
        if keep(family):
            groups[variant].append((float(ratio), float(ms)))
    problems = len({r[1] for r in rows if keep(r[0])})
    print(f"\n{title}: {problems} scenarios x {sys.argv[3]} seeds")
    print(f"| variant | mean length / any-angle optimum | worst | mean ms per run |")
    print("|---|---|---|---|")
    for v in order:
        g = groups.get(v, [])
        if not g:
            continue
        print(f"| {v} | {sum(r for r, _ in g) / len(g):.4f} | {max(r for r, _ in g):.4f} | {sum(m for _, m in g) / len(g):.1f} |")
table("Moving AI maps (data/maps/movingai)", lambda f: f == "movingai")
table("generated maps (data/maps/generated)", lambda f: f == "generated")
table("all", lambda f: True)
EOF
