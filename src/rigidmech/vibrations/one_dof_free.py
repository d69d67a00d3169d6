"""Free vibrations of one degree of freedom (book, ch. 21.2-21.4): the natural frequency, the
damping ratio and the damping cases, the free response in closed form, dry (Coulomb) friction
up to the stop.

Part of :mod:`rigidmech.vibrations.one_dof`, which re-exports every name here and states the
conventions; closed forms on numbers (numpy arrays broadcast) or sympy expressions.
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError
from ._scalars import _as, _lib, _nonnegative, _positive

__all__ = [
    "natural_frequency", "critical_damping", "damping_ratio", "damping_coefficient",
    "damped_frequency", "logarithmic_decrement", "damping_case", "free_response",
    "coulomb_stop", "coulomb_free_response",
]


def natural_frequency(stiffness, mass):
    """Natural angular frequency :math:`\\omega_0 = \\sqrt{k/m}` (ch. 21.2.2), rad/s.

    Examples
    --------
    >>> import sympy as sp
    >>> k, m = sp.symbols("k m", positive=True)
    >>> natural_frequency(k, m)
    sqrt(k)/sqrt(m)
    >>> float(natural_frequency(400.0, 4.0))
    10.0
    >>> natural_frequency(1.0, -1.0)
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `mass` must be finite and > 0; got -1.0.
    """
    _nonnegative(stiffness, "stiffness")
    _positive(mass, "mass")
    lib = _lib(stiffness, mass)
    return lib.sqrt(_as(stiffness, lib) / _as(mass, lib))


def critical_damping(stiffness, mass):
    """Critical damping coefficient :math:`c_c = 2\\sqrt{k m}` (ch. 21.3.2), N s/m: the
    damping at which the free motion stops oscillating (:math:`\\zeta = 1`).

    Parameters
    ----------
    stiffness, mass : float, array_like or sympy expression
        k > 0 and m > 0 (a symbol known to be nonpositive is refused).

    Returns
    -------
    float, ndarray or sympy expression

    Raises
    ------
    ArgumentError
        If `stiffness` or `mass` is not positive and finite.

    Examples
    --------
    >>> import sympy as sp
    >>> k, m = sp.symbols("k m", positive=True)
    >>> critical_damping(k, m)
    2*sqrt(k)*sqrt(m)
    >>> float(critical_damping(400.0, 4.0))
    80.0
    """
    _positive(stiffness, "stiffness")
    _positive(mass, "mass")
    lib = _lib(stiffness, mass)
    return 2 * lib.sqrt(_as(stiffness, lib) * _as(mass, lib))


def damping_ratio(damping, stiffness, mass):
    """Damping ratio :math:`\\zeta = c / (2\\sqrt{k m})` (ch. 21.3.2): c over the critical
    damping :math:`c_c = 2\\sqrt{k m}` (:func:`critical_damping`).

    Examples
    --------
    >>> import sympy as sp
    >>> c, k, m = sp.symbols("c k m", positive=True)
    >>> damping_ratio(c, k, m)
    c/(2*sqrt(k)*sqrt(m))
    >>> float(damping_ratio(4.0, 400.0, 4.0))
    0.05
    """
    _nonnegative(damping, "damping")
    c_c = critical_damping(stiffness, mass)
    lib = _lib(damping, stiffness, mass)
    return _as(damping, lib) / _as(c_c, lib)


def damping_coefficient(zeta, stiffness, mass):
    """Viscous damping coefficient :math:`c = \\zeta\\, c_c = 2\\zeta\\sqrt{k m}` of a given
    damping ratio (ch. 21.3.2), the inverse of :func:`damping_ratio`.

    Parameters
    ----------
    zeta : float, array_like or sympy expression
        Damping ratio, >= 0 (0: undamped).
    stiffness, mass : float, array_like or sympy expression
        k > 0 and m > 0.

    Returns
    -------
    float, ndarray or sympy expression

    Raises
    ------
    ArgumentError
        If `zeta` is negative or not finite, or `stiffness` or `mass` not positive.

    Examples
    --------
    >>> float(damping_coefficient(0.05, 400.0, 4.0))
    4.0
    >>> import sympy as sp
    >>> z, k, m = sp.symbols("zeta k m", positive=True)
    >>> damping_coefficient(z, k, m)
    2*sqrt(k)*sqrt(m)*zeta
    """
    _nonnegative(zeta, "zeta")
    c_c = critical_damping(stiffness, mass)
    lib = _lib(zeta, stiffness, mass)
    return _as(zeta, lib) * _as(c_c, lib)


def damped_frequency(omega0, zeta):
    """Damped angular frequency :math:`\\omega_d = \\omega_0 \\sqrt{1 - \\zeta^2}` (ζ < 1,
    ch. 21.3.2).

    Examples
    --------
    >>> round(float(damped_frequency(10.0, 0.6)), 12)
    8.0
    """
    lib = _lib(omega0, zeta)
    z = _as(zeta, lib)
    if lib is np and np.any(z >= 1):
        raise ArgumentError(f"`zeta` must be < 1 for a damped oscillation; got {zeta}.")
    return _as(omega0, lib) * lib.sqrt(1 - z**2)


def logarithmic_decrement(zeta):
    """Logarithmic decrement :math:`\\delta = \\ln(x_n / x_{n+1}) = 2\\pi\\zeta/\\sqrt{1 -
    \\zeta^2}`, the log of the ratio of two maxima one damped period apart (ch. 21.3.2).

    Examples
    --------
    >>> import sympy as sp
    >>> logarithmic_decrement(sp.Rational(3, 5))
    3*pi/2
    >>> round(float(logarithmic_decrement(0.05)), 6)
    0.314553
    """
    lib = _lib(zeta)
    z = _as(zeta, lib)
    if lib is np and np.any((z < 0) | (z >= 1)):
        raise ArgumentError(f"`zeta` must be in [0, 1); got {zeta}.")
    return 2 * lib.pi * z / lib.sqrt(1 - z**2)


def damping_case(zeta) -> str:
    """'undamped', 'underdamped' (ζ < 1), 'critical' (ζ = 1) or 'overdamped' (ζ > 1),
    ch. 21.3.2.

    Examples
    --------
    >>> damping_case(0.1), damping_case(1), damping_case(2.5)
    ('underdamped', 'critical', 'overdamped')
    """
    z = sp.sympify(zeta)
    if not z.is_number:
        raise ArgumentError(
            f"`zeta` must be a number to decide the damping case; got {zeta}. Substitute "
            "values, or pass `case=` explicitly.")
    if z < 0:
        raise ArgumentError(f"`zeta` must be >= 0; got {zeta}.")
    if z == 0:
        return "undamped"
    if z < 1:
        return "underdamped"
    return "critical" if float(z) == 1.0 else "overdamped"


def free_response(t, x0, v0, omega0, zeta=0, *, case=None):
    """Free response x(t) of :math:`\\ddot x + 2\\zeta\\omega_0\\dot x + \\omega_0^2 x = 0`
    from x(0) = x0, x'(0) = v0 (ch. 21.2.2, 21.3.2), in closed form:

    - ζ < 1: :math:`e^{-\\zeta\\omega_0 t}\\,(x_0\\cos\\omega_d t + \\frac{v_0 +
      \\zeta\\omega_0 x_0}{\\omega_d}\\sin\\omega_d t)`;
    - ζ = 1: :math:`e^{-\\omega_0 t}\\,(x_0 + (v_0 + \\omega_0 x_0)\\,t)`;
    - ζ > 1: :math:`A e^{s_1 t} + B e^{s_2 t}`, :math:`s_{1,2} = -\\omega_0(\\zeta \\mp
      \\sqrt{\\zeta^2 - 1})`, A = (v0 - s2 x0)/(s1 - s2), B = (s1 x0 - v0)/(s1 - s2).

    Parameters
    ----------
    t : float, array or sympy expression
    x0, v0, omega0, zeta : numbers or sympy expressions
    case : {'underdamped', 'critical', 'overdamped'}, optional
        Needed only when ζ is symbolic (the case cannot be decided); refused when it
        contradicts a numeric ζ.

    Notes
    -----
    With numbers the three forms are evaluated as one, continuous across ζ = 1 and free of
    cancellation for ζ close to 1 and for ζ >> 1 (about 1e-13 relative where the closed
    forms lose up to 1e-5).

    Examples
    --------
    >>> import sympy as sp
    >>> t, w = sp.symbols("t omega_0", positive=True)
    >>> free_response(t, 1, 0, w, 1)
    (omega_0*t + 1)*exp(-omega_0*t)
    >>> round(float(free_response(0.3, 1.0, 0.0, 10.0, 0.0)), 12) == round(math.cos(3.0), 12)
    True
    """
    _positive(omega0, "omega0")
    if case is not None and sp.sympify(zeta).is_number:
        decided = damping_case(zeta)
        if case != decided and not (case == "underdamped" and decided == "undamped"):
            raise ArgumentError(
                f"`case` {case!r} contradicts zeta = {zeta} (a {decided} oscillator); leave "
                "`case` out when zeta is a number.")
    case = case or damping_case(zeta)
    lib = _lib(t, x0, v0, omega0, zeta)
    t, x0, v0, w, z = (_as(a, lib) for a in (t, x0, v0, omega0, zeta))
    if lib is np:
        return _free_numeric(t, x0, v0, w, float(z))
    if case in ("undamped", "underdamped"):
        wd = w * lib.sqrt(1 - z**2)
        return lib.exp(-z * w * t) * (x0 * lib.cos(wd * t) + (v0 + z * w * x0) / wd
                                      * lib.sin(wd * t))
    if case == "critical":
        return lib.exp(-w * t) * (x0 + (v0 + w * x0) * t)
    if case == "overdamped":
        root = lib.sqrt(z**2 - 1)
        s1, s2 = -w * (z - root), -w * (z + root)
        return ((v0 - s2 * x0) * lib.exp(s1 * t) + (s1 * x0 - v0) * lib.exp(s2 * t)) / (s1 - s2)
    raise ArgumentError(
        f"`case` must be 'underdamped', 'critical' or 'overdamped'; got {case!r}.")


def _sinhc(u):
    """sinh(u) / u, 1 at u = 0 (sinh is accurate to rounding near 0: no cancellation)."""
    safe = np.where(u == 0, 1.0, u)
    return np.where(u == 0, 1.0, np.sinh(safe) / safe)


def _free_numeric(t, x0, v0, w, z):
    """The free response in numbers by one formula for every zeta, continuous across
    zeta = 1: e^{-zeta w t} (x0 C + (v0 + zeta w x0) S), C = cos(w_d t) or cosh(r w t),
    S = t sinc(w_d t) or t sinhc(r w t) (r = sqrt(zeta^2 - 1)), which tends to the critical
    form as zeta -> 1; for zeta > 1 the exponents s1 = -w / (zeta + r) and
    s2 = -w (zeta + r) are written without the cancellation of -w (zeta - r), and S as
    (e^{s1 t} - e^{s2 t}) / (2 r w) only where r w t >= 1 (no cancellation there either)."""
    b = v0 + z * w * x0
    if z <= 1:
        u = w * np.sqrt((1 - z) * (1 + z)) * t
        return np.exp(-z * w * t) * (x0 * np.cos(u) + b * t * np.sinc(u / np.pi))
    r = math.sqrt((z - 1) * (z + 1))
    e1, e2 = np.exp(-w / (z + r) * t), np.exp(-w * (z + r) * t)
    u = r * w * t
    small = np.abs(u) < 1
    S = np.where(small, t * np.exp(-z * w * t) * _sinhc(np.where(small, u, 0.0)),
                 (e1 - e2) / (2 * r * w))
    return x0 * (e1 + e2) / 2 + b * S


def _coulomb_check(x0, omega0, a):
    for value, name in ((omega0, "omega0"), (a, "friction_displacement")):
        if not float(value) > 0:
            raise ArgumentError(f"`{name}` must be > 0; got {value}.")
    return float(x0), float(omega0), float(a)


def coulomb_stop(x0, omega0, friction_displacement):
    """Where and when a spring-mass with dry (Coulomb) friction, released at rest from x0,
    stops (ch. 21.4.2).

    With :math:`a = F/k` (friction force over stiffness), each half-cycle lasts
    :math:`\\pi/\\omega_0` and the turning-point amplitude drops by 2a (4a = 4F/k per cycle).
    The mass stops at the first turning point inside the band :math:`|x| \\le a`, where the
    spring cannot overcome friction (static and kinetic friction taken equal).

    Returns
    -------
    (number of half-cycles N, stop time N π/ω0, stop position)

    Examples
    --------
    >>> n, t_stop, x_stop = coulomb_stop(1.0, 2.0, 0.1)
    >>> n, round(t_stop, 12), round(x_stop, 12)
    (5, 7.853981633974, -0.0)
    """
    x0, w0, a = _coulomb_check(x0, omega0, friction_displacement)
    if abs(x0) <= a:
        return 0, 0.0, x0
    n = math.ceil((abs(x0) - a) / (2 * a) - 1e-12)
    stop = math.copysign(1.0, x0) * (-1) ** n * (abs(x0) - 2 * n * a)
    return n, n * math.pi / w0, stop


def coulomb_free_response(t, x0, omega0, friction_displacement):
    """Free motion with dry friction from rest at x0 (ch. 21.4.2), piecewise in closed form.

    During half-cycle n (:math:`n\\pi/\\omega_0 \\le t < (n+1)\\pi/\\omega_0`) the mass moves
    one way and friction, constant, shifts the centre of the oscillation to
    :math:`\\pm a`: :math:`x = s_n a + (x_n - s_n a)\\cos\\omega_0(t - n\\pi/\\omega_0)`
    with :math:`x_n` the n-th turning point and :math:`s_n = \\operatorname{sign} x_n`; after
    the stop (:func:`coulomb_stop`) x stays constant.

    Examples
    --------
    >>> import numpy as np
    >>> x = coulomb_free_response(np.array([0.0, np.pi / 2, np.pi, 100.0]), 1.0, 2.0, 0.1)
    >>> np.round(x, 12).tolist()
    [1.0, -0.8, 0.6, -0.0]
    """
    x0, w0, a = _coulomb_check(x0, omega0, friction_displacement)
    n_stop, t_stop, x_stop = coulomb_stop(x0, w0, a)
    t = np.asarray(t, dtype=float)
    n = np.clip(np.floor(t * w0 / math.pi), 0, max(n_stop - 1, 0)).astype(int)
    turning = math.copysign(1.0, x0) * (abs(x0) - 2 * n * a) * np.where(n % 2 == 0, 1.0, -1.0)
    centre = np.sign(turning) * a
    x = centre + (turning - centre) * np.cos(w0 * (t - n * math.pi / w0))
    return np.where(t >= t_stop, x_stop, x)
