"""Closure conditions of the connections that link parameters (book, ch. 13.2, 25.3).

In a tree of bodies each connection is *built into* the frames: the child's frame is made
from its parent's by the motion the joint allows, with its own parameters of situation. A
connection that closes a loop, or a rolling contact, or a gear mesh, cannot be: it imposes
relations between parameters that already exist. :func:`closure_conditions` writes them, one
row per condition, as ``(label, velocity, position)``:

* a **joint** of the catalogue closing a loop: its point P1 = ``joint.at`` (taken on the
  first solid) and the point P2 of the second solid that must coincide with it (``meets``,
  default the same point). For each translation the joint blocks, along e of its local basis
  (u, v, w), the geometric condition is Φ = P1P2 . e = 0 and the kinematic one its time
  derivative. A rotation the joint blocks must already be blocked by the frames (the
  relative rotation component vanishes identically, as in a planar mechanism or two coaxial
  bearings); otherwise the orientation closure is refused (not supported yet). A condition
  that vanishes identically is dropped; one that is a non-zero constant means the two points
  cannot coincide and is refused;
* a **rolling contact** or a **gear mesh**: its velocity constraints
  (:class:`~rigidmech.kinematics.constraints.VelocityConstraint`), with their position form
  when they are holonomic (a wheel on a line, gears) and without one when they are not (a
  disc on a plane); the position form is only reported (its constant depends on the initial
  configuration), the constraint is enforced at the velocity level.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ConnectionError_
from ..torsors import Torsor
from ..vectors import Vector, t, time_derivative
from ..vectors.points import check_point

__all__ = ["closure_conditions", "closure_forces"]

_AXES = ("u", "v", "w")


def _time_derivative(e):
    """de/dt for e(q(t), t): the chain rule applied structurally
    (:func:`~rigidmech.vectors.time_derivative`), cheaper than sympy's ``diff``."""
    return time_derivative(e)


def _gear_rows(link):
    """The ratio condition of a gear mesh and the mesh force its multiplier stands for: the
    force F d at the pitch point I (d of the mesh's action torsor), whose power
    F d . (v(I in 2) - v(I in 1)) is kappa F c for the ratio condition c; a unit multiplier is
    the force d / kappa on the second gear and its opposite on the first."""
    conn = link.connection
    (c,) = conn.velocity_constraints()
    c = c.expression
    I = conn.pitch_point
    T, (F,) = conn.action_torsor("mesh")
    d = T.resultant.xreplace({F: 1})
    root = link.first.frame.root
    v2 = link.second.kinematic_torsor(relative_to=root, at=I).velocity
    v1 = link.first.kinematic_torsor(relative_to=root, at=I).velocity
    power = sp.expand(d.dot(v2 - v1))
    rates = sorted(c.atoms(sp.Derivative), key=str)
    rate = next(r for r in rates if sp.expand(c).coeff(r) != 0)
    kappa = sp.simplify(power.coeff(rate) / sp.expand(c).coeff(rate))
    if _zero(sp.expand(power - kappa * c)) is False:
        return [(f"{link.label}.1", c, None, None)]
    unit = (d / kappa).compact() if hasattr(d / kappa, "compact") else d / kappa
    return [(f"{link.label}.1", c, None, [(link.second, Torsor(unit, Vector.zero(), I)),
                                          (link.first, Torsor(-unit, Vector.zero(), I))])]


def _zero(e):
    """Whether ``e`` vanishes identically: a non-zero value at a random point settles it
    cheaply (no simplify for the conditions that remain, the usual case); otherwise
    ``simplify`` decides."""
    if e == 0:
        return True
    atoms = [*e.atoms(sp.Derivative), *e.atoms(sp.core.function.AppliedUndef),
             *(x for x in e.free_symbols if x != t)]
    for seed in (0.3711, 0.6173):
        rule = {a: sp.Float(seed + 0.1 * i) for i, a in enumerate(atoms)}
        try:
            value = e.xreplace(rule)  # Floats everywhere: evaluated as it is rebuilt
            value = complex(value if value.is_Number else value.subs(rule).evalf())
        except (TypeError, ValueError):
            break
        if abs(value) > 1e-9:
            return False
    return sp.simplify(e) == 0


def closure_conditions(link, meets=None) -> list:
    """The conditions ``(label, velocity, position)`` a linking connection imposes on the
    parameters of situation (see the module notes); ``position`` is None for a velocity-only
    (nonholonomic, or holonomic without a chosen constant) condition.

    Parameters
    ----------
    link : Link
    meets : Point, optional
        For a joint closing a loop, the point of ``link.second`` that coincides with the
        joint's point (a point of ``link.first``); default the joint's point itself.

    Raises
    ------
    ConnectionError\\_
        If the two points cannot coincide (a constant distance along a blocked direction),
        or the joint blocks a rotation the frames do not already block.

    Examples
    --------
    The pivot that closes a four-bar linkage: two conditions (the third, along the pivot's
    axis, vanishes identically).

    >>> import rigidmech as rm
    >>> from rigidmech.systems import Link
    >>> q1, q2, q3 = rm.coordinates("q1 q2 q3")
    >>> R0 = rm.Frame("R0"); k = R0.k
    >>> R1 = R0.rotated("R1", about=k, angle=q1)
    >>> R2 = R1.rotated("R2", about=k, angle=q2, origin=R0.origin.moved("B", R1.i))
    >>> R3 = R0.rotated("R3", about=k, angle=q3, origin=R0.point("D", 2, 0, 0))
    >>> C2, C3 = R2.origin.moved("C", R2.i), R3.origin.moved("C3", R3.i)
    >>> link = Link(rm.Body("coupler", frame=R2), rm.Body("rocker", frame=R3),
    ...             rm.joints.Pivot(at=C2, axis=k), "C")
    >>> [label for label, _, _ in closure_conditions(link, meets=C3)]
    ['C.u', 'C.v']
    """
    return [row[:3] for row in _rows(link, meets)]


def closure_forces(link, meets=None) -> list:
    """For each condition of :func:`closure_conditions`, the actions a unit Lagrange
    multiplier stands for: ``[(solid, Torsor), ...]`` on the two solids, whose power is the
    velocity condition (so that the generalised forces are A^T lambda): for a gear mesh, the
    mesh force at the pitch point along the line of action; None when the condition has no
    such action (a mesh whose power is not proportional to its ratio condition).

    Examples
    --------
    >>> import rigidmech as rm
    >>> from rigidmech.systems import Link
    >>> q1, q3 = rm.coordinates("q1 q3")
    >>> R0 = rm.Frame("R0"); k = R0.k
    >>> R1 = R0.rotated("R1", about=k, angle=q1)
    >>> R3 = R0.rotated("R3", about=k, angle=q3, origin=R0.point("D", 1, 0, 0))
    >>> link = Link(rm.Body("a", frame=R1), rm.Body("b", frame=R3),
    ...             rm.joints.Pivot(at=R1.origin.moved("C", R1.i), axis=k), "C")
    >>> [[(s.name, T.resultant) for s, T in row] for row in closure_forces(
    ...     link, meets=R3.origin.moved("C3", R3.j))]
    [[('b', R0.i), ('a', -R0.i)], [('b', R0.j), ('a', -R0.j)]]
    """
    return [row[3] for row in _rows(link, meets)]


def _rows(link, meets):
    """(label, velocity, position, forces) for each condition."""
    conn = link.connection
    first, second = link.first, link.second
    contact = getattr(conn, "contact", None)
    if contact is not None and callable(getattr(conn, "velocity_constraints", None)):
        I = contact.point
        v = contact.sliding_velocity
        rows = []
        for name, tv in zip(("t1", "t2"), contact.tangents(), strict=True):
            e = sp.expand(v.dot(tv))
            if not _zero(e):
                rows.append((f"{link.label}.{name}", e, None,
                             [(second, Torsor(tv, Vector.zero(), I)),
                              (first, Torsor(-tv, Vector.zero(), I))]))
        if not conn.pivoting:
            n = contact.normal
            e = sp.expand(contact.rotation.dot(n))
            if not _zero(e):
                rows.append((f"{link.label}.n", e, None,
                             [(second, Torsor(Vector.zero(), n, I)),
                              (first, Torsor(Vector.zero(), -n, I))]))
        return rows
    if hasattr(conn, "pitch_point"):
        return _gear_rows(link)
    if callable(getattr(conn, "velocity_constraints", None)):
        return [(f"{link.label}.{i + 1}", c.expression, None, None)
                for i, c in enumerate(conn.velocity_constraints())]
    P1 = conn.at
    P2 = P1 if meets is None else meets
    check_point(P2, "meets")
    if getattr(conn, "linked_motion", 0):
        raise ConnectionError_(
            f"{type(conn).__name__} at {P1.name} closes a loop between {link.first.name} and "
            f"{link.second.name}: a loop closed by a joint with linked motions (helical) is not "
            "supported yet; close the loop with another joint.")
    rows = []
    rotation = None
    for i in conn.blocked_motion:
        e = conn.basis[i % 3]
        if i < 3:
            if rotation is None:
                rotation = second.frame.rotation_vector(first.frame)
            w = sp.expand(rotation.dot(e))
            if not _zero(w):
                raise ConnectionError_(
                    f"{type(conn).__name__} at {P1.name} closes a loop between {first.name} "
                    f"and {second.name} and blocks the relative rotation about {e}, which the "
                    f"frames do not block (omega . {_AXES[i]} = {w}): orientation closure of "
                    "a loop is not supported yet. Close the loop with a joint that allows this "
                    "rotation (a spherical joint), or build the frames so that it vanishes.")
            continue
        phi = sp.expand((P2 - P1).dot(e))
        if _zero(phi):
            continue
        if not phi.has(t):
            raise ConnectionError_(
                f"{type(conn).__name__} at {P1.name} between {first.name} and {second.name}: "
                f"the points {P1.name} and {P2.name} do not coincide (their distance along "
                f"{_AXES[i - 3]} is the constant {sp.simplify(phi)}, whatever the parameters). "
                "Check the points of the connection.")
        rows.append((f"{link.label}.{_AXES[i - 3]}", _time_derivative(phi), phi,
                     [(second, Torsor(e, Vector.zero(), P2)),
                      (first, Torsor(-e, Vector.zero(), P1))]))
    return rows
