"""esc.ParallelEnv (docs/groups.md): a group stepped with PettingZoo's parallel interface.
Driven by a stored best genome's networks, one copy per robot (ParallelEnv.policies), it
reproduces every robot's rows of `esc replay`'s CSV step for step; errors name the agent."""

import numpy as np
import pandas as pd
import pytest

import esc
from conftest import EXPERIMENTS, HOMING, esc_run, run_esc

SETTINGS = {"epochs": 1, "steps": 40, "mu": 2, "lambda": 4}
GROUPS = EXPERIMENTS / "examples" / "groups.esc"
EXACT = {"x_m": "x", "y_m": "y", "heading_rad": "heading", "left_command": "left_command",
         "right_command": "right_command", "left_speed_mps": "left_speed", "right_speed_mps": "right_speed",
         "centroid_x_m": "centroid_x", "centroid_y_m": "centroid_y", "centroid_moved_m": "centroid_moved",
         "centroid_distance_m": "centroid_distance", "nearest_robot_m": "nearest_robot",
         "robot_distance_m": "robot_distance", "spread_m": "spread"}


@pytest.fixture(scope="module")
def group_runs(tmp_path_factory):
    """The dispersion group's run directory for a number of roles, run once each."""
    runs = {}

    def run(roles):
        if roles not in runs:
            runs[roles] = esc_run(GROUPS, tmp_path_factory.mktemp("group") / "run", {**SETTINGS, "roles": roles},
                                  "--experiment", "dispersion")
        return runs[roles]
    return run


# Three roles of five robots: robots 1 and 4 are role 1's, 2 and 5 role 2's, 3 role 3's.
@pytest.mark.parametrize("controller,roles", [("cc", 1), ("sc", 1), ("cc", 3)])
def test_a_stored_genome_drives_every_robot_as_the_replay_did(group_runs, tmp_path, controller, roles):
    group_run = group_runs(roles)
    run_esc("replay", group_run, "--controller", controller, "--run", 1, "--out", tmp_path)
    csv = pd.read_csv(tmp_path / f"replay-{controller}-run-01.csv", float_precision="round_trip", keep_default_na=False)
    best = esc.open(group_run).best(controller, 1)
    script = esc.compile(GROUPS, {**SETTINGS, "roles": roles})
    assert len(best.genome) == script.controller("dispersion", controller).genome_size
    assert script.controller("dispersion", controller).roles == roles
    env = esc.ParallelEnv(script, "dispersion", controller, seed=best.evaluation_seed)
    assert env.possible_agents == [f"robot_{i}" for i in range(1, 6)] and env.agents == []
    policies = env.policies(best.genome)
    observations, infos = env.reset()
    assert env.agents == env.possible_agents and set(observations) == set(env.agents)
    rows = []
    while env.agents:
        actions = {a: policies[a](observations[a]) for a in env.agents}
        observations, rewards, terminations, truncations, infos = env.step(actions)
        assert set(rewards) == set(actions) and len(set(terminations.values())) == 1
        rows.append(env.state())
    assert len(rows) * 5 == len(csv)
    for i, (_, row) in enumerate(csv.iterrows()):
        state = rows[i // 5][f"robot_{row['robot']}"]
        assert state["step"] == row["step"]
        for column, key in EXACT.items():
            assert state[key] == row[column], (column, row["step"], row["robot"])
        assert state["ir"].tolist() == [row[f"ir{k}"] for k in range(8)]
        assert (env.choices[state["action"]] if state["action"] >= 0 else "") == row["behavior"]
    assert truncations["robot_1"] and env.num_agents == 0


@pytest.mark.parametrize("controller", ["cc", "sc"])
def test_a_controller_per_body_drives_each_robot_with_its_bodys_network(tmp_path, controller):
    """experiments/examples/mixed_bodies.esc: three Kheperas (8 IR) and three Thymio IIs (7),
    a network per body; each agent observes its own body's network's inputs."""
    mixed = EXPERIMENTS / "examples" / "mixed_bodies.esc"
    run = esc_run(mixed, tmp_path / "run", SETTINGS, "--experiment", "mixed_dispersion")
    run_esc("replay", run, "--controller", controller, "--run", 1, "--out", tmp_path)
    csv = pd.read_csv(tmp_path / f"replay-{controller}-run-01.csv", float_precision="round_trip", keep_default_na=False)
    best = esc.open(run).best(controller, 1)
    env = esc.ParallelEnv(esc.compile(mixed, SETTINGS), "mixed_dispersion", controller, seed=best.evaluation_seed)
    assert [env.observation_space(a).shape for a in env.possible_agents] == [(8,)] * 3 + [(7,)] * 3
    assert env.observation_names_of("robot_4") == [f"prox_horizontal[{i}]" for i in range(7)]
    assert env.observation_names_of("robot_1") == [f"ir[{i}]" for i in range(8)]
    with pytest.raises(ValueError, match="give body= one of khepera, thymio2, not epuck"):
        env.policy(best.genome, "epuck")
    policies = env.policies(best.genome)
    observations, _ = env.reset()
    rows = []
    while env.agents:
        observations, _, _, _, _ = env.step({a: policies[a](observations[a]) for a in env.agents})
        rows.append(env.state())
    assert len(rows) * 6 == len(csv)
    for i, (_, row) in enumerate(csv.iterrows()):
        state = rows[i // 6][f"robot_{row['robot']}"]
        for column, key in EXACT.items():
            assert state[key] == row[column], (column, row["step"], row["robot"])


def test_a_genome_holds_every_roles_weights():
    script = esc.compile(GROUPS, {**SETTINGS, "roles": 5})
    c = script.controller("dispersion", "cc")
    assert c.roles == 5
    one = c.genome_size // 5
    with pytest.raises(ValueError, match=f"holds its 5 roles' weights, {c.genome_size} in all"):
        esc.ParallelEnv(script, "dispersion", "cc", seed=1).policies(np.zeros(one))
    with pytest.raises(ValueError, match=f"has genomes of {c.genome_size} weights \\(5 roles of {one}\\)"):
        esc.evaluate(script, "dispersion", "cc", np.zeros((1, one)))
    # Five equal roles are the clonal team; five different ones are not.
    weights = np.random.default_rng(4).uniform(-1, 1, (5, one))
    clonal = esc.evaluate(esc.compile(GROUPS, SETTINGS), "dispersion", "cc", weights[:1], seed=9)
    assert esc.evaluate(script, "dispersion", "cc", np.tile(weights[0], 5)[None], seed=9)[0] == clonal[0]
    assert esc.evaluate(script, "dispersion", "cc", weights.reshape(1, -1), seed=9)[0] != clonal[0]
    # Settings apply together, as `esc run --set` applies them: six roles of six robots is one change.
    assert esc.compile(GROUPS, {"roles": 6, "robots": 6}).controller("dispersion", "cc").roles == 6
    with pytest.raises(esc.Error, match="7 roles need at least 7 robots, and the group has 6"):
        esc.compile(GROUPS, {"roles": 7, "robots": 6})


def test_rewards_are_each_robots_step_term_and_errors_name_the_agent():
    script = esc.compile(GROUPS, SETTINGS)
    env = esc.ParallelEnv(script, "aggregation", seed=3)
    assert env.observation_space("robot_2").shape == (17,) and env.action_space("robot_5").shape == (2,)
    with pytest.raises(ValueError, match="robot_6"):
        env.action_space("robot_6")
    with pytest.raises(RuntimeError, match="reset"):
        env.step({a: [0.5, 0.5] for a in env.possible_agents})
    env.reset()
    with pytest.raises(ValueError, match="no action for robot_5"):
        env.step({a: [0.5, 0.5] for a in env.possible_agents[:4]})
    with pytest.raises(ValueError, match="not an agent"):
        env.step({**{a: [0.5, 0.5] for a in env.possible_agents}, "robot_0": [0, 0]})
    with pytest.raises(ValueError, match=r"actions\['robot_3'\]\[1\] is nan"):
        env.step({a: [0.5, np.nan if a == "robot_3" else 0.5] for a in env.possible_agents})
    before = env.state("robot_1")
    with pytest.raises(ValueError, match="robot 2's action is 2 values"):
        env.step({a: [0.5] * (3 if a == "robot_2" else 2) for a in env.possible_agents})
    assert env.state("robot_1")["left_command"] == before["left_command"], "a refused step changes nothing"
    # Every group observable is the replay's, whatever the fitness reads (aggregation reads no pair).
    assert env.state("robot_1")["nearest_robot"] > 0 and env.state("robot_1")["robot_distance"] > 0
    _, rewards, _, _, infos = env.step({a: [1.0, 1.0] for a in env.possible_agents})
    assert all(r == 0.0 for r in rewards.values())   # aggregation's step term is 0: its epoch term counts
    assert infos["robot_4"]["step"] == 1
    # Env drives a robot alone; a robot alone is a ParallelEnv of one.
    with pytest.raises(ValueError, match="esc.ParallelEnv"):
        esc.Env(script, "aggregation")
    alone = esc.ParallelEnv(esc.compile(HOMING["script"], HOMING["settings"]), HOMING["experiment"], seed=1)
    assert alone.possible_agents == ["robot_1"]
