"""Fitness of genomes: esc.evaluate, the function any Python optimizer can call, and esc.measure,
every objective and descriptor of them."""

from collections.abc import Iterable
from typing import Optional, Sequence, Union

import numpy as np

from esc import _arguments as arguments
from esc import _esc
from esc.network import Network
from esc.script import PathOrSource, Script, as_script

Seeds = Union[int, Sequence[int], np.ndarray]


def _seeds(seed: Seeds, count: int) -> np.ndarray:
    """One evaluation seed per genome: `seed` for every one, or one each. Read as Python
    ints, never through a float: numpy makes float64 of a list mixing seeds above and below
    2^63, which loses their low bits."""
    if isinstance(seed, np.ndarray):
        values = np.ravel(seed).tolist()
    elif isinstance(seed, Iterable) and not isinstance(seed, (str, bytes)):
        values = list(seed)
    else:
        values = [arguments.option("seed", seed)] * count
    if len(values) != count:
        raise ValueError(f"{len(values)} seeds for {count} genomes: give one seed, or one per genome")
    return np.array([arguments.option(f"seed[{i}]", s, "seed") for i, s in enumerate(values)], dtype=np.uint64)


def evaluate(script: Union[Script, PathOrSource], experiment: Optional[str], controller: str, genomes,
             epochs: Optional[int] = None, seed: Seeds = 0) -> np.ndarray:
    """The fitness of each genome of `controller` in `experiment`, as esc computes it.

    `script` is an esc.Script (esc.compile, with its settings) or a path or text to compile.
    `genomes` is, for a network controller, a 2-D float array with one genome (all the
    network's weights, Controller.genome_size of them: with `roles N`, N networks' weights one
    after the other) per row; for a tree controller, a
    sequence of encoded trees (1-D float arrays, as Run.best_genome(..., encoded=True) gives
    them); for a NEAT network (Controller.is_graph), a sequence of graph genomes, each an
    esc.Network (as Run.best_genome(controller, run) gives it) or its flat form (a 1-D float
    array, Network.encoded(); docs/neat.md).
    `experiment` None names the script's one experiment (ValueError when it declares
    several). `epochs` replaces the experiment's number of epochs (as --set epochs=N does).

    `seed` is the evaluation seed: the one random stream an evaluation draws its start poses,
    zones and sensor and motor noise from (epoch e from Rng(seed, e)); an int for every genome
    (common random numbers: every genome meets the same start poses), or a sequence of one
    per genome. In a run, offspring i of generation g evaluates with
    esc.evaluation_seed(run_seed, g, i); Run.best(...).evaluation_seed is the seed of a run's
    best evaluation, so esc.evaluate(script, experiment, controller, [best.genome],
    seed=best.evaluation_seed) returns best.fitness exactly, with the run's settings.

    Returns a float64 array of one fitness per genome, bit-identical to esc's for the same
    genome, settings and seed. Evaluations run on all threads with the GIL released; the
    result does not depend on the number of threads. Raises ValueError for an unknown
    experiment or controller, a genome of the wrong length (naming the expected and the given
    lengths), a tree that is not one of the controller's, a weight that is NaN or infinite
    (naming its index), `epochs` or a seed out of range; TypeError for genomes that are not
    real numbers (complex ones included) and for `epochs` or a seed that is not an integer.
    """
    return _esc.evaluate(*_evaluations(script, experiment, controller, genomes, epochs, seed))


def measure(script: Union[Script, PathOrSource], experiment: Optional[str], controller: str, genomes,
            epochs: Optional[int] = None, seed: Seeds = 0) -> "pandas.DataFrame":
    """Every objective and behavior descriptor of each genome, as esc measures them.

    The same arguments and evaluations as esc.evaluate. Returns a pandas DataFrame with one row
    per genome and one column per value, named as the script names them: the fitness first,
    then each further objective (`objective G`, as measured: a minimised one is not negated),
    then each descriptor (`descriptor D: ...`), in the order the experiment declares them.
    The fitness column equals esc.evaluate's result bit for bit.
    """
    import pandas as pd

    names, values = _esc.measure(*_evaluations(script, experiment, controller, genomes, epochs, seed))
    return pd.DataFrame(values, columns=names)


def _evaluations(script: Union[Script, PathOrSource], experiment: Optional[str], controller: str, genomes,
                 epochs: Optional[int], seed: Seeds) -> tuple:
    """The arguments of _esc.evaluate and _esc.measure, each checked as esc.evaluate documents."""
    s = as_script(script)
    experiment = s.experiment_named(experiment)
    epochs = arguments.optional("epochs", epochs)
    rows, count = _genome_rows(s, experiment, controller, genomes)
    return s._compiled, experiment, controller, rows, epochs, _seeds(seed, count)


def _genome_rows(s: Script, experiment: str, controller: str, genomes):
    """The genomes as the module takes them, and how many there are (raising ValueError as
    esc.evaluate documents)."""
    c = s.controller(experiment, controller)
    if c.is_tree and (isinstance(genomes, str) or any(isinstance(g, str) for g in genomes)):
        raise ValueError(f"`{controller}` is a tree controller: give its trees encoded, as "
                         "Run.best_genome(controller, run, encoded=True) returns them, not as text")
    if c.is_graph and isinstance(genomes, np.ndarray) and genomes.ndim == 2:
        raise ValueError(f"`{controller}` is a NEAT network: give its graph genomes as a sequence of 1-D arrays, "
                         "as Run.best_genome(controller, run) returns them (their lengths differ)")
    if c.is_graph and isinstance(genomes, Network):
        raise ValueError(f"`{controller}` is a NEAT network: give a sequence of genomes ([network] for one)")
    if c.is_graph:   # a Network's flat form, or one already flat
        genomes = [g.encoded() if isinstance(g, Network) else g for g in genomes]
    if c.is_tree or c.is_graph:   # encodings of varying length, one 1-D array each
        rows = [arguments.finite(f"genomes[{i}]", g).ravel() for i, g in enumerate(genomes)]
        return rows, len(rows)
    rows = arguments.finite("genomes", genomes)
    if rows.ndim != 2:
        raise ValueError(f"genomes of `{controller}` are a 2-D array, one genome of {c.genome_size} weights per "
                         f"row (genome[None, :] for one); got shape {rows.shape}")
    return rows, rows.shape[0]


def evaluation_seed(run_seed: int, generation: int, individual: int) -> int:
    """The evaluation seed of offspring `individual` (from 0) of generation `generation`
    (from 0) of a run whose seed is `run_seed` (summary.json's "seed" of the run)."""
    last_generation = arguments.limits("generations")[1] - 1
    return _esc.evaluation_seed(arguments.option("run_seed", run_seed, "seed"),
                                arguments.integer("generation", generation, 0, last_generation),
                                arguments.integer("individual", individual, 0, 2 ** 64 - 1))   # a size_t


def run_seed(master_seed: int, run: int) -> int:
    """The seed of run `run` (from 1) of an experiment whose master seed is `master_seed`."""
    return _esc.run_seed(arguments.option("master_seed", master_seed, "seed"),
                         arguments.option("run", run, "runs") - 1)
