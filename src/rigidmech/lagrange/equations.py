"""Lagrange's equations (book, ch. 25).

For a set of bodies with perfect connections and independent parameters of situation q_i,
with kinetic energy T relative to the Galilean reference and power coefficients Q_i of the
given actions (the comoments of the action torsors with the partial kinematic torsors,
ch. 25.1.2-25.1.3),

.. math:: \\frac{d}{dt}\\frac{\\partial T}{\\partial \\dot q_i}
          - \\frac{\\partial T}{\\partial q_i} = Q_i, \\qquad i = 1..n
          \\quad\\text{(ch. 25.3.2)}.

This is a second, independent route to the equations of motion: the dynamics layer writes the
fundamental principle body by body; here only the kinetic energy of the set and the power of
the actions are used. On the same system both give the same M(q) and f(q, q', t).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentTypeError
from .._core.symbolic import xreplace_shared
from ..dynamics import EquationsOfMotion, System
from ..vectors import t

__all__ = ["lagrange_equations"]


def lagrange_equations(system: System) -> EquationsOfMotion:
    """Equations of motion of ``system`` by Lagrange's equations (ch. 25.3).

    Parameters
    ----------
    system : System

    Returns
    -------
    EquationsOfMotion
        M(q) q'' = f(q, q', t), written like :meth:`System.equations_of_motion` with the
        coordinates q(t) and their derivatives.

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> q = rm.coordinates("q"); m, L, g = rm.constants("m L g", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> G = R0.origin.moved("G", L / 2 * R1.i)
    >>> bar = rm.Body("bar", frame=R1, mass=m, centre=G,
    ...               inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G))
    >>> s = rm.System(galilean=R0)
    >>> s.connect(R0, bar, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    >>> s.act(rm.gravity(g * R0.i))
    >>> eqs = lagrange_equations(s)
    >>> eqs.mass_matrix, sp.simplify(eqs.forcing)
    (Matrix([[L**2*m/3]]), Matrix([[-L*g*m*sin(q(t))/2]]))
    """
    if not isinstance(system, System):
        raise ArgumentTypeError(f"`system` must be a System; got {type(system).__name__}.")
    qs = system.coordinates
    q_sym, u_sym, a_sym, rule = system.symbols()
    n = len(qs)
    T = system.kinetic_energy()
    rates = [q.diff(t) for q in qs]
    lhs = [sp.diff(sp.diff(T, r), t) - sp.diff(T, q) for q, r in zip(qs, rates, strict=True)]
    lhs = xreplace_shared(lhs, rule)
    Q = xreplace_shared(list(system.generalized_forces()), rule)
    no_acc = {a: 0 for a in a_sym}
    M = sp.ImmutableMatrix(n, n, lambda i, j: sp.diff(lhs[i], a_sym[j]))
    f = sp.ImmutableMatrix(n, 1, lambda i, _: Q[i] - lhs[i].xreplace(no_acc))
    # the plain symbols served the differentiations only: results are written with q(t)
    return EquationsOfMotion(coordinates=qs, q=q_sym, u=u_sym, mass_matrix=M, forcing=f,
                             energy=system.mechanical_energy(),
                             model_parameters=system.parameters,
                             singular_sets=system.orientation_singularities(),
                             constraints=system.constraints())
