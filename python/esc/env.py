"""esc.Env: an experiment's epochs stepped one control step at a time, with Gymnasium's
interface (reset, step, observation_space, action_space) but without the gymnasium package."""

import secrets
from dataclasses import dataclass
from typing import Optional, Tuple, Union

import numpy as np

from esc import _arguments as arguments
from esc import _esc
from esc.network import Network
from esc.script import PathOrSource, Script, as_script


@dataclass(frozen=True, eq=False)
class Box:
    """A space of float64 vectors with bounds per entry, as gymnasium.spaces.Box: `shape`,
    `low`, `high` (numpy arrays; an infinite bound where the value is unbounded)."""

    low: np.ndarray
    high: np.ndarray

    @property
    def shape(self) -> Tuple[int, ...]:
        """The vectors' shape: (n,)."""
        return self.low.shape

    @property
    def dtype(self) -> np.dtype:
        """float64."""
        return self.low.dtype

    def contains(self, x) -> bool:
        """Whether `x` has the space's shape and lies within its bounds."""
        a = np.asarray(x, dtype=np.float64)
        return a.shape == self.shape and bool(np.all(a >= self.low) and np.all(a <= self.high))

    def __repr__(self) -> str:
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, float64)"


class _Episodes:
    """What Env and ParallelEnv share: an experiment's epochs as episodes of a seed, the
    controller, the names of an observation's entries, and policies from genomes."""

    def __init__(self, script: Union[Script, PathOrSource], experiment: Optional[str],
                 controller: Optional[str], seed: Optional[int], group: bool):
        self._script = as_script(script)
        self.experiment = self._script.experiment_named(experiment)
        self.controller = controller
        self._env = _esc.Env(self._script._compiled, self.experiment, controller,
                             secrets.randbits(64) if seed is None else arguments.option("seed", seed))
        if self._env.robots > 1 and not group:
            raise ValueError(f"experiment `{self.experiment}` has a group of {self._env.robots} robots: Env drives a "
                             "robot alone; step the group with esc.ParallelEnv (PettingZoo's parallel API), or "
                             "evaluate it with esc.evaluate")
        self._observations = Box(*self._env.observation_bounds())
        self._actions = Box(*self._env.action_bounds)

    @property
    def seed(self) -> int:
        """The evaluation seed of the episodes: episode k is epoch k of its evaluation."""
        return self._env.seed

    @property
    def observation_names(self) -> list:
        """What each entry of an observation is, by observable name ("ir[0]", "energy"); in a
        group whose bodies read other sensors, robot_1's (ParallelEnv.observation_names_of)."""
        return list(self._env.observation_names())

    @property
    def choices(self) -> list:
        """The controller's actions or behaviors (info["action"] indexes them); [] without."""
        return list(self._env.choices)

    @property
    def steps(self) -> int:
        """The control steps of an epoch: an episode is truncated after them."""
        return self._env.steps

    @property
    def epochs(self) -> int:
        """The epochs of one of esc's evaluations in this experiment: episodes 0 to epochs-1
        after a seed are that evaluation (later ones go on with epochs beyond it)."""
        return self._env.epochs

    @property
    def episode(self) -> int:
        """Episodes begun so far (reset() calls)."""
        return self._env.episodes

    def policy(self, genome, body: Optional[str] = None) -> "Policy":
        """The network of `controller` with weights `genome` as a policy for this Env:
        policy(observation) -> action. Its recurrent state (an Elman network's, a NEAT
        network's) starts afresh with every episode of this Env, as the network's does with
        every epoch in esc. For a NEAT network, `genome` is an esc.Network or its flat form.
        `genome` is checked as esc.evaluate checks a genome (real, finite numbers). For a
        controller per body, `genome` is the whole genome and the policy `body`'s network (by
        default the first robot's body)."""
        if self.controller is None:
            raise ValueError("this Env has no controller: its policy would be a network of which controller? "
                             "Make the Env with controller=NAME")
        if isinstance(genome, Network):
            genome = genome.encoded()
        if body is not None and not isinstance(body, str):
            raise TypeError(f"body: expected a body's name (str), got {type(body).__name__}")
        if body is None and self._script.controller(self.experiment, self.controller).per_body:
            body = self._script.bodies[self.experiment][0].name
        return Policy(self, _esc.Policy(self._script._compiled, self.experiment, self.controller,
                                        arguments.finite("genome", genome), body))

    def close(self) -> None:
        """Nothing to release (Gymnasium's interface)."""


class Env(_Episodes):
    """One experiment's epochs as episodes, stepped from Python like a Gymnasium environment.

    Episode k after reset(seed=S) (or after construction with seed S) is epoch k of esc's
    evaluation with evaluation seed S: the same start pose, zones, noise and `epoch`
    observable (esc.evaluate's `seed`). An episode ends when one of the fitness's stop
    conditions fires (or the accumulator runs empty): terminated; or after the experiment's
    steps per epoch: truncated. The reward of a step is the fitness's per-step term;
    info["fitness"] sums them over the episode as esc does (epoch and evaluation end terms,
    which need the whole epoch, are not in the rewards: esc.evaluate gives the whole fitness).

    Without `controller`, an action is the two wheel commands (left, right) in [-1, 1] and an
    observation the robot's senses: its IR sensors as its scripts name them (ir[0..7], the
    e-puck's prox[0..7]), as many light[i], the rangefinders range[i] and goal radars radar[i]
    the robot declares (the maze navigator's), and energy (observation_names).
    With a network controller, an observation is its network's inputs and an action its
    network's activated outputs, which its head turns into wheel commands as in a run: two
    commands (classical), one score per action then the actions' parameters (symbolic: the
    highest score acts), one score per behavior (supervisor). policy(genome) computes them
    from a genome, so driving Env with it replays esc's evaluation of that genome step for
    step. Tree controllers have no network: use controller=None, or esc.evaluate.

    `experiment` None is the script's one experiment (ValueError when it declares several).
    `seed` None draws a fresh one (the `seed` attribute tells it); else an integer in
    0..2^64-1 (TypeError, ValueError otherwise).
    """

    def __init__(self, script: Union[Script, PathOrSource], experiment: Optional[str] = None,
                 controller: Optional[str] = None, seed: Optional[int] = None):
        super().__init__(script, experiment, controller, seed, group=False)
        self.observation_space = self._observations
        self.action_space = self._actions

    def reset(self, seed: Optional[int] = None, options: Optional[dict] = None) -> Tuple[np.ndarray, dict]:
        """Starts the next episode, or with `seed` the first epoch of that evaluation seed's
        (`options` is accepted for Gymnasium's signature and unused). Returns (observation,
        info), info holding "epoch" (from 0), "step" (0), "fitness" (0) and "action" (-1).
        A seed is an integer in 0..2^64-1 (TypeError, ValueError otherwise)."""
        return self._env.reset(arguments.optional("seed", seed))

    def step(self, action) -> Tuple[np.ndarray, float, bool, bool, dict]:
        """One control step with `action` (action_space's shape): (observation, reward,
        terminated, truncated, info); info holds "epoch", "step" (steps taken this episode),
        "fitness" (this episode's rewards summed as esc sums them) and "action" (the index in
        `choices` of the action or behavior that acted, -1 for none). ValueError for an
        action of the wrong shape or with a NaN or infinite value (naming its index);
        TypeError for an action that is not real numbers; RuntimeError before reset() or
        after the episode ended."""
        return self._env.step(arguments.finite("action", action))

    def state(self) -> dict:
        """The robot after the last step, as `esc replay` writes a row of its CSV: x, y
        (metres), heading (radians), left/right_command, left/right_speed (m/s), ir, light,
        range and radar (the robot's rangefinders and goal radars; empty without them),
        energy, collided, with info's epoch, step, fitness and action."""
        return self._env.state()

    def __repr__(self) -> str:
        return (f"<esc.Env {self.experiment}, controller {self.controller}, seed {self.seed}: "
                f"observation {self.observation_space.shape}, action {self.action_space.shape}>")


class Policy:
    """A genome's network acting in an Env (made by Env.policy): called with an observation
    (the network's inputs), it returns the action (the network's activated outputs)."""

    def __init__(self, env: Env, network: "_esc.Policy"):
        self._env = env
        self._network = network
        self._episode = env.episode

    def __call__(self, observation) -> np.ndarray:
        """The action for `observation`, advancing the network's recurrent state."""
        if self._env.episode != self._episode:
            self._network.reset()
            self._episode = self._env.episode
        return self._network(arguments.finite("observation", observation))
