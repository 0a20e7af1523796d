#!/usr/bin/env python3
"""What the best controllers do in the recharge area, from a finished run of an experiment
with the energy accumulator (the paper's section 4.5: with a recharge twice slower, "the
robot simply stays in the recharge area until the energy level is back to maximum, using
the stop behavior"; "direct controller architectures never stop on the recharge area").
Replays each run's stored best controller (`esc replay`, every epoch; scripts/esc_runs.py)
and prints Markdown.

    python3 scripts/recharge-visits.py RUN_DIR [--esc build/cli/esc] [--condition NAME]...

A step is in the recharge area when the accumulator did not fall over it (it falls on every
step outside, and stays full or rises inside); a visit is a stretch of such steps. Per run:
- epochs and the steps they lasted (an epoch ends early when the accumulator is empty);
- visits: those left (the robot drove out) and those the epoch ended in;
- left full: visits left with the accumulator at least FULL (a step that crosses the area's
  edge recharges only on its substeps inside: a robot that waits for full may drive out a
  substep early, at 0.998);
- level left: the mean level at which the robot drove out (1 = full);
- still: the share of in-area steps whose centre moved less than STILL_MM (the evolved stop
  behaviors spin on the spot: the wheels turn, the centre does not move once the motors,
  with their inertia, have reached the spin);
- stop: for supervisors, the share of in-area steps that the behavior `stop` acted;
- last exit: in each epoch that the robot finishes outside the area with energy left, the
  level at which it last drove out, against the level needed to drive to the epoch's end
  (its remaining steps over the accumulator's discharge steps): waiting until full is worth
  nothing to a fitness that pays only outside the area, once the rest of the epoch is covered.
Only finished runs are replayed (summary.json's), so a campaign still running is read as
far as it got.
"""
import argparse
import json
import math
import os
import statistics
import sys
import tempfile
from collections import defaultdict

from esc_runs import parts, replay, split_epochs

STILL_MM = 0.5   # a step at full speed moves the centre about 8 mm
FULL = 0.99      # one control step recharges 0.01 at the paper's rate (100 steps), 0.005 at half of it


def discharge_steps(source):
    """The steps a full accumulator lasts, from the settings the run used."""
    with open(os.path.join(source, "settings.json")) as f:
        return float(json.load(f)["settings"]["robot.energy_discharge"])


def visits_of(rows, discharge):
    """Per-run figures from one replay's steps (every epoch); `discharge`: the steps a full
    accumulator lasts."""
    epochs = split_epochs(rows)
    f = {"epochs": len(epochs), "steps": [], "empty": 0, "left": 0, "left_full": 0, "ended_in": 0,
         "left_levels": [], "in_steps": 0, "still": 0, "stop": 0, "last_exits": []}
    for steps in epochs:
        f["steps"].append(len(steps))
        level, x, y = 1.0, None, None   # every epoch starts full
        inside = False
        last_exit = None
        for i, r in enumerate(steps):
            e = float(r["energy"])
            now_in = e >= level and e > 0.0
            if inside and not now_in:
                f["left"] += 1
                f["left_levels"].append(level)
                f["left_full"] += level >= FULL
                last_exit = (level, (len(steps) - i) / discharge)
            inside = now_in
            if inside:
                f["in_steps"] += 1
                # The first step of an epoch has no previous position: not counted as still.
                moved_mm = math.hypot(float(r["x_m"]) - x, float(r["y_m"]) - y) * 1000.0 if x is not None else None
                f["still"] += moved_mm is not None and moved_mm < STILL_MM
                f["stop"] += r.get("behavior") == "stop"
            level, x, y = e, float(r["x_m"]), float(r["y_m"])
        f["ended_in"] += inside
        f["empty"] += level == 0.0
        if last_exit and not inside and level > 0.0:
            f["last_exits"].append(last_exit)
    return f


def mean_text(values):
    return f"{statistics.mean(values):.2f}" if values else "-"


def exits_text(exits, between=" / "):
    """Mean level at the last exits, and mean level needed."""
    return mean_text([e[0] for e in exits]) + between + mean_text([e[1] for e in exits])


def share(n, d):
    return f"{100.0 * n / d:.0f}%" if d else "-"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("--esc", default="build/cli/esc")
    parser.add_argument("--condition", action="append", help="only this study condition (repeatable)")
    args = parser.parse_args()

    chosen = [p for p in parts(args.directory) if not args.condition or p[0] in args.condition]
    if not chosen:
        print("No such condition in this run.", file=sys.stderr)
        return 1
    print(f"# Recharge visits of the best controllers (full: level >= {FULL}; centre still: moved < {STILL_MM} mm "
          "in a step)\n")
    with tempfile.TemporaryDirectory() as scratch:
        for name, source, part in chosen:
            discharge = discharge_steps(source)
            for controller, c in part["controllers"].items():
                print(f"## {controller} in {name}\n")
                print("| run | best | steps per epoch | epochs emptied | visits left / ended in | left full "
                      "| level left | still in area | stop in area | last exit: level / needed |")
                print("|---|---|---|---|---|---|---|---|---|---|")
                totals = defaultdict(int)
                last_exits = []
                for r in c["runs"]:
                    rows = replay(args.esc, source, controller, int(r["run"]), scratch)
                    if all(float(s["energy"]) == 1.0 for s in rows):
                        sys.exit(f"{name}: the accumulator never moves (an experiment without the energy model?)")
                    f = visits_of(rows, discharge)
                    for k in ("left", "left_full", "ended_in", "in_steps", "still", "stop", "empty"):
                        totals[k] += f[k]
                    last_exits += f["last_exits"]
                    totals["runs_full"] += f["left"] > 0 and f["left_full"] == f["left"]
                    print(f"| {r['run']} | {r['best_fitness']:.1f} | {statistics.mean(f['steps']):.0f} "
                          f"| {f['empty']} of {f['epochs']} | {f['left']} / {f['ended_in']} "
                          f"| {share(f['left_full'], f['left'])} | {mean_text(f['left_levels'])} | {share(f['still'], f['in_steps'])} "
                          f"| {share(f['stop'], f['in_steps'])} "
                          f"| {exits_text(f['last_exits'])} |")
                print(f"\nAll runs: {totals['left']} visits left, {share(totals['left_full'], totals['left'])} of "
                      f"them full; {totals['runs_full']} of {len(c['runs'])} runs leave only when full; of the "
                      f"in-area steps, the centre still on {share(totals['still'], totals['in_steps'])} and `stop` "
                      f"acting on {share(totals['stop'], totals['in_steps'])}; {totals['empty']} epochs emptied; "
                      f"at the last exit of the {len(last_exits)} epochs finished outside the area, the level "
                      f"{exits_text(last_exits, ' against ')} needed for the rest of the epoch "
                      f"(its remaining steps over the accumulator's {discharge:.0f}).\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
