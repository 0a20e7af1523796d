#!/usr/bin/python3
"""esc's NSGA-II against DEAP's on ZDT1, ZDT2 and ZDT3; prints a Markdown table
(docs/optimizers.md holds the committed one).

    /usr/bin/python3 scripts/validate-nsga2.py [--esc build/tools/testfn/esc-testfn]
        [--seeds 15] [--jobs N] [--out FILE]

Needs Debian's python3-deap (apt-get install python3-deap), hence /usr/bin/python3.
DEAP runs its own examples/ga/nsga2.py: n = 30 in [0, 1], MU = 100, NGEN = 250 (the first
population and 249 generations of children, 25,000 evaluations), CXPB = 0.9,
cxSimulatedBinaryBounded and mutPolynomialBounded with eta 20, indpb 1/n, selTournamentDCD
and selNSGA2, seeded by random.seed(seed). esc runs `esc-testfn nsga2` with the same
settings and 250 generations counted alike, from its own Rng streams of the seed. Both final
populations' hypervolumes (reference (11, 11)) come from DEAP's hypervolume
(deap.benchmarks.tools.hypervolume); esc's C++ hypervolume is checked against it on every
one of those fronts and on random 2-D and 3-D point sets with ties. Exits 1 when a median
differs by more than 1 % or the two hypervolumes by more than 1e-12 relative.
"""
import array
import datetime
import math
import os
import random
import statistics
import subprocess
import sys
import time
from concurrent.futures import ProcessPoolExecutor

from validation_common import arguments, machine  # noqa: E402

import numpy
import scipy.stats
from deap import base, benchmarks, creator, tools
from deap.benchmarks.tools import hypervolume as deap_hypervolume

N_VARIABLES, MU, NGEN, CXPB, ETA = 30, 100, 250, 0.9, 20.0
LOWER, UPPER = 0.0, 1.0
REFERENCE = (11.0, 11.0)
FUNCTIONS = ("zdt1", "zdt2", "zdt3")
TOLERANCE = 0.01          # the medians' ratio
HV_AGREEMENT = 1e-12      # relative, esc's hypervolume against DEAP's

creator.create("FitnessMin", base.Fitness, weights=(-1.0, -1.0))
creator.create("Individual", array.array, typecode="d", fitness=creator.FitnessMin)
creator.create("FitnessMin3", base.Fitness, weights=(-1.0, -1.0, -1.0))
creator.create("Point", list, fitness=creator.FitnessMin)
creator.create("Point3", list, fitness=creator.FitnessMin3)


def toolbox_for(name):
    toolbox = base.Toolbox()
    toolbox.register("attr_float", lambda: [random.uniform(LOWER, UPPER) for _ in range(N_VARIABLES)])
    toolbox.register("individual", tools.initIterate, creator.Individual, toolbox.attr_float)
    toolbox.register("population", tools.initRepeat, list, toolbox.individual)
    toolbox.register("evaluate", getattr(benchmarks, name))
    toolbox.register("mate", tools.cxSimulatedBinaryBounded, low=LOWER, up=UPPER, eta=ETA)
    toolbox.register("mutate", tools.mutPolynomialBounded, low=LOWER, up=UPPER, eta=ETA, indpb=1.0 / N_VARIABLES)
    toolbox.register("select", tools.selNSGA2)
    return toolbox


def deap_run(name, seed):
    """DEAP's examples/ga/nsga2.py main(seed), less its statistics: the final objectives."""
    start = time.perf_counter()
    random.seed(seed)
    toolbox = toolbox_for(name)
    pop = toolbox.population(n=MU)
    for ind in pop:
        ind.fitness.values = toolbox.evaluate(ind)
    pop = toolbox.select(pop, len(pop))  # assigns the crowding distances
    for _ in range(1, NGEN):
        offspring = [toolbox.clone(ind) for ind in tools.selTournamentDCD(pop, len(pop))]
        for ind1, ind2 in zip(offspring[::2], offspring[1::2]):
            if random.random() <= CXPB:
                toolbox.mate(ind1, ind2)
            toolbox.mutate(ind1)
            toolbox.mutate(ind2)
            del ind1.fitness.values, ind2.fitness.values
        for ind in offspring:
            ind.fitness.values = toolbox.evaluate(ind)
        pop = toolbox.select(pop + offspring, MU)
    return [list(ind.fitness.values) for ind in pop], time.perf_counter() - start


def esc_run(esc, name, seed):
    start = time.perf_counter()
    out = subprocess.run([esc, "nsga2", "--function", name, "--n", str(N_VARIABLES), "--seed", str(seed),
                          "--population", str(MU), "--generations", str(NGEN), "--crossover", str(CXPB),
                          "--eta-crossover", str(ETA), "--eta-mutation", str(ETA)],
                         check=True, capture_output=True, text=True).stdout.splitlines()
    points = [[float(v) for v in line.split()] for line in out[:-1]]
    label, value = out[-1].split()
    assert label == "hypervolume" and len(points) == MU, out[-1]
    return points, float(value), time.perf_counter() - start


def esc_hypervolume(esc, points, reference):
    text = "".join(" ".join(repr(v) for v in p) + "\n" for p in points)
    out = subprocess.run([esc, "hypervolume", "--reference", *map(repr, reference)], input=text,
                         check=True, capture_output=True, text=True).stdout
    return float(out)


def hypervolume(points, reference=REFERENCE):
    """DEAP's hypervolume of minimised objective vectors."""
    kind = creator.Point if len(reference) == 2 else creator.Point3
    front = []
    for p in points:
        ind = kind(p)
        ind.fitness.values = tuple(p)
        front.append(ind)
    return deap_hypervolume(front, list(reference)) if front else 0.0


def optimal_hypervolume(name):
    """The optimal front's hypervolume: g = 1, f2 = h(f1), the region dominated by the running
    minimum of h over f1 in [0, 1] (ZDT3's front is the part of the curve that is a new minimum).
    Trapezoids on 2,000,001 points: within 1e-9 of the limit (ZDT1: 120 + 2/3, ZDT2: 120 + 1/3)."""
    t = numpy.linspace(0.0, 1.0, 2_000_001)
    h = {"zdt1": 1.0 - numpy.sqrt(t), "zdt2": 1.0 - t * t,
         "zdt3": 1.0 - numpy.sqrt(t) - t * numpy.sin(10.0 * math.pi * t)}[name]
    low = numpy.minimum.accumulate(h)
    r1, r2 = REFERENCE
    return float(numpy.trapz(r2 - low, t) + (r1 - 1.0) * (r2 - low[-1]))


def random_sets(dimension, count):
    """Point sets with ties, dominated points and points beyond the reference."""
    sets = []
    for seed in range(count):
        rng = numpy.random.RandomState(seed)
        k = rng.randint(1, 80)
        points = rng.uniform(0.0, 1.2, (k, dimension))
        if seed % 2 == 0:
            points = numpy.round(points, 1)  # many equal coordinates
        sets.append(points.tolist())
    return sets


def quartiles(values):
    q = statistics.quantiles(values, n=4, method="inclusive")
    return q[0], q[2]


def main():
    args = arguments(__doc__)
    seeds = range(1, args.seeds + 1)

    with ProcessPoolExecutor(args.jobs) as pool:
        runs = {name: ([pool.submit(esc_run, args.esc, name, s) for s in seeds],
                       [pool.submit(deap_run, name, s) for s in seeds]) for name in FUNCTIONS}
        runs = {name: ([x.result() for x in e], [x.result() for x in d]) for name, (e, d) in runs.items()}

    lines = [f"Measured {datetime.date.today().isoformat()} on {machine()}; {args.seeds} seeds per row, "
             f"scripts/validate-nsga2.py (DEAP {__import__('deap').__version__}, numpy {numpy.__version__}).",
             "",
             "| function | esc median HV (IQR) | DEAP median HV (IQR) | esc / DEAP | esc min-max | DEAP min-max "
             "| Mann-Whitney p | optimal front | median gap to it, esc and DEAP |",
             "|---|---|---|---|---|---|---|---|---|"]
    failed = []
    worst_hv = 0.0
    fronts = 0
    seconds = {"esc": [], "DEAP": []}
    for name, (esc_runs, deap_runs) in runs.items():
        hv_esc = [hypervolume(points) for points, _, _ in esc_runs]
        hv_deap = [hypervolume(points) for points, _ in deap_runs]
        # The C++ hypervolume on the same fronts: esc's printed, DEAP's piped back.
        for (points, printed, _), reference in zip(esc_runs, hv_esc):
            worst_hv = max(worst_hv, abs(printed - reference) / reference)
        for (points, _), reference in zip(deap_runs, hv_deap):
            worst_hv = max(worst_hv, abs(esc_hypervolume(args.esc, points, REFERENCE) - reference) / reference)
        fronts += len(esc_runs) + len(deap_runs)
        seconds["esc"] += [r[2] for r in esc_runs]
        seconds["DEAP"] += [r[1] for r in deap_runs]

        me, md = statistics.median(hv_esc), statistics.median(hv_deap)
        p = scipy.stats.mannwhitneyu(hv_esc, hv_deap, alternative="two-sided").pvalue
        if abs(me / md - 1.0) > TOLERANCE:
            failed.append(f"{name}: median hypervolume esc {me:.4f}, DEAP {md:.4f}")
        (e1, e3), (d1, d3) = quartiles(hv_esc), quartiles(hv_deap)
        best = optimal_hypervolume(name)
        lines.append(f"| {name.upper()} | {me:.4f} ({e1:.4f}-{e3:.4f}) | {md:.4f} ({d1:.4f}-{d3:.4f}) | "
                     f"{me / md:.5f} | {min(hv_esc):.4f}-{max(hv_esc):.4f} | {min(hv_deap):.4f}-{max(hv_deap):.4f} | "
                     f"{p:.2g} | {best:.4f} | {best - me:.4f}, {best - md:.4f} |")

    checks = 0
    for dimension, reference in ((2, (1.0, 1.0)), (3, (1.0, 1.0, 1.0))):
        for points in random_sets(dimension, 40):
            exact = hypervolume(points, reference)
            mine = esc_hypervolume(args.esc, points, reference)
            worst_hv = max(worst_hv, abs(mine - exact) / max(exact, 1e-300) if exact > 0 else abs(mine))
            checks += 1
    if worst_hv > HV_AGREEMENT:
        failed.append(f"esc's hypervolume differs from DEAP's by {worst_hv:.3g} (relative)")

    lines += ["",
              f"esc's C++ hypervolume against DEAP's: largest relative difference {worst_hv:.2g} over the {fronts} "
              f"final populations above and {checks} random 2-D and 3-D sets with ties, dominated points and "
              f"points beyond the reference. Median seconds per run: esc {statistics.median(seconds['esc']):.2f}, "
              f"DEAP {statistics.median(seconds['DEAP']):.1f}."]
    text = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    sys.stdout.write(text)
    for line in failed:
        print("FAILED:", line, file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
