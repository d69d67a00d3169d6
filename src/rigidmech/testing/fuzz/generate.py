"""Drawing random :class:`~rigidmech.testing.fuzz.Model` descriptions.

One drawing procedure, :func:`draw_model`, reads its random choices from a *source* with four
methods (``integer(lo, hi)``, ``real(lo, hi)``, ``choice(seq)``, ``flag(p)``). Two sources:
:class:`NumpySource` (a ``numpy.random.Generator``: the benchmark, no test dependency) and, in
:mod:`rigidmech.testing.fuzz.strategies`, one reading hypothesis' ``draw`` (the tests: a
disagreement shrinks to a minimal model). Every choice is written so that the value a
hypothesis source shrinks to (the smallest integer, the first entry, ``False``, the number
closest to zero) is the simpler mechanism: fewer bodies, a pivot, no offset, no action.

Numbers are drawn on a grid (multiples of 1/16) so that a model prints short and reproduces
exactly from its repr.

Examples
--------
>>> import numpy as np
>>> m = random_model(np.random.default_rng(3), max_bodies=3)
>>> m == random_model(np.random.default_rng(3), max_bodies=3)
True
"""

from __future__ import annotations

import math
from dataclasses import replace

from .description import (
    CLOSURES,
    JOINTS,
    ROLLING,
    BodySpec,
    ClosureSpec,
    DamperSpec,
    ForceSpec,
    KnifeSpec,
    Model,
    SpringSpec,
    TorqueSpec,
    TorsionalDamperSpec,
    coordinate_names,
    coordinate_ranges,
)

__all__ = ["NumpySource", "draw_model", "random_model", "JOINT_ORDER"]

#: The joints in the order a shrinking source prefers them (simplest first).
JOINT_ORDER = ("pivot", "prismatic", "cylindrical", "helical", "polar", "planar", "spherical",
               "annular", "point", "free", "ball", "disc")
#: the joints of a planar loop (their motion keeps parallel to the plane of normal W's axis
#: ``plane``: pivots about the normal, sliders and planar supports in the plane)
PLANAR_JOINTS = ("pivot", "prismatic", "planar")
#: sequences of three body-fixed rotation axes (0 = i, 1 = j, 2 = k): z-x-z first (the
#: book's Euler angles, ``Frame.euler``), then other proper Euler and Tait-Bryan sequences
ANGLE_SEQUENCES = ((2, 0, 2), (2, 1, 0), (0, 1, 2), (2, 1, 2), (1, 0, 1), (0, 2, 1))
_GRID = 16


class NumpySource:
    """Random choices from a ``numpy.random.Generator`` (see :func:`draw_model`).

    Examples
    --------
    >>> import numpy as np
    >>> s = NumpySource(np.random.default_rng(0))
    >>> -1 <= s.real(-1, 1) <= 1
    True
    """

    def __init__(self, rng):
        self._rng = rng

    def integer(self, lo, hi):
        """An integer in [lo, hi]."""
        return int(self._rng.integers(lo, hi + 1))

    def real(self, lo, hi):
        """A multiple of 1/16 in [lo, hi]."""
        return self.integer(math.ceil(lo * _GRID), math.floor(hi * _GRID)) / _GRID

    def choice(self, seq):
        """One entry of ``seq``."""
        return seq[self.integer(0, len(seq) - 1)]

    def flag(self, p):
        """True with probability ``p``."""
        return bool(self._rng.random() < p)


def _vec(src, lo=-1.0, hi=1.0):
    return tuple(src.real(lo, hi) for _ in range(3))


def _rotations(src, most):
    n = src.integer(0, most)
    return tuple((src.integer(0, 2), src.real(-math.pi, math.pi)) for _ in range(n))


def _inertia(src):
    # moments in [1.5, 2], products in [-0.15, 0.15]: by Gershgorin the principal moments
    # lie in [1.2, 2.3], so they are positive and satisfy the triangle inequalities
    # (2.3 <= 1.2 + 1.2) that rigidmech checks (ch. 15.3.2)
    return tuple(src.real(1.5, 2.0) for _ in range(3)) + tuple(
        src.real(-0.15, 0.15) for _ in range(3))


def _body(src, k, joints, turns):
    parent = src.integer(-1, k - 1) if k else -1
    allowed = [j for j in joints if not (j == "free" and parent != -1)]
    joint = src.choice(allowed)
    body = BodySpec(
        name=f"b{k}", parent=parent, joint=joint, axis=src.integer(0, 2), at=_vec(src),
        mount=_rotations(src, turns), twist=_rotations(src, turns),
        angles=src.choice(ANGLE_SEQUENCES), pitch=src.real(-1.0, 1.0) or 0.5,
        centre=_vec(src, -0.5, 0.5), mass=src.real(0.5, 2.0), inertia=_inertia(src))
    if joint in ROLLING:  # drawn only for them: the other models keep their drawings
        body = replace(body, radius=src.real(0.25, 1.0),
                       contact=src.choice(("given", "between")), pivoting=not src.flag(0.3))
    return body


def _planar_body(src, k, plane):
    """A body of a planar loop (normal: the ground's axis ``plane``): constant turns about
    the normal only, so that every frame keeps that axis; a chain (each body on the
    previous one), the shape that closes."""
    parent = k - 1
    joint = src.choice(PLANAR_JOINTS)
    axis = plane if joint != "prismatic" else (plane + src.integer(1, 2)) % 3
    turn = ((plane, src.real(-math.pi, math.pi)),)
    return BodySpec(
        name=f"b{k}", parent=parent, joint=joint, axis=axis, at=_vec(src),
        mount=turn if src.flag(0.5) else (), twist=turn if src.flag(0.5) else (),
        centre=_vec(src, -0.5, 0.5), mass=src.real(0.5, 2.0), inertia=_inertia(src))


def _other(src, n, k):
    """A body other than ``k`` or the ground (-1)."""
    j = src.integer(-1, n - 2)
    return j if j < k else j + 1


def draw_model(src, *, max_bodies=3, joints=JOINT_ORDER, max_dof=None, actions=True,
               ground=False, max_turns=2, closure=False, knives=False) -> Model:
    """A random :class:`Model` from the random choices of ``src``.

    Parameters
    ----------
    src : NumpySource or a hypothesis source
    max_bodies : int
        1 to ``max_bodies`` bodies, each on a random earlier body or the ground.
    joints : sequence of str
        The joints drawn from (keys of :data:`~rigidmech.testing.fuzz.JOINTS`).
    max_dof : int, optional
        Bodies whose joint would take the model above this many coordinates get a pivot
        instead (Kane's method on sympy's side grows fast with the coordinates).
    actions : bool
        Draw gravity, springs, dampers, torques, forces, torsional dampers.
    ground : bool
        Turn and move the ground frame relative to the Galilean frame.
    max_turns : int
        At most this many constant rotations in each body's mount and twist.
    closure : bool or str
        Close a loop from a random point of a body to the ground
        (:class:`~rigidmech.testing.fuzz.description.ClosureSpec`) at the ground point where
        that point is in a random assembled configuration (so that the loop can close): the
        last body whose chain from the ground has more coordinates than the joint has
        conditions, if any. ``True`` or ``"spherical"``: a spherical joint, the tree drawn
        from ``joints``; ``"pivot"`` or ``"slider"`` (a linear annular joint along a line of
        the plane): a planar loop, the tree drawn from :data:`PLANAR_JOINTS` (``joints`` is
        ignored); ``"planar"``: a pivot or a slider, drawn; ``"any"``: one of the three or
        none, drawn.
    knives : bool
        Give each body on a ``planar`` joint a knife edge with probability 1/2
        (:class:`~rigidmech.testing.fuzz.description.KnifeSpec`).
    """
    if closure == "any":
        closure = src.choice((False,) + CLOSURES)
    elif closure == "planar":
        closure = src.choice(("pivot", "slider"))
    kind = "spherical" if closure is True else closure
    plane = src.integer(0, 2) if kind in ("pivot", "slider") else None
    n = src.integer(1, max_bodies)
    bodies = []
    dof = 0
    for k in range(n):
        b = _body(src, k, joints, max_turns) if plane is None else _planar_body(src, k, plane)
        if max_dof is not None and dof + len(JOINTS[b.joint]) > max_dof:
            b = replace(b, joint="pivot", axis=b.axis if plane is None else plane)
        dof += len(JOINTS[b.joint])
        bodies.append(b)
    kw = {}
    if actions:
        if src.flag(0.7):
            kw["gravity"] = _vec(src, -10.0, 10.0)
        kw["springs"] = tuple(
            SpringSpec(k, _vec(src, -0.5, 0.5), _other(src, n, k), _vec(src),
                       src.real(0.5, 5.0), src.real(0.0, 1.0))
            for k in (src.integer(0, n - 1) for _ in range(src.integer(0, 2))))
        kw["dampers"] = tuple(
            DamperSpec(k, _vec(src, -0.5, 0.5), _other(src, n, k), _vec(src),
                       src.real(0.0, 2.0))
            for k in (src.integer(0, n - 1) for _ in range(src.integer(0, 1))))
        kw["torques"] = tuple(
            TorqueSpec(src.integer(0, n - 1), _vec(src), src.flag(0.5))
            for _ in range(src.integer(0, 2)))
        kw["forces"] = tuple(
            ForceSpec(src.integer(0, n - 1), _vec(src, -2.0, 2.0), _vec(src, -0.5, 0.5))
            for _ in range(src.integer(0, 1)))
        kw["torsional_dampers"] = tuple(
            TorsionalDamperSpec(k, src.real(0.0, 2.0))
            for k in (src.integer(0, n - 1) for _ in range(src.integer(0, 1))))
    if ground:
        kw["ground"] = _rotations(src, 3)
        kw["ground_origin"] = _vec(src)
    if knives:
        kw["knives"] = tuple(
            KnifeSpec(k, (src.real(-0.5, 0.5), src.real(-0.5, 0.5)),
                      src.real(-math.pi, math.pi))
            for k, b in enumerate(bodies) if b.joint == "planar" and src.flag(0.5))
    model = Model(bodies=tuple(bodies), **kw)
    if not kind:
        return model
    # the closing body: the last one whose chain down from the ground has more coordinates
    # than the closing joint has conditions (one degree of freedom at least is left)
    conditions = {"spherical": 3, "pivot": 2, "slider": 1}[kind]
    chain = []
    for b in bodies:
        chain.append(len(b.joint_kinds) + (0 if b.parent < 0 else chain[b.parent]))
    # (not a free body: its first connection would be a joint of the tree, not a loop)
    closing = [k for k, n in enumerate(chain) if n > conditions
               and not (bodies[k].parent < 0 and bodies[k].joint in ("free", "polar"))]
    if closing:
        ranges = coordinate_ranges(model)
        names = iter(coordinate_names(model))
        assembly = tuple(tuple(src.real(*ranges[next(names)]) for _ in b.joint_kinds)
                         for b in bodies)
        extra = {} if plane is None else {"plane": plane}
        if kind == "slider":
            extra["direction"] = src.real(-math.pi, math.pi)
        model = replace(model, closure=ClosureSpec(
            closing[-1], _vec(src, -0.5, 0.5), assembly, kind=kind, **extra))
    return model


def random_model(rng, **options) -> Model:
    """:func:`draw_model` from a ``numpy.random.Generator`` (options as there).

    Examples
    --------
    >>> import numpy as np
    >>> m = random_model(np.random.default_rng(1), max_bodies=1, actions=False)
    >>> len(m.bodies), m.springs
    (1, ())
    """
    return draw_model(NumpySource(rng), **options)
