#!/usr/bin/env python3
"""How each optimizer did, per condition of a study that compares them (docs/optimizers.md).

    scripts/optimizer-comparison.py DIR [--out FILE.md]

DIR is a finished run of a study such as experiments/studies/es_vs_cmaes.esc. For each
condition and controller: the runs' best fitness (mean, sd, median, best and worst run),
and how fast the mean over runs of each run's best so far rose: the first generation at
which it reached 50%, 90% and 99% of its final value (a run its optimizer stopped early keeps
its best so far to the end). The statistics between controllers and
between conditions (Welch, Mann-Whitney, A12, Holm) are what `esc run` prints at the end of
the study and the report shows; this table adds what they do not: the speed.
"""
import argparse
import json
import os
import statistics
import sys


def rows(summary):
    out = ["| condition | controller | best fitness, mean ± sd | median | best run | worst run | "
           "generation at 50% / 90% / 99% of the final best so far |",
           "|---|---|---|---|---|---|---|"]
    for condition in summary["conditions"]:
        for name, controller in condition["controllers"].items():
            runs = controller["runs"]
            best = [r["best_fitness"] for r in runs]
            # A run its optimizer stopped early keeps its best so far to the end.
            length = max(len(r["best"]) for r in runs)
            so_far = [statistics.mean(max(r["best"][: g + 1]) for r in runs) for g in range(length)]
            final = so_far[-1]
            reached = [next(g for g, v in enumerate(so_far) if v >= q * final) for q in (0.5, 0.9, 0.99)]
            sd = statistics.stdev(best) if len(best) > 1 else 0.0
            out.append(f"| {condition['name']} | {name} | {statistics.mean(best):.1f} ± {sd:.1f} | "
                       f"{statistics.median(best):.1f} | {max(best):.1f} | {min(best):.1f} | "
                       f"{reached[0]} / {reached[1]} / {reached[2]} |")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    parser.add_argument("--out")
    args = parser.parse_args()
    with open(os.path.join(args.dir, "summary.json")) as f:
        summary = json.load(f)
    if "conditions" not in summary:
        sys.exit(f"optimizer-comparison: {args.dir} holds an experiment, not a study")
    text = "\n".join(rows(summary)) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
