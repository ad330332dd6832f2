#!/usr/bin/env bash
# Runs the Slurm batch scripts of docs/slurm/ under a real Slurm on this machine and checks that
# each gives the database a single-process run gives, trial for trial:
#   - study-mpi.sh: 3 MPI ranks on this one node (rank 0 coordinates, 2 workers);
#   - study-array.sh as a job array of 3 shards, then study-merge.sh after it (afterok).
# The scripts run as written; only their size is scaled down from the sbatch command line
# (one node, 3 tasks, 1 CPU each). The study is data/experiments/ablation.yaml (every paper's
# plugins on 11 problems, then an ablation path) with REPETITIONS repetitions.
# Without a running Slurm it starts a one-node cluster (Debian's slurm-wlm and munge, installed by
# tools/setup.sh; as root):
# slurmctld and slurmd for this host, no cgroups.
#   tools/slurm-check.sh [REPETITIONS]   (default 2)
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
tools/setup.sh slurm-wlm munge
tools/build.sh release >/dev/null
export PATH="$repo/build/release/hosts/acobench:$PATH"

start_local_slurm() {
  [ "$(id -u)" -eq 0 ] || { echo "slurm-check: no Slurm is running, and starting one needs root" >&2; exit 1; }
  local host marker="# A one-node Slurm written by tools/slurm-check.sh"
  if [ -e /etc/slurm/slurm.conf ] && [ "$(head -1 /etc/slurm/slurm.conf)" != "$marker" ]; then
    echo "slurm-check: no Slurm is running, and /etc/slurm/slurm.conf is not this script's: start that Slurm first" >&2
    exit 1
  fi
  host=$(hostname -s)
  mkdir -p /var/spool/slurmd /var/log/slurm /run/munge /var/lib/slurm/slurmctld
  chown slurm:slurm /var/log/slurm /var/lib/slurm/slurmctld
  chown munge:munge /run/munge
  # The node line as slurmd measures this machine (CPUs, sockets, cores), without its memory:
  # a node found with less memory than configured is drained.
  cat >/etc/slurm/slurm.conf <<EOF
$marker
ClusterName=local
SlurmctldHost=$host
SlurmUser=slurm
AuthType=auth/munge
StateSaveLocation=/var/lib/slurm/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
$(slurmd -C | head -1 | sed 's/RealMemory=[0-9]*//') State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
  pgrep -x munged >/dev/null || su -s /bin/sh munge -c /usr/sbin/munged
  slurmctld
  slurmd
  for _ in $(seq 30); do
    sinfo -h -o %T 2>/dev/null | grep -q idle && return 0
    sleep 1
  done
  echo "slurm-check: the local Slurm did not come up; see /var/log/slurm/" >&2
  exit 1
}
sinfo -h >/dev/null 2>&1 || start_local_slurm
echo "slurm-check: $(sinfo --version), node $(sinfo -h -o '%N, %c CPUs, %T')"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
study() {
  mkdir -p "$work/$1"
  sed "s/^repetitions: .*/repetitions: ${REPETITIONS}/; s|\.\./maps|$repo/data/maps|" data/experiments/ablation.yaml \
    >"$work/$1/study.yaml"
}
REPETITIONS=${1:-2}
study reference
acobench run "$work/reference/study.yaml" --db "$work/reference/study.db" >/dev/null

# Passes when merging a run's database with the reference finds the same trials in both, equal:
# merge refuses a trial held twice with different results, and copies each trial once, so the
# trials copied equal those held twice only when both databases hold the same trials.
same_as_reference() {
  local label=$1 db=$2 out copied twice
  if ! out=$(acobench merge "$work/reference/study.db" "$db" --db "$(mktemp -u "$work/check-XXXX.db")" 2>&1); then
    echo "slurm-check: $label FAILED, its database differs from the single-process one: $out" >&2
    return 1
  fi
  copied=$(grep -o '[0-9]* trials copied' <<<"$out" | grep -o '^[0-9]*')
  twice=$(grep -o '[0-9]* held twice' <<<"$out" | grep -o '^[0-9]*')
  if [ "$copied" != "$twice" ]; then
    echo "slurm-check: $label FAILED, the two databases hold different trials: $out" >&2
    return 1
  fi
  echo "slurm-check: $label: the same $copied trials as the single-process run, with the same results"
}

# Submits a batch job from folder $1 (the other arguments are sbatch's), waits for it, and prints
# its final state: COMPLETED, FAILED, CANCELLED... (sbatch --wait exits 0 for a job cancelled
# because the jobs it depends on failed).
run_job() {
  local folder=$1 id
  shift
  id=$(cd "$folder" && sbatch --parsable --wait "$@") || true
  scontrol show job "$id" -o | grep -o 'JobState=[A-Z_]*' | cut -d= -f2
}

failed=0
# A batch job's verdict: it completed, and its database is the reference's.
verdict() {
  local label=$1 state=$2 db=$3
  if [ "$state" != COMPLETED ]; then
    echo "slurm-check: $label FAILED: its last batch job ended $state (the output is above)" >&2
    failed=1
  else
    same_as_reference "$label" "$db" || failed=1
  fi
}

study mpi
state=$(run_job "$work/mpi" --nodes=1 --ntasks=3 --cpus-per-task=1 --output=slurm-%j.out "$repo/docs/slurm/study-mpi.sh")
sed 's/^/  mpi | /' "$work"/mpi/*.out || true
verdict "study-mpi.sh (srun --mpi=pmix, 3 ranks)" "$state" "$work/mpi/study.db"

study array
array=$(cd "$work/array" && sbatch --parsable --array=1-3 --cpus-per-task=1 --output=slurm-%A_%a.out \
  "$repo/docs/slurm/study-array.sh")
# --kill-on-invalid-dep: if a shard fails, the merge job is cancelled instead of waiting forever.
state=$(run_job "$work/array" --dependency="afterok:$array" --kill-on-invalid-dep=yes --cpus-per-task=1 \
  --output=merge-%j.out "$repo/docs/slurm/study-merge.sh")
sed 's/^/  array | /' "$work"/array/slurm-*.out "$work"/array/merge-*.out || true
verdict "study-array.sh (3 shards) + study-merge.sh" "$state" "$work/array/study.db"
exit "$failed"
