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
(Matrix([[1]]), Matrix([[-2]]))
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
import sympy as sp
from sympy.physics import mechanics as me

from ..._core.errors import ArgumentError
from .description import ROLLING, Model, coordinate_names, coordinate_ranges

__all__ = ["to_sympy", "constant_dcm", "AXIAL"]


def _basis(frame):
    return (frame.x, frame.y, frame.z)


def _r(value):
    """A number of the description as an exact rational (the grid values are binary
    fractions; a coordinate passes through)."""
    return sp.Rational(value) if isinstance(value, (int, float)) else value


def _comps(frame, xyz):
    x, y, z = _basis(frame)
    return _r(xyz[0]) * x + _r(xyz[1]) * y + _r(xyz[2]) * z


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
        h = _r(b.pitch) / (2 * sp.pi)
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
    if kind == "ball":
        return (_angles(F, b.angles, q[2:], f"{n}_C"),
                _contact_point(b, F, P, q).locatenew(f"{n}_S", _r(b.radius) * e))
    if kind == "disc":
        A = F.orientnew(f"{n}_A", "Axis", [q[2], e])
        Bl = A.orientnew(f"{n}_L", "Axis", [q[3], _basis(A)[(b.axis + 1) % 3]])
        centre = _contact_point(b, F, P, q).locatenew(
            f"{n}_S", _r(b.radius) * _basis(Bl)[(b.axis + 2) % 3])
        return Bl.orientnew(f"{n}_C", "Axis", [q[4], _basis(Bl)[b.axis]]), centre
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


def _contact_point(b, F, P, q):
    """The contact point I = P + q1 u + q2 v of a rolling body on the plane of F."""
    u, v = _basis(F)[(b.axis + 1) % 3], _basis(F)[(b.axis + 2) % 3]
    return P.locatenew(f"{b.name}_I", q[0] * u + q[1] * v)


def _subtree(model, c):
    out = {c}
    for k, b in enumerate(model.bodies):
        if b.parent in out:
            out.add(k)
    return out


def to_sympy(model: Model, *, action_of=None, closure="multipliers", equations=True
             ) -> me.KanesMethod:
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

    A constrained model (a closing joint ``model.closure``: holonomic conditions; rolling
    bodies and knife edges: nonholonomic ones) gets in ``kane.closure`` the numeric functions
    of its conditions (``jacobian`` A of the velocity conditions A q' = 0, ``bias`` = A' q',
    the holonomic residual ``phi`` and ``phi_jacobian``, the dependent coordinates, the
    assembly, the coordinates' ``ranges``). With ``closure="kane"`` the conditions go to
    Kane's method (``q_dependent``, ``configuration_constraints``, ``u_dependent``,
    ``velocity_constraints``: sympy's documented usage); with ``closure="multipliers"``
    (default) the tree's equations are formed without them and
    :func:`~rigidmech.testing.fuzz.compare` adds the constraint force A^T lambda (the
    reference used, see the note in ``compare``).

    With ``equations=False`` Kane's equations are not formed: the KanesMethod has only its
    coordinates, speeds and ``closure`` (the consistent states of a constrained model, for
    the metamorphic tests, at a fraction of the cost).
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

    frames, origins, mounts, rigid, joint_points, joint_frames = [], [], [], [], [], []
    contacts = {}  # body index -> its contact point I (rolling bodies)
    for k, b in enumerate(model.bodies):
        Pf, Po = (W, OW) if b.parent < 0 else (frames[b.parent], origins[b.parent])
        P = Po.locatenew(f"{b.name}_P", _comps(Pf, b.at))
        F = _turn(Pf, b.mount, f"{b.name}_F")
        qb = [q[f"{model.prefix}_{b.name}_{k}"] for k in range(len(b.joint_kinds))]
        C, Oc = _joint(b, F, P, qb)
        joint_frames.append(C)
        if b.joint in ROLLING:
            contacts[k] = _contact_point(b, F, P, qb)
        B = _turn(C, b.twist, f"{b.name}_B")
        G = moving(Oc.locatenew(f"{b.name}_G", _comps(B, b.centre)), k)
        A, Bm, Cm, D, E, Fp = map(_r, b.inertia)
        inertia = me.inertia(B, A, Bm, Cm, ixy=-Fp, iyz=-D, izx=-E)
        rigid.append(me.RigidBody(b.name, G, B, _r(b.mass), (inertia, G)))
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
            tension = _r(s.k) * (length - _r(s.l0))
        else:
            tension = _r(s.c) * AB.dot(B_.vel(N) - A_.vel(N)) / length
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
        M = -_r(d.c) * (frames[d.body].ang_vel_in(N) - Bp.ang_vel_in(N)).dot(e) * e
        loads.append((frames[d.body], M))
        if parent >= 0:
            loads.append((frames[parent], -M))
    qs = [q[n] for n in names]
    us = me.dynamicsymbols([f"u_{n}" for n in names]) if len(names) > 1 else [
        me.dynamicsymbols(f"u_{names[0]}")]
    # the conditions are written before the auxiliary speeds change the velocities
    holonomic, nonholonomic = _conditions(model, q, N, W, OW, frames, origins, mounts, rigid,
                                          contacts, joint_frames)
    aux, unknowns = [], []
    if action_of is not None:
        aux, unknowns, extra = _auxiliary(model, action_of, N, frames, mounts, rigid, owned,
                                          joint_points[action_of])
        loads = loads + extra
    kd = [qi.diff() - ui for qi, ui in zip(qs, us, strict=True)]
    closing = {}
    if holonomic or nonholonomic:
        closing = _constraints(model, q, qs, us, holonomic, nonholonomic)
        if closure == "kane":
            dep = closing["dependent"]
            qs = [x for k, x in enumerate(qs) if k not in dep]
            us = [x for k, x in enumerate(us) if k not in closing["dependent_speeds"]]
        else:
            closing.pop("kane")
            closing["numeric"]["order"] = list(range(len(qs)))
    kane = me.KanesMethod(N, q_ind=qs, u_ind=us, u_auxiliary=aux, kd_eqs=kd,
                          **closing.get("kane", {}))
    if equations:
        kane.kanes_equations(rigid, loads)
    kane.action_symbols = tuple(unknowns)
    kane.closure = closing.get("numeric")
    kane.closure_method = closure
    return kane


def _velocity_of(k, X, N, rigid):
    """The velocity in N of the point of body ``k`` (-1: the ground) at the point X."""
    if k < 0:
        return me.Vector(0)
    G = rigid[k].masscenter
    return G.vel(N) + rigid[k].frame.ang_vel_in(N).cross(X.pos_from(G))


def _conditions(model, q, N, W, OW, frames, origins, mounts, rigid, contacts, joint_frames):
    """(holonomic conditions phi(q), nonholonomic conditions linear in q'): the closing
    joint's, the rolling contacts' (the tangential components of the sliding velocity
    v(I in S2) - v(I in S1), and the spin (omega(S2) - omega(S1)) . n without pivoting,
    ch. 10.1.3) and the knife edges' (the lateral component of v(P in S2/S1))."""
    holonomic, nonholonomic = [], []
    for k, I in contacts.items():
        b = model.bodies[k]
        e = _basis(mounts[k])
        slip = _velocity_of(k, I, N, rigid) - _velocity_of(b.parent, I, N, rigid)
        nonholonomic += [slip.dot(e[(b.axis + 1) % 3]), slip.dot(e[(b.axis + 2) % 3])]
        if not b.pivoting:
            spin = frames[k].ang_vel_in(N) - (N if b.parent < 0 else frames[b.parent]
                                              ).ang_vel_in(N)
            nonholonomic.append(spin.dot(e[b.axis]))
    for j, knife in enumerate(model.knives):
        k, b = knife.body, model.bodies[knife.body]
        C, F = joint_frames[k], mounts[k]
        u, v = _basis(C)[(b.axis + 1) % 3], _basis(C)[(b.axis + 2) % 3]
        P = origins[k].locatenew(f"Pk{j}", _r(knife.at[0]) * u + _r(knife.at[1]) * v)
        angle = _r(knife.angle)
        lateral = _basis(F)[b.axis].cross(sp.cos(angle) * u + sp.sin(angle) * v)
        slip = _velocity_of(k, P, N, rigid) - _velocity_of(b.parent, P, N, rigid)
        nonholonomic.append(slip.dot(lateral))
    c = model.closure
    if c is not None:
        meets = origins[c.body].locatenew("Mc", _comps(frames[c.body], c.meets))
        r = meets.pos_from(OW).to_matrix(W)
        values = {q[n]: v for n, v in model.assembly_values().items()}
        D = [float(x.xreplace(values)) for x in r]
        gap = [r[i] - D[i] for i in range(3)]
        n = c.plane
        if c.kind == "spherical":
            holonomic = gap
        elif c.kind == "pivot":  # a planar loop: the two components in the plane
            holonomic = [gap[(n + 1) % 3], gap[(n + 2) % 3]]
        else:  # slider along d = cos u + sin v: the component along n ^ d in the plane
            a = _r(c.direction)
            holonomic = [-sp.sin(a) * gap[(n + 1) % 3] + sp.cos(a) * gap[(n + 2) % 3]]
    return holonomic, nonholonomic


def _constraints(model, q, qs, us, holonomic, nonholonomic):
    """The conditions on both sides' terms: for the tree's equations with the constraint
    force A^T lambda (``numeric``: the rows A(q) q' = 0 of the velocity conditions and
    their bias A' q', the holonomic residual phi and its Jacobian, the dependent
    coordinates -- the best-conditioned columns of the Jacobian at the assembly: QR with
    column pivoting --, the assembly and the coordinates' ranges), and for Kane's method
    with dependent coordinates and speeds (``kane``)."""
    t = me.dynamicsymbols._t
    speeds = dict(zip([x.diff(t) for x in qs], us, strict=True))
    phi = sp.Matrix(holonomic)
    velocity = [e.diff(t).xreplace(speeds) for e in holonomic] + [
        sp.sympify(e).xreplace(speeds) for e in nonholonomic]
    A = sp.Matrix(velocity).jacobian(us)
    # A' q': the derivative of the velocity conditions without its u' terms
    no_acc = {**dict.fromkeys([x.diff(t, 2) for x in qs], 0),
              **dict.fromkeys([x.diff(t) for x in us], 0)}
    bias = [sp.sympify(e).diff(t).xreplace(no_acc).xreplace(speeds) for e in velocity]
    qsym, usym = sp.symbols(f"_c0:{len(qs)}"), sp.symbols(f"_v0:{len(qs)}")
    rule = {**dict(zip(us, usym, strict=True)), **dict(zip(qs, qsym, strict=True))}
    fA = sp.lambdify([qsym], A.xreplace(rule), "numpy")
    fbias = sp.lambdify([qsym, usym], [sp.sympify(b).xreplace(rule) for b in bias], "numpy")
    ranges = coordinate_ranges(model)
    numeric = {"jacobian": lambda x: np.array(fA(x), dtype=float).reshape(len(velocity), -1),
               "bias": lambda x, v: np.array(fbias(x, v), dtype=float).reshape(-1),
               "ranges": np.array([ranges[str(x.func)] for x in qs]),
               "dependent": [], "assembly": None, "phi": None}
    dep = []
    if holonomic:
        fphi = sp.lambdify([qsym], list(phi.xreplace(rule)), "numpy")
        fjac = sp.lambdify([qsym], phi.jacobian(qs).xreplace(rule), "numpy")
        values = {q[n]: v for n, v in model.assembly_values().items()}
        q0 = np.array([values[x] for x in qs])
        J0 = np.array(fjac(q0), dtype=float).reshape(len(holonomic), -1)
        if np.linalg.matrix_rank(J0, tol=1e-8 * max(np.max(np.abs(J0)), 1.0)) < len(holonomic):
            raise DegenerateModel(
                "the closing joint's conditions are not independent at the assembly (a "
                "locked or redundant loop)")
        dep = sorted(int(k) for k in scipy.linalg.qr(J0, pivoting=True)[2][:len(holonomic)])
        numeric.update(phi=lambda x: np.array(fphi(x), dtype=float).reshape(-1),
                       phi_jacobian=lambda x: np.array(fjac(x), dtype=float).reshape(
                           len(holonomic), -1), dependent=dep, assembly=q0)
    # dependent speeds: the holonomic ones, then the best-conditioned columns of the other
    # rows at a random state (Kane's method needs them independent there)
    dep_u = list(dep)
    if nonholonomic:
        x = numeric["assembly"] if holonomic else ranges_mid(numeric["ranges"])
        Af = numeric["jacobian"](x)
        if np.linalg.matrix_rank(Af, tol=1e-8 * max(np.max(np.abs(Af)), 1.0)) < len(velocity):
            raise DegenerateModel(
                "the velocity conditions are not independent (redundant connections: more "
                "conditions than the coordinates allow)")
        A0 = Af[len(holonomic):]
        free = [k for k in range(len(qs)) if k not in dep]
        piv = scipy.linalg.qr(A0[:, free], pivoting=True)[2][:len(nonholonomic)]
        dep_u = sorted(dep + [free[int(k)] for k in piv])
    order = [k for k in range(len(qs)) if k not in dep] + dep  # kane.q: independent first
    numeric["order"] = order
    return {
        "dependent": dep, "dependent_speeds": dep_u,
        "kane": {"q_dependent": [qs[k] for k in dep], "configuration_constraints": list(phi),
                 "u_dependent": [us[k] for k in dep_u], "velocity_constraints": velocity},
        "numeric": numeric,
    }


def ranges_mid(ranges):
    """A state inside the coordinates' ranges, away from their ends (a fixed irrational
    fraction of each range, so that no angle sits on a special value)."""
    return ranges[:, 0] + (ranges[:, 1] - ranges[:, 0]) * 0.3819660112501051


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
