"""The operator of inertia of a body at a point (book, ch. 15).

The operator of inertia of a body (S) at a point O maps a vector u to

.. math:: \\mathcal{J}_O(S)(\\mathbf{u}) = \\int_S \\mathbf{OM} \\wedge (\\mathbf{u} \\wedge
          \\mathbf{OM})\\, dm ,

a symmetric linear map (ch. 15.1.3). In the basis (i, j, k) of a frame its matrix has the book's
layout

.. math:: [\\mathcal{J}_O(S)]_{(i,j,k)} = \\begin{bmatrix} A & -F & -E \\\\ -F & B & -D \\\\
          -E & -D & C \\end{bmatrix}, \\quad
          A = \\int (y^2 + z^2)\\,dm,\\ D = \\int yz\\,dm,\\ E = \\int zx\\,dm,\\
          F = \\int xy\\,dm ,

with (x, y, z) the coordinates of M relative to O. The operator does not know the mass of
the body: the relations of Huygens (:meth:`InertiaOperator.moved`) take it as an argument.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.printing.latex import LatexPrinter

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import simplifies_to_zero
from ..vectors import Point, Vector
from ..vectors._rotations import rotation_steps
from ._checks import (
    PRODUCT_NAMES,
    REL_TOL,
    check_frame,
    check_inertia,
    check_point,
    check_same_tree,
    nonnegative,
    scalar,
)
from .principal import PrincipalAxes, principal_axes

__all__ = ["InertiaOperator"]

_ZERO = sp.S.Zero

#: Value of the private flag ``_central`` of a catalogue operator built without ``centre=``:
#: central, at the origin of its frame only until a body places it at its mass centre.
UNPLACED = "unplaced"


def _sym(rows):
    """Immutable symmetric matrix from the upper triangle of ``rows`` (lists of 3)."""
    return sp.ImmutableMatrix(3, 3, lambda r, c: rows[min(r, c)][max(r, c)])


def _huygens(mass, d):
    """Huygens term m [(d.d) I - d d^T] for d = PG in components (ch. 15.2.2)."""
    if all(x == 0 for x in d):
        return None
    dd = sp.Add(*(x * x for x in d if x != 0))
    rows = [[mass * (dd - d[r] * d[c]) if r == c else -mass * d[r] * d[c]
             for c in range(3)] for r in range(3)]
    return rows


def _elementary_step(J, axis, angle):
    """J in the basis rotated by ``angle`` about basis vector ``axis`` (double angles, so that
    an operator of revolution about the axis stays exactly unchanged)."""
    n, a, b = axis, (axis + 1) % 3, (axis + 2) % 3
    Jaa, Jbb, Jab, Jan, Jbn = J[a, a], J[b, b], J[a, b], J[a, n], J[b, n]
    c, s = sp.cos(angle), sp.sin(angle)
    new = [[None] * 3 for _ in range(3)]
    new[n][n] = J[n, n]
    if Jaa == Jbb and Jab == 0:
        new[a][a], new[b][b], new[a][b] = Jaa, Jbb, _ZERO
    else:
        c2, s2 = sp.cos(2 * angle), sp.sin(2 * angle)
        half_sum, half_diff = (Jaa + Jbb) / 2, (Jaa - Jbb) / 2
        new[a][a] = half_sum + half_diff * c2 + Jab * s2
        new[b][b] = half_sum - half_diff * c2 - Jab * s2
        new[a][b] = -half_diff * s2 + Jab * c2
    new[a][n] = c * Jan + s * Jbn
    new[b][n] = -s * Jan + c * Jbn
    return sp.ImmutableMatrix(3, 3, lambda r, k: new[min(r, k)][max(r, k)]
                              if new[min(r, k)][max(r, k)] is not None
                              else new[max(r, k)][min(r, k)])


def _bad_entry(value):
    """The first entry of a nested list/tuple that is neither a number nor a sympy
    expression (a string, which sympy would read as a symbol; None; any other object, which
    sympy would keep in a Matrix with a deprecation warning), or None if there is none."""
    if isinstance(value, list | tuple):
        for v in value:
            bad = _bad_entry(v)
            if bad is not None:
                return bad
        return None
    if isinstance(value, bool) or not isinstance(value, int | float | complex | np.number
                                                   | sp.Expr | np.ndarray):
        return (value,)
    return None


class InertiaOperator:
    """The operator of inertia of a body at a point, in the basis of a frame (ch. 15.1.3).

    Build it with :meth:`from_products` or :meth:`from_matrix`, or take one from the
    catalogue of homogeneous bodies (:func:`rigidmech.inertia.rod`, ...). Instances are
    immutable; every operation returns a new operator.

    Attributes
    ----------
    matrix : sympy.ImmutableMatrix, shape (3, 3)
        The matrix in the book's layout [[A, -F, -E], [-F, B, -D], [-E, -D, C]].
    frame : Frame
        The frame whose basis the matrix is expressed in.
    at : Point
        The point O at which the operator is taken.
    A, B, C : sympy expressions
        Moments of inertia about the axes (O, i), (O, j), (O, k).
    D, E, F : sympy expressions
        Products of inertia: D = int yz dm, E = int zx dm, F = int xy dm.

    Notes
    -----
    Conventions of the book (ch. 15.1.3): the products of inertia appear with a minus sign
    off the diagonal. ``==`` is exact and structural; use :meth:`is_close` (numbers) or
    :meth:`equals` (symbols) to compare values.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> from rigidmech.inertia import InertiaOperator
    >>> R0 = Frame("R0")
    >>> A, B, C, F = sp.symbols("A B C F")
    >>> J = InertiaOperator.from_products(A, B, C, F=F, frame=R0, at=R0.origin)
    >>> J.matrix
    Matrix([
    [ A, -F, 0],
    [-F,  B, 0],
    [ 0,  0, C]])
    >>> J.apply(R0.i)
    A*R0.i - F*R0.j
    """

    __slots__ = ("_matrix", "_frame", "_at", "_hash", "_central", "_shape")

    def __init__(self, *args, **kwargs):
        raise TypeError(
            "build an InertiaOperator with InertiaOperator.from_products(A, B, C, D, E, F, "
            "frame=, at=), InertiaOperator.from_matrix(matrix, frame=, at=) or from the "
            "catalogue (rigidmech.inertia.rod, disk, cylinder, ...)."
        )

    @classmethod
    def _make(cls, matrix, frame, at, central=False, shape=None):
        obj = object.__new__(cls)
        obj._shape = shape
        obj._matrix = matrix
        obj._frame = frame
        obj._at = at
        obj._hash = None
        obj._central = central
        return obj

    # -- construction -------------------------------------------------------------------
    @classmethod
    def from_products(cls, A, B, C, D=0, E=0, F=0, *, frame, at=None) -> InertiaOperator:
        """The operator with moments A, B, C and products D, E, F (ch. 15.1.3).

        Parameters
        ----------
        A, B, C : number or sympy expression
            Moments of inertia about (O, i), (O, j), (O, k); non-negative, each at most the
            sum of the other two (ch. 15.3.2).
        D, E, F : number or sympy expression, optional
            Products of inertia int yz dm, int zx dm, int xy dm (default 0).
        frame : Frame
            The frame whose basis (i, j, k) the values refer to.
        at : Point, optional
            The point O; defaults to the origin of ``frame``.

        Raises
        ------
        ArgumentError
            If a moment is negative, a triangle inequality fails, or (numbers) the matrix
            has a negative principal moment.
        ArgumentTypeError
            If an argument has the wrong type.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> InertiaOperator.from_products(2, 3, 4, F=1, frame=R0).matrix
        Matrix([
        [ 2, -1, 0],
        [-1,  3, 0],
        [ 0,  0, 4]])
        """
        frame = check_frame(frame, "frame")
        at = cls._check_at(frame, at)
        a, b, c, d, e, f = (scalar(x, n) for x, n in zip(
            (A, B, C, D, E, F), "ABCDEF", strict=True))
        matrix = sp.ImmutableMatrix([[a, -f, -e], [-f, b, -d], [-e, -d, c]])
        check_inertia(matrix, "A, B, C, D, E, F", products=True)
        return cls._make(matrix, frame, at)

    @classmethod
    def from_matrix(cls, matrix, *, frame, at=None) -> InertiaOperator:
        """The operator whose matrix in the basis of ``frame`` is ``matrix`` (book's layout).

        Parameters
        ----------
        matrix : array_like or sympy Matrix, shape (3, 3)
            Symmetric, [[A, -F, -E], [-F, B, -D], [-E, -D, C]]. Numeric entries may differ
            from their mirror by round-off (relative 1e-10); the mean is kept.
        frame : Frame
        at : Point, optional
            Defaults to the origin of ``frame``.

        Raises
        ------
        ArgumentError
            If ``matrix`` is not 3x3, not symmetric, or cannot be an operator of inertia.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> J = InertiaOperator.from_matrix([[2, -1, 0], [-1, 3, 0], [0, 0, 4]], frame=R0)
        >>> J.F
        1
        >>> InertiaOperator.from_matrix([[2, -2, 0], [-3, 3, 0], [0, 0, 4]], frame=R0)
        Traceback (most recent call last):
        ...
        rigidmech._core.errors.ArgumentError: `matrix` must be symmetric; got F=2 above ... below.
        """
        frame = check_frame(frame, "frame")
        at = cls._check_at(frame, at)
        bad = _bad_entry(matrix) if isinstance(matrix, list | tuple) else None
        if bad is not None and isinstance(bad[0], str | bytes):
            raise ArgumentTypeError(
                "`matrix` must be a number or a sympy expression in every entry; got a string "
                "(a string is not read as a symbol).")
        if bad is not None:
            raise ArgumentTypeError(
                "`matrix` must be a number or a sympy expression in every entry; got "
                f"{type(bad[0]).__name__} {bad[0]!r}.")
        try:
            m = sp.Matrix(matrix)
        except (sp.SympifyError, TypeError, ValueError) as exc:
            raise ArgumentTypeError(
                f"`matrix` must be a 3x3 array or sympy Matrix; got {type(matrix).__name__}."
            ) from exc
        if m.shape != (3, 3):
            raise ArgumentError(f"`matrix` must be 3x3; got shape {m.shape}.")
        m = m.applyfunc(lambda x: scalar(x, "matrix"))
        for r, c in ((0, 1), (0, 2), (1, 2)):
            up, low = m[r, c], m[c, r]
            if up == low or sp.expand(up - low) == 0:
                m[c, r] = up
                continue
            if up.is_number and low.is_number:
                scale = max(abs(float(x)) for x in m)
                if abs(float(up - low)) <= REL_TOL * scale:
                    m[r, c] = m[c, r] = (up + low) / 2
                    continue
            name = PRODUCT_NAMES[r, c]
            raise ArgumentError(
                f"`matrix` must be symmetric; got {name}={sp.sstr(-up)} above the diagonal "
                f"and {name}={sp.sstr(-low)} below."
            )
        matrix = sp.ImmutableMatrix(m)
        check_inertia(matrix, "matrix")
        return cls._make(matrix, frame, at)

    @staticmethod
    def _check_at(frame, at):
        if at is None:
            return frame.origin
        check_point(at, "at")
        check_same_tree(frame, at, "at")
        return at

    # -- access -------------------------------------------------------------------------
    @property
    def matrix(self) -> sp.ImmutableMatrix:
        """The 3x3 matrix in the book's layout, in the basis of :attr:`frame`."""
        return self._matrix

    @property
    def frame(self):
        """The frame whose basis the matrix is expressed in."""
        return self._frame

    @property
    def is_central(self) -> bool:
        """True for an operator known to be taken at the body's mass centre (the catalogue's
        operators, and the result of :meth:`moved` to the mass centre)."""
        return bool(self._central)

    @property
    def shape(self):
        """The :class:`~rigidmech.inertia.Shape` of the homogeneous body of the catalogue
        this operator is (ch. 15.5), or None (an operator given by its moments, a sum, an
        operator moved by Huygens). Kept by :meth:`placed_at`, :meth:`in_basis`,
        :meth:`subs` and :meth:`simplify`; not part of ``==``.

        Examples
        --------
        >>> from rigidmech.inertia import rod
        >>> from rigidmech.vectors import Frame
        >>> R1 = Frame("R1")
        >>> rod(1, 2, axis=R1.i).shape.kind
        'rod'
        >>> InertiaOperator.from_products(1, 1, 1, frame=R1).shape is None
        True
        """
        return self._shape

    @property
    def is_placed(self) -> bool:
        """False only for a catalogue operator built without ``centre=``: central, but its
        point (the origin of its frame) is a default that a
        :class:`~rigidmech.kinetics.Body` replaces by its own mass centre.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.inertia import disk
        >>> from rigidmech.vectors import Frame
        >>> R1 = Frame("R1")
        >>> disk(1, 2, axis=R1.k).is_placed, disk(1, 2, axis=R1.k, centre=R1.origin).is_placed
        (False, True)
        """
        return self._central != UNPLACED

    def placed_at(self, centre: Point) -> InertiaOperator:
        """The same central operator, taken at the mass centre ``centre`` of the body.

        The catalogue gives the operator of a homogeneous body at its mass centre; when no
        ``centre`` was given there, this places it (a :class:`~rigidmech.kinetics.Body` does
        it with its own mass centre). Only a central operator can be placed: any other one
        changes point by the relations of Huygens (:meth:`moved`).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.inertia import rod
        >>> from rigidmech.vectors import Frame
        >>> m, L = sp.symbols("m L", positive=True)
        >>> R1 = Frame("R1")
        >>> G = R1.point("G", L / 2, 0, 0)
        >>> rod(m, L, axis=R1.i).placed_at(G).at.name
        'G'
        """
        check_point(centre, "centre")
        if not self._central:
            raise ArgumentError(
                f"only an operator taken at the mass centre can be placed at another point; "
                f"this one is at {self._at.name}. Use moved(to, mass=, centre=) (Huygens)."
            )
        check_same_tree(self._frame, centre, "centre")
        return InertiaOperator._make(self._matrix, self._frame, centre, True, self._shape)

    @property
    def at(self) -> Point:
        """The point at which the operator is taken."""
        return self._at

    A = property(lambda self: self._matrix[0, 0], doc="Moment of inertia about (O, i).")
    B = property(lambda self: self._matrix[1, 1], doc="Moment of inertia about (O, j).")
    C = property(lambda self: self._matrix[2, 2], doc="Moment of inertia about (O, k).")
    D = property(lambda self: -self._matrix[1, 2], doc="Product of inertia int yz dm.")
    E = property(lambda self: -self._matrix[0, 2], doc="Product of inertia int zx dm.")
    F = property(lambda self: -self._matrix[0, 1], doc="Product of inertia int xy dm.")

    # -- the operator -------------------------------------------------------------------
    def apply(self, vector: Vector) -> Vector:
        """The image J_O(u) of a vector, expressed in the basis of :attr:`frame` (ch. 15.1.3).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> J = InertiaOperator.from_products(2, 3, 4, frame=R0)
        >>> J.apply(R0.i + R0.k)
        2*R0.i + 4*R0.k
        """
        if not isinstance(vector, Vector):
            raise ArgumentTypeError(f"`vector` must be a Vector; got {type(vector).__name__}.")
        u = vector._comps(self._frame)
        m = self._matrix
        out = [sp.Add(*(m[r, c] * u[c] for c in range(3) if m[r, c] != 0 and u[c] != 0))
               for r in range(3)]
        return Vector.from_components(self._frame, out)

    def moment_about(self, axis: Vector) -> sp.Expr:
        """Moment of inertia about the axis through :attr:`at` directed by ``axis``
        (ch. 15.3.4): :math:`I_\\Delta = \\mathbf{u} \\cdot \\mathcal{J}_O(\\mathbf{u})` for
        the unit vector u of the axis.

        Parameters
        ----------
        axis : Vector
            Direction of the axis; need not be a unit vector (it is divided by its squared
            norm), must not be zero.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> J = InertiaOperator.from_products(2, 2, 4, frame=R0)
        >>> J.moment_about(R0.i + R0.k)
        3
        """
        if not isinstance(axis, Vector):
            raise ArgumentTypeError(f"`axis` must be a Vector; got {type(axis).__name__}.")
        u = axis._comps(self._frame)
        norm2 = sp.Add(*(x * x for x in u if x != 0))
        if norm2 == 0:
            raise ArgumentError("`axis` must be a non-zero vector; got the zero vector.")
        num = sp.Add(*(self._matrix[r, c] * u[r] * u[c] for r in range(3) for c in range(3)
                       if u[r] != 0 and u[c] != 0 and self._matrix[r, c] != 0))
        return num if norm2 == 1 else num / norm2

    def components(self, frame) -> sp.ImmutableMatrix:
        """The matrix in the basis of ``frame``: ``self.in_basis(frame).matrix``.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> InertiaOperator.from_products(1, 2, 3, frame=R0).components(R0).diagonal()
        Matrix([[1, 2, 3]])
        """
        return self.in_basis(frame)._matrix

    def in_basis(self, frame) -> InertiaOperator:
        """The same operator (same point) with its matrix in the basis of ``frame``
        (ch. 15.2.4): :math:`[J]_{new} = P^T [J]_{old} P`, P the direction cosines whose
        columns are the new basis vectors in the old basis.

        The change of basis holds at each instant, whatever the motion of one frame relative
        to the other: entries may depend on the parameters of situation. Rotations about one
        basis vector are applied with double angles, so that an operator of revolution about
        that vector comes back unchanged (no cos^2 + sin^2 to simplify).

        Raises
        ------
        FrameError
            If ``frame`` belongs to another frame tree.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> J = InertiaOperator.from_products(1, 1, 2, frame=R0)
        >>> J.in_basis(R1).matrix == J.matrix
        True
        >>> InertiaOperator.from_products(1, 3, 3, frame=R0).in_basis(R1).A
        2 - cos(2*q(t))
        """
        check_frame(frame, "frame")
        if frame == self._frame:
            return self
        J = self._matrix
        for axis, value in rotation_steps(self._frame, frame):
            if axis is not None:
                J = _elementary_step(J, axis, value)
            else:
                P = sp.ImmutableMatrix(value)
                full = P.T * J * P
                J = _sym([[full[r, c] for c in range(3)] for r in range(3)])
        return InertiaOperator._make(J, frame, self._at, self._central, self._shape)

    def moved(self, to: Point, *, mass, centre: Point) -> InertiaOperator:
        """The operator at ``to``, by the relations of Huygens (ch. 15.2.1-15.2.2).

        .. math:: \\mathcal{J}_P(S) = \\mathcal{J}_G(S) + \\mathcal{J}_P(G, m), \\quad
                  [\\mathcal{J}_P(G, m)] = m \\left[ (\\mathbf{PG} \\cdot \\mathbf{PG})\\,I -
                  \\mathbf{PG}\\,\\mathbf{PG}^T \\right]

        The operator goes through the mass centre G: from :attr:`at` back to G, then to
        ``to``. The basis is unchanged.

        Parameters
        ----------
        to : Point
        mass : number or sympy expression
            Mass m of the body (>= 0).
        centre : Point
            Mass centre G of the body.

        Raises
        ------
        ArgumentError
            If the mass is negative, if this operator is a central one (:attr:`is_central`,
            the catalogue's) and ``centre`` is not the point it is taken at, or (numbers) if
            the operator at G implied by ``mass`` and ``centre`` is not an operator of
            inertia.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> from rigidmech.inertia import rod
        >>> m, L = sp.symbols("m L", positive=True)
        >>> R0 = Frame("R0")
        >>> G = R0.point("G", L / 2, 0, 0)
        >>> J = rod(m, L, axis=R0.i, centre=G).moved(R0.origin, mass=m, centre=G)
        >>> J.C
        L**2*m/3
        """
        check_point(to, "to")
        check_point(centre, "centre")
        check_same_tree(self._frame, to, "to")
        check_same_tree(self._frame, centre, "centre")
        mass = nonnegative(mass, "mass")
        if self._central and centre != self._at and not (centre - self._at).is_zero:
            raise ArgumentError(
                f"this operator is a central one, taken at the mass centre {self._at.name} of "
                f"its body, but `centre` is {centre.name}: moving it would use the wrong "
                f"Huygens term. Build it at that centre (the catalogue's `centre=`) or place it "
                f"there first: `.placed_at({centre.name}).moved(...)`."
            )
        J = self._matrix
        back = _huygens(mass, (centre - self._at)._comps(self._frame))
        if back is not None:
            J = J - sp.ImmutableMatrix(back)
            try:
                check_inertia(J, "mass", scale=self._matrix)
            except ArgumentError as exc:
                raise ArgumentError(
                    f"`mass` and `centre` do not fit this operator at {self._at.name}: "
                    f"removing the Huygens term leaves at {centre.name} a matrix that is not "
                    f"an operator of inertia ({exc}). Check the mass and the mass centre."
                ) from None
        forth = _huygens(mass, (centre - to)._comps(self._frame))
        if forth is not None:
            J = J + sp.ImmutableMatrix(forth)
        central = to == centre
        if back is None and forth is None:
            return InertiaOperator._make(J, self._frame, to, central)
        return InertiaOperator._make(_sym([[J[r, c] for c in range(3)] for r in range(3)]),
                                     self._frame, to, central)

    def principal_axes(self) -> PrincipalAxes:
        """Principal moments and axes of inertia at :attr:`at` (ch. 15.2.3).

        See :func:`rigidmech.inertia.principal_axes`.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> J = InertiaOperator.from_products(3, 3, 4, F=1, frame=R0)
        >>> J.principal_axes().moments
        (4, 2, 4)
        >>> J.principal_axes().axes[0]
        sqrt(2)/2*R0.i - sqrt(2)/2*R0.j
        >>> J = InertiaOperator.from_products(4.0, 5.0, 6.0, D=0.5, E=0.5, F=1.0, frame=R0)
        >>> [round(x, 4) for x in J.principal_axes().moments]
        [3.2115, 5.5767, 6.2118]
        """
        return principal_axes(self._matrix, self._frame)

    # -- algebra (associativity, ch. 15.4.4) --------------------------------------------
    def _check_common_point(self, other, operation):
        if not isinstance(other, InertiaOperator):
            raise ArgumentTypeError(
                f"`other` must be an InertiaOperator; got {type(other).__name__}."
            )
        if other._at != self._at:
            d = other._at - self._at
            if not (d.is_zero or d.equals(Vector.zero())):
                raise ArgumentError(
                    f"operators of inertia {operation} only at a common point (ch. 15.4.4); "
                    f"got one at {self._at.name} and one at {other._at.name}: move one with "
                    f"`.moved({self._at.name}, mass=..., centre=...)` first."
                )
        return other.in_basis(self._frame)._matrix

    def __add__(self, other):
        """Operator of the union of two bodies, at a common point (ch. 15.4.4)."""
        if not isinstance(other, InertiaOperator):
            if isinstance(other, int) and other == 0:
                return self
            return NotImplemented
        M = self._check_common_point(other, "add")
        return InertiaOperator._make(self._matrix + M, self._frame, self._at)

    def __radd__(self, other):
        if isinstance(other, int) and other == 0:
            return self
        return NotImplemented

    def __sub__(self, other):
        """Operator of a body with a part removed (a hole), at a common point (ch. 15.4.4)."""
        if not isinstance(other, InertiaOperator):
            return NotImplemented
        M = self._check_common_point(other, "subtract")
        matrix = self._matrix - M
        check_inertia(matrix, "other", scale=self._matrix)
        return InertiaOperator._make(matrix, self._frame, self._at)

    def __mul__(self, scalar_):
        if isinstance(scalar_, InertiaOperator | Vector):
            return NotImplemented
        try:
            s = nonnegative(scalar_, "scalar")
        except ArgumentTypeError:
            return NotImplemented
        return InertiaOperator._make(self._matrix * s, self._frame, self._at)

    __rmul__ = __mul__

    def __truediv__(self, scalar_):
        s = nonnegative(scalar_, "scalar")
        if s == 0:
            raise ArgumentError("`scalar` must be non-zero to divide an operator; got 0.")
        return InertiaOperator._make(self._matrix / s, self._frame, self._at)

    # -- transforms and comparison ------------------------------------------------------
    def subs(self, *args, **kwargs) -> InertiaOperator:
        """Substitute values in the entries, the point and the frame of the basis (sympy's
        ``subs``; frames as in :meth:`~rigidmech.vectors.Frame.subs`).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> m = sp.Symbol("m"); R0 = Frame("R0")
        >>> InertiaOperator.from_products(m, m, 2 * m, frame=R0).subs(m, 3).C
        6
        """
        return InertiaOperator._make(self._matrix.subs(*args, **kwargs),
                                     self._frame.subs(*args, **kwargs),
                                     self._at.subs(*args, **kwargs), self._central,
                                     None if self._shape is None
                                     else self._shape.subs(*args, **kwargs))

    def simplify(self) -> InertiaOperator:
        """The operator with simplified entries (never done unless asked).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> x = sp.Symbol("x"); R0 = Frame("R0")
        >>> J = InertiaOperator.from_products(sp.sin(x)**2 + sp.cos(x)**2, 1, 1, frame=R0)
        >>> J.simplify().A
        1
        """
        return InertiaOperator._make(self._matrix.applyfunc(sp.simplify), self._frame,
                                     self._at, self._central, self._shape)

    def is_close(self, other, *, rtol=1e-9, atol=0.0) -> bool:
        """Numeric closeness of the matrices (in this operator's basis) and of the points.

        Raises
        ------
        ArgumentError
            If an entry or a coordinate is not a number.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> J = InertiaOperator.from_products(1.0, 1.0, 1.0, frame=R0)
        >>> J.is_close(J * (1 + 1e-12))
        True
        """
        if not isinstance(other, InertiaOperator):
            raise ArgumentTypeError(
                f"`other` must be an InertiaOperator; got {type(other).__name__}."
            )
        try:
            a = np.array(self._matrix.tolist(), dtype=float)
            b = np.array(other.in_basis(self._frame)._matrix.tolist(), dtype=float)
            pa = np.array((self._at - self._frame.origin)._comps(self._frame), dtype=float)
            pb = np.array((other._at - self._frame.origin)._comps(self._frame), dtype=float)
        except TypeError as exc:
            raise ArgumentError(
                "`is_close` needs numeric entries and coordinates; substitute values first "
                "(`subs`) or use `equals` for a symbolic comparison."
            ) from exc
        return bool(np.allclose(a, b, rtol=rtol, atol=atol)
                    and np.allclose(pa, pb, rtol=rtol, atol=atol))

    def equals(self, other) -> bool:
        """Symbolic equality: same point and matrices whose difference simplifies to zero.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> J = InertiaOperator.from_products(1, 2, 3, frame=R0)
        >>> J.in_basis(R1).in_basis(R0).equals(J)
        True
        """
        if not isinstance(other, InertiaOperator):
            raise ArgumentTypeError(
                f"`other` must be an InertiaOperator; got {type(other).__name__}."
            )
        d = other._at - self._at
        if not (d.is_zero or d.equals(Vector.zero())):
            return False
        diff = self._matrix - other.in_basis(self._frame)._matrix
        return all(simplifies_to_zero(x) for x in diff)

    def __eq__(self, other):
        if not isinstance(other, InertiaOperator):
            return NotImplemented
        return (self._frame == other._frame and self._at == other._at
                and self._matrix == other._matrix)

    def __hash__(self):
        if self._hash is None:
            self._hash = hash((self._matrix, self._frame, self._at))
        return self._hash

    # -- printing -----------------------------------------------------------------------
    def __repr__(self):
        args = [sp.sstr(x) for x in (self.A, self.B, self.C)]
        args += [f"{n}={sp.sstr(x)}" for n, x in zip("DEF", (self.D, self.E, self.F),
                                                      strict=True) if x != 0]
        args += [f"frame={self._frame.name}", f"at={self._at.name}"]
        return f"InertiaOperator.from_products({', '.join(args)})"

    def __str__(self):
        rows = "; ".join(", ".join(sp.sstr(x) for x in self._matrix.row(r)) for r in range(3))
        return f"J({self._at.name}) in ({self._frame.name}): [{rows}]"

    def _latex(self, printer=None):
        printer = printer or LatexPrinter()
        f = printer._print(sp.Symbol(self._frame.name))
        basis = ", ".join(rf"\vec{{{u}}}_{{{f}}}" for u in "ijk")
        body = r" \\ ".join(" & ".join(printer._print(x) for x in self._matrix.row(r))
                            for r in range(3))
        at = printer._print(sp.Symbol(self._at.name))
        return (rf"\mathcal{{J}}_{{{at}}} = \begin{{bmatrix}} {body} \end{{bmatrix}}"
                rf"_{{({basis})}}")

    def _repr_latex_(self):
        return f"$\\displaystyle {self._latex()}$"
