"""Linear dependence, arbitrary bases and the metric (book, ch. 1.2-1.5).

A :class:`~rigidmech.vectors.Frame` carries a direct orthonormal basis. Chapter 1 of the book
also works in an *arbitrary* basis (e1, e2, e3) of the vector space: the scalar product then
needs the metric (the Gram matrix g_ij = e_i . e_j, ch. 1.3.3) and the vector product needs the
mixed product (e1, e2, e3) (ch. 1.4.2). :class:`Basis` holds three vectors of a frame tree and
gives these expressions; :func:`linearly_independent` and :func:`linear_dependence` decide the
independence of a family of vectors (ch. 1.2.2); :func:`double_cross` is the double vector
product (ch. 1.4.6).

Symbolic decisions (is a determinant zero? is a mixed product positive?) are made with
:func:`sympy.simplify`: an expression that simplifies to 0 is zero; any other expression is taken
as *generically* non-zero, that is non-zero for almost every value of its symbols.
"""

from __future__ import annotations

from itertools import combinations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import is_identically_zero
from .vector import Vector

__all__ = ["linearly_independent", "linear_dependence", "Basis", "double_cross"]


def _check_vectors(vectors, argument):
    for n, v in enumerate(vectors):
        if not isinstance(v, Vector):
            raise ArgumentTypeError(
                f"`{argument}` must be Vectors; got {type(v).__name__} at position {n}."
            )


def _reference_frame(vectors):
    for v in vectors:
        if v.frames:
            return v.frames[0]
    return None


def _component_matrix(vectors, frame=None):
    """3 x n matrix whose columns are the components of ``vectors`` in ``frame``."""
    frame = frame if frame is not None else _reference_frame(vectors)
    if frame is None:
        return sp.zeros(3, len(vectors))
    return sp.Matrix.hstack(*(v.components(frame) for v in vectors))


def linearly_independent(*vectors) -> bool:
    """Tell whether the vectors are linearly independent (book, ch. 1.2.2).

    Parameters
    ----------
    *vectors : Vector
        One to three vectors (more than three vectors of the 3-dimensional space are always
        dependent). They may use several bases of one frame tree.

    Returns
    -------
    bool
        True if no non-trivial combination of the vectors is zero.

    Raises
    ------
    ArgumentError
        If no vector is given.
    ArgumentTypeError
        If an argument is not a Vector.

    Notes
    -----
    The vectors are expressed in one basis (the first basis used by the first non-zero
    vector); they are independent when the matrix of their components has rank n, that is
    when one of its n x n minors is non-zero. A minor is zero when :func:`sympy.simplify`
    reduces it to 0. The symbolic answer is *generic*: ``True`` means that a minor is not
    identically zero, although it may vanish for particular values of the symbols (for
    ``a i + j`` and ``i + a j``, the determinant ``a**2 - 1`` vanishes for a = 1 and
    a = -1); substitute values to decide such cases. Zero-testing of sympy expressions is
    undecidable in general: a minor that is zero but that ``simplify`` cannot reduce makes the
    function answer ``True``. Floating-point components are taken as exact (a number counts as
    zero below 1e-25 only): round-off makes nearly dependent vectors independent, so give
    rationals or round the data first.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> linearly_independent(R0.i, R0.i + R0.j, R0.k)
    True
    >>> linearly_independent(R0.i, R0.j, R0.i - 2 * R0.j)
    False
    """
    _check_vectors(vectors, "vectors")
    n = len(vectors)
    if n == 0:
        raise ArgumentError("`vectors` must hold at least one Vector; got none.")
    if n > 3:
        return False
    m = _component_matrix(vectors)
    return any(not is_identically_zero(m.extract(list(rows), list(range(n))).det())
               for rows in combinations(range(3), n))


def linear_dependence(*vectors):
    """Coefficients of a linear dependence relation between vectors (book, ch. 1.2.2).

    Parameters
    ----------
    *vectors : Vector
        At least one vector.

    Returns
    -------
    tuple of sympy expressions or None
        Coefficients (lambda_1, ..., lambda_n), not all zero, with
        lambda_1 u_1 + ... + lambda_n u_n = 0; None if the vectors are linearly independent.

    Raises
    ------
    ArgumentError
        If no vector is given.

    Notes
    -----
    The relation is a vector of the null space of the component matrix, computed by sympy with
    simplification; the decision follows :func:`linearly_independent` (generic answer for
    symbolic components).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> linear_dependence(R0.i, R0.j, R0.i - 2 * R0.j)
    (-1, 2, 1)
    >>> linear_dependence(R0.i, R0.j) is None
    True
    """
    if linearly_independent(*vectors):
        return None
    m = _component_matrix(vectors)
    null = m.nullspace(simplify=True)
    if not null:  # simplify found the determinant zero but the row reduction did not
        return None
    return tuple(sp.simplify(x) for x in null[0])


def double_cross(u: Vector, v: Vector, w: Vector) -> Vector:
    """Double vector product u ^ (v ^ w) = (u . w) v - (u . v) w (book, ch. 1.4.6).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> double_cross(R0.i, R0.i, R0.j)
    -R0.j
    >>> R0.i.cross(R0.i.cross(R0.j))
    -R0.j
    """
    _check_vectors((u, v, w), "u, v, w")
    return u.dot(w) * v - u.dot(v) * w


class Basis:
    """A basis (e1, e2, e3) of the vector space, orthonormal or not (book, ch. 1.2.3).

    Parameters
    ----------
    e1, e2, e3 : Vector
        Three non-coplanar vectors of one frame tree.
    frame : Frame, optional
        Frame in whose orthonormal basis the computations are made (scalar products do not
        depend on it); defaults to the first frame used by ``e1``.

    Raises
    ------
    ArgumentError
        If the vectors are coplanar (zero mixed product): they do not form a basis.

    Notes
    -----
    With contravariant components u = u^i e_i (summation over i), the book gives (ch. 1.3.3,
    1.4.2)

    .. math:: \\mathbf{u}\\cdot\\mathbf{v} = g_{ij}\\,u^i v^j, \\qquad
              \\mathbf{u}\\wedge\\mathbf{v} = (u^2 v^3 - u^3 v^2)\\,\\mathbf{e}_2\\wedge
              \\mathbf{e}_3 + (u^3 v^1 - u^1 v^3)\\,\\mathbf{e}_3\\wedge\\mathbf{e}_1
              + (u^1 v^2 - u^2 v^1)\\,\\mathbf{e}_1\\wedge\\mathbf{e}_2

    with g_ij = e_i . e_j and e_j ^ e_k = (e1, e2, e3) e^i for (i, j, k) a circular
    permutation, e^i being the reciprocal basis (e^i . e_j = delta_ij, e^i = g^ij e_j).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> b = Basis(R0.i, R0.i + R0.j, R0.k)
    >>> b.metric
    Matrix([
    [1, 1, 0],
    [1, 2, 0],
    [0, 0, 1]])
    >>> b.components_of(R0.j).T
    Matrix([[-1, 1, 0]])
    >>> b.is_orthonormal, b.is_direct
    (False, True)
    """

    __slots__ = ("_vectors", "_frame", "_metric", "_volume")

    def __init__(self, e1: Vector, e2: Vector, e3: Vector, *, frame=None):
        vectors = (e1, e2, e3)
        _check_vectors(vectors, "e1, e2, e3")
        if frame is None:
            frame = _reference_frame(vectors)
        m = _component_matrix(vectors, frame)
        volume = sp.simplify(m.det()) if frame is not None else sp.S.Zero
        if is_identically_zero(volume):
            raise ArgumentError(
                f"`e1, e2, e3` must be non-coplanar to form a basis; got {e1!r}, {e2!r}, "
                f"{e3!r}, whose mixed product is 0."
            )
        self._vectors = vectors
        self._frame = frame
        self._volume = volume
        self._metric = sp.ImmutableMatrix(
            3, 3, lambda a, b: sp.simplify(vectors[a].dot(vectors[b])))

    @classmethod
    def of(cls, frame) -> Basis:
        """The orthonormal basis (i, j, k) of ``frame``.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> Basis.of(Frame("R0")).is_orthonormal
        True
        """
        return cls(frame.i, frame.j, frame.k, frame=frame)

    @property
    def vectors(self):
        """The basis vectors (e1, e2, e3)."""
        return self._vectors

    def __iter__(self):
        return iter(self._vectors)

    def __getitem__(self, n):
        return self._vectors[n]

    @property
    def metric(self) -> sp.ImmutableMatrix:
        """The metric g_ij = e_i . e_j (Gram matrix, ch. 1.3.3)."""
        return self._metric

    @property
    def mixed_product(self) -> sp.Expr:
        """The mixed product (e1, e2, e3) = e1 . (e2 ^ e3) (ch. 1.4.5).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Basis(2 * R0.i, R0.j, R0.k).mixed_product
        2
        """
        return self._volume

    def components_of(self, vector: Vector) -> sp.ImmutableMatrix:
        """Contravariant components u^i of ``vector``: u = u^i e_i (ch. 1.2.4).

        They solve the linear system g_ij u^j = e_i . u made by the metric.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Basis(R0.i + R0.j, R0.j, R0.k).components_of(R0.i).T
        Matrix([[1, -1, 0]])
        """
        _check_vectors((vector,), "vector")
        return sp.ImmutableMatrix(
            self._metric.LUsolve(self.covariant_components_of(vector)).applyfunc(sp.simplify))

    def covariant_components_of(self, vector: Vector) -> sp.ImmutableMatrix:
        """Covariant components u_i = e_i . u (the scalar products with the basis vectors).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Basis(R0.i + R0.j, R0.j, R0.k).covariant_components_of(R0.i).T
        Matrix([[1, 0, 0]])
        """
        _check_vectors((vector,), "vector")
        return sp.ImmutableMatrix(3, 1, [sp.simplify(e.dot(vector)) for e in self._vectors])

    def vector(self, c1, c2, c3) -> Vector:
        """The vector c1 e1 + c2 e2 + c3 e3.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Basis(R0.i + R0.j, R0.j, R0.k).vector(1, -1, 2)
        R0.i + 2*R0.k
        """
        return sum((sp.sympify(c) * e for c, e in zip((c1, c2, c3), self._vectors,
                                                      strict=True)), Vector.zero())

    def dot(self, c_u, c_v) -> sp.Expr:
        """Scalar product of two vectors given by their components in this basis (ch. 1.3.3).

        Parameters
        ----------
        c_u, c_v : sequence of 3 scalars
            Contravariant components u^i and v^j.

        Returns
        -------
        sympy expression
            g_ij u^i v^j.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Basis(R0.i, R0.i + R0.j, R0.k).dot((0, 1, 0), (0, 1, 0))
        2
        """
        u = _column(c_u, "c_u")
        v = _column(c_v, "c_v")
        return sp.expand((u.T * self._metric * v)[0, 0])

    def cross(self, c_u, c_v) -> sp.ImmutableMatrix:
        """Components in this basis of the vector product u ^ v (ch. 1.4.2).

        Parameters
        ----------
        c_u, c_v : sequence of 3 scalars
            Contravariant components of u and v.

        Returns
        -------
        sympy.ImmutableMatrix, shape (3, 1)
            Contravariant components w^k of w = u ^ v: w^k = (e1, e2, e3) g^kl eps_lij u^i v^j,
            with eps the permutation symbol and g^kl the inverse metric.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> b = Basis(R0.i, R0.i + R0.j, R0.k)
        >>> b.cross((1, 0, 0), (0, 1, 0)).T
        Matrix([[0, 0, 1]])
        """
        u = _column(c_u, "c_u")
        v = _column(c_v, "c_v")
        lowered = sp.Matrix([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]]) * self._volume
        return sp.ImmutableMatrix(self._metric.LUsolve(lowered).applyfunc(sp.simplify))

    def reciprocal(self) -> Basis:
        """The reciprocal basis (e^1, e^2, e^3) with e^i . e_j = delta_ij (ch. 1.4.2).

        e^1 = e2 ^ e3 / V, e^2 = e3 ^ e1 / V, e^3 = e1 ^ e2 / V, with V = (e1, e2, e3).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Basis(2 * R0.i, R0.j, R0.k).reciprocal().vectors[0]
        1/2*R0.i
        """
        e1, e2, e3 = self._vectors
        v = self._volume
        return Basis(e2.cross(e3) / v, e3.cross(e1) / v, e1.cross(e2) / v, frame=self._frame)

    @property
    def is_orthonormal(self) -> bool:
        """Whether the metric is the identity (ch. 1.3.5)."""
        return all(is_identically_zero(self._metric[a, b] - (1 if a == b else 0))
                   for a in range(3) for b in range(3))

    @property
    def is_direct(self) -> bool:
        """Whether the mixed product (e1, e2, e3) is positive (ch. 1.4.3).

        Raises
        ------
        ArgumentError
            If the sign of a symbolic mixed product cannot be decided from the assumptions
            on its symbols (declare them ``positive=True``, or substitute values).

        Examples
        --------
        >>> from rigidmech.vectors import Frame, constants
        >>> a = constants("a", positive=True)
        >>> R0 = Frame("R0")
        >>> Basis(a * R0.i, R0.j, R0.k).is_direct
        True
        >>> Basis(R0.j, R0.i, R0.k).is_direct
        False
        """
        positive = self._volume.is_positive
        if positive is None:
            raise ArgumentError(
                f"cannot decide whether the basis is direct: the sign of its mixed product "
                f"{self._volume} is unknown; declare its symbols positive or substitute values."
            )
        return bool(positive)

    def change_of_basis_matrix(self, other: Basis) -> sp.ImmutableMatrix:
        """Matrix P of the change from this basis to ``other`` (ch. 1.5.2).

        The columns of P are the components of ``other``'s vectors in this basis, so that the
        components of a vector change as u (in self) = P u (in other). This is the convention
        of :meth:`Frame.dcm <rigidmech.vectors.Frame.dcm>`.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> old = Basis.of(R0)
        >>> new = Basis(R0.i + R0.j, R0.j, R0.k)
        >>> old.change_of_basis_matrix(new)
        Matrix([
        [1, 0, 0],
        [1, 1, 0],
        [0, 0, 1]])
        """
        if not isinstance(other, Basis):
            raise ArgumentTypeError(f"`other` must be a Basis; got {type(other).__name__}.")
        return sp.ImmutableMatrix.hstack(*(self.components_of(e) for e in other._vectors))

    def __eq__(self, other):
        if not isinstance(other, Basis):
            return NotImplemented
        return self._vectors == other._vectors

    def __hash__(self):
        return hash(self._vectors)

    def __repr__(self):
        e1, e2, e3 = self._vectors
        return f"Basis({e1!r}, {e2!r}, {e3!r})"


def _column(c, argument):
    try:
        entries = [sp.sympify(x) for x in c]
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be 3 numbers or sympy expressions; got {c!r}."
        ) from exc
    if not all(isinstance(x, sp.Expr) for x in entries):
        raise ArgumentTypeError(f"`{argument}` must be 3 numbers or sympy expressions; got {c!r}.")
    col = sp.Matrix(entries)
    if col.shape != (3, 1):
        raise ArgumentError(f"`{argument}` must have 3 components; got {len(col)}: {c!r}.")
    return col
