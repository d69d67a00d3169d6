"""Reference problem of the free rotation of an asymmetric rigid body about its mass centre
(Euler's equations, book ch. 18.4), exact with Jacobi elliptic functions.

Part of :mod:`rigidmech.testing.problems`, which re-exports :func:`free_rigid_body` and states
the conventions (vectorised right-hand sides, ``exact`` at one time or an array of times).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
from scipy.special import ellipkm1, elliprf

from rigidmech._core.errors import ArgumentError

from .reference_problem import ReferenceProblem, _check_positive

__all__ = ["free_rigid_body"]


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
