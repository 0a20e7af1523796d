#!/usr/bin/env python3
"""Which runs of a loophole study settled on FORWARD-BACKWARD alternation (paper, section 3.2).

    scripts/loophole-criterion.py DIR [--esc BUILD/cli/esc] [--out FILE.md]

DIR is a finished run of experiments/paper/loophole.esc (the study, or one of its
experiments). Every run's best controller is replayed (`esc replay`, bit-identical to its
stored evaluation) and judged from its steps:

  backward share   the share of steps on which the robot moves backward (mean wheel speed
                   below -5% of the top speed)
  reversals        changes of direction (forward to backward or back) per 100 steps, a
                   direction holding until the robot moves the other way faster than 5% of
                   the top speed
  BACKWARD usage   for a symbolic controller, the share of steps its BACKWARD action chose

A run alternates when its backward share is at least 25% and it reverses at least 10 times
per 100 steps: the trick moves backward about half the time and reverses every few steps,
while a controller that backs away from a wall now and then does neither. The table lists
every run's figures, so the threshold can be judged against them.
"""
import argparse
import contextlib
import json
import os
import sys
import tempfile

from esc_runs import parts, replay, split_epochs

DEADBAND = 0.05        # share of the top speed below which the direction is kept
MIN_BACKWARD = 0.25
MIN_REVERSALS = 10.0   # per 100 steps


def judge(rows, top_speed):
    steps = len(rows)
    backward = 0
    reversals = 0
    used_backward = 0
    symbolic = any(r.get("behavior") for r in rows)
    for epoch_rows in split_epochs(rows):
        direction = 0
        for r in epoch_rows:
            v = (float(r["left_speed_mps"]) + float(r["right_speed_mps"])) / 2
            now = 1 if v > DEADBAND * top_speed else -1 if v < -DEADBAND * top_speed else 0
            backward += now < 0
            if now != 0:
                reversals += direction != 0 and now != direction
                direction = now
            used_backward += r.get("behavior") == "backward"
    return {
        "steps": steps,
        "backward": backward / steps if steps else 0.0,
        "reversals": 100.0 * reversals / steps if steps else 0.0,
        "backward_usage": used_backward / steps if steps else 0.0,
        "symbolic": symbolic,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dir")
    parser.add_argument("--esc", default=os.environ.get("ESC", "build/cli/esc"))
    parser.add_argument("--out", help="write the Markdown table here (default: print it)")
    a = parser.parse_args()
    lines = ["| condition | controller | run | best fitness | backward share | reversals / 100 steps "
             "| BACKWARD usage | alternates |", "|---|---|---|---|---|---|---|---|"]
    totals = []
    with tempfile.TemporaryDirectory() as scratch:
        for name, source, part in parts(a.dir):
            with open(os.path.join(source, "settings.json")) as f:
                settings = json.load(f)
            top = float(str(settings["settings"]["robot.max_speed"]).split()[0])
            for controller, c in part["controllers"].items():
                alternating = 0
                runs = c["runs"]
                for r in runs:
                    i = int(r["run"])   # from 1, as `esc replay --run` takes it
                    j = judge(replay(a.esc, source, controller, i, scratch), top)
                    alt = j["backward"] >= MIN_BACKWARD and j["reversals"] >= MIN_REVERSALS
                    alternating += alt
                    usage = f"{100 * j['backward_usage']:.0f}%" if j["symbolic"] else "-"
                    lines.append(f"| {name} | {controller} | {i} | {r['best_fitness']:.1f} | "
                                 f"{100 * j['backward']:.0f}% | {j['reversals']:.1f} | {usage} | "
                                 f"{'yes' if alt else 'no'} |")
                totals.append(f"| {name} | {controller} | {alternating} of {len(runs)} |")
    with open(a.out, "w") if a.out else contextlib.nullcontext(sys.stdout) as print_to:
        write_table(print_to, totals, lines)


def write_table(print_to, totals, lines):
    print("# Loophole: runs that alternate FORWARD and BACKWARD\n", file=print_to)
    print(f"Criterion: backward share >= {MIN_BACKWARD:.0%} and >= {MIN_REVERSALS:g} reversals per 100 steps "
          f"in the run's best evaluation (scripts/loophole-criterion.py).\n", file=print_to)
    print("| condition | controller | runs alternating |\n|---|---|---|", file=print_to)
    print("\n".join(totals) + "\n", file=print_to)
    print("\n".join(lines), file=print_to)


if __name__ == "__main__":
    main()
