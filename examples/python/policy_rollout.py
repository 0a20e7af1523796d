"""A hand-written policy in esc.Env, and a stored genome's network beside it: one episode
each (one epoch of the obstacle-avoidance experiment), trajectories plotted.
Usage: policy_rollout.py [RUN_DIR]   RUN_DIR: a run of obstacle_avoidance that compared SC_8_6;
when it holds none, a short one is made there (default runs/policy_rollout)."""
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import esc

SCRIPT = Path(__file__).resolve().parents[2] / "experiments" / "paper" / "obstacle_avoidance.esc"


def braitenberg(observation):
    """Wheel commands from the eight infrared sensors (0 far, 1 touching): slow down the
    wheel on the side away from an obstacle, so that the robot turns from it."""
    ir = observation[:8]
    left_side, right_side = ir[0:3].sum(), ir[3:6].sum()
    return np.array([1.0 - 2.0 * right_side, 1.0 - 2.0 * left_side]).clip(-1.0, 1.0)


def episode(env, policy):
    """(x, y) of every step of one episode, and its fitness."""
    observation, info = env.reset()
    path = []
    while True:
        observation, reward, terminated, truncated, info = env.step(policy(observation))
        state = env.state()
        path.append((state["x"], state["y"]))
        if terminated or truncated:
            return np.array(path), info["fitness"]


run_dir = Path(sys.argv[1] if len(sys.argv) > 1 else "runs/policy_rollout")
script = esc.compile(SCRIPT, {"epochs": 1})
if not (run_dir / "esc.db").exists():
    esc.run(script, runs=1, generations=3, controllers=["SC_8_6"], set={"mu": 5, "lambda": 20}, out=run_dir)
best = esc.open(run_dir).best("SC_8_6", 1)

hand = esc.Env(script, "obstacle_avoidance", seed=best.evaluation_seed)      # actions: wheel commands
evolved = esc.Env(script, "obstacle_avoidance", "SC_8_6", seed=best.evaluation_seed)
for name, env, policy in [("Braitenberg", hand, braitenberg), ("evolved SC_8_6", evolved, evolved.policy(best.genome))]:
    path, fitness = episode(env, policy)
    plt.plot(path[:, 0], path[:, 1], label=f"{name}: fitness {fitness:.1f} in {len(path)} steps")
plt.axis("equal")
plt.legend()
plt.title("one epoch of obstacle_avoidance, same start")
plt.savefig(f"{run_dir}/rollout.png")
print(f"figure: {run_dir}/rollout.png")
