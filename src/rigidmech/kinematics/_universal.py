"""Kepler's problem in universal variables (Stumpff functions): the propagation of a state
and the time from the periapsis, one formula for every conic (book, ch. 8.2; the
universal-variable form of Kepler's equation is the standard robust route near the
parabola and for nearly radial orbits, where the anomalies lose their precision).

With alpha = 1/a = 2/r0 - v0^2/mu, sigma0 = r0 . v0 / sqrt(mu) and the universal anomaly chi
(d chi/dt = sqrt(mu)/r), Kepler's equation reads

    sqrt(mu) dt = r0 chi + sigma0 chi^2 c2(z) + (1 - alpha r0) chi^3 c3(z),  z = alpha chi^2,

and the state follows from Lagrange's coefficients f, g, f', g'. Private: used by
:class:`rigidmech.kinematics.orbits.Orbit`.
"""

from __future__ import annotations

import math

import numpy as np

from .._core.errors import NumericalError
from .._core.lazy import lazy_functions

# lazy: import cost (scipy.optimize takes ~0.3 s; see docs/performance)
brentq, = lazy_functions(globals(), "scipy.optimize", "brentq")

_MAX_ITER = 200


def stumpff(z):
    """The Stumpff functions c2(z) = (1 - cos sqrt z) / z and c3(z) = (sqrt z - sin sqrt z) / z^1.5,
    continued analytically to z <= 0 (cosh, sinh).

    Hand-rolled: neither numpy nor scipy.special has them. For abs(z) < 1 the power series (no
    cancellation, 20 terms leave less than 1e-40); elsewhere the closed forms, c2 written with
    the half angle so that it does not cancel either.
    """
    if abs(z) < 1.0:
        c2 = c3 = 0.0
        t2, t3 = 0.5, 1.0 / 6.0            # (-z)^k / (2k+2)!, (-z)^k / (2k+3)!
        for k in range(20):
            c2 += t2
            c3 += t3
            t2 *= -z / ((2 * k + 3) * (2 * k + 4))
            t3 *= -z / ((2 * k + 4) * (2 * k + 5))
        return c2, c3
    try:
        if z > 0:
            y = math.sqrt(z)
            return 2 * math.sin(y / 2) ** 2 / z, (y - math.sin(y)) / (z * y)
        y = math.sqrt(-z)
        return 2 * math.sinh(y / 2) ** 2 / -z, (math.sinh(y) - y) / (-z * y)
    except OverflowError as exc:
        raise NumericalError(
            f"the universal anomaly overflows (z = {z:.6g}): the time is too far from the "
            "epoch on this hyperbola for double precision.") from exc


def ratio_atan(u, hyperbolic):
    """atan(u) / u (atanh(u) / u if ``hyperbolic``), without 0/0 for small u."""
    if abs(u) < 1e-4:
        return 1.0 + u * u / 3 if hyperbolic else 1.0 - u * u / 3
    return (math.atanh(u) if hyperbolic else math.atan(u)) / u


def universal_anomaly(dt, r, sigma, alpha, mu, time):
    """The universal anomaly chi at dt after the epoch: root of the increasing function
    F(chi) = r chi + sigma chi^2 c2 + (1 - alpha r) chi^3 c3 - sqrt(mu) dt (F' = r(chi) >= 0),
    bracketed by doubling and found by Brent's method (scipy). ``time`` is only for the
    message.

    Examples
    --------
    >>> chi = universal_anomaly(math.pi / 2, 1.0, 0.0, 1.0, 1.0, 0.0)  # circle r = 1
    >>> round(chi, 12) == round(math.pi / 2, 12)
    True
    """
    target = math.sqrt(mu) * dt

    def F(chi):
        c2, c3 = stumpff(alpha * chi * chi)
        return r * chi + sigma * chi * chi * c2 + (1 - alpha * r) * chi**3 * c3 - target

    if target == 0:
        return 0.0
    sign = 1.0 if target > 0 else -1.0
    # on a hyperbola sinh(sqrt(-alpha) chi) overflows beyond sqrt(-alpha) chi = 700
    cap = 700 / math.sqrt(-alpha) if alpha < 0 else math.inf
    lo, hi = 0.0, min(abs(target) / r, cap)
    for _ in range(2100):
        if sign * F(sign * hi) >= 0:
            break
        if hi == cap:
            raise NumericalError(
                f"Orbit.state_at: `time` {time!r} is too far from the epoch on this "
                "hyperbola: the universal anomaly overflows in double precision.")
        lo, hi = hi, min(2 * hi, cap)
    else:   # pragma: no cover - F grows at least like chi^3 / 6 when alpha <= 0
        raise NumericalError("Orbit.state_at: no bracket for the universal anomaly.")
    a, b = (sign * lo, sign * hi) if sign > 0 else (sign * hi, sign * lo)
    return brentq(F, a, b, xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=_MAX_ITER)


def propagate(r0, v0, alpha, mu, dt, time):
    """(r, v) at dt after the state (r0, v0), by Lagrange's f and g in universal variables.

    Examples
    --------
    >>> r, v = propagate(np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), 1.0, 1.0, math.pi, 0)
    >>> np.round(r, 12).tolist(), np.round(v, 12).tolist()
    ([-1.0, 0.0, 0.0], [-0.0, -1.0, 0.0])
    """
    sq = math.sqrt(mu)
    rn = float(np.linalg.norm(r0))
    sigma = float(r0 @ v0) / sq
    chi = universal_anomaly(dt, rn, sigma, alpha, mu, time)
    z = alpha * chi * chi
    c2, c3 = stumpff(z)
    r = chi * chi * c2 + sigma * chi * (1 - z * c3) + rn * (1 - z * c2)
    f = 1 - chi * chi * c2 / rn
    g = (rn * chi * (1 - z * c3) + sigma * chi * chi * c2) / sq
    fdot = -sq * chi * (1 - z * c3) / (r * rn)
    gdot = 1 - chi * chi * c2 / r
    return f * r0 + g * v0, fdot * r0 + gdot * v0


def time_from_periapsis(r0, v0, alpha, mu, r_p):
    """Time from the periapsis (distance r_p) to the state (r0, v0), by the universal Kepler
    equation from the periapsis sqrt(mu) t = r_p chi + e chi^3 c3(alpha chi^2), e = 1 - alpha
    r_p (positive terms, no cancellation near the parabola); chi from the state in closed
    form (E or H from e sin E = sigma sqrt(alpha), e cos E = 1 - alpha r). Negative before
    the periapsis.

    Examples
    --------
    The apoapsis of the ellipse r_p = 1, v_p = 1.2 (mu = 1, a = 1/0.56, e = 0.44) is half a
    period after the periapsis:

    >>> a = 1 / 0.56
    >>> r0, v0 = np.array([-a * 1.44, 0, 0]), np.array([0, -1.2 / (a * 1.44), 0])
    >>> t = time_from_periapsis(r0, v0, 0.56, 1.0, 1.0)
    >>> bool(np.isclose(t, math.pi * a**1.5, rtol=1e-13))
    True
    """
    r = float(np.linalg.norm(r0))
    sigma = float(r0 @ v0) / math.sqrt(mu)
    x = 1 - alpha * r                            # e cos E (e cosh H on a hyperbola)
    if alpha > 0 and x <= 0:
        chi = math.atan2(sigma * math.sqrt(alpha), x) / math.sqrt(alpha)
    else:
        u = sigma * math.sqrt(abs(alpha)) / x    # tan E or tanh H
        chi = sigma / x * ratio_atan(u, alpha < 0)
    c3 = stumpff(alpha * chi * chi)[1]
    return (r_p * chi + (1 - alpha * r_p) * chi**3 * c3) / math.sqrt(mu)
