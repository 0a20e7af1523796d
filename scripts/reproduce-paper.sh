#!/usr/bin/env bash
# Re-runs the paper's campaigns committed under results/paper/<campaign>/, each from its
# `command` file (one esc command line, run from the repository root, writing into $OUT).
#
#   scripts/reproduce-paper.sh [--full] [CAMPAIGN...]   run each as committed; its summary.json
#                                                        must equal the committed one byte for byte
#   scripts/reproduce-paper.sh --quick [CAMPAIGN...]    each command shortened (2 runs x 3
#                                                        generations x 2 epochs; or the campaign's
#                                                        `quick` command, if it has one): minutes
#                                                        for all, checks that every campaign runs
#   scripts/reproduce-paper.sh --full --write CAMPAIGN  run it and store what it gives in its
#                                                        directory (summary.json, export.csv,
#                                                        usage.csv, figures/, version, machine,
#                                                        cost.md; analysis.md from its `analysis`)
#   scripts/reproduce-paper.sh --write --from DIR CAMPAIGN
#                                                        store the run kept in DIR/CAMPAIGN (by KEEP)
#                                                        instead of running it: a campaign stopped
#                                                        (a session's end, a crash) is finished there
#                                                        first (by its `resume` command, default
#                                                        esc run --resume; by its command if it
#                                                        stopped in its dependencies); wall time
#                                                        from its files' times (any stop in it)
#
# With no CAMPAIGN, every directory of results/paper holding a `command`. ESC names the esc
# binary (default build/cli/esc); KEEP=DIR keeps each run's directory in DIR/<campaign> (one
# holding only deps/, a seeded dependency cache, is used, not emptied);
# PAPER_RESULTS=DIR reads (and writes) the campaigns there instead of results/paper. A
# campaign's optional `analysis` file is a command reading the finished run in $OUT; its
# output is stored as analysis.md.
# Exit status: 0 every campaign ran (and, in full, reproduced), 1 otherwise, 2 bad usage.
set -euo pipefail
# Paths given relative to where the script was called from (ESC, KEEP, PAPER_RESULTS, --from)
# stay so.
here=$PWD
absolute() { case $1 in /*) echo "$1" ;; *) echo "$here/$1" ;; esac; }
[ -n "${ESC:-}" ] && ESC=$(absolute "$ESC")
[ -n "${KEEP:-}" ] && KEEP=$(absolute "$KEEP")
[ -n "${PAPER_RESULTS:-}" ] && PAPER_RESULTS=$(absolute "$PAPER_RESULTS")
cd "$(dirname "$0")/.."

mode=full
write=0
from=
campaigns=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) mode=quick ;;
    --full) mode=full ;;
    --write) write=1 ;;
    -h|--help) sed -n '2,30p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --from) [ $# -gt 1 ] || { echo "reproduce-paper: --from needs a directory" >&2; exit 2; }
            from=$(absolute "$2"); shift ;;
    --from=*) from=$(absolute "${1#--from=}") ;;
    -*) echo "reproduce-paper: unknown option $1 (try --help)" >&2; exit 2 ;;
    *) campaigns+=("${1%/}") ;;
  esac
  shift
done
if [ "$write" = 1 ] && [ "$mode" != full ]; then
  echo "reproduce-paper: --write stores full-length results only; drop --quick" >&2
  exit 2
fi
if [ -n "$from" ] && [ "$write" != 1 ]; then
  echo "reproduce-paper: --from DIR stores a kept run: give --write too" >&2
  exit 2
fi

export ESC=${ESC:-build/cli/esc}
[ -x "$ESC" ] || { echo "reproduce-paper: no esc binary at $ESC (build first, or set ESC)" >&2; exit 2; }
root=${PAPER_RESULTS:-results/paper}
if [ ${#campaigns[@]} -eq 0 ]; then
  for d in "$root"/*/; do [ -f "$d/command" ] && campaigns+=("$(basename "$d")"); done
fi
[ ${#campaigns[@]} -gt 0 ] || { echo "reproduce-paper: no campaign under $root" >&2; exit 2; }

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
quick_args=(--runs 2 --generations 3 --set epochs=2)

# Wall time, control steps and steps/s per core of a finished run, beside the estimate of
# `esc bench --campaign` for the same experiments and controllers (not a bound: it counts
# every epoch at full length, at the rates of the genomes it times). SECONDS is the wall time
# measured here, or `untimed` for a run stored with --from.
cost_report() {
  local name=$1 out=$2 seconds=$3 script=$4 dest=$5
  "$ESC" export "$out" --format csv --out "$scratch/cost.csv" >/dev/null 2>&1
  "$ESC" bench --campaign "$script" --min-time 0.5 >"$scratch/bench.txt" 2>&1 || true
  python3 - "$name" "$scratch/cost.csv" "$seconds" "$(nproc)" "$scratch/bench.txt" "$out" >"$dest" <<'EOF'
import csv, os, sys
name, table, timed, cores, bench, out = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5], sys.argv[6]
rows = list(csv.DictReader(open(table)))
steps = sum(int(r["steps"]) for r in rows)
# The bench names a study's condition STUDY/CONDITION, the export its experiment.
pairs = {(r["experiment"], r["controller"]) for r in rows}
pairs |= {(f'{r["study"]}/{r["condition"]}', r["controller"]) for r in rows if r.get("study")}
estimate = 0.0
lines = []
for line in open(bench):
    f = line.split()
    if len(f) >= 7 and (f[0], f[1]) in pairs:
        estimate += float(f[-1])
        lines.append(line.rstrip())
print(f"# Cost of campaign {name}\n")
print("| wall time | control steps | cores | steps/s per core | core-hours | `esc bench --campaign` estimate |")
print("|---|---|---|---|---|---|")
if timed != "untimed":
    # A tiny run can take less than the clock's resolution: timed, with no rate to give.
    seconds = float(timed)
    core_hours = seconds * cores / 3600
    rate = f"{steps / (seconds * cores):,.0f}" if seconds > 0 else "-"
    ratio = f" ({estimate / core_hours:.1f}x the cost measured)" if core_hours > 0 and estimate > 0 else ""
    print(f"| {seconds / 60:.1f} min | {steps:,} | {cores} | {rate} | {core_hours:.2f} "
          f"| {estimate:.2f} core-hours{ratio} |")
else:
    # Stored with --from: not timed here. Its files' times bound it: settings.json is written
    # when the run starts (after its dependencies), summary.json after its last generation;
    # the span counts any time it was stopped, so the rate is at least what it says.
    span = os.path.getmtime(os.path.join(out, "summary.json")) - os.path.getmtime(os.path.join(out, "settings.json"))
    if span > 0:
        print(f"| {span / 60:.1f} min from its files' times (settings.json to summary.json: without its dependencies, "
              f"with any time it was stopped) | {steps:,} | {cores} | at least {steps / (span * cores):,.0f} "
              f"| at most {span * cores / 3600:.2f} | {estimate:.2f} core-hours |")
    else:
        print(f"| not measured | {steps:,} | {cores} | - | - | {estimate:.2f} core-hours |")
print("\nThe estimate counts every epoch at full length at the rates of the genomes it times (not a bound: "
      "epochs that end early make a run cheaper, controllers that step slower dearer); its lines:\n")
print("```")
print("\n".join(lines) if lines else "(none matched)")
print("```")
EOF
}

# Runs one step of storing a campaign; on failure says which, with the last lines it printed.
step() {
  local what=$1
  shift
  if ! "$@" >"$scratch/step.log" 2>&1; then
    echo "FAILED $name: $what did not work; last lines:"
    tail -5 "$scratch/step.log"
    return 1
  fi
}

# Stores what a full run of a campaign gave, beside its command: everything is made in a
# staging directory first and copied into place only when every part was made, so a failure
# leaves the committed files as they were (and is reported: the function returns 1).
store_results() {
  local name=$1 out=$2 seconds=$3
  local dir=$root/$name stage=$scratch/stage-$name
  rm -rf "$stage" "$scratch/report"
  mkdir -p "$stage"
  step "copying summary.json" cp "$out/summary.json" "$stage/summary.json" || return 1
  step "esc export" "$ESC" export "$out" --format csv --out "$stage/export.csv" || return 1
  # The usage table, where the esc that ran it had one.
  "$ESC" export "$out" --table usage --format csv --out "$stage/usage.csv" >/dev/null 2>&1 || rm -f "$stage/usage.csv"
  step "esc report" "$ESC" report "$out" --out "$scratch/report/report.html" || return 1
  if [ -d "$scratch/report/figures" ]; then cp -r "$scratch/report/figures" "$stage/figures"; fi
  # The standard library line names this checkout's path: not part of what made the results.
  "$ESC" --version | grep -v '^standard library:' >"$stage/version"
  {
    echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //')"
    echo "cores: $(nproc)"
    echo "memory: $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
    echo "system: $(uname -sr), $(. /etc/os-release && echo "$PRETTY_NAME")"
    echo "finished: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
    # Other work on the machine slows the wall time (cost.md) and changes no result.
    echo "load average when it finished (1, 5, 15 min): $(cut -d' ' -f1-3 /proc/loadavg)"
  } >"$stage/machine"
  local script
  script=$(awk '{for (i = 1; i <= NF; ++i) if ($i ~ /\.esc$/) {print $i; exit}}' "$dir/command")
  step "the cost report" cost_report "$name" "$out" "$seconds" "$script" "$stage/cost.md" || return 1
  if [ -f "$dir/analysis" ]; then
    if ! OUT=$out bash "$dir/analysis" >"$stage/analysis.md" 2>"$scratch/step.log"; then
      echo "FAILED $name: its analysis did not work; last lines:"
      tail -5 "$scratch/step.log"
      return 1
    fi
  fi
  rm -rf "$dir/figures"
  cp -r "$stage"/. "$dir"/
}

failed=0
for name in "${campaigns[@]}"; do
  dir=$root/$name
  if [ ! -f "$dir/command" ]; then
    echo "reproduce-paper: $name: no $dir/command" >&2
    failed=1
    continue
  fi
  if [ -n "$from" ]; then
    OUT=$from/$name
    echo "== $name: the run kept in $OUT, finished there first (esc's progress: $scratch/$name.log)"
    export OUT
    if [ ! -d "$OUT" ]; then
      echo "FAILED $name: $OUT does not exist (--from names the KEEP directory of a stopped campaign)"
      failed=1
      continue
    fi
    finish=("$ESC" run --resume "$OUT")
    [ -f "$dir/resume" ] && finish=(bash "$dir/resume")
    # Stopped while its dependencies ran (deps/ and no database yet): its command runs into
    # the same directory again, reusing the finished dependencies and continuing the other.
    if [ -d "$OUT/deps" ] && [ ! -s "$OUT/esc.db" ]; then finish=(bash "$dir/command"); fi
    if ! "${finish[@]}" >"$scratch/$name.log" 2>&1; then
      echo "FAILED $name: $OUT could not be finished; last lines:"
      tail -5 "$scratch/$name.log"
      failed=1
      continue
    fi
    if store_results "$name" "$OUT" untimed; then echo "stored $name in $dir (from $OUT)"; else failed=1; fi
    continue
  fi
  OUT=$scratch/runs/$name
  [ -n "${KEEP:-}" ] && OUT=$KEEP/$name
  # A kept directory holding nothing but deps/ is a dependency cache seeded for this run
  # (finished entries of the experiments it depends on, copied from another run): kept.
  if [ -n "${KEEP:-}" ] && [ "$(ls -A "$OUT" 2>/dev/null)" = deps ]; then
    echo "== $name: the dependency cache seeded in $OUT/deps is used"
  else
    rm -rf "$OUT"
  fi
  mkdir -p "$(dirname "$OUT")"
  export OUT
  args=()
  command=$dir/command
  if [ "$mode" = quick ]; then
    args=("${quick_args[@]}")
    if [ -f "$dir/quick" ]; then
      command=$dir/quick
      args=()
    fi
  fi
  echo "== $name ($mode): $(grep -v '^#' "$command" | tr -s ' \\\n' ' ')"
  # Before hours of running, not after them.
  if [ "$mode" = full ] && [ "$write" != 1 ] && [ ! -f "$dir/summary.json" ]; then
    echo "FAILED $name: nothing committed to compare with (run it with --write first)"
    failed=1
    continue
  fi
  # A full-length campaign runs for hours: where to watch it.
  if [ "$mode" = full ]; then echo "   esc's progress: $scratch/$name.log"; fi
  start=$(date +%s%N)
  if ! bash "$command" "${args[@]}" >"$scratch/$name.log" 2>&1; then
    echo "FAILED $name: the command did not finish; last lines:"
    tail -5 "$scratch/$name.log"
    failed=1
    continue
  fi
  seconds=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN { printf "%.1f", (b - a) / 1e9 }')
  if [ "$mode" = quick ]; then
    echo "ok     $name ran in ${seconds} s"
  elif [ "$write" = 1 ]; then
    if store_results "$name" "$OUT" "$seconds"; then echo "stored $name in $dir (${seconds} s)"; else failed=1; fi
  elif cmp -s "$OUT/summary.json" "$dir/summary.json"; then
    echo "ok     $name reproduces its committed summary.json byte for byte (${seconds} s)"
  else
    echo "FAILED $name: summary.json differs from the committed one"
    diff <(tr ',' '\n' <"$dir/summary.json") <(tr ',' '\n' <"$OUT/summary.json") | head -10 || true
    failed=1
  fi
done
exit $failed
