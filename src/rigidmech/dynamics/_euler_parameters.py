"""Equations of motion of bodies oriented by Euler parameters (book, ch. 9.1.2, 20.2).

Private helper of :mod:`rigidmech.dynamics`. A frame made by
:meth:`rigidmech.vectors.Frame.euler_parameters` depends on the direction of e = (e0, e1, e2,
e3) only, so the fundamental principle projected on the four partial kinematic torsors gives
equations M q'' = f whose mass matrix has the null vector n = (0, .., e, .., 0) (a change of
|e| moves nothing) and whose forcing has no component along n. :func:`complete` adds the
missing equation, the second derivative of |e|^2 = constant,

.. math:: \\mathbf{e}\\cdot\\ddot{\\mathbf{e}} = -\\dot{\\mathbf{e}}\\cdot\\dot{\\mathbf{e}},

as M' = M + s n n^T / |n|^2 and f' = f - s n (e'.e') / |n|^2 with s the mean diagonal entry
of the block of e (for a well-scaled matrix): since M n = 0 and n . f = 0, M' q'' = f' gives
the projection of the equations of motion orthogonal to n unchanged and n . q'' = -e'.e'. The
length of e then stays constant up to the integration error, and the orientation does not
depend on it anyway.
"""

from __future__ import annotations

import sympy as sp

from ..vectors import euler_parameters_of
from .equations import EquationsOfMotion

__all__ = ["euler_parameter_groups", "complete"]


def euler_parameter_groups(bodies, coordinates) -> tuple:
    """Index groups (4 indices into ``coordinates``) of the Euler parameters of the frames
    carrying ``bodies`` (a body frame or any of its ancestors)."""
    index = {q: i for i, q in enumerate(coordinates)}
    groups = []
    for body in bodies:
        f = body.frame
        while f is not None:
            e = euler_parameters_of(f)
            if e is not None and all(x in index for x in e):
                g = tuple(index[x] for x in e)
                if g not in groups:
                    groups.append(g)
            f = f.parent
    return tuple(groups)


def complete(eqs: EquationsOfMotion, groups) -> EquationsOfMotion:
    """``eqs`` with the equation e . e'' = -e' . e' of each group of Euler parameters (see
    the module docstring); ``eqs`` itself when there is none."""
    if not groups:
        return eqs
    M = sp.Matrix(eqs.mass_matrix)
    f = sp.Matrix(eqs.forcing)
    n_q = len(eqs.q)
    for g in groups:
        e = [eqs.q[i] for i in g]
        rates = [eqs.u[i] for i in g]
        n2 = sp.Add(*[x**2 for x in e])
        s = sp.Add(*[M[i, i] for i in g]) / 3
        if s == 0:
            s = sp.S.One
        n = sp.zeros(n_q, 1)
        for i, x in zip(g, e, strict=True):
            n[i] = x
        M = M + (s / n2) * (n * n.T)
        f = f - (s * sp.Add(*[r**2 for r in rates]) / n2) * n
    return EquationsOfMotion(
        coordinates=eqs.coordinates, q=eqs.q, u=eqs.u, mass_matrix=sp.ImmutableMatrix(M),
        forcing=sp.ImmutableMatrix(f), energy=lambda: eqs.energy, parameters=eqs.parameters,
        model_parameters=eqs._model, singular_sets=lambda: eqs.singular_sets,
        kinetic_energy=lambda: eqs.kinetic_energy, system=eqs.system,
        constraints=eqs.constraints)
