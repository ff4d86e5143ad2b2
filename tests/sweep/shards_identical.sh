#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# An 8-run sweep done sequentially and as two shards under GNU parallel gives byte-identical run
# folders (timing.json, which holds times and the host name, aside); --collect lists all 8 runs.
#   shards_identical.sh SWEEP_EXE SWEEP_FILE WORK_DIR
set -euo pipefail
exe=$1 sweep=$2 work=$3
command -v parallel >/dev/null || { echo "GNU parallel is not installed (scripts/install-deps.sh)"; exit 77; }
rm -rf "$work" && mkdir -p "$work"

"$exe" "$sweep" --out "$work/sequential" --jobs 1
parallel --halt now,fail=1 "$exe" "$sweep" --out "$work/sharded" --shard {}/2 ::: 0 1

runs=$(find "$work/sequential" -mindepth 1 -maxdepth 1 -name 'run_*' | wc -l)
[ "$runs" -eq 8 ] || { echo "FAIL: $runs run folders in the sequential sweep, expected 8"; exit 1; }
compared=0
while IFS= read -r file; do
  rel=${file#"$work/sequential/"}
  case $(basename "$rel") in timing.json) continue ;; esac
  cmp "$file" "$work/sharded/$rel" || { echo "FAIL: $rel differs between the layouts"; exit 1; }
  compared=$((compared + 1))
done < <(find "$work/sequential" -type f | sort)
extra=$(cd "$work/sharded" && find . -type f | sort | sed 's|^\./||' | while IFS= read -r f; do
  [ -e "$work/sequential/$f" ] || echo "$f"; done)
[ -z "$extra" ] || { echo "FAIL: only in the sharded sweep: $extra"; exit 1; }
grep -q '"status": "done"' "$work/sequential/run_000000/run.json" || { echo "FAIL: run 0 not done"; exit 1; }

"$exe" --collect "$work/sharded"
rows=$(($(wc -l < "$work/sharded/index.csv") - 1))
[ "$rows" -eq 8 ] || { echo "FAIL: index.csv has $rows rows, expected 8"; exit 1; }
echo "OK: $compared files identical over 8 runs, sequential vs 2 shards under GNU parallel"
