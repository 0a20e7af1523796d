"""Compiling scripts: esc.compile(path_or_source, settings) -> Script."""

import os
import warnings
from dataclasses import dataclass
from typing import Dict, List, Mapping, Optional, Sequence, Tuple, Union

from esc import _esc
from esc._library import standard_library
from esc.errors import Diagnostic, ScriptError, ScriptWarning

# The file name a script given as text has in diagnostics; its relative imports are searched
# from the working directory.
SOURCE_NAME = "<script>"


@dataclass(frozen=True)
class Controller:
    """A controller an experiment compares: its name, architecture ("8-14-6", "8-neat-2",
    "tree actions"), head ("classical", "symbolic", "supervisor" or "tree"), genome size (a
    network's weights, once per role; 0 for a tree or a NEAT network, whose genomes vary in
    length), its network's inputs by observable name ("ir[0]"), its choices (the actions or
    behaviors it picks from, in order), whether it is a NEAT network (`neat(...)`, its genome a
    graph) and the experiment's roles (`roles N`: a genome holds N networks' weights, role r's
    the r-th slice, driving robots r, r + N, ...; 1 for the clonal team). A controller per body
    (`per_body(...)`) has no inputs of its own: `per_body` lists each body of the group (in robot
    order) with its network's inputs, named as that body reads them; its genome holds every
    network's weights."""

    name: str
    architecture: str
    head: str
    genome_size: int
    inputs: Tuple[str, ...]
    choices: Tuple[str, ...]
    is_graph: bool = False
    roles: int = 1
    per_body: Tuple[Tuple[str, Tuple[str, ...]], ...] = ()

    @property
    def is_tree(self) -> bool:
        """Whether it is a GP tree (its genome an encoded tree) rather than a network."""
        return self.head == "tree"


@dataclass(frozen=True)
class Body:
    """A body an experiment's robots have (docs/robot-model.md): its robot declaration's name,
    how many robots have it (a group of several bodies lists them in robot order), its drive
    ("differential" or "acceleration"), its radius in metres, its outline (the corners from the
    axle, in metres; empty for a disc) and the sensors it offers a controller, by the names its
    scripts read them ("prox[0]", ..., "light[0]", ..., "energy")."""

    name: str
    robots: int
    drive: str
    radius_m: float
    outline_m: Tuple[Tuple[float, float], ...]
    sensors: Tuple[str, ...]


def _controller(d: dict) -> Controller:
    return Controller(d["name"], d["architecture"], d["head"], d["genome_size"], tuple(d["inputs"]),
                      tuple(d["choices"]), d["graph"], d["roles"],
                      tuple((body, tuple(inputs)) for body, inputs in d["per_body"]))


class Script:
    """A compiled script, its settings applied. Made by esc.compile; passed to esc.evaluate
    and esc.Env."""

    def __init__(self, compiled: "_esc.CompiledScript", given: Sequence[Tuple[str, str]] = ()):
        self._compiled = compiled
        self._given = tuple(given)

    @property
    def given_settings(self) -> Tuple[Tuple[str, str], ...]:
        """The settings esc.compile was given, as (key, value) texts in order: what esc.run
        gives `esc run` as --set KEY=VALUE."""
        return self._given

    @property
    def file(self) -> str:
        """The script's file as given, or "<script>" for a script given as text."""
        return self._compiled.file

    @property
    def experiments(self) -> List[str]:
        """The main file's experiments, in declaration order."""
        return list(self._compiled.experiments)

    @property
    def studies(self) -> Dict[str, List[str]]:
        """The main file's studies, in declaration order: name -> its conditions' names."""
        return {name: list(conditions) for name, conditions in self._compiled.studies}

    @property
    def refused(self) -> Dict[str, str]:
        """The experiments and studies that refused the settings esc.compile was given, each
        with why, as `esc run --set` says it (`esc run --experiment E` fails for E, so the
        file's other experiments stay usable); empty when every one took them. Each experiment
        and study condition is checked on its own: the settings on an experiment's dependencies
        are checked when esc.run runs it. Using a refused experiment (esc.Env, esc.evaluate,
        Script.controller) raises esc.Error with it."""
        return dict(self._compiled.refused)

    @property
    def controllers(self) -> Dict[str, Dict[str, Controller]]:
        """Per experiment, the controllers it compares in order: name -> Controller (the
        experiments that refused the settings given left out: Script.refused)."""
        return {e: {c["name"]: _controller(c) for c in self._compiled.controllers(e)} for e in self._usable()}

    @property
    def bodies(self) -> Dict[str, List[Body]]:
        """Per experiment, the bodies of its robots in robot order: one for a robot alone or a
        group of one body, several for `robot khepera x 2, epuck { ir_name ir } x 3` (the
        experiments that refused the settings given left out: Script.refused)."""
        return {e: [Body(b["name"], b["robots"], b["drive"], b["radius_m"],
                         tuple(tuple(v) for v in b["outline_m"]), tuple(b["sensors"]))
                    for b in self._compiled.bodies(e)] for e in self._usable()}

    @property
    def settings(self) -> Dict[str, Dict[str, str]]:
        """Per experiment, every setting as resolved with the settings given applied, as
        settings.json holds them ("epochs" -> "10", ...) (the experiments that refused the
        settings given left out: Script.refused)."""
        return {e: dict(self._compiled.settings(e)) for e in self._usable()}

    def _usable(self) -> List[str]:
        refused = self._compiled.refused
        return [e for e in self.experiments if e not in refused]

    def controller(self, experiment: Optional[str], name: str) -> Controller:
        """Controller `name` of `experiment` (None: the script's one experiment); ValueError
        naming the experiments or controllers there are (and the closest), esc.Error where the
        experiment refused the settings given (Script.refused)."""
        return _controller(self._compiled.controller(self.experiment_named(experiment), name))

    def experiment_named(self, experiment: Optional[str]) -> str:
        """`experiment` itself, or for None the one experiment the main file declares, as
        `esc run` without --experiment runs it; ValueError when it declares none or several
        (which one was meant?)."""
        if experiment is not None:
            if not isinstance(experiment, str):
                raise TypeError(f"experiment={experiment!r}: expected the name of an experiment (a str) or None")
            return experiment
        names = self.experiments
        if len(names) == 1:
            return names[0]
        declared = ", ".join(f"`{n}`" for n in names) if names else "none"
        raise ValueError(f"experiment=None: {self.file} declares {len(names)} experiments ({declared}): name one")

    def __repr__(self) -> str:
        return f"<esc.Script {self.file}: experiments {self.experiments}, studies {list(self.studies)}>"


PathOrSource = Union[str, "os.PathLike[str]"]


def _setting_text(value) -> str:
    """A setting's value as `--set KEY=VALUE` writes it (True and False as on and off)."""
    if isinstance(value, bool):
        return "on" if value else "off"
    return str(value)


def _is_path(path_or_source: PathOrSource) -> bool:
    """Whether the argument names a file rather than holding script text: a PathLike always;
    a str when it is an existing file or directory, or a one-line name ending in .esc (a
    missing file, reported as such rather than compiled as text)."""
    if isinstance(path_or_source, os.PathLike):
        return True
    if not isinstance(path_or_source, str):
        raise TypeError(f"path_or_source={path_or_source!r}: expected a path (str or os.PathLike) or script text")
    if os.path.exists(path_or_source):
        return True
    return "\n" not in path_or_source and path_or_source.strip().endswith(".esc")


def compile(path_or_source: PathOrSource, settings: Optional[Mapping[str, object]] = None) -> Script:
    """Compiles a script as the esc program does.

    `path_or_source` is a path (str or os.PathLike) to a script file, or the script's text
    (relative imports then searched from the working directory; diagnostics name it
    "<script>"). Imports not found beside the script are searched in $ESC_PATH, then in esc's
    standard library. `settings` ({"epochs": 2, "robot.inertia": False, ...}) are applied to
    every experiment and study condition as `esc run --set KEY=VALUE` applies them.

    A relative path that does not exist from the working directory is looked up as an import
    is, in $ESC_PATH then in the standard library: "paper/obstacle_avoidance.esc" is the
    shipped script, installed or in the build tree (Script.file says which file was read).

    Raises FileNotFoundError for a missing file, IsADirectoryError for a directory,
    esc.ScriptError for a script with errors (its first error's file, line, column and
    message), esc.Error for settings that every experiment and study refuses (an unknown key);
    settings that only some refuse (`robots` on a group of several bodies) leave those out,
    named in Script.refused. Warnings are issued as esc.ScriptWarning.
    """
    pairs = [(str(k), _setting_text(v)) for k, v in (settings or {}).items()]
    if _is_path(path_or_source):
        path = os.fspath(_esc.find_main_script(os.fspath(path_or_source), standard_library()))
        if os.path.isdir(path):
            raise IsADirectoryError(21, "A script is a file; this is a directory", path)
        if not os.path.isfile(path):
            raise FileNotFoundError(2, "No such script", path)
        compiled = _esc.compile_file(path, standard_library(), pairs)
    else:
        compiled = _esc.compile_source(path_or_source, SOURCE_NAME, standard_library(), pairs)
    diagnostics = [Diagnostic.from_dict(d) for d in compiled.diagnostics]
    if not compiled.ok:
        raise ScriptError(compiled.rendered, diagnostics)
    if diagnostics:
        warnings.warn(compiled.rendered.rstrip("\n"), ScriptWarning, stacklevel=2)
    return Script(compiled, pairs)


def as_script(script: Union[Script, PathOrSource]) -> Script:
    """`script` itself, or the Script a path or text compiles to."""
    return script if isinstance(script, Script) else compile(script)
