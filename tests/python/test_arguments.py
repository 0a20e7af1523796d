"""Arguments checked as the esc program checks its options: the command line's own ranges, a
TypeError or ValueError naming the argument, the value and what is accepted, and nothing run
or written for a refused one; genomes and actions real and finite; experiment=None for a
script's one experiment; a script not found as given looked up as an import is."""

import os
import re

import numpy as np
import pytest

import esc
from conftest import EXPERIMENTS, HOMING, TREES, run_esc

GENOMES = np.zeros((2, 151))


def test_the_ranges_are_the_command_lines(tmp_path):
    assert esc._esc.limits["threads"] == (0, 4096)
    assert esc._esc.limits["runs"] == esc._esc.limits["generations"] == (1, 10 ** 9)
    assert esc._esc.limits["seed"] == (0, 2 ** 64 - 1)
    for value in (-1, 4097):   # the same numbers refused by esc run (exit 2: the command line)
        refused = run_esc("run", HOMING["script"], "--threads", value, "--out", tmp_path / "cli", check=False)
        assert refused.returncode == 2 and f"Value {value} not in range 0 to 4096" in refused.stderr
    for value in (0, 10 ** 9 + 1):
        refused = run_esc("run", HOMING["script"], "--runs", value, "--out", tmp_path / "cli", check=False)
        assert refused.returncode == 2
    assert not (tmp_path / "cli").exists()


@pytest.mark.parametrize("given, error, message", [
    ({"threads": -5}, ValueError, "threads=-5: expected an integer in 0..4096"),
    ({"threads": 5000}, ValueError, "threads=5000: expected an integer in 0..4096"),
    ({"threads": 2.0}, TypeError, "threads=2.0: expected an integer in 0..4096"),
    ({"threads": True}, TypeError, "threads=True: expected an integer"),
    ({"runs": 0}, ValueError, "runs=0: expected an integer in 1..1000000000"),
    ({"runs": False}, TypeError, "runs=False"),
    ({"generations": 10 ** 9 + 1}, ValueError, "generations=1000000001: expected an integer in 1..1000000000"),
    ({"generations": "3"}, TypeError, "generations='3'"),
    ({"seed": -1}, ValueError, "seed=-1: expected an integer in 0..18446744073709551615"),
    ({"seed": 2 ** 64}, ValueError, "seed=18446744073709551616"),
    ({"seed": 1.5}, TypeError, "seed=1.5"),
])
def test_run_refuses_what_esc_run_refuses_before_writing(tmp_path, given, error, message):
    with pytest.raises(error, match=re.escape(message)):
        esc.run(HOMING["script"], out=tmp_path / "never", **given)
    assert not (tmp_path / "never").exists()


def test_resume_checks_its_arguments_too(tmp_path):
    with pytest.raises(ValueError, match=re.escape("threads=5000: expected an integer in 0..4096")):
        esc.resume(tmp_path / "nowhere", threads=5000)
    with pytest.raises(TypeError, match=re.escape("generations=2.5")):
        esc.resume(tmp_path / "nowhere", generations=2.5)


def test_evaluate_checks_epochs_and_seeds(homing_script):
    with pytest.raises(TypeError, match=re.escape("epochs=2.5: expected an integer in 1..2147483647")):
        esc.evaluate(homing_script, "homing", "SC", GENOMES, epochs=2.5)
    with pytest.raises(TypeError, match="epochs=True"):
        esc.evaluate(homing_script, "homing", "SC", GENOMES, epochs=True)
    with pytest.raises(ValueError, match=re.escape("epochs=0: expected an integer in 1..2147483647")):
        esc.measure(homing_script, "homing", "SC", GENOMES, epochs=0)
    with pytest.raises(TypeError, match=re.escape("seed=1.5: expected an integer in 0..18446744073709551615")):
        esc.evaluate(homing_script, "homing", "SC", GENOMES, seed=1.5)
    with pytest.raises(TypeError, match="seed=True"):
        esc.evaluate(homing_script, "homing", "SC", GENOMES, seed=True)
    with pytest.raises(ValueError, match=re.escape("seed[1]=-1: expected an integer in 0..18446744073709551615")):
        esc.evaluate(homing_script, "homing", "SC", GENOMES, seed=[3, -1])
    with pytest.raises(TypeError, match=re.escape("seed[0]=3.0")):
        esc.evaluate(homing_script, "homing", "SC", GENOMES, seed=np.array([3.0, 4.0]))
    assert esc.evaluate(homing_script, "homing", "SC", GENOMES, seed=np.uint64(2 ** 64 - 1)).shape == (2,)


def test_genomes_are_real_and_finite(homing_script, tree_script):
    for bad, where in ((np.nan, "genomes[1][17] is nan"), (np.inf, "genomes[1][17] is inf"),
                       (-np.inf, "genomes[1][17] is -inf")):
        genomes = GENOMES.copy()
        genomes[1, 17] = bad
        with pytest.raises(ValueError, match=re.escape(where + ": expected a finite number")):
            esc.evaluate(homing_script, "homing", "SC", genomes)
    with pytest.raises(TypeError, match="genomes: expected real numbers, got an array of complex128"):
        esc.evaluate(homing_script, "homing", "SC", GENOMES + 1j)
    with pytest.raises(TypeError, match="expected real numbers"):
        esc.measure(homing_script, "homing", "SC", [["a"] * 151])
    trees = [np.array([0.0, 1.0]), np.array([np.nan])]
    with pytest.raises(ValueError, match=re.escape("genomes[1][0] is nan")):
        esc.evaluate(tree_script, TREES["experiment"], "GW", trees)


def test_env_checks_seeds_and_actions(homing_script):
    with pytest.raises(ValueError, match=re.escape("seed=18446744073709551616: expected an integer in 0..")):
        esc.Env(homing_script, "homing", seed=2 ** 64)
    env = esc.Env(homing_script, "homing", "SC", seed=1)
    with pytest.raises(ValueError, match=re.escape("seed=-1: expected an integer in 0..")):
        env.reset(seed=-1)
    with pytest.raises(TypeError, match=re.escape("seed=1.5")):
        env.reset(seed=1.5)
    env.reset()
    with pytest.raises(TypeError, match="action: expected real numbers, got an array of <U1"):
        env.step(["a", "b", "c", "d", "e", "f"])
    with pytest.raises(TypeError, match="action: expected real numbers"):
        env.step(np.zeros(6, dtype=complex))
    action = np.zeros(6)
    action[4] = np.nan
    with pytest.raises(ValueError, match=re.escape("action[4] is nan: expected a finite number")):
        env.step(action)
    assert env.episode == 1 and env.state()["step"] == 0, "a refused action is not stepped"
    genome = np.zeros(151)
    genome[150] = np.inf
    with pytest.raises(ValueError, match=re.escape("genome[150] is inf")):
        env.policy(genome)


def test_experiment_none_is_the_scripts_one_experiment(homing_script):
    genomes = np.random.default_rng(1).uniform(-1, 1, (2, 151))
    named = esc.evaluate(homing_script, "homing", "SC", genomes, seed=5)
    assert esc.evaluate(homing_script, None, "SC", genomes, seed=5).tolist() == named.tolist()
    assert esc.Env(homing_script, controller="SC").experiment == "homing"
    assert homing_script.controller(None, "SC").genome_size == 151
    mazes = esc.compile(EXPERIMENTS / "lehman_stanley" / "mazes.esc")
    with pytest.raises(ValueError, match=r"experiment=None: .*mazes.esc declares 4 experiments \(`medium`, `hard`, `medium_neat`, `hard_neat`\)"):
        esc.Env(mazes)
    with pytest.raises(TypeError, match="experiment=3"):
        esc.evaluate(homing_script, 3, "SC", genomes)


def test_a_run_that_does_not_exist_is_not_one_unfinished(homing_run):
    run = esc.open(homing_run)
    for number in (0, 2):
        with pytest.raises(ValueError, match=re.escape(f"run={number}: expected an integer in 1..1")):
            run.members("CC", number)
        with pytest.raises(ValueError, match=re.escape(f"run={number}: expected an integer in 1..1")):
            run.best("CC", number)
    with pytest.raises(TypeError, match="run='1'"):
        run.best_genome("CC", "1")


def test_a_directory_is_no_script(tmp_path):
    with pytest.raises(IsADirectoryError):
        esc.compile(str(tmp_path))
    with pytest.raises(IsADirectoryError):
        esc.compile(tmp_path)
    with pytest.raises(TypeError, match="path_or_source=3"):
        esc.compile(3)


def test_a_script_not_found_as_given_is_looked_up_as_an_import(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    shipped = esc.compile("paper/obstacle_avoidance.esc")   # the standard library's
    assert os.path.samefile(shipped.file, EXPERIMENTS / "paper" / "obstacle_avoidance.esc")
    assert shipped.experiments[0] == "obstacle_avoidance"
    mine = tmp_path / "mine" / "paper"
    mine.mkdir(parents=True)
    (mine / "obstacle_avoidance.esc").write_text('import "examples/quick_start.esc"\n'
                                                 'study s {\n  condition a = quick_start { robot.inertia on }\n}\n')
    monkeypatch.setenv("ESC_PATH", str(tmp_path / "mine"))
    assert esc.compile("paper/obstacle_avoidance.esc").file == str(mine / "obstacle_avoidance.esc")   # ESC_PATH first
    checked = run_esc("check", "paper/obstacle_avoidance.esc", "examples/homing.esc").stdout.splitlines()
    assert checked[0] == f"{mine / 'obstacle_avoidance.esc'}: ok (0 experiments; 1 study: s (1 condition))"
    library_file, said = checked[1].split(": ", 1)   # the program's own library, found the same way
    assert os.path.samefile(library_file, EXPERIMENTS / "examples" / "homing.esc")
    assert said == "ok (1 experiment: homing)"
    with pytest.raises(FileNotFoundError):
        esc.compile("paper/absent.esc")


def test_progress_is_told_of_a_generation_once_stored_and_its_exception_keeps_it(tmp_path):
    out = tmp_path / "stopped"
    told = []

    class Enough(Exception):
        pass

    def progress(g):
        stored = esc.open(out).table()
        told.append((g.controller, g.generation))
        assert ((stored.controller == g.controller) & (stored.generation == g.generation)).any()
        if len(told) == 3:
            raise Enough()

    with pytest.raises(Enough):
        esc.run(HOMING["script"], runs=1, generations=3, threads=2, set=HOMING["settings"], out=out, progress=progress)
    stored = esc.open(out).table()
    assert set(told) <= set(zip(stored.controller, stored.generation)), "the generation told of was stored"
    whole = esc.run(HOMING["script"], runs=1, generations=3, threads=2, set=HOMING["settings"], out=tmp_path / "whole")
    columns = ["controller", "run", "generation", "best", "mean"]
    assert esc.resume(out).table()[columns].equals(whole.table()[columns])


def test_an_existing_output_directory_is_refused_in_pythons_words(tmp_path):
    (tmp_path / "taken").mkdir()
    (tmp_path / "taken" / "notes.txt").write_text("mine")
    with pytest.raises(esc.Error) as caught:
        esc.run(HOMING["script"], runs=1, generations=1, set=HOMING["settings"], out=tmp_path / "taken")
    assert caught.value.kind == "results"
    assert "choose another output directory" in str(caught.value) and "--out" not in str(caught.value)
    assert os.listdir(tmp_path / "taken") == ["notes.txt"]
