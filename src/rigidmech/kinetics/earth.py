"""The Earth as a reference: a frame turning with the Earth at a latitude, apparent gravity,
deviation of the plumb line (book, ch. 12.2.1, 19).

The geocentric frame R0 = (C; i0, j0, k0), k0 along the polar axis, is taken as Galilean; the
Earth turns relative to it at the rate Omega = 7.292115e-5 rad/s (one sidereal day) about k0.
At the latitude lambda and on the surface (radius R), the local frame
R = (O; e, n, u) has e towards the east, n towards the north and u upwards (along CO).
A point at rest in R undergoes the entrainment acceleration
a_e = Omega ^ (Omega ^ CO), of magnitude Omega^2 R cos(lambda), directed towards the
polar axis. The apparent gravity is the attraction corrected by the inertial force of
entrainment (ch. 12.2.1, 19):

.. math::
    \\mathbf{g}_a = \\mathbf{g}_0 - \\mathbf{a}_e
    = -g_0\\,\\mathbf{u} + \\Omega^2R\\cos\\lambda\\,(\\cos\\lambda\\,\\mathbf{u}
      - \\sin\\lambda\\,\\mathbf{n}),

    g_a = \\sqrt{(g_0 - \\Omega^2R\\cos^2\\lambda)^2 + (\\Omega^2R\\sin\\lambda\\cos\\lambda)^2},
    \\qquad
    \\tan\\alpha = \\frac{\\Omega^2R\\sin\\lambda\\cos\\lambda}{g_0 - \\Omega^2R\\cos^2\\lambda},

alpha being the angle between the plumb line and the direction of the centre (ch. 12.2.1, 19).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..kinematics import acceleration_composition
from ..vectors import Frame, Vector, t

__all__ = ["EARTH_ROTATION_RATE", "EARTH_RADIUS", "EarthReference", "earth_reference"]

EARTH_ROTATION_RATE = 7.292115e-5
"""The Earth's rotation rate relative to the stars, rad/s (IERS)."""

EARTH_RADIUS = 6.371e6
"""The Earth's mean radius, m."""


def _scalar(x, argument):
    try:
        value = sp.sympify(x)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got {type(x).__name__}."
        ) from exc
    if not isinstance(value, sp.Expr):
        raise ArgumentTypeError(f"`{argument}` must be a number or a sympy expression; got "
                                f"{x!r}.")
    return value


class EarthReference:
    """A reference turning with the Earth, at a latitude on its surface (ch. 12.2.1, 19).

    Build with :func:`earth_reference`. Attributes: ``geocentric`` (R0, taken as Galilean),
    ``earth`` (the frame turning with the Earth, origin at the centre C), ``frame`` (the local
    frame (O; east, north, up) at the surface), ``latitude``, ``radius``, ``rate`` and
    ``rotation`` (the vector Omega k0).

    Examples
    --------
    >>> import sympy as sp
    >>> lam, W = sp.symbols("lambda Omega", positive=True)
    >>> E = earth_reference(latitude=lam, rate=W)
    >>> E.rotation.components(E.frame).T
    Matrix([[0, Omega*cos(lambda), Omega*sin(lambda)]])
    """

    __slots__ = ("_geocentric", "_earth", "_frame", "_latitude", "_radius", "_rate")

    def __init__(self, geocentric, earth, frame, latitude, radius, rate):
        self._geocentric, self._earth, self._frame = geocentric, earth, frame
        self._latitude, self._radius, self._rate = latitude, radius, rate

    geocentric = property(lambda self: self._geocentric,
                          doc="The geocentric frame R0, taken as Galilean.")
    earth = property(lambda self: self._earth,
                     doc="The frame turning with the Earth (origin at the centre).")
    frame = property(lambda self: self._frame,
                     doc="The local frame (O; east, north, up) at the latitude.")
    latitude = property(lambda self: self._latitude, doc="The latitude lambda (rad).")
    radius = property(lambda self: self._radius, doc="The Earth's radius R.")
    rate = property(lambda self: self._rate, doc="The rotation rate Omega (rad/s).")

    @property
    def rotation(self) -> Vector:
        """omega(Earth/R0) = Omega k0."""
        return self._earth.rotation_vector(self._geocentric)

    @property
    def east(self) -> Vector:
        """The unit vector towards the east."""
        return self._frame.i

    @property
    def north(self) -> Vector:
        """The unit vector towards the north."""
        return self._frame.j

    @property
    def up(self) -> Vector:
        """The unit vector along the radius CO, upwards."""
        return self._frame.k

    def entrainment_acceleration(self) -> Vector:
        """a_e = Omega ^ (Omega ^ CO) of the point O at rest on the surface (ch. 17.1.3).

        Examples
        --------
        >>> import sympy as sp
        >>> lam, W, R = sp.symbols("lambda Omega R", positive=True)
        >>> E = earth_reference(latitude=lam, rate=W, radius=R)
        >>> sp.simplify(E.entrainment_acceleration().components(E.frame).T)
        Matrix([[0, Omega**2*R*sin(2*lambda)/2, -Omega**2*R*cos(lambda)**2]])
        """
        O = self._frame.origin
        return acceleration_composition(O, relative_to=self._frame,
                                        absolute=self._geocentric).entrainment

    def apparent_gravity(self, g0) -> Vector:
        """g_a = -g0 u - a_e: the attraction g0 towards the centre with the inertial force of
        entrainment per unit mass (ch. 12.2.1, 19).

        Examples
        --------
        >>> import sympy as sp
        >>> g0, W, R = sp.symbols("g0 Omega R", positive=True)
        >>> E = earth_reference(latitude=0, rate=W, radius=R)
        >>> E.apparent_gravity(g0).components(E.frame).T
        Matrix([[0, 0, Omega**2*R - g0]])
        """
        g0 = _scalar(g0, "g0")
        return (-g0 * self.up - self.entrainment_acceleration()).express(self._frame)

    def plumb_line_deviation(self, g0) -> sp.Expr:
        """The angle alpha between the plumb line (along g_a) and the direction of the
        centre: tan(alpha) = Omega^2 R sin(lambda) cos(lambda) / (g0 - Omega^2 R cos^2(lambda))
        (ch. 12.2.1, 19).

        Examples
        --------
        >>> E = earth_reference(latitude=0.7853981633974483)
        >>> round(float(E.plumb_line_deviation(9.82)) * 180 / 3.141592653589793, 3)
        0.099
        """
        ga = self.apparent_gravity(g0).components(self._frame)
        return sp.atan2(-ga[1], -ga[2])

    def __repr__(self):
        return (f"EarthReference(latitude={self._latitude}, radius={self._radius}, "
                f"rate={self._rate})")


def earth_reference(*, latitude, radius=EARTH_RADIUS, rate=EARTH_ROTATION_RATE,
                    geocentric: Frame | None = None, name: str = "R_earth") -> EarthReference:
    """The reference turning with the Earth at ``latitude`` (ch. 12.2.1, 19).

    Parameters
    ----------
    latitude : number or sympy expression
        lambda in radians, in [-pi/2, pi/2] (positive in the northern hemisphere).
    radius : number or sympy expression, optional
        The Earth's radius (default :data:`EARTH_RADIUS`, m).
    rate : number or sympy expression, optional
        The rotation rate Omega (default :data:`EARTH_ROTATION_RATE`, rad/s).
    geocentric : Frame, optional
        The Galilean geocentric frame R0 (k0 along the polar axis); a new root frame
        ``"R0"`` by default.
    name : str, optional
        Name of the local frame; the Earth frame is ``name + "_T"``.

    Raises
    ------
    ArgumentError
        A numeric latitude outside [-pi/2, pi/2].

    Examples
    --------
    >>> E = earth_reference(latitude=0.8)
    >>> E.frame.name, E.earth.name, float(E.rate)
    ('R_earth', 'R_earth_T', 7.292115e-05)
    """
    lam = _scalar(latitude, "latitude")
    if lam.is_number:
        if not lam.is_real or not (-sp.pi / 2 <= lam <= sp.pi / 2):
            raise ArgumentError(
                f"`latitude` must be in radians within [-pi/2, pi/2]; got {latitude} "
                "(convert degrees with math.radians).")
    R = _scalar(radius, "radius")
    W = _scalar(rate, "rate")
    if (R.is_number and not R > 0) or R.is_nonpositive:
        raise ArgumentError(f"`radius` must be > 0; got {radius}.")
    if geocentric is None:
        geocentric = Frame("R0")
    elif not isinstance(geocentric, Frame):
        raise ArgumentTypeError(
            f"`geocentric` must be a Frame; got {type(geocentric).__name__}.")
    earth = geocentric.rotated(name + "_T", about=geocentric.k, angle=W * t)
    # (south, east, up) at the surface, then a quarter turn about up: (east, north, up)
    seu = earth.rotated(name + "_seu", about=earth.j, angle=sp.pi / 2 - lam,
                        origin=geocentric.origin.moved(
                            "O_" + name, R * (sp.cos(lam) * earth.i + sp.sin(lam) * earth.k)))
    local = seu.rotated(name, about=seu.k, angle=sp.pi / 2)
    return EarthReference(geocentric, earth, local, lam, R, W)
