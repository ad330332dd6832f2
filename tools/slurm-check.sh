#!/usr/bin/env bash
# Runs the Slurm batch scripts of docs/slurm/ under a real Slurm on this machine and checks that
# each gives the database a single-process run gives, trial for trial:
#   - study-mpi.sh: 3 MPI ranks on this one node (rank 0 coordinates, 2 workers);
#   - study-array.sh as a job array of 3 shards, then study-merge.sh after it (afterok).
# The scripts run as written; only their size is scaled down from the sbatch command line
# (one node, 3 tasks, 1 CPU each). The study is data/experiments/ablation.yaml (every paper's
# plugins on 11 problems, then an ablation path) with REPETITIONS repetitions.
# Without a running Slurm it starts a one-node cluster (Debian's slurm-wlm and munge, as root):
# slurmctld and slurmd for this host, no cgroups.
#   tools/slurm-check.sh [REPETITIONS]   (default 2)
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
tools/build.sh release >/dev/null
export PATH="$repo/build/release/hosts/acobench:$PATH"

start_local_slurm() {
  [ "$(id -u)" -eq 0 ] || { echo "slurm-check: no Slurm is running, and starting one needs root" >&2; exit 1; }
  local missing=()
  for package in slurm-wlm munge; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
  done
  if ((${#missing[@]})); then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
  fi
  local host marker="# A one-node Slurm written by tools/slurm-check.sh"
  if [ -e /etc/slurm/slurm.conf ] && [ "$(head -1 /etc/slurm/slurm.conf)" != "$marker" ]; then
    echo "slurm-check: no Slurm is running, and /etc/slurm/slurm.conf is not this script's: start that Slurm first" >&2
    exit 1
  fi
  host=$(hostname -s)
  mkdir -p /var/spool/slurmd /var/log/slurm /run/munge /var/lib/slurm/slurmctld
  chown slurm:slurm /var/log/slurm /var/lib/slurm/slurmctld
  chown munge:munge /run/munge
  # The node line as slurmd measures this machine (CPUs, sockets, memory).
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

failed=0
study mpi
(cd "$work/mpi" && sbatch --wait --quiet --nodes=1 --ntasks=3 --cpus-per-task=1 --output=slurm-%j.out \
  "$repo/docs/slurm/study-mpi.sh") || { failed=1; cat "$work"/mpi/slurm-*.out >&2; }
sed 's/^/  mpi | /' "$work"/mpi/slurm-*.out
[ "$failed" -eq 1 ] || same_as_reference "study-mpi.sh (srun --mpi=pmix, 3 ranks)" "$work/mpi/study.db" || failed=1

study array
array=$(cd "$work/array" && sbatch --parsable --array=1-3 --cpus-per-task=1 --output=slurm-%A_%a.out \
  "$repo/docs/slurm/study-array.sh")
(cd "$work/array" && sbatch --wait --quiet --dependency="afterok:$array" --cpus-per-task=1 --output=merge-%j.out \
  "$repo/docs/slurm/study-merge.sh") || { failed=1; cat "$work"/array/*.out >&2; }
sed 's/^/  array | /' "$work"/array/slurm-*.out "$work"/array/merge-*.out
[ "$failed" -eq 1 ] ||
  same_as_reference "study-array.sh (3 shards) + study-merge.sh" "$work/array/study.db" || failed=1
exit "$failed"
