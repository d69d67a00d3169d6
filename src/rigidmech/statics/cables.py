"""Statics of wires and flexible cables (book, ch. 14.3).

A flexible cable transmits only a tension along its tangent (ch. 14.3.1). Its equilibrium under
a load per unit length (ch. 14.3.2) gives, in a vertical plane with x horizontal and y upward:

* under its own weight w per unit length (ch. 14.3.3), the **catenary**
  :math:`y = a\\cosh((x - x_0)/a) + c` with :math:`a = H/w`, H the horizontal component of the
  tension (the same all along the cable), and the tension :math:`T(x) = H\\cosh((x - x_0)/a)`;
* under a load q per unit of *horizontal* length (a suspension bridge deck), a **parabola**
  :math:`y'' = q/H`;
* on a rough cylinder (ch. 14.3.4), the tension varies along the arc of contact by the
  Euler-Eytelwein (capstan) law :math:`T_1 \\le T_2\\,e^{f\\alpha}`: see :func:`capstan_ratio`,
  :func:`holding_force`, :func:`belt_slip_torque`.

Conventions: support A is at the origin of the plane, support B at (``span``, ``height``);
``height`` may be negative. Every length, load and tension is a float (the catenary's equation
is transcendental); :meth:`Catenary.shape` gives the cable as a :class:`~rigidmech.vectors.Curve`
in a frame whose ``i`` is horizontal and ``j`` points up.
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.lazy import lazy_functions
from ..vectors import Curve, Frame

# lazy: import cost (scipy.optimize takes ~0.3 s; see docs/performance)
brentq, = lazy_functions(globals(), "scipy.optimize", "brentq")

__all__ = ["Catenary", "ParabolicCable", "capstan_ratio", "holding_force", "hoisting_force",
           "belt_slip_torque"]


def _positive(value, argument):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`{argument}` must be a real number; got {value!r}.") from None
    if not (math.isfinite(v) and v > 0):
        raise ArgumentError(f"`{argument}` must be a finite number > 0; got {value!r}.")
    return v


def _finite(value, argument):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`{argument}` must be a real number; got {value!r}.") from None
    if not math.isfinite(v):
        raise ArgumentError(f"`{argument}` must be finite; got {value!r}.")
    return v


def _log_sinhc(u):
    """log(sinh(u) / u) for u >= 0, without overflow for large u nor cancellation near 0."""
    if u < 1e-3:
        u2 = u * u
        return u2 / 6 - u2 * u2 / 180 + u2**3 / 2835
    return u + math.log1p(-math.exp(-2 * u)) - math.log(2 * u)


def _solve_sinhc(ratio):
    """The u > 0 with sinh(u)/u = ratio > 1, by bracketing and Brent's method."""
    target = math.log(ratio)
    hi = 1.0
    while _log_sinhc(hi) < target:
        hi *= 2.0
    return brentq(lambda u: _log_sinhc(u) - target, 0.0, hi, xtol=1e-300,
                  rtol=4 * np.finfo(float).eps, maxiter=500)


class Catenary:
    """A heavy cable hanging between two supports: the catenary (ch. 14.3.3).

    Give the ``span`` L, the ``weight_per_length`` w, the ``height`` h of support B above A
    (default 0), and exactly one of ``horizontal_tension`` H or ``length`` S.

    Parameters
    ----------
    span : float
        Horizontal distance L > 0 between the supports.
    weight_per_length : float
        Weight w > 0 per unit length of cable.
    horizontal_tension : float, optional
        Horizontal component H > 0 of the tension.
    length : float, optional
        Length S of the cable; must exceed the distance sqrt(L^2 + h^2) between the supports.
    height : float
        Height of B above A (negative if B is lower).

    Raises
    ------
    ArgumentError
        Both or neither of ``horizontal_tension`` and ``length`` given; a cable not longer
        than the distance between its supports; a non-positive span, weight or tension.

    Notes
    -----
    With :math:`a = H/w`, the cable through A(0, 0) and B(L, h) is
    :math:`y = a(\\cosh((x-x_0)/a) - \\cosh(x_0/a))`, where
    :math:`x_0 = L/2 - a\\,\\mathrm{asinh}\\big(h / (2a\\sinh(L/2a))\\big)` is the abscissa of the
    lowest point of the (extended) curve; its length is
    :math:`S = \\sqrt{h^2 + (2a\\sinh(L/2a))^2}`. From S, the parameter a follows from
    :math:`\\sinh(u)/u = \\sqrt{S^2 - h^2}/L`, :math:`u = L/2a`, solved by bracketing and
    Brent's method (:func:`scipy.optimize.brentq`) on the logarithm of both sides, which is
    monotonic in u. The tension is :math:`T(x) = H\\cosh((x-x_0)/a) = H + w\\,(y - y_0)`.

    Examples
    --------
    >>> c = Catenary(span=100.0, weight_per_length=10.0, horizontal_tension=5000.0)
    >>> round(c.sag, 6), round(c.length, 6)         # a = 500: sag = a (cosh(L/2a) - 1)
    (2.502084, 100.16675)
    >>> d = Catenary(span=100.0, weight_per_length=10.0, length=c.length)
    >>> round(d.horizontal_tension, 6)
    5000.0
    """

    __slots__ = ("_span", "_w", "_h", "_H", "_a", "_x0", "_length")

    def __init__(self, *, span, weight_per_length, horizontal_tension=None, length=None,
                 height=0.0):
        self._span = _positive(span, "span")
        self._w = _positive(weight_per_length, "weight_per_length")
        self._h = _finite(height, "height")
        if (horizontal_tension is None) == (length is None):
            raise ArgumentError(
                "give exactly one of `horizontal_tension` and `length`; got "
                f"horizontal_tension={horizontal_tension!r}, length={length!r}.")
        L, h = self._span, self._h
        if horizontal_tension is not None:
            self._H = _positive(horizontal_tension, "horizontal_tension")
            a = self._H / self._w
        else:
            S = _positive(length, "length")
            chord = math.hypot(L, h)
            if not S > chord:
                raise ArgumentError(
                    f"`length` must exceed the distance between the supports, "
                    f"sqrt(span^2 + height^2) = {chord!r}; got {S!r}: a cable shorter than "
                    "its span cannot hang between the supports.")
            u = _solve_sinhc(math.sqrt((S - h) * (S + h)) / L)
            a = L / (2 * u)
            self._H = a * self._w
        if L / (2 * a) > 700:
            raise ArgumentError(
                f"`horizontal_tension` must exceed w L / 1400 = {self._w * L / 1400!r} (beyond "
                f"that the catenary's length overflows a float); got {self._H!r}.")
        self._a = a
        chord_term = 2 * a * math.sinh(L / (2 * a))
        self._x0 = L / 2 - a * math.asinh(h / chord_term)
        self._length = math.hypot(h, chord_term)

    # -- data -----------------------------------------------------------------------------
    span = property(lambda self: self._span, doc="Horizontal distance L between supports.")
    height = property(lambda self: self._h, doc="Height h of support B above support A.")
    weight_per_length = property(lambda self: self._w, doc="Weight w per unit length.")
    horizontal_tension = property(lambda self: self._H,
                                  doc="Horizontal component H of the tension.")
    parameter = property(lambda self: self._a, doc="Parameter a = H / w of the catenary.")
    length = property(lambda self: self._length, doc="Length S of the cable.")

    @property
    def lowest_point(self):
        """(x, y) of the lowest point of the cable (a support if the vertex lies outside).

        Examples
        --------
        >>> Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=1.0).lowest_point
        (1.0, -0.5430806348152437)
        """
        x = min(max(self._x0, 0.0), self._span)
        return x, float(self.y(x))

    @property
    def sag(self) -> float:
        """Largest vertical distance between the chord AB and the cable.

        Examples
        --------
        >>> round(Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=1.0).sag, 12)
        0.543080634815
        """
        x = self._x0 + self._a * math.asinh(self._h / self._span)
        return float(self._h * x / self._span - self.y(x))

    # -- fields ---------------------------------------------------------------------------
    def y(self, x):
        """Height of the cable above A at abscissa ``x`` (float or array).

        Examples
        --------
        >>> c = Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=1.0, height=0.5)
        >>> float(c.y(0.0)), round(float(c.y(2.0)), 12)
        (0.0, 0.5)
        """
        x = np.asarray(x, dtype=float)
        a, x0 = self._a, self._x0
        return a * (np.cosh((x - x0) / a) - math.cosh(x0 / a))

    def slope(self, x):
        """dy/dx = sinh((x - x0)/a) at ``x``.

        Examples
        --------
        >>> float(Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=1.0).slope(1.0))
        0.0
        """
        return np.sinh((np.asarray(x, dtype=float) - self._x0) / self._a)

    def tension(self, x):
        """Magnitude of the tension T(x) = H cosh((x - x0)/a).

        Examples
        --------
        >>> float(Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=3.0).tension(1.0))
        3.0
        """
        return self._H * np.cosh((np.asarray(x, dtype=float) - self._x0) / self._a)

    def arc_length(self, x):
        """Length of cable from A to abscissa ``x``.

        Examples
        --------
        >>> c = Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=1.0)
        >>> bool(abs(c.arc_length(2.0) - c.length) < 1e-14)
        True
        """
        a, x0 = self._a, self._x0
        return a * (np.sinh((np.asarray(x, dtype=float) - x0) / a) + math.sinh(x0 / a))

    @property
    def support_tensions(self):
        """Tensions (T_A, T_B) at the supports.

        Examples
        --------
        >>> c = Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=1.0)
        >>> [round(float(t), 12) for t in c.support_tensions]
        [1.543080634815, 1.543080634815]
        """
        return float(self.tension(0.0)), float(self.tension(self._span))

    @property
    def support_vertical_forces(self):
        """Upward forces (V_A, V_B) the supports exert on the cable; V_A + V_B = w S.

        Examples
        --------
        >>> c = Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=1.0)
        >>> [round(v, 12) for v in c.support_vertical_forces]
        [1.175201193644, 1.175201193644]
        """
        return (-self._H * float(self.slope(0.0)), self._H * float(self.slope(self._span)))

    def shape(self, frame: Frame | None = None) -> Curve:
        """The cable as a :class:`~rigidmech.vectors.Curve` x i + y(x) j in ``frame``
        (default a new frame ``R0``), parameter x from 0 to ``span``.

        Examples
        --------
        >>> c = Catenary(span=2.0, weight_per_length=1.0, horizontal_tension=1.0)
        >>> C = c.shape()
        >>> float(C.curvature(at=1.0))                  # 1/a at the vertex
        1.0
        """
        frame = Frame("R0") if frame is None else frame
        x = sp.Symbol("x", real=True)
        a, x0 = sp.Float(self._a), sp.Float(self._x0)
        y = a * (sp.cosh((x - x0) / a) - sp.cosh(x0 / a))
        return Curve(frame.vector(x, y, 0), x, frame)

    def __repr__(self):
        return (f"Catenary(span={self._span!r}, weight_per_length={self._w!r}, "
                f"horizontal_tension={self._H!r}, height={self._h!r})")


class ParabolicCable:
    """A cable carrying a load q uniformly distributed along the horizontal: a parabola
    (ch. 14.3.2), as for the main cable of a suspension bridge (its own weight neglected).

    Give the ``span`` L, ``load_per_horizontal_length`` q, ``height`` h of B above A, and
    exactly one of ``horizontal_tension`` H or ``sag`` f (below the chord at mid-span).

    Notes
    -----
    The equilibrium of the cable gives :math:`H\\,y'' = q`, hence through A(0, 0) and B(L, h)
    :math:`y = \\frac{q}{2H}x(x - L) + \\frac{h}{L}x`, a sag :math:`f = qL^2/8H` at mid-span
    below the chord, a tension :math:`T = H\\sqrt{1 + y'^2}` and a length
    :math:`\\int_0^L\\sqrt{1+y'^2}\\,dx` in closed form.

    Examples
    --------
    >>> p = ParabolicCable(span=100.0, load_per_horizontal_length=2.0, sag=10.0)
    >>> p.horizontal_tension                   # q L^2 / (8 f)
    250.0
    >>> [round(t, 6) for t in p.support_tensions]
    [269.258240, 269.258240]
    """

    __slots__ = ("_span", "_q", "_h", "_H")

    def __init__(self, *, span, load_per_horizontal_length, horizontal_tension=None, sag=None,
                 height=0.0):
        self._span = _positive(span, "span")
        self._q = _positive(load_per_horizontal_length, "load_per_horizontal_length")
        self._h = _finite(height, "height")
        if (horizontal_tension is None) == (sag is None):
            raise ArgumentError(
                "give exactly one of `horizontal_tension` and `sag`; got "
                f"horizontal_tension={horizontal_tension!r}, sag={sag!r}.")
        if horizontal_tension is not None:
            self._H = _positive(horizontal_tension, "horizontal_tension")
        else:
            self._H = self._q * self._span**2 / (8 * _positive(sag, "sag"))

    span = property(lambda self: self._span, doc="Horizontal distance L between supports.")
    height = property(lambda self: self._h, doc="Height h of B above A.")
    horizontal_tension = property(lambda self: self._H, doc="Horizontal tension H.")

    @property
    def sag(self) -> float:
        """Sag q L^2 / (8 H) below the chord at mid-span.

        Examples
        --------
        >>> ParabolicCable(span=10.0, load_per_horizontal_length=8.0, horizontal_tension=100.0).sag
        1.0
        """
        return self._q * self._span**2 / (8 * self._H)

    def y(self, x):
        """Height above A at abscissa ``x``.

        Examples
        --------
        >>> c = ParabolicCable(span=10.0, load_per_horizontal_length=8.0, sag=1.0)
        >>> float(c.y(5.0))
        -1.0
        """
        x = np.asarray(x, dtype=float)
        return self._q / (2 * self._H) * x * (x - self._span) + self._h / self._span * x

    def slope(self, x):
        """dy/dx at ``x``.

        Examples
        --------
        >>> float(ParabolicCable(span=10.0, load_per_horizontal_length=8.0, sag=1.0).slope(5.0))
        0.0
        """
        x = np.asarray(x, dtype=float)
        return self._q / self._H * (x - self._span / 2) + self._h / self._span

    def tension(self, x):
        """Magnitude of the tension H sqrt(1 + y'^2).

        Examples
        --------
        >>> c = ParabolicCable(span=10.0, load_per_horizontal_length=8.0, sag=1.0)
        >>> float(c.tension(5.0))
        100.0
        """
        return self._H * np.sqrt(1 + self.slope(x) ** 2)

    @property
    def support_tensions(self):
        """Tensions (T_A, T_B) at the supports.

        Examples
        --------
        >>> c = ParabolicCable(span=10.0, load_per_horizontal_length=8.0, sag=1.0)
        >>> [round(t, 9) for t in c.support_tensions]
        [107.703296143, 107.703296143]
        """
        return float(self.tension(0.0)), float(self.tension(self._span))

    @property
    def length(self) -> float:
        """Length of the cable, in closed form.

        Examples
        --------
        >>> round(ParabolicCable(span=10.0, load_per_horizontal_length=8.0, sag=1.0).length, 9)
        10.260606304
        """
        p = self._q / self._H

        def primitive(s):
            return (s * math.sqrt(1 + s * s) + math.asinh(s)) / 2

        return (primitive(float(self.slope(self._span))) - primitive(float(self.slope(0.0)))) / p

    def shape(self, frame: Frame | None = None) -> Curve:
        """The cable as a :class:`~rigidmech.vectors.Curve` in ``frame`` (i horizontal, j up).

        Examples
        --------
        >>> c = ParabolicCable(span=10.0, load_per_horizontal_length=8.0, sag=1.0)
        >>> float(c.shape().curvature(at=5.0))          # q / H at the vertex
        0.08
        """
        frame = Frame("R0") if frame is None else frame
        x = sp.Symbol("x", real=True)
        q, H, L, h = (sp.Float(v) for v in (self._q, self._H, self._span, self._h))
        return Curve(frame.vector(x, q / (2 * H) * x * (x - L) + h / L * x, 0), x, frame)

    def __repr__(self):
        return (f"ParabolicCable(span={self._span!r}, load_per_horizontal_length={self._q!r}, "
                f"horizontal_tension={self._H!r}, height={self._h!r})")


def _coefficient(friction):
    f = getattr(friction, "static", friction)
    try:
        f = float(f)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"`friction` must be a coefficient or a Coulomb law; got {friction!r}.") from None
    if not (math.isfinite(f) and f >= 0):
        raise ArgumentError(f"`friction` must be a finite coefficient >= 0; got {f!r}.")
    return f


def _angle(angle):
    a = _finite(angle, "angle")
    if a < 0:
        raise ArgumentError(f"`angle` (the angle of wrap, radians) must be >= 0; got {a!r}.")
    return a


def capstan_ratio(friction, angle) -> float:
    """Largest ratio T1/T2 = exp(f alpha) of the tensions at the ends of a rope wound by
    ``angle`` alpha (radians) on a rough cylinder, at the limit of sliding (ch. 14.3.4,
    Euler-Eytelwein).

    ``friction`` is a coefficient or a :class:`~rigidmech.actions.contact_laws.Coulomb` law
    (its static coefficient is used).

    Examples
    --------
    >>> import math
    >>> round(capstan_ratio(0.3, 3 * 2 * math.pi), 3)       # three turns
    285.678
    """
    return math.exp(_coefficient(friction) * _angle(angle))


def holding_force(load, friction, angle) -> float:
    """Smallest force that holds ``load`` at the other end of a rope wound by ``angle`` on a
    rough post: load * exp(-f alpha) (ch. 14.3.4).

    Examples
    --------
    >>> round(holding_force(1000.0, 0.3, 2 * 3.141592653589793), 6)
    151.835802
    """
    return _positive(load, "load") / capstan_ratio(friction, angle)


def hoisting_force(load, friction, angle) -> float:
    """Force needed to start raising ``load`` with a rope wound by ``angle`` on a rough fixed
    cylinder: load * exp(f alpha) (ch. 14.3.4).

    Examples
    --------
    >>> round(hoisting_force(100.0, 0.25, 3.141592653589793), 6)
    219.328005
    """
    return _positive(load, "load") * capstan_ratio(friction, angle)


def belt_slip_torque(radius, friction, angle, *, slack_tension=None, pretension=None) -> float:
    """Largest torque a belt transmits to a pulley of ``radius`` before slipping (ch. 10.2.4,
    14.3.4).

    At the limit the tight and slack tensions satisfy T1 = T2 exp(f alpha); the torque is
    (T1 - T2) r. Give either the ``slack_tension`` T2, or the ``pretension`` T0 of a belt
    mounted with T1 + T2 = 2 T0, for which C = 2 T0 r (e^{f alpha} - 1)/(e^{f alpha} + 1).

    Examples
    --------
    >>> import math
    >>> round(belt_slip_torque(0.1, 0.3, math.pi, slack_tension=100.0), 9)
    15.663323952
    >>> round(belt_slip_torque(0.1, 0.3, math.pi, pretension=100.0), 9)
    8.783995554
    """
    r = _positive(radius, "radius")
    e = capstan_ratio(friction, angle)
    if (slack_tension is None) == (pretension is None):
        raise ArgumentError(
            "give exactly one of `slack_tension` and `pretension`; got "
            f"slack_tension={slack_tension!r}, pretension={pretension!r}.")
    if slack_tension is not None:
        return _positive(slack_tension, "slack_tension") * (e - 1) * r
    return 2 * _positive(pretension, "pretension") * r * (e - 1) / (e + 1)
