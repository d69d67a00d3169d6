"""What a :class:`~rigidmech.dynamics.Simulation` computes along its motion (book, ch. 18.3,
27): any expression of the motion, the action of a connection, the energy, its drift and its
balance.

Functions of the simulation, called by the methods of :class:`~rigidmech.dynamics.Simulation`
that carry the documentation. An expression is compiled once per call, with the stand-in
symbols of the equations (:mod:`rigidmech.dynamics._compiled`), and evaluated over all the
samples at once; q'' comes from the equations' compiled solver.

Examples
--------
>>> import sympy as sp, rigidmech as rm
>>> x = rm.coordinates("x")
>>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
...                            forcing=sp.ImmutableMatrix([[-x]]))
>>> sim = eqs.simulate(t=(0, 1), q0=[1.0], n_output=3)
>>> evaluate(sim, x.diff(rm.t, 2) + x, None).round(12).tolist()
[0.0, 0.0, 0.0]
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .._core.compile import compile_expressions
from .._core.errors import ArgumentError, ArgumentTypeError, CompilationError
from .._core.symbolic import atoms_shared, xreplace_shared
from ..vectors import Frame, Vector
from ..vectors import t as _t
from ._compiled import coordinate_name as _name
from .energy import energy_terms
from .energy import time_dependence as decide_time_dependence

__all__ = ["at_events", "connection_action", "energy", "energy_balance", "energy_drift",
           "energy_not_conserved", "energy_scale", "evaluate", "need_equations",
           "time_dependence"]


def need_equations(sim, what):
    """The equations of ``sim``; refused for a simulation loaded from a file."""
    if sim._eqs is None:
        raise ArgumentError(
            f"{what} needs the equations of motion, which a simulation loaded from a "
            "file does not have; simulate again to get them.")
    return sim._eqs


def input_values(sim):
    """The values of the inputs at the sample times (callables of t evaluated)."""
    out = []
    for w in sim._eqs.inputs:
        v = sim._params[_name(w)]
        if callable(v):
            try:
                v = np.asarray(v(sim.t), dtype=float)
            except (TypeError, ValueError):  # a callable of one float only
                v = np.array([float(v(x)) for x in sim.t])
        out.append(np.broadcast_to(np.asarray(v, dtype=float), sim.t.shape))
    return out


def evaluate(sim, expr, frame=None, along=None):
    """``expr`` along the motion of ``sim`` (see :meth:`Simulation.evaluate
    <rigidmech.dynamics.Simulation.evaluate>`); ``along`` maps more symbols to their values
    at the samples (the Lagrange multipliers)."""
    if isinstance(expr, Vector):
        if not isinstance(frame, Frame):
            raise ArgumentTypeError(
                f"`frame` must be a Frame to evaluate a Vector's components in; got "
                f"{type(frame).__name__}.")
        return evaluate(sim, expr.components(frame))[:, 0]
    eqs = need_equations(sim, "evaluate()")
    q_s, u_s, a_s, w_s, rule = eqs._stand_ins()
    if isinstance(expr, sp.MatrixBase):
        shape = expr.shape
        flat = xreplace_shared(list(expr), rule)
        e = sp.ImmutableMatrix(*shape, flat)
    else:
        try:
            flat = xreplace_shared([sp.sympify(expr)], rule)
        except (sp.SympifyError, TypeError) as exc:
            raise ArgumentTypeError(
                f"`expr` must be a sympy expression or Matrix; got {type(expr).__name__}."
            ) from exc
        e = flat[0]
    symbols, functions, derivatives = atoms_shared(flat)
    if functions or derivatives:
        raise CompilationError(
            f"`expr` contains {', '.join(sorted(map(str, functions | derivatives)))}, "
            "which is neither a coordinate of the equations, one of its first two "
            "derivatives nor an input.")
    extra = list(along or {})
    known = set(q_s) | set(u_s) | set(a_s) | set(w_s) | {_t} | set(extra)
    constants = sorted(symbols - known, key=lambda s: s.name)
    missing = [c.name for c in constants if c.name not in sim._params]
    if missing:
        raise ArgumentError(
            f"`expr` depends on {missing}, which the simulation has no value for; give "
            "them to simulate().")
    values = [float(sim._params[c.name]) for c in constants]
    f = compile_expressions(e, [_t, list(q_s), list(u_s), list(a_s), *constants,
                                *w_s, *extra])
    inputs = input_values(sim)
    if any(e.has(a) for a in a_s):
        params = [float(sim._params[p.name]) for p in eqs.parameters]
        acc = eqs._solver()(sim.t, sim.q, sim.u, *params, *inputs)
    else:
        acc = np.zeros_like(sim.q)
    out = f(sim.t, sim.q, sim.u, acc, *values, *inputs, *(along[x] for x in extra))
    if isinstance(e, sp.MatrixBase):
        return np.broadcast_to(out, tuple(e.shape) + sim.t.shape).copy()
    return np.broadcast_to(out, sim.t.shape).copy()


def at_events(sim, which):
    """The states at the occurrences of event ``which`` as a simulation (see
    :meth:`Simulation.at_events <rigidmech.dynamics.Simulation.at_events>`)."""
    if isinstance(which, bool) or not isinstance(which, int | np.integer):
        raise ArgumentTypeError(f"`which` must be the index (an int) of an event given to "
                                f"simulate(); got {type(which).__name__} {which!r}.")
    if sim._y_events is None:
        raise ArgumentError(
            "the states at the events are not known: this simulation was built without them "
            "(loaded from a .csv file or an older .npz file); simulate again, and save to "
            ".npz to keep them.")
    if not 0 <= which < len(sim._t_events):
        raise ArgumentError(
            f"`which` must be the index of an event given to simulate(), 0 to "
            f"{len(sim._t_events) - 1}; got {which!r}" + (
                " (the run was given no events)." if not sim._t_events else "."))
    return type(sim)(sim._eqs, None, sim._params, 0.0, sim.notes, status=sim.status,
                      message=f"The states at the occurrences of event {which}.",
                      names=sim._names, t=sim._t_events[which],
                      y=sim._y_events[which], t_events=[], y_events=[],
                      method=sim._method, t_stop=sim._t_stop)


def connection_action(sim, parent, child, basis, system, label=None, at=None):
    """The six components of the action of ``parent`` on ``child`` along the motion (see
    :meth:`Simulation.connection_action <rigidmech.dynamics.Simulation.connection_action>`):
    the Lagrange multipliers of a system with linking connections are evaluated at the
    stored states (from the augmented system, as :meth:`System.multipliers
    <rigidmech.dynamics.System.multipliers>`)."""
    eqs = need_equations(sim, "connection_action()")
    system = system if system is not None else getattr(eqs, "system", None)
    if system is None:
        raise ArgumentError(
            "`system` is needed: these equations were not derived by "
            "System.equations_of_motion(); pass system=... .")
    if system.equations_of_motion() is not eqs:
        raise ArgumentError(
            "`system` has changed since these equations were derived (or is another "
            "system): its connection actions would not match this motion. Simulate the "
            "system's current equations (system.equations_of_motion().simulate(...)).")
    if at is not None and basis is None:
        raise ArgumentError(
            "`at` needs `basis`: the moment at another point than the joint's is given by "
            "its components in a frame; pass basis=<a Frame> (e.g. the Galilean frame).")
    if basis is None:
        comps = system.connection_components(parent, child, label=label)
        keys = list(comps)
        exprs = [comps[k] for k in keys]
    else:
        if not isinstance(basis, Frame):
            raise ArgumentTypeError(f"`basis` must be a Frame or None; got "
                                    f"{type(basis).__name__}.")
        torsor = system.connection_action(parent, child, label=label)
        moment = torsor.moment_at(torsor.point if at is None else at)  # default: the joint's
        keys = ["X", "Y", "Z", "L", "M", "N"]
        exprs = list(torsor.resultant.components(basis)) + list(moment.components(basis))
    matrix = sp.ImmutableMatrix(len(exprs), 1, exprs)
    lams = [x for x in system.multiplier_symbols() if matrix.has(x)]
    along = None
    if lams:
        along = dict(zip(system.multiplier_symbols(), multipliers(sim), strict=True))
        along = {x: along[x] for x in lams}
    values = evaluate(sim, matrix, along=along)
    return {k: values[i, 0] for i, k in enumerate(keys)}


def multipliers(sim):
    """The Lagrange multipliers at the samples of ``sim``, shape (m, n_samples): the last
    rows of the solution of the augmented system (see :meth:`System.multipliers
    <rigidmech.dynamics.System.multipliers>`)."""
    eqs = need_equations(sim, "multipliers")
    params = [float(sim._params[p.name]) for p in eqs.parameters]
    full = eqs._solver().full(sim.t, sim.q, sim.u, *params, *input_values(sim))
    return -np.asarray(full)[len(eqs.coordinates):]


def _without_potential(eqs):
    """Why ``eqs`` has no mechanical energy, in words: the actions of its system that have no
    potential energy, or that the equations were given none."""
    system = getattr(eqs, "system", None)
    if system is None:
        return "these equations were given no energy (energy=None)"
    solids = (system._ground, *system._bodies)
    actions = [a for a in system.actions
               if a.potential_energy(solids, system._galilean) is None]
    if not actions:
        return "the system has changed since these equations were derived"
    names = ", ".join(repr(a) for a in actions)
    return (f"the action{'s' if len(actions) > 1 else ''} {names} ha"
            f"{'ve' if len(actions) > 1 else 's'} no potential energy (a couple or a force "
            "that does work without deriving from a potential), so T + V is not defined")


def energy(sim):
    """T + V along the motion."""
    eqs = need_equations(sim, "energy()")
    e = eqs.energy
    if e is None:
        raise ArgumentError(
            f"no mechanical energy to follow: {_without_potential(eqs)}. Use "
            "energy_balance(), which counts the work of every action.")
    return evaluate(sim, e)


def energy_scale(sim) -> float:
    """The scale of the energy drift, ``max(T(0) + |V(0)|, max_t T)`` (see
    :meth:`Simulation.energy_scale <rigidmech.dynamics.Simulation.energy_scale>`)."""
    eqs = need_equations(sim, "energy_scale()")
    e = energy(sim)
    kinetic = getattr(eqs, "kinetic_energy", None)
    if kinetic is not None:
        T = np.abs(evaluate(sim, kinetic))
        return float(max(T[0] + abs(e[0] - T[0]), np.max(T)))
    s = np.abs(e)
    scale = float(s[0])
    if scale == 0.0:
        scale = float(np.max(s))
    return scale


def energy_drift(sim, scale) -> float:
    """``max_t |E(t) - E(0)| / scale`` (see :meth:`Simulation.energy_drift
    <rigidmech.dynamics.Simulation.energy_drift>`)."""
    reason = energy_not_conserved(sim)
    if reason is not None:
        raise ArgumentError(
            f"energy_drift() would misreport: {reason}, so T + V changes without any "
            "error of the integration. Use energy_balance(), which accounts for it.")
    e = energy(sim)
    delta = float(np.max(np.abs(e - e[0])))
    if scale is None:
        scale = energy_scale(sim)
    else:
        scale = float(scale)
        if not (math.isfinite(scale) and scale > 0):
            raise ArgumentError(f"`scale` must be a finite number > 0; got {scale}.")
    if scale == 0.0:
        return 0.0 if delta == 0.0 else math.inf
    return delta / scale


def energy_not_conserved(sim):
    """Why T + V is not conserved along an exact motion, or None."""
    reason = time_dependence(sim)
    if reason is not None:
        return reason
    system = getattr(need_equations(sim, "energy_not_conserved()"), "system", None)
    if system is None:
        return None
    dissipative = [a for a in system.actions
                   if callable(getattr(a, "dissipation_function", None))]
    if not dissipative:
        return None
    names = ", ".join(type(a).__name__ for a in dissipative)
    return f"the system's dissipative actions ({names}) dissipate energy"


def time_dependence(sim):
    """Why T + V changes along a correct motion without non-conservative actions, or None
    (decided once for the equations)."""
    eqs = need_equations(sim, "time_dependence()")
    cache = eqs._cache   # decided once for the equations
    if "time_dependence" not in cache:
        _, u_s, _, _, rule = eqs._stand_ins()
        cache["time_dependence"] = decide_time_dependence(
            getattr(eqs, "kinetic_energy", None), eqs.energy, u_s, rule)
    return cache["time_dependence"]


def energy_balance(sim):
    """E(t) - E(0) - W(t) along the motion (see :meth:`Simulation.energy_balance
    <rigidmech.dynamics.Simulation.energy_balance>`)."""
    from scipy.integrate import cumulative_simpson, cumulative_trapezoid

    eqs = need_equations(sim, "energy_balance()")
    system = getattr(eqs, "system", None)
    if system is None:
        raise ArgumentError(
            "energy_balance() needs equations derived by System.equations_of_motion(): "
            "the work of the non-conservative actions is taken from the system.")
    if system.equations_of_motion() is not eqs:
        raise ArgumentError(
            "the system has changed since these equations were derived: its energy "
            "would not match this motion.")
    E, P = energy_terms(system)
    e = evaluate(sim, E)
    p = evaluate(sim, P)
    if sim.t.size >= 3:
        W = cumulative_simpson(p, x=sim.t, initial=0.0)
    elif sim.t.size == 2:
        W = cumulative_trapezoid(p, x=sim.t, initial=0.0)
    else:
        W = np.zeros_like(sim.t)
    return e - e[0] - W

