"""Random mechanisms as plain immutable data (the description both builders read).

A :class:`Model` is a tuple of :class:`BodySpec` (each body hangs from an earlier one or
from the ground, book ch. 13.2: a tree of connections) and the actions exerted on the
bodies (ch. 11-14): gravity, linear springs and dampers, applied torques, forces, torsional
dampers. Every number is a Python float; nothing here knows rigidmech or sympy, so that the
two builders (:func:`~rigidmech.testing.fuzz.to_rigidmech`,
:func:`~rigidmech.testing.fuzz.to_sympy`) read the same description independently.

Kinematics of one body ``b`` (all angles in radians, all components in the frame named):

1. the *mount frame* F: the parent's frame (the ground frame for ``parent == -1``) moved to
   the point ``at`` (components in the parent's frame), then turned by the constant
   rotations ``mount`` (each ``(axis index, angle)`` about the current frame's axis);
2. the joint moves a frame C relative to F with the body's coordinates, about or along the
   joint axis ``e = F.basis[axis]`` (see :data:`JOINTS`);
3. the body frame B is C turned by the constant rotations ``twist``; the mass centre is at
   ``centre`` (components in B) from B's origin, and the operator of inertia at the mass
   centre has the book's constants ``inertia = (A, B, C, D, E, F)`` in B (ch. 15.1.3:
   moments A, B, C, products D = int yz dm, E = int zx dm, F = int xy dm).

The ground frame itself may be turned and moved relative to the Galilean frame by
``ground`` (constant rotations) and ``ground_origin``: the metamorphic tests use it.

Examples
--------
>>> import numpy as np
>>> from rigidmech.testing.fuzz import random_model
>>> model = random_model(np.random.default_rng(0), max_bodies=2)
>>> 1 <= len(model.bodies) <= 2 and model.bodies[0].parent == -1
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..._core.errors import ArgumentError

__all__ = ["JOINTS", "ROLLING", "CLOSURES", "BodySpec", "KnifeSpec", "SpringSpec",
           "DamperSpec", "TorqueSpec", "ForceSpec",
           "TorsionalDamperSpec", "ClosureSpec", "Model", "coordinate_names", "coordinate_kinds",
           "coordinate_ranges"]

#: The joints of the catalogue the generator draws, with the kinds of their coordinates in
#: order ('a' angle, 'l' length) -- the frame C relative to F (e the axis, u, v the two other
#: axes of F in circular order after e):
#:
#: * ``pivot``: C = F turned by q about e (ch. 13.2.2, pivot);
#: * ``prismatic``: C = F translated by q e (a translated frame);
#: * ``cylindrical``: C = F turned by q1 about e, its origin moved by q2 e;
#: * ``helical``: C = F turned by q about e, moved by pitch q / (2 pi) along e;
#: * ``spherical``: C = F turned by three body-fixed angles of the sequence ``angles``
#:   (z-x-z, the book's Euler angles, made by ``Frame.euler``; or any other sequence as a
#:   chain of elementary rotations);
#: * ``planar`` (planar support of normal e): origin moved by q1 u + q2 v, turned by q3
#:   about e;
#: * ``annular`` (linear annular, sphere in a cylinder of axis e): origin moved by q1 e,
#:   turned by three angles about it;
#: * ``point`` (point contact of normal e): origin moved by q1 u + q2 v, three angles;
#: * ``free`` (no connection: a free body, ground parent only): origin moved by
#:   q1 i + q2 j + q3 k of F, three angles;
#: * ``polar``: a helper frame H = F turned by q2 about e, the point S = F's origin moved by
#:   q1 H.u, and C = F translated to S (a translated frame of a rotated helper frame: C does
#:   not turn); connected by a planar support of normal e (added as a free body on ground).
#: * ``ball`` (a sphere of radius ``radius`` rolling without slipping on the plane of F of
#:   normal e, ch. 10.1.3): contact point I = F's origin moved by q1 u + q2 v, C turned by
#:   three angles about the sphere's centre I + radius e; connected by a rolling contact
#:   (two nonholonomic conditions, a third "without pivoting" one if not ``pivoting``);
#: * ``disc`` (a disc of radius ``radius`` rolling without slipping on the plane of F, the
#:   book's rolling disc): contact point I = F's origin moved by q1 u + q2 v; heading q3
#:   about e (frame A), lean q4 about A.u (frame B, upright at pi/2), the centre at
#:   I + radius B.v, and C = B turned by the spin q5 about B.e there (the disc's plane is
#:   C's (u, v)); connected by a rolling contact as ``ball``.
JOINTS = {
    "pivot": "a", "prismatic": "l", "cylindrical": "al", "helical": "a",
    "spherical": "aaa", "planar": "lla", "annular": "laaa", "point": "llaaa",
    "free": "lllaaa", "polar": "la", "ball": "llaaa", "disc": "llaaa",
}
#: the joints that are rolling contacts (velocity constraints, no joint of the catalogue)
ROLLING = ("ball", "disc")
#: the kinds of closing joints (:class:`ClosureSpec`)
CLOSURES = ("spherical", "pivot", "slider")


@dataclass(frozen=True)
class BodySpec:
    """One body and the joint that carries it (see the module's docstring).

    For the rolling joints (:data:`ROLLING`): ``radius`` of the sphere or disc, ``contact``
    ``"given"`` (rigidmech is given the contact point and the normal) or ``"between"``
    (found by ``ContactKinematics.between`` from the surfaces), ``pivoting`` False adds the
    condition "without pivoting".

    Examples
    --------
    >>> b = BodySpec(name="b0", parent=-1, joint="pivot")
    >>> b.mass, b.inertia
    (1.0, (1.0, 1.0, 1.0, 0.0, 0.0, 0.0))
    """

    name: str
    parent: int
    joint: str
    axis: int = 2
    at: tuple = (0.0, 0.0, 0.0)
    mount: tuple = ()
    twist: tuple = ()
    angles: tuple = (2, 0, 2)
    pitch: float = 0.5
    centre: tuple = (0.0, 0.0, 0.0)
    mass: float = 1.0
    inertia: tuple = (1.0, 1.0, 1.0, 0.0, 0.0, 0.0)
    radius: float = 0.5
    contact: str = "given"
    pivoting: bool = True

    @property
    def joint_kinds(self) -> str:
        """The kinds of the joint's coordinates, in order (``JOINTS[joint]``)."""
        return JOINTS[self.joint]


@dataclass(frozen=True)
class SpringSpec:
    """A linear spring of stiffness ``k`` and free length ``l0`` between the point ``a``
    of body ``body_a`` and the point ``b`` of body ``body_b`` (-1: the ground); points as
    components in the body's frame from its origin."""

    body_a: int
    a: tuple
    body_b: int
    b: tuple
    k: float
    l0: float


@dataclass(frozen=True)
class DamperSpec:
    """A linear viscous damper of coefficient ``c`` between two points (as
    :class:`SpringSpec`)."""

    body_a: int
    a: tuple
    body_b: int
    b: tuple
    c: float


@dataclass(frozen=True)
class TorqueSpec:
    """A constant couple of components ``moment`` in the body's frame, on body ``body``;
    its opposite on the body's parent if ``reaction`` (a motor between them)."""

    body: int
    moment: tuple
    reaction: bool = False


@dataclass(frozen=True)
class ForceSpec:
    """A constant force of components ``vector`` in the ground frame, applied at the point
    ``at`` of body ``body`` (components in the body's frame)."""

    body: int
    vector: tuple
    at: tuple


@dataclass(frozen=True)
class TorsionalDamperSpec:
    """A torsional damper of coefficient ``c`` about the joint axis e of body ``body``,
    between the body and its parent: couple -c (omega(body/parent) . e) e on the body."""

    body: int
    c: float


@dataclass(frozen=True)
class KnifeSpec:
    """A knife edge (a blade that cannot slide sideways, the Chaplygin sleigh's) between body
    ``body``, which must be on a ``planar`` joint, and the body's parent: the blade is at the
    point ``at = (a, b)`` of the joint frame C (P = C's origin + a u + b v) along the
    direction cos(angle) u + sin(angle) v of C, on the plane of normal e of F; one
    nonholonomic condition v(P in body/parent) . (e ^ direction) = 0.

    Examples
    --------
    >>> KnifeSpec(body=0, at=(-0.5, 0.0), angle=0.0).angle
    0.0
    """

    body: int
    at: tuple
    angle: float


@dataclass(frozen=True)
class ClosureSpec:
    """A joint closing a loop between a body and the ground (ch. 13.2): the point ``meets``
    of body ``body`` (components in its frame from its origin) is held at the fixed point D
    of the ground where it is in the assembled configuration ``assembly`` (for each body,
    the values of its coordinates).

    ``kind`` (:data:`CLOSURES`): ``"spherical"`` (a ball joint at D: three conditions);
    ``"pivot"`` (a pivot of axis the ground frame's axis ``plane``, closing a planar loop
    whose joints all keep the motion parallel to that plane: the two conditions in the
    plane); ``"slider"`` (a linear annular joint at D along the direction cos(direction) u +
    sin(direction) v of the plane, u, v the two ground axes after the normal in circular
    order: the point slides on a line of the plane, one condition, a slider-crank).

    Examples
    --------
    >>> ClosureSpec(body=1, meets=(0.5, 0.0, 0.0), assembly=((0.25,), (1.0,))).body
    1
    """

    body: int
    meets: tuple
    assembly: tuple
    kind: str = "spherical"
    plane: int = 2
    direction: float = 0.0

    @property
    def conditions(self) -> int:
        """The number of independent conditions (3, 2 or 1)."""
        return {"spherical": 3, "pivot": 2, "slider": 1}[self.kind]


@dataclass(frozen=True)
class Model:
    """A random mechanism: bodies (parents first), actions, and the placement of the ground
    frame relative to the Galilean one.

    Examples
    --------
    >>> m = Model(bodies=(BodySpec(name="b0", parent=-1, joint="pivot"),))
    >>> coordinate_names(m)
    ('q_b0_0',)
    """

    bodies: tuple
    gravity: tuple | None = None
    springs: tuple = ()
    dampers: tuple = ()
    torques: tuple = ()
    forces: tuple = ()
    torsional_dampers: tuple = ()
    ground: tuple = ()
    ground_origin: tuple = (0.0, 0.0, 0.0)
    prefix: str = "q"
    closure: ClosureSpec | None = None
    knives: tuple = ()

    def __post_init__(self):
        for k, b in enumerate(self.bodies):
            if not -1 <= b.parent < k:
                raise ArgumentError(
                    f"`bodies[{k}].parent` must be an earlier body's index or -1 (the ground); "
                    f"got {b.parent}. List every parent before its children.")
            if b.joint not in JOINTS:
                raise ArgumentError(
                    f"`bodies[{k}].joint` must be one of {sorted(JOINTS)}; got {b.joint!r}.")
            if b.joint == "free" and b.parent != -1:
                raise ArgumentError(
                    f"`bodies[{k}].parent` must be -1 for a free body (it hangs from the "
                    f"ground); got {b.parent}. Use another joint to carry it on a body.")
        for j, k in enumerate(self.knives):
            if not (0 <= k.body < len(self.bodies)
                    and self.bodies[k.body].joint == "planar"):
                raise ArgumentError(
                    f"`knives[{j}].body` must be the index of a body on a 'planar' joint; got "
                    f"{k.body}. A knife edge guides a body that moves on a plane.")
        if self.closure is not None and self.closure.kind not in CLOSURES:
            raise ArgumentError(f"`closure.kind` must be one of {CLOSURES}; got "
                                f"{self.closure.kind!r}.")

    @property
    def degrees_of_freedom(self) -> int:
        """The number of coordinates."""
        return sum(len(JOINTS[b.joint]) for b in self.bodies)

    def assembly_values(self) -> dict:
        """Coordinate name -> value in the assembled configuration of the closure."""
        return {f"{self.prefix}_{b.name}_{k}": x
                for b, values in zip(self.bodies, self.closure.assembly, strict=True)
                for k, x in enumerate(values)}

    def summary(self) -> str:
        """One line: ``b0:pivot<-G b1:spherical<-b0 | g springs=1 ...``."""
        parts = [f"{b.name}:{b.joint}<-{'G' if b.parent < 0 else self.bodies[b.parent].name}"
                 for b in self.bodies]
        acts = [f"{n}={len(v)}" for n, v in (("springs", self.springs),
                                             ("dampers", self.dampers),
                                             ("torques", self.torques),
                                             ("forces", self.forces),
                                             ("tdampers", self.torsional_dampers)) if v]
        loop = (f" loop:{self.closure.kind}:{self.bodies[self.closure.body].name}"
                if self.closure else "")
        loop += "".join(f" knife:{self.bodies[k.body].name}" for k in self.knives)
        return " ".join(parts) + loop + " |" + (" g" if self.gravity else "") + "".join(
            " " + a for a in acts)


def coordinate_names(model: Model) -> tuple:
    """Names of the coordinates, body by body (``{prefix}_{body}_{k}``)."""
    return tuple(f"{model.prefix}_{b.name}_{k}" for b in model.bodies
                 for k in range(len(JOINTS[b.joint])))


def coordinate_kinds(model: Model) -> dict:
    """Name -> ``'a'`` (angle) or ``'l'`` (length) for each coordinate.

    Examples
    --------
    >>> coordinate_kinds(Model(bodies=(BodySpec(name="b", parent=-1, joint="cylindrical"),)))
    {'q_b_0': 'a', 'q_b_1': 'l'}
    """
    out = {}
    for b in model.bodies:
        for k, kind in enumerate(JOINTS[b.joint]):
            out[f"{model.prefix}_{b.name}_{k}"] = kind
    return out


def coordinate_ranges(model: Model) -> dict:
    """Name -> (low, high) of the random states: angles in (-pi, pi) except the middle
    angle of a sequence of three, kept away from its singular set (sin = 0 for a proper
    Euler sequence such as z-x-z, cos = 0 for a Tait-Bryan one; the lean of a ``disc`` in
    (0.4, pi - 0.4)); lengths in (-1, 1), the radius of ``polar`` in (0.5, 1.5) (its mass
    matrix is singular at 0).

    Examples
    --------
    >>> coordinate_ranges(Model(bodies=(BodySpec(name="b", parent=-1, joint="spherical"),)))
    {'q_b_0': (-3.14..., 3.14...), 'q_b_1': (0.3, 2.84...), 'q_b_2': (-3.14..., 3.14...)}
    """
    out = {}
    for b in model.bodies:
        kinds = JOINTS[b.joint]
        for k, kind in enumerate(kinds):
            rng = (-math.pi, math.pi) if kind == "a" else (-1.0, 1.0)
            if b.joint == "polar" and k == 0:
                rng = (0.5, 1.5)
            if kinds.endswith("aaa") and k == len(kinds) - 2:
                proper = b.angles[0] == b.angles[2]
                rng = (0.3, math.pi - 0.3) if proper else (-1.2, 1.2)
                if b.joint == "disc":  # the lean: a disc lying flat is singular
                    rng = (0.4, math.pi - 0.4)
            out[f"{model.prefix}_{b.name}_{k}"] = rng
    return out
