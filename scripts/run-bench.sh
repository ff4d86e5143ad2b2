#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# Runs every benchmark executable built under BUILD/bench; each prints lines "METRIC <name> <value> <unit>".
set -euo pipefail
build=${1:-build}
shopt -s nullglob
found=0
for b in "$build"/bench/bench_*; do
  [ -x "$b" ] || continue
  found=1
  echo "== $(basename "$b")"
  "$b"
done
[ $found -eq 1 ] || echo "run-bench: no benchmarks built under $build/bench"
