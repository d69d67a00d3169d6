"""The actions in the connections of a :class:`~rigidmech.dynamics.System`, derived only on
demand (book, ch. 18.2, 25.3).

Functions of the system, called by the methods of :class:`~rigidmech.dynamics.System` that
carry the documentation. The action of a tree connection is the fundamental principle for the
set of bodies it carries: {A(parent -> child)} = the sum over the carried bodies of their
dynamic torsors minus the other actions exerted on them (the given actions, and the actions of
the linking connections written with their Lagrange multipliers). The action of a connection
that closes a loop, rolls or meshes is the sum of its multipliers' unit torsors on the child.

A joint that closes a loop may block motions the frames already block (a linear annular
bearing B on the axis of a rotor held by a ball joint A: B stays on the axis whatever the
spin): those give no closure condition, hence no multiplier, yet the joint carries the
corresponding components of its action (B's Y, Z). They are the *silent unknowns* of the
loop: they enter the fundamental principle for the bodies each tree joint carries, and the
components every tree joint cannot carry (a perfect joint's zero components: no moment at a
ball joint) give the linear equations that determine them, the statics-style solve of the
loop's unknowns with the dynamic torsors on the left (ch. 14.2, 18.2). Those the equations
leave undetermined are hyperstatic (two coaxial pivots): they are taken zero in the closing
joint, the tree joints carrying the load, :meth:`System.hyperstatic_unknowns
<rigidmech.dynamics.System.hyperstatic_unknowns>` names them, and every action that depends on
them issues a :class:`~rigidmech.errors.HyperstaticWarning` naming them (cached or not). Each
action is cached in the system's cache.

Examples
--------
>>> import rigidmech as rm
>>> q = rm.coordinates("q"); m, g = rm.constants("m g", positive=True)
>>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
>>> s = rm.System(galilean=R0)
>>> s.connect(R0, rm.Body("disc", frame=R1, mass=m), rm.joints.Pivot(at=R0.origin, axis=R0.k))
>>> s.act(rm.gravity(-g * R0.j))
>>> connection_action(s, R0, s.bodies[0], None).resultant
g*m*R0.j
"""

from __future__ import annotations

import warnings

import numpy as np
import sympy as sp

from .._core.errors import ConnectionError_, HyperstaticWarning
from ..actions import Joint
from ..systems.mobility import GenericValues, numeric_rank
from ..torsors import Torsor
from ..vectors import Frame, Vector
from ._derivation import contributions
from ._tree import solid as as_solid

__all__ = ["connection_action", "connection_components", "hyperstatic_unknowns",
           "silent_actions", "subtree"]

_NAMES = ("X", "Y", "Z", "L", "M", "N")
_AXES = ("u", "v", "w")


def subtree(system, body):
    """``body`` and the bodies hanging from it by tree joints, depth first."""
    out = [body]
    for child, (parent, _) in system._joints.items():
        if parent is body:
            out.extend(subtree(system, child))
    return out


def connection_action(system, parent, child, label):
    """The action of ``parent`` on ``child`` through their connection in ``system``, cached
    (see :meth:`System.connection_action <rigidmech.dynamics.System.connection_action>`)."""
    parent = as_solid(system, parent, "parent")
    child = as_solid(system, child, "child")
    if system._contacts:
        raise ConnectionError_(
            "the system has one-sided contacts with friction whose actions depend on the "
            "regime: its connection actions would miss them (see "
            "rigidmech.regimes.contact_motion and ContactMotion.contact_actions).")
    link = system._link(parent, child, label)
    key = ("action", id(link))
    if key in system._cache:
        _warn_hyperstatic(system, link)
        return system._cache[key]
    actions = system._closure_actions()
    own = next((rows for k, rows in actions if k is link), None)
    if own is not None and any(f is None for _, f in own) or (
            actions and any(f is None for k, rows in actions if k is not link
                            for _, f in rows)):
        raise ConnectionError_(
            "a linking connection of this system has no action torsor for its multiplier "
            "(a gear mesh whose power is not proportional to its ratio condition): its "
            "connection actions are not derived.")
    result = _raw_action(system, link)
    solution, _ = _silent_solution(system)
    if solution:
        result = Torsor(result.resultant.xreplace(solution),
                        result.moment.xreplace(solution), result.point)
    system._cache[key] = Torsor(result.resultant.compact(), result.moment.compact(),
                                result.point)
    _warn_hyperstatic(system, link)
    return system._cache[key]


def _symbols_of(torsor):
    return {s for v in (torsor.resultant, torsor.moment) for _, comps in v._parts
            for c in comps for s in sp.sympify(c).free_symbols}


def _warn_hyperstatic(system, link):
    """A HyperstaticWarning naming the undetermined unknowns the action through ``link``
    depends on (taken zero), if any: the action of the closing joint itself, and those of
    the tree joints that carry their load."""
    _, undetermined = _silent_solution(system)
    if not undetermined:
        return
    key = ("hyperstatic in action", id(link))
    if key not in system._cache:
        present = {s.name for s in _symbols_of(_raw_action(system, link))}
        system._cache[key] = tuple(n for n in undetermined if n in present)
    names = system._cache[key]
    if names:
        warnings.warn(
            f"the connection action of {link.second.name} through {link.label!r} depends "
            f"on {', '.join(names)}, components of the action of a loop-closing joint that "
            f"the fundamental principle does not determine (a hyperstatic mounting, book "
            f"ch. 14.2; see System.hyperstatic_unknowns()): they are taken zero, the tree "
            f"joints carrying the load: one admissible split among infinitely many (it "
            f"depends on the stiffness of the parts). The other components are determined. "
            f"Silence this with warnings.simplefilter('ignore', "
            f"rigidmech.errors.HyperstaticWarning).", HyperstaticWarning, stacklevel=4)


def _raw_action(system, link):
    """The action through ``link`` with the silent unknowns as symbols, cached."""
    key = ("raw action", id(link))
    if key not in system._cache:
        system._cache[key] = _derive_raw_action(system, link)
    return system._cache[key]


def _derive_raw_action(system, link):
    child = link.second
    tree = any(k is link for k in system._graph.tree_links())
    actions = [*system._closure_actions(), *silent_actions(system)]
    if not tree:
        own = [row for k, rows in actions if k is link for row in rows]
        P = system._meets.get(id(link))
        P = P.origin if isinstance(P, Frame) else P
        if P is None:
            P = next((T.point for _, forces in own for solid, T in forces
                      if solid is child), None) or link.connection.at
        total = Torsor.zero(P)
        for lam, forces in own:
            for solid, T in forces:
                if solid is child:
                    total = total + lam * T
        return total.at(P)
    conn = link.connection
    P = conn.contact.point if hasattr(conn, "contact") else conn.at
    carried = (subtree(system, child) if not system._closures
               else list(system._graph.carried_by(link)))
    total = Torsor.zero(P)
    for b in carried:
        if b.mass:
            total = total + b.dynamic_torsor(system._galilean, at=P)
    for solid, torsor, _ in contributions(system):
        if solid in carried:
            total = total - torsor
    for k, rows in actions:
        if k is link:
            continue
        for lam, forces in rows:
            for solid, T in forces:
                if solid in carried:
                    total = total - lam * T
    return Torsor(total.resultant.compact(), total.moment.compact(), P)


def silent_actions(system):
    """The silent unknowns of the joints that close loops (see the module notes), in the
    form of the multipliers' actions: ``[(link, [(symbol, [(solid, unit torsor), ...]),
    ...]), ...]``, the symbol named ``<label>.<component>`` (``B.Y``), cached."""
    if "silent_actions" not in system._cache:
        out = []
        for link, rows in system._closures:
            conn = link.connection
            if not isinstance(conn, Joint):
                continue
            have = {row[0] for row in rows}
            meets = system._meets.get(id(link))
            P1 = conn.at
            P2 = meets.origin if isinstance(meets, Frame) else (meets or P1)
            silent = []
            for i in conn.blocked_motion:
                e = conn.basis[i % 3]
                if i < 3:
                    condition, name = f"{link.label}.r{_AXES[i]}", _NAMES[i + 3]
                    unit = [(link.second, Torsor(Vector.zero(), e, P2)),
                            (link.first, Torsor(Vector.zero(), -e, P1))]
                else:
                    condition, name = f"{link.label}.{_AXES[i - 3]}", _NAMES[i - 3]
                    unit = [(link.second, Torsor(e, Vector.zero(), P2)),
                            (link.first, Torsor(-e, Vector.zero(), P1))]
                if condition not in have:
                    silent.append((_NAMES.index(name),
                                   sp.Symbol(f"{link.label}.{name}", real=True), unit))
            if silent:   # in the order (X, Y, Z, L, M, N)
                out.append((link, [(sym, unit) for _, sym, unit in sorted(
                    silent, key=lambda x: x[0])]))
        system._cache["silent_actions"] = out
    return system._cache["silent_actions"]


def _silent_solution(system):
    """({silent symbol: value}, undetermined names): the silent unknowns solved from the
    zero components of the tree joints' actions (linear in them), those left undetermined
    (hyperstatic) taken zero; cached. The rank is decided at a generic configuration by the
    rule of :func:`rigidmech.systems.analyse` (the same decision as the hyperstaticity)."""
    if "silent_solution" in system._cache:
        return system._cache["silent_solution"]
    symbols = [sym for _, rows in silent_actions(system) for sym, _ in rows]
    if not symbols:
        system._cache["silent_solution"] = ({}, ())
        return system._cache["silent_solution"]
    closures = {id(k) for k, _ in system._closures}
    equations = []
    for link in system._graph.tree_links():
        conn = link.connection
        if not isinstance(conn, Joint) or id(link) in closures or not conn.zero_components:
            continue
        comps = conn.components(_raw_action(system, link))
        equations.extend(sp.expand(comps[_NAMES[i]]) for i in conn.zero_components)
    zero = dict.fromkeys(symbols, 0)
    B = sp.Matrix([[eq.coeff(s) for s in symbols] for eq in equations]) if equations \
        else sp.zeros(0, len(symbols))
    E0 = sp.Matrix([eq.xreplace(zero) for eq in equations])
    numbers = GenericValues(None, 0)
    Bn = np.array([[numbers(x) for x in row] for row in B.tolist()], dtype=float) \
        if equations else np.zeros((0, len(symbols)))
    columns, rows = [], []
    for c in range(len(symbols)):       # the unknowns met first are determined first
        if numeric_rank(Bn[:, columns + [c]]) > len(columns):
            columns.append(c)
    for r in range(len(equations)):
        if numeric_rank(Bn[rows + [r]][:, columns]) > len(rows):
            rows.append(r)
        if len(rows) == len(columns):
            break
    solution = dict(zero)
    if columns:
        values = B.extract(rows, columns).LUsolve(-E0.extract(rows, [0]))
        solution.update({symbols[c]: v for c, v in zip(columns, values, strict=True)})
    undetermined = tuple(s.name for n, s in enumerate(symbols) if n not in columns)
    system._cache["silent_solution"] = (solution, undetermined)
    return system._cache["silent_solution"]


def hyperstatic_unknowns(system):
    """The names of the silent unknowns of ``system`` that the fundamental principle does
    not determine (see :meth:`System.hyperstatic_unknowns
    <rigidmech.dynamics.System.hyperstatic_unknowns>`)."""
    return _silent_solution(system)[1]


def connection_components(system, parent, child, label):
    """The components (X, Y, Z, L, M, N) of that action in the joint's local basis (see
    :meth:`System.connection_components
    <rigidmech.dynamics.System.connection_components>`)."""
    T = connection_action(system, parent, child, label)
    child = as_solid(system, child, "child")
    joint = system._link(as_solid(system, parent, "parent"), child, label).connection
    if not callable(getattr(joint, "components", None)):
        raise ConnectionError_(
            f"the connection to {child.name} has no local components (a rolling contact "
            "or a gear mesh): use connection_action.")
    return dict(joint.components(T))
