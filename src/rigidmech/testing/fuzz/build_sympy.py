"""Build a :class:`~rigidmech.testing.fuzz.Model` in sympy.physics.mechanics, independently.

Nothing of rigidmech is used: frames are ``ReferenceFrame.orientnew`` (``"Axis"`` for an
elementary rotation, ``"Body"`` for three body-fixed angles), points ``Point.locatenew``,
every velocity is the derivative in N of the position from the fixed origin
(``pos_from(O).dt(N)``), bodies ``RigidBody`` and the equations come from ``KanesMethod``
with the kinematic differential equations u = q', so that Kane's speeds are the coordinates'
derivatives. The actions are written out by hand from their definitions (ch. 11-14): a
spring's force -k (l - l0) AB / l on B, a damper's -c l' AB / l, a torsional damper's couple
-c (omega(S/parent) . e) e.

Inertia convention: ``sympy.physics.mechanics.inertia(frame, ixx, iyy, izz, ixy, iyz, izx)``
takes the tensor's entries, whose off-diagonal ones are minus the book's products of inertia:
``ixy = -F, iyz = -D, izx = -E`` (ch. 15.1.3).

Examples
--------
>>> from rigidmech.testing.fuzz import BodySpec, Model, to_sympy
>>> kane = to_sympy(Model(bodies=(BodySpec(name="b0", parent=-1, joint="prismatic"),),
...                       gravity=(0.0, 0.0, -2.0)))
>>> kane.mass_matrix, kane.forcing
(Matrix([[1.0]]), Matrix([[-2.0]]))
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
import sympy as sp
from sympy.physics import mechanics as me

from ..._core.errors import ArgumentError
from .description import Model, coordinate_names

__all__ = ["to_sympy", "constant_dcm", "AXIAL"]


def _basis(frame):
    return (frame.x, frame.y, frame.z)


def _comps(frame, xyz):
    x, y, z = _basis(frame)
    return xyz[0] * x + xyz[1] * y + xyz[2] * z


def constant_dcm(rotations):
    """``F.dcm(parent)`` (numbers) of the frame F obtained from ``parent`` by the successive
    body-fixed rotations ``(axis index, angle)``: the product of the elementary direction
    cosine matrices, last rotation on the left.

    Examples
    --------
    >>> from sympy.physics.mechanics import ReferenceFrame
    >>> N = ReferenceFrame("N")
    >>> A = N.orientnew("A", "Axis", [0.3, N.x]).orientnew("B", "Axis", [-1.2, N.y])
    >>> import numpy as np
    >>> bool(np.allclose(np.array(A.dcm(N), dtype=float), constant_dcm(((0, 0.3), (1, -1.2)))))
    False
    >>> A = N.orientnew("A", "Axis", [0.3, N.x])
    >>> A = A.orientnew("B", "Axis", [-1.2, A.y])
    >>> bool(np.allclose(np.array(A.dcm(N), dtype=float), constant_dcm(((0, 0.3), (1, -1.2)))))
    True
    """
    D = np.eye(3)
    for axis, angle in rotations:
        c, s = np.cos(angle), np.sin(angle)
        E = np.eye(3)
        j, k = (axis + 1) % 3, (axis + 2) % 3
        E[j, j] = E[k, k] = c
        E[j, k], E[k, j] = s, -s
        D = E @ D
    return D


def _turn(frame, rotations, name):
    """``frame`` turned by constant rotations, as one frame oriented by its (numerical)
    direction cosine matrix: a chain of constant frames would make Kane's method multiply
    their matrices symbol by symbol (several times slower)."""
    if not rotations:
        return frame
    F = me.ReferenceFrame(name)
    F.orient_explicit(frame, sp.Matrix(constant_dcm(rotations).T))  # sets F.dcm(frame)=D
    return F


def _angles(F, seq, a, name):
    return F.orientnew(name, "Body", list(a), "".join(str(s + 1) for s in seq))


def _joint(b, F, P, q):
    """(C, origin of C) for the joint of ``b`` from the mount frame F at P."""
    n, e = b.name, _basis(F)[b.axis]
    u, v = _basis(F)[(b.axis + 1) % 3], _basis(F)[(b.axis + 2) % 3]
    kind = b.joint
    if kind == "pivot":
        return F.orientnew(f"{n}_C", "Axis", [q[0], e]), P
    if kind == "prismatic":
        return F, P.locatenew(f"{n}_S", q[0] * e)
    if kind == "cylindrical":
        return F.orientnew(f"{n}_C", "Axis", [q[0], e]), P.locatenew(f"{n}_S", q[1] * e)
    if kind == "helical":
        h = sp.Float(b.pitch) / (2 * sp.pi)
        return F.orientnew(f"{n}_C", "Axis", [q[0], e]), P.locatenew(f"{n}_S", h * q[0] * e)
    if kind == "spherical":
        return _angles(F, b.angles, q, f"{n}_C"), P
    if kind == "planar":
        return (F.orientnew(f"{n}_C", "Axis", [q[2], e]),
                P.locatenew(f"{n}_S", q[0] * u + q[1] * v))
    if kind == "annular":
        return _angles(F, b.angles, q[1:], f"{n}_C"), P.locatenew(f"{n}_S", q[0] * e)
    if kind == "point":
        return (_angles(F, b.angles, q[2:], f"{n}_C"),
                P.locatenew(f"{n}_S", q[0] * u + q[1] * v))
    if kind == "free":
        return _angles(F, b.angles, q[3:], f"{n}_C"), P.locatenew(f"{n}_S", _comps(F, q[:3]))
    if kind == "polar":
        H = F.orientnew(f"{n}_H", "Axis", [q[1], e])
        return F, P.locatenew(f"{n}_S", q[0] * _basis(H)[(b.axis + 1) % 3])
    raise ValueError(f"unknown joint {kind!r}")


#: joints whose action is compared (a local basis from their axis, as rigidmech's)
AXIAL = ("pivot", "prismatic", "cylindrical", "helical", "planar", "annular", "point")
#: the point the action of each joint is reduced at: the joint point P fixed in the parent,
#: or the moving centre S of the sphere (annular) or the contact point (point)
_AT_CENTRE = ("annular", "point")


class DegenerateModel(ArgumentError):
    """The model has no well-defined equations to compare (e.g. redundant closure
    conditions); :func:`~rigidmech.testing.fuzz.compare` reports it as ``'degenerate'``.

    Examples
    --------
    >>> issubclass(DegenerateModel, ValueError)
    True
    """


def _subtree(model, c):
    out = {c}
    for k, b in enumerate(model.bodies):
        if b.parent in out:
            out.add(k)
    return out


def to_sympy(model: Model, *, action_of=None, closure="multipliers") -> me.KanesMethod:
    """The ``KanesMethod`` of ``model``, its equations formed.

    Its ``q`` are ``dynamicsymbols`` named as :func:`~rigidmech.testing.fuzz.coordinate_names`
    and its ``u`` the speeds with u = q' (``mass_matrix`` and ``forcing`` give
    M(q) u' = f(q, u)).

    With ``action_of`` (a body index whose joint is in :data:`AXIAL`), the action of its
    parent on it is sought with six auxiliary speeds (``u_auxiliary``): a relative velocity
    and a rotation of the body's subtree along the joint's local basis (u, v, w) at the
    joint's point, and the unknown action X u + Y v + Z w, moment L u + M v + N w, on the
    body there (symbols ``X, Y, Z, L, M, N`` in ``kane.action_symbols``). The
    auxiliary equations ``kane.auxiliary_eqs`` then give them once u' is known; the
    unknowns are zero in ``mass_matrix`` and ``forcing``.

    A model with a closing joint (``model.closure``) gets in ``kane.closure`` the numeric
    functions of its conditions (``phi``, ``jacobian``, ``bias`` = J' q', the dependent
    coordinates and the assembly). With ``closure="kane"`` the conditions go to Kane's method
    (``q_dependent``, ``configuration_constraints``, ``u_dependent``,
    ``velocity_constraints``); with ``closure="multipliers"`` (default) the tree's equations
    are formed without them and :func:`~rigidmech.testing.fuzz.compare` adds the constraint
    force J^T lambda (the reference used, see the note in ``compare``).
    """
    names = coordinate_names(model)
    q = dict(zip(names, me.dynamicsymbols(names), strict=True)) if len(names) > 1 else {
        names[0]: me.dynamicsymbols(names[0])}
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    W = _turn(N, model.ground, "W")
    OW = O.locatenew("OW", _comps(N, model.ground_origin))

    owned = []  # (point, body index) of every point with a velocity

    def moving(point, owner):
        point.set_vel(N, point.pos_from(O).dt(N))
        owned.append((point, owner))
        return point

    frames, origins, mounts, rigid, joint_points = [], [], [], [], []
    for k, b in enumerate(model.bodies):
        Pf, Po = (W, OW) if b.parent < 0 else (frames[b.parent], origins[b.parent])
        P = Po.locatenew(f"{b.name}_P", _comps(Pf, b.at))
        F = _turn(Pf, b.mount, f"{b.name}_F")
        qb = [q[f"{model.prefix}_{b.name}_{k}"] for k in range(len(b.joint_kinds))]
        C, Oc = _joint(b, F, P, qb)
        B = _turn(C, b.twist, f"{b.name}_B")
        G = moving(Oc.locatenew(f"{b.name}_G", _comps(B, b.centre)), k)
        A, Bm, Cm, D, E, Fp = b.inertia
        inertia = me.inertia(B, A, Bm, Cm, ixy=-Fp, iyz=-D, izx=-E)
        rigid.append(me.RigidBody(b.name, G, B, b.mass, (inertia, G)))
        frames.append(B)
        origins.append(Oc)
        mounts.append(F)
        joint_points.append(Oc if b.joint in _AT_CENTRE else P)

    def point(k, xyz, label):
        frame, origin = (W, OW) if k < 0 else (frames[k], origins[k])
        return moving(origin.locatenew(label, _comps(frame, xyz)), k)

    loads = []
    if model.gravity is not None:
        g = _comps(W, model.gravity)
        loads += [(body.masscenter, body.mass * g) for body in rigid]
    for j, s in enumerate(model.springs + model.dampers):
        A_, B_ = point(s.body_a, s.a, f"A{j}"), point(s.body_b, s.b, f"B{j}")
        AB = B_.pos_from(A_)
        length = sp.sqrt(AB.dot(AB))
        if hasattr(s, "k"):
            tension = s.k * (length - s.l0)
        else:
            tension = s.c * AB.dot(B_.vel(N) - A_.vel(N)) / length
        force = -tension * AB / length
        if s.body_b >= 0:
            loads.append((B_, force))
        if s.body_a >= 0:
            loads.append((A_, -force))
    for c in model.torques:
        M = _comps(frames[c.body], c.moment)
        loads.append((frames[c.body], M))
        parent = model.bodies[c.body].parent
        if c.reaction and parent >= 0:
            loads.append((frames[parent], -M))
    for j, f in enumerate(model.forces):
        loads.append((point(f.body, f.at, f"Fa{j}"), _comps(W, f.vector)))
    for d in model.torsional_dampers:
        parent = model.bodies[d.body].parent
        e = _basis(mounts[d.body])[model.bodies[d.body].axis]
        Bp = N if parent < 0 else frames[parent]
        M = -d.c * (frames[d.body].ang_vel_in(N) - Bp.ang_vel_in(N)).dot(e) * e
        loads.append((frames[d.body], M))
        if parent >= 0:
            loads.append((frames[parent], -M))
    qs = [q[n] for n in names]
    us = me.dynamicsymbols([f"u_{n}" for n in names]) if len(names) > 1 else [
        me.dynamicsymbols(f"u_{names[0]}")]
    aux, unknowns = [], []
    if action_of is not None:
        aux, unknowns, extra = _auxiliary(model, action_of, N, frames, mounts, rigid, owned,
                                          joint_points[action_of])
        loads = loads + extra
    kd = [qi.diff() - ui for qi, ui in zip(qs, us, strict=True)]
    closing = {}
    if model.closure is not None:
        closing = _closure(model, q, qs, us, W, OW, frames, origins)
        if closure == "kane":
            dep = closing["dependent"]
            qs = [x for k, x in enumerate(qs) if k not in dep]
            us = [x for k, x in enumerate(us) if k not in dep]
        else:
            closing.pop("kane")
            closing["numeric"]["order"] = list(range(len(qs)))
    kane = me.KanesMethod(N, q_ind=qs, u_ind=us, u_auxiliary=aux, kd_eqs=kd,
                          **closing.get("kane", {}))
    kane.kanes_equations(rigid, loads)
    kane.action_symbols = tuple(unknowns)
    kane.closure = closing.get("numeric")
    kane.closure_method = closure
    return kane


def _closure(model, q, qs, us, W, OW, frames, origins):
    """The spherical closing joint: its three conditions (the body's point at the ground
    point D where it is in the assembled configuration), the dependent coordinates (the
    best-conditioned columns of the conditions' Jacobian at the assembly: QR with column
    pivoting) and their numeric functions for the consistent states."""
    c = model.closure
    meets = origins[c.body].locatenew("Mc", _comps(frames[c.body], c.meets))
    r = meets.pos_from(OW).to_matrix(W)
    values = {q[n]: v for n, v in model.assembly_values().items()}
    D = [float(x.xreplace(values)) for x in r]
    phi = sp.Matrix([r[i] - D[i] for i in range(3)])
    qsym = sp.symbols(f"_c0:{len(qs)}")
    rule = dict(zip(qs, qsym, strict=True))
    fphi = sp.lambdify([qsym], list(phi.xreplace(rule)), "numpy")
    fjac = sp.lambdify([qsym], phi.jacobian(qs).xreplace(rule), "numpy")
    q0 = np.array([values[x] for x in qs])
    J0 = np.array(fjac(q0), dtype=float)
    if np.linalg.matrix_rank(J0, tol=1e-8 * max(np.max(np.abs(J0)), 1.0)) < 3:
        raise DegenerateModel(
            "the closing joint's three conditions are not independent at the assembly (a "
            "locked or redundant loop)")
    pivots = scipy.linalg.qr(J0, pivoting=True)[2]
    dep = sorted(int(k) for k in pivots[:3])
    speeds = dict(zip([x.diff() for x in qs], us, strict=True))
    t = me.dynamicsymbols._t
    velocity = [e.diff(t).xreplace(speeds) for e in phi]
    # J' q': the second derivative of the conditions without its q'' terms
    no_acc = dict.fromkeys([x.diff(t, 2) for x in qs], 0)
    bias = [e.diff(t, 2).xreplace(no_acc).xreplace(speeds) for e in phi]
    usym = sp.symbols(f"_v0:{len(qs)}")
    fbias = sp.lambdify([qsym, usym], [sp.sympify(b).xreplace(
        {**rule, **dict(zip(us, usym, strict=True))}) for b in bias], "numpy")
    order = [k for k in range(len(qs)) if k not in dep] + dep  # kane.q: independent first
    return {
        "dependent": dep,
        "kane": {"q_dependent": [qs[k] for k in dep], "configuration_constraints": list(phi),
                 "u_dependent": [us[k] for k in dep], "velocity_constraints": velocity},
        "numeric": {"phi": lambda x: np.array(fphi(x), dtype=float),
                    "jacobian": lambda x: np.array(fjac(x), dtype=float),
                    "bias": lambda x, v: np.array(fbias(x, v), dtype=float),
                    "dependent": dep, "assembly": q0, "order": order},
    }


def _auxiliary(model, c, N, frames, mounts, rigid, owned, P):
    """Auxiliary speeds of the subtree of body ``c`` at its joint point P, and the loads of
    the unknown action on ``c``."""
    b = model.bodies[c]
    if b.joint not in AXIAL:
        raise ArgumentError(
            f"`action_of` must be a body on one of the joints {AXIAL}; body {c} is on a "
            f"{b.joint!r} joint.")
    F = mounts[c]
    e = _basis(F)
    u, v, w = e[(b.axis + 1) % 3], e[(b.axis + 2) % 3], e[b.axis]
    ua = me.dynamicsymbols(f"ua_{b.name}_1:7")
    dv = ua[0] * u + ua[1] * v + ua[2] * w
    dw = ua[3] * u + ua[4] * v + ua[5] * w
    carried = _subtree(model, c)
    omega = {k: frames[k].ang_vel_in(N) for k in carried}
    Bc, Gc = frames[c], rigid[c].masscenter
    Pc = P.locatenew(f"{b.name}_Pc", 0)  # the point of the body at P
    Pc.set_vel(N, Gc.vel(N) + omega[c].cross(P.pos_from(Gc)) + dv)
    for point, owner in owned:
        if owner in carried:
            point.set_vel(N, point.vel(N) + dv + dw.cross(point.pos_from(P)))
    for k in carried:
        frames[k].set_ang_vel(N, omega[k] + dw)
    X, Y, Z, L, M, Nn = sp.symbols("X Y Z L M N")
    loads = [(Pc, X * u + Y * v + Z * w), (Bc, L * u + M * v + Nn * w)]
    return list(ua), (X, Y, Z, L, M, Nn), loads
