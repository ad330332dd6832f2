#!/usr/bin/env bash
# Speed figures: set up, build, run the benchmark (arguments go to aco_bench; see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh release >/dev/null
exec build/release/bench/aco_bench "$@"
