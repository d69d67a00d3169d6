"""Numbers or sympy expressions: the choice of library and the checks of the closed forms of
one degree of freedom (:mod:`rigidmech.vibrations.one_dof`), shared with the pendulum and the
rotors. Private."""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError


def _symbolic(*args):
    return any(isinstance(a, sp.Basic) and not isinstance(a, sp.Float | sp.Integer)
               for a in args)


def _lib(*args):
    return sp if _symbolic(*args) else np


def _as(x, lib):
    return sp.sympify(x) if lib is sp else np.asarray(x, dtype=float)


def _nonnegative(x, name):
    if isinstance(x, sp.Basic):
        if x.is_negative:
            raise ArgumentError(f"`{name}` must be >= 0; got {x}.")
        return x
    arr = np.asarray(x, dtype=float)
    if np.any(arr < 0) or not np.all(np.isfinite(arr)):
        raise ArgumentError(f"`{name}` must be finite and >= 0; got {x}.")
    return x


def _positive(x, name):
    if isinstance(x, sp.Basic):
        if x.is_nonpositive:
            raise ArgumentError(f"`{name}` must be > 0; got {x}.")
        return x
    arr = np.asarray(x, dtype=float)
    if np.any(arr <= 0) or not np.all(np.isfinite(arr)):
        raise ArgumentError(f"`{name}` must be finite and > 0; got {x}.")
    return x
