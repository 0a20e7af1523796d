#!/usr/bin/env bash
# Issue 44's speed check: evaluations per second per core of Lehman & Stanley's own program
# (novelty-search-cpp, built outside this repository) beside esc's NEAT on lib/navigator.esc,
# the same algorithm (NEAT scored by novelty) on the same mazes, each run to its first solution,
# one after the other on this machine, in CPU time (docs/performance.md).
# Build theirs first: git clone https://github.com/jal278/novelty-search-cpp; cd novelty-search-cpp;
# make CFLAGS="-O3 -std=gnu++98 -w".
# Usage: scripts/navigator-vs-authors.sh PEER_DIR [ESC_BINARY] [RUNS]   (defaults: build/cli/esc, 3)
# Prints one line per program and maze: evaluations, CPU seconds, evaluations/s per core.
# Needs GNU time (/usr/bin/time, Debian's package `time`).
set -euo pipefail

if [ $# -lt 1 ] || [ ! -x "$1/rtneat" ]; then
  echo "usage: $0 PEER_DIR [ESC_BINARY] [RUNS]: PEER_DIR holds novelty-search-cpp's rtneat, built" >&2
  exit 2
fi
peer=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/.." && pwd)
esc=$(realpath "${2:-$root/build/cli/esc}")
runs=${3:-3}
script=$root/experiments/lehman_stanley/navigator_mazes.esc
work=$(mktemp -d)
out=""
trap 'rm -rf "$work"; [ -z "$out" ] || rm -rf "${peer:?}/$out"' EXIT
cpu() { awk '{ print $1 + $2 }' "$1"; }   # user + system seconds from /usr/bin/time -f "%U %S"
line() { awk -v who="$1" -v maze="$2" -v e="$3" -v s="$4" \
           'BEGIN { printf "%-6s %-6s %8d evaluations %7.1f s %6.0f a second\n", who, maze, e, s, e / s }'; }

for maze in medium hard; do
  evals=0 seconds=0
  for run in $(seq 1 "$runs"); do
    # Their program writes OUTDIR + a name into char[30] buffers: keep the directory short.
    out=r$$${maze:0:1}$run
    mkdir -p "$peer/$out"
    (cd "$peer" && /usr/bin/time -f "%U %S" -o "$work/cpu" ./rtneat maze.ne "$out/" "${maze}_maze.txt" 2 \
       > "$work/stdout" 2>&1)
    # "Maze solved by indiv# N": N evaluations made, the first population's included (their
    # record.dat has a line per offspring only).
    made=$(awk '/Maze solved by indiv#/ { print $NF; exit }' "$work/stdout")
    if [ -z "$made" ]; then
      echo "their run $run on the $maze maze did not solve it: counted to its budget" >&2
      made=$(( $(wc -l < "$peer/$out/record.dat") + $(awk '$1 == "pop_size" { print $2 }' "$peer/maze.ne") ))
    fi
    evals=$((evals + made))
    seconds=$(awk -v a="$seconds" -v b="$(cpu "$work/cpu")" 'BEGIN { print a + b }')
    rm -rf "${peer:?}/$out"
    out=""
  done
  line theirs "$maze" "$evals" "$seconds"
  threshold=$([ "$maze" = medium ] && echo 0.02 || echo 0.0286)
  /usr/bin/time -f "%U %S" -o "$work/cpu" "$esc" run "$script" --experiment "${maze}_neat_on_navigator" \
    --set neat.score=novelty --set neat.novelty_threshold="$threshold" --runs "$runs" --threads 1 \
    --out "$work/$maze" > /dev/null
  evals=$("$esc" export "$work/$maze" --format csv |
          awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "evaluations") c = i; next }
                   { e += $c } END { if (!c) exit 1; print e }')
  line esc "$maze" "$evals" "$(cpu "$work/cpu")"
done
