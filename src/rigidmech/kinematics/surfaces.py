"""Surfaces of solids in contact and their point of contact (book, ch. 10.1).

Two solids touch at a point I where their surfaces have a common tangent plane, of normal n
(ch. 10.1.1). For the simple surfaces of the book's examples the contact point and the common
normal follow from the geometry:

================  ======================================  ===============================
surfaces          in contact when                         contact point I
================  ======================================  ===============================
sphere / plane    distance(C, plane) = r                  C - r n
cylinder / plane  axis parallel to the plane at height r  axis point A - r n
circle / line     line in the circle's plane at           foot of the perpendicular from
(in a plane)      distance r from C                       C to the line
circle / plane    height of C = r abs(d), with            C - r d / abs(d) (disc above
(disc in 3D)      d = n - (n . a) a (a: disc's axis)      the plane)
circle / circle   C1C2 = r1 + r2 (external) or            C1 + r1 C1C2 / C1C2 (external),
(coplanar)        C1C2 = abs(r1 - r2) (internal)          on the line of the centres
sphere / sphere   C1C2 = r1 + r2 or abs(r1 - r2)          as for circles
================  ======================================  ===============================

Planes and lines are :class:`~rigidmech.vectors.Plane` and :class:`~rigidmech.vectors.Line`;
spheres, cylinders and circles are the value types of this module. Radii must be positive.
Contact is decided by the library's one rule for "does this expression vanish": its values at
random points, in 64-digit arithmetic for exact data, with algebra only when they do not
decide; float data count to their rounding. Surfaces that are not provably in contact are
refused, with the gap in the message. For a disc on a plane, d is
written along a basis vector of the frames of the problem when it can be (d = lambda e, for example
e = j of the frame after the precession and the nutation of Euler angles), so that no
square root is needed; the normal is the plane's, turned towards the disc when the sign of the
centre's height is known.
"""

from __future__ import annotations

from typing import NamedTuple

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from .._core.symbolic import vanishes
from ..vectors import Line, Plane, Point, Vector
from ..vectors.points import check_point

__all__ = ["Sphere", "Cylinder", "Circle", "ContactGeometry", "contact_geometry"]


def _radius(radius):
    try:
        r = sp.sympify(radius)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`radius` must be a number or a sympy expression; got {type(radius).__name__}."
        ) from exc
    if not isinstance(r, sp.Expr) or r.is_positive is False or (r.is_number and r.is_zero):
        raise ArgumentError(f"`radius` must be positive; got {r}.")
    return r


def _vector(v, argument):
    if isinstance(v, Point) or not isinstance(v, Vector):
        kind = f"the Point {v.name}" if isinstance(v, Point) else type(v).__name__
        raise ArgumentTypeError(f"`{argument}` must be a Vector; got {kind}.")
    if v.is_zero:
        raise ArgumentError(f"`{argument}` must be a non-zero Vector; got the zero vector.")
    return v


def _unit(v):
    n2 = sp.simplify(v.dot(v))
    return v if n2 == 1 else v / sp.sqrt(n2)


# A numeric gap at most this fraction of the size of the surfaces (``scale``) is rounding of data
# given in floats (0.7 - 0.6 for 0.1): a contact, the rule of every gap below.
_GAP_RTOL = 1e-12


def _zero(x, scale=None) -> bool:
    """Whether the gap ``x`` is zero. With symbols, the rule of every such decision in the
    library, :func:`~rigidmech._core.symbolic.vanishes` (values at random points, algebra only
    when they do not decide; float constants to their rounding). A number is zero when its
    magnitude is at most _GAP_RTOL times the number ``scale`` (the size the gap is a
    difference of: a radius, a squared distance), exactly zero without one."""
    x = sp.sympify(x)
    if x == 0:
        return True
    if scale is not None and x.is_number:
        size = sp.sympify(scale)
        if size.is_number:
            return abs(complex(x)) <= _GAP_RTOL * abs(complex(size))
    return vanishes(x)


class Sphere:
    """A sphere of centre ``centre`` and radius ``radius`` (ch. 10.1).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> Sphere(Frame("R0").origin, 2).radius
    2
    """

    __slots__ = ("_centre", "_radius")

    def __init__(self, centre: Point, radius):
        check_point(centre, "centre")
        self._centre = centre
        self._radius = _radius(radius)

    @property
    def centre(self) -> Point:
        """The centre C."""
        return self._centre

    @property
    def radius(self):
        """The radius r > 0."""
        return self._radius

    def __repr__(self):
        return f"Sphere({self._centre.name}, {self._radius})"


class Cylinder:
    """A circular cylinder of axis ``axis`` (a :class:`~rigidmech.vectors.Line`) and radius
    ``radius`` (ch. 10.1).

    Examples
    --------
    >>> from rigidmech import Frame, Line
    >>> R0 = Frame("R0")
    >>> Cylinder(Line(R0.origin, R0.i), 1).axis.direction
    R0.i
    """

    __slots__ = ("_axis", "_radius")

    def __init__(self, axis: Line, radius):
        if not isinstance(axis, Line):
            raise ArgumentTypeError(f"`axis` must be a Line; got {type(axis).__name__}.")
        self._axis = axis
        self._radius = _radius(radius)

    @property
    def axis(self) -> Line:
        """The axis of the cylinder."""
        return self._axis

    @property
    def radius(self):
        """The radius r > 0."""
        return self._radius

    def __repr__(self):
        return f"Cylinder({self._axis!r}, {self._radius})"


class Circle:
    """A circle of centre ``centre``, radius ``radius``, in the plane of normal ``normal``:
    the rim of a disc or a wheel, or a pitch circle (ch. 10.1, 10.2).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> Circle(R0.origin, 3, normal=R0.k)
    Circle(O_R0, 3, normal=R0.k)
    """

    __slots__ = ("_centre", "_radius", "_normal")

    def __init__(self, centre: Point, radius, *, normal: Vector):
        check_point(centre, "centre")
        self._centre = centre
        self._radius = _radius(radius)
        self._normal = _unit(_vector(normal, "normal"))

    @property
    def centre(self) -> Point:
        """The centre C."""
        return self._centre

    @property
    def radius(self):
        """The radius r > 0."""
        return self._radius

    @property
    def normal(self) -> Vector:
        """Unit normal to the circle's plane (the axis of the disc)."""
        return self._normal

    def __repr__(self):
        return f"Circle({self._centre.name}, {self._radius}, normal={self._normal!r})"


class ContactGeometry(NamedTuple):
    """Where two surfaces touch: the contact point and the common unit normal, directed from
    the second surface towards the first (ch. 10.1.1).

    Examples
    --------
    >>> from rigidmech import Frame, Plane
    >>> R0 = Frame("R0")
    >>> g = contact_geometry(Sphere(R0.point("C", 0, 0, 1), 1), Plane(R0.origin, R0.k))
    >>> g.point.coordinates(R0).T, g.normal
    (Matrix([[0, 0, 0]]), R0.k)
    """

    point: Point
    normal: Vector


def contact_geometry(first, second, *, name: str = "I", inner: str | None = None
                     ) -> ContactGeometry:
    """The contact point and common normal of two surfaces in contact (ch. 10.1.1).

    Parameters
    ----------
    first, second : Sphere, Cylinder, Circle, Plane or Line
        The surfaces, in either order among the supported pairs (see the module's table).
    name : str
        Name of the contact point.
    inner : {"first", "second"}, optional
        For an internal contact of circles or spheres whose radii cannot be compared (symbols
        without a known order), which surface is inside the other.

    Returns
    -------
    ContactGeometry
        The point I and the unit normal n from ``second`` towards ``first``.

    Raises
    ------
    ConnectionError\\_
        If the surfaces are not in contact (the gap does not simplify to zero).
    ArgumentTypeError
        For a pair of surfaces this function does not treat.

    Examples
    --------
    A wheel of radius r, centre at height r above the line y = 0:

    >>> import sympy as sp
    >>> from rigidmech import Frame, Line, coordinates
    >>> x = coordinates("x"); r = sp.Symbol("r", positive=True)
    >>> R0 = Frame("R0")
    >>> rim = Circle(R0.point("C", x, r, 0), r, normal=R0.k)
    >>> I, n = contact_geometry(rim, Line(R0.origin, R0.i))
    >>> I.coordinates(R0).T, n
    (Matrix([[x(t), 0, 0]]), R0.j)
    """
    if inner not in (None, "first", "second"):
        raise ArgumentError(f"`inner` must be None, 'first' or 'second'; got {inner!r}.")
    for a, b, flip in ((first, second, False), (second, first, True)):
        solver = _PAIRS.get((type(a), type(b)))
        if solver is not None:
            inner_a = None if inner is None else ((inner == "first") != flip)
            point, normal = solver(a, b, name, inner_a)
            return ContactGeometry(point, -normal if flip else normal)
    raise ArgumentTypeError(
        f"contact between a {type(first).__name__} and a {type(second).__name__} is not "
        "treated; supported pairs: sphere/plane, cylinder/plane, circle/line, circle/circle, "
        "sphere/sphere (or give the contact point and normal yourself).")


def _not_in_contact(what, gap):
    raise ConnectionError_(
        f"the surfaces are not in contact: {what}; got a gap of {sp.simplify(gap)} (it must "
        "simplify to 0). Place the solids so that they touch.")


def _sphere_plane(s, p, name, _inner):
    n = _unit(p.normal)
    h = sp.simplify((s.centre - p.point).dot(n))
    if _zero(h - s.radius, s.radius):
        return s.centre.moved(name, -s.radius * n), n
    if _zero(h + s.radius, s.radius):
        return s.centre.moved(name, s.radius * n), -n
    _not_in_contact("the distance from the centre to the plane must equal the radius",
                    abs(h) - s.radius)


def _cylinder_plane(c, p, name, _inner):
    n = _unit(p.normal)
    if not _zero(c.axis.direction.dot(n), sp.sqrt(c.axis.direction.dot(c.axis.direction))):
        raise ConnectionError_(
            "the surfaces are not in contact along a line: the cylinder's axis must be "
            f"parallel to the plane; got axis . normal = {sp.simplify(c.axis.direction.dot(n))}.")
    h = sp.simplify((c.axis.point - p.point).dot(n))
    if _zero(h - c.radius, c.radius):
        return c.axis.point.moved(name, -c.radius * n), n
    if _zero(h + c.radius, c.radius):
        return c.axis.point.moved(name, c.radius * n), -n
    _not_in_contact("the distance from the axis to the plane must equal the radius",
                    abs(h) - c.radius)


def _circle_line(c, line, name, _inner):
    d = _unit(line.direction)
    k = c.normal
    off = sp.simplify((line.point - c.centre).dot(k))
    if not (_zero(d.dot(k), 1) and _zero(off, c.radius)):
        raise ConnectionError_(
            "the surfaces are not in contact: the line must lie in the circle's plane; got "
            f"direction . normal = {sp.simplify(d.dot(k))} and an offset of {off} from the "
            "plane.")
    cp = line.point - c.centre
    foot = cp - cp.dot(d) * d
    if not _zero(foot.dot(foot) - c.radius**2, 2 * c.radius**2):   # d^2 - r^2 ~ 2 r gap
        _not_in_contact("the distance from the centre to the line must equal the radius",
                        sp.sqrt(foot.dot(foot)) - c.radius)
    return c.centre.moved(name, foot), -foot / c.radius


def _frames_of(*vectors):
    out = []
    for v in vectors:
        for f, _ in v.parts:
            while f is not None:
                if f not in out:
                    out.append(f)
                f = f.parent
    return out


def _circle_plane(c, p, name, _inner):
    """A disc (circle of axis a) on a plane of normal n: the lowest point of the rim, on the
    direction d = n - (n . a) a of the steepest descent in the disc's plane."""
    n, a = _unit(p.normal), c.normal
    d = (n - n.dot(a) * a).compact()
    h = sp.simplify((c.centre - p.point).dot(n))
    if _zero(d.dot(d)):
        raise ConnectionError_(
            "the surfaces are not in contact at a point: the circle lies in a plane parallel "
            "to the plane (its axis is along the plane's normal).")
    # d = lam e along a basis vector e of a frame of the problem, when there is one: then
    # |d| = +-lam without a square root, and the branch is decided by the exact gap h -+ r lam
    e = next((e for f in _frames_of(a, n) for e in f.basis
              if _zero(d.cross(e).dot(d.cross(e)))), None)
    if e is not None:
        lam = sp.simplify(d.dot(e))
    else:
        lam = sp.sqrt(sp.simplify(d.dot(d)))
        e = d / lam
    # disc above (h > 0): lowest point C - r d/|d| at h = r |d|; below: highest point
    # C + r d/|d| at h = -r |d|. With d = lam e both cases give C - r e when h = r lam and
    # C + r e when h = -r lam, whatever the sign of lam.
    normal = -n if h.is_negative else n
    if _zero(h - c.radius * lam, c.radius):
        return c.centre.moved(name, -c.radius * e), normal
    if _zero(h + c.radius * lam, c.radius):
        return c.centre.moved(name, c.radius * e), normal
    _not_in_contact("the height of the centre above the plane must be r |n - (n . a) a|",
                    abs(h) - c.radius * abs(lam))


def _round_round(a, b, name, inner_a):
    """Circle/circle or sphere/sphere: n from b towards a."""
    if isinstance(a, Circle):
        k = a.normal
        off = sp.simplify((b.centre - a.centre).dot(k))
        if not (_zero(a.normal.cross(b.normal).dot(a.normal.cross(b.normal)))
                and _zero(off, a.radius + b.radius)):
            raise ConnectionError_(
                "the surfaces are not in contact: the circles must lie in one plane; got an "
                f"offset of {off} between their planes or planes that are not parallel.")
    ab = b.centre - a.centre
    d2 = ab.dot(ab)
    ra, rb = a.radius, b.radius
    if inner_a is None and _zero(d2 - (ra + rb) ** 2, 2 * (ra + rb) ** 2):
        return a.centre.moved(name, ra / (ra + rb) * ab), -ab / (ra + rb)
    if not _zero(d2 - (ra - rb) ** 2, 2 * (ra + rb) ** 2):
        _not_in_contact(
            "the distance between the centres must be the sum (external contact) or the "
            "difference (internal contact) of the radii",
            sp.sqrt(d2) - (ra + rb) if inner_a is None else sp.sqrt(d2) - abs(ra - rb))
    if inner_a is None:
        diff = sp.simplify(rb - ra)
        if diff.is_positive:
            inner_a = True
        elif diff.is_negative:
            inner_a = False
        else:
            raise ArgumentError(
                f"internal contact: cannot tell which of the radii {ra} and {rb} is the "
                "larger; pass `inner='first'` or `inner='second'`.")
    if inner_a:  # a inside b: I on the ray from b's centre through a's, at distance rb
        e = -ab / (rb - ra)
        return b.centre.moved(name, rb * e), -e
    e = ab / (ra - rb)  # b inside a: I on the ray from a's centre through b's
    return a.centre.moved(name, ra * e), e


_PAIRS = {
    (Sphere, Plane): _sphere_plane,
    (Cylinder, Plane): _cylinder_plane,
    (Circle, Line): _circle_line,
    (Circle, Plane): _circle_plane,
    (Circle, Circle): _round_round,
    (Sphere, Sphere): _round_round,
}
