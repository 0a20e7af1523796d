"""esc.evaluate: a stored best genome evaluated with its stored evaluation seed scores its
stored fitness exactly; many genomes at once, on all threads; wrong genomes refused."""

import numpy as np
import pytest

import esc
from conftest import EXPERIMENTS, HOMING, TREES, best_json, esc_run


@pytest.mark.parametrize("controller", ["CC", "SC", "SV"])
def test_a_stored_best_genome_scores_its_stored_fitness_exactly(homing_run, homing_script, controller):
    stored = best_json(homing_run, controller)
    genome = np.array([stored["genome"]])
    fitness = esc.evaluate(homing_script, "homing", controller, genome, seed=int(stored["evaluation_seed"]))
    assert fitness.dtype == np.float64 and fitness.shape == (1,)
    assert fitness[0] == stored["fitness"]


def test_epochs_replaces_the_experiments(homing_run):
    best = esc.open(homing_run).best("SC", 1)
    other = {k: v for k, v in HOMING["settings"].items() if k != "epochs"}
    script = esc.compile(HOMING["script"], other)   # 5 epochs, as the script says
    five = esc.evaluate(script, "homing", "SC", [best.genome], seed=best.evaluation_seed)
    one = esc.evaluate(script, "homing", "SC", [best.genome], epochs=1, seed=best.evaluation_seed)
    assert one[0] == best.fitness
    assert five[0] != best.fitness


def test_trees_are_evaluated_from_their_encoding(tree_run, tree_script):
    run = esc.open(tree_run)
    for controller in ("GW", "GS"):
        best = run.best(controller, 1)
        fitness = esc.evaluate(tree_script, TREES["experiment"], controller,
                               [run.best_genome(controller, 1, encoded=True)], seed=best.evaluation_seed)
        assert fitness[0] == best.fitness
    with pytest.raises(ValueError, match="encoded"):
        esc.evaluate(tree_script, TREES["experiment"], "GW", [run.best_genome("GW", 1)])
    with pytest.raises(ValueError, match="not an encoded tree"):
        esc.evaluate(tree_script, TREES["experiment"], "GW", [np.array([1.0, 2.0, 3.0])])


def test_many_genomes_each_with_its_seed_whatever_the_order(homing_script):
    rng = np.random.default_rng(5)
    genomes = rng.uniform(-1, 1, size=(12, 151))   # SC of homing: 17-5r-6, 151 weights
    seeds = [esc.evaluation_seed(77, 0, i) for i in range(12)]
    fitness = esc.evaluate(homing_script, "homing", "SC", genomes, seed=seeds)
    reversed_ = esc.evaluate(homing_script, "homing", "SC", genomes[::-1], seed=seeds[::-1])
    assert fitness.tolist() == reversed_[::-1].tolist()
    alone = [esc.evaluate(homing_script, "homing", "SC", genomes[i:i + 1], seed=seeds[i])[0] for i in (0, 7)]
    assert alone == [fitness[0], fitness[7]]
    common = esc.evaluate(homing_script, "homing", "SC", genomes[:2].tolist(), seed=3)
    assert common.shape == (2,)


def test_a_wrong_genome_length_names_both_lengths(homing_script):
    with pytest.raises(ValueError, match=r"151 weights.* 10"):
        esc.evaluate(homing_script, "homing", "SC", np.zeros((2, 10)))
    with pytest.raises(ValueError, match="2-D"):
        esc.evaluate(homing_script, "homing", "SC", np.zeros(151))


def test_unknown_names_and_bad_seeds_are_value_errors(homing_script):
    genomes = np.zeros((1, 151))
    with pytest.raises(ValueError, match="did you mean `SC`"):
        esc.evaluate(homing_script, "homing", "SCX", genomes)
    with pytest.raises(ValueError, match="did you mean `homing`"):
        esc.evaluate(homing_script, "homin", "SC", genomes)
    with pytest.raises(ValueError, match="2 seeds for 1 genomes"):
        esc.evaluate(homing_script, "homing", "SC", genomes, seed=[1, 2])
    with pytest.raises(ValueError, match=r"seed=-1: expected an integer in 0\.\.18446744073709551615"):
        esc.evaluate(homing_script, "homing", "SC", genomes, seed=-1)
    with pytest.raises(ValueError, match="epochs=0"):
        esc.evaluate(homing_script, "homing", "SC", genomes, epochs=0)


def test_measure_names_every_objective_and_descriptor_as_the_script_does():
    from conftest import EXPERIMENTS
    rng = np.random.default_rng(3)
    script = esc.compile(EXPERIMENTS / "examples" / "speed_energy.esc")
    genomes = rng.uniform(-1, 1, size=(4, script.controller("speed_energy", "C").genome_size))
    table = esc.measure(script, "speed_energy", "C", genomes, epochs=1, seed=9)
    assert list(table.columns) == ["speed", "effort"]
    assert table["speed"].tolist() == esc.evaluate(script, "speed_energy", "C", genomes, epochs=1, seed=9).tolist()
    assert (table["effort"] >= 0).all(), "a minimised objective as measured, not negated"
    mazes = esc.compile(EXPERIMENTS / "lehman_stanley" / "mazes.esc", {"steps": 40})
    walkers = rng.uniform(-1, 1, size=(3, 67))
    positions = esc.measure(mazes, "medium", "navigator_net", walkers)
    assert list(positions.columns) == ["reach_goal", "final_x", "final_y"]
    assert ((positions[["final_x", "final_y"]] >= 0) & (positions[["final_x", "final_y"]] <= 1.03125)).all().all()


def test_a_group_is_evaluated_and_its_best_scores_its_stored_fitness(tmp_path):
    """experiments/examples/groups.esc: five Kheperas, one genome driving each (docs/groups.md)."""
    settings = {"epochs": 1, "steps": 40, "mu": 2, "lambda": 4}
    script_path = EXPERIMENTS / "examples" / "groups.esc"
    out = esc_run(script_path, tmp_path / "run", settings, "--experiment", "dispersion")
    stored = best_json(out, "cc")
    script = esc.compile(script_path, settings)
    fitness = esc.evaluate(script, "dispersion", "cc", np.array([stored["genome"]]),
                           seed=int(stored["evaluation_seed"]))
    assert fitness[0] == stored["fitness"]
    # Env drives one robot: a group's is refused, saying what to use.
    with pytest.raises(ValueError, match="group of 5 robots"):
        esc.Env(script, "dispersion", "cc")


def test_a_controller_per_body_is_evaluated_and_its_best_scores_its_stored_fitness(tmp_path):
    """experiments/examples/mixed_bodies.esc: Kheperas and Thymio IIs, a network per body."""
    settings = {"epochs": 1, "steps": 40, "mu": 2, "lambda": 4}
    script_path = EXPERIMENTS / "examples" / "mixed_bodies.esc"
    out = esc_run(script_path, tmp_path / "run", settings, "--experiment", "mixed_dispersion")
    script = esc.compile(script_path, settings)
    cc = script.controller("mixed_dispersion", "cc")
    assert cc.architecture == "khepera 8-4-2 / thymio2 7-4-2" and cc.inputs == ()
    assert [body for body, _ in cc.per_body] == ["khepera", "thymio2"]
    assert cc.per_body[0][1] == tuple(f"ir[{i}]" for i in range(8))
    assert cc.per_body[1][1] == tuple(f"prox_horizontal[{i}]" for i in range(7))
    assert cc.genome_size == 46 + 42
    stored = best_json(out, "cc")
    assert len(stored["genome"]) == cc.genome_size
    fitness = esc.evaluate(script, "mixed_dispersion", "cc", np.array([stored["genome"]]),
                           seed=int(stored["evaluation_seed"]))
    assert fitness[0] == stored["fitness"]
