"""Helpers of the cross-check against sympy.physics.mechanics: q'' from both libraries.

Both sides are reduced to numbers the same way: the mass matrix M and the forcing f are
evaluated at a state (q, q') and parameter values, and M q'' = f is solved. On the rigidmech
side that is the compiled right-hand side of :meth:`EquationsOfMotion.rhs` (its second half);
on the sympy side it is ``KanesMethod.mass_matrix`` / ``forcing`` (with the kinematic
differential equations u = q', so that the speeds are the coordinates' derivatives) or
``LagrangesMethod.mass_matrix`` / ``forcing``, lambdified and solved by ``numpy.linalg.solve``.

Coordinates are matched by name (each model uses the same names on both sides), so an order
that differs between the libraries is harmless; parameters and specified inputs are matched by
name too (a specified input ``F(t)`` of sympy is given the constant value of rigidmech's
constant ``F`` at the instant considered).
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from numpy.testing import assert_allclose
from sympy.physics import mechanics as me

__all__ = ["sympy_accelerations", "rigidmech_accelerations", "assert_same_accelerations",
           "random_states"]

_T = me.dynamicsymbols._t


def _name(x):
    return x.func.__name__ if isinstance(x, sp.core.function.AppliedUndef) else x.name


def sympy_accelerations(mass_matrix, forcing, coordinates, speeds=None):
    """q''(q, q', values) from sympy's M(q) and f(q, u) (``speeds`` None: f uses q').

    Returns ``(names, function)``: the coordinates' names and a function of three dicts
    name -> float (coordinates, their derivatives, constants and inputs) returning q'' as an
    array in the order of ``names``.
    """
    names = [_name(q) for q in coordinates]
    q_sym = [sp.Symbol(f"_q_{n}") for n in names]
    u_sym = [sp.Symbol(f"_u_{n}") for n in names]
    rule = {}
    for k, q in enumerate(coordinates):
        rule[q.diff(_T)] = u_sym[k]
        rule[q] = q_sym[k]
        if speeds is not None:
            rule[speeds[k]] = u_sym[k]
    exprs = [sp.ImmutableMatrix(mass_matrix).xreplace(rule),
             sp.ImmutableMatrix(forcing).xreplace(rule)]
    # what is left: constants and specified inputs F(t), both given by name
    others = set()
    for e in exprs:
        others |= e.free_symbols - set(q_sym) - set(u_sym) - {_T}
        others |= {a for a in e.atoms(sp.core.function.AppliedUndef)}
    leftover = [o for o in others if isinstance(o, sp.Derivative)]
    assert not leftover, f"unreplaced derivatives in sympy's equations: {leftover}"
    others = sorted(others, key=_name)
    plain = [sp.Symbol(f"_p_{_name(o)}") for o in others]
    exprs = [e.xreplace(dict(zip(others, plain, strict=True))) for e in exprs]
    fM, ff = (sp.lambdify([q_sym, u_sym, plain], e, "numpy") for e in exprs)
    other_names = [_name(o) for o in others]

    def qdd(q, u, values):
        qv = [q[n] for n in names]
        uv = [u[n] for n in names]
        pv = [values[n] for n in other_names]
        M = np.array(fM(qv, uv, pv), dtype=float)
        f = np.array(ff(qv, uv, pv), dtype=float).reshape(-1)
        return np.linalg.solve(M, f)

    return names, qdd


def rigidmech_accelerations(eqs):
    """q''(q, q', values) from rigidmech's compiled right-hand side, same calling convention
    as :func:`sympy_accelerations` (only the parameters the equations depend on are
    passed)."""
    names = [_name(q) for q in eqs.coordinates]
    n = len(names)

    def qdd(q, u, values):
        params = {p.name: values[p.name] for p in eqs.parameters}
        y = np.array([q[k] for k in names] + [u[k] for k in names], dtype=float)
        return eqs.rhs(**params)(0.0, y)[n:]

    return names, qdd


def assert_same_accelerations(eqs, sympy_side, *, states, rtol=1e-10):
    """Compare q'' of both sides at each ``(q, u, values)`` of ``states``.

    ``sympy_side`` is the ``(names, function)`` of :func:`sympy_accelerations`. The tolerance
    is relative to the largest |q''| of the state (an absolute floor of ``rtol`` times that
    scale, so that a component that should be zero is compared at the round-off of the
    others). Returns the largest relative difference seen.
    """
    names_rm, ours = rigidmech_accelerations(eqs)
    names_sp, theirs = sympy_side
    assert sorted(names_rm) == sorted(names_sp), (names_rm, names_sp)
    order = [names_sp.index(n) for n in names_rm]
    worst = 0.0
    for q, u, values in states:
        a = ours(q, u, values)
        b = theirs(q, u, values)[order]
        scale = max(float(np.max(np.abs(b))), 1e-300)
        assert_allclose(a, b, rtol=rtol, atol=rtol * scale,
                        err_msg=f"q'' differ at q={q}, u={u}, values={values}")
        worst = max(worst, float(np.max(np.abs(a - b))) / scale)
    return worst


def random_states(rng, coordinates, parameters, count=5):
    """``count`` random (q, u, values) triples.

    ``coordinates`` maps a name to the (low, high) range of q (q' is drawn in [-2, 2]);
    ``parameters`` maps a name to a (low, high) range of its value.
    """
    out = []
    for _ in range(count):
        q = {n: float(rng.uniform(*r)) for n, r in coordinates.items()}
        u = {n: float(rng.uniform(-2.0, 2.0)) for n in coordinates}
        values = {n: float(rng.uniform(*r)) for n, r in parameters.items()}
        out.append((q, u, values))
    return out
