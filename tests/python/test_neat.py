"""NEAT networks (`neat(...)`, docs/neat.md) from Python: a stored best graph genome evaluated
with its stored evaluation seed scores its stored fitness exactly; graph genomes are a
sequence of 1-D arrays or esc.Network, checked; Env drives a NEAT controller's head, and
Env.policy of a stored network ends an episode at its stored fitness."""

import numpy as np
import pytest

import esc
from conftest import SOURCE, esc_run

NEAT = {"script": SOURCE / "examples" / "neat_obstacle_avoidance.esc", "experiment": "neat_obstacle_avoidance",
        "settings": {"epochs": 1, "steps": 60, "neat.population": 10, "mu": 2, "lambda": 4}}


@pytest.fixture(scope="module")
def neat_run(tmp_path_factory):
    return esc_run(NEAT["script"], tmp_path_factory.mktemp("neat") / "run", NEAT["settings"])


@pytest.fixture(scope="module")
def neat_script():
    return esc.compile(NEAT["script"], NEAT["settings"])


def test_the_script_names_its_neat_controllers(neat_script):
    kinds = {name: c.is_graph for name, c in neat_script.controllers[NEAT["experiment"]].items()}
    assert kinds == {"CC_8_2": False, "CC_8_20_2": False, "NEAT_8_2": True, "NEAT_SC": True}


@pytest.mark.parametrize("controller", ["NEAT_8_2", "NEAT_SC"])
def test_a_stored_best_graph_genome_scores_its_stored_fitness_exactly(neat_run, neat_script, controller):
    run = esc.open(neat_run)
    best = run.best(controller, 1)
    network = run.best_genome(controller, 1)
    flat = run.best_genome(controller, 1, encoded=True)
    for genome in (network, flat):
        fitness = esc.evaluate(neat_script, NEAT["experiment"], controller, [genome], seed=best.evaluation_seed)
        assert fitness[0] == best.fitness


def test_best_genome_of_a_neat_network_is_its_nodes_and_links(neat_run):
    run = esc.open(neat_run)
    network = run.best_genome("NEAT_8_2", 1)
    assert isinstance(network, esc.Network)
    assert list(network.nodes.columns) == ["id", "kind", "activation"]
    assert list(network.links.columns) == ["in", "out", "weight", "enabled", "innovation"]
    kinds = network.nodes["kind"].value_counts().to_dict()
    assert kinds["input"] == 8 and kinds["bias"] == 1 and kinds["output"] == 2
    assert network.nodes.loc[network.nodes["kind"] == "output", "activation"].tolist() == ["tanh", "tanh"]
    assert network.links["innovation"].is_monotonic_increasing
    # Tables and flat form agree both ways, bit for bit.
    flat = run.best_genome("NEAT_8_2", 1, encoded=True)
    assert np.array_equal(network.encoded(), flat)
    assert np.array_equal(esc.Network.decode(flat).encoded(), flat)
    # The export's topology table holds the same links.
    assert network.enabled_links == int(network.links["enabled"].sum())
    # Tables that are no graph genome are refused in the codec's words.
    broken = esc.Network(network.nodes, network.links.assign(out=network.links["out"] + 1000))
    with pytest.raises(ValueError, match="not a graph genome"):
        broken.encoded()
    with pytest.raises(ValueError, match="not a graph genome"):
        esc.Network.decode(np.array([1.0, 2.0, 3.0]))


def test_graph_genomes_are_checked(neat_run, neat_script):
    genome = esc.open(neat_run).best_genome("NEAT_8_2", 1, encoded=True)
    with pytest.raises(ValueError, match="sequence of 1-D arrays"):
        esc.evaluate(neat_script, NEAT["experiment"], "NEAT_8_2", genome[None, :])
    with pytest.raises(ValueError, match="genome 1 is not a graph genome of controller `NEAT_8_2`"):
        esc.evaluate(neat_script, NEAT["experiment"], "NEAT_8_2", [genome, np.array([1.0, 2.0, 3.0])])
    # The classical head's genome has 2 outputs; the symbolic head's network has 6.
    with pytest.raises(ValueError, match="outputs"):
        esc.evaluate(neat_script, NEAT["experiment"], "NEAT_SC", [genome])
    with pytest.raises(ValueError, match=r"\[network\] for one"):
        esc.evaluate(neat_script, NEAT["experiment"], "NEAT_8_2", esc.Network.decode(genome))


def test_env_drives_a_neat_controllers_head(neat_script):
    env = esc.Env(neat_script, NEAT["experiment"], "NEAT_8_2", seed=4)
    observation, info = env.reset()
    assert observation.shape == (8,)
    observation, reward, terminated, truncated, info = env.step(np.array([0.5, 0.5]))
    assert info["step"] == 1
    with pytest.raises(ValueError, match="not a graph genome of `NEAT_8_2`"):
        env.policy(np.zeros(3))


@pytest.mark.parametrize("controller", ["NEAT_8_2", "NEAT_SC"])
def test_env_driven_by_a_stored_neat_network_scores_its_fitness(neat_run, neat_script, controller):
    """Env.policy of a stored best NEAT network (an esc.Network, or its flat form): one
    episode with the best's evaluation seed ends at the stored fitness, bit for bit."""
    run = esc.open(neat_run)
    best = run.best(controller, 1)
    for genome in (run.best_genome(controller, 1), run.best_genome(controller, 1, encoded=True)):
        env = esc.Env(neat_script, NEAT["experiment"], controller, seed=best.evaluation_seed)
        policy = env.policy(genome)
        observation, info = env.reset()
        while True:
            observation, reward, terminated, truncated, info = env.step(policy(observation))
            if terminated or truncated:
                break
        assert info["fitness"] == best.fitness


def test_members_of_neat_networks_under_nsga2_and_map_elites_are_networks(tmp_path):
    """A NEAT network evolved by NSGA-II or MAP-Elites (NEAT's operators, docs/neat.md): its
    final front's and archive's members are esc.Network, each scoring its stored objectives
    exactly when evaluated again with its evaluation seed."""
    script = SOURCE / "tests" / "cli" / "data" / "tiny_neat_selections.esc"
    run = esc.open(esc_run(script, tmp_path / "run", {"generations": 4}))
    compiled = esc.compile(script)
    for controller, kind in (("NC_nsga2", "front"), ("NC_me", "archive")):
        members = run.members(controller, 1)
        assert members and all(m.kind == kind for m in members)
        for m in members[:5]:
            assert isinstance(m.genome, esc.Network)
            assert m.genome.nodes["kind"].tolist().count("input") == 8
            fitness = esc.evaluate(compiled, "selections", controller, [m.genome], seed=m.evaluation_seed)
            assert fitness[0] == m.objectives["avoid"]
    # The topology table holds the same networks: the front's members beside each run's best.
    topology = run.table("topology")
    front = topology[(topology.controller == "NC_nsga2") & (topology.member == "front")]
    assert front.cell.nunique() == len(run.members("NC_nsga2", 1))
    assert set(topology.member) == {"best", "front", "archive"}
