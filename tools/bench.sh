#!/usr/bin/env bash
# Speed figures: set up, build, run the engine benchmark (arguments go to aco_bench; see
# --help), then acobench's throughput: 10,000 trials of the papers' 20x20 setting
# (bench/throughput.yaml) into a fresh results database, in worker processes and in-process.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh release >/dev/null
build/release/bench/aco_bench "$@"
echo
echo "acobench throughput (bench/throughput.yaml: 10,000 trials, map1, 50 ants x 100 iterations),"
echo "trials in worker processes (the default) and --in-process, in turn, three times each:"
dir=$(mktemp -d)
for round in 1 2 3; do
  for mode in workers in-process; do
    rm -f "$dir/throughput.db"*
    flag=(); [ "$mode" = in-process ] && flag=(--in-process)
    echo -n "  $mode: "
    build/release/hosts/acobench/acobench run bench/throughput.yaml --db "$dir/throughput.db" "${flag[@]}" 2>/dev/null |
      grep -o '[0-9.]* trials/s'
  done
done
rm -rf "$dir"
