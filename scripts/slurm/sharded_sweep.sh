#!/bin/bash
# A sharded equilibrium sweep (or stiffness study) as a Slurm job array, then
# the merge once every shard has finished:
#
#   jid=$(sbatch --parsable --array=1-16 scripts/slurm/sharded_sweep.sh \
#         equilibria scenarios/dense_grid_pac89_load_transfer.toml out/dense)
#   sbatch --dependency=afterok:$jid --wrap \
#         "handling merge out/dense/shard-*-of-16.json --out out/dense"
#
# Arguments: the command (equilibria or study), its input file, the output
# folder shared by the array's tasks. N is the array's size, K the task's
# index (arrays numbered from 1). Each shard writes out/…/shard-K-of-N.json;
# the merge writes the outputs of the unsharded run, byte for byte. Shard files
# name their inputs by absolute path, so the merge may run in any directory
# of a machine that sees the same files at the same paths.
#SBATCH --job-name=handling-shard
#SBATCH --cpus-per-task=2
#SBATCH --time=01:00:00
set -euo pipefail
command=$1
input=$2
out=$3
k=${SLURM_ARRAY_TASK_ID:?run as a job array: sbatch --array=1-N}
n=${SLURM_ARRAY_TASK_COUNT:?run as a job array: sbatch --array=1-N}
export RAYON_NUM_THREADS=${SLURM_CPUS_PER_TASK:-2}
exec handling "$command" "$input" --shard "$k/$n" --out "$out"
