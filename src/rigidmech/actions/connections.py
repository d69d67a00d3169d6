"""The rest of the catalogue of connections (book, ch. 13.2.2-13.2.4).

:mod:`rigidmech.actions.joints` holds the base :class:`~rigidmech.actions.joints.Joint` and
the pivot, prismatic, cylindrical and spherical connections; this module completes the
catalogue. Each connection is described in its local direct orthonormal basis (u, v, w), w
along its axis or normal, reduced at its point O. For a perfect connection (without friction)
the power of the mutual actions, the comoment of the action torsor with the relative kinematic
torsor, is zero for every allowed motion (ch. 13.2.4); this fixes which components of the
action are unknown:

===================  ==============  =============================  =================  ===
connection           alias           allowed {omega ; v(O)}         unknowns           dof
===================  ==============  =============================  =================  ===
Pivot                Revolute        {r w ; 0}                      X Y Z L M          1
Prismatic            Slide           {0 ; c w}                      X Y L M N          1
Helical              Screw           {r w ; h r w}                  X Y Z L M (N=-hZ)  1
Cylindrical                          {r w ; c w}                    X Y L M            2
Spherical            BallJoint       {p u + q v + r w ; 0}          X Y Z              3
SphericalWithFinger                  {p u + q v ; 0}                X Y Z N            2
PlanarSupport        Planar          {r w ; a u + b v}              Z L M              3
LinearAnnular        SphereCylinder  {p u + q v + r w ; c w}        X Y                4
LinearRectilinear    LineContact     {p u + r w ; a u + b v}        Z M                4
PointContact         SpherePlane     {p u + q v + r w ; a u + b v}  Z                  5
Embedding            Fixed           {0 ; 0}                        X Y Z L M N        0
===================  ==============  =============================  =================  ===

Here X, Y, Z are the components of the resultant and L, M, N those of the moment at O on
(u, v, w); h = p / (2 pi) is the reduced pitch of a helical connection of pitch p; p, q, r
and a, b, c stand for free components. The names are the French school's (*liaisons*:
pivot, glissière, hélicoïdale, pivot glissant, rotule, rotule à doigt, appui plan, linéaire
annulaire, linéaire rectiligne, ponctuelle, encastrement), which the book follows; the aliases
are the usual engineering names (``CylinderPlane`` is a second alias of
``LinearRectilinear``; sphere-plane, cylinder-plane and sphere-cylinder are the ISO 3952
names). The
number of degrees of freedom is six minus the number of independent conditions on the
relative motion.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..vectors import Point, Vector
from ..vectors.points import check_point
from .actions import _check_perpendicular
from .joints import _MOTION_NAMES, Joint, Pivot, Prismatic, Spherical, _axis_basis

__all__ = [
    "Helical", "SphericalWithFinger", "PlanarSupport", "LinearAnnular", "LinearRectilinear",
    "PointContact", "Embedding",
    "Screw", "Planar", "SphereCylinder", "LineContact", "CylinderPlane", "SpherePlane",
    "Fixed", "Revolute", "Slide", "BallJoint",
]


class Helical(Joint):
    """Helical connection (screw and nut, *liaison hélicoïdale*) about the axis (``at``,
    ``axis``), of pitch ``pitch`` (ch. 13.2.2). Engineering alias: :data:`Screw`.

    The rotation about the axis and the translation along it are linked: one turn advances
    the child by ``pitch`` along ``axis``, so the relative motion is {r w ; h r w} with the
    reduced pitch h = pitch / (2 pi). A positive pitch is a right-handed thread, a negative
    one a left-handed thread.

    Perfect connection: the power Z h r + N r vanishes for every r, so N = -h Z; the unknowns
    are X, Y, Z, L, M.

    Parameters
    ----------
    at : Point
        A point of the axis.
    axis : Vector
        A unit basis vector of a frame (``R0.k``).
    pitch : number or sympy expression
        Advance per turn, non-zero (a pitch of zero is a :class:`Pivot`).

    Raises
    ------
    ArgumentError
        If ``pitch`` is zero.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0"); p = sp.Symbol("p", positive=True)
    >>> screw = Helical(at=R0.origin, axis=R0.k, pitch=p)
    >>> screw.unknown_names, screw.degrees_of_freedom
    (('X', 'Y', 'Z', 'L', 'M'), 1)
    >>> T, _ = screw.action_torsor("01")
    >>> T.moment
    L_01*R0.i + M_01*R0.j - Z_01*p/(2*pi)*R0.k
    """

    __slots__ = ("_pitch",)
    linked_components = (5,)
    blocked_motion = (0, 1, 3, 4)
    linked_motion = 1

    def __init__(self, *, at: Point, axis: Vector, pitch):
        super().__init__(at=at, axis=axis)
        try:
            pitch = sp.sympify(pitch)
        except (sp.SympifyError, TypeError) as exc:
            raise ArgumentTypeError(
                f"`pitch` must be a number or a sympy expression; got {type(pitch).__name__}."
            ) from exc
        if pitch.is_zero:
            raise ArgumentError(
                "`pitch` must be non-zero (the advance per turn); got 0. A helical connection "
                "of zero pitch is a Pivot.")
        self._pitch = pitch

    @property
    def pitch(self):
        """The pitch p, advance along the axis per turn."""
        return self._pitch

    @property
    def reduced_pitch(self):
        """h = p / (2 pi), the advance per radian."""
        return self._pitch / (2 * sp.pi)

    def _action_values(self, syms):
        vals = super()._action_values(syms)
        vals[5] = -self.reduced_pitch * vals[2]
        return vals

    def _motion_values(self, syms):
        vals = super()._motion_values(syms)
        vals[5] = self.reduced_pitch * vals[2]
        return vals

    def _motion_residuals(self, comps):
        out = super()._motion_residuals(comps)
        out.append((f"Z - h*{_MOTION_NAMES[2]}", comps[5] - self.reduced_pitch * comps[2]))
        return out

    def __repr__(self):
        return f"Helical(at={self._at.name}, axis={self._axis!r}, pitch={self._pitch})"


class SphericalWithFinger(Joint):
    """Spherical connection with finger (*rotule à doigt*) of centre ``at`` (ch. 13.2.2):
    the rotations about the centre, except the rotation about ``axis`` which the finger
    sliding in its groove blocks.

    Perfect connection: unknowns X, Y, Z and the moment N about ``axis`` (L = M = 0).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> j = SphericalWithFinger(at=R0.origin, axis=R0.k)
    >>> j.unknown_names, j.degrees_of_freedom
    (('X', 'Y', 'Z', 'N'), 2)
    """

    __slots__ = ()
    zero_components = (3, 4)
    blocked_motion = (2, 3, 4, 5)


class PlanarSupport(Joint):
    """Planar support (*appui plan*) on the plane through ``at`` of normal ``normal``
    (ch. 13.2.2): two translations in the plane and the rotation about the normal.
    Engineering alias: :data:`Planar`.

    Perfect connection: unknowns Z (normal force) and L, M (moments about the plane's axes).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> j = PlanarSupport(at=R0.origin, normal=R0.k)
    >>> j.unknown_names, j.degrees_of_freedom
    (('Z', 'L', 'M'), 3)
    """

    __slots__ = ()
    zero_components = (0, 1, 5)
    blocked_motion = (0, 1, 5)

    def __init__(self, *, at: Point, normal: Vector):
        super().__init__(at=at, axis=_checked(normal, "normal"))

    @property
    def normal(self) -> Vector:
        """The normal to the contact plane (w of the local basis)."""
        return self._axis


class LinearAnnular(Joint):
    """Linear annular connection (*linéaire annulaire*, sphere in a cylinder) of centre
    ``at`` along the cylinder's axis ``axis`` (ch. 13.2.2): the rotations about the sphere's
    centre and the translation along the axis. Engineering alias: :data:`SphereCylinder`.

    Perfect connection: a force through the centre, perpendicular to the axis; unknowns X, Y.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> j = LinearAnnular(at=R0.origin, axis=R0.i)
    >>> j.unknown_names, j.degrees_of_freedom
    (('X', 'Y'), 4)
    """

    __slots__ = ()
    zero_components = (2, 3, 4, 5)
    blocked_motion = (3, 4)


class LinearRectilinear(Joint):
    """Linear rectilinear connection (*linéaire rectiligne*, cylinder on a plane) along the
    contact line through ``at`` of direction ``direction``, on the plane of normal ``normal``
    (ch. 13.2.2). Engineering aliases: :data:`LineContact`, :data:`CylinderPlane`.

    The local basis is (u, v, w) = (``direction``, ``normal`` ^ ``direction``, ``normal``).
    Allowed: the translations in the plane, the rotation about the normal and the rotation
    about the contact line (rolling). Perfect connection: unknowns Z (normal force) and M (the
    moment about v that a force distributed along the line can have).

    Raises
    ------
    ArgumentError
        If ``direction`` is not orthogonal to ``normal``.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> j = LinearRectilinear(at=R0.origin, normal=R0.k, direction=R0.i)
    >>> j.unknown_names, j.degrees_of_freedom, [str(e) for e in j.basis]
    (('Z', 'M'), 4, ['i_R0', 'j_R0', 'k_R0'])
    """

    __slots__ = ("_direction",)
    zero_components = (0, 1, 3, 5)
    blocked_motion = (1, 5)

    def __init__(self, *, at: Point, normal: Vector, direction: Vector):
        super().__init__(at=at, axis=_checked(normal, "normal"))
        u = _checked(direction, "direction")
        w = self._basis[2]
        _check_perpendicular(u, w, "direction", "normal", "the contact line lies in the "
                             "plane: ", word="orthogonal")
        self._basis = (u, w.cross(u), w)
        self._direction = u

    @property
    def normal(self) -> Vector:
        """The normal to the plane (w)."""
        return self._axis

    @property
    def direction(self) -> Vector:
        """The direction of the contact line (u)."""
        return self._direction

    def __repr__(self):
        return (f"LinearRectilinear(at={self._at.name}, normal={self._axis!r}, "
                f"direction={self._direction!r})")


class PointContact(Joint):
    """Point connection (*liaison ponctuelle*, sphere on a plane) at the contact point
    ``at`` with the common normal ``normal`` (ch. 13.2.2). Engineering alias:
    :data:`SpherePlane`.

    Allowed: every rotation and the two translations in the tangent plane (the contact point
    slides). Perfect connection (no friction): the normal force Z alone.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> j = PointContact(at=R0.origin, normal=R0.k)
    >>> j.unknown_names, j.degrees_of_freedom
    (('Z',), 5)
    """

    __slots__ = ()
    zero_components = (0, 1, 3, 4, 5)
    blocked_motion = (5,)

    def __init__(self, *, at: Point, normal: Vector):
        super().__init__(at=at, axis=_checked(normal, "normal"))

    @property
    def normal(self) -> Vector:
        """The common normal (w)."""
        return self._axis


class Embedding(Joint):
    """Embedding (fixed connection, *encastrement*) at ``at`` (ch. 13.2.2): no relative
    motion. Engineering alias: :data:`Fixed`.

    All six components of the action are unknown, given in the basis of ``axis``'s frame
    (default: the basis of the root frame of ``at``).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> j = Embedding(at=R0.origin)
    >>> j.unknown_names, j.degrees_of_freedom
    (('X', 'Y', 'Z', 'L', 'M', 'N'), 0)
    """

    __slots__ = ()
    blocked_motion = (0, 1, 2, 3, 4, 5)

    def __init__(self, *, at: Point, axis: Vector | None = None):
        check_point(at, "at")
        super().__init__(at=at, axis=at.root.k if axis is None else axis)


def _checked(vector, argument):
    if isinstance(vector, Point) or not isinstance(vector, Vector):
        kind = f"the Point {vector.name}" if isinstance(vector, Point) else type(vector).__name__
        raise ArgumentTypeError(f"`{argument}` must be a Vector; got {kind}.")
    _axis_basis(vector, argument)
    return vector


#: Engineering name of :class:`Helical`.
Screw = Helical
#: Engineering name of :class:`PlanarSupport`.
Planar = PlanarSupport
#: Engineering (ISO 3952) name of :class:`LinearAnnular`.
SphereCylinder = LinearAnnular
#: Engineering names of :class:`LinearRectilinear`.
LineContact = CylinderPlane = LinearRectilinear
#: Engineering (ISO 3952) name of :class:`PointContact`.
SpherePlane = PointContact
#: Engineering name of :class:`Embedding`.
Fixed = Embedding
#: Engineering name of :class:`~rigidmech.actions.joints.Pivot`.
Revolute = Pivot
#: Book's name (*glissière*) of :class:`~rigidmech.actions.joints.Prismatic`.
Slide = Prismatic
#: Engineering name of :class:`~rigidmech.actions.joints.Spherical`.
BallJoint = Spherical
