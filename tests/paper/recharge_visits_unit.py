"""visits_of (scripts/recharge-visits.py) on steps made up for it: a visit left full, one left
early, one an epoch ends in, an epoch that empties, the still and `stop` counts, the last exit
of the one epoch finished outside the area."""
import importlib.util
import pathlib
import sys

root = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(root / "scripts"))
spec = importlib.util.spec_from_file_location("recharge_visits", root / "scripts" / "recharge-visits.py")
rv = importlib.util.module_from_spec(spec)
spec.loader.exec_module(rv)


def steps(epoch, energies, xs, behaviors=None):
    return [{"epoch": str(epoch), "energy": str(e), "x_m": str(x), "y_m": "0.5",
             "behavior": (behaviors or [""] * len(energies))[i]} for i, (e, x) in enumerate(zip(energies, xs))]


rows = (
    # Out (falls), in (rises to full, holds there standing still under `stop`), out again.
    steps(1, [0.99, 0.98, 0.99, 1.0, 1.0, 0.99], [0.10, 0.11, 0.12, 0.12, 0.12, 0.13],
          ["sweep", "sweep", "stop", "stop", "stop", "sweep"])
    # Out, in and left at 0.6 (not full); in again when the epoch ends.
    + steps(2, [0.5, 0.6, 0.59, 0.6], [0.3, 0.31, 0.32, 0.33])
    # Emptied.
    + steps(3, [0.01, 0.0], [0.4, 0.41]))
f = rv.visits_of(rows, 10.0)   # a full accumulator lasts 10 steps
expected = {"epochs": 3, "steps": [6, 4, 2], "left": 2, "left_full": 1, "ended_in": 1, "left_levels": [1.0, 0.6],
            "in_steps": 5, "still": 2, "stop": 3, "empty": 1,
            # Epoch 1 is left full at its 6th step, 1 step before its end: 0.1 needed.
            "last_exits": [(1.0, 0.1)]}
for key, value in expected.items():
    if f[key] != value:
        sys.exit(f"{key}: {f[key]} (expected {value}); all: {f}")
print("ok", f)
