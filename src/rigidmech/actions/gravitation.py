"""Newton's attraction: point masses, spherical bodies, and gravity as its local
approximation (book, ch. 12).

Two point masses m1 at A and m2 at B attract each other (ch. 12.1.1):

.. math::
    \\mathbf{F}_{1\\to 2} = -\\mathcal{G}\\,\\frac{m_1 m_2}{AB^3}\\,\\mathbf{AB},\\qquad
    E_p = -\\mathcal{G}\\,\\frac{m_1 m_2}{AB}.

A homogeneous spherical body of mass M and radius R (solid or a thin shell) attracts an outer
point as if its mass were at its centre C. With r = CP (ch. 12.1.3), the field g(P) = -g(r)
CP/r and the potential V(P) (potential energy of a unit mass) are

==========================  ==========================  ==================================
body                        g(r), r < R                 V(r), r < R
==========================  ==========================  ==================================
point mass                  (no inside)                 (no inside)
homogeneous solid sphere    G M r / R^3                 -G M (3 R^2 - r^2) / (2 R^3)
spherical shell             0                           -G M / R
==========================  ==========================  ==================================

and g(r) = G M / r^2, V(r) = -G M / r outside (r >= R) for all three. Near the surface the
field is nearly uniform: gravity g = G M / R^2 (ch. 12.2.1), the :class:`~rigidmech.actions.Gravity`
of the actions module.
"""

from __future__ import annotations

import sympy as sp

from .._core.deprecation import deprecated_aliases
from .._core.errors import ArgumentError, ArgumentTypeError
from ..torsors import slider
from ..vectors import Point, Vector
from ..vectors.points import check_point
from .actions import Action, Gravity, _check_solid

__all__ = ["GRAVITATIONAL_CONSTANT", "Attractor", "point_mass_attractor",
           "homogeneous_sphere_attractor",
           "spherical_shell_attractor", "NewtonAttraction", "SphericalBodyAttraction",
           "surface_gravity"]

GRAVITATIONAL_CONSTANT = 6.67430e-11
"""Newton's constant G in m^3 kg^-1 s^-2 (CODATA 2018)."""

_KINDS = ("point mass", "homogeneous sphere", "spherical shell")


def _scalar(x, argument, *, positive=False):
    try:
        value = sp.sympify(x)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got {type(x).__name__}."
        ) from exc
    if not isinstance(value, sp.Expr):
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got {x!r}.")
    if value.is_number and not value.is_finite:
        raise ArgumentError(f"`{argument}` must be finite; got {value}.")
    if value.is_negative or (positive and value.is_zero):
        need = "> 0" if positive else ">= 0"
        raise ArgumentError(f"`{argument}` must be {need}; got {x}.")
    return value


class Attractor:
    """A spherically symmetric attracting body: a point mass, a homogeneous solid sphere or
    a thin spherical shell (ch. 12.1.3). Build with :func:`point_mass_attractor`,
    :func:`homogeneous_sphere_attractor`, :func:`spherical_shell_attractor`.

    Examples
    --------
    >>> import sympy as sp
    >>> M, R, r, G = sp.symbols("M R r G", positive=True)
    >>> earth = homogeneous_sphere_attractor(M, R, G=G)
    >>> earth.field_magnitude(R / 2), earth.potential(2 * R)
    (G*M/(2*R**2), -G*M/(2*R))
    """

    __slots__ = ("_kind", "_mass", "_radius", "_G")

    def __init__(self, kind, mass, radius=0, *, G=GRAVITATIONAL_CONSTANT):
        if kind not in _KINDS:
            raise ArgumentError(f"`kind` must be one of {_KINDS}; got {kind!r}.")
        self._kind = kind
        self._mass = _scalar(mass, "mass")
        self._radius = _scalar(radius, "radius", positive=kind != "point mass")
        self._G = _scalar(G, "G", positive=True)

    kind = property(lambda self: self._kind, doc="The kind of body.")
    mass = property(lambda self: self._mass, doc="The mass M.")
    radius = property(lambda self: self._radius, doc="The radius R (0 for a point mass).")
    G = property(lambda self: self._G, doc="The gravitational constant used.")

    @property
    def mu(self):
        """The gravitational parameter G M."""
        return self._G * self._mass

    def _outside(self, r):
        if self._kind == "point mass":
            return True
        return sp.sympify(r >= self._radius)

    def field_magnitude(self, r):
        """g(r): the magnitude of the attraction per unit mass at distance r from the
        centre, directed towards the centre (ch. 12.1.3).

        Examples
        --------
        >>> (spherical_shell_attractor(1, 2, G=1).field_magnitude(1),
        ...  point_mass_attractor(4, G=1).field_magnitude(2))
        (0, 1)
        """
        r = _scalar(r, "r")
        if r.is_zero:
            if self._kind == "point mass":
                raise ArgumentError("`r` must be > 0 for a point mass; got 0.")
            return sp.S.Zero
        outside = self.mu / r**2
        inside = (self.mu * r / self._radius**3 if self._kind == "homogeneous sphere"
                  else sp.S.Zero)
        return self._select(r, outside, inside)

    def potential(self, r):
        """V(r): the potential energy of a unit mass at distance r, zero at infinity
        (ch. 12.1.3); the field is -dV/dr along the outward radius.

        Examples
        --------
        >>> homogeneous_sphere_attractor(1, 1, G=1).potential(0)
        -3/2
        """
        r = _scalar(r, "r")
        if r.is_zero and self._kind == "point mass":
            raise ArgumentError("`r` must be > 0 for a point mass; got 0.")
        outside = -self.mu / r if not r.is_zero else sp.nan
        if self._kind == "homogeneous sphere":
            inside = -self.mu * (3 * self._radius**2 - r**2) / (2 * self._radius**3)
        else:
            inside = -self.mu / self._radius if self._radius != 0 else sp.nan
        return self._select(r, outside, inside)

    def _select(self, r, outside, inside):
        where = self._outside(r)
        if where is sp.true or where is True:
            return outside
        if where is sp.false:
            return inside
        return sp.Piecewise((outside, where), (inside, True))

    def field(self, at: Point, *, centre: Point) -> Vector:
        """The field vector g(P) = -g(r) CP / r at ``at`` of the body centred at ``centre``.

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> point_mass_attractor(8, G=1).field(R0.point("P", 2, 0, 0), centre=R0.origin)
        -2*R0.i
        """
        check_point(at, "at")
        check_point(centre, "centre")
        cp = at - centre
        r = cp.magnitude()
        return -self.field_magnitude(r) / r * cp

    def local_gravity(self, at: Point, *, centre: Point) -> Gravity:
        """The uniform field that approximates the attraction near ``at`` (ch. 12.2.1): the
        :class:`Gravity` action of field g(P).

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> point_mass_attractor(8, G=1).local_gravity(R0.point("P", 0, 0, 2), centre=R0.origin)
        Gravity(-2*R0.k)
        """
        return Gravity(self.field(at, centre=centre))

    def __repr__(self):
        radius = "" if self._kind == "point mass" else f", radius={self._radius}"
        return f"Attractor({self._kind!r}, mass={self._mass}{radius}, G={self._G})"


def point_mass_attractor(mass, *, G=GRAVITATIONAL_CONSTANT) -> Attractor:
    """A point mass (ch. 12.1.1).

    Examples
    --------
    >>> f"{float(point_mass_attractor(5.972e24).mu):.4e}"   # G M of the Earth, m^3/s^2
    '3.9859e+14'
    """
    return Attractor("point mass", mass, 0, G=G)


def homogeneous_sphere_attractor(mass, radius, *, G=GRAVITATIONAL_CONSTANT) -> Attractor:
    """A homogeneous solid sphere of mass M and radius R (ch. 12.1.3).

    Examples
    --------
    >>> homogeneous_sphere_attractor(1, 2, G=1).field_magnitude(1)
    1/8
    """
    return Attractor("homogeneous sphere", mass, radius, G=G)


def spherical_shell_attractor(mass, radius, *, G=GRAVITATIONAL_CONSTANT) -> Attractor:
    """A thin homogeneous spherical shell of mass M and radius R (ch. 12.1.3).

    Examples
    --------
    >>> spherical_shell_attractor(1, 2, G=1).potential(1)
    -1/2
    """
    return Attractor("spherical shell", mass, radius, G=G)


def surface_gravity(mass, radius, *, G=GRAVITATIONAL_CONSTANT):
    """g = G M / R^2, gravity at the surface of a spherical body (ch. 12.2.1).

    Examples
    --------
    >>> round(surface_gravity(5.972e24, 6.371e6), 3)
    9.82
    """
    return homogeneous_sphere_attractor(mass, radius, G=G).field_magnitude(radius)


def _massive(s, argument):
    _check_solid(s, argument)
    m = getattr(s, "mass", None)
    if m is None:
        raise ArgumentError(f"`{argument}` ({s.name}) must have a mass; create it as a Body "
                            "with mass=...")
    return m


class NewtonAttraction(Action):
    """Newton's mutual attraction of two bodies ``a`` and ``b`` treated as point masses (or
    spherical bodies) at their mass centres (ch. 12.1.1).

    The force on b is the slider {-G m_a m_b AB / AB^3}_B, the opposite one acts on a, and
    the potential energy is -G m_a m_b / AB.

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> x = rm.coordinates("x"); G, m1, m2 = sp.symbols("G m1 m2", positive=True)
    >>> R0 = rm.Frame("R0")
    >>> a = rm.Body("a", frame=R0, mass=m1)
    >>> b = rm.Body("b", frame=R0.translated("Rb", R0.point("B", x, 0, 0)), mass=m2)
    >>> att = NewtonAttraction(a, b, G=G)
    >>> att.potential_energy([a, b], R0)
    -G*m1*m2/Abs(x(t))
    """

    __slots__ = ("_a", "_b", "_G")

    def __init__(self, a, b, *, G=GRAVITATIONAL_CONSTANT):
        _massive(a, "a")
        _massive(b, "b")
        if a is b:
            raise ArgumentError("`a` and `b` must be two different bodies; got the same body "
                                f"{a.name} twice.")
        self._a, self._b = a, b
        self._G = _scalar(G, "G", positive=True)

    def _force_on_b(self):
        ab = self._b.centre - self._a.centre
        d = ab.magnitude()
        return -self._G * self._a.mass * self._b.mass / d**3 * ab

    def contributions(self, solids):
        f = self._force_on_b()
        return [(self._b, slider(f, self._b.centre)), (self._a, slider(-f, self._a.centre))]

    def potential_energy(self, solids, frame):
        d = (self._b.centre - self._a.centre).magnitude()
        return -self._G * self._a.mass * self._b.mass / d

    def __repr__(self):
        return f"NewtonAttraction({self._a.name}, {self._b.name}, G={self._G})"


class SphericalBodyAttraction(Action):
    """The attraction of a spherical body (an :class:`Attractor`) fixed at ``centre`` on every
    massive solid, applied at its mass centre (ch. 12.1.3).

    The force on a solid of mass m is m g(G); its potential energy m V(CG).

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> r = rm.coordinates("r"); mu, m = sp.symbols("mu m", positive=True)
    >>> R0 = rm.Frame("R0")
    >>> sat = rm.Body("sat", frame=R0.translated("R1", R0.point("S", r, 0, 0)), mass=m)
    >>> earth = SphericalBodyAttraction(point_mass_attractor(mu, G=1), centre=R0.origin)
    >>> earth.contributions([sat])[0][1].resultant
    -m*mu/(r(t)*Abs(r(t)))*R0.i
    """

    __slots__ = ("_body", "_centre")

    def __init__(self, body: Attractor, *, centre: Point):
        if not isinstance(body, Attractor):
            raise ArgumentTypeError(
                "`body` must be an Attractor (point_mass_attractor, homogeneous_sphere_attractor, "
                f"spherical_shell_attractor); got {type(body).__name__}.")
        check_point(centre, "centre")
        self._body, self._centre = body, centre

    @property
    def body(self) -> Attractor:
        """The attracting body."""
        return self._body

    @staticmethod
    def _massive(solids):
        return [s for s in solids if getattr(s, "mass", None) is not None and s.mass != 0]

    def contributions(self, solids):
        return [(s, slider(s.mass * self._body.field(s.centre, centre=self._centre), s.centre))
                for s in self._massive(solids)]

    def potential_energy(self, solids, frame):
        return sp.Add(*[s.mass * self._body.potential((s.centre - self._centre).magnitude())
                        for s in self._massive(solids)])

    def __repr__(self):
        return f"SphericalBodyAttraction({self._body!r}, centre={self._centre.name})"



# the former names, which clashed with the inertia operators rigidmech.inertia.point_mass and
# rigidmech.inertia.spherical_shell
_RENAMED = {old: (f"rigidmech.actions.{old}_attractor", globals()[f"{old}_attractor"])
            for old in ("point_mass", "homogeneous_sphere", "spherical_shell")}
__getattr__ = deprecated_aliases(__name__, _RENAMED)
