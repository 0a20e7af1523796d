#!/usr/bin/env bash
# scripts/recharge-visits.py on short runs: of the energy experiment (a plain experiment: a
# table per controller, a row per run) and of the generalization campaign (a study: only the
# conditions asked for, read from their own directories); every share within 0-100%, every
# epoch's visits ending inside at most once.
set -euo pipefail
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$ESC" run experiments/paper/energy.esc --runs 2 --generations 2 --set epochs=2 --set steps=300 --threads 2 \
  --out "$out/run" >/dev/null
python3 scripts/recharge-visits.py "$out/run" --esc "$ESC" >"$out/table.md"
cat "$out/table.md"
for c in CC SC CS SS; do
  grep -qF "## $c in energy" "$out/table.md" || { echo "missing: the table of $c"; exit 1; }
done
rows=$(grep -cE '^\| [12] \| [0-9.-]+ \| [0-9]+ \| [0-2] of 2 \| [0-9]+ / [0-2] \| ' "$out/table.md")
[ "$rows" -eq 8 ] || { echo "expected 8 run rows (4 controllers x 2 runs), found $rows"; exit 1; }
python3 - "$out/table.md" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
shares = [int(s) for s in re.findall(r"(-?\d+)%", text)]
bad = [s for s in shares if not 0 <= s <= 100]
if bad or not shares:
    sys.exit(f"shares outside 0-100%: {bad}")
# The last exit's level and the level needed (the energy script's 285 discharge steps).
exits = re.findall(r"\| ([0-9.]+|-) / ([0-9.]+|-) \|\n", text)
if len(exits) != 8:
    sys.exit(f"expected a last exit column in 8 rows, found {len(exits)}")
levels = [float(v) for pair in exits for v in pair if v != "-"]
if any(not 0.0 <= v <= 1.0 for v in levels):
    sys.exit(f"last exit levels outside 0-1: {levels}")
if text.count("over the accumulator's 285)") != 4:
    sys.exit("each controller's summary names the accumulator's 285 discharge steps")
PY
"$ESC" run results/paper/generalization/campaign.esc --runs 2 --generations 2 --set epochs=1 --set steps=300 \
  --threads 2 --out "$out/study" >/dev/null
python3 scripts/recharge-visits.py "$out/study" --esc "$ESC" --condition slow_recharge_evolved >"$out/study.md"
[ "$(grep -c '^## ' "$out/study.md")" -eq 4 ] || { echo "expected the 4 controllers of one condition"; exit 1; }
[ "$(grep -c '^## .* in slow_recharge_evolved$' "$out/study.md")" -eq 4 ] || { echo "wrong condition"; exit 1; }
if python3 scripts/recharge-visits.py "$out/study" --esc "$ESC" --condition no_such >/dev/null 2>&1; then
  echo "an unknown condition must fail"; exit 1
fi
