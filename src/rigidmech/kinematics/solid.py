"""Kinematics of a rigid body (book, ch. 9): the kinematic torsor and the velocity and
acceleration fields of a solid.

A solid is known by the frame attached to it. For any two points A, B of the solid S moving
relative to R (ch. 9.2.2, 9.2.5):

.. math::
    \\mathbf{v}(B \\in S/R) = \\mathbf{v}(A \\in S/R) + \\boldsymbol{\\omega}(S/R) \\wedge
    \\mathbf{AB},

    \\mathbf{a}(B \\in S/R) = \\mathbf{a}(A \\in S/R) + \\frac{d\\boldsymbol{\\omega}}{dt}
    \\wedge \\mathbf{AB} + \\boldsymbol{\\omega} \\wedge (\\boldsymbol{\\omega} \\wedge
    \\mathbf{AB}),

so the velocity field is the moment field of the kinematic torsor
{V(S/R)} = {omega(S/R) ; v(A in S/R)}.
"""

from __future__ import annotations

from .._core.errors import ArgumentTypeError, FrameError
from ..torsors import Torsor
from ..vectors import Frame, Point, Vector
from ..vectors.points import check_point

__all__ = ["Solid", "KinematicTorsor", "kinematic_torsor"]


def as_solid(x, argument):
    """``x`` as a :class:`Solid`: a Solid (a Body is one) as it is, a Frame as the solid it
    is fixed in; anything else refused naming ``argument``."""
    if isinstance(x, Solid):
        return x
    if isinstance(x, Frame):
        return Solid(x.name, x)
    raise ArgumentTypeError(
        f"`{argument}` must be a Solid, a Body or a Frame; got {type(x).__name__}.")


def _check_frame(frame, argument):
    if not isinstance(frame, Frame):
        raise ArgumentTypeError(f"`{argument}` must be a Frame; got {type(frame).__name__}.")


class KinematicTorsor(Torsor):
    """The kinematic torsor {V(S/R)} = {omega(S/R) ; v(A in S/R)} (book, ch. 9.2.4).

    It remembers the moving frame and the reference so that composition checks the chain
    (ch. 9.3.1): {V(2/1)} + {V(1/0)} gives {V(2/0)}; {V(2/1)} + {V(3/0)} is an error.

    Examples
    --------
    >>> from rigidmech import Frame, coordinates
    >>> from rigidmech.kinematics import kinematic_torsor
    >>> q1, q2 = coordinates("q1 q2")
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.k, angle=q1)
    >>> R2 = R1.rotated("R2", about=R1.k, angle=q2)
    >>> V21 = kinematic_torsor(R2, relative_to=R1, at=R0.origin)
    >>> V10 = kinematic_torsor(R1, relative_to=R0, at=R0.origin)
    >>> V20 = V21 + V10
    >>> V20.moving.name, V20.reference.name
    ('R2', 'R0')
    """

    __slots__ = ("_moving", "_reference")

    def __init__(self, rotation: Vector, velocity: Vector, at: Point, *, moving: Frame,
                 reference: Frame):
        super().__init__(rotation, velocity, at)
        _check_frame(moving, "moving")
        _check_frame(reference, "reference")
        self._moving = moving
        self._reference = reference

    def _copy_extra(self, other):
        self._moving = other._moving
        self._reference = other._reference

    @property
    def moving(self) -> Frame:
        """The frame (solid) whose motion this torsor describes."""
        return self._moving

    @property
    def reference(self) -> Frame:
        """The reference the motion is relative to."""
        return self._reference

    @property
    def rotation(self) -> Vector:
        """The rotation vector omega(S/R) (the resultant)."""
        return self._resultant

    @property
    def velocity(self) -> Vector:
        """The velocity v(A in S/R) at the point of reduction (the moment)."""
        return self._moment

    def velocity_at(self, point: Point) -> Vector:
        """v(B in S/R) by the transport formula (ch. 9.2.2)."""
        return self.moment_at(point)

    def __add__(self, other):
        if not isinstance(other, KinematicTorsor):
            raise ArgumentTypeError(
                "a kinematic torsor composes only with a kinematic torsor (ch. 9.3.1); got "
                f"{type(other).__name__}. Use comoment() for the power of an action."
            )
        if self._reference == other._moving:
            first, second = self, other
        elif other._reference == self._moving:
            first, second = other, self
        else:
            raise FrameError(
                f"cannot compose V({self._moving.name}/{self._reference.name}) with "
                f"V({other._moving.name}/{other._reference.name}): the frames do not chain. "
                "Compose V(2/1) with V(1/0)."
            )
        total = Torsor.__add__(self, other)
        total._moving = first._moving
        total._reference = second._reference
        return total

    def __neg__(self):
        """The inverse motion {V(R/S)} = -{V(S/R)} (ch. 9.3.2)."""
        out = Torsor.__neg__(self)
        out._moving, out._reference = self._reference, self._moving
        return out

    def __sub__(self, other):
        return self + (-other)

    def __mul__(self, scalar):
        raise ArgumentTypeError(
            "a kinematic torsor is not scaled; convert with Torsor(t.resultant, t.moment, "
            "t.point) for the plain torsor algebra."
        )

    __rmul__ = __mul__

    def __repr__(self):
        return (f"KinematicTorsor(V({self._moving.name}/{self._reference.name}): "
                f"rotation={self._resultant!r}, velocity={self._moment!r}, "
                f"at={self._point.name})")


def kinematic_torsor(frame: Frame, *, relative_to: Frame, at: Point,
                     anchor: Point | None = None) -> KinematicTorsor:
    """{V(S/R)} for the solid attached to ``frame``, reduced at ``at`` (ch. 9.2.4).

    v(A in S/R) = v(B/R) + omega(S/R) ^ BA, where B is ``anchor``, a point fixed in the
    solid (default: the origin of ``frame``).

    Examples
    --------
    >>> from rigidmech import Frame, coordinates
    >>> q = coordinates("q")
    >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> V = kinematic_torsor(R1, relative_to=R0, at=R0.point("A", 2, 0, 0))
    >>> V.velocity
    2*Derivative(q(t), t)*R0.j
    """
    _check_frame(frame, "frame")
    _check_frame(relative_to, "relative_to")
    check_point(at, "at")
    anchor = frame.origin if anchor is None else anchor
    check_point(anchor, "anchor")
    w = frame.rotation_vector(relative_to)
    v = (anchor - relative_to.origin).dt(relative_to) + w.cross(at - anchor)
    return KinematicTorsor(w, v, at, moving=frame, reference=relative_to)


class Solid:
    """A rigid body known by the frame attached to it (book, ch. 9.1).

    Parameters
    ----------
    name : str
    frame : Frame
        The reference system attached to the body.

    Examples
    --------
    >>> from rigidmech import Frame, coordinates
    >>> q = coordinates("q")
    >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> S1 = Solid("S1", frame=R1)
    >>> S1.velocity(R0.point("A", 1, 0, 0), relative_to=R0)
    Derivative(q(t), t)*R0.j
    >>> S1.acceleration(R0.point("A", 1, 0, 0), relative_to=R0)
    -Derivative(q(t), t)**2*R0.i + Derivative(q(t), (t, 2))*R0.j
    """

    __slots__ = ("_name", "_frame")

    def __init__(self, name: str, frame: Frame):
        if not isinstance(name, str) or not name:
            raise ArgumentTypeError(f"`name` must be a non-empty string; got {name!r}.")
        _check_frame(frame, "frame")
        self._name = name
        self._frame = frame

    @property
    def name(self) -> str:
        """Name of the solid."""
        return self._name

    @property
    def frame(self) -> Frame:
        """The frame attached to the solid."""
        return self._frame

    @property
    def anchor(self) -> Point:
        """A point known to be fixed in the solid, from which its velocity field is built
        (the frame's origin here; a Body uses its mass centre)."""
        return self._frame.origin

    def rotation_vector(self, relative_to: Frame) -> Vector:
        """omega(S/R) (ch. 9.2.3)."""
        return self._frame.rotation_vector(relative_to)

    def kinematic_torsor(self, *, relative_to: Frame, at: Point) -> KinematicTorsor:
        """{V(S/R)} reduced at ``at`` (ch. 9.2.4)."""
        return kinematic_torsor(self._frame, relative_to=relative_to, at=at,
                                anchor=self.anchor)

    def velocity(self, point: Point, *, relative_to: Frame) -> Vector:
        """v(P in S/R): velocity of the point of the solid that coincides with ``point``."""
        check_point(point, "point")
        return self.kinematic_torsor(relative_to=relative_to, at=point).velocity

    def acceleration(self, point: Point, *, relative_to: Frame) -> Vector:
        """a(P in S/R) for a point P fixed in the solid (ch. 9.2.5)."""
        check_point(point, "point")
        _check_frame(relative_to, "relative_to")
        w = self._frame.rotation_vector(relative_to)
        b = self.anchor
        r = point - b
        a_anchor = (b - relative_to.origin).dt(relative_to).dt(relative_to)
        return a_anchor + w.dt(relative_to).cross(r) + w.cross(w.cross(r))

    def __repr__(self):
        return f"{type(self).__name__}({self._name!r}, frame={self._frame.name})"
