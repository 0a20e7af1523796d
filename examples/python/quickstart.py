"""Compile a script, run it, plot each controller's best fitness per generation.
Usage: quickstart.py [OUT_DIR]   (a short run: 2 runs x 5 generations x 2 epochs)"""
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import esc

SCRIPT = Path(__file__).resolve().parents[2] / "experiments" / "paper" / "obstacle_avoidance.esc"

out = sys.argv[1] if len(sys.argv) > 1 else "runs/quickstart"
script = esc.compile(SCRIPT, {"epochs": 2, "mu": 5, "lambda": 20})
run = esc.run(script, runs=2, generations=5, controllers=["CC_8_2", "SC_8_6"], out=out,
              progress=lambda g: print(f"{g.controller} run {g.run} generation {g.generation}: best {g.best:.1f}"))
curves = run.table().groupby(["controller", "generation"])["best"].mean().unstack(0)
curves.plot(xlabel="generation", ylabel="best fitness (mean of the runs)", title=run.experiments[0])
plt.savefig(f"{out}/curves.png")
print(curves.tail(1).to_string(), f"\nfigure: {out}/curves.png")
