"""Running experiments and studies: esc.run(...) and esc.resume(dir) -> Run."""

import os
from typing import Callable, Mapping, NamedTuple, Optional, Sequence, Union

from esc import _arguments as arguments
from esc import _esc
from esc._library import standard_library
from esc.results import Run, open as open_run
from esc.script import SOURCE_NAME, Script, _setting_text
from esc.script import compile as compile_script

PathLike = Union[str, "os.PathLike[str]"]


class Generation(NamedTuple):
    """One generation done, as the progress callable receives it: the study condition ("" for
    an experiment), the controller, the run (from 1), the generation (from 0), and the best
    and mean fitness of its offspring."""

    condition: str
    controller: str
    run: int
    generation: int
    best: float
    mean: float


Progress = Callable[[Generation], None]


def _script_and_settings(script: Union[Script, PathLike]):
    """The script file to run and the settings given with it; a script that does not compile
    raises its esc.ScriptError here, with its locations."""
    if not isinstance(script, Script):
        script = compile_script(script)
    if script.file == SOURCE_NAME:
        raise ValueError("esc.run needs a script file (a run stores its path, to resume it): write the text to "
                         "a .esc file and give its path")
    return script.file, [f"{k}={v}" for k, v in script.given_settings]


def run(script: Union[Script, PathLike], experiment: Optional[str] = None, runs: Optional[int] = None,
        generations: Optional[int] = None, seed: Optional[int] = None, threads: Optional[int] = None,
        out: Optional[PathLike] = None, set: Optional[Mapping[str, object]] = None,
        progress: Optional[Progress] = None, controllers: Optional[Sequence[str]] = None,
        cache: Optional[PathLike] = None) -> Run:
    """Runs an experiment or a study of a script into a directory, as `esc run` does with the
    same arguments, and returns it opened (esc.open).

    `script` is a script file, or a Script esc.compile made of one (its settings are then
    given as --set, before `set`). `experiment` names an experiment or a study (default: the
    first the script declares); `runs`, `generations`, `seed`, `set` ({"epochs": 1}),
    `controllers` and `cache` are `esc run`'s --runs, --generations, --seed, --set,
    --controllers and --cache; `threads` defaults to all cores; `out` to
    runs/<name>-<local time>. The directory holds exactly what `esc run` writes with the same
    arguments (esc.db, summary.json, the CSVs), byte for byte where esc run's are.

    `runs` and `generations` are integers in 1..10^9, `seed` in 0..2^64-1, `threads` in
    0..4096 (0: all cores), as `esc run` accepts them: TypeError for another type (a bool or
    a float included), ValueError out of range, before anything is compiled or written.

    `progress`, if given, is called with a Generation after each generation is stored.
    Ctrl-C (KeyboardInterrupt), or an exception `progress` raises, stops the run there, that
    generation kept: esc.resume continues it. Raises esc.ScriptError (the script), esc.Error
    (a setting, the directory, a dependency, memory), FileNotFoundError (no such script).
    """
    runs = arguments.optional("runs", runs)
    generations = arguments.optional("generations", generations)
    seed = arguments.optional("seed", seed)
    threads = arguments.optional("threads", threads)
    path, given = _script_and_settings(script)
    given += [f"{k}={_setting_text(v)}" for k, v in (set or {}).items()]
    outcome = _esc.run(path, experiment or "", runs, generations, seed, threads or 0, os.fspath(out or ""), given,
                       list(controllers or []), os.fspath(cache or ""), standard_library(), progress)
    return open_run(outcome["dir"])


def resume(dir: PathLike, generations: Optional[int] = None, script: Optional[PathLike] = None,
           threads: Optional[int] = None, progress: Optional[Progress] = None,
           cache: Optional[PathLike] = None) -> Run:
    """Continues the run or study in `dir` where it stopped (a kill, Ctrl-C), with the
    settings it started with, as `esc run --resume DIR` does; with `generations`, carries
    every run on to that many generations. `script` is where its script is now, if it moved.
    Returns the directory opened; one already complete is returned as it is.

    `generations` and `threads` are checked as esc.run checks them. Raises esc.Error when the
    directory cannot be resumed (the message says why: the script changed, nothing stored, a
    run still writing into it, ...)."""
    generations = arguments.optional("generations", generations)
    threads = arguments.optional("threads", threads)
    _esc.resume(os.fspath(dir), generations, os.fspath(script or ""), threads or 0, os.fspath(cache or ""),
                standard_library(), progress)
    return open_run(dir)
