"""The torsor {R ; M(A)}: the book's key concept and rigidmech's spine (book, ch. 5).

One type serves for every torsor of mechanics: kinematic {omega ; v(A)}, action {R ; M(A)},
kinetic {m v(G) ; sigma(A)} and dynamic {m a(G) ; delta(A)} torsors: one torsor algebra
for all of mechanics. A torsor is known by its resultant, its moment at one point (the point of
reduction) and that point; the moment field follows from the transport formula (ch. 5.1.2)

.. math:: \\mathbf{M}(B) = \\mathbf{M}(A) + \\mathbf{BA} \\wedge \\mathbf{R}.

Geometry of the moment field (ch. 5.1.6-5.2): the moment about an axis, the central axis
(a :class:`~rigidmech.vectors.geometry.Line`) and the pitch, the classification into zero
torsor, couple, slider or general torsor, and the resolution of any torsor into a slider
plus a couple (:class:`Resolution`), the simplest one having the slider on the central axis.
Printing follows the book: ``str`` gives ``{R ; M}_A``; LaTeX and sympy's ``pprint`` give
the braces with R over M and the point of reduction as a subscript.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.printing.pretty.stringpict import prettyForm

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import zero_decision
from ..vectors import Point, Vector
from ..vectors.geometry import Line
from ..vectors.points import check_point
from ._checks import (
    _axis_elements,
    _check_vector,
    _is_line,
    _make_line,
    _undecided,
    _vector_is_zero,
)

__all__ = ["Torsor", "Resolution", "slider", "couple"]

_KINDS = ("zero", "couple", "slider", "torsor")


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
    def __add__(self, other):
        if isinstance(other, Vector | Point):
            raise ArgumentTypeError(
                f"a Torsor can only be added to a Torsor; got {type(other).__name__}. Build "
                "the torsor first (slider(vector, through=point) or couple(vector))."
            )
        if not isinstance(other, Torsor):
            return NotImplemented
        return type(self)._new(
            self._resultant + other._resultant,
            self._moment + other.moment_at(self._point),
            self._point,
            like=self,
        )

    def __radd__(self, other):
        # sum(torsors) starts from 0
        if isinstance(other, int) and other == 0:
            return self
        return NotImplemented

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
    def classify(self, *, atol=None) -> str:
        """Classification (ch. 5.2): 'zero', 'couple', 'slider' or 'torsor'.

        Parameters
        ----------
        atol : float, optional
            ``None`` (default): exact decisions (sympy ``simplify``), as :attr:`kind`.
            A number: numeric decisions for float components, with the norm of the
            resultant, the norm of the moment (for R = 0) and the pitch length
            :math:`|\\mathbf{R}\\cdot\\mathbf{M}|/|\\mathbf{R}|` compared with ``atol``.

        Returns
        -------
        str
            'zero' (R = 0, M = 0), 'couple' (R = 0, M != 0, ch. 5.2.2), 'slider' (R != 0 and
            automoment 0: the moment vanishes on the central axis, ch. 5.2.1) or 'torsor'
            (automoment != 0, ch. 5.2.3).

        Raises
        ------
        ArgumentError
            When ``atol`` is None and a decision cannot be made for symbolic values (for
            example whether ``a*R0.i`` is zero, with ``a`` a symbol of unknown value): the
            message names the undecided quantity. Substitute values or give the symbols
            assumptions (``nonzero=True``, ``positive=True``).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> Torsor(resultant=R0.k, moment=1e-14 * R0.k, at=R0.origin).classify(atol=1e-9)
        'slider'
        >>> Torsor(resultant=R0.k, moment=1e-14 * R0.k, at=R0.origin).classify()
        'torsor'
        """
        if atol is not None:
            return self._classify_numeric(float(atol))
        r_zero = _vector_is_zero(self._resultant)
        if r_zero is None:
            raise _undecided("the resultant", self._resultant)
        if r_zero:
            m_zero = _vector_is_zero(self._moment)
            if m_zero is None:
                raise _undecided("the moment of a torsor with zero resultant", self._moment)
            return "zero" if m_zero else "couple"
        a = zero_decision(self.automoment)
        if a is None:
            raise _undecided("the automoment", self.automoment)
        return "slider" if a else "torsor"

    def _classify_numeric(self, atol):
        frame = (self._resultant.frames + self._moment.frames + (self._point.root,))[0]
        try:
            r = np.array([complex(x) for x in self._resultant.components(frame)]).real
            m = np.array([complex(x) for x in self._moment.components(frame)]).real
        except TypeError as exc:
            raise ArgumentError(
                "`atol` classification needs numeric components; got symbols. Substitute "
                "values first, or call classify() without `atol` for exact decisions."
            ) from exc
        nr = float(np.linalg.norm(r))
        if nr <= atol:
            return "zero" if np.linalg.norm(m) <= atol else "couple"
        return "slider" if abs(float(r @ m)) / nr <= atol else "torsor"

    @property
    def kind(self) -> str:
        """Classification (ch. 5.2): 'zero', 'couple' (R = 0, M != 0), 'slider' (R != 0,
        automoment 0) or 'torsor' (general).

        Decisions are exact (sympy ``simplify``, component by component); a case that
        cannot be decided for symbolic values raises :class:`ArgumentError` naming the
        undecided quantity. For float components with round-off use
        :meth:`classify` with ``atol``.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> Torsor(resultant=Vector.zero(), moment=R0.i, at=R0.origin).kind
        'couple'
        """
        return self.classify()

    def _require_resultant(self, what):
        r_zero = _vector_is_zero(self._resultant)
        if r_zero is None:
            raise _undecided("the resultant", self._resultant)
        if r_zero:
            raise ArgumentError(
                f"a torsor with zero resultant (a couple or the zero torsor) has no {what}: "
                "its moment is the same at every point (ch. 5.2.2)."
            )

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
        self._require_resultant("pitch")
        return sp.simplify(self.automoment / self._resultant.dot(self._resultant))

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
        self._require_resultant("central axis")
        r2 = self._resultant.dot(self._resultant)
        m = self.moment_at(near)
        return near.moved("I", self._resultant.cross(m) / r2)

    def central_axis(self) -> Line:
        """The central axis: the line of direction R through the central point (ch. 5.1.7).

        It is the locus of the points where the moment is parallel to the resultant; there
        the moment has its least norm, :math:`|\\mathbf{R}\\cdot\\mathbf{M}|/|\\mathbf{R}|`.

        Returns
        -------
        Line
            Through :meth:`central_point` (the point of the axis nearest to the point of
            reduction), with direction the resultant.

        Raises
        ------
        ArgumentError
            If the resultant is zero: a couple or the zero torsor has no central axis.

        Notes
        -----
        With :math:`\\mathbf{M}_A` the moment at the point of reduction A (ch. 5.1.7),

        .. math:: \\mathbf{AI} = \\frac{\\mathbf{R}\\wedge\\mathbf{M}_A}{R^2},\\qquad
                  \\mathbf{M}_I = \\frac{\\mathbf{R}\\cdot\\mathbf{M}_A}{R^2}\\,\\mathbf{R}.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> axis = Torsor(resultant=R0.k, moment=R0.i + 2 * R0.k, at=R0.origin).central_axis()
        >>> axis.point.coordinates(R0).T, axis.direction
        (Matrix([[0, 1, 0]]), R0.k)
        """
        return _make_line(self.central_point(), self._resultant)

    def moment_about(self, axis, direction: Vector | None = None) -> sp.Expr:
        """The moment about an axis: M(P) . u, P a point of the axis, u its unit direction
        (ch. 5.1.6). It does not depend on the point P chosen on the axis.

        Parameters
        ----------
        axis : Line or Point
            The axis, or one of its points (then give ``direction``).
        direction : Vector, optional
            Direction of the axis when ``axis`` is a Point; need not be a unit vector.

        Returns
        -------
        sympy expression

        Raises
        ------
        ArgumentTypeError
            If ``axis`` is neither a Line nor a Point, or ``direction`` is not a Vector.
        ArgumentError
            If ``direction`` is missing for a Point, given for a Line, or zero.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> T = Torsor(resultant=R0.i, moment=Vector.zero(), at=R0.origin)
        >>> T.moment_about(R0.point("P", 0, -2, 5), direction=3 * R0.k)
        -2
        """
        point, u = _axis_elements(axis, direction)
        return self.moment_at(point).dot(u) / u.magnitude()

    def resolve(self, through) -> Resolution:
        """Resolution into a slider through a given point plus a couple (ch. 5.2.3).

        Parameters
        ----------
        through : Point or Line
            The point of the slider's line (its direction is that of the resultant), or that
            line itself, which must then be parallel to the resultant.

        Returns
        -------
        Resolution
            ``slider`` = {R ; 0} reduced at the point, ``couple`` = {0 ; M(point)}; their sum
            is this torsor at every point.

        Raises
        ------
        ArgumentTypeError
            If ``through`` is neither a Point nor a Line.
        ArgumentError
            If ``through`` is a Line not parallel to the resultant.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> T = Torsor(resultant=R0.k, moment=R0.i, at=R0.origin)
        >>> slider_part, couple_part = T.resolve(R0.point("B", 0, 0, 7))
        >>> couple_part.moment
        R0.i
        >>> (slider_part + couple_part).equals(T)
        True
        """
        if _is_line(through):
            point, u = _axis_elements(through, None)
            if _vector_is_zero(self._resultant) is False and \
                    _vector_is_zero(self._resultant.cross(u)) is not True:
                raise ArgumentError(
                    "`through` must be a line parallel to the resultant "
                    f"{self._resultant!r}; got a line of direction {u!r}. Pass a Point to "
                    "take the parallel line through it."
                )
        else:
            if isinstance(through, Vector):
                raise ArgumentTypeError(
                    "`through` must be a Point or a Line (a Vector is not a Point: use "
                    "A.moved(name, vector)); got Vector."
                )
            check_point(through, "through")
            point = through
        return Resolution(
            Torsor._new(self._resultant, Vector.zero(), point),
            Torsor._new(Vector.zero(), self.moment_at(point), point),
        )

    def simplest_form(self) -> Resolution:
        """The simplest resolution: a slider on the central axis plus a couple parallel to
        the resultant (ch. 5.2.3-5.2.4).

        Returns
        -------
        Resolution
            ``slider`` = {R ; 0} at the central point I, ``couple`` = {0 ; p R} with p the
            pitch: the least moment. For a slider the couple is zero; for a couple (R = 0)
            the slider is the zero torsor and the couple is the torsor itself.

        Raises
        ------
        ArgumentError
            If it cannot be decided whether the resultant is zero (symbolic values).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> T = Torsor(resultant=R0.k, moment=R0.i + 2 * R0.k, at=R0.origin)
        >>> form = T.simplest_form()
        >>> form.slider.point.coordinates(R0).T, form.couple.moment
        (Matrix([[0, 1, 0]]), 2*R0.k)
        """
        r_zero = _vector_is_zero(self._resultant)
        if r_zero is None:
            raise _undecided("the resultant", self._resultant)
        if r_zero:
            return Resolution(Torsor._new(Vector.zero(), Vector.zero(), self._point),
                              Torsor._new(Vector.zero(), self._moment, self._point))
        point = self.central_point()
        least = self._resultant * self.pitch
        return Resolution(Torsor._new(self._resultant, Vector.zero(), point),
                          Torsor._new(Vector.zero(), least, point))

    # -- transforms and comparison ------------------------------------------------------
    def applyfunc(self, func) -> Torsor:
        """Apply ``func`` to every component of the resultant and the moment."""
        return type(self)._new(self._resultant.applyfunc(func), self._moment.applyfunc(func),
                               self._point, like=self)

    def subs(self, *args, **kwargs) -> Torsor:
        """Substitute values in the resultant, the moment and the point of reduction, frames
        included (see :meth:`Vector.subs`): the result no longer depends on what was
        substituted.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> T = Torsor(resultant=R1.i, moment=Vector.zero(), at=R0.origin).subs(q, 0)
        >>> T.resultant.components(R0).T
        Matrix([[1, 0, 0]])
        """
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

    def _pretty(self, printer=None):
        """sympy's ``pprint``: the book's braces, R above M, the point as a subscript."""
        if printer is not None and not printer._use_unicode:
            return prettyForm(str(self))
        r, m = str(self._resultant), str(self._moment)
        w = max(len(r), len(m))
        pad = " " * len(self._point.name)
        return prettyForm("\n".join([f"\u23a7 {r:<{w}} \u23ab{pad}",
                                     f"\u23a8 {'':<{w}} \u23ac{pad}",
                                     f"\u23a9 {m:<{w}} \u23ad{self._point.name}"]))


class Resolution:
    """A torsor resolved into a slider plus a couple (ch. 5.2.3-5.2.4).

    Returned by :meth:`Torsor.resolve` and :meth:`Torsor.simplest_form`; immutable. It
    unpacks as ``slider, couple = T.resolve(B)``, and :attr:`torsor` (the sum) is the
    resolved torsor, at every point.

    Parameters
    ----------
    slider : Torsor
        The slider {R ; 0}, reduced at a point of its line (R may be zero).
    couple : Torsor
        The couple {0 ; C}.

    Examples
    --------
    >>> from rigidmech import Frame, Torsor
    >>> R0 = Frame("R0")
    >>> T = Torsor(resultant=R0.k, moment=R0.i + 2 * R0.k, at=R0.origin)
    >>> form = T.simplest_form()
    >>> form
    Resolution(slider=Torsor(resultant=R0.k, moment=0, at=I),
               couple=Torsor(resultant=0, moment=2*R0.k, at=I))
    >>> print(form)
    {k_R0 ; 0}_I + {0 ; 2 k_R0}_I
    >>> form.torsor.equals(T)
    True
    """

    __slots__ = ("_slider", "_couple")

    def __init__(self, slider: Torsor, couple: Torsor):
        for value, argument in ((slider, "slider"), (couple, "couple")):
            if not isinstance(value, Torsor):
                raise ArgumentTypeError(
                    f"`{argument}` must be a Torsor; got {type(value).__name__}.")
        if _vector_is_zero(slider.moment) is False:
            raise ArgumentError(
                f"`slider` must have a zero moment at its point; got {slider.moment!r}.")
        if _vector_is_zero(couple.resultant) is False:
            raise ArgumentError(
                f"`couple` must have a zero resultant; got {couple.resultant!r}.")
        self._slider = slider
        self._couple = couple

    @property
    def slider(self) -> Torsor:
        """The slider part {R ; 0}, reduced at a point of its line."""
        return self._slider

    @property
    def couple(self) -> Torsor:
        """The couple part {0 ; C}."""
        return self._couple

    @property
    def torsor(self) -> Torsor:
        """The sum slider + couple, reduced at the slider's point."""
        return self._slider + self._couple

    def axis(self) -> Line:
        """The line of the slider (through its point, direction R).

        Raises
        ------
        ArgumentError
            If the resultant is zero (the slider is then the zero torsor).

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> R0 = Frame("R0")
        >>> T = Torsor(resultant=R0.i, moment=R0.k, at=R0.origin)
        >>> T.resolve(R0.point("B", 0, 0, 1)).axis().direction
        R0.i
        """
        self._slider._require_resultant("slider line")
        return _make_line(self._slider.point, self._slider.resultant)

    def __iter__(self):
        return iter((self._slider, self._couple))

    def __eq__(self, other):
        if not isinstance(other, Resolution):
            return NotImplemented
        return self._slider == other._slider and self._couple == other._couple

    def __hash__(self):
        return hash((Resolution, self._slider, self._couple))

    def __repr__(self):
        return f"Resolution(slider={self._slider!r}, couple={self._couple!r})"

    def __str__(self):
        return f"{self._slider} + {self._couple}"

    def _latex(self, printer=None):
        return f"{self._slider._latex(printer)} + {self._couple._latex(printer)}"

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
