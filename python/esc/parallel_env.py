"""esc.ParallelEnv: a group's epochs (docs/groups.md) stepped one control step at a time,
every robot at once, with PettingZoo's parallel interface (agents, reset, step, dicts keyed
by agent, observation_space(agent), action_space(agent)) but without the pettingzoo package."""

from typing import Dict, Optional, Tuple, Union

import numpy as np

from esc import _arguments as arguments
from esc.env import Box, Policy, _Episodes
from esc.script import PathOrSource, Script


class ParallelEnv(_Episodes):
    """A group experiment's epochs as episodes, every robot an agent, stepped together.

    The agents are "robot_1" to "robot_N", as `esc replay` numbers the robots. Episode k after
    reset(seed=S) is epoch k of esc's evaluation with seed S, as with Env: every robot starts
    where that epoch starts it. step() takes every live agent's action (a dict keyed by
    agent): each robot's controller head turns its action into wheel commands, then the group
    steps once. An agent's reward is its robot's fitness step term (the group's, the one esc
    sums, is their mean); info["fitness"] is the group's sum so far, info["action"] the
    robot's acting action or behavior. An episode ends for every robot at once: when one
    robot's stop condition fires (terminated) or after the experiment's steps (truncated);
    `agents` is then empty until reset(). A robot alone is a group of one.

    Observations and actions are an Env's, per robot (observation_space(agent),
    action_space(agent), the same for every agent of one body). With a controller per body
    (`per_body(...)`, a group whose bodies read other sensors), an agent observes its own
    body's network's inputs (observation_names_of(agent)). policies(genome) gives each robot
    its own copy of a genome's network, as esc's evaluation of a clonal group does.
    """

    metadata = {"name": "esc_parallel_v0", "is_parallelizable": True}

    def __init__(self, script: Union[Script, PathOrSource], experiment: Optional[str] = None,
                 controller: Optional[str] = None, seed: Optional[int] = None):
        super().__init__(script, experiment, controller, seed, group=True)
        self.possible_agents = [f"robot_{i + 1}" for i in range(self._env.robots)]
        self.agents = []
        self.observation_spaces = {a: Box(*self._env.observation_bounds(i)) for i, a in enumerate(self.possible_agents)}
        self.action_spaces = {a: self._actions for a in self.possible_agents}

    @property
    def num_agents(self) -> int:
        """Agents alive now."""
        return len(self.agents)

    @property
    def max_num_agents(self) -> int:
        """The robots of the group."""
        return len(self.possible_agents)

    def _agent(self, agent: str) -> int:
        if agent not in self.possible_agents:
            raise ValueError(f"{agent!r} is not an agent of this group: its agents are robot_1 to "
                             f"robot_{len(self.possible_agents)}")
        return self.possible_agents.index(agent)

    def observation_space(self, agent: str) -> Box:
        """The observations of `agent`: its robot's senses, or its network's inputs."""
        self._agent(agent)
        return self.observation_spaces[agent]

    def observation_names_of(self, agent: str) -> list:
        """What each entry of `agent`'s observation is, by observable name as its body reads it."""
        return list(self._env.observation_names(self._agent(agent)))

    def action_space(self, agent: str) -> Box:
        """The actions of `agent`: wheel commands, or its network's outputs."""
        self._agent(agent)
        return self.action_spaces[agent]

    def reset(self, seed: Optional[int] = None, options: Optional[dict] = None) -> Tuple[Dict, Dict]:
        """Starts the next episode, or with `seed` the first epoch of that evaluation seed's:
        (observations, infos), dicts keyed by agent. A seed is an integer in 0..2^64-1."""
        observations, infos = self._env.reset_group(arguments.optional("seed", seed))
        self.agents = list(self.possible_agents)
        return dict(zip(self.agents, observations)), dict(zip(self.agents, infos))

    def step(self, actions: Dict) -> Tuple[Dict, Dict, Dict, Dict, Dict]:
        """One control step of the group with every live agent's action: (observations,
        rewards, terminations, truncations, infos), dicts keyed by agent. ValueError for a
        missing or unknown agent, or an action of the wrong shape or not finite (naming the
        agent); RuntimeError before reset() or after the episode ended."""
        if not self.agents:
            raise RuntimeError("call reset() before step()" if self.episode == 0
                               else "the episode has ended: call reset()")
        if not isinstance(actions, dict):
            raise TypeError(f"actions: expected a dict keyed by agent ({', '.join(self.agents)}), got "
                            f"{type(actions).__name__}")
        for agent in actions:
            self._agent(agent)
        missing = [a for a in self.agents if a not in actions]
        if missing:
            raise ValueError(f"actions: no action for {', '.join(missing)}: every live agent acts at each step")
        given = [arguments.finite(f"actions[{a!r}]", actions[a]) for a in self.agents]
        observations, rewards, terminated, truncated, infos = self._env.step_group(given)
        agents = self.agents
        if terminated or truncated:
            self.agents = []
        return (dict(zip(agents, observations)), dict(zip(agents, rewards)),
                {a: bool(terminated) for a in agents}, {a: bool(truncated) for a in agents},
                dict(zip(agents, infos)))

    def state(self, agent: Optional[str] = None):
        """Each robot after the last step as `esc replay` writes its rows (Env.state's keys and
        the group's observables: centroid_x, ..., spread): a dict keyed by agent, or one
        robot's dict with `agent`."""
        if agent is not None:
            return self._env.state(self._agent(agent))
        return {a: self._env.state(i) for i, a in enumerate(self.possible_agents)}

    def policies(self, genome) -> Dict[str, Policy]:
        """Each agent's own copy of the network of `controller` with weights `genome` (its own
        recurrent state, started afresh with every episode), as Env.policy makes one. With
        `roles N`, `genome` holds N networks' weights, one after the other (as esc evolves and
        stores them), and robot_i's network is role (i - 1) mod N's. With a controller per
        body, `genome` holds every body's network, and each robot's is its body's."""
        c = self._script.controller(self.experiment, self.controller) if self.controller is not None else None
        roles = c.roles if c is not None else 1   # without a controller, policy() says what is missing
        if c is not None and c.per_body:
            bodies = [b.name for b in self._script.bodies[self.experiment] for _ in range(b.robots)]
            return {a: self.policy(genome, body) for a, body in zip(self.possible_agents, bodies)}
        if roles == 1:
            return {a: self.policy(genome) for a in self.possible_agents}
        weights = arguments.finite("genome", genome)
        size = c.genome_size
        if weights.ndim != 1 or weights.size != size:
            raise ValueError(f"a genome of `{self.controller}` in experiment `{self.experiment}` holds its {roles} "
                             f"roles' weights, {size} in all; got shape {weights.shape}")
        parts = np.split(weights, roles)
        return {a: self.policy(parts[i % roles]) for i, a in enumerate(self.possible_agents)}

    def render(self) -> None:
        """No rendering: `esc replay` draws a group's evaluation."""

    def __repr__(self) -> str:
        return (f"<esc.ParallelEnv {self.experiment}, {len(self.possible_agents)} robots, controller "
                f"{self.controller}, seed {self.seed}: observation {self._observations.shape}, "
                f"action {self._actions.shape}>")
