"""Reference problems of orbits (book, ch. 27.3): Kepler orbits, exact through Kepler's
equation (27.3.1 planet about the Sun, 27.3.2 satellite about the Earth), and the periodic
Arenstorf orbit of the restricted three-body problem (the moon probe of 27.3.3).

Part of :mod:`rigidmech.testing.problems`, which re-exports every name here and states the
conventions (vectorised right-hand sides, ``exact`` at one time or an array of times).
"""

from __future__ import annotations

import math

import numpy as np

from rigidmech._core.errors import ArgumentError

from .reference_problem import ReferenceProblem, _check_positive

__all__ = ["kepler", "arenstorf", "solve_kepler_equation", "ARENSTORF_MU", "ARENSTORF_Y0",
           "ARENSTORF_PERIOD"]


# ---------------------------------------------------------------------------------------------
# Kepler orbits (27.3.1 planet about the Sun, 27.3.2 satellite about the Earth)
# ---------------------------------------------------------------------------------------------


def solve_kepler_equation(mean_anomaly, e: float):
    r"""Eccentric anomaly :math:`E` with :math:`E - e\sin E = M`, by Newton to machine precision.

    Parameters
    ----------
    mean_anomaly : float or ndarray
        Mean anomaly :math:`M` (radians, any range).
    e : float
        Eccentricity, ``0 <= e < 1``.

    Returns
    -------
    ndarray
        :math:`E`, same shape as `mean_anomaly`.

    Examples
    --------
    >>> E = solve_kepler_equation(1.0, 0.9)
    >>> float(abs(E - 0.9 * np.sin(E) - 1.0)) < 1e-15
    True
    """
    M = np.asarray(mean_anomaly, dtype=float)
    turns = np.round(M / (2.0 * np.pi))
    Mr = M - 2.0 * np.pi * turns  # in [-pi, pi]
    # Danby's starter E0 = M + 0.85 e sign(sin M) converges for every e < 1.
    E = Mr + 0.85 * e * np.sign(np.sin(Mr))
    for _ in range(60):
        f = E - e * np.sin(E) - Mr
        dE = f / (1.0 - e * np.cos(E))
        E = E - dE
        if np.all(np.abs(dE) <= 4e-16 * (1.0 + np.abs(E))):
            break
    # one more Newton step once converged: the last correction is below rounding
    E = E - (E - e * np.sin(E) - Mr) / (1.0 - e * np.cos(E))
    return E + 2.0 * np.pi * turns


def kepler(e: float, *, orbits: float = 10.0, mu: float = 1.0, a: float = 1.0):
    r"""Two-body (Kepler) orbit of eccentricity `e`, started at the pericentre (book, 27.3.1-2).

    .. math::

        \ddot{\mathbf r} = -\mu\,\frac{\mathbf r}{r^3}, \qquad
        \mathbf r(0) = (a(1-e), 0), \quad
        \dot{\mathbf r}(0) = \Big(0, \sqrt{\tfrac{\mu}{a}\tfrac{1+e}{1-e}}\Big).

    Parameters
    ----------
    e : float
        Eccentricity, ``0 <= e < 1`` (0.6 and 0.9 are the benchmark cases).
    orbits : float
        Length of ``t_span`` in periods :math:`T = 2\pi\sqrt{a^3/\mu}`.
    mu : float
        Gravitational parameter :math:`\mu = G M` of the central body (1 in reduced units; the
        Sun's 1.327e20 m^3/s^2 for a planet, 27.3.1, the Earth's 3.986e14 m^3/s^2 for a
        satellite, 27.3.2).
    a : float
        Semi-major axis.

    Returns
    -------
    ReferenceProblem
        State ``y = [x, y, vx, vy]``; ``energy`` is the specific orbital energy
        :math:`\tfrac12 v^2 - \mu/r = -\mu/(2a)`.

    Raises
    ------
    ArgumentError
        If `e` is not in [0, 1) or `orbits`, `mu`, `a` are not positive.

    Notes
    -----
    The exact position follows from the eccentric anomaly :math:`E`, root of Kepler's equation
    :math:`E - e\sin E = n t` with :math:`n = \sqrt{\mu/a^3}` (book, 8.2.4), solved by Newton's
    method to machine precision (:func:`solve_kepler_equation`):

    .. math::

        x = a(\cos E - e), \quad y = a\sqrt{1-e^2}\,\sin E, \quad
        \dot x = -\frac{n a \sin E}{1 - e\cos E}, \quad
        \dot y = \frac{n a \sqrt{1-e^2}\cos E}{1 - e\cos E}.

    Examples
    --------
    >>> p = kepler(0.6)
    >>> p.exact(p.period).round(12).tolist()   # back at the pericentre
    [0.4, 0.0, 0.0, 2.0]
    >>> float(p.energy(p.y0))
    -0.5
    """
    e = float(e)
    if not 0.0 <= e < 1.0:
        raise ArgumentError(f"`e` must be in [0, 1) for a closed orbit; got {e!r}.")
    orbits = _check_positive("orbits", orbits)
    mu = _check_positive("mu", mu)
    a = _check_positive("a", a)
    n = math.sqrt(mu / a**3)
    period = 2.0 * math.pi / n
    b = a * math.sqrt(1.0 - e * e)

    def acceleration(t, q):
        r2 = q[0] * q[0] + q[1] * q[1]
        c = -mu / (r2 * np.sqrt(r2))
        return np.array([c * q[0], c * q[1]])

    def fun(t, y):
        if type(y) is np.ndarray and y.ndim == 1:  # one state: plain floats, no numpy scalars
            x1, x2, v1, v2 = y.tolist()
            r2 = x1 * x1 + x2 * x2
            c = -mu / (r2 * math.sqrt(r2))
            return np.array([v1, v2, c * x1, c * x2])
        r2 = y[0] * y[0] + y[1] * y[1]
        c = -mu / (r2 * np.sqrt(r2))
        return np.array([y[2], y[3], c * y[0], c * y[1]])

    def exact(t):
        E = solve_kepler_equation(n * np.asarray(t, dtype=float), e)
        s, c = np.sin(E), np.cos(E)
        d = 1.0 - e * c
        return np.array([a * (c - e), b * s, -n * a * s / d, n * b * c / d])

    def energy(y):
        y = np.asarray(y, dtype=float)
        return 0.5 * (y[2] ** 2 + y[3] ** 2) - mu / np.hypot(y[0], y[1])

    return ReferenceProblem(
        f"kepler-e{e:g}",
        fun,
        (0.0, orbits * period),
        [a * (1.0 - e), 0.0, 0.0, math.sqrt(mu / a * (1.0 + e) / (1.0 - e))],
        exact,
        acceleration=acceleration,
        energy=energy,
        period=period,
        description=f"Kepler orbit, e = {e:g} (book 27.3.1-27.3.2)",
    )


# ---------------------------------------------------------------------------------------------
# Arenstorf orbit (restricted three-body problem; the moon probe of 27.3.3)
# ---------------------------------------------------------------------------------------------

#: Earth-Moon mass ratio and periodic initial state of the Arenstorf orbit (Hairer, Norsett and
#: Wanner, *Solving ODEs I*, eq. II.0.1-II.0.2, 1993).
ARENSTORF_MU = 0.012277471
ARENSTORF_Y0 = (0.994, 0.0, 0.0, -2.00158510637908252240537862224)
ARENSTORF_PERIOD = 17.0652165601579625588917206249


def arenstorf(orbits: int = 1):
    r"""Arenstorf's periodic orbit of a probe in the Earth-Moon system (book, 27.3.3).

    .. math::

        \ddot x = x + 2\dot y - \mu'\frac{x+\mu}{D_1} - \mu\frac{x-\mu'}{D_2}, \qquad
        \ddot y = y - 2\dot x - \mu'\frac{y}{D_1} - \mu\frac{y}{D_2},

    with :math:`D_1 = ((x+\mu)^2+y^2)^{3/2}`, :math:`D_2 = ((x-\mu')^2+y^2)^{3/2}`,
    :math:`\mu = 0.012277471`, :math:`\mu' = 1-\mu`, in the frame rotating with the Earth and
    the Moon (reduced units).

    Parameters
    ----------
    orbits : int
        Number of periods in ``t_span``.

    Returns
    -------
    ReferenceProblem
        State ``y = [x, y, x', y']``. The exact solution is known only at multiples of the
        period :math:`T = 17.0652165601579625588917206249`, where it equals ``y0``;
        ``exact(t)`` raises :class:`ArgumentError` elsewhere. ``energy`` is the Jacobi
        integral :math:`x^2 + y^2 + 2\mu'/r_1 + 2\mu/r_2 - \dot x^2 - \dot y^2`. No separable
        ``acceleration`` (Coriolis terms).

    Raises
    ------
    ArgumentError
        If `orbits` is not a positive integer.

    Examples
    --------
    >>> p = arenstorf()
    >>> p.exact(p.period).tolist() == p.y0.tolist()
    True
    >>> p.exact(1.0)
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `t` must be a multiple of the period ...
    """
    if isinstance(orbits, bool) or not isinstance(orbits, int | np.integer) or orbits < 1:
        raise ArgumentError(f"`orbits` must be a positive integer; got {orbits!r}.")
    mu = ARENSTORF_MU
    mp = 1.0 - mu
    T = ARENSTORF_PERIOD
    y0 = np.array(ARENSTORF_Y0)

    def fun(t, y):
        x1, x2, v1, v2 = y[0], y[1], y[2], y[3]
        r1 = (x1 + mu) ** 2 + x2**2
        r2 = (x1 - mp) ** 2 + x2**2
        d1 = r1 * np.sqrt(r1)
        d2 = r2 * np.sqrt(r2)
        a1 = x1 + 2.0 * v2 - mp * (x1 + mu) / d1 - mu * (x1 - mp) / d2
        a2 = x2 - 2.0 * v1 - mp * x2 / d1 - mu * x2 / d2
        return np.array([v1, v2, a1, a2])

    def exact(t):
        t_arr = np.asarray(t, dtype=float)
        k = np.round(t_arr / T)
        if np.any(np.abs(t_arr - k * T) > 1e-12 * T * np.maximum(1.0, np.abs(k))):
            raise ArgumentError(
                f"`t` must be a multiple of the period T = {T!r} (the Arenstorf orbit is "
                f"known exactly only there); got {t!r}."
            )
        if t_arr.ndim == 0:
            return y0.copy()
        return np.repeat(y0[:, None], t_arr.size, axis=1)

    def energy(y):
        y = np.asarray(y, dtype=float)
        r1 = np.hypot(y[0] + mu, y[1])
        r2 = np.hypot(y[0] - mp, y[1])
        return y[0] ** 2 + y[1] ** 2 + 2 * mp / r1 + 2 * mu / r2 - y[2] ** 2 - y[3] ** 2

    return ReferenceProblem(
        "arenstorf",
        fun,
        (0.0, orbits * T),
        y0,
        exact,
        energy=energy,
        period=T,
        description="Arenstorf orbit, restricted three-body problem (book 27.3.3)",
    )
