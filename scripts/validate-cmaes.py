#!/usr/bin/python3
"""esc's CMA-ES against DEAP's (deap.cma.Strategy) on the literature's test functions;
prints a Markdown table (docs/optimizers.md holds the committed one).

    /usr/bin/python3 scripts/validate-cmaes.py [--esc build/tools/testfn/esc-testfn]
        [--seeds 15] [--jobs N] [--out FILE]

Needs Debian's python3-deap (apt-get install python3-deap), hence /usr/bin/python3.
Both sides get the same lambda (4 + floor(3 ln n)), sigma (0.2 of the box [-5, 5], i.e. 2)
and start-point distribution (uniform in the box); each draws from its own generator
(esc: Rng streams from the seed; DEAP: numpy.random.seed(seed)). esc keeps its candidates in
the box, DEAP samples unbounded. Measured: evaluations until f < 1e-8, counting the one that
got there. Sphere, rotated ellipsoid (condition 1e6) and Rosenbrock compare medians;
Rastrigin compares success rates, esc with and without IPOP, DEAP plain. A run without
restarts ends when a stop fires; DEAP, which has none, gets esc's (sd below 1e-12 of the
width in every coordinate, condition of C above 1e14, 10 flat generations).
"""
import datetime
import math
import os
import statistics
import subprocess
import sys
from concurrent.futures import ProcessPoolExecutor

from validation_common import arguments, machine  # noqa: E402

os.environ.setdefault("OMP_NUM_THREADS", "1")  # one numpy thread per worker
import numpy  # noqa: E402
from deap import base, cma, creator  # noqa: E402

LOWER, UPPER, SIGMA0, TARGET = -5.0, 5.0, 0.2, 1e-8
BUDGET = 1_000_000            # sphere, ellipsoid, Rosenbrock
RASTRIGIN_BUDGET = 200_000    # times n, Rastrigin (IPOP's doubled populations are costly)
IPOP_RESTARTS = 9
FLAT_GENERATIONS, TOL_SIGMA, MAX_CONDITION = 10, 1e-12, 1e14

creator.create("FitnessMin", base.Fitness, weights=(-1.0,))
creator.create("Individual", list, fitness=creator.FitnessMin)


def default_lambda(n):
    return 4 + int(3 * math.log(n))


def ellipsoid_for(n, seed):
    # Its own generator, so the rotation leaves DEAP's stream alone.
    rng = numpy.random.RandomState(1_000_000 + seed)
    q, r = numpy.linalg.qr(rng.standard_normal((n, n)))
    q = q * numpy.sign(numpy.diag(r))
    scale = 10.0 ** (6.0 * numpy.arange(n) / max(n - 1, 1))
    return lambda x: float(numpy.dot(scale, numpy.dot(q.T, x) ** 2))


def function(name, n, seed):
    if name == "sphere":
        return lambda x: float(numpy.dot(x, x))
    if name == "ellipsoid":
        return ellipsoid_for(n, seed)
    if name == "rosenbrock":
        return lambda x: float(numpy.sum(100.0 * (x[:-1] ** 2 - x[1:]) ** 2 + (x[:-1] - 1.0) ** 2))
    if name == "rastrigin":
        return lambda x: float(10.0 * len(x) + numpy.sum(x * x - 10.0 * numpy.cos(2.0 * numpy.pi * x)))
    raise ValueError(name)


def deap_run(name, n, seed, budget):
    numpy.random.seed(seed)
    f = function(name, n, seed)
    lam = default_lambda(n)
    strategy = cma.Strategy(centroid=numpy.random.uniform(LOWER, UPPER, n),
                            sigma=SIGMA0 * (UPPER - LOWER), lambda_=lam)
    evals, flat = 0, 0
    kth = min(lam - 1, int(0.1 + lam / 4))
    while True:
        population = strategy.generate(creator.Individual)
        values = []
        for ind in population:
            if evals == budget:
                return None, evals
            v = f(numpy.asarray(ind))
            evals += 1
            if v < TARGET:
                return evals, evals
            ind.fitness.values = (v,)
            values.append(v)
        strategy.update(population)
        values.sort()
        flat = flat + 1 if values[0] == values[kth] else 0
        sd = strategy.sigma * numpy.maximum(numpy.sqrt(numpy.diag(strategy.C)), numpy.abs(strategy.pc))
        if (numpy.all(sd < TOL_SIGMA * (UPPER - LOWER)) or strategy.cond ** 2 > MAX_CONDITION
                or flat >= FLAT_GENERATIONS):
            return None, evals


def esc_run(esc, name, n, seed, budget, ipop):
    import json
    out = subprocess.run([esc, "--function", name, "--n", str(n), "--seed", str(seed), "--target", str(TARGET),
                          "--max-evals", str(budget), "--sigma", str(SIGMA0), "--lower", str(LOWER),
                          "--upper", str(UPPER), "--ipop", str(ipop)],
                         check=True, capture_output=True, text=True).stdout
    r = json.loads(out)
    return r["evaluations_to_target"], r["evaluations"], r["restarts"]


def median_hits(hits):
    # Failures count as infinitely long, so the median exists while most runs succeed.
    ordered = sorted(math.inf if h is None else h for h in hits)
    m = statistics.median(ordered)
    return None if math.isinf(m) else m


def fmt(v):
    return "—" if v is None else f"{v:,.0f}"


def main():
    args = arguments(__doc__)
    seeds = range(1, args.seeds + 1)
    dims = (10, 40)

    with ProcessPoolExecutor(args.jobs) as pool:
        # Everything submitted first, so the slow rows overlap the fast ones.
        medians = {(name, n): ([pool.submit(esc_run, args.esc, name, n, s, BUDGET, 0) for s in seeds],
                               [pool.submit(deap_run, name, n, s, BUDGET) for s in seeds])
                   for name in ("sphere", "ellipsoid", "rosenbrock") for n in dims}
        rastrigin = {n: ([pool.submit(esc_run, args.esc, "rastrigin", n, s, RASTRIGIN_BUDGET * n, 0) for s in seeds],
                         [pool.submit(esc_run, args.esc, "rastrigin", n, s, RASTRIGIN_BUDGET * n, IPOP_RESTARTS)
                          for s in seeds],
                         [pool.submit(deap_run, "rastrigin", n, s, RASTRIGIN_BUDGET * n) for s in seeds])
                     for n in dims}
        medians = {k: tuple([x.result()[0] for x in runs] for runs in v) for k, v in medians.items()}
        rastrigin = {k: tuple([x.result() for x in runs] for runs in v) for k, v in rastrigin.items()}

    lines = [f"Measured {datetime.date.today().isoformat()} on {machine()}; {args.seeds} seeds per row, "
             f"scripts/validate-cmaes.py (DEAP {__import__('deap').__version__}, numpy {numpy.__version__}).",
             "",
             "| function | n | λ | esc median evaluations | DEAP median evaluations | esc / DEAP | successes esc, DEAP |",
             "|---|---|---|---|---|---|---|"]
    for (name, n), (e, d) in medians.items():
        me, md = median_hits(e), median_hits(d)
        ratio = "—" if me is None or md is None else f"{me / md:.2f}"
        ok = lambda hits: sum(h is not None for h in hits)  # noqa: E731
        lines.append(f"| {name} | {n} | {default_lambda(n)} | {fmt(me)} | {fmt(md)} | {ratio} | "
                     f"{ok(e)}, {ok(d)} of {args.seeds} |")
    lines += ["",
              f"Rastrigin, f < 1e-8 within {RASTRIGIN_BUDGET:,} n evaluations; IPOP with at most "
              f"{IPOP_RESTARTS} restarts:",
              "",
              "| n | esc plain | esc IPOP | IPOP median evaluations (successes) | IPOP median restarts | DEAP plain |",
              "|---|---|---|---|---|---|"]
    for n, (plain, ipop, d) in rastrigin.items():
        rate = lambda runs: f"{sum(r[0] is not None for r in runs)} / {args.seeds}"  # noqa: E731
        wins = [r[0] for r in ipop if r[0] is not None]
        lines.append(f"| {n} | {rate(plain)} | {rate(ipop)} | {fmt(statistics.median(wins) if wins else None)} | "
                     f"{statistics.median(r[2] for r in ipop):g} | {rate(d)} |")
    text = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
