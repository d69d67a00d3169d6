"""The actions in the connections of a :class:`~rigidmech.dynamics.System`, derived only on
demand (book, ch. 18.2, 25.3).

Functions of the system, called by the methods of :class:`~rigidmech.dynamics.System` that
carry the documentation. The action of a tree connection is the fundamental principle for the
set of bodies it carries: {A(parent -> child)} = the sum over the carried bodies of their
dynamic torsors minus the other actions exerted on them (the given actions, and the actions of
the linking connections written with their Lagrange multipliers). The action of a connection
that closes a loop, rolls or meshes is the sum of its multipliers' unit torsors on the child.
Each action is cached in the system's cache.

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

from .._core.errors import ConnectionError_
from ..torsors import Torsor
from ..vectors import Frame
from ._derivation import contributions
from ._tree import solid as as_solid

__all__ = ["connection_action", "connection_components", "subtree"]


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
        return system._cache[key]
    actions = system._closure_actions()
    own = next((rows for k, rows in actions if k is link), None)
    tree = any(k is link for k in system._graph.tree_links())
    if own is not None and any(f is None for _, f in own) or (
            actions and any(f is None for k, rows in actions if k is not link
                            for _, f in rows)):
        raise ConnectionError_(
            "a linking connection of this system has no action torsor for its multiplier "
            "(a gear mesh whose power is not proportional to its ratio condition): its "
            "connection actions are not derived.")
    if not tree:
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
        result = total.at(P)
    else:
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
        result = Torsor(total.resultant.compact(), total.moment.compact(), P)
    system._cache[key] = Torsor(result.resultant.compact(), result.moment.compact(),
                                result.point)
    return system._cache[key]


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
