"""The standard library of scripts (`import "lib/khepera.esc"`) the package compiles with."""

import os

from esc import _paths


def standard_library() -> str:
    """The directory of esc's standard library and shipped scripts, found relative to this
    package (never a path of the machine that built it), as the esc program finds it
    relative to its binary. $ESC_PATH's directories are searched before it."""
    here = os.path.dirname(os.path.abspath(__file__))
    return os.path.normpath(os.path.join(here, _paths.STANDARD_LIBRARY))
