"""DEAP's CMA-ES evolving the obstacle-avoidance symbolic controller SC_8_6 through
esc.evaluate, beside esc's own run (its ES) with the same number of evaluations.
Usage: deap_cmaes.py [--generations G] [--lambda L] [--epochs E] [--out DIR]"""
import argparse
from pathlib import Path

import numpy as np
from deap import base, cma, creator

import esc

SCRIPT = Path(__file__).resolve().parents[2] / "experiments" / "paper" / "obstacle_avoidance.esc"

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--generations", type=int, default=50)
parser.add_argument("--lambda", dest="lam", type=int, default=40)
parser.add_argument("--epochs", type=int, default=3)
parser.add_argument("--seed", type=int, default=1)
parser.add_argument("--out", default="runs/deap_cmaes")
args = parser.parse_args()

script = esc.compile(SCRIPT, {"epochs": args.epochs})
controller = script.controller("obstacle_avoidance", "SC_8_6")

# DEAP's CMA-ES: ask (generate) a population, evaluate it with esc on every core, tell (update).
creator.create("FitnessMax", base.Fitness, weights=(1.0,))
creator.create("Individual", list, fitness=creator.FitnessMax)
np.random.seed(args.seed)
strategy = cma.Strategy(centroid=[0.0] * controller.genome_size, sigma=0.5, lambda_=args.lam)
run_seed = esc.run_seed(args.seed, 1)
best_deap = -np.inf
for generation in range(args.generations):
    population = strategy.generate(creator.Individual)
    seeds = [esc.evaluation_seed(run_seed, generation, i) for i in range(len(population))]
    fitness = esc.evaluate(script, "obstacle_avoidance", "SC_8_6", np.array(population), seed=seeds)
    for individual, f in zip(population, fitness):
        individual.fitness.values = (f,)
    strategy.update(population)
    best_deap = max(best_deap, fitness.max())
    print(f"DEAP CMA-ES generation {generation}: best {fitness.max():.1f}, mean {fitness.mean():.1f}")

# esc's own run of the script's ES, with as many evaluations (lambda x generations).
mu = max(1, args.lam // 5)
own = esc.run(script, runs=1, generations=args.generations, seed=args.seed, controllers=["SC_8_6"],
              set={"mu": mu, "lambda": args.lam}, out=args.out)
best_es = own.best("SC_8_6", 1).fitness
print(f"\n{args.generations} x {args.lam} evaluations each: best fitness DEAP CMA-ES {best_deap:.1f}, "
      f"esc's ES (mu {mu}) {best_es:.1f}")
