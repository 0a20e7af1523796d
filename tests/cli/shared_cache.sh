#!/usr/bin/env bash
# Four `esc run`s started together on one dependency cache: the dependency they all need
# runs once (one process runs it, the others wait and reuse it), and the four give the same
# results. Usage: shared_cache.sh ESC WORK
set -euo pipefail
esc=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
script=$(dirname "$0")/data/start_from.esc
for i in 1 2 3 4; do
  "$esc" run "$script" --experiment again --runs 2 --cache "$work/cache" --out "$work/run$i" \
      >"$work/out$i.txt" 2>&1 &
done
wait
ran=$(cat "$work"/out*.txt | grep -c "dependency basic: running into" || true)
reused=$(cat "$work"/out*.txt | grep -c "dependency basic: reused" || true)
[ "$ran" -eq 1 ] && [ "$reused" -eq 3 ] || { echo "FAIL: basic ran $ran times, was reused $reused times"; cat "$work"/out*.txt; exit 1; }
[ "$(ls "$work/cache")" = "$(cd "$work/cache" && ls -d basic-*)" ] || { echo "FAIL: cache holds"; ls "$work/cache"; exit 1; }
for i in 2 3 4; do
  cmp <("$esc" export "$work/run1" | cut -d, -f1-11) <("$esc" export "$work/run$i" | cut -d, -f1-11) \
    || { echo "FAIL: run$i differs from run1"; exit 1; }
done
echo "basic ran once for four runs; their results are the same"
