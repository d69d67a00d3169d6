"""Connections between solids and their action torsors (book, ch. 13.2).

A connection (joint) between two solids restricts their relative motion; the action that one
solid exerts on the other through it is an action torsor with unknown components. For a
connection without friction (a perfect connection) the power of the mutual actions is zero
for every motion the connection allows (ch. 13.2.4), which fixes the form of the torsor:

===========  ========================  =============================  ======================
connection   relative motion           action torsor at O             unknowns (local basis)
===========  ========================  =============================  ======================
pivot        rotation about (O, w)     {X u + Y v + Z w ; L u + M v}  X, Y, Z, L, M
prismatic    translation along w       {X u + Y v ; L u + M v + N w}  X, Y, L, M, N
cylindrical  rotation about and        {X u + Y v ; L u + M v}        X, Y, L, M
             translation along (O, w)
spherical    rotation about O          {X u + Y v + Z w ; 0}          X, Y, Z
===========  ========================  =============================  ======================

(u, v, w) is a direct orthonormal basis with w along the axis, taken from the frame the axis
vector belongs to.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from .._core.symbolic import vanishes
from ..torsors import Torsor
from ..vectors import Point, Vector
from ..vectors.points import check_point

__all__ = ["Joint", "Pivot", "Prismatic", "Cylindrical", "Spherical"]

_NAMES = ("X", "Y", "Z", "L", "M", "N")
#: names of the relative-motion components (rotation, then velocity at the joint's point) in
#: the messages of ``check`` and in the symbols of ``allowed_motion``
_MOTION_NAMES = ("wX", "wY", "wZ", "X", "Y", "Z")
_MOTION_SYMBOLS = ("omega_u", "omega_v", "omega_w", "v_u", "v_v", "v_w")


def _axis_basis(axis, argument="axis"):
    """Direct orthonormal (u, v, w) with w = axis, for an axis along a basis vector."""
    if isinstance(axis, Point):
        raise ArgumentTypeError(
            f"`{argument}` must be a Vector; got the Point {axis.name}.")
    if not isinstance(axis, Vector):
        raise ArgumentTypeError(f"`{argument}` must be a Vector; got {type(axis).__name__}.")
    if len(axis.parts) != 1:
        raise ArgumentError(
            f"`{argument}` must be a basis vector of a frame (e.g. R0.k); got {axis!r}.")
    frame, c = axis.parts[0]
    nz = [n for n in range(3) if c[n] != 0]
    if len(nz) != 1 or c[nz[0]] not in (1, -1):
        raise ArgumentError(
            f"`{argument}` must be a unit basis vector of a frame (e.g. R0.k); got {axis!r}.")
    n, s = nz[0], c[nz[0]]
    e = frame.basis
    u, v, w = e[(n + 1) % 3], e[(n + 2) % 3], e[n]
    return (s * u, v, s * w) if s == 1 else (u, -v, -w)


class Joint:
    """Base of the catalogue of connections (ch. 13.2.2).

    A joint knows its local basis (u, v, w), its point of reduction, which of the six
    components (X, Y, Z along u, v, w for the resultant; L, M, N for the moment) are unknown
    for a perfect connection, and how to check that a relative motion is one it allows.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> j = Pivot(at=Frame("R0").origin, axis=Frame("R0").k)
    >>> isinstance(j, Joint), [str(e) for e in j.basis]
    (True, ['i_R0', 'j_R0', 'k_R0'])
    """

    __slots__ = ("_at", "_axis", "_basis")
    #: indices in (X, Y, Z, L, M, N) of the action components that are zero for a perfect joint
    zero_components: tuple = ()
    #: indices in (X, Y, Z, L, M, N) of the action components fixed by the others (the moment
    #: N = -h Z of a helical joint); they are not unknowns
    linked_components: tuple = ()
    #: indices in (omega_u, omega_v, omega_w, v_u, v_v, v_w) of the relative motion the joint
    #: forbids (kinematic torsor components at its point that must vanish)
    blocked_motion: tuple = ()
    #: number of relations between the allowed components of the motion (v_w = h omega_w for
    #: a helical joint)
    linked_motion: int = 0

    def __init__(self, *, at: Point, axis: Vector):
        check_point(at, "at")
        self._basis = _axis_basis(axis)
        self._at = at
        self._axis = axis

    @property
    def at(self) -> Point:
        """Point of reduction of the connection's action torsor."""
        return self._at

    @property
    def axis(self) -> Vector:
        """Axis of the connection (w of the local basis)."""
        return self._axis

    @property
    def basis(self):
        """Local direct orthonormal basis (u, v, w), w along the axis."""
        return self._basis

    @property
    def unknown_names(self):
        """Names of the unknown components of the action torsor of a perfect connection."""
        return tuple(n for i, n in enumerate(_NAMES)
                     if i not in self.zero_components and i not in self.linked_components)

    @property
    def degrees_of_freedom(self) -> int:
        """Number of independent relative motions the connection allows (ch. 13.2.2): six
        minus the blocked components minus the relations between the others.

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> Pivot(at=R0.origin, axis=R0.k).degrees_of_freedom
        1
        """
        return 6 - len(self.blocked_motion) - self.linked_motion

    def _action_values(self, syms):
        """The six components (X, Y, Z, L, M, N) of the perfect action from the symbols."""
        return [sp.S.Zero if i in self.zero_components else s for i, s in enumerate(syms)]

    def _motion_values(self, syms):
        """The six components (omega_u, omega_v, omega_w, v_u, v_v, v_w) of an allowed
        relative motion from the symbols."""
        return [sp.S.Zero if i in self.blocked_motion else s for i, s in enumerate(syms)]

    def _motion_residuals(self, comps):
        """(name, expression) pairs that vanish for every allowed relative motion."""
        return [(_MOTION_NAMES[i], c) for i, c in enumerate(comps) if i in self.blocked_motion]

    def allowed_motion(self, label: str) -> tuple[Torsor, tuple]:
        """The kinematic torsor of the most general relative motion the connection allows,
        reduced at its point, with the free components as symbols ``omega_u_label``, ...,
        ``v_w_label`` in the local basis (u, v, w) (ch. 13.2.2).

        Returns
        -------
        (Torsor, tuple of sympy.Symbol)
            The torsor {omega ; v(at)} and its free components (as many as the degrees of
            freedom).

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> V, free = Pivot(at=R0.origin, axis=R0.k).allowed_motion("01")
        >>> V.resultant, free
        (omega_w_01*R0.k, (omega_w_01,))
        """
        syms = [sp.Symbol(f"{n}_{label}", real=True) for n in _MOTION_SYMBOLS]
        vals = self._motion_values(syms)
        u, v, w = self._basis
        rot = vals[0] * u + vals[1] * v + vals[2] * w
        vel = vals[3] * u + vals[4] * v + vals[5] * w
        free = tuple(s for s, x in zip(syms, vals, strict=True) if x == s)
        return Torsor(rot, vel, self._at), free

    def action_torsor(self, label: str) -> tuple[Torsor, tuple]:
        """The action torsor of a perfect connection with unknown components as symbols
        ``X_label``, ... (ch. 13.2.4).

        Returns
        -------
        (Torsor, tuple of sympy.Symbol)

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> T, unknowns = Pivot(at=R0.origin, axis=R0.k).action_torsor("01")
        >>> unknowns
        (X_01, Y_01, Z_01, L_01, M_01)
        """
        syms = [sp.Symbol(f"{n}_{label}", real=True) for n in _NAMES]
        vals = self._action_values(syms)
        u, v, w = self._basis
        r = vals[0] * u + vals[1] * v + vals[2] * w
        m = vals[3] * u + vals[4] * v + vals[5] * w
        return Torsor(r, m, self._at), tuple(
            s for i, s in enumerate(syms)
            if i not in self.zero_components and i not in self.linked_components)

    def components(self, torsor: Torsor) -> dict:
        """The six components (X, Y, Z, L, M, N) of ``torsor`` in the local basis, with the
        moment taken at the joint's point.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> j = Pivot(at=R0.origin, axis=R0.k)
        >>> j.components(Torsor(R0.i, R0.k, R0.origin))["N"]
        1
        """
        if not isinstance(torsor, Torsor):
            raise ArgumentTypeError(f"`torsor` must be a Torsor; got {type(torsor).__name__}.")
        m = torsor.moment_at(self._at)
        u, v, w = self._basis
        vals = [torsor.resultant.dot(e) for e in (u, v, w)] + [m.dot(e) for e in (u, v, w)]
        return dict(zip(_NAMES, vals, strict=True))

    def check(self, motion: Torsor) -> None:
        """Raise ``ConnectionError_`` if ``motion``, the kinematic torsor of the child relative
        to the parent, is not one this joint allows: a component the joint blocks must vanish
        (:func:`~rigidmech._core.symbolic.vanishes`: exactly for exact expressions, to the
        rounding of their float constants otherwise: at most 1e-9 of the magnitude of the
        terms of the components of its kind, rotation rates or velocities).

        Examples
        --------
        >>> from rigidmech import Frame, coordinates
        >>> from rigidmech.kinematics import kinematic_torsor
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> V = kinematic_torsor(R1, relative_to=R0, at=R0.origin)
        >>> Pivot(at=R0.origin, axis=R0.k).check(V)
        >>> Pivot(at=R0.point("A", 1, 0, 0), axis=R0.k).check(V)
        Traceback (most recent call last):
        ...
        rigidmech._core.errors.ConnectionError_: Pivot at A: ... (components [Y] ...
        """
        if not isinstance(motion, Torsor):
            raise ArgumentTypeError(f"`motion` must be a Torsor; got {type(motion).__name__}.")
        V = motion.at(self._at)
        comps = self._motion_components(V)
        # each blocked component relative to the components of its kind (rotation rates, or
        # velocities at the joint's point): the same verdict in any unit of length
        bad = [(n, c) for n, c in self._motion_residuals(comps)
               if not vanishes(c, scale=comps[:3] if n.startswith("w") else comps[3:])]
        if bad:
            raise ConnectionError_(
                f"{type(self).__name__} at {self._at.name}: the relative motion is not "
                f"allowed by the joint (components [{', '.join(n for n, _ in bad)}] of the "
                f"relative kinematic torsor should vanish; got [{', '.join(str(c) for _, c in bad)}"
                "]). Check the frames' rotation axes and the bodies' points."
            )

    def _motion_components(self, V):
        u, v, w = self._basis
        return [V.resultant.dot(e) for e in (u, v, w)] + [V.moment.dot(e) for e in (u, v, w)]

    def __repr__(self):
        return f"{type(self).__name__}(at={self._at.name}, axis={self._axis!r})"


class Pivot(Joint):
    """Pivot (revolute) connection about the axis (``at``, ``axis``) (ch. 13.2.2).

    Perfect: the moment about the axis is zero, N = 0.

    Examples
    --------
    >>> from rigidmech import Frame, coordinates
    >>> q = coordinates("q")
    >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> Pivot(at=R0.origin, axis=R0.k).unknown_names
    ('X', 'Y', 'Z', 'L', 'M')
    """

    __slots__ = ()
    zero_components = (5,)
    #: allowed motion: rotation about w only, no velocity at the point
    blocked_motion = (0, 1, 3, 4, 5)


class Prismatic(Joint):
    """Prismatic (slider, *glissiere*) connection along ``axis`` (ch. 13.2.2).

    Perfect: the resultant along the axis is zero, Z = 0. ``at`` is the point of reduction.

    Examples
    --------
    >>> from rigidmech import Frame, coordinates
    >>> x = coordinates("x")
    >>> R0 = Frame("R0"); R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    >>> Prismatic(at=R1.origin, axis=R0.i).unknown_names
    ('X', 'Y', 'L', 'M', 'N')
    """

    __slots__ = ()
    zero_components = (2,)
    blocked_motion = (0, 1, 2, 3, 4)


class Cylindrical(Joint):
    """Cylindrical connection (*pivot glissant*) about and along the axis (``at``, ``axis``)
    (ch. 13.2.2): rotation about and translation along one line.

    Perfect: no resultant along the axis and no moment about it, Z = N = 0.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> Cylindrical(at=R0.origin, axis=R0.k).unknown_names
    ('X', 'Y', 'L', 'M')
    """

    __slots__ = ()
    zero_components = (2, 5)
    blocked_motion = (0, 1, 3, 4)


class Spherical(Joint):
    """Spherical connection (ball joint, *rotule*) at ``at`` (ch. 13.2.2): any rotation about
    the point.

    Perfect: no moment at the centre, L = M = N = 0. The components are given in the basis
    of ``axis``'s frame (default: the basis of the root frame of ``at``).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> Spherical(at=R0.origin).unknown_names
    ('X', 'Y', 'Z')
    """

    __slots__ = ()
    zero_components = (3, 4, 5)
    blocked_motion = (3, 4, 5)

    def __init__(self, *, at: Point, axis: Vector | None = None):
        check_point(at, "at")
        super().__init__(at=at, axis=at.root.k if axis is None else axis)
