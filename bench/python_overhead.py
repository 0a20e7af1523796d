"""The Python module's overhead, measured in one run (docs/performance.md, "From Python"):

1. esc.evaluate against `esc run`: evaluations per second of the obstacle-avoidance SC 8-14-6
   at generation 0 (random genomes in the gene bounds [-1, 1], one evaluation seed each,
   10 epochs x 150 steps, lambda evaluations on every core), in alternating rounds.
2. Env.step against esc's own control step: microseconds per step of Env driven by the same
   controller's network (Env.policy), and of Env.step alone, against `esc bench`'s
   step/obstacle_avoidance/SC_8_14_6 (whole evaluations on one core, per control step).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py build/cli/esc [--rounds N]
"""
import argparse
import os
import re
import statistics
import subprocess
import tempfile
import time

import numpy as np

import esc

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "experiments", "paper", "obstacle_avoidance.esc")
EXPERIMENT, CONTROLLER = "obstacle_avoidance", "SC_8_14_6"


def esc_run_rate(binary, lam, work):
    """Evaluations per second of generation 0 of `esc run` (its own clock: the round's seconds)."""
    out = os.path.join(work, f"run-{time.monotonic_ns()}")
    subprocess.run([binary, "run", SCRIPT, "--runs", "1", "--generations", "1", "--controllers", CONTROLLER,
                    "--set", f"lambda={lam}", "--out", out], check=True, stdout=subprocess.DEVNULL)
    row = esc.open(out).table().iloc[0]
    return row["evaluations"] / row["seconds"]


def evaluate_rate(script, lam, rng):
    genomes = rng.uniform(-1.0, 1.0, size=(lam, script.controller(EXPERIMENT, CONTROLLER).genome_size))
    seeds = rng.integers(0, 2**63, size=lam, dtype=np.uint64).tolist()
    start = time.perf_counter()
    esc.evaluate(script, EXPERIMENT, CONTROLLER, genomes, seed=seeds)
    return lam / (time.perf_counter() - start)


def native_step_us(binary):
    text = subprocess.run([binary, "bench", "--min-time", "1", "--benchmark",
                           "--benchmark_filter=^step/obstacle_avoidance/SC_8_14_6$"],
                          check=True, capture_output=True, text=True).stdout
    rate = float(re.search(r"SC_8_14_6 \(.*\): (\d+) control steps/s per core", text).group(1))
    return 1e6 / rate


def env_step_us(script, steps, rng, with_policy):
    env = esc.Env(script, EXPERIMENT, CONTROLLER, seed=1)
    policy = env.policy(rng.uniform(-1.0, 1.0, size=script.controller(EXPERIMENT, CONTROLLER).genome_size))
    constant = np.zeros(env.action_space.shape)
    done, elapsed = 0, 0.0
    while done < steps:
        observation, _ = env.reset()
        start = time.perf_counter()
        while True:
            action = policy(observation) if with_policy else constant
            observation, _, terminated, truncated, _ = env.step(action)
            done += 1
            if terminated or truncated:
                break
        elapsed += time.perf_counter() - start
    return 1e6 * elapsed / done


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("esc_binary")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--lambda", dest="lam", type=int, default=150)
    parser.add_argument("--steps", type=int, default=200_000)
    args = parser.parse_args()
    script = esc.compile(SCRIPT)
    rng = np.random.default_rng(1)
    cli, py = [], []
    with tempfile.TemporaryDirectory() as work:
        for r in range(args.rounds):   # alternating, so that drifts of the machine hit both alike
            if r % 2 == 0:
                cli.append(esc_run_rate(args.esc_binary, args.lam, work))
                py.append(evaluate_rate(script, args.lam, rng))
            else:
                py.append(evaluate_rate(script, args.lam, rng))
                cli.append(esc_run_rate(args.esc_binary, args.lam, work))
    native = native_step_us(args.esc_binary)
    stepped = env_step_us(script, args.steps, rng, with_policy=True)
    bare = env_step_us(script, args.steps, rng, with_policy=False)
    print(f"machine: {os.cpu_count()} hardware threads")
    print(f"esc run, generation 0:  {statistics.median(cli):9.1f} evaluations/s (median of {len(cli)}; "
          f"{min(cli):.1f} to {max(cli):.1f})")
    print(f"esc.evaluate:           {statistics.median(py):9.1f} evaluations/s (median of {len(py)}; "
          f"{min(py):.1f} to {max(py):.1f})")
    print(f"ratio esc.evaluate / esc run: {statistics.median(py) / statistics.median(cli):.3f}")
    print(f"native step (esc bench, one core): {native:6.2f} us")
    print(f"Env.step(policy(obs)):             {stepped:6.2f} us  (+{stepped - native:.2f} us)")
    print(f"Env.step(constant action):         {bare:6.2f} us  (+{bare - native:.2f} us)")


if __name__ == "__main__":
    main()
