"""Adaptive embedded Runge-Kutta pairs: Dormand-Prince 5(4) and DOP853 (book, ch. 26.2).

The step is chosen so that an estimate of the local error stays below the tolerance, measured
in Hairer's weighted RMS norm ``sqrt(mean((err / (atol + rtol max(|y0|, |y1|)))**2))``; the
new step is ``h * min(10, max(0.2, 0.9 err**(-1/(q+1))))`` with ``q`` the order of the error
estimator, never growing just after a rejection (the same rules as scipy's ``solve_ivp`` RK45
and DOP853, so that both take the same steps). The starting step follows Hairer's algorithm.

Dense output: Shampine's 4th-order interpolant for ``"dopri5"`` (free: it reuses the stages)
and DOP853's 7th-order interpolant (three extra evaluations of ``f`` per step, made only when a
dense output, ``t_eval`` or a located event needs them).

Stiffness detection (Hairer, Wanner II, Sec. IV.2; codes DOPRI5/DOP853): the two last stages
share the time ``t + h``, so ``h |lambda| ~ |h| ||f(y1) - f(ys)|| / ||y1 - ys||`` estimates
the step times the dominant eigenvalue of the Jacobian. When it stays above the border of the
stability domain (3.25 for DOPRI5, 6.1 for DOP853) for 15 consecutive checks, a
:class:`~rigidmech.ode.StiffnessWarning` advises ``method="radau"``. Checks are made every
`nstiff` accepted steps (1000 by default) and at every step once the estimate is high.

Batches: with ``y0`` of shape ``(n, batch)``, every trajectory is advanced with the same step,
chosen from the largest error norm over the batch.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from rigidmech._core.errors import ArgumentError

from . import _registry, tableaux
from ._driver import Problem, Recorder, initial_step
from ._warnings import StiffnessWarning

__all__ = ["dopri5", "dop853"]

SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0


class _Pair:
    """Constants of one embedded pair, precomputed once."""

    def __init__(self, name, tableau, order_est, stiff_border):
        self.name = name
        self.s = tableau.stages if name == "dop853" else tableau.stages - 1  # w/o FSAL stage
        self.A = [np.ascontiguousarray(tableau.A[i, :i]) for i in range(self.s)]
        self.c = tableau.c[: self.s].copy()
        self.b = tableau.b[: self.s].copy()
        self.exponent = -1.0 / (order_est + 1)
        self.order_est = order_est
        self.stiff_border = stiff_border


_DP5 = _Pair("dopri5", tableaux.DOPRI5, 4, 3.25)
_DP5.E = tableaux.DOPRI5_E.copy()
_DP5.P = tableaux.DOPRI5_P.T.copy()  # (4, 7)
_D8 = _Pair("dop853", tableaux.DOP853, 7, 6.1)
_D8.E5 = tableaux.DOP853_E5.copy()
_D8.E3 = tableaux.DOP853_E3.copy()
_D8.D = tableaux.DOP853_D.copy()
_D8.A_extra = [np.ascontiguousarray(a[: 13 + i]) for i, a in enumerate(tableaux.DOP853_A_EXTRA)]
_D8.c_extra = tableaux.DOP853_C_EXTRA.copy()


def _integrate(pair, fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps,
               dense_output, events, nstiff):
    t0, t_end = t_span
    direction = 1.0 if t_end > t0 else -1.0
    shape = y0.shape
    prob = Problem(fun, shape)
    n = shape[0]
    y = y0.reshape(-1).copy()
    N = y.size
    s = pair.s
    is853 = pair.name == "dop853"
    K = np.empty((16 if is853 else s + 1, N))
    rec = Recorder(t0, y, shape, dense_output, events, "nested" if is853 else "power")
    prob(t0, y, K[0])
    if not np.isfinite(K[0]).all():
        rec.fail("The right-hand side is not finite", t0, y)
        return rec.result(pair.name, prob.nfev, 0)
    if first_step is None:
        h_abs = initial_step(prob, t0, y, K[0], direction, pair.order_est, rtol, atol, t_end,
                             max_step)
    else:
        h_abs = first_step
    A, c, b, exponent = pair.A, pair.c, pair.b, pair.exponent
    t = t0
    nrej = 0
    naccpt = 0
    iasti = nonsti = 0
    warned = False
    ys = y
    while direction * (t - t_end) < 0:
        if naccpt >= max_steps:
            rec.fail(f"The maximum number of steps `max_steps` = {max_steps} was reached", t, y)
            break
        min_step = 10.0 * abs(math.nextafter(t, direction * math.inf) - t)
        if h_abs > max_step:
            h_abs = max_step
        elif h_abs < min_step:
            h_abs = min_step
        rejected = accepted = False
        while True:
            if not h_abs >= min_step:  # also catches a nan step
                break
            h = h_abs * direction
            t_new = t + h
            if direction * (t_new - t_end) > 0:
                t_new = t_end
            h = t_new - t
            h_abs = abs(h)
            for i in range(1, s):
                ys = y + (h * A[i]) @ K[:i]
                prob(t + c[i] * h, ys, K[i])
            y_new = y + (h * b) @ K[:s]
            prob(t_new, y_new, K[s])
            scale = atol + rtol * np.maximum(np.abs(y), np.abs(y_new))
            if is853:
                s5 = prob.sumsq((pair.E5 @ K[:13]) / scale)
                s3 = prob.sumsq((pair.E3 @ K[:13]) / scale)
                den = s5 + 0.01 * s3
                if prob.batch:
                    with np.errstate(invalid="ignore", divide="ignore"):
                        e = np.where(den > 0, h_abs * s5 / np.sqrt(den * n), 0.0)
                    err = float(np.max(e))
                else:
                    err = h_abs * s5 / math.sqrt(den * N) if den > 0 else 0.0
            else:
                err = prob.norm(((h * pair.E) @ K[: s + 1]) / scale)
            if err < 1.0:
                if err == 0.0:
                    factor = MAX_FACTOR
                else:
                    factor = min(MAX_FACTOR, SAFETY * err**exponent)
                if rejected:
                    factor = min(1.0, factor)
                h_abs *= factor
                accepted = True
                break
            # rejected (err >= 1, or nan/inf: shrink as much as allowed)
            if err == err and err != math.inf:
                h_abs *= max(MIN_FACTOR, SAFETY * err**exponent)
            else:
                h_abs *= MIN_FACTOR
            rejected = True
            nrej += 1
        if not accepted:
            rec.fail("The step size fell below the resolution of t (step size underflow)",
                     t, y)
            break
        if not np.isfinite(y_new).all():  # pragma: no cover - caught by err above
            rec.fail("The state became non-finite", t_new, y_new)
            break
        naccpt += 1
        # stiffness detection (Hairer's DOPRI5/DOP853 test)
        if nstiff and (naccpt % nstiff == 0 or iasti > 0):
            den = float(np.dot(y_new - ys, y_new - ys))
            if den > 0:
                d = K[s] - K[s - 1]
                hlamb = h_abs * math.sqrt(float(np.dot(d, d)) / den)
                if hlamb > pair.stiff_border:
                    nonsti = 0
                    iasti += 1
                    if iasti == 15 and not warned:
                        warned = True
                        warnings.warn(
                            f"The problem seems to have become stiff at t = {t_new:.6g} "
                            f"(method {pair.name!r}, h*|lambda| ~ {hlamb:.3g} for 15 checks): "
                            "use method='radau'.",
                            StiffnessWarning,
                            stacklevel=4,
                        )
                else:
                    nonsti += 1
                    if nonsti == 6:
                        iasti = 0
        if rec.cs is not None or events is not None:
            coeffs = _dense_dop853(pair, prob, t, y, y_new, h, K) if is853 else (
                (h * pair.P) @ K[: s + 1])
        else:
            coeffs = None
        stop = rec.accept(t_new, y_new, coeffs)
        t = t_new
        y = y_new
        K[0] = K[s]
        if stop:
            break
    return rec.result(pair.name, prob.nfev, nrej)


def _dense_dop853(pair, prob, t, y, y_new, h, K):
    """DOP853's interpolation coefficients, computed lazily (3 more evaluations of f)."""
    Kc = K.copy()

    def coeffs():
        for j, (a, cj) in enumerate(zip(pair.A_extra, pair.c_extra, strict=True)):
            prob(t + cj * h, y + (h * a) @ Kc[: 13 + j], Kc[13 + j])
        F = np.empty((7, y.size))
        dy = y_new - y
        F[0] = dy
        F[1] = h * Kc[0] - dy
        F[2] = 2.0 * dy - h * (Kc[12] + Kc[0])
        F[3:] = h * (pair.D @ Kc)
        return F

    return coeffs


def _check_nstiff(nstiff):
    if isinstance(nstiff, bool) or not isinstance(nstiff, int | np.integer) or nstiff < 0:
        raise ArgumentError(f"`nstiff` must be an int >= 0 (0 disables the test); got {nstiff!r}.")
    return int(nstiff)


def dopri5(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
           max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None,
           nstiff=1000):
    """Dormand-Prince 5(4) with error control, dense output and stiffness detection.

    Called through :func:`rigidmech.ode.solve` (``method="dopri5"`` or ``"rk45"``), which
    validates the arguments; see its parameters. `nstiff` (int, default 1000) sets how often
    the stiffness test runs; 0 disables it.

    Returns
    -------
    OdeResult

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> r = ode.solve(lambda t, y: -y, (0.0, 2.0), [1.0], method="dopri5", rtol=1e-8)
    >>> bool(abs(r.y[0, -1] - np.exp(-2.0)) < 1e-8), r.status
    (True, 0)
    """
    nstiff = _check_nstiff(nstiff)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        return _integrate(_DP5, fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                          max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                          events=events, nstiff=nstiff)


def dop853(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
           max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None,
           nstiff=1000):
    """Dormand-Prince 8(5,3) (Hairer's DOP853) with error control, 7th-order dense output and
    stiffness detection.

    Called through :func:`rigidmech.ode.solve` (``method="dop853"``, the default), which
    validates the arguments; see its parameters. `nstiff` as in :func:`dopri5`.

    Returns
    -------
    OdeResult

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> osc = lambda t, y: np.array([y[1], -y[0]])
    >>> r = ode.solve(osc, (0.0, 20.0), [1.0, 0.0], method="dop853", rtol=1e-12, atol=1e-14)
    >>> bool(abs(r.y[0, -1] - np.cos(20.0)) < 1e-11)
    True
    """
    nstiff = _check_nstiff(nstiff)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        return _integrate(_D8, fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                          max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                          events=events, nstiff=nstiff)


_registry.register("dopri5", dopri5, kind="adaptive")
_registry.register("rk45", dopri5, kind="adaptive")
_registry.register("dop853", dop853, kind="adaptive")
