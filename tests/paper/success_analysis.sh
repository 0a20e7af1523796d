#!/usr/bin/env bash
# scripts/success-analysis.py on a short run of the medium maze's study (2 runs of 40
# generations; every run stops at its first success): the successes, the evaluations to
# success and the evaluations made per method, then esc's tests of the six pairs, as esc's
# end table computes them (the numbers are this seed's, bit for bit).
set -euo pipefail
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$ESC" run experiments/lehman_stanley/mazes.esc --experiment medium_maze_methods --runs 2 --generations 40 \
  --threads 2 --out "$out/run" >/dev/null
python3 scripts/success-analysis.py "$out/run" --esc "$ESC" >"$out/table.md"
cat "$out/table.md"
expect() { grep -qF "$1" "$out/table.md" || { echo "missing: $1"; exit 1; }; }
expect 'Success: `reach_goal > -0.0171875`'
# Novelty search: run 1 succeeded at evaluation 5,796 (stopped after generation 23), run 2
# at 2,094 (after generation 8): 24 + 9 generations of 250 evaluations.
expect "| novelty | navigator_net | 2 of 2 | 3,945 (2,618) | 3,945.0 | 2,094-5,796 | 8,250 |"
expect "| fitness_based | navigator_net | 1 of 2 | 6,462 | 6,462 | 6,462-6,462 | 16,500 |"
expect "| navigator_net: fitness_based vs novelty | 1/2 vs 2/2 | 1.0000 | 1.0000 | 4.0 | 0.3333 | 1.0000 | 10,001 |"
expect "| navigator_net: novelty vs map_elites | 2/2 vs 2/2 | 1.0000 | 1.0000 | 3.0 | 0.6667 | 1.0000 | none |"
rows=$(grep -c '^| navigator_net: ' "$out/table.md")
[ "$rows" -eq 6 ] || { echo "expected 6 pairs (4 methods), found $rows"; exit 1; }
