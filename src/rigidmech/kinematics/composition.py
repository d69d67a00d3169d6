"""Change of reference system: composition of velocities and accelerations (book, ch. 17.1).

A point M moves relative to a reference R1 = (O1; i1, j1, k1), which itself moves relative to
R0 (often the Galilean reference). With omega = omega(R1/R0) and O1M the position of M in R1,
the derivation formula gives (ch. 17.1.2-17.1.3)

.. math::
    \\mathbf{v}(M/R_0) = \\underbrace{\\mathbf{v}(M/R_1)}_{\\text{relative}}
    + \\underbrace{\\mathbf{v}(O_1/R_0) + \\boldsymbol{\\omega}\\wedge\\mathbf{O_1M}}
      _{\\text{entrainment}},

    \\mathbf{a}(M/R_0) = \\underbrace{\\mathbf{a}(M/R_1)}_{\\text{relative}}
    + \\underbrace{\\mathbf{a}(O_1/R_0)
      + \\left.\\tfrac{d\\boldsymbol{\\omega}}{dt}\\right|_{R_0}\\wedge\\mathbf{O_1M}
      + \\boldsymbol{\\omega}\\wedge(\\boldsymbol{\\omega}\\wedge\\mathbf{O_1M})}
      _{\\text{entrainment}}
    + \\underbrace{2\\,\\boldsymbol{\\omega}\\wedge\\mathbf{v}(M/R_1)}_{\\text{Coriolis}} .

The entrainment terms are the velocity and the acceleration, relative to R0, of the point
fixed in R1 that coincides with M at the instant considered. For a solid S moving relative to
R1 the same law holds for the point of S that coincides with a given point P (ch. 17.1.3):
the relative terms are then v(P in S/R1) and a(P in S/R1).
"""

from __future__ import annotations

from .._core.errors import ArgumentTypeError, FrameError
from ..vectors import Frame, Point, Vector
from ..vectors.points import check_point
from .solid import Solid

__all__ = ["Composition", "velocity_composition", "acceleration_composition"]


class Composition:
    """The terms of a composition of velocities or of accelerations (ch. 17.1).

    A value: ``relative``, ``entrainment`` and ``coriolis`` (zero for velocities) are vectors;
    ``absolute`` is their sum, the velocity or acceleration relative to the absolute
    reference. Unpacks as ``relative, entrainment, coriolis``.

    Examples
    --------
    >>> import rigidmech as rm
    >>> r, th = rm.coordinates("r theta")
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=th)
    >>> M = R0.origin.moved("M", r * R1.i)
    >>> c = velocity_composition(M, relative_to=R1, absolute=R0)
    >>> c.relative, c.entrainment
    (Derivative(r(t), t)*R1.i, r(t)*Derivative(theta(t), t)*R1.j)
    >>> c.kind, c.absolute == c.relative + c.entrainment
    ('velocity', True)
    """

    __slots__ = ("_kind", "_relative", "_entrainment", "_coriolis", "_moving_frame",
                 "_absolute_frame")

    def __init__(self, kind: str, relative: Vector, entrainment: Vector, coriolis: Vector, *,
                 relative_to: Frame, absolute: Frame):
        self._kind = kind
        self._relative = relative
        self._entrainment = entrainment
        self._coriolis = coriolis
        self._moving_frame = relative_to
        self._absolute_frame = absolute

    @property
    def kind(self) -> str:
        """``"velocity"`` or ``"acceleration"``."""
        return self._kind

    @property
    def relative(self) -> Vector:
        """The relative term, relative to the moving reference R1."""
        return self._relative

    @property
    def entrainment(self) -> Vector:
        """The entrainment term: motion of the coinciding point fixed in R1, relative to R0."""
        return self._entrainment

    @property
    def coriolis(self) -> Vector:
        """The Coriolis (complementary) term 2 omega(R1/R0) ^ v(M/R1); zero for a
        velocity."""
        return self._coriolis

    @property
    def absolute(self) -> Vector:
        """relative + entrainment + coriolis: the quantity relative to R0."""
        return self._relative + self._entrainment + self._coriolis

    @property
    def relative_to(self) -> Frame:
        """The moving reference R1."""
        return self._moving_frame

    @property
    def absolute_frame(self) -> Frame:
        """The absolute reference R0."""
        return self._absolute_frame

    def subs(self, *args, **kwargs) -> Composition:
        """The composition with values substituted in every term."""
        return Composition(self._kind, *(v.subs(*args, **kwargs) for v in self),
                           relative_to=self._moving_frame, absolute=self._absolute_frame)

    def __iter__(self):
        return iter((self._relative, self._entrainment, self._coriolis))

    def __eq__(self, other):
        if not isinstance(other, Composition):
            return NotImplemented
        return (self._kind == other._kind and tuple(self) == tuple(other)
                and self._moving_frame == other._moving_frame
                and self._absolute_frame == other._absolute_frame)

    def __hash__(self):
        return hash((self._kind, tuple(self), self._moving_frame.name,
                     self._absolute_frame.name))

    def __repr__(self):
        return (f"Composition({self._kind!r}, {self._moving_frame.name}/"
                f"{self._absolute_frame.name}: relative={self._relative!r}, "
                f"entrainment={self._entrainment!r}, coriolis={self._coriolis!r})")


def _check_frame(frame, argument):
    if not isinstance(frame, Frame):
        raise ArgumentTypeError(f"`{argument}` must be a Frame; got {type(frame).__name__}.")


def _check_chain(moving, relative_to, absolute, at):
    _check_frame(relative_to, "relative_to")
    _check_frame(absolute, "absolute")
    if relative_to.root != absolute.root:
        raise FrameError(
            f"`relative_to` ({relative_to.name}) and `absolute` ({absolute.name}) must belong "
            f"to the same frame tree; got trees rooted at {relative_to.root.name} and "
            f"{absolute.root.name}.")
    if isinstance(moving, Point):
        if at is not None:
            raise ArgumentTypeError(
                "`at` is only for a solid: the point itself is the moving point; got "
                f"at={at.name if isinstance(at, Point) else at!r}.")
        return moving, None
    if isinstance(moving, Solid):
        frame, anchor = moving.frame, moving.anchor
    elif isinstance(moving, Frame):
        frame, anchor = moving, moving.origin
    else:
        raise ArgumentTypeError(
            f"`moving` must be a Point, a Solid or a Frame; got {type(moving).__name__}.")
    if at is None:
        raise ArgumentTypeError(
            f"`at` is needed for the solid {frame.name}: the point P at which the velocity "
            "or acceleration of the coinciding point of the solid is wanted.")
    check_point(at, "at")
    if frame.root != absolute.root:
        raise FrameError(f"the solid's frame {frame.name} is not in the tree of "
                         f"{absolute.name}.")
    return at, (frame, anchor)


def _field_velocity(frame, anchor, point, reference):
    # v(P in S/R) = v(A/R) + omega(S/R) ^ AP, A fixed in S (ch. 9.2.2)
    w = frame.rotation_vector(reference)
    return anchor.velocity(reference) + w.cross(point - anchor)


def _field_acceleration(frame, anchor, point, reference):
    # a(P in S/R) = a(A/R) + omega' ^ AP + omega ^ (omega ^ AP) (ch. 9.2.5)
    w = frame.rotation_vector(reference)
    r = point - anchor
    return anchor.acceleration(reference) + w.dt(reference).cross(r) + w.cross(w.cross(r))


def _relative_velocity(point, solid, relative_to):
    if solid is None:
        return point.velocity(relative_to)
    return _field_velocity(*solid, point, relative_to)


def velocity_composition(moving, *, relative_to: Frame, absolute: Frame,
                         at: Point | None = None) -> Composition:
    """Composition of velocities: v(M/R0) = v(M/R1) + v_e(M) (ch. 17.1.2).

    Parameters
    ----------
    moving : Point, Solid or Frame
        The moving point M, or a solid (or the frame attached to it) moving relative to R1.
    relative_to : Frame
        The moving reference R1 (relative motion).
    absolute : Frame
        The reference R0 in which R1 moves (absolute motion).
    at : Point, optional
        For a solid only: the point P whose coinciding point of the solid is considered.

    Returns
    -------
    Composition
        ``relative`` = v(M/R1) (or v(P in S/R1)), ``entrainment`` = v(O1/R0) +
        omega(R1/R0) ^ O1M, ``coriolis`` = 0.

    Raises
    ------
    ArgumentTypeError
        A wrong type, or ``at`` missing for a solid (given for a point).
    FrameError
        Frames of different trees.

    Examples
    --------
    >>> import rigidmech as rm
    >>> x = rm.coordinates("x"); V = rm.constants("V")
    >>> R0 = rm.Frame("R0"); R1 = R0.translated("R1", R0.point("O1", V * rm.t, 0, 0))
    >>> velocity_composition(R1.point("M", x, 0, 0), relative_to=R1, absolute=R0).absolute.compact()
    (V + Derivative(x(t), t))*R0.i
    """
    point, solid = _check_chain(moving, relative_to, absolute, at)
    v_rel = _relative_velocity(point, solid, relative_to)
    v_ent = _field_velocity(relative_to, relative_to.origin, point, absolute)
    return Composition("velocity", v_rel, v_ent, Vector.zero(), relative_to=relative_to,
                       absolute=absolute)


def acceleration_composition(moving, *, relative_to: Frame, absolute: Frame,
                             at: Point | None = None) -> Composition:
    """Composition of accelerations: a(M/R0) = a(M/R1) + a_e(M) + a_c(M) (ch. 17.1.3).

    Parameters
    ----------
    moving : Point, Solid or Frame
        The moving point M, or a solid (or its frame) moving relative to R1.
    relative_to, absolute : Frame
        The moving reference R1 and the reference R0 in which it moves.
    at : Point, optional
        For a solid only: the point P whose coinciding point of the solid is considered.

    Returns
    -------
    Composition
        ``relative`` = a(M/R1), ``entrainment`` = a(O1/R0) + omega' ^ O1M + omega ^ (omega ^
        O1M) with omega = omega(R1/R0) and omega' its derivative relative to R0,
        ``coriolis`` = 2 omega ^ v(M/R1).

    Examples
    --------
    A bead M at distance r(t) on a rod turning at theta(t) about k0 (ch. 17.1):

    >>> import rigidmech as rm
    >>> r, th = rm.coordinates("r theta")
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=th)
    >>> M = R0.origin.moved("M", r * R1.i)
    >>> c = acceleration_composition(M, relative_to=R1, absolute=R0)
    >>> c.relative
    Derivative(r(t), (t, 2))*R1.i
    >>> c.entrainment.components(R1).T
    Matrix([[-r(t)*Derivative(theta(t), t)**2, r(t)*Derivative(theta(t), (t, 2)), 0]])
    >>> c.coriolis
    2*Derivative(r(t), t)*Derivative(theta(t), t)*R1.j
    """
    point, solid = _check_chain(moving, relative_to, absolute, at)
    if solid is None:
        a_rel = point.acceleration(relative_to)
    else:
        a_rel = _field_acceleration(*solid, point, relative_to)
    v_rel = _relative_velocity(point, solid, relative_to)
    a_ent = _field_acceleration(relative_to, relative_to.origin, point, absolute)
    a_cor = 2 * relative_to.rotation_vector(absolute).cross(v_rel)
    return Composition("acceleration", a_rel, a_ent, a_cor, relative_to=relative_to,
                       absolute=absolute)

