"""Kepler orbits, numerically: the conic from a state, the state at a time, transfers
(book, ch. 8.2 and the space problems of ch. 27.3).

A point moving under the central acceleration a = -mu OM / r^3 (Newton's attraction of a
centre of gravitational parameter mu = G M, ch. 12) describes a conic with a focus at the
centre (ch. 8.2). From one state (r0, v0) the invariants are

.. math::
    \\mathbf{h} = \\mathbf{r}\\wedge\\mathbf{v},\\qquad
    \\varepsilon = \\tfrac12 v^2 - \\frac{\\mu}{r},\\qquad
    \\mathbf{e} = \\frac{\\mathbf{v}\\wedge\\mathbf{h}}{\\mu} - \\frac{\\mathbf{r}}{r},

the semi-latus rectum p = h^2/mu, the semi-major axis a = -mu/(2 epsilon) and the
polar equation r = p / (1 + e cos nu). The kind of conic is decided by the sign of the specific
energy epsilon (the physical invariant), not by the eccentricity computed from it. Kepler's
equation M = E - e sin E (ellipse), M = e sinh H - H (hyperbola), M being the mean anomaly, is
solved by :func:`kepler_elliptic` and :func:`kepler_hyperbolic`; :meth:`Orbit.state_at` uses
the universal-variable form of it (Stumpff functions), one formula for every conic that stays
accurate near the parabola and for nearly radial orbits, where the anomalies lose their
precision.

This module is numeric (numpy, scipy): it needs no frame nor symbol, only arrays of three
components in any inertial frame centred at the attracting centre. It belongs to kinematics
because the motion is known from the central acceleration alone (ch. 8); the force that
produces it is in :mod:`rigidmech.actions.gravitation`.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from .._core.errors import ArgumentError
from ._orbit_elements import periapsis_speed, perifocal_basis
from ._orbit_plot import in_xy_plane, plot_orbit
from ._universal import propagate, time_from_periapsis
from .kepler import (  # moved there (split); re-exported so they stay importable here
    HohmannTransfer,
    _positive,
    circular_speed,
    escape_speed,
    hohmann_transfer,
    kepler_elliptic,
    kepler_hyperbolic,
)

__all__ = ["Orbit", "HohmannTransfer", "kepler_elliptic", "kepler_hyperbolic",
           "circular_speed", "escape_speed", "hohmann_transfer"]

# eccentricity up to which the conic is a circle: e_vec is computed to about 1e-16 (times
# v^2 r / mu), so below 1e-12 its direction, the periapsis, is not defined
_CIRCLE_E = 1e-12


def _vector3(x, argument):
    a = np.asarray(x, dtype=float)
    if a.shape != (3,):
        raise ArgumentError(f"`{argument}` must hold 3 components; got shape {a.shape}.")
    if not np.all(np.isfinite(a)):
        raise ArgumentError(f"`{argument}` must be finite; got {a}.")
    return a



class Orbit:
    """The Kepler conic described from an initial state under a = -mu r / r^3.

    Parameters
    ----------
    position, velocity : array_like, shape (3,)
        r0 and v0 relative to the attracting centre, in an inertial frame.
    mu : float
        Gravitational parameter G M > 0.
    epoch : float, optional
        The time t0 of the state (default 0).
    parabolic_tol : float, optional
        Relative tolerance on the specific energy: the conic is a parabola when
        ``abs(epsilon) <= parabolic_tol * (v0**2 / 2 + mu / r0)`` (the two terms whose
        difference is epsilon set its rounding scale), otherwise an ellipse (epsilon < 0) or
        a hyperbola (epsilon > 0). Default 1e-12; 0 keeps only an energy exactly zero.

    Raises
    ------
    ArgumentError
        Radial motion (angular momentum below 1e-14 r0 max(v0, sqrt(mu/r0)), the rounding
        level of r0 ^ v0: the conic degenerates into a segment and its plane and periapsis
        are undefined), r0 = 0, mu <= 0.

    Notes
    -----
    The kind decides only the elements (``is_bound``, ``period``, ``apoapsis``,
    ``semi_major_axis``, ``eccentricity``, which is 1 for a parabola). :meth:`state_at`
    propagates the given state with its own energy whatever the kind, so it is continuous
    across the parabolic band; for a bound orbit it is accurate to about 1e-12 relative to the
    size of the orbit, also when the orbit is nearly radial (e close to 1 with a tiny
    periapsis), except close to such a periapsis, where the state itself is ill-conditioned.
    A nearly radial ellipse may report ``eccentricity == 1.0``: 1 - e is below the rounding
    of 1; a, the period and the apoapsis come from the energy and stay exact.

    ``argument_of_periapsis`` is the angle from the ascending node to the periapsis in the
    plane of the orbit (the usual omega). For an orbit in the plane z = 0, where the node is
    undefined, it is measured from the x axis in the sense of the motion. The conic is a
    circle when it is bound with e <= 1e-12 (below that, the direction of the eccentricity
    vector is rounding noise); the periapsis of a circle is the position at the epoch.

    Examples
    --------
    >>> o = Orbit([1.0, 0, 0], [0, 1.2, 0], mu=1.0)
    >>> o.kind, round(o.eccentricity, 12), round(o.periapsis, 12)
    ('ellipse', 0.44, 1.0)
    >>> r, v = o.state_at(o.period)
    >>> bool(np.allclose(r, [1, 0, 0], atol=1e-12))
    True
    """

    __slots__ = ("_mu", "_r0", "_v0", "_epoch", "_h", "_e_vec", "_e", "_p", "_energy",
                 "_alpha", "_kind", "_P", "_Q", "_nu0", "_tp")

    def __init__(self, position, velocity, *, mu, epoch=0.0, parabolic_tol=1e-12):
        mu = _positive(mu, "mu")
        if not (isinstance(parabolic_tol, int | float) and 0 <= parabolic_tol < 1):
            raise ArgumentError(f"`parabolic_tol` must be a number in [0, 1); got "
                                f"{parabolic_tol!r}.")
        r0 = _vector3(position, "position")
        v0 = _vector3(velocity, "velocity")
        r = float(np.linalg.norm(r0))
        if r == 0:
            raise ArgumentError("`position` must not be the attracting centre; got r0 = 0.")
        h = np.cross(r0, v0)
        hn = np.linalg.norm(h)
        if hn <= 1e-14 * r * max(np.linalg.norm(v0), math.sqrt(mu / r)):
            raise ArgumentError(
                "the angular momentum r0 ^ v0 is zero (radial motion): there is no conic; "
                f"got position {r0} and velocity {v0}, which are parallel.")
        e_vec = np.cross(v0, h) / mu - r0 / r
        self._mu, self._r0, self._v0 = mu, r0, v0
        if isinstance(epoch, bool) or not isinstance(epoch, numbers.Real) \
                or not math.isfinite(epoch):
            raise ArgumentError(f"`epoch` must be a finite number (the time of the state); "
                                f"got {epoch!r}.")
        self._epoch = float(epoch)
        self._h, self._e_vec = h, e_vec
        self._p = p = float(hn**2 / mu)
        kinetic, potential = float(v0 @ v0 / 2), mu / r
        self._energy = energy = kinetic - potential
        self._alpha = alpha = -2 * energy / mu          # 1 / a, of the sign of -epsilon
        e_norm = float(np.linalg.norm(e_vec))
        if abs(energy) <= parabolic_tol * (kinetic + potential):
            e, kind = 1.0, "parabola"
        else:
            # e^2 = 1 - alpha p: on the side of 1 the energy says, accurate near e = 1 (a
            # nearly radial orbit); the norm of e_vec is the accurate one near e = 0
            e = e_norm if e_norm < 0.5 else math.sqrt(max(0.0, 1 - alpha * p))
            kind = ("circle" if e <= _CIRCLE_E else "ellipse") if energy < 0 else "hyperbola"
        self._e, self._kind = e, kind
        w = h / hn
        # a circle's periapsis is the position at the epoch (e_vec is rounding noise there)
        P = e_vec / e_norm if kind != "circle" else r0 / r
        self._P = P
        self._Q = np.cross(w, P)
        self._nu0 = math.atan2(r0 @ self._Q, r0 @ P)
        self._tp = self._epoch - self._time_since_periapsis()
        for a in (self._r0, self._v0, self._h, self._e_vec, self._P, self._Q):
            a.setflags(write=False)

    @classmethod
    def from_apsides(cls, periapsis, apoapsis, *, mu, raan=0.0, inclination=0.0,
                     argument_of_periapsis=0.0, epoch=0.0):
        """The ellipse of given periapsis and apoapsis radii, at its periapsis at `epoch`.

        Book, ch. 8.2: a = (r_p + r_a)/2, e = (r_a - r_p)/(r_a + r_p), and the speed at the
        periapsis from the vis-viva equation, v_p^2 = mu (2/r_p - 1/a).

        Parameters
        ----------
        periapsis, apoapsis : float
            The radii r_p <= r_a, positive and finite (r_p = r_a: a circle).
        mu : float
            Gravitational parameter G M > 0.
        raan, inclination, argument_of_periapsis : float, optional
            The plane and the periapsis, in radians: longitude of the ascending node Omega,
            inclination i in [0, pi], argument of the periapsis omega (the periapsis direction
            is R3(Omega) R1(i) R3(omega) applied to the x axis). Default 0: the plane z = 0,
            periapsis on the x axis, motion counterclockwise about z.
        epoch : float, optional
            The time of the passage at the periapsis.

        Returns
        -------
        Orbit
            Built from the state at the periapsis; its kind follows the usual rule of
            :class:`Orbit` (the energy, then e <= 1e-12 for a circle).

        Raises
        ------
        ArgumentError
            A radius not positive and finite, ``apoapsis < periapsis`` or an inclination
            outside [0, pi].
        ArgumentTypeError
            An angle that is not a real number.

        Examples
        --------
        >>> o = Orbit.from_apsides(1.0, 3.0, mu=1.0)
        >>> o.kind, round(o.eccentricity, 12), round(o.semi_major_axis, 12)
        ('ellipse', 0.5, 2.0)
        >>> round(o.apoapsis, 12)
        3.0
        """
        mu = _positive(mu, "mu")
        rp, ra = _positive(periapsis, "periapsis"), _positive(apoapsis, "apoapsis")
        if ra < rp:
            raise ArgumentError(
                f"`apoapsis` must be >= `periapsis`; got apoapsis {ra} < periapsis {rp}. "
                "Swap them.")
        P, Q = perifocal_basis(raan, inclination, argument_of_periapsis)
        return cls(rp * P, periapsis_speed(mu, rp, ra) * Q, mu=mu, epoch=epoch)

    @classmethod
    def circular(cls, period, *, mu, raan=0.0, inclination=0.0, argument_of_periapsis=0.0,
                 epoch=0.0):
        """The circular orbit of a given period; its radius from Kepler's third law.

        Book, ch. 8.2: T = 2 pi sqrt(a^3 / mu), so r = (mu (T / 2 pi)^2)^(1/3).

        Parameters
        ----------
        period : float
            T > 0.
        mu : float
            Gravitational parameter G M > 0.
        raan, inclination, argument_of_periapsis, epoch : float, optional
            As in :meth:`from_apsides`; the point is at the direction of angle
            `argument_of_periapsis` from the node at `epoch`.

        Returns
        -------
        Orbit
            Of kind ``"circle"``.

        Examples
        --------
        The geostationary orbit (one sidereal day, the Earth's mu in SI units):

        >>> o = Orbit.circular(86164.0905, mu=3.986004418e14)
        >>> o.kind, round(o.periapsis / 1e3, 1)
        ('circle', 42164.2)
        """
        mu = _positive(mu, "mu")
        T = _positive(period, "period")
        r = (mu * (T / (2 * math.pi)) ** 2) ** (1 / 3)
        return cls.from_apsides(r, r, mu=mu, raan=raan, inclination=inclination,
                                argument_of_periapsis=argument_of_periapsis, epoch=epoch)

    @property
    def mu(self) -> float:
        """Gravitational parameter mu."""
        return self._mu

    @property
    def kind(self) -> str:
        """``"circle"``, ``"ellipse"``, ``"parabola"`` or ``"hyperbola"``."""
        return self._kind

    @property
    def is_bound(self) -> bool:
        """True for a circle or an ellipse (negative specific energy)."""
        return self._kind in ("circle", "ellipse")

    @property
    def eccentricity(self) -> float:
        """The eccentricity e."""
        return self._e

    @property
    def eccentricity_vector(self) -> np.ndarray:
        """The eccentricity (Laplace-Runge-Lenz) vector, pointing to the periapsis."""
        return self._e_vec

    @property
    def angular_momentum(self) -> np.ndarray:
        """The specific angular momentum h = r ^ v (the areal constant vector, ch. 8.1.3)."""
        return self._h

    @property
    def specific_energy(self) -> float:
        """epsilon = v^2/2 - mu/r."""
        return self._energy

    @property
    def semi_latus_rectum(self) -> float:
        """p = h^2 / mu."""
        return self._p

    @property
    def semi_major_axis(self) -> float:
        """a = -mu / (2 epsilon): positive for an ellipse, negative for a hyperbola, inf for
        a parabola."""
        if self._kind == "parabola":
            return math.inf
        return 1 / self._alpha

    @property
    def periapsis(self) -> float:
        """Distance of closest approach p / (1 + e)."""
        return self._p / (1 + self._e)

    @property
    def apoapsis(self) -> float:
        """Greatest distance a (1 + e) (inf if unbound)."""
        return (1 + self._e) / self._alpha if self.is_bound else math.inf

    @property
    def period(self) -> float:
        """2 pi sqrt(a^3 / mu) (inf if unbound)."""
        if not self.is_bound:
            return math.inf
        return 2 * math.pi / (math.sqrt(self._mu) * self._alpha**1.5)

    @property
    def periapsis_direction(self) -> np.ndarray:
        """Unit vector from the centre to the periapsis."""
        return self._P

    @property
    def normal(self) -> np.ndarray:
        """Unit normal h / norm(h) to the plane of the orbit."""
        return np.cross(self._P, self._Q)

    @property
    def inclination(self) -> float:
        """Angle between h and the z axis, in [0, pi]."""
        return math.acos(max(-1.0, min(1.0, self.normal[2])))

    @property
    def argument_of_periapsis(self) -> float:
        """omega in [0, 2 pi): from the ascending node (from the x axis for an orbit in
        the plane z = 0) to the periapsis, in the sense of the motion."""
        w = self.normal
        node = np.cross([0.0, 0.0, 1.0], w)
        if in_xy_plane(w):
            node = np.array([1.0, 0.0, 0.0])
        node = node / np.linalg.norm(node)
        angle = math.atan2(np.cross(node, self._P) @ w, node @ self._P)
        return angle % (2 * math.pi)

    @property
    def true_anomaly_at_epoch(self) -> float:
        """nu0, the angle from the periapsis to r0, in (-pi, pi]."""
        return self._nu0

    @property
    def time_of_periapsis(self) -> float:
        """A time of passage at the periapsis (the last one before or at the epoch for an
        ellipse)."""
        return self._tp

    def radius_at(self, true_anomaly):
        """r = p / (1 + e cos nu), the polar equation of the conic (ch. 8.2).

        Raises
        ------
        ArgumentError
            For a hyperbola or a parabola, a true anomaly outside the branch,
            abs(nu) >= acos(-1/e) (beyond the asymptotes, where the formula gives r <= 0).

        Examples
        --------
        >>> Orbit([1.0, 0, 0], [0, 1.0, 0], mu=1.0).radius_at(2.0)
        1.0
        """
        nu = np.asarray(true_anomaly, dtype=float)
        denominator = 1 + self._e * np.cos(nu)
        if np.any(~(denominator > 0)):
            limit = math.acos(-1 / self._e)
            raise ArgumentError(
                f"`true_anomaly` must lie between the asymptotes of this {self._kind}, "
                f"abs(nu) < acos(-1/e) = {limit:.6g} (modulo 2 pi); got {true_anomaly}.")
        out = self._p / denominator
        return float(out) if out.ndim == 0 else out

    def _time_since_periapsis(self):
        """Time from the periapsis to the epoch state (universal Kepler equation); zero for
        a circle, whose periapsis is the position at the epoch."""
        if self._kind == "circle":
            return 0.0
        t = time_from_periapsis(self._r0, self._v0, self._alpha, self._mu,
                                self._p / (1 + self._e))
        if self.is_bound and t < 0:
            t += self.period                         # the last passage before the epoch
        return t

    def state_at(self, time):
        """Position and velocity at ``time`` (scalar or array of shape (n,)).

        Universal-variable propagation of the epoch state (Lagrange's f and g with the
        Stumpff functions): one formula for the ellipse, the parabola and the hyperbola,
        accurate near e = 1 and for nearly radial orbits. A bound orbit is first reduced to
        within half a period of the epoch.

        Returns
        -------
        (r, v) : ndarray, shape (3,) or (n, 3) each

        Examples
        --------
        Half a period after the periapsis the point is at the apoapsis:

        >>> o = Orbit([1.0, 0, 0], [0, 1.2, 0], mu=1.0)
        >>> r, v = o.state_at(o.period / 2)
        >>> bool(np.isclose(np.linalg.norm(r), o.apoapsis, rtol=1e-12))
        True
        """
        t = np.asarray(time, dtype=float)
        if not np.all(np.isfinite(t)):
            raise ArgumentError(f"`time` must be finite; got {time}.")
        alpha = self._alpha
        period = 2 * math.pi / (math.sqrt(self._mu) * alpha**1.5) if alpha > 0 else math.inf
        pos = np.empty(t.shape + (3,))
        vel = np.empty(t.shape + (3,))
        for index, ti in np.ndenumerate(t):
            dt = float(ti) - self._epoch
            if math.isfinite(period):
                dt -= period * round(dt / period)
            pos[index], vel[index] = propagate(self._r0, self._v0, alpha, self._mu, dt,
                                               float(ti))
        return pos, vel

    def plot(self, ax=None, *, points=200, focus=True, apsides=True, path=None, unit=None,
             extent=10.0, label=None):
        """Draw the conic in its plane (ch. 8.2): the curve, the attracting centre at its
        focus, the periapsis and the apoapsis.

        On the conventions of the library's other plots: axes labelled with their name and
        unit, equal aspect, a new figure in a constrained layout (no label is cut) with its
        legend outside the axes, on the right (on given axes the legend goes to their right).
        An orbit in the plane z = 0 is drawn in the axes x, y of its frame; any other in its
        perifocal axes, ξ towards the periapsis and η 90 degrees ahead in the sense of the
        motion. The points satisfy r = p / (1 + e cos nu) (:meth:`radius_at`) to rounding.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Default a new figure (pyplot's, or off-screen when ``path`` is given).
        points : int
            Points on the curve (>= 3). An ellipse is closed (uniform in the eccentric
            anomaly); a parabola or a hyperbola is drawn over the true anomalies where
            r <= ``extent`` * periapsis (always inside the asymptotes, so finite).
        focus, apsides : bool
            Mark the attracting centre; the periapsis (and the apoapsis of an ellipse; a
            circle has none).
        path : str or path, optional
            Save the figure there.
        unit : str, optional
            The length unit of the labels (``"x [km]"``); plain ``x``, ``y`` if not given.
        extent : float
            > 1, the reach of an open branch in periapsis distances (default 10).
        label : str, optional
            The curve's legend entry (default its kind and eccentricity).

        Returns
        -------
        Axes

        Examples
        --------
        >>> o = Orbit.from_apsides(7000.0, 42000.0, mu=398600.0)
        >>> ax = o.plot(unit="km")
        >>> ax.get_xlabel(), ax.get_ylabel()
        ('x [km]', 'y [km]')
        >>> [t.get_text() for t in ax.figure.legends[0].get_texts()]
        ['ellipse, e = 0.7143', 'centre', 'periapsis', 'apoapsis']
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """
        return plot_orbit(self, ax, points=points, focus=focus, apsides=apsides, path=path,
                          unit=unit, extent=extent, label=label)

    def __repr__(self):
        return (f"Orbit({self._kind}: e={self._e:.6g}, p={self._p:.6g}, "
                f"energy={self._energy:.6g}, mu={self._mu:.6g})")
