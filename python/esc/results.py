"""Reading run directories: esc.open(path) -> Run."""

import builtins
import io
import json
import os
from dataclasses import dataclass
from typing import List, Optional, Union

import numpy as np

from esc import _arguments as arguments
from esc import _esc
from esc._library import standard_library
from esc.errors import Error
from esc.network import Network


@dataclass(frozen=True)
class BestEvaluation:
    """Where a run's best evaluation happened, enough to evaluate it again: esc.evaluate of
    `genome` with seed=`evaluation_seed` and the run's settings gives `fitness` exactly.
    `run` counts from 1, `generation` and `individual` (the offspring index) from 0;
    `run_seed` is the run's seed, from which evaluation_seed(run_seed, generation,
    individual) derives the evaluation's."""

    run: int
    run_seed: int
    fitness: float
    generation: int
    individual: int
    evaluation_seed: int
    genome: np.ndarray
    tree: Optional[str]


@dataclass(frozen=True)
class Member:
    """A member of a run's final Pareto front (NSGA-II; novelty and fitness) or an elite of
    its final archive (MAP-Elites): `kind` "front" or "archive", `cell` its position in the
    front or its archive cell, `objectives` by name as the front and archive tables hold them
    (the optimizer's own, such as novelty, first; then the experiment's as declared),
    `descriptors` in the experiment's order, and `genome` (a NEAT network's as an esc.Network). `generation` and `candidate` (from
    0) say which evaluation measured it and `evaluation_seed` that evaluation's seed:
    esc.evaluate of `genome` with that seed and the run's settings gives its fitness exactly.
    All three are None for a run stored by an esc that did not record them."""

    kind: str
    cell: int
    objectives: dict
    descriptors: np.ndarray
    genome: Union[np.ndarray, Network]
    generation: Optional[int]
    candidate: Optional[int]
    evaluation_seed: Optional[int]


class Run:
    """A run directory of esc (an experiment's or a study's), read once when opened, from a
    copy of its database: nothing in the directory is ever changed, and a read-only one
    opens. Made by esc.open."""

    def __init__(self, path: str, stored: "_esc.StoredRun"):
        self._path = path
        self._stored = stored

    @property
    def path(self) -> str:
        """The directory as given to esc.open (the `directory` column of its tables)."""
        return self._path

    @property
    def study(self) -> Optional[str]:
        """The study's name, or None for an experiment's directory."""
        return self._stored.study or None

    @property
    def experiments(self) -> List[str]:
        """The experiments stored: one, or a study's, one per condition."""
        return list(self._stored.experiments)

    @property
    def conditions(self) -> List[str]:
        """A study's conditions in the study's order; [] for an experiment."""
        return list(self._stored.conditions)

    @property
    def controllers(self) -> List[str]:
        """The controllers compared, in order."""
        return list(self._stored.controllers)

    @property
    def summary(self) -> dict:
        """summary.json as a dict (docs/results-store.md): per controller its runs' best
        fitness, seeds and per-generation best and mean (the population's sd per generation
        is in `table("generations")`). Seeds are decimal strings."""
        file = os.path.join(self._path, "summary.json")
        try:
            with builtins.open(file, encoding="utf-8") as f:
                return json.load(f)
        except FileNotFoundError:
            raise Error(f"{self._path} has no summary.json: no run of it has finished yet") from None

    def table(self, name: str = "generations"):
        """Table `name` as a pandas DataFrame: "generations" (the default export: one row
        per run and generation), "usage" (behavior usage per run, generation and behavior),
        "metrics" (what each optimizer reported per generation), "front" (NSGA-II's first
        front per generation), "archive" (MAP-Elites' and novelty search's archive changes
        per generation: the archive after generation g is
        `t[t.generation <= g].groupby(["run", "cell"]).last()`), "success" (Fisher's exact
        test and the censored Mann-Whitney test of every pair the end table compares, for an
        experiment that declares `success when`), "comparisons" (the end table's tests of the
        runs' best fitness, a row per pair: Welch, Mann-Whitney, A12, Brown-Forsythe, each p
        with Holm's adjustment) or "topology" (the nodes and links of each
        run's best NEAT network and of its final front's or archive's). ValueError for
        another name.

        It is pandas.read_csv of the very text `esc export DIR --table NAME --format csv`
        writes (the `directory` column holds the path as given to esc.open), read with
        float_precision="round_trip": the same columns and dtypes, and every number the
        double esc stored (the CSV's 17 significant digits read back exactly, where pandas'
        default parser may miss the last bit)."""
        import pandas as pd

        text = self._stored.table_csv(name, os.fspath(standard_library()))
        return pd.read_csv(io.StringIO(text), float_precision="round_trip")

    def best(self, controller: str, run: int, condition: Optional[str] = None) -> BestEvaluation:
        """The best evaluation of finished run `run` (from 1) of `controller` (of a study's
        `condition`, which a study of several conditions needs). ValueError for a controller,
        run or condition it does not hold (a run outside 1..runs, or one not finished);
        TypeError for a run that is not an integer."""
        d = self._stored.best(controller, self._run(run, condition), condition or "")
        return BestEvaluation(d["run"], d["run_seed"], d["fitness"], d["generation"], d["individual"],
                              d["evaluation_seed"], d["genome"], d["tree"])

    def members(self, controller: str, run: int, condition: Optional[str] = None) -> List[Member]:
        """What finished run `run` (from 1) of `controller` kept beside its best: its final
        front or archive, genomes included, rebuilt from the optimizer's stored state with the
        experiment compiled from the run's stored sources. Novelty search without the fitness
        keeps behaviors alone: its members are the archived descriptors, without objectives or
        genome. esc.Error when the optimizer keeps no members (the ES, CMA-ES, GP) or the run
        is not finished; ValueError for a controller, run (outside 1..runs) or condition the
        directory does not hold; TypeError for a run that is not an integer."""
        run = self._run(run, condition)
        found = self._stored.members(controller, run, condition or "", os.fspath(standard_library()))
        for d in found:
            if d.pop("graph"):
                d["genome"] = Network.decode(d["genome"])
        return [Member(**d) for d in found]

    def best_genome(self, controller: str, run: int, condition: Optional[str] = None,
                    encoded: bool = False) -> Union[np.ndarray, str, Network]:
        """The best genome of finished run `run` (from 1) of `controller`: a network's
        weights as a float64 array; a tree's text as script code, or with encoded=True the
        encoded tree (a float64 array) that esc.evaluate takes; a NEAT network's nodes and
        links (esc.Network), or with encoded=True its flat form (a float64 array, docs/neat.md).
        esc.evaluate takes a Network and a flat form alike."""
        d = self._stored.best(controller, self._run(run, condition), condition or "")
        if encoded:
            return d["genome"]
        if d["tree"] is not None:
            return d["tree"]
        return Network.decode(d["genome"]) if d["graph"] else d["genome"]

    def _run(self, run: int, condition: Optional[str]) -> int:
        """`run` checked against the runs the directory's experiment (or `condition`) has."""
        return arguments.integer("run", run, 1, self._stored.runs(condition or ""))

    def __repr__(self) -> str:
        what = f"study {self.study}" if self.study else f"experiment {self.experiments[0]}"
        return f"<esc.Run {self._path}: {what}, controllers {self.controllers}>"


def open(path: Union[str, "os.PathLike[str]"]) -> Run:
    """Opens the run directory `path` (written by `esc run`) without changing it.

    Raises FileNotFoundError when `path` does not exist, esc.Error with the store's message
    when it is not an esc run directory, is damaged, or holds no committed generation.
    """
    p = os.fspath(path)
    if not os.path.exists(p):
        raise FileNotFoundError(2, "No such run directory", p)
    return Run(p, _esc.StoredRun(p))
