"""One private bridge from :class:`~rigidmech.dynamics.EquationsOfMotion` to plain symbols.

The equations may write q and q' as the plain symbols ``eqs.q``, ``eqs.u``, or as the user's
q(t) and Derivative(q(t), t); this module maps every such form (and q''(t)) to symbols of its
own, so that the analyses of this layer never depend on the representation.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import xreplace_shared
from ..dynamics import EquationsOfMotion
from ..vectors import t as _t

__all__ = ["Normalised", "normalise"]


class Normalised:
    """M(q), f(q, u) of an EquationsOfMotion written with plain symbols q, u, a."""

    __slots__ = ("eqs", "q", "u", "a", "M", "f", "rule", "parameters", "names")

    def __init__(self, eqs, q, u, a, M, f, rule, parameters, names):
        self.eqs, self.q, self.u, self.a = eqs, q, u, a
        self.M, self.f, self.rule = M, f, rule
        self.parameters, self.names = parameters, names

    def to_plain(self, expr):
        """Any expression in q(t), q'(t), q''(t) or eqs.q, eqs.u, with our symbols."""
        return xreplace_shared([sp.sympify(expr)], self.rule)[0]

    def index(self, coordinate) -> int:
        """Position of a coordinate given as q(t), the eqs symbol, our symbol or its name."""
        for n, name in enumerate(self.names):
            if coordinate in (self.eqs.coordinates[n], self.eqs.q[n], self.q[n], name):
                return n
            if isinstance(coordinate, sp.Basic) and getattr(coordinate, "name", None) == name:
                return n
        raise ArgumentError(
            f"unknown coordinate {coordinate!r}; the equations have {list(self.names)}.")


def _name(c, n):
    if isinstance(c, sp.Symbol):
        return c.name
    if isinstance(c, sp.core.function.AppliedUndef):
        return c.func.__name__
    return f"q{n + 1}"


def normalise(eqs) -> Normalised:
    """Map q(t), q'(t), q''(t) of ``eqs.coordinates`` and the symbols ``eqs.q``, ``eqs.u`` to
    fresh real symbols q_i, u_i, a_i (memoised walk, shared subexpressions kept shared)."""
    if not isinstance(eqs, EquationsOfMotion):
        raise ArgumentTypeError(
            f"`eqs` must be an EquationsOfMotion (System.equations_of_motion()); got "
            f"{type(eqs).__name__}.")
    coords = tuple(eqs.coordinates)
    names = tuple(_name(c, n) for n, c in enumerate(coords))
    q = tuple(sp.Dummy(n, real=True) for n in names)
    u = tuple(sp.Dummy(n + "_dot", real=True) for n in names)
    a = tuple(sp.Dummy(n + "_ddot", real=True) for n in names)
    rule = {}
    for n, c in enumerate(coords):
        if isinstance(c, sp.core.function.AppliedUndef) or c.has(_t):
            # the time of the function itself (rigidmech's t, or sympy.physics.mechanics'
            # dynamicsymbols._t)
            time = c.args[0] if isinstance(c, sp.core.function.AppliedUndef) else _t
            rule[sp.Derivative(c, (time, 2))] = a[n]
            rule[sp.Derivative(c, time)] = u[n]
        rule[c] = q[n]
    for n, (qs, us) in enumerate(zip(eqs.q, eqs.u, strict=True)):
        rule[us] = u[n]
        rule[qs] = q[n]
    memo = {}
    entries = list(eqs.mass_matrix) + list(eqs.forcing)
    plain = xreplace_shared(entries, rule, memo)
    k = len(coords)
    M = sp.ImmutableMatrix(k, k, plain[: k * k])
    f = sp.ImmutableMatrix(k, 1, plain[k * k:])
    return Normalised(eqs, q, u, a, M, f, rule, tuple(eqs.parameters), names)
