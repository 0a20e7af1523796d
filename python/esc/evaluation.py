"""Fitness of genomes: esc.evaluate, the function any Python optimizer can call, and esc.measure,
every objective and descriptor of them."""

from typing import Optional, Sequence, Union

import numpy as np

from esc import _esc
from esc.script import PathOrSource, Script, as_script

_SEED_LIMIT = 2 ** 64

Seeds = Union[int, Sequence[int], np.ndarray]


def _seeds(seed: Seeds, count: int) -> np.ndarray:
    """One evaluation seed per genome: `seed` for every one, or one each. Read as Python
    ints, never through a float: numpy makes float64 of a list mixing seeds above and below
    2^63, which loses their low bits."""
    if isinstance(seed, (int, np.integer)):
        values = [seed] * count
    else:
        values = np.ravel(seed).tolist() if isinstance(seed, np.ndarray) else list(seed)
    if len(values) != count:
        raise ValueError(f"{len(values)} seeds for {count} genomes: give one seed, or one per genome")
    for s in values:
        if not isinstance(s, (int, np.integer)) or isinstance(s, bool) or not 0 <= s < _SEED_LIMIT:
            raise ValueError(f"seed {s!r} is not a 64-bit unsigned integer")
    return np.array([int(s) for s in values], dtype=np.uint64)


def evaluate(script: Union[Script, PathOrSource], experiment: str, controller: str, genomes,
             epochs: Optional[int] = None, seed: Seeds = 0) -> np.ndarray:
    """The fitness of each genome of `controller` in `experiment`, as esc computes it.

    `script` is an esc.Script (esc.compile, with its settings) or a path or text to compile.
    `genomes` is, for a network controller, a 2-D float array with one genome (all the
    network's weights, Controller.genome_size of them) per row; for a tree controller, a
    sequence of encoded trees (1-D float arrays, as Run.best_genome(..., encoded=True) gives
    them). `epochs` replaces the experiment's number of epochs (as --set epochs=N does).

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
    lengths), or a tree that is not one of the controller's.
    """
    s = as_script(script)
    rows, count = _genome_rows(s, experiment, controller, genomes)
    return _esc.evaluate(s._compiled, experiment, controller, rows, epochs, _seeds(seed, count))


def measure(script: Union[Script, PathOrSource], experiment: str, controller: str, genomes,
            epochs: Optional[int] = None, seed: Seeds = 0) -> "pandas.DataFrame":
    """Every objective and behavior descriptor of each genome, as esc measures them.

    The same arguments and evaluations as esc.evaluate. Returns a pandas DataFrame with one row
    per genome and one column per value, named as the script names them: the fitness first,
    then each further objective (`objective G`, as measured: a minimised one is not negated),
    then each descriptor (`descriptor D: ...`), in the order the experiment declares them.
    The fitness column equals esc.evaluate's result bit for bit.
    """
    import pandas as pd

    s = as_script(script)
    rows, count = _genome_rows(s, experiment, controller, genomes)
    names, values = _esc.measure(s._compiled, experiment, controller, rows, epochs, _seeds(seed, count))
    return pd.DataFrame(values, columns=names)


def _genome_rows(s: Script, experiment: str, controller: str, genomes):
    """The genomes as the module takes them, and how many there are (raising ValueError as
    esc.evaluate documents)."""
    c = s.controller(experiment, controller)
    if c.is_tree:
        if isinstance(genomes, str) or any(isinstance(g, str) for g in genomes):
            raise ValueError(f"`{controller}` is a tree controller: give its trees encoded, as "
                             "Run.best_genome(controller, run, encoded=True) returns them, not as text")
        rows = [np.asarray(g, dtype=np.float64).ravel() for g in genomes]
        return rows, len(rows)
    rows = np.asarray(genomes, dtype=np.float64)
    if rows.ndim != 2:
        raise ValueError(f"genomes of `{controller}` are a 2-D array, one genome of {c.genome_size} weights per "
                         f"row (genome[None, :] for one); got shape {rows.shape}")
    return rows, rows.shape[0]


def evaluation_seed(run_seed: int, generation: int, individual: int) -> int:
    """The evaluation seed of offspring `individual` (from 0) of generation `generation`
    (from 0) of a run whose seed is `run_seed` (summary.json's "seed" of the run)."""
    return _esc.evaluation_seed(run_seed, generation, individual)


def run_seed(master_seed: int, run: int) -> int:
    """The seed of run `run` (from 1) of an experiment whose master seed is `master_seed`."""
    return _esc.run_seed(master_seed, run - 1)
