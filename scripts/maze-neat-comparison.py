#!/usr/bin/env python3
"""Lehman & Stanley's mazes: NEAT as esc runs it beside the paper's NEAT and esc's searches
of a fixed network (docs/maze-results.md). Reads the stored studies' summary.json
(results/lehman-stanley/MAZE and MAZE-neat) and, optionally, a file of the authors' own
program's runs made here; prints Markdown.

    python3 scripts/maze-neat-comparison.py medium [--results results/lehman-stanley]
        [--authors FILE] [--authors-fitness FILE] [--bodies]

Per method: runs that solved the maze and the evaluations to the first solution (mean, sd,
median, range over the solved runs). Then Fisher's exact test (two-sided) of each NEAT
method's successes against the paper's count for the same method and against esc's
fixed-network method of the same selection (NEAT by the fitness against CMA-ES, NEAT scored
by novelty against novelty search). The authors' file has one line per run: MAZE RUN
RECORDED SOLVED USER_S SYS_S, RECORDED the lines of their record.dat (one per offspring: the
first population's 250 evaluations are not recorded, and are added here); their
fitness-based runs' file MAZE RUN SOLVED_AT CPU_S, SOLVED_AT the individual that first
solved it ("none": not within the budget of 250,000).

With --bodies, also the 2 x 2 of issue 44 from the navigator's study (MAZE-navigator): for
each selection, the fixed network and NEAT on the Khepera and on Lehman & Stanley's navigator,
each cell's successes against the paper's count (Fisher), and the body's effect (Khepera
against navigator) and the representation's (fixed network against NEAT) on each side.
"""
import argparse
import json
import math
import os
import statistics

# The paper's counts (Lehman & Stanley 2011, section 6; docs/maze-results.md, "The paper's
# numbers"): runs that solved the maze of 40, and the mean (sd) evaluations where reported.
PAPER = {
    "medium": {"fitness": (40, "56,334 (48,705)"), "novelty": (40, "18,274 (20,447)")},
    "hard": {"fitness": (3, "not reported"), "novelty": (39, "35,109 (30,236)")},
}
RUNS_IN_PAPER = 40
BUDGET = 250_000
# Their novelty loop evaluates its first population (pop_size 250 in maze.ne) before it
# records anything: each run made this many evaluations more than its record.dat has lines.
AUTHORS_UNRECORDED = 250
# esc's condition of the same selection, in each study.
FIXED = {"fitness": "fitness_based", "novelty": "novelty"}
NEAT = {"fitness": "neat_fitness", "novelty": "neat_novelty"}


def fisher_two_sided(a, n_a, b, n_b):
    """Fisher's exact test of a successes in n_a against b in n_b: the probability, under
    the hypergeometric law with the margins fixed, of every table no more likely than the one
    observed (with a relative tolerance of 1e-7, as R and SciPy use)."""
    total, successes = n_a + n_b, a + b
    def p(x):
        return math.comb(n_a, x) * math.comb(n_b, successes - x) / math.comb(total, successes)
    observed = p(a)
    lo, hi = max(0, successes - n_b), min(n_a, successes)
    return min(1.0, sum(p(x) for x in range(lo, hi + 1) if p(x) <= observed * (1 + 1e-7)))


def stored(directory):
    """A stored study's summary; exits with one line when it is not stored (yet)."""
    path = os.path.join(directory, "summary.json")
    if not os.path.exists(path):
        raise SystemExit(f"maze-neat-comparison: {path} is not stored (yet): scripts/reproduce-paper.sh --write stores it")
    with open(path) as f:
        return json.load(f)


def solved_of(summary, condition):
    for c in summary["conditions"]:
        if c["name"] == condition:
            (controller,) = c["controllers"].values()
            runs = controller["runs"]
            return [r["success_evaluation"] for r in runs if r.get("success_evaluation") is not None], len(runs)
    raise SystemExit(f"no condition {condition} in the summary")


def stats(solved):
    if not solved:
        return "-", "-", "-"
    spread = f"{statistics.mean(solved):,.0f} ({statistics.stdev(solved):,.0f})" if len(solved) > 1 else f"{solved[0]:,}"
    median = statistics.median(solved)
    return spread, f"{median:,.1f}" if median % 1 else f"{median:,.0f}", f"{min(solved):,}-{max(solved):,}"


def p_text(p):
    return f"{p:.1e}" if p < 1e-4 else f"{p:.3g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("maze", choices=sorted(PAPER))
    parser.add_argument("--results", default="results/lehman-stanley")
    parser.add_argument("--authors")
    parser.add_argument("--authors-fitness")
    parser.add_argument("--bodies", action="store_true")
    args = parser.parse_args()
    fixed, neat = (stored(os.path.join(args.results, name)) for name in (args.maze, args.maze + "-neat"))

    print("| method | runs that solved it | evaluations to success: mean (sd) | median | range |")
    print("|---|---|---|---|---|")
    for selection in ("fitness", "novelty"):
        count, mean = PAPER[args.maze][selection]
        print(f"| paper: NEAT, {selection} | {count} of {RUNS_IN_PAPER} | {mean} | | |")
    if args.authors:
        with open(args.authors) as f:
            rows = [line.split() for line in f if line.split() and line.split()[0] == args.maze]
        solved = [int(r[2]) + AUTHORS_UNRECORDED for r in rows if r[3] == "1"]
        evaluations = sum(int(r[2]) + AUTHORS_UNRECORDED for r in rows)
        seconds = sum(float(r[4]) + float(r[5]) for r in rows)
        spread, median, extent = stats(solved)
        print(f"| the authors' program here: NEAT, novelty | {len(solved)} of {len(rows)} | {spread} | {median} "
              f"| {extent} |")
    if args.authors_fitness:
        with open(args.authors_fitness) as f:
            runs = [line.split() for line in f if line.split() and line.split()[0] == args.maze]
        solved = [int(r[2]) for r in runs if r[2] != "none" and int(r[2]) <= BUDGET]
        spread, median, extent = stats(solved)
        print(f"| the authors' program here: NEAT, fitness | {len(solved)} of {len(runs)} | {spread} | {median} "
              f"| {extent} |")
    for selection in ("fitness", "novelty"):
        for label, summary, condition in ((f"esc: fixed network, {FIXED[selection]}", fixed, FIXED[selection]),
                                          (f"esc: NEAT, {selection}", neat, NEAT[selection])):
            solved, runs = solved_of(summary, condition)
            spread, median, extent = stats(solved)
            print(f"| {label} | {len(solved)} of {runs} | {spread} | {median} | {extent} |")

    print("\n| NEAT in esc against | successes | Fisher p (two-sided) |")
    print("|---|---|---|")
    for selection in ("fitness", "novelty"):
        solved, runs = solved_of(neat, NEAT[selection])
        paper = PAPER[args.maze][selection][0]
        print(f"| NEAT, {selection}: the paper's NEAT, {selection} | {len(solved)}/{runs} vs {paper}/{RUNS_IN_PAPER} "
              f"| {p_text(fisher_two_sided(len(solved), runs, paper, RUNS_IN_PAPER))} |")
        other, other_runs = solved_of(fixed, FIXED[selection])
        print(f"| NEAT, {selection}: esc's fixed network, {FIXED[selection]} | {len(solved)}/{runs} vs "
              f"{len(other)}/{other_runs} | {p_text(fisher_two_sided(len(solved), runs, len(other), other_runs))} |")
    if args.authors:
        print(f"\nThe authors' program: {evaluations:,} evaluations in {seconds:,.1f} s of CPU time, "
              f"{evaluations / seconds:,.0f} evaluations per second per core.")
    if args.bodies:
        bodies(args.maze, fixed, neat, stored(os.path.join(args.results, args.maze + "-navigator")))


def bodies(maze, fixed, neat, navigator):
    """Issue 44's 2 x 2: representation (fixed network, NEAT) by body (Khepera, navigator)."""
    def cell(summary, condition):
        solved, runs = solved_of(summary, condition)
        mean = f", mean {statistics.mean(solved):,.0f}" if solved else ""
        return len(solved), runs, f"{len(solved)}/{runs}{mean}"

    def fisher(a, b):
        return p_text(fisher_two_sided(a[0], a[1], b[0], b[1]))

    print("\n| selection | network | Khepera: solved, evaluations | navigator: solved, evaluations "
          "| Fisher p, Khepera vs navigator | paper (NEAT) | Fisher p vs paper: Khepera | navigator |")
    print("|---|---|---|---|---|---|---|---|")
    for selection in ("fitness", "novelty"):
        paper = (PAPER[maze][selection][0], RUNS_IN_PAPER)
        cells = {}
        for network, summary, condition in (("fixed", fixed, FIXED[selection]), ("NEAT", neat, NEAT[selection])):
            khepera, body = cell(summary, condition), cell(navigator, condition)
            cells[network] = (khepera, body)
            print(f"| {selection} | {network} | {khepera[2]} | {body[2]} | {fisher(khepera, body)} "
                  f"| {paper[0]}/{paper[1]} | {fisher(khepera, paper)} | {fisher(body, paper)} |")
        (fk, fn), (nk, nn) = cells["fixed"], cells["NEAT"]
        print(f"| {selection} | fixed vs NEAT, Fisher p | {fisher(fk, nk)} | {fisher(fn, nn)} | | | | |")


if __name__ == "__main__":
    main()
