#!/usr/bin/env bash
# acobench beyond one process, on this machine: bench/throughput.yaml (10,000 trials of the
# papers' 20x20 setting) as one process, under mpirun with 1, 2 and 4 ranks (rank 0 coordinates,
# the others run trials on all cores each, or on one thread each), and as 3 shards plus their
# merge. Prints trials per second and the coordinator's time per trial. mpirun runs with
# --bind-to none: by default it binds each rank to one core when -n is 2 or less.
#   tools/bench-cluster.sh [REPETITIONS]   (default 10000)
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh release >/dev/null
acobench=$PWD/build/release/hosts/acobench/acobench
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed "s/^repetitions: .*/repetitions: ${1:-10000}/; s|\.\./data|$PWD/data|" bench/throughput.yaml > "$work/throughput.yaml"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # containers run as root
echo "acobench on $(nproc) cores, bench/throughput.yaml with ${1:-10000} repetitions:"

# The summary line's trials/s, and the coordinator's line under MPI.
report() {
  local label=$1 log=$2
  printf '  %-44s %s\n' "$label" "$(grep -o '[0-9.]* trials/s' "$log")"
  if grep -q "worker ranks" "$log"; then printf '  %-44s %s\n' "" "$(grep -o 'coordinator.*' "$log")"; fi
}

"$acobench" run "$work/throughput.yaml" --db "$work/single.db" >"$work/single.log" 2>/dev/null
report "one process, $(nproc) threads" "$work/single.log"
for ranks in 1 2 4; do
  mpirun --oversubscribe --bind-to none -n "$ranks" "$acobench" run "$work/throughput.yaml" --db "$work/mpi$ranks.db" \
    >"$work/mpi$ranks.log" 2>/dev/null
  report "mpirun -n $ranks, workers on all cores" "$work/mpi$ranks.log"
done
mpirun --oversubscribe --bind-to none -n 3 "$acobench" run "$work/throughput.yaml" --db "$work/mpi3t1.db" --threads 1 \
  >"$work/mpi3t1.log" 2>/dev/null
report "mpirun -n 3, workers on 1 thread each" "$work/mpi3t1.log"

began=$(date +%s.%N)
for k in 1 2 3; do
  "$acobench" run "$work/throughput.yaml" --shard "$k/3" --db "$work/shard$k.db" >/dev/null 2>&1
done
sharded=$(date +%s.%N)
"$acobench" merge "$work"/shard{1,2,3}.db --db "$work/merged.db" >/dev/null
merged=$(date +%s.%N)
awk -v a="$began" -v b="$sharded" -v c="$merged" \
  'BEGIN { printf "  %-44s %.1f s for the 3 shards one after the other, %.1f s to merge\n", "3 shards + merge", b - a, c - b }' 
