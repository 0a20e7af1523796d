#!/usr/bin/env bash
# Reading a run leaves it as it was and needs no write access: export, report (to another
# directory) and replay (to another directory) of a run directory whose files and bytes
# must not change, then (mode `mount`, as root where a
# read-only bind mount can be made; else skipped, 77) on that directory mounted read-only,
# where a report or replay into it and a carry-on of it are refused as read-only, and its
# resume says it is complete.
# Usage: read_only.sh files|mount ESC WORK
set -euo pipefail
mode=$1 esc=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
"$esc" run "$(dirname "$0")/../../experiments/examples/quick_start.esc" --runs 1 --generations 2 --set epochs=1 \
    --out "$work/run" >/dev/null
dir=$work/run
if [ "$mode" = mount ]; then
  mkdir -p "$work/ro"
  mount --bind -o ro "$work/run" "$work/ro" 2>/dev/null || { echo "no read-only bind mount here: skipped"; exit 77; }
  trap 'umount "$work/ro"' EXIT
  dir=$work/ro
  touch "$dir/probe" 2>/dev/null && { echo "FAIL: the mount is writable"; exit 1; }
fi
snapshot() { (cd "$work/run" && find . -type f -print0 | sort -z | xargs -0 sha256sum); }
before=$(snapshot)
"$esc" export "$dir" --format csv >"$work/export.csv"
"$esc" export "$dir" --table usage >/dev/null
"$esc" report "$dir" --out "$work/report/report.html" >/dev/null
"$esc" replay "$dir" --out "$work/replay" >/dev/null
[ "$(wc -l <"$work/export.csv")" -eq 5 ] || { echo "FAIL: export has $(wc -l <"$work/export.csv") lines"; exit 1; }
[ "$(snapshot)" = "$before" ] || { echo "FAIL: reading changed the run directory"; diff <(echo "$before") <(snapshot); exit 1; }
if [ "$mode" = mount ]; then
  # What must write there says "read-only" and where to write instead, in two lines.
  expect_refusal() {   # expected first line, then the command
    local want=$1; shift
    if "$esc" "$@" >"$work/refusal" 2>&1; then echo "FAIL: esc $* wrote into a read-only directory"; exit 1; fi
    [ "$(head -n 1 "$work/refusal")" = "$want" ] || { echo "FAIL: esc $*:"; cat "$work/refusal"; exit 1; }
    [ "$(wc -l <"$work/refusal")" -eq 2 ] || { echo "FAIL: esc $*: not two lines"; cat "$work/refusal"; exit 1; }
  }
  expect_refusal "esc: error: $dir is read-only: the report and its figures cannot be written there" report "$dir"
  expect_refusal "esc: error: $dir is read-only: the replay's files cannot be written there" replay "$dir"
  expect_refusal "esc: error: $dir is read-only: a resume writes the generations it runs into the run's directory" \
      run --resume "$dir" --generations 4
  # A finished run has nothing to write: its resume says so, as anywhere.
  "$esc" run --resume "$dir" >"$work/complete" 2>&1 || { echo "FAIL: resuming a finished run:"; cat "$work/complete"; exit 1; }
  [ "$(cat "$work/complete")" = "esc: $dir is complete (2 x 1 runs x 2 generations); nothing to resume" ] \
      || { echo "FAIL: a finished run resumed:"; cat "$work/complete"; exit 1; }
  [ "$(snapshot)" = "$before" ] || { echo "FAIL: a refusal changed the run directory"; exit 1; }
fi
echo "export, report and replay read $dir and left it as it was"
