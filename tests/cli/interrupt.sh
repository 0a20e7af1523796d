#!/usr/bin/env bash
# SIGINT and SIGTERM during `esc run`: one line saying after how many generations it stopped
# (a study: of all its conditions), naming the directory and how to resume it (before its
# first generation is stored: the command that starts it again),
# the status of the signal (130, 143), and a directory that reads (resuming a stopped run is
# tested with kill -9 in the cli tests).
# Usage: interrupt.sh ESC WORK
set -uo pipefail
esc=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
script=$(dirname "$0")/../../experiments/examples/quick_start.esc
for signal in INT TERM; do
  dir=$work/run-$signal
  "$esc" run "$script" --runs 2 --generations 100000 --out "$dir" >"$work/out-$signal" 2>"$work/err-$signal" &
  pid=$!
  for _ in $(seq 100); do   # until its first generation is stored
    grep -qE "gen +2/" "$work/out-$signal" 2>/dev/null && break
    sleep 0.1
  done
  kill -"$signal" "$pid"
  wait "$pid"
  status=$?
  expected=$([ "$signal" = INT ] && echo 130 || echo 143)
  [ "$status" -eq "$expected" ] || { echo "FAIL: SIG$signal: status $status, not $expected"; exit 1; }
  grep -qxE "esc: stopped after [1-9][0-9]* of 400000 generations \(all runs together\); $dir holds every generation finished: \`esc run --resume $dir\` continues it" \
      "$work/err-$signal" || { echo "FAIL: SIG$signal: no resume line"; cat "$work/err-$signal"; exit 1; }
done
"$esc" export "$work/run-INT" >/dev/null || { echo "FAIL: the stopped run does not read"; exit 1; }

# A signal sent twice at once (GNU timeout signals the process and its group) reaches two
# threads: one line all the same, not two interleaved ("stopped after  after 11 of  of ...").
for i in 1 2 3; do
  dir=$work/run-twice-$i
  "$esc" run "$script" --runs 2 --generations 100000 --out "$dir" >"$work/out-twice" 2>"$work/err-twice" &
  pid=$!
  for _ in $(seq 100); do
    grep -qE "gen +2/" "$work/out-twice" 2>/dev/null && break
    sleep 0.1
  done
  kill -TERM "$pid"; kill -TERM "$pid"
  wait "$pid"
  [ "$(grep -c "esc: stopped" "$work/err-twice")" -eq 1 ] &&
    grep -qxE "esc: stopped after [1-9][0-9]* of 400000 generations \(all runs together\); $dir holds every generation finished: \`esc run --resume $dir\` continues it" \
      "$work/err-twice" || { echo "FAIL: a signal sent twice: not one line"; cat "$work/err-twice"; exit 1; }
done

# Stopped before its first generation was stored: a resume would find nothing, so the line
# gives the command that starts it again, and that command runs into the directory.
dir=$work/run-first
"$esc" run "$script" --runs 1 --generations 1 --set epochs=3000 --out "$dir" >"$work/out-first" 2>"$work/err-first" &
pid=$!
for _ in $(seq 100); do   # until its directory is made (generation 0 takes seconds)
  [ -f "$dir/summary.json" ] && break
  sleep 0.1
done
sleep 0.3
kill -INT "$pid"
wait "$pid"
status=$?
[ "$status" -eq 130 ] || { echo "FAIL: before the first generation: status $status, not 130"; exit 1; }
restart="esc run $(cd "$(dirname "$script")" && pwd)/quick_start.esc --experiment quick_start --runs 1 --generations 1 --set epochs=3000 --out $dir"
grep -qxF "esc: stopped before its first generation was stored; $dir holds nothing to resume: \`$restart\` starts it again (finished dependencies in its deps/ are reused)" \
    "$work/err-first" || { echo "FAIL: before the first generation: no line to start it again"; cat "$work/err-first"; exit 1; }
"$esc" run --resume "$dir" >"$work/resume-first" 2>&1 && { echo "FAIL: a run that stored nothing resumed"; exit 1; }
timeout 3 ${restart/esc/$esc} >"$work/again-first" 2>&1
grep -q "running quick_start" "$work/again-first" || { echo "FAIL: the command given does not start it again"; cat "$work/again-first"; exit 1; }

# A study counts its every condition: stopped in the second of three, the line counts the
# first's generations too, of all three's. 400 generations a run, so that the second condition
# outlasts the wait below on an idle machine (at 40 the whole study ended before the signal).
study=$(dirname "$0")/data/tiny_study.esc
dir=$work/study
"$esc" run "$study" --experiment tiny_study_fewer --runs 1 --generations 400 --threads 1 --out "$dir" \
    >"$work/out-study" 2>"$work/err-study" &
pid=$!
for _ in $(seq 300); do   # until the second condition has stored a few generations
  grep -q "condition 2/3" "$work/out-study" 2>/dev/null && break
  sleep 0.1
done
sleep 0.5
kill -INT "$pid"
wait "$pid"
said=$(sed -nE 's/^esc: stopped after ([0-9]+) of 2400 generations \(all runs together\); .*/\1/p' "$work/err-study")
stored=$(( $("$esc" export "$dir" | wc -l) - 1 ))
[ -n "$said" ] && [ "$said" -gt 800 ] && [ "$said" -le "$stored" ] && [ "$said" -ge $((stored - 1)) ] ||
    { echo "FAIL: the study's stop counts '$said' of 2400 where $stored are stored"; cat "$work/err-study"; exit 1; }
echo "SIGINT and SIGTERM each printed where to resume, or how to start again; a study counted $said of 2400 ($stored stored)"
