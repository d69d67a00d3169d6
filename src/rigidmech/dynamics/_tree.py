"""The tree of bodies and coordinates of a :class:`~rigidmech.dynamics.System`, and how
:meth:`~rigidmech.dynamics.System.connect` files each connection (book, ch. 13.2, 18).

Functions of the system's building state (its graph, coordinate owners, tree joints, linking
connections, contacts, declaration ranks and cache), called by the methods of
:class:`~rigidmech.dynamics.System` that carry the documentation:

* the bodies and their parameters of situation: which coordinates a body's frame and centre
  depend on, which connection (or free body) moves each one, their order in the equations;
* :func:`connect`: a joint of the catalogue giving a body its first connection is a tree joint
  (checked against the frames); a joint between two solids already connected closes a loop,
  and a rolling contact, gear mesh or knife edge links the parameters: their condition rows
  are kept in the system's closures, for the constraints and the Lagrange multipliers
  (:mod:`rigidmech.dynamics.linked`); a one-sided contact with friction is only recorded
  (:func:`touch`), for :func:`rigidmech.regimes.contact_motion`.

Examples
--------
>>> import rigidmech as rm
>>> x, y = rm.coordinates("x y")
>>> R0 = rm.Frame("R0"); P = R0.point("P", x, y, 0)
>>> body_coordinates(rm.Body("b", frame=R0.translated("R1", P)))
[x(t), y(t)]
"""

from __future__ import annotations

import re

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from ..actions import Joint
from ..kinetics import Body
from ..systems import closure_conditions
from ..vectors import Frame
from ..vectors.symbols import declared_order, declared_ranks, is_coordinate
from .reference import _placing as _frame_exprs
from .reference import _point_placing

__all__ = ["add", "body_coordinates", "connect", "ordered_coordinates", "solid", "touch"]


def natural(name):
    """Sort key: q2 before q10."""
    return [int(p) if p.isdigit() else p for p in re.split(r"(\d+)", name)]


def coordinates_in(expr_iterable):
    """The parameters of situation q(t) in the expressions, in the order met (by name in one)."""
    found = []
    for e in expr_iterable:
        atoms = sp.sympify(e).atoms(sp.core.function.AppliedUndef)
        for a in sorted(atoms, key=lambda a: natural(str(a))):
            if is_coordinate(a) and a not in found:
                found.append(a)
    return found


def body_coordinates(body):
    """The parameters of situation q(t) on which the body's frame or mass centre depends."""
    exprs = _frame_exprs(body.frame)
    exprs.extend(_point_placing(body.centre))
    return coordinates_in(exprs)


def solid(system, s, argument):
    """`s` as a solid of the system: a Body, or a frame of the graph (the Galilean one)."""
    if isinstance(s, Frame):
        return system._graph.solid(s, argument)
    if not isinstance(s, Body):
        raise ArgumentTypeError(
            f"`{argument}` must be a Body or the Galilean frame; got {type(s).__name__}.")
    return s


def add(system, body):
    """Add a free body to ``system`` (:meth:`System.add <rigidmech.dynamics.System.add>`)."""
    body = solid(system, body, "body")
    if body is system._ground:
        raise ConnectionError_("the Galilean reference is not a body to add.")
    system._graph.check_body(body)
    claim(system, body, body_coordinates(body), f"the free body {body.name}")
    system._graph = system._graph.with_body(body)
    for q, rank in declared_ranks(body_coordinates(body)).items():
        system._ranks.setdefault(q, rank)
    system._cache.clear()


def claim(system, body, coordinates, owner):
    """Record that ``owner`` (a connection or a free body) moves ``coordinates``; a
    coordinate moved by two connections would be counted twice in the equations."""
    for q in coordinates:
        known = system._owners.get(q)
        if known is not None and known[0] is not body:
            raise ConnectionError_(
                f"the coordinate {q} of body {body.name} is already moved by {known[1]}: "
                "each parameter of situation belongs to one connection (or free body). "
                "Build the body's frame from its parent's, or give it its own coordinate.")
    for q in coordinates:
        system._owners[q] = (body, owner)


def ordered_coordinates(system):
    """The parameters of situation of ``system`` in the order of the equations (see
    :attr:`System.coordinates <rigidmech.dynamics.System.coordinates>`)."""
    if system._given_coordinates is not None:
        return system._given_coordinates
    if "coordinates" in system._cache:
        return system._cache["coordinates"]
    exprs = []
    for b in system._bodies:
        exprs.extend(_frame_exprs(b.frame))
        exprs.extend(_point_placing(b.centre))
    found = declared_order(coordinates_in(exprs), ranks=system._ranks)
    if not found:
        raise ArgumentError("the system has no parameter of situation: nothing moves.")
    system._cache["coordinates"] = tuple(found)
    return system._cache["coordinates"]


def connect(system, parent, child, joint, meets, label):
    """Connect ``child`` to ``parent`` by ``joint`` in ``system`` (see :meth:`System.connect
    <rigidmech.dynamics.System.connect>`): a tree joint, a connection that closes a loop or
    links the parameters (its condition rows kept in the system's closures), or a one-sided
    contact (:func:`touch`)."""
    parent = solid(system, parent, "parent")
    child = solid(system, child, "child")
    if getattr(joint, "one_sided", False):
        return touch(system, parent, child, joint)
    linking = callable(getattr(joint, "velocity_constraints", None))
    if not (isinstance(joint, Joint) or linking):
        raise ArgumentTypeError(
            f"`joint` must be a connection from rm.joints, a RollingContact or a "
            f"GearMesh; got {type(joint).__name__}.")
    if child is system._ground:
        raise ConnectionError_(
            "`child` cannot be the Galilean reference: connect bodies to it as parent.")
    if parent is not system._ground and parent not in system._bodies:
        raise ConnectionError_(
            f"connect the parent {parent.name} before its children.")
    # the joint closes a loop when the child is already connected, by a tree joint or by a
    # linking connection (a rolling contact): the same rule as ``closing`` below
    connected = child in system._joints or (
        child in system._bodies and bool(system._graph.links_of(child)))
    if meets is not None and not (isinstance(joint, Joint) and connected):
        raise ArgumentError(
            "`meets` is the point of `child` that closes a loop: give it only for a joint "
            f"between two solids already connected; got it for {child.name}, which has no "
            "connection yet.")
    if linking:
        check_linking_solids(parent, child, joint)
    new_body = child not in system._bodies
    if new_body:
        system._graph.check_body(child)
    closing = not new_body and (bool(system._graph.links_of(child)) or linking)
    graph = system._graph.with_connection(parent, child, joint, label=label)
    link = graph.links[-1]
    if closing or linking:
        rows = closure_conditions(link, meets=meets)
    if not closing:
        if not linking:
            R = system._galilean
            at = joint.at
            motion = child.kinematic_torsor(relative_to=R, at=at) + (
                -parent.kinematic_torsor(relative_to=R, at=at))
            joint.check(motion)
        parent_coordinates = set() if parent is system._ground else set(
            body_coordinates(parent))
        claim(system, child, [q for q in body_coordinates(child)
                              if q not in parent_coordinates],
              f"the connection {parent.name} -> {child.name}")
        if not linking:
            system._joints[child] = (parent, joint)
    if closing or linking:
        system._closures.append((link, tuple(rows)))
        if meets is not None:
            system._meets[id(link)] = meets
    system._graph = graph
    if new_body:
        for q, rank in declared_ranks(body_coordinates(child)).items():
            system._ranks.setdefault(q, rank)
    system._cache.clear()


def check_linking_solids(parent, child, conn):
    """Refuse a rolling contact, gear mesh or one-sided contact built on other frames than
    those of ``parent`` and ``child``."""
    ends = tuple(s.frame for s in conn.solids)
    # RollingContact: (moving S2, other S1); GearMesh: (first S1, second S2)
    expected = (child.frame, parent.frame) if hasattr(conn, "contact") else (
        parent.frame, child.frame)
    if ends != expected:
        raise ConnectionError_(
            f"{type(conn).__name__} joins the frames {ends[0].name} and {ends[1].name}, "
            f"but connects {parent.name} (frame {parent.frame.name}) and {child.name} "
            f"(frame {child.frame.name}) here: build it on the frames of the two bodies "
            "(the rolling solid as `child`, the driven gear as `child`).")


def touch(system, parent, child, contact):
    """Record a one-sided contact with friction (a :class:`~rigidmech.actions.
    FrictionContact`): its action depends on the regime (stick, slip, open), so it is
    left out of :meth:`System.equations_of_motion
    <rigidmech.dynamics.System.equations_of_motion>`; :func:`rigidmech.regimes.contact_motion`
    derives each regime from the system."""
    if child is system._ground:
        raise ConnectionError_(
            "`child` cannot be the Galilean reference: connect bodies to it as parent.")
    if parent is not system._ground and parent not in system._bodies:
        raise ConnectionError_(f"connect the parent {parent.name} before its children.")
    check_linking_solids(parent, child, contact)
    if child not in system._bodies:
        system.add(child)
    system._contacts.append((parent, child, contact))
    system._cache.clear()

