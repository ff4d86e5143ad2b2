#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# Runs the libFuzzer targets built in BUILD (make fuzz-short / make fuzz-long).
#   run-fuzz.sh BUILD short   each target for FUZZ_SECONDS (default 10) seconds
#   run-fuzz.sh BUILD long    each target for FUZZ_RUNS (default 1000000) executions or
#                             FUZZ_MAX_SECONDS (default 1200) seconds, whichever comes first
# The working corpus grows in BUILD/fuzz/work/<target> (seeded from fuzz/corpus/<target>); a
# crash leaves its input in BUILD/fuzz/artifacts/<target>/ and fails the run. Turn each one into
# a regression: copy it to fuzz/regressions/<target>/ (replayed by CTest) and fix the bug.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: run-fuzz.sh BUILD short|long}
mode=${2:?usage: run-fuzz.sh BUILD short|long}
case "$mode" in
  short) limits=(-max_total_time="${FUZZ_SECONDS:-10}") ;;
  long) limits=(-runs="${FUZZ_RUNS:-1000000}" -max_total_time="${FUZZ_MAX_SECONDS:-1200}") ;;
  *) echo "run-fuzz.sh: mode must be short or long" >&2; exit 2 ;;
esac
declare -A dict=([obj_loader]=obj [ply_loader]=ply [scene_parser]=scene [fracturerb_csv]=fracturerb_csv)
failed=0
summary=()
for target in obj_loader ply_loader scene_parser fracturerb_csv; do
  exe="$build/fuzz/fuzz_$target"
  [ -x "$exe" ] || { echo "run-fuzz.sh: $exe missing (make fuzz-build)" >&2; exit 2; }
  work="$build/fuzz/work/$target"
  artifacts="$build/fuzz/artifacts/$target"
  mkdir -p "$work" "$artifacts"
  cp -n fuzz/corpus/$target/* "$work"/ 2>/dev/null || true
  log="$build/fuzz/$target.log"
  # One process, low priority: the development machine's cores are shared.
  nice -n 19 "$exe" "${limits[@]}" -dict="fuzz/dict/${dict[$target]}.dict" -max_len=4096 -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" "$work" > "$log" 2>&1
  code=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  seconds=$(grep -o 'Done [0-9]* runs in [0-9]* second' "$log" | grep -o 'in [0-9]*' | grep -o '[0-9]*' | tail -1)
  if [ $code -ne 0 ]; then
    failed=1
    summary+=("fuzz_$target: FAILED (exit $code) after ${runs:-?} executions; see $log and $artifacts/")
  else
    summary+=("fuzz_$target: ${runs:-?} executions in ${seconds:-?} s, no crash; corpus $(ls "$work" | wc -l) inputs")
  fi
done
printf '%s\n' "${summary[@]}"
exit $failed
