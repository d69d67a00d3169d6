"""Reference problems with exact solutions, to test and compare the solvers (book, ch. 27).

Each problem is an immutable :class:`ReferenceProblem`: a first-order right-hand side
``fun(t, y)``, where possible the second-order form ``q'' = a(t, q)`` used by the geometric
methods, an interval, an initial state, the exact solution ``exact(t)`` and, where one exists, a
conserved quantity ``energy(y)``. The book's numerical chapter solves the same motions:

- the simple pendulum of large amplitude (section 27.1.3), exact with Jacobi elliptic functions;
- a planet about the Sun (27.3.1) and a satellite about the Earth (27.3.2): Kepler orbits, exact
  through Kepler's equation;
- a damped oscillator under a harmonic force (ch. 21.3.3, solved numerically in the spirit of
  27.1), exact in closed form including the transient;
- the free rotation of an asymmetric rigid body (Euler's equations, ch. 18.4), exact with Jacobi
  elliptic functions;
- the Arenstorf orbit of the restricted three-body problem (Earth-Moon-probe, the setting of the
  book's moon probe 27.3.3): periodic, so that ``y(T) = y0``.

All right-hand sides are vectorised: ``y`` may be a state of shape ``(n,)`` or a batch of shape
``(n, batch)``; ``exact`` takes a scalar time (state of shape ``(n,)``) or an array of ``k`` times
(shape ``(n, k)``). For a single state (a 1-D ndarray), the ``fun`` of the pendulum, Kepler and
oscillator problems compute on plain Python floats (``y.tolist()``, :mod:`math`) instead of
numpy scalars: about 2x cheaper per call, same values, always a fresh ndarray. The benchmarks
hand this same ``fun`` to ``solve_ivp`` and to :func:`rigidmech.ode.solve`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from fractions import Fraction

import numpy as np
from scipy.special import ellipj, ellipk, ellipkm1, elliprf

from rigidmech._core.errors import ArgumentError

__all__ = [
    "ReferenceProblem",
    "pendulum",
    "kepler",
    "damped_oscillator",
    "arenstorf",
    "free_rigid_body",
]


class ReferenceProblem:
    """An initial-value problem with a known exact solution (book, ch. 27).

    Instances are immutable; build them with :func:`pendulum`, :func:`kepler`,
    :func:`damped_oscillator`, :func:`arenstorf` or :func:`free_rigid_body`.

    Parameters
    ----------
    name : str
        Short identifier, e.g. ``"kepler-e0.6"``.
    fun : callable
        First-order right-hand side ``fun(t, y)``, ``y`` of shape ``(n,)`` or ``(n, batch)``.
    t_span : tuple of float
        Integration interval ``(t0, t1)``.
    y0 : array_like, shape (n,)
        Initial state (stored as a read-only copy).
    exact : callable
        ``exact(t)``: state of shape ``(n,)`` for a scalar ``t``, ``(n, k)`` for ``k`` times.
    acceleration : callable or None
        ``a(t, q)`` of the separable second-order form ``q'' = a(t, q)``, ``q`` of shape
        ``(n // 2,)`` or ``(n // 2, batch)``; then ``y = [q, q']``. None if the force depends
        on the velocity.
    energy : callable or None
        A quantity conserved along the exact motion, ``energy(y)`` for ``y`` of shape ``(n,)``
        or ``(n, k)``; None for dissipative problems.
    period : float or None
        Period of the motion, when it is periodic.
    description : str
        One line stating the physics and the book's section.

    Examples
    --------
    >>> p = kepler(0.6)
    >>> p
    ReferenceProblem('kepler-e0.6', n=4, t_span=(0.0, 62.83185307179586))
    >>> p.y0.flags.writeable
    False
    >>> p.name = "other"
    Traceback (most recent call last):
    ...
    AttributeError: ReferenceProblem is immutable
    """

    __slots__ = (
        "name",
        "fun",
        "t_span",
        "y0",
        "exact",
        "acceleration",
        "energy",
        "period",
        "description",
    )

    def __init__(
        self,
        name: str,
        fun: Callable,
        t_span: tuple[float, float],
        y0,
        exact: Callable,
        *,
        acceleration: Callable | None = None,
        energy: Callable | None = None,
        period: float | None = None,
        description: str = "",
    ):
        y0 = np.array(y0, dtype=float)
        y0.setflags(write=False)
        values = dict(
            name=name,
            fun=fun,
            t_span=(float(t_span[0]), float(t_span[1])),
            y0=y0,
            exact=exact,
            acceleration=acceleration,
            energy=energy,
            period=None if period is None else float(period),
            description=description,
        )
        for key, value in values.items():
            object.__setattr__(self, key, value)

    def __setattr__(self, key, value):
        raise AttributeError("ReferenceProblem is immutable")

    def __delattr__(self, key):
        raise AttributeError("ReferenceProblem is immutable")

    def __repr__(self) -> str:
        return f"ReferenceProblem({self.name!r}, n={self.y0.size}, t_span={self.t_span})"

    @property
    def q0(self) -> np.ndarray:
        """Initial positions (first half of `y0`), for second-order methods."""
        return self.y0[: self.y0.size // 2]

    def final_error(self, y_final) -> float:
        """Max-norm error of a final state against the exact one at ``t_span[1]``.

        Examples
        --------
        >>> p = pendulum()
        >>> p.final_error(p.exact(p.t_span[1]))
        0.0
        """
        ref = self.exact(self.t_span[1])
        return float(np.max(np.abs(np.asarray(y_final, dtype=float) - ref)))


def _check_positive(name: str, value: float) -> float:
    value = float(value)
    if not (value > 0.0 and math.isfinite(value)):
        raise ArgumentError(f"`{name}` must be a finite number > 0; got {value!r}.")
    return value


# ---------------------------------------------------------------------------------------------
# Simple pendulum (27.1.3)
# ---------------------------------------------------------------------------------------------


def pendulum(theta0_deg: float = 170.0, omega0: float = 1.0, periods: float = 10.0):
    r"""Simple pendulum released at rest from a large angle (book, section 27.1.3).

    .. math::

        \ddot\theta + \omega_0^2 \sin\theta = 0, \qquad \theta(0) = \theta_0,
        \quad \dot\theta(0) = 0 .

    Parameters
    ----------
    theta0_deg : float
        Release angle in degrees, ``0 < theta0_deg < 180``.
    omega0 : float
        :math:`\omega_0 = \sqrt{g/\ell}` in rad/s.
    periods : float
        Length of ``t_span`` in periods.

    Returns
    -------
    ReferenceProblem
        State ``y = [theta, theta']``; ``energy`` is
        :math:`\tfrac12\dot\theta^2 - \omega_0^2\cos\theta` (per unit :math:`m\ell^2`).

    Raises
    ------
    ArgumentError
        If `theta0_deg` is not in (0, 180) or `omega0`, `periods` are not positive.

    Notes
    -----
    With :math:`k = \sin(\theta_0/2)` and :math:`K(k)` the complete elliptic integral of the
    first kind, the exact motion is

    .. math::

        \sin\frac{\theta}{2} = k\,\mathrm{sn}(K + \omega_0 t, k), \qquad
        \dot\theta = 2 k \omega_0\, \mathrm{cn}(K + \omega_0 t, k),

    of period :math:`T = 4K(k)/\omega_0` (the book's 27.1.3 compares the numerical period with
    the small-amplitude :math:`2\pi/\omega_0`). The elliptic argument is reduced modulo
    :math:`4K` before calling :func:`scipy.special.ellipj`, which keeps full accuracy over
    many periods.

    Examples
    --------
    >>> p = pendulum(170.0)
    >>> round(p.period, 6)                    # 4 K(sin 85 deg): 2.44 times the linear period
    15.326968
    >>> p.exact(p.period).round(12).tolist()  # back at rest at theta0 after one period
    [2.967059728390, 0.0]
    """
    theta0_deg = float(theta0_deg)
    if not 0.0 < theta0_deg < 180.0:
        raise ArgumentError(
            f"`theta0_deg` must be in (0, 180) degrees for an oscillating pendulum; "
            f"got {theta0_deg!r}."
        )
    w = _check_positive("omega0", omega0)
    periods = _check_positive("periods", periods)
    theta0 = math.radians(theta0_deg)
    k = math.sin(theta0 / 2.0)
    m = k * k
    K = float(ellipk(m))
    period = 4.0 * K / w
    w2 = w * w

    def fun(t, y):
        if type(y) is np.ndarray and y.ndim == 1:  # one state: plain floats, no numpy scalars
            theta, dtheta = y.tolist()
            return np.array([dtheta, -w2 * math.sin(theta)])
        return np.array([y[1], -w2 * np.sin(y[0])])

    def acceleration(t, q):
        return -w2 * np.sin(q)

    def exact(t):
        t = np.asarray(t, dtype=float)
        u = np.mod(K + w * t, 4.0 * K)
        sn, cn, _dn, _ph = ellipj(u, m)
        theta = 2.0 * np.arcsin(k * sn)
        return np.array([theta, 2.0 * k * w * cn])

    def energy(y):
        y = np.asarray(y, dtype=float)
        return 0.5 * y[1] ** 2 - w2 * np.cos(y[0])

    return ReferenceProblem(
        f"pendulum-{theta0_deg:g}deg",
        fun,
        (0.0, periods * period),
        [theta0, 0.0],
        exact,
        acceleration=acceleration,
        energy=energy,
        period=period,
        description=f"simple pendulum, theta0 = {theta0_deg:g} deg (book 27.1.3)",
    )


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
# Damped forced oscillator (ch. 21.3.3)
# ---------------------------------------------------------------------------------------------


def damped_oscillator(
    omega0: float = 10.0,
    zeta: float = 0.05,
    *,
    forcing: float = 1.0,
    omega: float = 8.0,
    t_end: float = 10.0,
    x0: float = 1.0,
    v0: float = 0.0,
):
    r"""Damped oscillator under a harmonic force, with its transient (book, 21.3.3 and 27.1).

    .. math::

        \ddot x + 2\zeta\omega_0\dot x + \omega_0^2 x = F\cos\Omega t .

    Parameters
    ----------
    omega0 : float
        Natural angular frequency :math:`\omega_0` (rad/s).
    zeta : float
        Damping ratio :math:`\zeta`, ``0 <= zeta < 1`` (under-damped).
    forcing : float
        Amplitude :math:`F` of the force per unit mass.
    omega : float
        Forcing angular frequency :math:`\Omega`.
    t_end : float
        End of ``t_span = (0, t_end)``.
    x0, v0 : float
        Initial position and velocity.

    Returns
    -------
    ReferenceProblem
        State ``y = [x, x']``; no ``acceleration`` (the force depends on the velocity) and no
        ``energy`` (the motion is dissipative).

    Raises
    ------
    ArgumentError
        If `zeta` is not in [0, 1) or `omega0`, `t_end` are not positive.

    Notes
    -----
    The steady state is :math:`x_p = \mathrm{Re}\big(F e^{i\Omega t} /
    (\omega_0^2 - \Omega^2 + 2i\zeta\omega_0\Omega)\big)`; the transient is
    :math:`e^{-\zeta\omega_0 t}(C_1\cos\omega_d t + C_2\sin\omega_d t)` with
    :math:`\omega_d = \omega_0\sqrt{1-\zeta^2}`, :math:`C_1 = x_0 - x_p(0)` and
    :math:`C_2 = (v_0 - \dot x_p(0) + \zeta\omega_0 C_1)/\omega_d`.

    Examples
    --------
    >>> p = damped_oscillator()
    >>> p.exact(0.0).tolist()
    [1.0, 0.0]
    """
    w0 = _check_positive("omega0", omega0)
    zeta = float(zeta)
    if not 0.0 <= zeta < 1.0:
        raise ArgumentError(f"`zeta` must be in [0, 1) (under-damped); got {zeta!r}.")
    t_end = _check_positive("t_end", t_end)
    F, W = float(forcing), float(omega)
    Z = F / complex(w0 * w0 - W * W, 2.0 * zeta * w0 * W)
    wd = w0 * math.sqrt(1.0 - zeta * zeta)
    sigma = zeta * w0
    C1 = float(x0) - Z.real
    C2 = (float(v0) - (-W * Z.imag) + sigma * C1) / wd
    c_damp, k_stiff = 2.0 * zeta * w0, w0 * w0

    def fun(t, y):
        if type(y) is np.ndarray and y.ndim == 1:  # one state: plain floats, no numpy scalars
            x, v = y.tolist()
            return np.array([v, F * math.cos(W * t) - c_damp * v - k_stiff * x])
        return np.array([y[1], F * np.cos(W * t) - c_damp * y[1] - k_stiff * y[0]])

    def exact(t):
        t = np.asarray(t, dtype=float)
        ph = np.exp(1j * W * t) * Z
        xp, vp = ph.real, (1j * W * ph).real
        env = np.exp(-sigma * t)
        c, s = np.cos(wd * t), np.sin(wd * t)
        xh = env * (C1 * c + C2 * s)
        vh = env * ((-sigma * C1 + wd * C2) * c + (-sigma * C2 - wd * C1) * s)
        return np.array([xp + xh, vp + vh])

    return ReferenceProblem(
        f"oscillator-w{w0:g}-z{zeta:g}",
        fun,
        (0.0, t_end),
        [x0, v0],
        exact,
        description=f"damped forced oscillator, omega0 = {w0:g}, zeta = {zeta:g} (book 21.3.3)",
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


# ---------------------------------------------------------------------------------------------
# Free rotation of an asymmetric rigid body (Euler's equations)
# ---------------------------------------------------------------------------------------------


def _incomplete_f(phi, m1, K):
    """``F(phi | m)`` from ``m1 = 1 - m`` (Carlson's form ``sin phi R_F(cos^2, cos^2 + m1 sin^2,
    1)``, free of ``1 - m sin^2 phi``), extended by ``F(phi + k pi) = F(phi) + 2 k K``."""
    k = round(phi / math.pi)
    p = phi - k * math.pi
    s, c = math.sin(p), math.cos(p)
    return 2 * k * K + s * float(elliprf(c * c, c * c + m1 * s * s, 1.0))


def _jacobi_agm(u, m1):
    """``sn, cn, dn (u | m)`` from ``m1 = 1 - m`` by the arithmetic-geometric mean
    (Abramowitz and Stegun 16.4), started from ``b0 = sqrt(m1)`` so that no digit of ``1 - m``
    is lost when ``m`` is close to 1."""
    a, b, c = [1.0], [math.sqrt(m1)], [math.sqrt(1.0 - m1)]
    while abs(c[-1]) > 1e-17 * a[-1] and len(a) < 40:
        a.append(0.5 * (a[-1] + b[-1]))
        c.append(0.5 * (a[-2] - b[-1]))
        b.append(math.sqrt(a[-2] * b[-1]))
    n = len(a) - 1
    phi = (2.0**n) * a[n] * np.asarray(u, dtype=float)
    phi_next = phi
    for j in range(n, 0, -1):
        phi_next = phi
        phi = 0.5 * (phi + np.arcsin(c[j] / a[j] * np.sin(phi)))
    sn, cn = np.sin(phi), np.cos(phi)
    dn = cn / np.cos(phi_next - phi) if n else np.ones_like(phi)
    return sn, cn, dn


def free_rigid_body(
    inertia=(1.0, 2.0, 3.0), omega0=(1.0, 0.2, 0.5), *, periods: float = 5.0
):
    r"""Free rotation of an asymmetric body about its mass centre: Euler's equations (ch. 18.4).

    .. math::

        A\dot\omega_1 = (B - C)\,\omega_2\omega_3, \quad
        B\dot\omega_2 = (C - A)\,\omega_3\omega_1, \quad
        C\dot\omega_3 = (A - B)\,\omega_1\omega_2,

    in the principal axes of inertia, ``A < B < C``.

    Parameters
    ----------
    inertia : sequence of 3 float
        Principal moments ``(A, B, C)`` with ``0 < A < B < C``.
    omega0 : sequence of 3 float
        Initial components of the rotation vector in the principal basis.
    periods : float
        Length of ``t_span`` in periods of the angular velocity.

    Returns
    -------
    ReferenceProblem
        State ``y = [omega_1, omega_2, omega_3]``; ``energy`` is the kinetic energy
        :math:`T = \tfrac12(A\omega_1^2 + B\omega_2^2 + C\omega_3^2)`; the squared angular
        momentum :math:`L^2 = A^2\omega_1^2 + B^2\omega_2^2 + C^2\omega_3^2` is conserved too.

    Raises
    ------
    ArgumentError
        If the moments are not ``0 < A < B < C``, or the motion lies on the separatrix
        :math:`2TB = L^2` (no periodic elliptic solution).

    Notes
    -----
    The case distinction is the sign of :math:`2TB - L^2` (the body turns about the axis of
    largest or of smallest inertia). If :math:`L^2 > 2TB`, with
    :math:`\lambda = \sqrt{(C-B)(L^2-2TA)/(ABC)}` and
    :math:`m = k^2 = \frac{(B-A)(2TC-L^2)}{(C-B)(L^2-2TA)}`,

    .. math::

        \omega_1 = s\,\sqrt{\tfrac{2TC - L^2}{A(C-A)}}\,\mathrm{cn}\,u, \quad
        \omega_2 = \sqrt{\tfrac{2TC - L^2}{B(C-B)}}\,\mathrm{sn}\,u, \quad
        \omega_3 = s\,\sqrt{\tfrac{L^2 - 2TA}{C(C-A)}}\,\mathrm{dn}\,u,

    with :math:`s = \operatorname{sign}\omega_3(0)` and :math:`u = \lambda t + u_0`. If
    :math:`L^2 < 2TB` the roles of the axes 1 and 3 are exchanged:
    :math:`\lambda = \sqrt{(B-A)(2TC-L^2)/(ABC)}`,
    :math:`m = \frac{(C-B)(L^2-2TA)}{(B-A)(2TC-L^2)}`,
    :math:`\omega_1 = s\sqrt{(2TC-L^2)/(A(C-A))}\,\mathrm{dn}\,u`,
    :math:`\omega_2 = \sqrt{(L^2-2TA)/(B(B-A))}\,\mathrm{sn}\,u`,
    :math:`\omega_3 = s\sqrt{(L^2-2TA)/(C(C-A))}\,\mathrm{cn}\,u`, :math:`s = \operatorname
    {sign}\omega_1(0)`. The phase :math:`u_0 = F(\varphi_0 \mid m)` is the incomplete elliptic
    integral of the amplitude :math:`\varphi_0` read from :math:`(\mathrm{sn}\,u_0,
    \mathrm{cn}\,u_0)` at :math:`t = 0`; the period is :math:`4K(m)/\lambda` (Landau and
    Lifshitz, *Mechanics*, section 37, with the signs fixed by Euler's equations).

    To stay exact near the separatrix, :math:`2TC - L^2 = A(C-A)\omega_1^2 + B(C-B)\omega_2^2`,
    :math:`L^2 - 2TA = B(B-A)\omega_2^2 + C(C-A)\omega_3^2` and
    :math:`2TB - L^2 = A(B-A)\omega_1^2 - C(C-B)\omega_3^2` are formed in exact rational
    arithmetic from the given floats, and :math:`K`, :math:`u_0` and
    :math:`\mathrm{sn}, \mathrm{cn}, \mathrm{dn}` are computed from :math:`1 - m` (Carlson's
    :math:`R_F`, the arithmetic-geometric mean) rather than from :math:`m`.

    Examples
    --------
    >>> p = free_rigid_body()
    >>> bool(np.allclose(p.exact(0.0), p.y0, atol=1e-15))
    True
    >>> bool(np.allclose(p.exact(p.period), p.y0, atol=1e-13))
    True
    """
    A, B, C = (float(v) for v in inertia)
    if not 0.0 < A < B < C:
        raise ArgumentError(
            f"`inertia` must be principal moments with 0 < A < B < C; got {tuple(inertia)!r}."
        )
    w = np.array(omega0, dtype=float)
    if w.shape != (3,) or not np.all(np.isfinite(w)):
        raise ArgumentError(f"`omega0` must be 3 finite numbers; got {omega0!r}.")
    periods = _check_positive("periods", periods)
    L2 = A * A * w[0] ** 2 + B * B * w[1] ** 2 + C * C * w[2] ** 2
    # the three differences exactly (rational arithmetic on the given floats), then rounded
    # once: near the separatrix 2TB - L^2 is a tiny difference of large terms, whose rounding
    # in floats would cost as many digits of 1 - m (and of the solution) as it cancels
    fA, fB, fC = (Fraction(v) for v in (A, B, C))
    f1, f2, f3 = (Fraction(float(v)) ** 2 for v in w)
    cC_q = fA * (fC - fA) * f1 + fB * (fC - fB) * f2  # 2TC - L^2 >= 0
    cA_q = fB * (fB - fA) * f2 + fC * (fC - fA) * f3  # L^2 - 2TA >= 0
    gap_q = fA * (fB - fA) * f1 - fC * (fC - fB) * f3  # 2TB - L^2
    cC, cA, gap = float(cC_q), float(cA_q), float(gap_q)
    if abs(gap) <= 1e-12 * L2 or L2 == 0.0:
        raise ArgumentError(
            f"`omega0` lies on the separatrix 2TB = L^2 (2TB - L^2 = {gap:.3g}); the rotation "
            f"is not periodic there - perturb `omega0`."
        )
    a1 = math.sqrt(cC / (A * (C - A)))
    a3 = math.sqrt(cA / (C * (C - A)))
    if gap < 0.0:  # L^2 > 2TB: turns about the C axis, omega_3 keeps its sign
        lam = math.sqrt((C - B) * cA / (A * B * C))
        m1 = float((fC - fA) * -gap_q / ((fC - fB) * cA_q))  # 1 - m, exactly then rounded
        a2 = math.sqrt(cC / (B * (C - B)))
        s = 1.0 if w[2] >= 0 else -1.0
        phi0 = math.atan2(w[1] / a2, s * w[0] / a1)
    else:  # L^2 < 2TB: turns about the A axis, omega_1 keeps its sign
        lam = math.sqrt((B - A) * cC / (A * B * C))
        m1 = float((fC - fA) * gap_q / ((fB - fA) * cC_q))
        a2 = math.sqrt(cA / (B * (B - A)))
        s = 1.0 if w[0] >= 0 else -1.0
        phi0 = math.atan2(w[1] / a2, s * w[2] / a3)
    # from 1 - m, not m: near the separatrix (m -> 1) scipy's ellipkinc and ellipj lose the
    # digits of 1 - m that a float m cannot hold
    K = float(ellipkm1(m1))
    u0 = _incomplete_f(phi0, m1, K)
    period = 4.0 * K / lam
    about_c = gap < 0.0

    def fun(t, y):
        return np.array(
            [
                (B - C) / A * y[1] * y[2],
                (C - A) / B * y[2] * y[0],
                (A - B) / C * y[0] * y[1],
            ]
        )

    def exact(t):
        u = np.mod(lam * np.asarray(t, dtype=float) + u0, 4.0 * K)
        sn, cn, dn = _jacobi_agm(u, m1)
        if about_c:
            return np.array([s * a1 * cn, a2 * sn, s * a3 * dn])
        return np.array([s * a1 * dn, a2 * sn, s * a3 * cn])

    def energy(y):
        y = np.asarray(y, dtype=float)
        return 0.5 * (A * y[0] ** 2 + B * y[1] ** 2 + C * y[2] ** 2)

    return ReferenceProblem(
        "free-rigid-body",
        fun,
        (0.0, periods * period),
        w,
        exact,
        energy=energy,
        period=period,
        description=f"free asymmetric rigid body, (A, B, C) = {(A, B, C)} (Euler's equations)",
    )
