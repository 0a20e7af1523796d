"""esc from Python: compile experiment scripts, read run directories as pandas tables,
evaluate genomes with esc's own simulator (bit-identical fitness, on every thread) and step
an experiment's epochs like a Gymnasium environment.

    import esc
    script = esc.compile("experiments/paper/obstacle_avoidance.esc", {"epochs": 2})
    run = esc.open("runs/oa")                     # a directory `esc run` wrote
    curves = run.table()                          # = esc export runs/oa --format csv
    best = run.best("SC_8_14_6", 1)
    esc.evaluate(script, "obstacle_avoidance", "SC_8_14_6", [best.genome], seed=best.evaluation_seed)
    env = esc.Env(script, "obstacle_avoidance", "SC_8_14_6", seed=best.evaluation_seed)
    group = esc.ParallelEnv(esc.compile("experiments/examples/groups.esc"), "dispersion")   # PettingZoo-shaped

Errors: esc.Error (esc refuses something: the message the esc program prints), its subclass
esc.ScriptError (a script that does not compile: file, line, column, message), ValueError for
a wrong argument (an unknown name, a genome of the wrong length, a NaN weight, a number out of
the range the esc program accepts), TypeError for an argument of the wrong type (a float
where an integer is expected, a complex genome).
"""

from esc._esc import __version__
from esc.env import Box, Env, Policy
from esc.errors import Diagnostic, Error, ScriptError, ScriptWarning
from esc.evaluation import evaluate, evaluation_seed, measure, run_seed
from esc.network import Network
from esc.parallel_env import ParallelEnv
from esc.results import BestEvaluation, Member, Run, open
from esc.running import Generation, resume, run
from esc.script import Body, Controller, Script, compile

__all__ = [
    "__version__",
    "Box", "Env", "ParallelEnv", "Policy",
    "Diagnostic", "Error", "ScriptError", "ScriptWarning",
    "evaluate", "evaluation_seed", "measure", "run_seed", "Network",
    "BestEvaluation", "Member", "Run", "open",
    "Generation", "resume", "run",
    "Body", "Controller", "Script", "compile",
]
