#!/usr/bin/env bash
# scripts/useless-usage.py on a short run of the sensitivity study: a table for CS and SS in
# the conditions with useless behaviors (8 and 24), none for the 4-behavior one; a row per run;
# shares between 0% and 100%.
set -euo pipefail
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$ESC" run experiments/paper/sensitivity.esc --experiment sensitivity --runs 2 --generations 2 --set epochs=1 \
  --set steps=100 --threads 2 --out "$out/run" >/dev/null
python3 scripts/useless-usage.py "$out/run" --esc "$ESC" >"$out/table.md"
cat "$out/table.md"
expect() { grep -qF "$1" "$out/table.md" || { echo "missing: $1"; exit 1; }; }
for c in CS SS; do
  expect "## $c in behaviors_8"
  expect "## $c in behaviors_24"
done
if grep -qF "in behaviors_4" "$out/table.md"; then echo "behaviors_4 has no useless behavior"; exit 1; fi
rows=$(grep -c '^| [12] | [0-9.]*% | [0-9.]*% | ' "$out/table.md")
[ "$rows" -eq 8 ] || { echo "expected 8 run rows (2 conditions x 2 controllers x 2 runs), found $rows"; exit 1; }
