"""Build a :class:`~rigidmech.testing.fuzz.Model` with rigidmech's public API.

Frames (``Frame.rotated``, ``translated``, ``euler``), points (``Point.moved``), bodies,
joints of the catalogue (``rm.joints``), ``System.connect`` / ``System.add`` and the actions
(``rm.gravity``, ``rm.Spring``, ``rm.actions.Damper``, ``rm.Couple``, ``rm.Force``,
``rm.actions.TorsionalDamper``): what a user writes, nothing internal.

Examples
--------
>>> from rigidmech.testing.fuzz import BodySpec, Model, to_rigidmech
>>> system = to_rigidmech(Model(bodies=(BodySpec(name="b0", parent=-1, joint="pivot"),),
...                             gravity=(0.0, -9.81, 0.0)))
>>> [q.func.__name__ for q in system.equations_of_motion().coordinates]
['q_b0_0']
"""

from __future__ import annotations

import sympy as sp

import rigidmech as rm
from rigidmech.inertia import InertiaOperator
from rigidmech.kinematics import ContactKinematics
from rigidmech.kinematics.surfaces import Circle, Plane, Sphere

from .description import ROLLING, Model, coordinate_names

__all__ = ["to_rigidmech", "ground_frame"]


_EXACT = [True]


def _x(value):
    """A number of the description as an exact rational (the grid values are binary
    fractions, so nothing is rounded): exact models keep rigidmech's symbolic decisions
    exact (joint checks, closures). Floats with ``to_rigidmech(..., exact=False)``: those
    decisions then tolerate their round-off (1e-16 q') relative to the size of the terms."""
    return sp.Rational(value) if _EXACT[-1] else float(value)


def _basis(frame):
    return (frame.i, frame.j, frame.k)


def _comps(frame, xyz):
    i, j, k = _basis(frame)
    return _x(xyz[0]) * i + _x(xyz[1]) * j + _x(xyz[2]) * k


def _turn(frame, rotations, prefix, origin=None):
    """``frame`` turned by the constant rotations (the first one moved to ``origin``)."""
    for j, (axis, angle) in enumerate(rotations):
        frame = frame.rotated(f"{prefix}{j}", about=_basis(frame)[axis], angle=_x(angle),
                              origin=origin if j == 0 else None)
    return frame


def ground_frame(R0, model: Model):
    """The frame the ground parts of ``model`` are given in: ``R0`` itself, or ``R0`` moved
    to ``model.ground_origin`` and turned by ``model.ground`` (fixed in R0).

    Examples
    --------
    >>> from rigidmech.testing.fuzz import BodySpec, Model
    >>> R0 = rm.Frame("R0")
    >>> ground_frame(R0, Model(bodies=(BodySpec(name="b", parent=-1, joint="pivot"),))) is R0
    True
    """
    if not model.ground and not any(model.ground_origin):
        return R0
    W = R0.translated("W_", R0.point("Og_", *map(_x, model.ground_origin)))
    return _turn(W, model.ground, "W")


def _angles(F, seq, a, name, origin):
    if tuple(seq) == (2, 0, 2):
        return F.euler(name, *a, origin=origin)
    X = F
    for j in range(3):
        X = X.rotated(name if j == 2 else f"{name}_A{j}", about=_basis(X)[seq[j]],
                      angle=a[j], origin=origin if j == 0 else None)
    return X


def _joint_frame(b, F, q):
    """The frame C moved by the joint relative to the mount frame F (see ``JOINTS``), and
    the point the joint object is reduced at."""
    n, e = b.name, _basis(F)[b.axis]
    u, v = _basis(F)[(b.axis + 1) % 3], _basis(F)[(b.axis + 2) % 3]
    O = F.origin
    kind = b.joint
    if kind == "pivot":
        return F.rotated(f"{n}_C", about=e, angle=q[0]), O
    if kind == "prismatic":
        return F.translated(f"{n}_C", O.moved(f"{n}_S", q[0] * e)), O
    if kind == "cylindrical":
        return F.rotated(f"{n}_C", about=e, angle=q[0],
                         origin=O.moved(f"{n}_S", q[1] * e)), O
    if kind == "helical":
        S = O.moved(f"{n}_S", _x(b.pitch) / (2 * sp.pi) * q[0] * e)
        return F.rotated(f"{n}_C", about=e, angle=q[0], origin=S), O
    if kind == "spherical":
        return _angles(F, b.angles, q, f"{n}_C", O), O
    if kind == "planar":
        S = O.moved(f"{n}_S", q[0] * u + q[1] * v)
        return F.rotated(f"{n}_C", about=e, angle=q[2], origin=S), O
    if kind == "annular":
        S = O.moved(f"{n}_S", q[0] * e)
        return _angles(F, b.angles, q[1:], f"{n}_C", S), S
    if kind == "point":
        S = O.moved(f"{n}_S", q[0] * u + q[1] * v)
        return _angles(F, b.angles, q[2:], f"{n}_C", S), S
    if kind == "free":
        S = O.moved(f"{n}_S", q[0] * F.i + q[1] * F.j + q[2] * F.k)
        return _angles(F, b.angles, q[3:], f"{n}_C", S), S
    if kind == "polar":
        H = F.rotated(f"{n}_H", about=e, angle=q[1])
        S = O.moved(f"{n}_S", q[0] * _basis(H)[(b.axis + 1) % 3])
        return F.translated(f"{n}_C", S), O
    if kind == "ball":
        I = O.moved(f"{n}_I", q[0] * u + q[1] * v)
        return _angles(F, b.angles, q[2:], f"{n}_C", I.moved(f"{n}_S", _x(b.radius) * e)), I
    if kind == "disc":
        I = O.moved(f"{n}_I", q[0] * u + q[1] * v)
        A = F.rotated(f"{n}_A", about=e, angle=q[2])
        Bl = A.rotated(f"{n}_L", about=_basis(A)[(b.axis + 1) % 3], angle=q[3])
        centre = I.moved(f"{n}_S", _x(b.radius) * _basis(Bl)[(b.axis + 2) % 3])
        return Bl.rotated(f"{n}_C", about=_basis(Bl)[b.axis], angle=q[4], origin=centre), I
    raise ValueError(f"unknown joint {kind!r}")


def _joint(b, F, at):
    e = _basis(F)[b.axis]
    return {
        "pivot": lambda: rm.joints.Pivot(at=at, axis=e),
        "prismatic": lambda: rm.joints.Prismatic(at=at, axis=e),
        "cylindrical": lambda: rm.joints.Cylindrical(at=at, axis=e),
        "helical": lambda: rm.joints.Helical(at=at, axis=e, pitch=_x(b.pitch)),
        "spherical": lambda: rm.joints.Spherical(at=at),
        "planar": lambda: rm.joints.PlanarSupport(at=at, normal=e),
        "polar": lambda: rm.joints.PlanarSupport(at=at, normal=e),
        "annular": lambda: rm.joints.LinearAnnular(at=at, axis=e),
        "point": lambda: rm.joints.PointContact(at=at, normal=e),
    }[b.joint]()


def _rolling(b, F, C, I, body, parent):
    """The rolling contact of a ``ball`` or ``disc`` body on the plane of F."""
    e = _basis(F)[b.axis]
    if b.contact == "between":
        surface = (Sphere(C.origin, _x(b.radius)) if b.joint == "ball"
                   else Circle(C.origin, _x(b.radius), normal=_basis(C)[b.axis]))
        kin = ContactKinematics.between(body, surface, parent, Plane(F.origin, e),
                                        name=f"{b.name}_Ic")
    else:
        kin = ContactKinematics(body, parent, at=I, normal=e)
    return rm.actions.RollingContact(kin, pivoting=bool(b.pivoting))


def _coordinates(model):
    names = coordinate_names(model)
    qs = rm.coordinates(" ".join(names))
    return dict(zip(names, qs if isinstance(qs, tuple) else (qs,), strict=True))


def to_rigidmech(model: Model, *, coordinates=None, exact=True):
    """The :class:`rigidmech.System` of ``model`` (Galilean frame ``R0``).

    Parameters
    ----------
    model : Model
    coordinates : sequence of str, optional
        Names of the coordinates in the order the system should use (given to
        :class:`~rigidmech.System`); default: rigidmech's own order.
    exact : bool
        Give rigidmech the numbers as exact rationals (default) or as floats.

    Returns
    -------
    System
        Its bodies in the order of ``model.bodies``.
    """
    _EXACT.append(bool(exact))
    try:
        return _build(model, coordinates)
    finally:
        _EXACT.pop()


def _build(model, coordinates):
    q = _coordinates(model)
    R0 = rm.Frame("R0")
    W = ground_frame(R0, model)
    order = None if coordinates is None else [q[n] for n in coordinates]
    system = rm.System(galilean=R0, coordinates=order)
    bodies, mounts, joints = [], [], []
    for b in model.bodies:
        Pf = W if b.parent < 0 else bodies[b.parent].frame
        parent = R0 if b.parent < 0 else bodies[b.parent]
        P = Pf.origin.moved(f"{b.name}_P", _comps(Pf, b.at))
        F = (_turn(Pf, b.mount, f"{b.name}_F", origin=P) if b.mount
             else Pf.translated(f"{b.name}_F", P))
        qb = [q[f"{model.prefix}_{b.name}_{k}"] for k in range(len(b.joint_kinds))]
        C, at = _joint_frame(b, F, qb)
        B = _turn(C, b.twist, f"{b.name}_B") if b.twist else C
        G = B.origin.moved(f"{b.name}_G", _comps(B, b.centre))
        body = rm.Body(b.name, frame=B, mass=_x(b.mass), centre=G,
                       inertia=InertiaOperator.from_products(*map(_x, b.inertia), frame=B,
                                                             at=G))
        if b.joint == "free" or (b.joint == "polar" and b.parent < 0):
            system.add(body)
        elif b.joint in ROLLING:
            system.connect(parent, body, _rolling(b, F, C, at, body, parent))
        else:
            system.connect(parent, body, _joint(b, F, at))
        bodies.append(body)
        mounts.append(F)
        joints.append(C)

    def point(k, xyz, label):
        frame = W if k < 0 else bodies[k].frame
        return frame.origin.moved(label, _comps(frame, xyz))

    def solid(k):
        return None if k < 0 else bodies[k]

    def parent_of(k):
        return solid(model.bodies[k].parent)

    if model.gravity is not None:
        system.act(rm.gravity(_comps(W, model.gravity)))
    for j, s in enumerate(model.springs):
        system.act(rm.Spring(_x(s.k), _x(s.l0), a=point(s.body_a, s.a, f"Ka{j}"),
                             b=point(s.body_b, s.b, f"Kb{j}"), on_a=solid(s.body_a),
                             on_b=solid(s.body_b)))
    for j, d in enumerate(model.dampers):
        system.act(rm.actions.Damper(_x(d.c), a=point(d.body_a, d.a, f"Da{j}"),
                                     b=point(d.body_b, d.b, f"Db{j}"), on_a=solid(d.body_a),
                                     on_b=solid(d.body_b)))
    for c in model.torques:
        system.act(rm.Couple(on=bodies[c.body], moment=_comps(bodies[c.body].frame, c.moment),
                             reaction_on=parent_of(c.body) if c.reaction else None))
    for j, f in enumerate(model.forces):
        system.act(rm.Force(on=bodies[f.body], vector=_comps(W, f.vector),
                            at=point(f.body, f.at, f"Fa{j}")))
    for d in model.torsional_dampers:
        e = _basis(mounts[d.body])[model.bodies[d.body].axis]
        system.act(rm.actions.TorsionalDamper(_x(d.c), axis=e, on=bodies[d.body],
                                              reaction_on=parent_of(d.body)))
    for j, k in enumerate(model.knives):
        F, C = mounts[k.body], joints[k.body]
        axis = model.bodies[k.body].axis
        u, v = _basis(C)[(axis + 1) % 3], _basis(C)[(axis + 2) % 3]
        P = C.origin.moved(f"Pk{j}", _x(k.at[0]) * u + _x(k.at[1]) * v)
        angle = _x(k.angle)
        system.connect(parent_of(k.body) or R0, bodies[k.body], rm.actions.KnifeEdge(
            bodies[k.body], parent_of(k.body) or R0, at=P,
            direction=sp.cos(angle) * u + sp.sin(angle) * v, normal=_basis(F)[axis]))
    if model.closure is not None:
        _close(system, model, q, W, bodies, R0)
    return system


def _close(system, model, q, W, bodies, R0):
    """The joint closing the loop, at the ground point where the body's point is in the
    assembled configuration (computed here from rigidmech's own kinematics)."""
    c = model.closure
    body = bodies[c.body]
    meets = body.frame.origin.moved("Mc", _comps(body.frame, c.meets))
    values = {q[n]: _x(v) for n, v in model.assembly_values().items()}
    where = (meets - W.origin).components(W).subs(values)
    D = W.origin.moved("Dc", _comps(W, [float(sp.N(x, 30)) for x in where]))
    n = _basis(W)[c.plane]
    joint = {
        "spherical": lambda: rm.joints.Spherical(at=D),
        "pivot": lambda: rm.joints.Pivot(at=D, axis=n),
        # the line's direction: an axis of the ground frame turned about the normal
        "slider": lambda: rm.joints.LinearAnnular(at=D, axis=_basis(W.rotated(
            "Wd", about=n, angle=_x(c.direction)))[(c.plane + 1) % 3]),
    }[c.kind]()
    system.connect(R0, body, joint, meets=meets)
