#!/bin/bash
# acobench under MPI on four nodes of 32 cores: rank 0 coordinates and writes the database, the
# other four ranks run trials on all cores of their node; the coordinator shares the first node.
# Submit from the folder holding study.yaml: sbatch study-mpi.sh. Rerunning it resumes the study.
#SBATCH --job-name=aco-study
#SBATCH --nodes=4
#SBATCH --ntasks=5
#SBATCH --cpus-per-task=32
#SBATCH --overcommit
#SBATCH --time=12:00:00
set -euo pipefail
cd "$SLURM_SUBMIT_DIR"
verdict=0  # 3 when trials failed (stored and reported): the report is written all the same
srun --mpi=pmix acobench run study.yaml --db study.db --threads "$SLURM_CPUS_PER_TASK" || verdict=$?
acobench report study.db --out study-report
exit "$verdict"
