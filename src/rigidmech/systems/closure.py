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
  derivative. A rotation the joint blocks about e_i is usually blocked by the frames already
  (the relative rotation component vanishes identically, as in a planar mechanism or two
  coaxial bearings): then it gives no condition. Otherwise (a spatial loop) ``meets`` must be
  a frame of the second solid, its origin P2 and its axes (e_1(2), e_2(2), e_3(2)) meeting the
  joint's basis (e_1(1), e_2(1), e_3(1)) = (u, v, w) when the loop is closed, the joint's axis
  a vector of a frame fixed in the first solid; with (i, j, k) cyclic the condition is
  Φ = e_k(1) . e_j(2) = 0 (or -e_j(1) . e_k(2) = 0 when the joint allows the rotation about
  e_k: a pivot uses only w(2)), whose time derivative is (omega2 - omega1) . C with
  C = e_j(2) ^ e_k(1) (resp. e_j(1) ^ e_k(2)), equal to e_i when closed: the multiplier is
  the couple of the joint about e_i (these conditions also hold with an axis reversed,
  w(2) = -w(1): assemble from values near the intended position). A condition that
  vanishes identically is dropped, provided the two points also move together as points of
  their solids, (v(P2 in 2) - v(P1 in 1)) . e = 0 (two coaxial bearings); otherwise (``meets``
  left out while the joint's point is a point of one solid only) the loop would stay open,
  and it is refused. A condition that is a non-zero constant means the two points (or axes)
  cannot coincide and is refused;
* a **helical** joint closing a loop adds its linked motion, at the velocity level only:
  (v(P2 in 2) - v(P1 in 1)) . w - h (omega2 - omega1) . w = 0, h = pitch / (2 pi) (its
  position form would carry the relative angle, which the frames do not name); its
  multiplier is the axial force Z, with the couple N = -h Z of a perfect helical joint;
* a **rolling contact**, a **gear mesh** or a **knife edge**: its velocity constraints
  (:class:`~rigidmech.kinematics.constraints.VelocityConstraint`), with their position form
  when they are holonomic (a wheel on a line, gears) and without one when they are not (a
  disc on a plane); the position form is only reported (its constant depends on the initial
  configuration), the constraint is enforced at the velocity level.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ConnectionError_
from .._core.symbolic import vanishes
from ..torsors import Torsor
from ..vectors import Frame, Vector, t, time_derivative
from ..vectors.points import check_point

__all__ = ["closure_conditions", "closure_forces"]

_AXES = ("u", "v", "w")

# The previous form of the rolling rows (expanded), kept only for the test of equivalence
# (tests/dynamics/test_derivation_equivalence.py); not an option.
_EXPAND_CONTACT_ROWS = False


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


def _zero(e, scale=None):
    """Whether ``e`` vanishes identically (:func:`~rigidmech._core.symbolic.vanishes`, the
    rule of the joints and the energy balance): a non-zero value at a sample point settles it
    cheaply (no simplify for the conditions that remain, the usual case); otherwise
    ``simplify`` decides; float constants count to their rounding, relative to the terms of
    ``scale`` (the quantities of the same kind: the positions of the points, the other
    components of a velocity or rotation) when given. The time t is sampled like the other
    symbols: a condition on a support driven as a function of t (a belt, a turntable) carries
    it explicitly, and leaving it out of the sample sent every such row to ``simplify``
    (seconds per row for a ball on a driven turntable); q(t) and its derivatives are sampled
    as wholes, so the value of t does not reach them."""
    return vanishes(e, scale=scale)


def closure_conditions(link, meets=None) -> list:
    """The conditions ``(label, velocity, position)`` a linking connection imposes on the
    parameters of situation (see the module notes); ``position`` is None for a velocity-only
    (nonholonomic, or holonomic without a chosen constant) condition.

    Parameters
    ----------
    link : Link
    meets : Point or Frame, optional
        For a joint closing a loop, the point of ``link.second`` that coincides with the
        joint's point (a point of ``link.first``); default the joint's point itself. A frame
        of ``link.second`` (origin and axes) for a joint that blocks a relative rotation the
        frames do not.

    Raises
    ------
    ConnectionError\\_
        If the two points (or axes) cannot coincide (a constant distance along a blocked
        direction), or coincide but do not move together as points of their solids (``meets``
        left out for a point of the first solid only), or the joint blocks a rotation the
        frames do not already block and ``meets`` is not a frame of the second solid.

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

    A spatial loop: a body on a ball joint (pitch b, then roll c), its axis k held along R0.k
    by a pivot; ``meets`` is the body's frame, whose k is the pivot's axis when closed.

    >>> b, c = rm.coordinates("b c")
    >>> A = R0.rotated("A", about=R0.j, angle=b); R = A.rotated("R", about=A.i, angle=c)
    >>> link = Link(rm.Body("ground", frame=R0), rm.Body("body", frame=R),
    ...             rm.joints.Pivot(at=R0.origin, axis=k), "P")
    >>> [(label, phi) for label, _, phi in closure_conditions(link, meets=R)]
    [('P.ru', sin(c(t))), ('P.rv', sin(b(t))*cos(c(t)))]
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
        speeds = [v.dot(d) for d in (*contact.tangents(), contact.normal)]
        for name, tv in zip(("t1", "t2"), contact.tangents(), strict=True):
            # not expanded: the sliding velocity of a contact point built from a normalised
            # direction (the bicycle's front wheel) swells 6x under expand, and every later
            # step (the Jacobian, the bias d/dt, the rank check) pays for the swell
            e = v.dot(tv)
            if _EXPAND_CONTACT_ROWS:
                e = sp.expand(e)
            if not _zero(e, scale=speeds):
                rows.append((f"{link.label}.{name}", e, None,
                             [(second, Torsor(tv, Vector.zero(), I)),
                              (first, Torsor(-tv, Vector.zero(), I))]))
        if not conn.pivoting:
            n = contact.normal
            e = sp.expand(contact.rotation.dot(n))
            if not _zero(e, scale=[contact.rotation.dot(d) for d in contact.tangents()]):
                rows.append((f"{link.label}.n", e, None,
                             [(second, Torsor(Vector.zero(), n, I)),
                              (first, Torsor(Vector.zero(), -n, I))]))
        return rows
    if hasattr(conn, "pitch_point"):
        return _gear_rows(link)
    if callable(getattr(conn, "constraint_torsors", None)):
        # a connection that gives, for each constraint, the action on the second solid a
        # unit multiplier stands for (a knife edge): its opposite acts on the first
        return [(f"{link.label}.{i + 1}", c.expression, None, [(second, T), (first, -T)])
                for i, (c, T) in enumerate(zip(conn.velocity_constraints(),
                                               conn.constraint_torsors(), strict=True))]
    if callable(getattr(conn, "velocity_constraints", None)):
        return [(f"{link.label}.{i + 1}", c.expression, None, None)
                for i, c in enumerate(conn.velocity_constraints())]
    P1 = conn.at
    P2, axes2 = _meeting(conn, meets)
    rows = []
    rotation = None
    basis1 = conn.basis
    free = [i for i in range(3) if i not in conn.blocked_motion]
    for i in conn.blocked_motion:
        e = basis1[i % 3]
        if i < 3:
            if rotation is None:
                rotation = second.frame.rotation_vector(first.frame)
            if _zero(sp.expand(rotation.dot(e)), scale=[rotation.dot(d) for d in basis1]):
                continue  # the frames already block it
            rows.append(_orientation_row(link, i, free, axes2, P2))
            continue
        phi = sp.expand((P2 - P1).dot(e))
        origin = first.frame.root.origin
        if _zero(phi, scale=[(P1 - origin).dot(e), (P2 - origin).dot(e)]):
            _check_same_point(link, P1, P2, e, _AXES[i - 3])
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
    if getattr(conn, "linked_motion", 0):
        rows.append(_helical_row(link, P2))
    return rows


def _meeting(conn, meets):
    """(P2, (u2, v2, w2) or None): the point of the second solid that meets the joint's
    point, and its copy of the joint's basis when ``meets`` is a frame."""
    if meets is None:
        return conn.at, None
    if isinstance(meets, Frame):
        return meets.origin, tuple(meets.basis)
    check_point(meets, "meets")
    return meets, None


def _check_same_point(link, P1, P2, e, axis):
    """A condition along e that vanishes identically is dropped only if the two points also
    move together as points of their solids: (v(P2 in 2) - v(P1 in 1)) . e = 0. Otherwise
    (typically ``meets`` left out, the joint's point being a point of one solid only, as the
    end B of a coupler) the loop would silently stay open: refuse it."""
    first, second = link.first, link.second
    root = first.frame.root
    v2 = second.kinematic_torsor(relative_to=root, at=P2).velocity
    v1 = first.kinematic_torsor(relative_to=root, at=P1).velocity
    slip = sp.expand((v2 - v1).dot(e))
    if not _zero(slip, scale=[v1.dot(e), v2.dot(e)]):
        conn = link.connection
        raise ConnectionError_(
            f"{type(conn).__name__} at {P1.name} closes a loop between {first.name} and "
            f"{second.name}, but {P2.name} moves with only one of them (the difference of "
            f"its velocities as a point of each along {axis} is {slip}, not zero): the loop "
            f"would stay open. Give `meets`, the point of {second.name} that meets "
            f"{P1.name} when the loop is closed.")


def _fixed_in(vectors, solid, argument):
    """Refuse basis vectors that turn relative to ``solid``: the position form of an
    orientation closure needs vectors of each solid."""
    frame = vectors[0].parts[0][0]
    w = frame.rotation_vector(solid.frame)
    if not all(_zero(sp.expand(w.dot(e))) for e in frame.basis):
        raise ConnectionError_(
            f"the {argument} of the joint closing a loop must be fixed in {solid.name} (its "
            f"frame {frame.name} turns relative to {solid.frame.name}): build it on a frame "
            f"of {solid.name}.")


def _orientation_row(link, i, free, axes2, P2):
    """The closure of the relative rotation about e_i (i in 0, 1, 2 for u, v, w) that the
    joint blocks and the frames do not: with (i, j, k) cyclic, Φ = e_k(1) . e_j(2) (or
    -e_j(1) . e_k(2) when the rotation about e_k is free), vectors of the first solid and
    of the second (``meets``, a frame) that coincide when the loop is closed; dΦ/dt =
    (omega2 - omega1) . C with C = e_j(2) ^ e_k(1) (or e_j(1) ^ e_k(2)), the couple a unit
    multiplier stands for (C = e_i when closed)."""
    conn, first, second = link.connection, link.first, link.second
    if axes2 is None:
        raise ConnectionError_(
            f"{type(conn).__name__} at {conn.at.name} closes a loop between {first.name} and "
            f"{second.name} and blocks the relative rotation about {_AXES[i]}, which the "
            "frames do not block: give `meets` as a frame of the second solid whose origin "
            "meets the joint's point and whose axes (i, j, k) meet the joint's (u, v, w) "
            "when the loop is closed (only k is used when the joint allows a rotation about "
            "its axis).")
    _fixed_in(conn.basis, first, "axis")
    _fixed_in(axes2, second, "frame `meets`")
    e1 = conn.basis
    j, k = (i + 1) % 3, (i + 2) % 3
    if k in free:
        phi, couple = -e1[j].dot(axes2[k]), e1[j].cross(axes2[k])
    else:
        phi, couple = e1[k].dot(axes2[j]), axes2[j].cross(e1[k])
    phi = sp.expand(phi)
    if not phi.has(t):
        raise ConnectionError_(
            f"{type(conn).__name__} at {conn.at.name} between {first.name} and {second.name}: "
            f"the axes of the frame `meets` cannot meet the joint's (the closure of the "
            f"rotation about {_AXES[i]} is the constant {sp.simplify(phi)}).")
    return (f"{link.label}.r{_AXES[i]}", _time_derivative(phi), phi,
            [(second, Torsor(Vector.zero(), couple, P2)),
             (first, Torsor(Vector.zero(), -couple, conn.at))])


def _helical_row(link, P2):
    """The linked motion of a helical joint closing a loop, at the velocity level:
    (v(P2 in 2) - v(P1 in 1)) . w - h (omega2 - omega1) . w = 0 (no position form: its
    constant is the initial configuration's); a unit multiplier stands for the force w and
    the couple -h w on the second solid (the book's N = -h Z), their opposites on the
    first."""
    conn, first, second = link.connection, link.first, link.second
    root = first.frame.root
    w, h = conn.basis[2], conn.reduced_pitch
    v2 = second.kinematic_torsor(relative_to=root, at=P2).velocity
    v1 = first.kinematic_torsor(relative_to=root, at=conn.at).velocity
    omega = second.frame.rotation_vector(first.frame)
    c = sp.expand((v2 - v1).dot(w) - h * omega.dot(w))
    return (f"{link.label}.h", c, None,
            [(second, Torsor(w, -h * w, P2)), (first, Torsor(-w, h * w, conn.at))])
