#!/usr/bin/env bash
# scripts/optimizer-comparison.py on a short run of the ES-against-CMA-ES study: a row for
# every condition and controller; an experiment's directory is refused.
set -euo pipefail
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$ESC" run experiments/studies/es_vs_cmaes.esc --runs 2 --generations 3 --set epochs=1 --threads 2 \
    --out "$out/run" >/dev/null
python3 scripts/optimizer-comparison.py "$out/run" --out "$out/table.md"
rows=$(grep -c '^| \(es\|cmaes\|sep_cmaes\) | [A-Z0-9_]* | ' "$out/table.md")
[ "$rows" -eq 12 ] || { echo "expected 12 rows (3 conditions x 4 controllers), found $rows"; exit 1; }
grep -q '^| sep_cmaes | SC_8_8_6 | ' "$out/table.md" || { echo "missing sep_cmaes SC_8_8_6"; exit 1; }
"$ESC" run tests/cli/data/tiny.esc --runs 2 --generations 2 --out "$out/tiny" >/dev/null
if python3 scripts/optimizer-comparison.py "$out/tiny" 2>/dev/null; then echo "read an experiment as a study"; exit 1; fi
