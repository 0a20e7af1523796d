#!/usr/bin/env bash
# scripts/reproduce-paper.sh's storing, on a tiny campaign in a scratch PAPER_RESULTS: a full
# run is stored (summary, export, usage, figures, version, machine, cost) and re-runs byte
# for byte; a kept run is stored with --from (its wall time from its files' times) and gives
# the same summary; one stopped in its dependencies is finished by its command, and one whose
# KEEP directory was seeded with a dependency cache reuses it; --from of a missing directory
# fails and stores nothing.
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
root=$work/paper
mkdir -p "$root/tiny" "$root/uses"
cat >"$root/tiny/command" <<'CMD'
"${ESC:-build/cli/esc}" run tests/cli/data/tiny.esc --generations 2 --out "$OUT" "$@"
CMD
cat >"$root/uses/command" <<'CMD'
"${ESC:-build/cli/esc}" run tests/cli/data/evolved.esc --experiment supervised --out "$OUT" "$@"
CMD
fail() { echo "store_campaign: $*"; exit 1; }
export PAPER_RESULTS=$root

scripts/reproduce-paper.sh --full --write tiny
for f in summary.json export.csv version machine cost.md; do [ -s "$root/tiny/$f" ] || fail "no $f stored"; done
grep -q ' min | ' "$root/tiny/cost.md" || fail "cost.md has no wall time"
scripts/reproduce-paper.sh tiny || fail "the stored campaign does not re-run byte for byte"
cp "$root/tiny/summary.json" "$work/first.json"

# A kept run, stored with --from.
OUT=$work/keep/tiny bash "$root/tiny/command" >/dev/null
rm "$root/tiny/summary.json"
scripts/reproduce-paper.sh --write --from "$work/keep" tiny
cmp "$root/tiny/summary.json" "$work/first.json" || fail "--from stored another summary"
grep -q "from its files' times" "$root/tiny/cost.md" || fail "cost.md of a --from store has no wall time"

# Stopped in its dependencies: deps/ alone, the dependency finished or not.
mkdir -p "$work/keep/uses/deps"
scripts/reproduce-paper.sh --write --from "$work/keep" uses
[ -s "$root/uses/summary.json" ] || fail "a campaign stopped in its dependencies was not finished"
cp "$root/uses/summary.json" "$work/uses.json"

# KEEP holding only a dependency cache seeded from another run: used, not emptied, and its
# entry reused rather than run again.
mkdir -p "$work/seeded/uses"
cp -r "$work/keep/uses/deps" "$work/seeded/uses/"
touch "$work/seeded/uses/deps/seeded-by-hand"
seeded=$(KEEP=$work/seeded scripts/reproduce-paper.sh --full --write uses)
grep -q "the dependency cache seeded in $work/seeded/uses/deps is used" <<<"$seeded" || fail "seeded cache not used: $seeded"
[ -e "$work/seeded/uses/deps/seeded-by-hand" ] || fail "the seeded dependency cache was emptied"
[ "$(find "$work/seeded/uses/deps" -mindepth 1 -maxdepth 1 -type d | wc -l)" = 1 ] || fail "the seeded dependency ran again"
cmp "$root/uses/summary.json" "$work/uses.json" || fail "a seeded cache gave another summary"

if scripts/reproduce-paper.sh --write --from "$work/nowhere" tiny; then fail "--from a missing directory passed"; fi
cmp "$root/tiny/summary.json" "$work/first.json" || fail "a failed --from changed the stored summary"
echo "store_campaign: ok"
