#!/usr/bin/env bash
# A disk that fills during `esc run`: the error names the directory and how to continue, no
# .tmp file is left, and once there is room `esc run --resume` finishes the run with the
# results of an unbroken one. Needs a small file system of its own: a tmpfs, mounted where
# the test may mount (root with CAP_SYS_ADMIN); elsewhere it is skipped (exit 77).
# Usage: disk_full.sh ESC WORK
set -uo pipefail
esc=$1 work=$2
script=$(dirname "$0")/data/tiny.esc
[ -d "$work/disk" ] && mountpoint -q "$work/disk" && umount "$work/disk"
rm -rf "$work"
mkdir -p "$work/disk"
mount -t tmpfs -o size=600k tmpfs "$work/disk" 2>/dev/null || { echo "SKIP: cannot mount a tmpfs here"; exit 77; }
trap 'umount "$work/disk" 2>/dev/null' EXIT
run=(run "$script" --generations 300 --runs 3 --threads 1)
dir=$work/disk/run
"$esc" "${run[@]}" --out "$dir" >"$work/out" 2>"$work/err"
status=$?
[ "$status" -eq 1 ] || { echo "FAIL: status $status on a full disk, not 1"; cat "$work/err"; exit 1; }
grep -qx "esc: error: the disk holding $dir is full (.*)" "$work/err" ||
  { echo "FAIL: the error does not name the directory"; cat "$work/err"; exit 1; }
grep -qxF "help: free some space: \`esc run --resume $dir\` continues from the last generation stored" "$work/err" ||
  { echo "FAIL: no advice to resume"; cat "$work/err"; exit 1; }
[ "$(wc -l <"$work/err")" -eq 2 ] || { echo "FAIL: more than two lines"; cat "$work/err"; exit 1; }
if find "$dir" -name '*.tmp' | grep -q .; then echo "FAIL: a .tmp file is left"; find "$dir" -name '*.tmp'; exit 1; fi
mount -o remount,size=64m "$work/disk" || { echo "FAIL: cannot grow the tmpfs"; exit 1; }
"$esc" run --resume "$dir" >"$work/resumed" 2>&1 || { echo "FAIL: the resume failed"; cat "$work/resumed"; exit 1; }
"$esc" "${run[@]}" --out "$work/unbroken" >/dev/null 2>&1 || { echo "FAIL: the unbroken run failed"; exit 1; }
python3 - "$dir/summary.json" "$work/unbroken/summary.json" <<'PY' || exit 1
import json, sys
a, b = (json.load(open(f))["controllers"] for f in sys.argv[1:])
if a != b:
    sys.exit("FAIL: the resumed run's results differ from the unbroken run's")
PY
echo "a full disk named the directory, left no .tmp file, and the resumed run equals the unbroken one"
