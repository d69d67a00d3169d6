"""The derivation of the equations of motion of a :class:`~rigidmech.dynamics.System`: the
fundamental principle of dynamics for a set of bodies (book, ch. 18, 20, 25.1).

Functions of the system, called by the methods of :class:`~rigidmech.dynamics.System` that
carry the documentation, each result cached in the system's cache (cleared when the system
changes):

* the actions' contributions (solid, torsor, action) and the partial kinematic torsors
  {V_i(S/R)} = d{V(S/R)}/dq_i' of a solid at a point, in function form (ch. 25.1.2);
* the equations of motion M(q) q'' = f(q, q', t), free of connection unknowns (ch. 20.2,
  25.1.4): the fundamental principle written for each body, {D(S/R)} = {A(ext -> S)}, is
  combined with weights given by the partial kinematic torsors. The actions of perfect
  connections have zero power coefficients and drop out, leaving for each parameter of
  situation q_i

  .. math:: \\sum_S \\{\\mathcal{D}(S/R)\\}\\cdot\\{\\mathcal{V}_i(S/R)\\}
            = \\sum_S \\{\\mathcal{A}(\\bar S \\to S)\\}\\cdot\\{\\mathcal{V}_i(S/R)\\},

  where the dot is the comoment. The mass matrix is assembled directly from the partial
  velocities (M_ij = sum m V_i.V_j + Omega_i.J_G(Omega_j)), never extracted from an
  expanded expression, and every vector of a body is kept in the body's own basis: the cost
  grows polynomially with the number of bodies (no expression swell);
* the generalized forces, the energies and the constants of the model, as snapshots (values,
  not the system) for the equations to evaluate later.

Examples
--------
>>> import rigidmech as rm
>>> x = rm.coordinates("x"); m = rm.constants("m", positive=True)
>>> R0 = rm.Frame("R0"); P = R0.point("P", x, 0, 0)
>>> body = rm.Body("b", frame=R0.translated("R1", P), mass=m, centre=P)
>>> _kinetic_energy(R0, (body,))
m*Derivative(x(t), t)**2/2
"""

from __future__ import annotations

from functools import partial

import sympy as sp

from .._core.errors import ConnectionError_
from .._core.symbolic import free_symbols_shared
from ..vectors import Vector, partial_rotation_vector, t
from . import _euler_parameters
from ._singularities import orientation_singularities
from .equations import EquationsOfMotion
from .reference import _placing as _frame_exprs
from .reference import _point_placing, _vector_placing

__all__ = ["contributions", "equations_of_motion", "generalized_forces", "kinetic_energy_of",
           "mechanical_energy", "parameters", "partials", "symbols"]


def _mechanical_energy(galilean, solids, bodies, actions):
    """T + V of ``bodies`` under ``actions`` (values, not the system: a snapshot)."""
    T = sp.Add(*[b.kinetic_energy(galilean) for b in bodies if b.mass])
    V = []
    for action in actions:
        pe = action.potential_energy(solids, galilean)
        if pe is None:
            return None
        V.append(pe)
    return T + sp.Add(*V)


def mechanical_energy(system):
    """T + V of ``system`` now, or None if an action has no potential."""
    return _mechanical_energy(system._galilean, (system._ground, *system._bodies),
                              tuple(system._bodies), tuple(system._actions))


def kinetic_energy_of(system):
    """Kinetic energy of the bodies of ``system`` relative to its reference, now."""
    return _kinetic_energy(system._galilean, system._bodies)


def _kinetic_energy(galilean, bodies):
    """Kinetic energy of `bodies` relative to `galilean` (a snapshot, for the equations)."""
    return sp.Add(*[b.kinetic_energy(galilean) for b in bodies if b.mass])


def _constants(bodies, contributions):
    """The constant symbols of bodies (mass, inertia, centre, frames) and action torsors."""
    exprs = []
    for b in bodies:
        exprs.extend(_frame_exprs(b.frame))
        exprs.extend(_point_placing(b.centre))
        if b.mass is not None:
            exprs.append(b.mass)
        if b.inertia is not None:
            exprs.extend(b.inertia.matrix)
    for _, torsor, _ in contributions:
        for v in (torsor.resultant, torsor.moment, torsor.point.position):
            exprs.extend(_vector_placing(v))
    return tuple(sorted(free_symbols_shared(exprs) - {t}, key=lambda s: s.name))


def symbols(system):
    """Plain symbols q, q_dot, q_ddot for q(t), q'(t), q''(t) and the rule between
    them: not used in the results (which keep q(t)), offered by
    :meth:`System.symbols <rigidmech.dynamics.System.symbols>`."""
    if "symbols" not in system._cache:
        qs = system.coordinates
        names = [q.func.__name__ for q in qs]
        q_sym = tuple(sp.Symbol(n, real=True) for n in names)
        u_sym = tuple(sp.Symbol(n + "_dot", real=True) for n in names)
        a_sym = tuple(sp.Symbol(n + "_ddot", real=True) for n in names)
        rule = {}
        for q, qs_, us, as_ in zip(qs, q_sym, u_sym, a_sym, strict=True):
            rule[q.diff(t, 2)] = as_
            rule[q.diff(t)] = us
            rule[q] = qs_
        system._cache["symbols"] = (q_sym, u_sym, a_sym, rule)
    return system._cache["symbols"]


def contributions(system):
    """The actions' contributions (solid, torsor, action) on the bodies of ``system`` (those
    on the ground left out), cached."""
    if "contributions" not in system._cache:
        solids = [system._ground, *system._bodies]
        out = []
        for action in system._actions:
            for solid, torsor in action.contributions(solids):
                if solid is not system._ground:
                    out.append((solid, torsor, action))
        system._cache["contributions"] = out
    return system._cache["contributions"]


def partials(system, solid, point):
    """Partial kinematic torsor elements (Omega_i, V_i(point)) of ``solid`` for each
    parameter q_i, in function form (ch. 25.1.2).

    V_i(P) = d(O_R P)/dq_i |_R for the anchor of the solid, transported to P with
    Omega_i = d omega / d q_i': no differentiation of velocity expressions is needed.
    """
    key = ("partials", solid, point)
    if key not in system._cache:
        R = system._galilean
        anchor_pos = solid.anchor - R.origin
        out = []
        for q in system.coordinates:
            W = partial_rotation_vector(solid.frame, R, q)
            V = anchor_pos.diff(q, R)
            if point != solid.anchor and not W.is_zero:
                V = V + W.cross(point - solid.anchor)
            out.append((W, V))
        system._cache[key] = out
    return system._cache[key]


# False: the previous path (sympy's xreplace), kept only for the test of equivalence
# (tests/dynamics/test_derivation_equivalence.py); not an option.
_SHARED_REPLACE = True


def _replace_shared(vector, rule, memo):
    """``vector.xreplace(rule)``, the same result, each distinct subexpression rebuilt once
    (``memo`` shared between calls).

    sympy's ``xreplace`` walks an expression as a tree: the accelerations of a chain repeat
    the subexpressions of the bodies before them, and dropping q'' from them was half the
    derivation of the 3D chain. Unlike :func:`~rigidmech._core.symbolic.xreplace_shared`, sums
    and products are rebuilt with evaluation, as ``xreplace`` does (here leaves are replaced by
    zero, which must cancel the terms that hold them).
    """
    def walk(e):
        hit = memo.get(e)
        if hit is not None:
            return hit
        if e in rule:
            out = rule[e]
        elif not e.args:
            out = e
        else:
            args = tuple(walk(a) for a in e.args)
            out = e if all(a is b for a, b in zip(args, e.args, strict=True)) else e.func(*args)
        memo[e] = out
        return out

    if not _SHARED_REPLACE:
        return vector.xreplace(rule)
    return vector.applyfunc(walk)


def equations_of_motion(system, open_contacts):
    """The equations of motion of ``system``, derived once and cached (see
    :meth:`System.equations_of_motion <rigidmech.dynamics.System.equations_of_motion>`)."""
    if system._contacts and not open_contacts:
        raise ConnectionError_(
            f"the system has {len(system._contacts)} one-sided contact(s) with friction "
            "whose equations change with the regime (stick, slip, lift-off): integrate it "
            "with rigidmech.regimes.contact_motion, or pass open_contacts=True for the "
            "equations with the contacts open.")
    if "eom" in system._cache:
        return system._cache["eom"]
    R = system._galilean
    n = len(system.coordinates)
    no_acc = {sp.Derivative(q, (t, 2)): 0 for q in system.coordinates}  # no diff: cheap
    # Terms are collected in lists and summed once: adding to a growing sympy sum
    # re-sorts it at every step.
    M_terms = [[[] for _ in range(n)] for _ in range(n)]
    f_terms = [[] for _ in range(n)]
    memo = {}  # the subexpressions of all bodies' accelerations, rebuilt once
    for body in system._bodies:
        if not body.mass:
            continue
        parts = partials(system, body, body.centre)
        m = body.mass
        # accelerations without the q'' terms (they make up M q'')
        a0 = _replace_shared(body.centre.velocity(R).dt(R), no_acc, memo)
        J = body.inertia
        if J is not None:
            w = body.rotation_vector(R)
            d0 = _replace_shared(J.apply(w).dt(R), no_acc, memo)
            JW = [J.apply(Wi) if not Wi.is_zero else Vector.zero() for Wi, _ in parts]
        for i in range(n):
            Wi, Vi = parts[i]
            if Wi.is_zero and Vi.is_zero:
                continue
            f_terms[i].append(-m * a0.dot(Vi))
            if J is not None:
                f_terms[i].append(-d0.dot(Wi))
            for j in range(i, n):
                Wj, Vj = parts[j]
                M_terms[i][j].append(m * Vi.dot(Vj))
                if J is not None:
                    M_terms[i][j].append(JW[j].dot(Wi))
    for solid, torsor, _ in contributions(system):
        parts = partials(system, solid, torsor.point)
        for i in range(n):
            Wi, Vi = parts[i]
            f_terms[i].append(torsor.resultant.dot(Vi))
            f_terms[i].append(torsor.moment.dot(Wi))
    M = [[sp.Add(*M_terms[i][j]) if j >= i else None for j in range(n)] for i in range(n)]
    for i in range(n):
        for j in range(i):
            M[i][j] = M[j][i]
    f = [sp.Add(*terms) for terms in f_terms]
    bodies, actions = tuple(system._bodies), tuple(system._actions)
    eqs = EquationsOfMotion(
        coordinates=system.coordinates, mass_matrix=sp.ImmutableMatrix(M),
        forcing=sp.ImmutableMatrix(n, 1, f),
        energy=partial(_mechanical_energy, R, (system._ground, *bodies), bodies, actions),
        model_parameters=partial(_constants, bodies, tuple(contributions(system))),
        singular_sets=partial(orientation_singularities, tuple(bodies), R),
        kinetic_energy=partial(_kinetic_energy, R, bodies), system=system,
        constraints=system.constraints())
    # frames oriented by Euler parameters: add e . e'' = -e' . e' (their M is singular)
    eqs = _euler_parameters.complete(eqs, _euler_parameters.euler_parameter_groups(
        bodies, system.coordinates))
    system._cache["eom"] = eqs
    return eqs


def parameters(system):
    """The constant symbols of the model of ``system``, sorted by name (cached)."""
    if "parameters" not in system._cache:
        system._cache["parameters"] = _constants(tuple(system._bodies),
                                                 tuple(contributions(system)))
    return system._cache["parameters"]


def generalized_forces(system):
    """Power coefficients Q_i of the given actions of ``system`` (ch. 25.1.3)."""
    n = len(system.coordinates)
    Q = [[] for _ in range(n)]
    for solid, torsor, _ in contributions(system):
        parts = partials(system, solid, torsor.point)
        for i, (Wi, Vi) in enumerate(parts):
            Q[i].append(torsor.resultant.dot(Vi) + torsor.moment.dot(Wi))
    return sp.ImmutableMatrix(n, 1, [sp.Add(*terms) for terms in Q])
