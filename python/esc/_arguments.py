"""Arguments checked as the esc program checks its options, before anything runs: the same
ranges (esc._esc.limits, the numbers the command line checks against), and a TypeError (not
a number of the right kind) or ValueError (out of range, not finite) that names the
argument, the value given and what is accepted: "threads=-5: expected an integer in
0..4096"."""

import numbers
from typing import Optional, Tuple

import numpy as np

from esc import _esc


def limits(option: str) -> Tuple[int, int]:
    """The lowest and highest value the esc program accepts for `option` ("threads", "runs",
    "generations", "seed", "epochs")."""
    return _esc.limits[option]


def integer(name: str, value, lowest: int, highest: int) -> int:
    """`value` as an int when it is a whole number (a bool is not: True counts nothing) from
    `lowest` to `highest`."""
    accepted = f"expected an integer in {lowest}..{highest}"
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}={value!r}: {accepted}")
    if not lowest <= value <= highest:
        raise ValueError(f"{name}={value!r}: {accepted}")
    return int(value)


def option(name: str, value, limit: Optional[str] = None) -> int:
    """`value` checked against the esc program's range for option `limit` (default `name`)."""
    return integer(name, value, *limits(limit or name))


def optional(name: str, value, limit: Optional[str] = None) -> Optional[int]:
    """None (the esc program's default), or `value` checked as `option` checks it."""
    return None if value is None else option(name, value, limit)


def finite(name: str, values) -> np.ndarray:
    """`values` as a float64 array: real numbers (an int, float or bool array; a complex one
    would lose its imaginary part), each finite (a NaN or an infinity would be simulated as
    it is, to a fitness that means nothing). The error names the first bad entry's index."""
    a = np.asarray(values)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name}: expected real numbers, got an array of {a.dtype}")
    a = a.astype(np.float64, copy=False)
    bad = np.argwhere(~np.isfinite(a))
    if bad.size:
        where = "".join(f"[{i}]" for i in bad[0])
        raise ValueError(f"{name}{where} is {a[tuple(bad[0])]}: expected a finite number")
    return a
