#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# One task of a Slurm job array runs one shard of a sweep (README "Sweeps"):
#   sbatch --array=0-15 scripts/slurm-sweep.sh SWEEP OUT [more btfracture-sweep options]
# Task t of a contiguous array min..max runs shard (t - min)/(max - min + 1); resubmitting the
# same array after a failure or a time limit skips the finished runs. Each task runs
# SLURM_CPUS_PER_TASK runs at once (default 1), one thread each. BTFRACTURE_SWEEP names the
# executable (default: btfracture-sweep on PATH).
#SBATCH --job-name=btfracture-sweep
#SBATCH --cpus-per-task=1
#SBATCH --mem-per-cpu=2G
#SBATCH --output=slurm-%A_%a.out
set -euo pipefail

if [ $# -lt 2 ]; then
  echo "usage: sbatch --array=0-(K-1) $0 SWEEP OUT [btfracture-sweep options]" >&2
  exit 2
fi
sweep=$1
out=$2
shift 2

task=${SLURM_ARRAY_TASK_ID:?not a Slurm array task (submit with sbatch --array=...)}
first=${SLURM_ARRAY_TASK_MIN:-0}
last=${SLURM_ARRAY_TASK_MAX:?SLURM_ARRAY_TASK_MAX is not set}
count=$((last - first + 1))
if [ -n "${SLURM_ARRAY_TASK_COUNT:-}" ] && [ "$SLURM_ARRAY_TASK_COUNT" -ne "$count" ]; then
  echo "slurm-sweep: the array must be contiguous (--array=a-b, no step or list)" >&2
  exit 2
fi
shard=$((task - first))

exec "${BTFRACTURE_SWEEP:-btfracture-sweep}" "$sweep" --out "$out" --shard "$shard/$count" \
  --jobs "${SLURM_CPUS_PER_TASK:-1}" "$@"
