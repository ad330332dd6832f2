#!/bin/bash
# acobench without MPI: a job array of 8 tasks, each running one shard of the study into its own
# database (study.shard-K-of-8.db). Submit from the folder holding study.yaml:
#   jobid=$(sbatch --parsable study-array.sh)
#   sbatch --dependency=afterok:$jobid study-merge.sh
# A task that failed or ran out of time is resubmitted alone (sbatch --array=5 study-array.sh)
# and resumes its shard. Failed trials are results (stored, reported): --allow-failures keeps them
# from failing the task, which would hold back the merge.
#SBATCH --job-name=aco-shards
#SBATCH --array=1-8
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=32
#SBATCH --time=04:00:00
set -euo pipefail
cd "$SLURM_SUBMIT_DIR"
acobench run study.yaml --shard "$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT" --threads "$SLURM_CPUS_PER_TASK" --allow-failures
