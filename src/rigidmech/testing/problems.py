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

import numpy as np
from scipy.special import ellipj, ellipk

from rigidmech._core.errors import ArgumentError

# The orbits and the rigid body live in their own modules (split by concern); this module is
# the public home of every reference problem and re-exports them.
from .orbit_problems import (  # noqa: F401  (the constants and Kepler's equation: importable here)
    ARENSTORF_MU,
    ARENSTORF_PERIOD,
    ARENSTORF_Y0,
    arenstorf,
    kepler,
    solve_kepler_equation,
)
from .reference_problem import ReferenceProblem, _check_positive
from .rigid_body_problem import free_rigid_body

__all__ = [
    "ReferenceProblem",
    "pendulum",
    "kepler",
    "damped_oscillator",
    "arenstorf",
    "free_rigid_body",
]


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
