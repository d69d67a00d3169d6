"""The connection unknowns at a limiting equilibrium (book, ch. 14.4), for a free-body
diagram at the limit: the solution of the equations of statics inside every contact's laws
with the largest margin, by the linear program of :mod:`rigidmech.statics.limits` itself
(one rule for the limit and its actions).

Examples
--------
See :func:`rigidmech.drawing.fbd_actions.limiting_values`.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.validation import substitutions
from ..statics import Limit, Statics
from ..statics.limits import _lp_margin  # the limit's own program (no public equivalent)

__all__ = ["limiting_values"]


def limiting_values(statics, limit, values) -> dict:
    """``{unknown: value}`` at ``limit.value`` (see the public function's docstring)."""
    if not isinstance(statics, Statics):
        raise ArgumentTypeError(f"`statics` must be a Statics; got {type(statics).__name__}.")
    if not isinstance(limit, Limit):
        raise ArgumentTypeError(
            f"`limit` must be a Limit (Statics.limit(...)); got {type(limit).__name__}.")
    if limit.value is None:
        raise ArgumentError(
            "`limit` must be a limit reached in its interval; got one where the equilibrium "
            "holds throughout (limit.value is None): there is no limiting equilibrium to "
            "draw.")
    xs = list(statics.unknowns)
    rows = [e for _, _, e in statics.equations()]
    conds = [e for _, _, e in statics.contact_conditions()]
    symbols = set().union(*(e.free_symbols for e in rows + conds))
    subs = substitutions(values, symbols)
    subs[limit.parameter] = limit.value
    A, b = sp.linear_eq_to_matrix([e.xreplace(subs) for e in rows], xs)
    G, _ = sp.linear_eq_to_matrix([e.xreplace(subs) for e in conds], xs)
    free = (A.free_symbols | b.free_symbols | G.free_symbols)
    if free:
        raise ArgumentError(f"`values` must give numbers for {sorted(free, key=str)}.")
    An, bn, Gn = (np.array(M.tolist(), dtype=float) for M in (A, b, G))
    norms = np.linalg.norm(Gn, axis=1)
    Gn = Gn / np.where(norms > 0, norms, 1.0)[:, None]
    _, x = _lp_margin(An, bn.reshape(-1), Gn, want_x=True)
    if x is None:
        raise ArgumentError("`limit`: the equations of statics have no solution at "
                            f"{limit.parameter} = {limit.value}.")
    return {u: float(v) for u, v in zip(xs, x, strict=True)}
