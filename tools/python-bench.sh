#!/usr/bin/env bash
# What a pheromone update written in Python costs: Ant System in numpy (examples/python/ant_system.py,
# through update/python) against the native update/ant_system, per iteration, on classic map1 and
# on a 512x512 map. Both give the same walks bit for bit, so the difference in time per iteration is
# the update's own. Time per iteration is read from acoplan's --json (convergence_time_s, from the
# end of the first iteration to the end of the last: the start-up of Python and the first call are
# left out), best of ROUNDS runs (default 3), on one thread. A benchmark, not a test.
#   tools/python-bench.sh [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-3}
tools/build.sh release >/dev/null
acoplan=build/release/hosts/acoplan/acoplan

# Milliseconds per iteration, the best of the rounds.
per_iteration() {
  for ((round = 0; round < rounds; ++round)); do
    "$acoplan" "$@" --threads 1 --json | python3 -c '
import json, sys
c = json.load(sys.stdin)["convergence_time_s"]
print((c[-1] - c[0]) / (len(c) - 1) * 1000)'
  done | sort -g | head -1
}

row() {
  local name=$1 settings=$2
  shift 2
  local native python
  native=$(per_iteration "$@" --update ant_system)
  python=$(per_iteration "$@" --update python --update.class ant_system:AntSystem --update.path examples/python)
  awk -v name="$name" -v settings="$settings" -v n="$native" -v p="$python" \
    'BEGIN { printf "| %s | %s | %.3f | %.3f | %+.3f | %.1f |\n", name, settings, n, p, p - n, p / n }'
}

echo "Ant System's update in Python (update/python) against C++ (update/ant_system): ms per iteration,"
echo "best of $rounds runs, 1 thread; the walks are the same, so the difference is the update's cost."
echo
echo "| map | colony | C++ ms/it | Python ms/it | Python - C++ | ratio |"
echo "|---|---|---|---|---|---|"
row "classic map1 (20x20, 1,708 edges)" "ant-system preset: 50 ants x 100 it" \
  --preset ant-system --scen data/maps/classic20/map1.txt.scen --corner-cutting
row "room512-32-s1 #19 (512x512, 1,882,996 edges)" "robust preset: 50 ants x 20 it" \
  --scen data/maps/generated/room512-32-s1.map.scen --scen-index 19 --ants 50 --iterations 20
