#!/usr/bin/env bash
# Issue 15's two scaling measurements, for a machine with 16 cores (docs/performance.md,
# "Scaling beyond 2 cores"): no such machine was at hand when esc's figures were taken, so
# this script holds the whole measurement, to run in a few minutes wherever one is.
#   1. `esc bench --threads 16`: one generation of the obstacle workload on 1..16 threads;
#      the target is a speed-up of at least 14x at 16 threads.
#   2. The same paper script by `esc run --threads 16` (one process) and by
#      `mpirun -np 16 esc run --threads 1` (16 ranks): wall times within 10%, and the same
#      summary.json (results never depend on how the work is spread).
# Usage: scripts/scaling-16.sh [ESC_BINARY] [WORKERS]   (defaults: build/cli/esc, 16)
# Environment: GENERATIONS (default 60) and RUNS (default 2) size the run of part 2;
# MIN_TIME (default 1) is esc bench's seconds per benchmark.
set -euo pipefail

esc=${1:-build/cli/esc}
workers=${2:-16}
generations=${GENERATIONS:-60}
runs=${RUNS:-2}
min_time=${MIN_TIME:-1}
script=experiments/paper/obstacle_avoidance.esc
out=$(mktemp -d "${TMPDIR:-/tmp}/esc-scaling.XXXXXX")
trap 'rm -rf "$out"' EXIT

if [[ ! -x $esc ]]; then
  echo "scaling-16.sh: error: no esc binary at '$esc'" >&2
  echo "help: build it first (cmake --build build), or pass its path as the first argument" >&2
  exit 2
fi
cores=$(nproc)
if (( cores < workers )); then
  echo "scaling-16.sh: warning: this machine has $cores cores, fewer than the $workers workers measured" >&2
fi

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $cores cores"
echo "esc: $("$esc" --version | head -1)"
echo

echo "== 1. esc bench --threads $workers (speed-up of one generation over 1 thread; target >= 14x at 16)"
"$esc" bench --threads "$workers" --min-time "$min_time" \
  --benchmark --benchmark_filter='threads/obstacle_avoidance' | tee "$out/bench.txt" |
  grep -E '^ *[0-9]+ threads? ?:' || { cat "$out/bench.txt"; exit 1; }
echo

# Wall-clock seconds of a command, its output kept in a log.
timed() {
  local log=$1
  shift
  local start end
  start=$(date +%s.%N)
  "$@" >"$log" 2>&1 || { cat "$log" >&2; return 1; }
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}

echo "== 2. $script, --runs $runs --generations $generations: threads against MPI ranks (target: within 10%)"
args=(run "$script" --runs "$runs" --generations "$generations" --seed 1)
threads_s=$(timed "$out/threads.log" "$esc" "${args[@]}" --threads "$workers" --out "$out/threads")
mpi=(mpirun --oversubscribe)
if (( EUID == 0 )); then mpi+=(--allow-run-as-root); fi
mpi_s=$(timed "$out/mpi.log" "${mpi[@]}" -np "$workers" "$esc" "${args[@]}" --threads 1 --out "$out/mpi")
same=no
if cmp -s "$out/threads/summary.json" "$out/mpi/summary.json"; then same=yes; fi
printf '%-40s %10s\n' "how" "wall s"
printf '%-40s %10.1f\n' "esc run --threads $workers" "$threads_s"
printf '%-40s %10.1f\n' "mpirun -np $workers esc run --threads 1" "$mpi_s"
printf 'MPI / threads: %.3f   same summary.json: %s\n' "$(echo "$mpi_s / $threads_s" | bc -l)" "$same"
