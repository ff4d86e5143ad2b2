#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# A sweep killed (SIGKILL, with its runs) while a run is under way, then resumed: every run ends
# done exactly once - the runs finished before the kill are not run again (same run.json inode,
# one attempt), the run cut short has no run.json (so it does not count as done) and is run
# again from an emptied folder (two attempts).
#   resume_after_kill.sh SWEEP_EXE SWEEP_FILE WORK_DIR
set -euo pipefail
exe=$1 sweep=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
out=$work/out
mkdir -p "$out"

setsid "$exe" "$sweep" --out "$out" --jobs 1 2> "$work/first.log" &
leader=$!
# Wait until at least one run has finished and the next one has started.
for _ in $(seq 1 600); do
  finished=$(find "$out" -name run.json | wc -l)
  started=$(find "$out" -name attempts | wc -l)
  [ "$finished" -ge 1 ] && [ "$started" -gt "$finished" ] && break
  sleep 0.05
done
kill -KILL -- "-$leader"
wait "$leader" 2>/dev/null || true
sleep 0.2

finished=$(find "$out" -name run.json | wc -l)
partial=()
for dir in "$out"/run_*; do
  [ -e "$dir/run.json" ] || partial+=("$dir")
done
if [ "$finished" -lt 1 ] || [ "$finished" -ge 8 ]; then
  echo "FAIL: $finished runs finished before the kill"; exit 1
fi
[ "${#partial[@]}" -ge 1 ] || { echo "FAIL: no run was under way at the kill"; exit 1; }
declare -A inode
for json in "$out"/run_*/run.json; do inode[$json]=$(stat -c %i "$json"); done

"$exe" "$sweep" --out "$out" --jobs 2

for i in $(seq 0 7); do
  dir=$(printf '%s/run_%06d' "$out" "$i")
  grep -q '"status": "done"' "$dir/run.json" || { echo "FAIL: $dir not done"; exit 1; }
  attempts=$(cat "$dir/attempts")
  if [ -n "${inode[$dir/run.json]:-}" ]; then
    [ "${inode[$dir/run.json]}" = "$(stat -c %i "$dir/run.json")" ] || { echo "FAIL: $dir was run again"; exit 1; }
    [ "$attempts" -eq 1 ] || { echo "FAIL: $dir finished before the kill but has $attempts attempts"; exit 1; }
  fi
done
for dir in "${partial[@]}"; do
  [ "$(cat "$dir/attempts")" -eq 2 ] || { echo "FAIL: $dir, cut short, was not run a second time"; exit 1; }
  find "$dir" -name '*.tmp' | grep -q . && { echo "FAIL: temporary file left in $dir"; exit 1; }
done
# A third invocation finds nothing to do.
"$exe" "$sweep" --out "$out" 2>&1 | grep -q "8 finished before, 0 to do" || { echo "FAIL: finished runs not skipped"; exit 1; }
echo "OK: $finished runs finished before the kill, ${#partial[@]} cut short and redone, all 8 done once"
