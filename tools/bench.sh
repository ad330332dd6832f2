#!/usr/bin/env bash
# Speed figures: set up, build, run the engine benchmark (arguments go to aco_bench; see
# --help), then acobench's throughput: 10,000 trials of the papers' 20x20 setting
# (bench/throughput.yaml) into a fresh results database.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh release >/dev/null
build/release/bench/aco_bench "$@"
echo
echo "acobench throughput (bench/throughput.yaml: 10,000 trials, map1, 50 ants x 100 iterations):"
db=$(mktemp -d)/throughput.db
build/release/hosts/acobench/acobench run bench/throughput.yaml --db "$db" 2>/dev/null
rm -rf "$(dirname "$db")"
