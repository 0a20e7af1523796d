#!/usr/bin/env python3
"""The paper's sensitivity analysis from a finished run: how much the supervisors act
through behaviors of libraries marked `useless`, over the generations, and where each run
ends. Reads `esc export DIR --table usage` and `esc export DIR` (no other dependency);
prints Markdown.

    python3 scripts/useless-usage.py RUN_DIR [--esc build/cli/esc] [--points 6]

Per (condition, controller): the share of the best evaluation's steps spent in useless
behaviors, mean over the runs (min-max), at evenly spaced generations; then per run that
share at the first and the last generation, and the run's best fitness.
"""
import argparse
import statistics
import sys
from collections import defaultdict

from esc_runs import export


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("--esc", default="build/cli/esc")
    parser.add_argument("--points", type=int, default=6, help="generations shown (first and last included)")
    args = parser.parse_args()

    # (condition, controller) -> run -> generation -> [useless steps, all steps]
    shares = defaultdict(lambda: defaultdict(lambda: defaultdict(lambda: [0, 0])))
    marked = set()   # (condition, controller) offered a useless behavior, used or not
    for r in export(args.esc, args.directory, "--table", "usage"):
        # The usage table leaves a plain experiment's condition empty, the main export names it.
        key = (r["condition"] or r["experiment"], r["controller"])
        if r["useless"] == "1":
            marked.add(key)
        cell = shares[key][int(r["run"])][int(r["generation"])]
        steps = int(r["best_steps"])
        cell[0] += steps if r["useless"] == "1" else 0
        cell[1] += steps
    best = defaultdict(lambda: defaultdict(lambda: float("-inf")))
    for r in export(args.esc, args.directory):
        key = (r["condition"], r["controller"])
        best[key][int(r["run"])] = max(best[key][int(r["run"])], float(r["best"]))

    keys = [k for k in shares if k in marked]
    if not keys:
        print("No controller of this run is offered a behavior of a library marked `useless`.")
        return 0

    def share(cell):
        return cell[0] / cell[1] if cell[1] else 0.0

    print("# Useless behaviors: share of the best evaluation's steps\n")
    for key in keys:
        runs = shares[key]
        last = min(max(gens) for gens in runs.values())
        points = sorted({round(i * last / max(args.points - 1, 1)) for i in range(args.points)})
        condition, controller = key
        print(f"## {controller} in {condition}\n")
        print("| generation | " + " | ".join(str(g) for g in points) + " |")
        print("|---" * (len(points) + 1) + "|")
        cells = []
        for g in points:
            values = [share(runs[r][g]) for r in sorted(runs)]
            cells.append(f"{100 * statistics.mean(values):.1f}% ({100 * min(values):.0f}-{100 * max(values):.0f})")
        print("| useless, mean (min-max) over runs | " + " | ".join(cells) + " |\n")
        print("| run | useless at generation 0 | useless at generation " + str(last) + " | best fitness |")
        print("|---|---|---|---|")
        for r in sorted(runs):
            print(f"| {r} | {100 * share(runs[r][0]):.1f}% | {100 * share(runs[r][last]):.1f}% | {best[key][r]:.1f} |")
        fitness = [best[key][r] for r in sorted(runs)]
        sd = statistics.stdev(fitness) if len(fitness) > 1 else 0.0
        print(f"\nBest fitness over the runs: {statistics.mean(fitness):.1f} ± {sd:.1f}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
