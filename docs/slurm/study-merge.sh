#!/bin/bash
# After study-array.sh: the shards' databases merged into study.db, then what shards do not run
# (the rounds of an ablation path, if the study has one; nothing else when every shard
# succeeded), then the report; the job ends with acobench run's verdict (3: trials failed).
#SBATCH --job-name=aco-merge
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=32
#SBATCH --time=04:00:00
set -euo pipefail
cd "$SLURM_SUBMIT_DIR"
acobench merge study.shard-*-of-*.db --db study.db
verdict=0
acobench run study.yaml --db study.db --threads "$SLURM_CPUS_PER_TASK" || verdict=$?
acobench report study.db --out study-report
exit "$verdict"
