#!/usr/bin/env bash
# Reading a run leaves it as it was and needs no write access: export, report (to another
# directory) and replay (to another directory) of a run directory whose files and bytes
# must not change, then (mode `mount`, as root where a
# read-only bind mount can be made; else skipped, 77) on that directory mounted read-only.
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
echo "export, report and replay read $dir and left it as it was"
