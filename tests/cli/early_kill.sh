#!/usr/bin/env bash
# `esc run` killed (SIGKILL) in its first milliseconds, again and again: whatever instant it
# dies, the directory it leaves is either continued to its end by `esc run --resume` or,
# holding nothing, accepted by `esc run --out` (never stuck between the two); and a reader
# (`esc export`) at that instant, nor the resume, calls it damaged.
# Usage: early_kill.sh ESC WORK [KILLS [MAX_MS [SEED]]]: KILLS kills (15) after delays
# spread evenly over 0..MAX_MS ms (50), or drawn at random from SEED when one is given.
set -uo pipefail
esc=$1 work=$2 kills=${3:-15} max_ms=${4:-50} seed=${5:-}
script=$(cd "$(dirname "$0")" && pwd)/data/tiny.esc
run=(run "$script" --generations 2 --runs 1 --threads 1)
rm -rf "$work"
mkdir -p "$work"
[ -n "$seed" ] && RANDOM=$seed
absent=0 resumed=0 accepted=0 finished=0 stuck=0 damaged=0
for i in $(seq 1 "$kills"); do
  if [ -n "$seed" ]; then
    delay_us=$(( (RANDOM * 32768 + RANDOM) % (max_ms * 1000 + 1) ))
  else
    delay_us=$(( (i - 1) * max_ms * 1000 / (kills > 1 ? kills - 1 : 1) ))
  fi
  dir=$work/run-$i
  "$esc" "${run[@]}" --out "$dir" >/dev/null 2>&1 &
  pid=$!
  sleep "$(printf '%d.%06d' $((delay_us / 1000000)) $((delay_us % 1000000)))"
  "$esc" export "$dir" >"$work/read-$i" 2>&1 &   # a reader at the instant it dies
  reader=$!
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  wait "$reader"
  [ -e "$dir" ] || absent=$((absent + 1))
  if "$esc" run --resume "$dir" >"$work/resume-$i" 2>&1; then
    if grep -q "is complete" "$work/resume-$i"; then finished=$((finished + 1)); else resumed=$((resumed + 1)); fi
  elif "$esc" "${run[@]}" --out "$dir" >"$work/again-$i" 2>&1; then
    accepted=$((accepted + 1))
  else
    stuck=$((stuck + 1))
    echo "STUCK: $dir (killed after $delay_us us) holds:"
    (cd "$dir" && find . | sort)
    cat "$work/resume-$i" "$work/again-$i"
  fi
  if grep -q "damaged" "$work/read-$i" "$work/resume-$i"; then
    damaged=$((damaged + 1))
    echo "DAMAGED: $dir (killed after $delay_us us):"
    cat "$work/read-$i" "$work/resume-$i"
  fi
done
echo "$kills kills in the first $max_ms ms: $resumed resumed, $accepted accepted by run --out ($absent before the" \
     "directory existed), $finished finished before the kill; $stuck stuck, $damaged called damaged"
[ "$stuck" -eq 0 ] && [ "$damaged" -eq 0 ]
