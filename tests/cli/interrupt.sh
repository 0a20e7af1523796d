#!/usr/bin/env bash
# SIGINT and SIGTERM during `esc run`: one line saying after how many generations it stopped,
# naming the directory and how to resume it,
# the status of the signal (130, 143), and a directory that reads (resuming a stopped run is
# tested with kill -9 in the cli tests).
# Usage: interrupt.sh ESC WORK
set -uo pipefail
esc=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
script=$(dirname "$0")/../../experiments/examples/quick_start.esc
for signal in INT TERM; do
  dir=$work/run-$signal
  "$esc" run "$script" --runs 2 --generations 100000 --out "$dir" >"$work/out-$signal" 2>"$work/err-$signal" &
  pid=$!
  for _ in $(seq 100); do   # until its first generation is stored
    grep -q "gen" "$work/out-$signal" 2>/dev/null && break
    sleep 0.1
  done
  kill -"$signal" "$pid"
  wait "$pid"
  status=$?
  expected=$([ "$signal" = INT ] && echo 130 || echo 143)
  [ "$status" -eq "$expected" ] || { echo "FAIL: SIG$signal: status $status, not $expected"; exit 1; }
  grep -qxE "esc: stopped after [1-9][0-9]* of 400000 generations \(all runs together\); $dir holds every generation finished: \`esc run --resume $dir\` continues it" \
      "$work/err-$signal" || { echo "FAIL: SIG$signal: no resume line"; cat "$work/err-$signal"; exit 1; }
done
"$esc" export "$work/run-INT" >/dev/null || { echo "FAIL: the stopped run does not read"; exit 1; }
echo "SIGINT and SIGTERM each printed where to resume"
