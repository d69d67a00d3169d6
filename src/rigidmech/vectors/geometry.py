"""Lines and planes of the geometric space (book, ch. 2.1-2.4).

A :class:`Line` is a point and a direction (ch. 2.2.1), a :class:`Plane` a point and a normal
(ch. 2.2.2, 2.4.1). Both are immutable values built from the points and vectors of a frame tree.
Intersections, parallelism and orthogonality (ch. 2.2.3-2.2.4), distances and the common
perpendicular of two lines and the angle of two bipoints (ch. 2.1.4) complete them; the change of
reference system (ch. 2.5) is in :mod:`rigidmech.vectors.reference_change`.

Symbolic decisions (are two directions parallel? does a point lie on a plane?) simplify the
expression concerned and compare it with zero; see
:func:`rigidmech.vectors.basis.linearly_independent` for what this means for symbolic data.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import is_identically_zero
from .points import Point, check_point
from .vector import Vector, _check_frame, _check_vector

__all__ = [
    "Line", "Plane", "intersection", "is_parallel", "is_orthogonal", "distance",
    "common_perpendicular", "angle",
]


def _vector_is_zero(v: Vector) -> bool:
    if v.is_zero:
        return True
    return all(is_identically_zero(c) for c in v.components(v.frames[0]))


def _at(base: Point, displacement: Vector, name: str) -> Point:
    return base.moved(name, displacement)


class Line:
    """A line: a point A and a non-zero direction u; the points A + lambda u (ch. 2.2.1).

    Parameters
    ----------
    point : Point
    direction : Vector
        Non-zero; kept as given (not normalised).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> L = Line(R0.origin, R0.i + R0.j)
    >>> L.contains(R0.point("P", 2, 2, 0))
    True
    """

    __slots__ = ("_point", "_direction")

    def __init__(self, point: Point, direction: Vector):
        check_point(point, "point")
        _check_vector(direction, "direction")
        if _vector_is_zero(direction):
            raise ArgumentError(
                "`direction` must be a non-zero Vector to define a line; got the zero vector."
            )
        self._point = point
        self._direction = direction

    @classmethod
    def through(cls, A: Point, B: Point) -> Line:
        """The line through two distinct points, directed by the bipoint AB.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Line.through(R0.origin, R0.point("B", 0, 0, 2)).direction
        2*R0.k
        """
        check_point(A, "A")
        check_point(B, "B")
        if _vector_is_zero(B - A):
            raise ArgumentError(
                f"`A` and `B` must be distinct points to define a line; got {A.name} and "
                f"{B.name} at the same place."
            )
        return cls(A, B - A)

    @classmethod
    def from_planes(cls, plane1: Plane, plane2: Plane, *, name: str = "A") -> Line:
        """The line where two non-parallel planes meet (ch. 2.4.2).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> L = Line.from_planes(Plane(R0.origin, R0.i), Plane(R0.origin, R0.j))
        >>> L.direction
        R0.k
        """
        return intersection(plane1, plane2, name=name)

    @classmethod
    def from_equations(cls, frame, equation1, equation2, *, name: str = "A") -> Line:
        """The line of Cartesian equations a1 x + b1 y + c1 z + d1 = 0 and
        a2 x + b2 y + c2 z + d2 = 0 in ``frame`` (ch. 2.4.2).

        Parameters
        ----------
        frame : Frame
        equation1, equation2 : sequence of 4 scalars
            The coefficients (a, b, c, d) of each plane.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> L = Line.from_equations(R0, (1, 0, 0, -1), (0, 1, 0, -2))
        >>> L.point.coordinates(R0).T, L.direction
        (Matrix([[1, 2, 0]]), R0.k)
        """
        return cls.from_planes(Plane.from_equation(frame, *_coefficients(equation1, "equation1")),
                               Plane.from_equation(frame, *_coefficients(equation2, "equation2")),
                               name=name)

    @property
    def point(self) -> Point:
        """The point A of the line."""
        return self._point

    @property
    def direction(self) -> Vector:
        """The direction vector u."""
        return self._direction

    def point_at(self, parameter, name: str = "M") -> Point:
        """The point A + parameter u.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Line(R0.origin, R0.i).point_at(3).coordinates(R0).T
        Matrix([[3, 0, 0]])
        """
        return _at(self._point, sp.sympify(parameter) * self._direction, name)

    def contains(self, point: Point) -> bool:
        """Whether ``point`` lies on the line: AP ^ u = 0."""
        check_point(point, "point")
        return _vector_is_zero((point - self._point).cross(self._direction))

    def __eq__(self, other):
        if not isinstance(other, Line):
            return NotImplemented
        return self._point == other._point and self._direction == other._direction

    def __hash__(self):
        return hash((Line, self._point, self._direction))

    def __repr__(self):
        return f"Line({self._point.name}, {self._direction!r})"


class Plane:
    """A plane: a point A and a non-zero normal n; the points P with n . AP = 0 (ch. 2.2.2).

    Parameters
    ----------
    point : Point
    normal : Vector
        Non-zero; kept as given (not normalised).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> P = Plane(R0.point("A", 0, 0, 1), R0.k)
    >>> P.equation(R0)
    (0, 0, 1, -1)
    """

    __slots__ = ("_point", "_normal")

    def __init__(self, point: Point, normal: Vector):
        check_point(point, "point")
        _check_vector(normal, "normal")
        if _vector_is_zero(normal):
            raise ArgumentError(
                "`normal` must be a non-zero Vector to define a plane; got the zero vector."
            )
        self._point = point
        self._normal = normal

    @classmethod
    def through(cls, A: Point, B: Point, C: Point) -> Plane:
        """The plane through three non-collinear points, with normal AB ^ AC.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Plane.through(R0.origin, R0.point("B", 1, 0, 0), R0.point("C", 0, 1, 0)).normal
        R0.k
        """
        for p, arg in ((A, "A"), (B, "B"), (C, "C")):
            check_point(p, arg)
        n = (B - A).cross(C - A)
        if _vector_is_zero(n):
            raise ArgumentError(
                f"`A`, `B`, `C` must be non-collinear points to define a plane; got "
                f"{A.name}, {B.name}, {C.name} on one line."
            )
        return cls(A, n)

    @classmethod
    def from_equation(cls, frame, a, b, c, d, *, name: str = "A") -> Plane:
        """The plane a x + b y + c z + d = 0 in the reference system ``frame`` (ch. 2.4.1).

        The stored point is the foot of the perpendicular from the origin of ``frame``, the
        normal is a i + b j + c k.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> P = Plane.from_equation(R0, 0, 0, 2, -4)
        >>> P.point.coordinates(R0).T, P.normal
        (Matrix([[0, 0, 2]]), 2*R0.k)
        """
        _check_frame(frame, "frame")
        a, b, c, d = _coefficients((a, b, c, d), "a, b, c, d")
        n = frame.vector(a, b, c)
        if _vector_is_zero(n):
            raise ArgumentError(
                "`a, b, c` must not all be zero in a plane equation a x + b y + c z + d = 0; "
                f"got a={a}, b={b}, c={c}."
            )
        return cls(_at(frame.origin, sp.simplify(-d / (a**2 + b**2 + c**2)) * n, name), n)

    @property
    def point(self) -> Point:
        """The point A of the plane."""
        return self._point

    @property
    def normal(self) -> Vector:
        """The normal vector n."""
        return self._normal

    def equation(self, frame):
        """Coefficients (a, b, c, d) of the Cartesian equation a x + b y + c z + d = 0 of the
        plane in the reference system ``frame`` (ch. 2.4.1); (a, b, c) are the components of
        the normal in ``frame``.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Plane(R0.point("A", 1, 0, 0), R0.i + R0.j).equation(R0)
        (1, 1, 0, -1)
        """
        _check_frame(frame, "frame")
        a, b, c = (sp.simplify(x) for x in self._normal.components(frame))
        d = sp.simplify(-self._normal.dot(self._point - frame.origin))
        return (a, b, c, d)

    def contains(self, point: Point) -> bool:
        """Whether ``point`` lies in the plane: n . AP = 0."""
        check_point(point, "point")
        return is_identically_zero(self._normal.dot(point - self._point))

    def __eq__(self, other):
        if not isinstance(other, Plane):
            return NotImplemented
        return self._point == other._point and self._normal == other._normal

    def __hash__(self):
        return hash((Plane, self._point, self._normal))

    def __repr__(self):
        return f"Plane({self._point.name}, {self._normal!r})"


def _coefficients(values, argument):
    try:
        out = tuple(sp.sympify(x) for x in values)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be numbers or sympy expressions; got {values!r}."
        ) from exc
    if len(out) != 4:
        raise ArgumentError(
            f"`{argument}` must hold the 4 coefficients (a, b, c, d) of a x + b y + c z + d = 0; "
            f"got {len(out)}."
        )
    return out


def _kind(x, argument, allowed=(Line, Plane)):
    if not isinstance(x, allowed):
        names = " or ".join(c.__name__ for c in allowed)
        raise ArgumentTypeError(f"`{argument}` must be a {names}; got {type(x).__name__}.")
    return x


def intersection(a, b, *, name: str = "I"):
    """Intersection of two lines, a line and a plane, or two planes (ch. 2.2).

    Parameters
    ----------
    a, b : Line or Plane
    name : str
        Name of the point returned (for a plane and a plane: of the point of the line).

    Returns
    -------
    Point, Line or None
        * line and plane: the point where they meet;
        * plane and plane: their line of intersection, directed by n1 ^ n2;
        * line and line: the common point of secant lines; None for two distinct parallel
          lines and for skew lines (not coplanar), which have no common point.

    Raises
    ------
    ArgumentError
        For parallel planes, a line parallel to a plane (no point, or every point of the
        line if it lies in the plane) and two coincident lines.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> L = Line(R0.point("A", 1, 1, 5), R0.k)
    >>> intersection(L, Plane(R0.origin, R0.k)).coordinates(R0).T
    Matrix([[1, 1, 0]])
    >>> intersection(L, Line(R0.origin, R0.j)) is None
    True
    """
    _kind(a, "a")
    _kind(b, "b")
    if isinstance(a, Plane) and isinstance(b, Line):
        a, b = b, a
    if isinstance(a, Line) and isinstance(b, Plane):
        u, n = a.direction, b.normal
        un = u.dot(n)
        if is_identically_zero(un):
            where = "lies in" if b.contains(a.point) else "does not meet"
            raise ArgumentError(
                f"`a` and `b` must not be parallel to intersect a line and a plane; got a line "
                f"parallel to the plane (it {where} the plane)."
            )
        lam = sp.simplify(n.dot(b.point - a.point) / un)
        return _at(a.point, lam * u, name)
    if isinstance(a, Plane):
        n1, n2 = a.normal, b.normal
        u = n1.cross(n2)
        if _vector_is_zero(u):
            same = "the same plane" if b.contains(a.point) else "distinct parallel planes"
            raise ArgumentError(
                f"`a` and `b` must be non-parallel planes to intersect in a line; got {same}."
            )
        h1, h2 = n1.dot(a.point.position), n2.dot(b.point.position)
        g11, g12, g22 = n1.dot(n1), n1.dot(n2), n2.dot(n2)
        det = g11 * g22 - g12**2
        x = (sp.simplify((h1 * g22 - h2 * g12) / det) * n1
             + sp.simplify((h2 * g11 - h1 * g12) / det) * n2)
        return Line(_at(a.point.root.origin, x, name), u)
    # two lines
    u1, u2 = a.direction, b.direction
    n = u1.cross(u2)
    w = b.point - a.point
    if _vector_is_zero(n):
        if a.contains(b.point):
            raise ArgumentError(
                "`a` and `b` must be distinct lines to have one common point; got two "
                "coincident lines (every point is common)."
            )
        return None
    if not is_identically_zero(w.dot(n)):
        return None
    lam = sp.simplify(w.cross(u2).dot(n) / n.dot(n))
    return _at(a.point, lam * u1, name)


def is_parallel(a, b) -> bool:
    """Whether two lines, a line and a plane, or two planes are parallel (ch. 2.2.3).

    Lines: u1 ^ u2 = 0; line and plane: u . n = 0; planes: n1 ^ n2 = 0. Coincident lines and
    planes, and a line lying in a plane, count as parallel.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> is_parallel(Line(R0.origin, R0.i), Plane(R0.point("A", 0, 0, 1), R0.k))
    True
    """
    _kind(a, "a")
    _kind(b, "b")
    va = a.direction if isinstance(a, Line) else a.normal
    vb = b.direction if isinstance(b, Line) else b.normal
    if isinstance(a, Line) != isinstance(b, Line):
        return is_identically_zero(va.dot(vb))
    return _vector_is_zero(va.cross(vb))


def is_orthogonal(a, b) -> bool:
    """Whether two lines, a line and a plane, or two planes are orthogonal (ch. 2.2.4).

    Lines: u1 . u2 = 0 (they need not meet); line and plane: u ^ n = 0; planes: n1 . n2 = 0.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> is_orthogonal(Plane(R0.origin, R0.i), Plane(R0.origin, R0.j))
    True
    """
    _kind(a, "a")
    _kind(b, "b")
    va = a.direction if isinstance(a, Line) else a.normal
    vb = b.direction if isinstance(b, Line) else b.normal
    if isinstance(a, Line) != isinstance(b, Line):
        return _vector_is_zero(va.cross(vb))
    return is_identically_zero(va.dot(vb))


def _point_line(p, line):
    u = line.direction
    return (p - line.point).cross(u).magnitude() / u.magnitude()


def _point_plane(p, plane):
    n = plane.normal
    return sp.Abs(n.dot(p - plane.point)) / n.magnitude()


def distance(a, b):
    """Distance between points, lines and planes (ch. 2.1.3, 2.2).

    Parameters
    ----------
    a, b : Point, Line or Plane

    Returns
    -------
    sympy expression
        * point-line: ``|AP ^ u| / |u|``; point-plane: ``|n . AP| / |n|``;
        * line-line: ``|(A2 - A1) . (u1 ^ u2)| / |u1 ^ u2|`` (the length of the common
          perpendicular), or the point-line distance for parallel lines;
        * line-plane and plane-plane: 0 when they meet, else the distance from a point.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> distance(Line(R0.origin, R0.i), Line(R0.point("A", 0, 0, 3), R0.j))
    3
    >>> distance(R0.point("P", 1, 2, 3), Plane(R0.origin, R0.k))
    3
    """
    allowed = (Point, Line, Plane)
    _kind(a, "a", allowed)
    _kind(b, "b", allowed)
    order = {Point: 0, Line: 1, Plane: 2}
    if order[type(a)] > order[type(b)]:
        a, b = b, a
    if isinstance(a, Point):
        if isinstance(b, Point):
            d = a.distance(b)
        elif isinstance(b, Line):
            d = _point_line(a, b)
        else:
            d = _point_plane(a, b)
    elif isinstance(a, Line) and isinstance(b, Line):
        n = a.direction.cross(b.direction)
        if _vector_is_zero(n):
            d = _point_line(b.point, a)
        else:
            d = sp.Abs((b.point - a.point).dot(n)) / n.magnitude()
    else:
        d = _point_plane(a.point, b) if is_parallel(a, b) else sp.S.Zero
    return sp.simplify(d)


def common_perpendicular(line1: Line, line2: Line, *, names=("H1", "H2")):
    """Feet (H1, H2) of the common perpendicular of two non-parallel lines (ch. 2.2.4).

    H1 = A1 + lambda1 u1 and H2 = A2 + lambda2 u2 with H1H2 orthogonal to u1 and u2:
    ``lambda1 = ((A2 - A1) ^ u2) . n / |n|^2`` and ``lambda2 = ((A2 - A1) ^ u1) . n / |n|^2``,
    n = u1 ^ u2. The distance between the lines is ``|H1H2|``; H1 = H2 for secant lines.

    Raises
    ------
    ArgumentError
        For parallel lines, which have infinitely many common perpendiculars.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> H1, H2 = common_perpendicular(Line(R0.origin, R0.i), Line(R0.point("A", 0, 5, 3), R0.j))
    >>> H1.coordinates(R0).T, H2.coordinates(R0).T
    (Matrix([[0, 0, 0]]), Matrix([[0, 0, 3]]))
    """
    _kind(line1, "line1", (Line,))
    _kind(line2, "line2", (Line,))
    u1, u2 = line1.direction, line2.direction
    n = u1.cross(u2)
    if _vector_is_zero(n):
        raise ArgumentError(
            "`line1` and `line2` must not be parallel to have a single common perpendicular; "
            "got parallel lines (use distance() for their distance)."
        )
    w = line2.point - line1.point
    nn = n.dot(n)
    l1 = sp.simplify(w.cross(u2).dot(n) / nn)
    l2 = sp.simplify(w.cross(u1).dot(n) / nn)
    return (_at(line1.point, l1 * u1, names[0]), _at(line2.point, l2 * u2, names[1]))


def angle(u: Vector, v: Vector):
    """Angle in [0, pi] between two non-zero vectors, e.g. the bipoints AB and AC (ch. 2.1.4).

    ``cos(angle) = u . v / (|u| |v|)``.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> A, B, C = R0.origin, R0.point("B", 1, 0, 0), R0.point("C", 1, 1, 0)
    >>> angle(B - A, C - A)
    pi/4
    """
    _check_vector(u, "u")
    _check_vector(v, "v")
    for x, arg in ((u, "u"), (v, "v")):
        if _vector_is_zero(x):
            raise ArgumentError(f"`{arg}` must be a non-zero vector to have an angle; got 0.")
    return sp.simplify(sp.acos(u.dot(v) / (u.magnitude() * v.magnitude())))
