#!/usr/bin/env bash
# The any-angle yardstick on the bundled large maps: for each Moving AI map of data/maps/movingai
# and the 2048x2048 cave of data/maps/large, the ratio of the exact any-angle optimum to the
# file's octile optimum over SAMPLE scenarios evenly spread over the file, and the time of one
# search (any-angle, and basic Theta* beside it) over the LONGEST scenarios of largest octile
# optimum (LONGEST_LARGE of them on the cave, where Theta* alone takes seconds).
#   tools/any-angle-bench.sh [SAMPLE [LONGEST [LONGEST_LARGE]]]     defaults 40 10 3
# Builds build/release first (tools/build.sh). Times are wall-clock on this machine, one thread.
set -euo pipefail
cd "$(dirname "$0")/.."
sample=${1:-40}
longest=${2:-10}
longest_large=${3:-3}
tools/build.sh release >/dev/null
tool=build/release/bin/aco-any-angle
summary() { "$tool" "$@" | tail -n 1; }  # the tool's last line: "# N scenarios: ..."
printf '%-26s %9s %9s %9s %11s %11s %11s %11s\n' map size ratio_mean ratio_min any_ms_mean any_ms_max \
  theta_ms_mean theta_ms_max
for scen in data/maps/movingai/*.scen data/maps/movingai/*/*.scen data/maps/large/*.scen; do
  n=$longest
  case $scen in data/maps/large/*) n=$longest_large ;; esac
  ratios=$(summary "$scen" --sample "$sample" --no-theta-star)
  times=$(summary "$scen" --longest "$n" --time)
  size=$(awk 'NR == 2 { print $3 "x" $4 }' "$scen")
  # "# 40 scenarios: any-angle/octile mean 0.95717 min 0.95386"
  read -r mean min < <(sed -E 's/.*mean ([0-9.]+) min ([0-9.]+).*/\1 \2/' <<<"$ratios")
  # "...; any-angle ms mean 2.4 max 5.4; theta* ms mean 16.0 max 22.0"
  read -r any_mean any_max theta_mean theta_max < <(
    sed -E 's/.*any-angle ms mean ([0-9.]+) max ([0-9.]+); theta\* ms mean ([0-9.]+) max ([0-9.]+).*/\1 \2 \3 \4/' <<<"$times")
  printf '%-26s %9s %9s %9s %11s %11s %11s %11s\n' "$(basename "$scen" .map.scen)" "$size" "$mean" "$min" \
    "$any_mean" "$any_max" "$theta_mean" "$theta_max"
done
echo "ratio: any-angle optimum / octile optimum over $sample scenarios spread over each file; times (ms): one search,"
echo "over the $longest scenarios of largest octile optimum ($longest_large on data/maps/large)"
