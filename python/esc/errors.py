"""esc's exceptions: Error for anything esc refuses, ScriptError for a script that does not
compile, with the locations and text `esc check` prints."""

from dataclasses import dataclass
from typing import List, Sequence, Tuple


class Error(Exception):
    """Something esc refuses, with the message the esc program prints after "esc: error:":
    a run directory that is not one (or is damaged), a setting refused, a script that does
    not compile (ScriptError). `kind`, where esc.run or esc.resume refused, says what was
    refused: "script", "setting", "results" (the directory), "dependency" or "memory"."""

    kind: str = ""


class ScriptWarning(UserWarning):
    """A warning of the compiler about a script that compiled (its text as `esc check`
    prints it)."""


@dataclass(frozen=True)
class Note:
    """A place a diagnostic points to besides its own ("first declared here")."""

    file: str
    line: int
    column: int
    message: str


@dataclass(frozen=True)
class Diagnostic:
    """One error, warning or note of the compiler: where (file as named, line and column
    from 1, the length underlined), what, and its help lines ("did you mean `hidden`?")."""

    severity: str
    file: str
    line: int
    column: int
    length: int
    message: str
    help: Tuple[str, ...]
    notes: Tuple[Note, ...]

    @classmethod
    def from_dict(cls, d: dict) -> "Diagnostic":
        """The diagnostic of one of esc._esc's dicts."""
        notes = tuple(Note(n["file"], n["line"], n["column"], n["message"]) for n in d["notes"])
        return cls(d["severity"], d["file"], d["line"], d["column"], d["length"], d["message"],
                   tuple(d["help"]), notes)


class ScriptError(Error):
    """A script that does not compile. `file`, `line`, `column` and `message` are those of
    its first error, as the esc program prints them (file:line:column: error: message);
    `diagnostics` holds every error, warning and note; str() is the whole text `esc check`
    prints, source lines and carets included."""

    def __init__(self, rendered: str, diagnostics: Sequence[Diagnostic]):
        super().__init__(rendered.rstrip("\n"))
        self.diagnostics: List[Diagnostic] = list(diagnostics)
        first = next((d for d in self.diagnostics if d.severity == "error"), None)
        self.file = first.file if first else ""
        self.line = first.line if first else 0
        self.column = first.column if first else 0
        self.message = first.message if first else rendered.strip()
