"""esc.Env: driven by a stored best genome's network (Env.policy), it reproduces the CSV of
`esc replay` step for step; episodes are the epochs of esc's evaluation; errors."""

import numpy as np
import pandas as pd
import pytest

import esc
from conftest import HOMING, SOURCE, TREES, run_esc

# The replay CSV's columns that Env.state() gives, all compared exactly (the CSV writes 17
# significant digits, read back with pandas' round-trip parser).
EXACT = {"x_m": "x", "y_m": "y", "heading_rad": "heading", "left_command": "left_command",
         "right_command": "right_command", "left_speed_mps": "left_speed", "right_speed_mps": "right_speed",
         "energy": "energy", "fitness": "fitness"}


def episode(env: esc.Env, policy) -> list:
    """One episode driven by `policy`: per step, Env's state and what step() returned."""
    steps = []
    observation, info = env.reset()
    assert info["step"] == 0
    while True:
        observation, reward, terminated, truncated, info = env.step(policy(observation))
        steps.append((env.state(), reward, terminated, truncated, info))
        if terminated or truncated:
            return steps


@pytest.mark.parametrize("controller", ["CC", "SC", "SV"])
def test_a_stored_genome_in_env_reproduces_the_replay_csv(homing_run, homing_script, tmp_path, controller):
    run_esc("replay", homing_run, "--controller", controller, "--run", 1, "--epochs", 1, "--out", tmp_path)
    csv = pd.read_csv(tmp_path / f"replay-{controller}-run-01.csv", float_precision="round_trip",
                      keep_default_na=False)
    best = esc.open(homing_run).best(controller, 1)
    env = esc.Env(homing_script, "homing", controller, seed=best.evaluation_seed)
    steps = episode(env, env.policy(best.genome))
    assert len(steps) == len(csv)
    for (state, reward, terminated, truncated, info), (_, row) in zip(steps, csv.iterrows()):
        assert (info["epoch"] + 1, info["step"]) == (row["epoch"], row["step"])
        for column, key in EXACT.items():
            assert state[key] == row[column], (column, row["step"])
        assert state["ir"].tolist() == [row[f"ir{i}"] for i in range(8)]
        assert state["light"].tolist() == [row[f"light{i}"] for i in range(8)]
        assert state["range"].size == 0 and state["radar"].size == 0   # the Khepera's own senses
        assert int(state["collided"]) == row["collided"]
        assert (env.choices[info["action"]] if info["action"] >= 0 else "") == row["behavior"]
        assert row["time_s"] == pytest.approx(info["step"] * 0.1)
    state, _, terminated, truncated, info = steps[-1]
    assert info["fitness"] == best.fitness   # one epoch: the episode's rewards are the fitness
    assert terminated != truncated and truncated == (len(steps) == env.steps)


def test_episodes_are_the_epochs_of_an_evaluation(homing_run):
    """Two episodes' rewards, summed in order, are the fitness of a two-epoch evaluation with
    the same seed: the same start poses, noise and network state reset per epoch."""
    script = esc.compile(HOMING["script"], dict(HOMING["settings"], epochs=2))
    best = esc.open(homing_run).best("SC", 1)
    env = esc.Env(script, "homing", "SC", seed=best.evaluation_seed)
    policy = env.policy(best.genome)
    total = 0.0
    for k in range(2):
        for _, reward, _, _, info in episode(env, policy):
            assert info["epoch"] == k
            total += reward
    assert env.episode == 2
    assert total == esc.evaluate(script, "homing", "SC", [best.genome], seed=best.evaluation_seed)[0]
    first, _ = env.reset(seed=best.evaluation_seed)   # a seed starts again from its first epoch
    again, info = esc.Env(script, "homing", "SC", seed=best.evaluation_seed).reset()
    assert first.tolist() == again.tolist() and info["epoch"] == 0


def test_spaces_without_and_with_a_controller(homing_script):
    env = esc.Env(homing_script, "homing", seed=1)
    assert env.observation_names == [f"ir[{i}]" for i in range(8)] + [f"light[{i}]" for i in range(8)] + ["energy"]
    assert env.observation_space.shape == (17,) and env.action_space.shape == (2,)
    assert env.action_space.low.tolist() == [-1, -1] and env.action_space.high.tolist() == [1, 1]
    observation, info = env.reset()
    assert env.observation_space.contains(observation)
    observation, reward, terminated, truncated, info = env.step(np.array([0.5, 0.5]))
    assert isinstance(reward, float) and info["action"] == -1 and env.state()["left_command"] == 0.5
    sc = esc.Env(homing_script, "homing", "SC", seed=1)
    assert sc.action_space.shape == (6,) and sc.action_space.low.tolist() == [0] * 6
    assert sc.choices == ["forward", "left", "right"]
    assert esc.Env(homing_script, "homing", "SV").action_space.shape == (4,)


def test_the_navigators_rangefinders_and_radars_are_observations_in_0_1():
    script = esc.compile(SOURCE / "examples" / "maze.esc")
    env = esc.Env(script, "maze_navigation", "navigator_net", seed=1)
    assert env.observation_names == [f"range[{i}]" for i in range(6)] + [f"radar[{i}]" for i in range(4)]
    assert env.observation_space.low.tolist() == [0] * 10 and env.observation_space.high.tolist() == [1] * 10
    observation, _ = env.reset()
    assert env.observation_space.contains(observation)
    assert observation[6:].sum() == 1   # the goal lies in exactly one radar slice
    for _ in range(30):
        observation, *_ = env.step([1.0, 0.6])
        assert env.observation_space.contains(observation)
        state = env.state()
        assert state["range"].tolist() == observation[:6].tolist()
        assert state["radar"].tolist() == observation[6:].tolist()
    bare = esc.Env(script, "maze_navigation", seed=1)   # its senses: the navigator's too
    assert bare.observation_names == ([f"ir[{i}]" for i in range(8)] + [f"light[{i}]" for i in range(8)] +
                                      [f"range[{i}]" for i in range(6)] + [f"radar[{i}]" for i in range(4)] +
                                      ["energy"])
    observation, _ = bare.reset()
    assert observation[16:22].tolist() == bare.state()["range"].tolist()


def test_driving_the_wheels_by_hand_ends_by_truncation():
    script = esc.compile(TREES["script"], TREES["settings"])
    env = esc.Env(script, TREES["experiment"], seed=2)
    env.reset()
    steps = 0
    while True:
        _, _, terminated, truncated, _ = env.step([0.0, 0.0])   # standing still: never collides
        steps += 1
        if terminated or truncated:
            break
    assert (steps, truncated, terminated) == (env.steps, True, False)
    with pytest.raises(RuntimeError, match="reset"):
        env.step([0.0, 0.0])


def test_wrong_uses_are_errors(homing_script, homing_run):
    env = esc.Env(homing_script, "homing", "SC", seed=1)
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.zeros(6))
    env.reset()
    with pytest.raises(ValueError, match="6 values"):
        env.step(np.zeros(2))
    with pytest.raises(ValueError, match="151 weights.* 3"):
        env.policy(np.zeros(3))
    with pytest.raises(ValueError, match="no controller"):
        esc.Env(homing_script, "homing").policy(np.zeros(151))
    with pytest.raises(ValueError, match="did you mean `SC`"):
        esc.Env(homing_script, "homing", "SCX")
    trees = esc.compile(TREES["script"], TREES["settings"])
    with pytest.raises(ValueError, match="tree controller"):
        esc.Env(trees, TREES["experiment"], "GW")


def test_the_observation_is_the_robots_own_senses_by_its_names():
    """Without a controller an observation is what the body declares, named as its scripts
    read it: the e-puck's eight `prox` sensors, their light, the accumulator; the navigator's
    rangefinders and radars, no IR."""
    from conftest import EXPERIMENTS
    puck = esc.Env(EXPERIMENTS / "bodies" / "epuck_obstacle_avoidance.esc", "epuck_obstacle_avoidance", seed=1)
    names = puck.observation_names
    assert names[:8] == [f"prox[{i}]" for i in range(8)]
    assert names[8:] == [f"light[{i}]" for i in range(8)] + ["energy"]
    observation, _ = puck.reset()
    assert observation.shape == (17,)
    script = esc.compile(EXPERIMENTS / "bodies" / "epuck_obstacle_avoidance.esc")
    assert script.controllers["epuck_obstacle_avoidance"]["CC_8_20_2"].inputs == tuple(f"prox[{i}]" for i in range(8))
    nav = esc.Env('import "lib/navigator.esc"\n'
                  "arena m { size 1m x 60cm  goal at (90cm, 50cm)  start at (10cm, 10cm) }\n"
                  "fitness near { step: 0  epoch: -goal_distance }\n"
                  "controller N = mlp(range[0..5], radar[0..3] -> wheels)\n"
                  "experiment e { arena m  robot navigator  fitness near  compare N }\n", seed=1)
    assert nav.observation_names == [f"range[{i}]" for i in range(6)] + [f"radar[{i}]" for i in range(4)] + ["energy"]
    # The Thymio II's seven horizontal sensors and its two ground sensors, by their Aseba names,
    # 1 over the visible mark the robot starts on; a bumper added, 0 away from the walls.
    thymio = esc.Env('import "lib/thymio2.esc"\n'
                     "robot grounded = thymio2 { bumpers [(-45deg, 45deg)] }\n"
                     "arena m { size 1m x 1m  zone mark rect 10cm x 20cm at (60cm, 50cm) visible\n"
                     "  start at (50cm, 50cm) heading 0deg }\n"
                     "fitness f { step: speed }\n"
                     "controller C = mlp(prox_horizontal[0..6], prox_ground[0..1] -> wheels)\n"
                     "experiment e { arena m  robot grounded  fitness f  compare C }\n", seed=1)
    names = thymio.observation_names
    assert names[:7] == [f"prox_horizontal[{i}]" for i in range(7)]
    assert names[-4:] == ["prox_ground[0]", "prox_ground[1]", "bumper[0]", "energy"]
    observation, _ = thymio.reset()
    assert observation.shape == (7 + 7 + 2 + 1 + 1,)
    assert list(observation[-4:-1]) == [1.0, 1.0, 0.0]
    state = thymio.state()
    assert list(state["ground_sensor"]) == [1.0, 1.0]   # both over the mark at the start
    assert list(state["bumper"]) == [0.0]
