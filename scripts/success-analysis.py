#!/usr/bin/env python3
"""Success per method of a finished study or experiment that declares `success when` (the
maze studies of experiments/lehman_stanley/mazes.esc): how many runs succeeded and how many
evaluations they took, then esc's own tests of every pair. Reads summary.json and `esc
export DIR --table success` (no other dependency); prints Markdown.

    python3 scripts/success-analysis.py RUN_DIR [--esc build/cli/esc]

Per condition and controller: runs that succeeded; over those, the evaluations up to and
including the first success: mean (sample sd), median, range; and the evaluations the runs
made in all (a run that stops at its success makes no more). Then per pair, as the end table
compares them: Fisher's exact test of the counts and the censored Mann-Whitney test of the
evaluations to success, each with Holm's adjustment over its family.
"""
import argparse
import json
import os
import statistics

from esc_runs import export


def cells(summary):
    """(condition, controller, runs) of a study's summary or a plain experiment's."""
    if "conditions" in summary:
        for c in summary["conditions"]:
            for name, controller in c["controllers"].items():
                yield c["name"], name, controller["runs"], c.get("success")
    else:
        for name, controller in summary["controllers"].items():
            yield "", name, controller["runs"], summary.get("success")


def number(x, decimals=0):
    return f"{x:,.{decimals}f}"


def p_text(field):
    if field in ("", "nan"):
        return "n/a"
    p = float(field)
    return f"{p:.1e}" if p < 1e-4 else f"{p:.4f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("--esc", default="build/cli/esc")
    args = parser.parse_args()

    with open(os.path.join(args.directory, "summary.json")) as f:
        summary = json.load(f)
    rows = list(cells(summary))
    tests = {test for *_, test in rows if test}
    print(f"Success: `{', '.join(sorted(tests))}` (esc's resolved test, in SI).\n")
    print("| condition | controller | runs that succeeded | evaluations to success: mean (sd) | median | range "
          "| evaluations made, all runs |")
    print("|---|---|---|---|---|---|---|")
    # Evaluations the runs made, per (condition, controller): the default export's rows, one
    # per generation (a plain experiment's condition is its name there).
    made = {}
    for g in export(args.esc, args.directory):
        key = (g["condition"] if g["study"] else "", g["controller"])
        made[key] = made.get(key, 0) + int(g["evaluations"])
    for condition, controller, runs, _ in rows:
        solved = [r["success_evaluation"] for r in runs if r.get("success_evaluation") is not None]
        spread = f"{number(statistics.mean(solved))} ({number(statistics.stdev(solved))})" if len(solved) > 1 else \
            (number(solved[0]) if solved else "n/a")
        median = number(statistics.median(solved), 1 if len(solved) % 2 == 0 else 0) if solved else "n/a"
        extent = f"{number(min(solved))}-{number(max(solved))}" if solved else "n/a"
        print(f"| {condition} | {controller} | {len(solved)} of {len(runs)} | {spread} | {median} | {extent} "
              f"| {made.get((condition, controller), 0):,} |")

    pairs = export(args.esc, args.directory, "--table", "success")
    if not pairs:
        return
    print("\n| pair | successes | Fisher p | p Holm | Mann-Whitney U (censored) | p | p Holm | censored at |")
    print("|---|---|---|---|---|---|---|---|")
    for p in pairs:
        if p["condition_a"] == p["condition_b"]:
            label = f"{p['condition_a'] + ': ' if p['condition_a'] else ''}{p['controller_a']} vs {p['controller_b']}"
        else:
            label = f"{p['controller_a']}: {p['condition_a']} vs {p['condition_b']}"
        censored = "none" if p["censored_at"] == "nan" else number(float(p["censored_at"]))
        print(f"| {label} | {p['successes_a']}/{p['runs_a']} vs {p['successes_b']}/{p['runs_b']} "
              f"| {p_text(p['fisher_p'])} | {p_text(p['fisher_p_holm'])} | {float(p['censored_u']):.1f} "
              f"| {p_text(p['censored_p'])} | {p_text(p['censored_p_holm'])} | {censored} |")
    print("\nHolm: over the pairs shown, one family per test. Censored Mann-Whitney (Gehan): a run that never "
          "succeeded counts as more than the pair's largest budget (`censored at`; none when every run succeeded).")


if __name__ == "__main__":
    main()
