#!/usr/bin/env bash
# A fault campaign as a Slurm job array: one task per shard, every core of the
# task's node used (`--jobs` defaults to all cores). Submit from a DRCC checkout
# with a release build:
#   cargo build --release
#   mkdir -p campaign-results
#   sbatch --array=1-32 scripts/campaign/slurm-array.sh 100000 1 dual   # or star
# then merge:  ./target/release/drcc campaign merge campaign-results/*.jsonl
#SBATCH --job-name=drcc-campaign
#SBATCH --cpus-per-task=8
#SBATCH --time=02:00:00
#SBATCH --output=campaign-results/slurm-%A_%a.out
set -euo pipefail
count="${1:-100000}"
seed="${2:-1}"
topology="${3:-dual}"
shards="${SLURM_ARRAY_TASK_COUNT:?run as a Slurm job array (sbatch --array=1-N)}"
shard="${SLURM_ARRAY_TASK_ID:?run as a Slurm job array (sbatch --array=1-N)}"
mkdir -p campaign-results
exec ./target/release/drcc campaign --topology "$topology" --faults single \
  --count "$count" --seed "$seed" --shard "$shard/$shards" \
  --out "campaign-results/$topology-shard-$shard-of-$shards.jsonl"
