"""The energy balance of a system: theorem of power and energy (book, ch. 18.3, 25).

For the parameters of situation q of a :class:`~rigidmech.dynamics.System`, with T its kinetic
energy relative to its reference, V the potential energy of the actions that have one and
Q_i^nc the power coefficients of the others (dampers, given forces and inputs, the inertial
actions of a moving reference when they have no potential), the equations of motion imply

.. math::
    \\frac{dE}{dt} = P, \\qquad
    E = \\sum_i \\dot q_i\\frac{\\partial T}{\\partial \\dot q_i} - T + V, \\qquad
    P = \\sum_i Q_i^{nc}\\,\\dot q_i - \\frac{\\partial (T - V)}{\\partial t},

the last derivative with q and q' held (the explicit dependence on time: a prescribed motion,
a field that turns or moves). When neither the positions nor the potentials depend on time
explicitly, T is quadratic in the q' and E = T + V, the mechanical energy, whose change is the
work of the non-conservative actions (ch. 18.3.3); otherwise E is Painlevé's energy function
T2 - T0 + V (T2, T0 the parts of T of degree 2 and 0 in the q'), and P also holds the power
that keeps up the prescribed motion. Linking connections (loops, rolling, gears) are perfect
and their multipliers do no work as long as their conditions do not depend on time.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError
from .._core.symbolic import vanishes
from ..vectors import t

__all__ = ["energy_terms", "time_dependence"]


def _split_actions(system):
    """The potential energy of the conservative actions and the list of the others: those
    without a potential and the dissipative ones (a damper, whose potential is zero)."""
    solids = (system._ground, *system._bodies)
    V, nc = [], []
    for action in system._actions:
        pe = action.potential_energy(solids, system.reference)
        if pe is None or callable(getattr(action, "dissipation_function", None)):
            nc.append(action)
        if pe is not None:
            V.append(pe)
    return sp.Add(*V), nc


def _explicit_dt(expr, system):
    """d expr / dt with q, q' (and q'') held."""
    _, _, _, rule = system.symbols()
    back = {v: k for k, v in rule.items()}
    plain = sp.sympify(expr).xreplace(rule)
    if not plain.has(t):
        return sp.S.Zero
    return plain.diff(t).xreplace(back)


def _check_constraints(system):
    c = system.constraints()
    if c is None:
        return
    rest = dict.fromkeys((q.diff(t) for q in system.coordinates), 0)
    for label, row in zip(c.labels, c.velocity, strict=True):
        if not vanishes(row.xreplace(rest)):
            raise ArgumentError(
                f"the linking connection {label} has a condition that depends on time "
                "explicitly: its multiplier works, and the energy balance does not "
                "include it.")


def _nonzero(expr):
    """Not identically zero, by the rule of the joints and the closures
    (:func:`~rigidmech._core.symbolic.vanishes`: a sample point, then ``simplify``; float
    constants to their rounding)."""
    return not vanishes(expr)


def time_dependence(kinetic, energy, rates, rule):
    """Why T + V is not an energy that only non-conservative actions change, or None: T not
    quadratic in the rates (a prescribed motion: T has parts of degree 0 or 1 in the q') or
    T + V depending on time explicitly (a field that turns or moves).

    Parameters
    ----------
    kinetic, energy : sympy expressions or None
        T and T + V with q(t), q'(t).
    rates : sequence of Symbol
        The plain symbols that ``rule`` puts in place of the q'(t).
    rule : dict
        q(t), q'(t), ... -> plain symbols.

    Examples
    --------
    >>> import rigidmech as rm, sympy as sp
    >>> r = rm.coordinates("r"); w = sp.Symbol("omega")
    >>> u, q = sp.symbols("u q")
    >>> rule = {r.diff(rm.t): u, r: q}
    >>> time_dependence((r.diff(rm.t)**2 + w**2 * r**2) / 2, None, [u], rule)
    'the kinetic energy has terms of degree 0 or 1 in the rates (a motion prescribed with time)'
    >>> time_dependence(r.diff(rm.t)**2 / 2, r.diff(rm.t)**2 / 2 + rm.t * r, [u], rule)
    'the energy T + V depends on time explicitly (a prescribed motion or a field that varies)'
    """
    if kinetic is not None:
        # T(s q') = T2 s^2 + T1 s + T0: T0 and T1 from one derivative in s at s = 0
        s = sp.Dummy("s")
        T = sp.sympify(kinetic).xreplace(rule).xreplace({u: s * u for u in rates})
        low = (T.xreplace({s: 0}), T.diff(s).xreplace({s: 0}))
        if any(_nonzero(x) for x in low):
            return ("the kinetic energy has terms of degree 0 or 1 in the rates (a motion "
                    "prescribed with time)")
    if energy is not None:
        E = sp.sympify(energy).xreplace(rule)
        if E.has(t) and _nonzero(E.diff(t)):
            return ("the energy T + V depends on time explicitly (a prescribed motion or a "
                    "field that varies)")
    return None


def energy_terms(system):
    """(E, P): the energy function E and its rate P (dE/dt = P along every motion), written
    with q(t), q'(t) and t.

    Examples
    --------
    A damped oscillator: E = T + V and P = -c x'^2.

    >>> import rigidmech as rm
    >>> x = rm.coordinates("x"); m, k, c = rm.constants("m k c", positive=True)
    >>> R0 = rm.Frame("R0"); P = R0.point("P", x, 0, 0)
    >>> s = rm.System(galilean=R0)
    >>> b = rm.Body("b", frame=R0.translated("R1", P), mass=m, centre=P); s.add(b)
    >>> s.act(rm.Spring(k, 0, a=R0.origin, b=P, on_b=b))
    >>> s.act(rm.actions.Damper(c, a=R0.origin, b=P, on_b=b))
    >>> E, P = energy_terms(s)
    >>> E.simplify(), P.simplify()
    (k*x(t)**2/2 + m*Derivative(x(t), t)**2/2, -c*Derivative(x(t), t)**2)
    """
    key = "energy_terms"
    if key in system._cache:
        return system._cache[key]
    _check_constraints(system)
    qs = system.coordinates
    T = system.kinetic_energy()
    V, nc = _split_actions(system)
    E = sp.Add(*[q.diff(t) * T.diff(q.diff(t)) for q in qs]) - T + V
    power = []
    parts_of = system._partials
    for solid, torsor, action in system._contributions():
        if not any(action is a for a in nc):
            continue
        for q, (Wi, Vi) in zip(qs, parts_of(solid, torsor.point), strict=True):
            power.append((torsor.resultant.dot(Vi) + torsor.moment.dot(Wi)) * q.diff(t))
    dL = _explicit_dt(T - V, system)
    system._cache[key] = (E, sp.Add(*power) - dL)
    return system._cache[key]
