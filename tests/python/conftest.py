"""Shared set-up of the Python module's tests: the esc program built beside the module ($ESC)
and tiny run directories made by it, one per script, once per test file."""

import json
import os
import subprocess
from pathlib import Path

import pytest

import esc

SOURCE = Path(os.environ.get("ESC_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXPERIMENTS = SOURCE / "experiments"

# Tiny runs: one run of two generations of one short epoch, each setting both given to
# `esc run --set` and to esc.compile, so that the script compiled here is the run's.
HOMING = {"script": EXPERIMENTS / "examples" / "homing.esc", "experiment": "homing",
          "settings": {"epochs": 1, "steps": 200, "mu": 3, "lambda": 6}}
TREES = {"script": EXPERIMENTS / "gp" / "obstacle_avoidance_gp.esc", "experiment": "obstacle_avoidance_gp",
         "settings": {"epochs": 1, "steps": 60, "gp.population": 8, "mu": 2, "lambda": 4}}
# A study of two conditions of experiments/examples/quick_start.esc, found in the standard library.
STUDY_TEXT = """import "examples/quick_start.esc"

study tiny {
  condition inertia_on = quick_start { robot.inertia on }
  condition inertia_off = quick_start { robot.inertia off }
  runs 1
  seed 3
}
"""
STUDY_SETTINGS = {"epochs": 1, "mu": 2, "lambda": 4}


def esc_program() -> str:
    """The esc program of this build, or a skip when the tests run without one."""
    program = os.environ.get("ESC")
    if not program:
        pytest.skip("$ESC (the esc program built with the module) is not set")
    return program


def run_esc(*args, **kwargs) -> subprocess.CompletedProcess:
    """esc with `args`, its output captured; raises on a non-zero exit unless check=False."""
    kwargs.setdefault("check", True)
    return subprocess.run([esc_program(), *map(str, args)], capture_output=True, text=True, **kwargs)


def esc_run(script, out: Path, settings: dict, *extra) -> Path:
    """`esc run SCRIPT --runs 1 --generations 2 --set K=V ... --out OUT`."""
    sets = [a for k, v in settings.items() for a in ("--set", f"{k}={v}")]
    run_esc("run", script, "--runs", 1, "--generations", 2, "--threads", 2, *sets, *extra, "--out", out)
    return out


def best_json(directory: Path, controller: str, run: int = 1) -> dict:
    """CONTROLLER/run-NN.best.json of a run directory."""
    return json.loads((directory / controller / f"run-{run:02}.best.json").read_text())


@pytest.fixture(scope="session")
def homing_run(tmp_path_factory) -> Path:
    """A run of the homing experiment: Elman networks, classical, symbolic and supervisor."""
    return esc_run(HOMING["script"], tmp_path_factory.mktemp("homing") / "run", HOMING["settings"])


@pytest.fixture(scope="session")
def homing_script() -> esc.Script:
    return esc.compile(HOMING["script"], HOMING["settings"])


@pytest.fixture(scope="session")
def tree_run(tmp_path_factory) -> Path:
    """A run of GP trees: a Wheels tree (GW) and an Action tree (GS)."""
    return esc_run(TREES["script"], tmp_path_factory.mktemp("trees") / "run", TREES["settings"])


@pytest.fixture(scope="session")
def tree_script() -> esc.Script:
    return esc.compile(TREES["script"], TREES["settings"])


@pytest.fixture(scope="session")
def study_run(tmp_path_factory) -> Path:
    """A study's directory: two conditions."""
    where = tmp_path_factory.mktemp("study")
    script = where / "tiny_study.esc"
    script.write_text(STUDY_TEXT)
    return esc_run(script, where / "run", STUDY_SETTINGS)
