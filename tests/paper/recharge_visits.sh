#!/usr/bin/env bash
# scripts/recharge-visits.py on a short run of the energy experiment: a table per controller,
# a row per run, every share between 0% and 100%, and the supervisors' in-area steps counted
# under `stop` no more often than there are in-area steps.
set -euo pipefail
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$ESC" run experiments/paper/energy.esc --runs 2 --generations 2 --set epochs=2 --set steps=300 --threads 2 \
  --out "$out/run" >/dev/null
python3 scripts/recharge-visits.py "$out/run" --esc "$ESC" >"$out/table.md"
cat "$out/table.md"
for c in CC SC CS SS; do
  grep -qF "## $c" "$out/table.md" || { echo "missing: the table of $c"; exit 1; }
done
rows=$(grep -cE '^\| [12] \| [0-9.-]+ \| [0-9]+ \| [0-2] of 2 \| [0-9]+ / [01] \| ' "$out/table.md")
[ "$rows" -eq 8 ] || { echo "expected 8 run rows (4 controllers x 2 runs), found $rows"; exit 1; }
if grep -qE '[0-9]{4,}%|1[0-9][1-9]%|-[0-9]+%' "$out/table.md"; then echo "a share outside 0-100%"; exit 1; fi
