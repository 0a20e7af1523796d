#!/usr/bin/env bash
# scripts/loophole-criterion.py on a short run of the loophole study: every run of every
# controller gets a row; the SC without BACKWARD never alternates; the SC with it already
# alternates in the simulator without inertia (3 generations suffice there) and not with it.
set -euo pipefail
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$ESC" run experiments/paper/loophole.esc --runs 2 --generations 3 --set epochs=2 --threads 2 --out "$out/run" >/dev/null
python3 scripts/loophole-criterion.py "$out/run" --esc "$ESC" --out "$out/table.md"
cat "$out/table.md"
expect() { grep -qF "$1" "$out/table.md" || { echo "missing: $1"; exit 1; }; }
expect '| loophole_no_inertia | SC3 | 0 of 2 |'
expect '| loophole_inertia | SC3 | 0 of 2 |'
expect '| loophole_no_inertia | SC4 | 2 of 2 |'
expect '| loophole_inertia | SC4 | 0 of 2 |'
rows=$(grep -c '^| loophole_[a-z_]* | [A-Z0-9_]* | [0-9] |' "$out/table.md")
[ "$rows" -eq 20 ] || { echo "expected 20 run rows (10 controllers x 2 runs), found $rows"; exit 1; }
