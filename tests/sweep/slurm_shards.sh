#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# The Slurm script's shard arithmetic without Slurm: for arrays 0..K-1 and 1..K (K = 1..5), the
# tasks' shares (btfracture-sweep --list through the script, with Slurm's environment faked)
# cover every run of the sweep exactly once; a non-contiguous array is refused.
#   slurm_shards.sh SLURM_SCRIPT SWEEP_EXE SWEEP_FILE
set -euo pipefail
script=$1 exe=$2 sweep=$3
runs=8
for first in 0 1; do
  for count in 1 2 3 4 5; do
    last=$((first + count - 1))
    listed=$(for task in $(seq "$first" "$last"); do
      SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_MIN=$first SLURM_ARRAY_TASK_MAX=$last \
        SLURM_ARRAY_TASK_COUNT=$count BTFRACTURE_SWEEP=$exe "$script" "$sweep" unused --list
    done | sort -n | tr '\n' ' ')
    expected=$(seq 0 $((runs - 1)) | tr '\n' ' ')
    [ "$listed" = "$expected" ] || { echo "FAIL: array $first-$last covers '$listed', expected '$expected'"; exit 1; }
  done
done
if SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=6 SLURM_ARRAY_TASK_COUNT=4 \
  BTFRACTURE_SWEEP=$exe "$script" "$sweep" unused --list 2>/dev/null; then
  echo "FAIL: a stepped array (0-6:2) was accepted"; exit 1
fi
echo "OK: arrays 0..K-1 and 1..K, K = 1..5, cover the $runs runs exactly once"
