"""The torsor {R ; M(A)}: the book's key concept and rigidmech's spine (book, ch. 5).

One type serves for every torsor of mechanics: kinematic {omega ; v(A)}, action {R ; M(A)},
kinetic {m v(G) ; sigma(A)} and dynamic {m a(G) ; delta(A)} torsors (ARCHITECTURE.md,
principle 2). A torsor is known by its resultant, its moment at one point (the point of
reduction) and that point; the moment field follows from the transport formula (ch. 5.1.2)

.. math:: \\mathbf{M}(B) = \\mathbf{M}(A) + \\mathbf{BA} \\wedge \\mathbf{R}.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..vectors import Point, Vector
from ..vectors.points import check_point

__all__ = ["Torsor", "slider", "couple"]

_KINDS = ("zero", "couple", "slider", "torsor")


def _check_vector(v, argument):
    if isinstance(v, Point):
        raise ArgumentTypeError(
            f"`{argument}` must be a Vector; got the Point {v.name}. Use a bipoint B - A."
        )
    if not isinstance(v, Vector):
        raise ArgumentTypeError(f"`{argument}` must be a Vector; got {type(v).__name__}.")


def _is_zero(expr) -> bool | None:
    """Exact decision when possible: True/False, or None if undecidable."""
    if expr == 0:
        return True
    z = sp.simplify(expr)
    if z == 0:
        return True
    if z.is_zero is False or (z.is_number and z != 0):
        return False
    return None


class Torsor:
    """A torsor {R ; M(A)}: resultant R, moment M(A) at the point of reduction A (ch. 5.1).

    Parameters
    ----------
    resultant : Vector
        The resultant R.
    moment : Vector
        The moment M(A) at ``at``.
    at : Point
        The point of reduction A.

    Notes
    -----
    Book conventions (ch. 5.1): transport :math:`\\mathbf{M}(B) = \\mathbf{M}(A) +
    \\mathbf{BA}\\wedge\\mathbf{R}`; automoment (scalar invariant) :math:`\\mathbf{R}\\cdot
    \\mathbf{M}(A)`; comoment of two torsors :math:`\\mathbf{R}_1\\cdot\\mathbf{M}_2(A) +
    \\mathbf{R}_2\\cdot\\mathbf{M}_1(A)`. ``==`` is exact and structural (same resultant,
    moment and point); use :meth:`equals` (symbolic) or :meth:`is_close` (numeric) to compare
    torsors reduced at different points.

    Examples
    --------
    >>> from rigidmech import Frame, Torsor
    >>> R0 = Frame("R0")
    >>> A = R0.point("A", 1, 2, 0)
    >>> T = Torsor(resultant=R0.k, moment=R0.i, at=A)
    >>> T.at(R0.origin)
    Torsor(resultant=R0.k, moment=3*R0.i - R0.j, at=O_R0)
    >>> T.automoment
    0
    >>> T.kind
    'slider'
    """

    __slots__ = ("_resultant", "_moment", "_point", "_hash")

    def __init__(self, resultant: Vector, moment: Vector, at: Point):
        _check_vector(resultant, "resultant")
        _check_vector(moment, "moment")
        check_point(at, "at")
        self._resultant = resultant
        self._moment = moment
        self._point = at
        self._hash = None

    @classmethod
    def _new(cls, resultant, moment, point, like=None):
        obj = object.__new__(cls)
        obj._resultant = resultant
        obj._moment = moment
        obj._point = point
        obj._hash = None
        if like is not None:
            obj._copy_extra(like)
        return obj

    def _copy_extra(self, other):
        """Hook for subclasses carrying more than the three elements."""

    @classmethod
    def zero(cls, at: Point) -> Torsor:
        """The zero torsor, reduced at ``at``.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> Torsor.zero(Frame("R0").origin).kind
        'zero'
        """
        check_point(at, "at")
        return cls._new(Vector.zero(), Vector.zero(), at)

    # -- elements -----------------------------------------------------------------------
    @property
    def resultant(self) -> Vector:
        """The resultant R."""
        return self._resultant

    @property
    def moment(self) -> Vector:
        """The moment at the point of reduction."""
        return self._moment

    @property
    def point(self) -> Point:
        """The point of reduction."""
        return self._point

    def moment_at(self, point: Point) -> Vector:
        """Moment at ``point`` by the transport formula M(B) = M(A) + BA ^ R (ch. 5.1.2).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> T = Torsor(resultant=R0.j, moment=Vector.zero(), at=R0.origin)
        >>> T.moment_at(R0.point("B", 2, 0, 0))
        -2*R0.k
        """
        check_point(point, "point")
        if point is self._point or point == self._point:
            return self._moment
        return self._moment + (self._point - point).cross(self._resultant)

    def at(self, point: Point) -> Torsor:
        """The same torsor reduced at ``point`` (ch. 5.1.2).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> T = Torsor(resultant=R0.j, moment=R0.k, at=R0.origin)
        >>> T.at(R0.point("B", 1, 0, 0)).moment
        0
        """
        return type(self)._new(self._resultant, self.moment_at(point), point, like=self)

    # -- algebra ------------------------------------------------------------------------
    def _check_combinable(self, other):
        if not isinstance(other, Torsor):
            raise ArgumentTypeError(
                f"a Torsor can only be combined with a Torsor; got {type(other).__name__}."
            )

    def __add__(self, other):
        if not isinstance(other, Torsor):
            return NotImplemented
        self._check_combinable(other)
        return type(self)._new(
            self._resultant + other._resultant,
            self._moment + other.moment_at(self._point),
            self._point,
            like=self,
        )

    def __neg__(self):
        return type(self)._new(-self._resultant, -self._moment, self._point, like=self)

    def __sub__(self, other):
        if not isinstance(other, Torsor):
            return NotImplemented
        return self + (-other)

    def __mul__(self, scalar):
        if isinstance(scalar, Torsor | Vector):
            raise ArgumentTypeError(
                "a torsor is multiplied by scalars only; use comoment(other) for the product "
                "of two torsors."
            )
        try:
            s = sp.sympify(scalar)
        except (sp.SympifyError, TypeError):
            return NotImplemented
        return type(self)._new(self._resultant * s, self._moment * s, self._point, like=self)

    __rmul__ = __mul__

    def __truediv__(self, scalar):
        s = sp.sympify(scalar)
        if s == 0:
            raise ArgumentError("`scalar` must be non-zero to divide a torsor; got 0.")
        return self * (1 / s)

    @property
    def automoment(self) -> sp.Expr:
        """The automoment (scalar invariant) R . M(A), the same at every point (ch. 5.1.4).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> Torsor(resultant=2 * R0.k, moment=3 * R0.k, at=R0.origin).automoment
        6
        """
        return self._resultant.dot(self._moment)

    def comoment(self, other: Torsor) -> sp.Expr:
        """The comoment R1 . M2(A) + R2 . M1(A), the same at every point A (ch. 5.1.5).

        The power of an action on a body is the comoment of the action torsor and the
        kinematic torsor of the body (ch. 11.3.1).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> F = Torsor(resultant=R0.i, moment=Vector.zero(), at=R0.origin)
        >>> V = Torsor(resultant=R0.k, moment=2 * R0.i, at=R0.origin)
        >>> F.comoment(V)
        2
        """
        if not isinstance(other, Torsor):
            raise ArgumentTypeError(f"`other` must be a Torsor; got {type(other).__name__}.")
        return self._resultant.dot(other.moment_at(self._point)) + other._resultant.dot(
            self._moment)

    # -- geometry -----------------------------------------------------------------------
    @property
    def kind(self) -> str:
        """Classification (ch. 5.2): 'zero', 'couple' (R = 0, M != 0), 'slider' (R != 0,
        automoment 0) or 'torsor' (general).

        Decisions are exact (sympy ``simplify``); a case that cannot be decided for
        symbolic values raises :class:`ArgumentError` naming the undecided quantity.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> Torsor(resultant=Vector.zero(), moment=R0.i, at=R0.origin).kind
        'couple'
        """
        r2 = self._resultant.dot(self._resultant)
        r_zero = _is_zero(r2)
        if r_zero is None:
            raise ArgumentError(
                f"cannot decide whether the resultant is zero: |R|^2 = {r2}; substitute values."
            )
        if r_zero:
            m2 = self._moment.dot(self._moment)
            m_zero = _is_zero(m2)
            if m_zero is None:
                raise ArgumentError(
                    f"cannot decide whether the moment is zero: |M|^2 = {m2}; substitute values."
                )
            return "zero" if m_zero else "couple"
        a = _is_zero(self.automoment)
        if a is None:
            raise ArgumentError(
                f"cannot decide whether the automoment {self.automoment} is zero; "
                "substitute values."
            )
        return "slider" if a else "torsor"

    @property
    def pitch(self) -> sp.Expr:
        """The pitch R . M / R^2, the same at every point (ch. 5.1.7).

        Raises
        ------
        ArgumentError
            If the resultant is zero (a couple or the zero torsor has no central axis).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> Torsor(resultant=2 * R0.k, moment=6 * R0.k, at=R0.origin).pitch
        3
        """
        r2 = self._resultant.dot(self._resultant)
        if _is_zero(r2):
            raise ArgumentError(
                "a torsor with zero resultant (couple or zero torsor) has no pitch and no "
                "central axis."
            )
        return sp.simplify(self.automoment / r2)

    def central_point(self, near: Point | None = None) -> Point:
        """The point of the central axis nearest to ``near`` (default: the point of
        reduction): A + R ^ M(A) / R^2 (ch. 5.1.7).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> T = Torsor(resultant=R0.k, moment=R0.i, at=R0.origin)
        >>> T.central_point().coordinates(R0).T
        Matrix([[0, 1, 0]])
        """
        near = self._point if near is None else near
        check_point(near, "near")
        r2 = self._resultant.dot(self._resultant)
        if _is_zero(r2):
            raise ArgumentError(
                "a torsor with zero resultant (couple or zero torsor) has no central axis."
            )
        m = self.moment_at(near)
        return near.moved("I", self._resultant.cross(m) / r2)

    # -- transforms and comparison ------------------------------------------------------
    def applyfunc(self, func) -> Torsor:
        """Apply ``func`` to every component of the resultant and the moment."""
        return type(self)._new(self._resultant.applyfunc(func), self._moment.applyfunc(func),
                               self._point, like=self)

    def subs(self, *args, **kwargs) -> Torsor:
        """Substitute values in the resultant, the moment and the point of reduction."""
        return type(self)._new(self._resultant.subs(*args, **kwargs),
                               self._moment.subs(*args, **kwargs),
                               self._point.subs(*args, **kwargs), like=self)

    def simplify(self) -> Torsor:
        """Simplify every component."""
        return self.applyfunc(sp.simplify)

    def components(self, frame):
        """The resultant and the moment at the point of reduction, in ``frame``'s basis.

        Returns
        -------
        tuple of two sympy ImmutableMatrix, shape (3, 1)

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> R, M = Torsor(resultant=R0.k, moment=R0.i, at=R0.origin).components(R0)
        >>> M.T
        Matrix([[1, 0, 0]])
        """
        return self._resultant.components(frame), self._moment.components(frame)

    def equals(self, other: Torsor) -> bool:
        """Symbolic equality: same resultant and same moment at this point of reduction.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> T = Torsor(resultant=R0.k, moment=R0.i, at=R0.point("A", 1, 2, 3))
        >>> T.at(R0.origin).equals(T)
        True
        """
        if not isinstance(other, Torsor):
            raise ArgumentTypeError(f"`other` must be a Torsor; got {type(other).__name__}.")
        return self._resultant.equals(other._resultant) and self._moment.equals(
            other.moment_at(self._point))

    def is_close(self, other: Torsor, *, rtol=1e-9, atol=0.0) -> bool:
        """Numeric closeness of resultants and of moments at this point of reduction."""
        if not isinstance(other, Torsor):
            raise ArgumentTypeError(f"`other` must be a Torsor; got {type(other).__name__}.")
        return self._resultant.is_close(other._resultant, rtol=rtol, atol=atol) and \
            self._moment.is_close(other.moment_at(self._point), rtol=rtol, atol=atol)

    def __eq__(self, other):
        if not isinstance(other, Torsor):
            return NotImplemented
        return (type(self) is type(other) and self._point == other._point
                and self._resultant == other._resultant and self._moment == other._moment)

    def __hash__(self):
        if self._hash is None:
            self._hash = hash((type(self).__name__, self._resultant, self._moment, self._point))
        return self._hash

    # -- printing -----------------------------------------------------------------------
    def __repr__(self):
        return (f"{type(self).__name__}(resultant={self._resultant!r}, "
                f"moment={self._moment!r}, at={self._point.name})")

    def __str__(self):
        return f"{{{self._resultant} ; {self._moment}}}_{self._point.name}"

    def _latex(self, printer=None):
        r = self._resultant._latex(printer)
        m = self._moment._latex(printer)
        return (rf"\left\{{ \begin{{matrix}} {r} \\ {m} \end{{matrix}} \right\}}"
                rf"_{{{self._point.name}}}")

    def _repr_latex_(self):
        return f"$\\displaystyle {self._latex()}$"


def slider(resultant: Vector, through: Point) -> Torsor:
    """The slider of resultant ``resultant`` on the line through ``through`` (ch. 5.2.1).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> slider(R0.i, R0.point("A", 0, 1, 0)).moment_at(R0.origin)
    -R0.k
    """
    _check_vector(resultant, "resultant")
    check_point(through, "through")
    return Torsor._new(resultant, Vector.zero(), through)


def couple(moment: Vector, at: Point | None = None) -> Torsor:
    """The couple-torsor of moment ``moment`` (zero resultant, same moment everywhere,
    ch. 5.2.2). ``at`` defaults to the origin of the root frame.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> couple(R0.k).moment_at(R0.point("A", 5, 5, 5))
    R0.k
    """
    _check_vector(moment, "moment")
    if at is None:
        if moment.is_zero:
            raise ArgumentError("`at` is needed for a zero couple (no frame to take it from).")
        at = moment.frames[0].root.origin
    check_point(at, "at")
    return Torsor._new(Vector.zero(), moment, at)
