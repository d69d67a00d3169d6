"""Closed-form solutions used by the ODE tests (computed here, independent of the library)."""

from __future__ import annotations

import numpy as np


def kepler_rhs(t, y):
    """Planar Kepler problem with mu = 1: y = [x, y, vx, vy]."""
    r3 = (y[0] ** 2 + y[1] ** 2) ** 1.5
    return np.array([y[2], y[3], -y[0] / r3, -y[1] / r3])


def kepler_initial(e):
    """Pericentre of the orbit of semi-major axis 1 and eccentricity e (period 2 pi)."""
    return np.array([1.0 - e, 0.0, 0.0, np.sqrt((1.0 + e) / (1.0 - e))])


def kepler_exact(t, e):
    """Exact state at time t: Kepler's equation E - e sin E = t solved by Newton."""
    M = np.asarray(t, dtype=float)
    E = M + e * np.sin(M)
    for _ in range(50):
        dE = (E - e * np.sin(E) - M) / (1.0 - e * np.cos(E))
        E = E - dE
        if np.all(np.abs(dE) < 1e-16 * (1 + np.abs(E))):
            break
    s = np.sqrt(1.0 - e * e)
    den = 1.0 - e * np.cos(E)
    return np.array([np.cos(E) - e, s * np.sin(E), -np.sin(E) / den, s * np.cos(E) / den])


def oscillator_rhs(t, y):
    """Harmonic oscillator x'' = -x."""
    return np.array([y[1], -y[0]])


def oscillator_exact(t, x0=1.0, v0=0.0):
    t = np.asarray(t, dtype=float)
    return np.array([x0 * np.cos(t) + v0 * np.sin(t), -x0 * np.sin(t) + v0 * np.cos(t)])


# damped forced oscillator x'' + 2 zeta w0 x' + w0^2 x = F cos(w t), x(0) = x0, x'(0) = v0
W0, ZETA, F, W = 10.0, 0.05, 1.0, 7.0


def forced_rhs(t, y):
    return np.array([y[1], F * np.cos(W * t) - 2 * ZETA * W0 * y[1] - W0**2 * y[0]])


def forced_exact(t, x0=1.0, v0=0.0):
    """Particular solution (complex amplitude) plus the damped homogeneous solution."""
    t = np.asarray(t, dtype=float)
    Z = F / (W0**2 - W**2 + 2j * ZETA * W0 * W)
    a, b = Z.real, Z.imag  # x_p = a cos(wt) - b sin(wt)
    xp0, vp0 = a, -b * W
    sig = ZETA * W0
    wd = W0 * np.sqrt(1 - ZETA**2)
    c1 = x0 - xp0
    c2 = (v0 - vp0 + sig * c1) / wd
    ex = np.exp(-sig * t)
    xh = ex * (c1 * np.cos(wd * t) + c2 * np.sin(wd * t))
    vh = ex * (-sig * (c1 * np.cos(wd * t) + c2 * np.sin(wd * t))
               + wd * (-c1 * np.sin(wd * t) + c2 * np.cos(wd * t)))
    xp = a * np.cos(W * t) - b * np.sin(W * t)
    vp = -a * W * np.sin(W * t) - b * W * np.cos(W * t)
    return np.array([xh + xp, vh + vp])
