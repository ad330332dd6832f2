#!/usr/bin/env bash
# Does the recommended pipeline's pheromone matter on maps nobody tuned on? (docs/learning.md)
# Generates fresh validation maps (aco_mapgen --benchmark with SEED, default 9001: not the
# shipped maps' seeds 1-3), takes 10 scenarios of each 512x512 map (random, room, maze, two
# maps each: 60 problems) plus every scenario file named in EXTRA_SCEN (public maps you fetched,
# say; 10 scenarios each), and runs each configuration against its no-learning and restart
# twins with 3 repetitions (seeds) in acobench. Prints the report's summary tables.
#   tools/learning-study.sh [SEED] [OUTDIR]       OUTDIR default: build/learning-study-SEED
# CONFIGS: extra configurations as YAML flow mappings, one per line (default: none), e.g.
#   CONFIGS='{name: MMAS, update: max_min, heuristic: progress, beta: 3, deadlock: backtrack}'
# The restart twin runs without the walk limit: on room maps it takes much longer than the colony.
set -euo pipefail
cd "$(dirname "$0")/.."
seed="${1:-9001}"
out="${2:-build/learning-study-$seed}"
[ -x build/release/hosts/acobench/acobench ] || tools/build.sh release >/dev/null
root=$(pwd)
mkdir -p "$out/maps"
[ -e "$out/maps/random512-20-s$seed.map.scen" ] || build/release/tools/aco_mapgen --benchmark "$out/maps" "$seed" >/dev/null
{
  echo "name: learning-study-$seed"
  echo "seed: $seed"
  echo "repetitions: 3"
  echo "problems:"
  for scen in "$out"/maps/*512-*.map.scen ${EXTRA_SCEN:-}; do
    echo "  - {scen: $(realpath "$scen"), count: 10}"
  done
  echo "baseline: {name: robust preset, config: $root/data/presets/robust.ini}"
  if [ -n "${CONFIGS:-}" ]; then
    echo "configurations:"
    while IFS= read -r config; do [ -n "$config" ] && echo "  - $config"; done <<<"$CONFIGS"
  fi
  echo "null-models: true"
} >"$out/study.yaml"
build/release/hosts/acobench/acobench run "$out/study.yaml" --db "$out/study.db" --threads 2 >&2
build/release/hosts/acobench/acobench report "$out/study.db" --out "$out/report" >/dev/null
awk '/^## / { keep = /^## (Does the pheromone matter\?|Summary by problem set)/ } keep' "$out/report/report.md"
echo "Full report: $out/report/report.html"
