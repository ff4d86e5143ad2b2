#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# Sweep throughput for sizing cluster jobs: RUNS runs of demos/sweep/bunny_impacts.json (100
# steps each) at 500 and at 1,000 BEM triangles, JOBS at once, one thread each. Prints
#   METRIC sweep_bem<N>_runs_per_hour <value> runs/h
#   METRIC sweep_bem<N>_seconds_per_run <value> s        (mean wall time of one run)
#   METRIC sweep_bem<N>_cpu_seconds_per_run <value> s    (mean CPU time of one run; on a shared
#     machine 3600 x cores / this is the rate undisturbed cores would give)
#   METRIC sweep_bem<N>_longest_run <value> s             (CPU time of the slowest run)
#   METRIC sweep_bem<N>_peak_memory_per_run <value> MB   (largest resident set of a run)
#   bench/sweep_throughput.sh [BUILD] [RUNS] [JOBS]      (defaults build 8 2)
set -euo pipefail
build=${1:-build}
runs=${2:-8}
jobs=${3:-2}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for bem in 500 1000; do
  sweep=$work/bunny_bem$bem.json
  sed -e "s|\"../scenes/bunny_smash.json\"|\"$root/demos/scenes/bunny_smash.json\"|" \
      -e "s|\"runs\": 1000|\"runs\": $runs, \"bem_triangles\": $bem|" \
      "$root/demos/sweep/bunny_impacts.json" > "$sweep"
  start=$(date +%s.%N)
  "$build/demos/btfracture-sweep" "$sweep" --out "$work/out$bem" --jobs "$jobs" --threads 1 || true
  end=$(date +%s.%N)
  "$build/demos/btfracture-sweep" --collect "$work/out$bem" > /dev/null
  # index.csv columns: status 2, wall_s 27, cpu_s 29, peak_memory_mb 30
  awk -F, -v runs="$runs" -v start="$start" -v end="$end" -v bem="$bem" 'NR > 1 {
      n++; done += ($2 == "done"); seconds += $27; cpu += $29; if ($29 > longest) longest = $29; if ($30 > memory) memory = $30 }
    END {
      wall = end - start
      if (n != runs) { print "sweep_throughput: " n " of " runs " runs finished" > "/dev/stderr"; exit 1 }
      printf "METRIC sweep_bem%d_runs_per_hour %.0f runs/h\n", bem, 3600 * runs / wall
      printf "METRIC sweep_bem%d_seconds_per_run %.1f s\n", bem, seconds / n
      printf "METRIC sweep_bem%d_cpu_seconds_per_run %.1f s\n", bem, cpu / n
      printf "METRIC sweep_bem%d_longest_run %.1f s\n", bem, longest
      printf "METRIC sweep_bem%d_peak_memory_per_run %.0f MB\n", bem, memory
      printf "sweep_throughput: BEM %d: %d runs (%d done) in %.0f s wall\n", bem, n, done, wall > "/dev/stderr"
    }' "$work/out$bem/index.csv"
done
