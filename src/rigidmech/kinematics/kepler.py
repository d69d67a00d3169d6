"""Kepler's equation, circular and escape speeds, the Hohmann transfer (book, ch. 8.2 and the
space problems of ch. 27.3).

Kepler's equation M = E - e sin E (ellipse), M = e sinh H - H (hyperbola), M being the mean
anomaly, is solved by :func:`kepler_elliptic` and :func:`kepler_hyperbolic` (Newton's method on
a convex increasing branch, so the iterates decrease monotonically to the root). The conic
itself, from a state, and its propagation in time are :class:`rigidmech.kinematics.Orbit`
(module :mod:`rigidmech.kinematics.orbits`, which re-exports the names of this module).

Numeric (numpy): no frame nor symbol.
"""

from __future__ import annotations

import math

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError, NumericalError

__all__ = ["HohmannTransfer", "kepler_elliptic", "kepler_hyperbolic",
           "circular_speed", "escape_speed", "hohmann_transfer"]

_MAX_ITER = 200


def _positive(x, argument):
    try:
        x = float(x)
    except (TypeError, ValueError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be a positive number; got {type(x).__name__}.") from exc
    if not (math.isfinite(x) and x > 0):
        raise ArgumentError(f"`{argument}` must be a positive finite number; got {x}.")
    return x



def _newton(f, fprime, x0, what):
    # monotone Newton: the starts below lie where f >= 0 on a convex increasing branch, so the
    # iterates decrease to the root; stop when a step no longer shrinks.
    x = np.array(x0, dtype=float)
    active = np.ones(x.shape, dtype=bool)
    last = np.full(x.shape, np.inf)
    for _ in range(_MAX_ITER):
        step = np.where(active, f(x) / fprime(x), 0.0)
        x = x - step
        size = np.abs(step)
        tol = 4 * np.finfo(float).eps * np.maximum(1.0, np.abs(x))
        # converged, or rounding noise (a small step that no longer shrinks)
        active &= ~((size <= tol) | ((size >= last) & (size < 1e-8)))
        last = np.where(active, size, last)
        if not active.any():
            return x
    raise NumericalError(f"{what}: Newton's method did not converge in {_MAX_ITER} "
                         "iterations.")


def _check_e_M(e, low, high, mean_anomaly):
    e = np.asarray(e, dtype=float)
    bad = ~((e >= low) & (e < high)) if high != np.inf else ~((e > low) & np.isfinite(e))
    if np.any(bad):
        span = f"[{low}, {high})" if high != np.inf else f"({low}, inf)"
        raise ArgumentError(f"`e` must lie in {span}; got {e[bad] if e.ndim else e}.")
    M = np.asarray(mean_anomaly, dtype=float)
    if not np.all(np.isfinite(M)):
        raise ArgumentError(f"`mean_anomaly` must be finite; got {mean_anomaly}.")
    return e, M


def kepler_elliptic(mean_anomaly, e):
    """The eccentric anomaly E solving Kepler's equation E - e sin E = M, 0 <= e < 1.

    Newton's method started at min(abs(M) + e, pi) on the reduced anomaly abs(M) in [0, pi], where
    the function is convex and increasing: the iterates decrease monotonically to the root for
    every e < 1 (no divergence near e = 1). Broadcasts over arrays.

    Parameters
    ----------
    mean_anomaly : float or array
        M in radians, any value (the result keeps its turn: E - M is in [-pi, pi]).
    e : float or array
        Eccentricity in [0, 1).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> E = kepler_elliptic(1.0, 0.5)
    >>> round(float(E - 0.5 * np.sin(E)), 12)
    1.0
    """
    e, M = _check_e_M(e, 0.0, 1.0, mean_anomaly)
    turns = np.round(M / (2 * np.pi))
    Mr = M - 2 * np.pi * turns  # in [-pi, pi]
    s = np.where(Mr < 0, -1.0, 1.0)
    m = np.abs(Mr)
    E = _newton(lambda E: E - e * np.sin(E) - m, lambda E: 1 - e * np.cos(E),
                np.minimum(m + e, np.pi) + 0 * e, "kepler_elliptic")
    out = s * E + 2 * np.pi * turns
    return float(out) if out.ndim == 0 else out


def kepler_hyperbolic(mean_anomaly, e):
    """The hyperbolic anomaly H solving e sinh H - H = M, e > 1.

    Newton's method started at asinh(abs(M) / (e - 1)), where the (convex, increasing) function is
    non-negative: the iterates decrease monotonically to the root. Broadcasts over arrays.

    Examples
    --------
    >>> H = kepler_hyperbolic(2.0, 1.5)
    >>> round(float(1.5 * np.sinh(H) - H), 12)
    2.0
    """
    e, M = _check_e_M(e, 1.0, np.inf, mean_anomaly)
    s = np.where(M < 0, -1.0, 1.0)
    m = np.abs(M)
    H = _newton(lambda H: e * np.sinh(H) - H - m, lambda H: e * np.cosh(H) - 1,
                np.arcsinh(m / (e - 1)), "kepler_hyperbolic")
    out = s * H
    return float(out) if out.ndim == 0 else out


def circular_speed(mu, r) -> float:
    """Speed sqrt(mu / r) on a circular orbit of radius r (ch. 8.2).

    Examples
    --------
    >>> circular_speed(4.0, 1.0)
    2.0
    """
    return math.sqrt(_positive(mu, "mu") / _positive(r, "r"))


def escape_speed(mu, r) -> float:
    """Escape (parabolic) speed sqrt(2 mu / r) at distance r: zero specific energy.

    Examples
    --------
    >>> escape_speed(2.0, 1.0)
    2.0
    """
    return math.sqrt(2 * _positive(mu, "mu") / _positive(r, "r"))



class HohmannTransfer:
    """The Hohmann transfer between coplanar circular orbits of radii r1 and r2 (ch. 27.3).

    Attributes are read-only: ``r1``, ``r2``, ``mu``, ``semi_major_axis`` = (r1 + r2)/2,
    ``delta_v1``, ``delta_v2`` (speed changes at departure and arrival, positive when
    speeding up), ``total_delta_v`` (sum of their magnitudes), ``time`` (half the period of
    the transfer ellipse).

    Examples
    --------
    >>> h = hohmann_transfer(1.0, 1.0, 4.0)
    >>> round(h.time, 12) == round(np.pi * 2.5**1.5, 12)
    True
    """

    __slots__ = ("_r1", "_r2", "_mu")

    def __init__(self, mu, r1, r2):
        self._mu = _positive(mu, "mu")
        self._r1 = _positive(r1, "r1")
        self._r2 = _positive(r2, "r2")

    r1 = property(lambda self: self._r1, doc="Radius of the departure circle.")
    r2 = property(lambda self: self._r2, doc="Radius of the arrival circle.")
    mu = property(lambda self: self._mu, doc="Gravitational parameter.")

    @property
    def semi_major_axis(self) -> float:
        """(r1 + r2) / 2."""
        return (self._r1 + self._r2) / 2

    @property
    def delta_v1(self) -> float:
        """sqrt(mu/r1) (sqrt(2 r2/(r1 + r2)) - 1)."""
        r1, r2 = self._r1, self._r2
        return math.sqrt(self._mu / r1) * (math.sqrt(2 * r2 / (r1 + r2)) - 1)

    @property
    def delta_v2(self) -> float:
        """sqrt(mu/r2) (1 - sqrt(2 r1/(r1 + r2)))."""
        r1, r2 = self._r1, self._r2
        return math.sqrt(self._mu / r2) * (1 - math.sqrt(2 * r1 / (r1 + r2)))

    @property
    def total_delta_v(self) -> float:
        """abs(delta_v1) + abs(delta_v2)."""
        return abs(self.delta_v1) + abs(self.delta_v2)

    @property
    def time(self) -> float:
        """pi sqrt(a^3 / mu), half a period of the transfer ellipse."""
        return math.pi * math.sqrt(self.semi_major_axis**3 / self._mu)

    def plot(self, ax=None, *, points=200, path=None, unit=None):
        """Draw the departure circle, the arrival circle and the transfer ellipse (ch. 27.3),
        the centre and the two burns at the apsides, on the conventions of
        :meth:`Orbit.plot <rigidmech.kinematics.orbits.Orbit.plot>`: equal aspect, axes
        ``x [unit]``, ``y [unit]``, a new figure in a constrained layout with its legend
        outside the axes. The departure is on the +x axis, the motion counter-clockwise.

        Parameters
        ----------
        ax : matplotlib Axes, optional
        points : int
            Points on each curve (>= 3).
        path : str or path, optional
            Save the figure there (a new figure is then drawn off-screen).
        unit : str, optional
            The length unit of the labels.

        Returns
        -------
        Axes

        Examples
        --------
        >>> ax = HohmannTransfer(398600.0, 6678.0, 42164.0).plot(unit="km")
        >>> ax.get_xlabel(), len(ax.figure.legends)
        ('x [km]', 1)
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """
        from ._orbit_plot import plot_transfer

        return plot_transfer(self, ax, points=points, path=path, unit=unit)

    def __repr__(self):
        return (f"HohmannTransfer(mu={self._mu:g}, r1={self._r1:g}, r2={self._r2:g}: "
                f"dv1={self.delta_v1:.6g}, dv2={self.delta_v2:.6g}, time={self.time:.6g})")


def hohmann_transfer(mu, r1, r2) -> HohmannTransfer:
    """The Hohmann transfer from the circle of radius r1 to that of radius r2 (ch. 27.3).

    Examples
    --------
    >>> h = hohmann_transfer(3.986004418e14, 6678e3, 42164e3)   # LEO to GEO, SI units
    >>> round(h.delta_v1), round(h.delta_v2)
    (2426, 1467)
    """
    return HohmannTransfer(mu, r1, r2)
