"""Adaptive embedded Runge-Kutta pairs: Dormand-Prince 5(4) and DOP853 (book, ch. 26.2).

The step is chosen so that an estimate of the local error stays below the tolerance, measured
in Hairer's weighted RMS norm ``sqrt(mean((err / (atol + rtol max(|y0|, |y1|)))**2))``; the
new step is ``h * min(10, max(0.2, 0.9 err**(-1/(q+1))))`` with ``q`` the order of the error
estimator, never growing just after a rejection (the same rules as scipy's ``solve_ivp`` RK45
and DOP853, so that both take the same steps). The starting step follows Hairer's algorithm.
With ``step_control="pi"``, an accepted step is followed by Gustafsson's PI controller
``h_new = h * 0.9 * err_n**(-0.7/k) * err_{n-1}**(0.4/k)`` (``k = q + 1``; Hairer, Wanner II,
IV.2, eq. (2.43)), which damps the oscillation of the step size: on eccentric orbits it rejects
about half as many steps, for a similar number of evaluations at equal error.

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

import numpy as np

from rigidmech._core.errors import ArgumentError

from . import _registry, tableaux
from ._driver import Problem, Recorder, initial_step
from ._floatpath import FLOAT_PATH_MAX_N, make_unrolled_stepper
from ._warnings import stiffness_count

__all__ = ["dopri5", "dop853"]

SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
#: Gains of the PI step-size controller (Gustafsson 1991; HNW II, IV.2, eq. (2.43)):
#: ``h_new = h * SAFETY * err_n**(-PI_KI / k) * err_{n-1}**(PI_KP / k)``, ``k = q + 1``.
PI_KI = 0.7
PI_KP = 0.4
#: Floor of the previous error in the PI formula (as in Hairer's DOPRI5 code).
PI_ERR_FLOOR = 1e-4
STEP_CONTROLS = ("i", "pi")


def _stiffness_test(pair, hlamb, t_new, iasti, nonsti, warned):
    """One step of Hairer's stiffness detection for `pair` (shared by the numpy and the float
    paths); see :func:`~rigidmech.ode._warnings.stiffness_count`."""
    return stiffness_count(pair.name, pair.stiff_border, hlamb, t_new, iasti, nonsti, warned)


class _Pair:
    """Constants of one embedded pair, precomputed once."""

    def __init__(self, name, tableau, order_est, stiff_border):
        self.name = name
        self.s = tableau.stages if name == "dop853" else tableau.stages - 1  # w/o FSAL stage
        self.c = tableau.c[: self.s].copy()
        self.b = tableau.b[: self.s].copy()
        self.exponent = -1.0 / (order_est + 1)
        self.Ab = np.zeros((self.s + 1, self.s))
        self.Ab[: self.s] = tableau.A[: self.s, : self.s]
        self.Ab[self.s] = self.b
        self.order_est = order_est
        self.stiff_border = stiff_border


_DP5 = _Pair("dopri5", tableaux.DOPRI5, 4, 3.25)
_DP5.E = tableaux.DOPRI5_E.copy()
_DP5.P = tableaux.DOPRI5_P.T.copy()  # (4, 7)
_D8 = _Pair("dop853", tableaux.DOP853, 7, 6.1)
_D8.E5 = tableaux.DOP853_E5.copy()
_D8.E3 = tableaux.DOP853_E3.copy()
_D8.D = tableaux.DOP853_D.copy()
_D8.E53 = np.stack([_D8.E5, _D8.E3])
_D8.A_extra = [np.ascontiguousarray(a[: 13 + i]) for i, a in enumerate(tableaux.DOP853_A_EXTRA)]
_D8.c_extra = tableaux.DOP853_C_EXTRA.copy()
_DP5.kernel_args = ("dopri5", tableaux.DOPRI5.A, _DP5.b, _DP5.c, 6, [_DP5.E])
_D8.kernel_args = ("dop853", tableaux.DOP853.A, _D8.b, _D8.c, 12, [_D8.E5, _D8.E3])
_KERNELS = {}


def _kernel(pair, n, norm=False):
    """The plain-float step of `pair` for `n` equations (generated once, then cached)."""
    key = (pair.name, n, norm)
    if key not in _KERNELS:
        _KERNELS[key] = make_unrolled_stepper(*pair.kernel_args, n, norm=norm)
    return _KERNELS[key]


def _use_float_path(shape, fun, t0, y0):
    """The plain-float kernel serves one small trajectory whose `fun` returns an ndarray."""
    if len(shape) != 1 or shape[0] > FLOAT_PATH_MAX_N:
        return False, None
    f0 = fun(t0, y0.copy())
    ok = type(f0) is np.ndarray and f0.shape == shape and f0.dtype == np.float64
    return ok, (f0.copy() if ok else f0)  # `fun` may return the same buffer at every call


def _next_step(err, h_abs, err_old, rejected, exponent, pi, pi_alpha, pi_beta):
    """The step-size controller of both paths: ``(h_abs, err_old, accepted)`` after an attempt
    with error norm `err` (accepted if ``err < 1``; nan or inf shrink as much as allowed)."""
    if err < 1.0:
        if err == 0.0:
            factor = MAX_FACTOR
        elif pi:
            factor = min(MAX_FACTOR, SAFETY * err**pi_alpha * err_old**pi_beta)
        else:
            factor = min(MAX_FACTOR, SAFETY * err**exponent)
        if rejected:
            factor = min(1.0, factor)
        if pi:
            err_old = max(err, PI_ERR_FLOOR)
        return h_abs * factor, err_old, True
    if math.isfinite(err):
        return h_abs * max(MIN_FACTOR, SAFETY * err**exponent), err_old, False
    return h_abs * MIN_FACTOR, err_old, False


def _integrate(pair, fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps,
               dense_output, events, nstiff, f0=None, step_control="i"):
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
    if f0 is None:
        prob(t0, y, K[0])
    else:  # already evaluated by the dispatcher
        prob.nfev += 1
        K[0] = f0
    if not np.isfinite(K[0]).all():
        rec.fail("The right-hand side is not finite", t0, y)
        return rec.result(pair.name, prob.nfev, 0)
    if first_step is None:
        h_abs = initial_step(prob, t0, y, K[0], direction, pair.order_est, rtol, atol, t_end,
                             max_step)
    else:
        h_abs = first_step
    c, exponent = pair.c, pair.exponent
    pi, pi_alpha, pi_beta, err_old = _pi_constants(pair, step_control)
    Amat = pair.Ab  # stage matrix with the weights b as its last row
    E53 = pair.E53 if is853 else None
    dot = np.dot
    flat = not prob.batch  # single trajectory: call fun directly, copy its output into K
    nfev = 0
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
            hA = h * Amat  # one product for all the stages of this attempt
            for i in range(1, s):
                ys = dot(hA[i, :i], K[:i])
                ys += y
                if flat:
                    K[i] = fun(t + c[i] * h, ys)
                else:
                    prob(t + c[i] * h, ys, K[i])
            y_new = dot(hA[s, :s], K[:s])
            y_new += y
            if flat:
                K[s] = fun(t_new, y_new)
            else:
                prob(t_new, y_new, K[s])
            if flat:
                nfev += s
            scale = np.abs(y)
            np.maximum(scale, np.abs(y_new), out=scale)
            scale *= rtol
            scale += atol
            if is853:
                e53 = dot(E53, K[:13])
                e53 /= scale
                if prob.batch:
                    sq = (e53 * e53).reshape((2,) + shape).sum(axis=1)
                    s5, s3 = sq[0], sq[1]
                    den = s5 + 0.01 * s3
                    with np.errstate(invalid="ignore", divide="ignore"):
                        e = np.where(den > 0, h_abs * s5 / np.sqrt(den * n), 0.0)
                    err = float(np.max(e))
                else:
                    s5, s3 = np.einsum("ij,ij->i", e53, e53).tolist()
                    den = s5 + 0.01 * s3
                    err = h_abs * s5 / math.sqrt(den * N) if den > 0 else (
                        0.0 if den == 0 else den)
            else:
                e = dot(pair.E, K[: s + 1])
                e /= scale
                err = h_abs * prob.norm(e)
            h_abs, err_old, accepted = _next_step(err, h_abs, err_old, rejected, exponent, pi,
                                                  pi_alpha, pi_beta)
            if accepted:
                break
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
                iasti, nonsti, warned = _stiffness_test(pair, hlamb, t_new, iasti, nonsti,
                                                        warned)
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
    return rec.result(pair.name, prob.nfev + nfev, nrej)


def _integrate_float(pair, fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps,
                     dense_output, events, nstiff, f0, step_control="i"):
    """The same algorithm as :func:`_integrate` on lists of floats (one small trajectory)."""
    t0, t_end = t_span
    direction = 1.0 if t_end > t0 else -1.0
    shape = y0.shape
    N = shape[0]
    prob = Problem(fun, shape)
    prob.nfev = 1
    is853 = pair.name == "dop853"
    rec = Recorder(t0, y0.reshape(-1), shape, dense_output, events,
                   "nested" if is853 else "power")
    if not np.isfinite(f0).all():
        rec.fail("The right-hand side is not finite", t0, y0)
        return rec.result(pair.name, prob.nfev, 0)
    if first_step is None:
        h_abs = initial_step(prob, t0, y0, f0, direction, pair.order_est, rtol, atol, t_end,
                             max_step)
    else:
        h_abs = first_step
    atols = list(np.broadcast_to(np.asarray(atol, dtype=float), (N,)).tolist())
    y = y0.tolist()
    k0 = f0.tolist()
    kernel = _kernel(pair, N, norm=True)  # returns the weighted sums of squares
    exponent = pair.exponent
    pi, pi_alpha, pi_beta, err_old = _pi_constants(pair, step_control)
    want = rec.cs is not None or events is not None
    isfinite = math.isfinite
    sqrt = math.sqrt
    t = t0
    nrej = naccpt = iasti = nonsti = 0
    nfev = 1
    warned = False
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
            if not h_abs >= min_step:
                break
            h = h_abs * direction
            t_new = t + h
            if direction * (t_new - t_end) > 0:
                t_new = t_end
            h = t_new - t
            h_abs = abs(h)
            out = kernel(fun, t, y, k0, h, rtol, atols)
            nfev += pair.s
            y_new = out[0]
            if is853:
                s5 = out[3]
                den = s5 + 0.01 * out[4]
                err = h_abs * s5 / sqrt(den * N) if den > 0 else (0.0 if den == 0 else den)
            else:
                err = h_abs * sqrt(out[3] / N)
            h_abs, err_old, accepted = _next_step(err, h_abs, err_old, rejected, exponent, pi,
                                                  pi_alpha, pi_beta)
            if accepted:
                break
            rejected = True
            nrej += 1
        if not accepted:
            rec.fail("The step size fell below the resolution of t (step size underflow)",
                     t, y)
            break
        if not isfinite(sum(y_new)):
            rec.fail("The state became non-finite", t_new, y_new)
            break
        naccpt += 1
        ks = out[1]
        if nstiff and (naccpt % nstiff == 0 or iasti > 0):
            ys = out[2]
            den = sum((a - b_) ** 2 for a, b_ in zip(y_new, ys, strict=True))
            if den > 0:
                num = sum((a - b_) ** 2 for a, b_ in zip(ks[-1], ks[-2], strict=True))
                hlamb = h_abs * sqrt(num / den)
                iasti, nonsti, warned = _stiffness_test(pair, hlamb, t_new, iasti, nonsti,
                                                        warned)
        if want:
            ya, yna = np.array(y), np.array(y_new)
            if is853:
                K = np.empty((16, N))
                K[:13] = ks
                coeffs = _dense_dop853(pair, prob, t, ya, yna, h, K)
            else:
                coeffs = (h * pair.P) @ np.array(ks)
            stop = rec.accept(t_new, yna, coeffs)
        else:
            stop = rec.accept(t_new, y_new)
        t = t_new
        y = y_new
        k0 = ks[-1]
        if stop:
            break
    return rec.result(pair.name, nfev + prob.nfev - 1, nrej)


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


def _pi_constants(pair, step_control):
    """``(pi, alpha, beta, err_old)``: exponents of the PI controller, or unused values."""
    k = pair.order_est + 1
    return step_control == "pi", -PI_KI / k, PI_KP / k, 1.0


def _check_step_control(step_control):
    if not isinstance(step_control, str) or step_control not in STEP_CONTROLS:
        raise ArgumentError(
            f"`step_control` must be one of {STEP_CONTROLS} (\"i\": the integral controller of "
            f"scipy and Hairer's codes, \"pi\": Gustafsson's PI controller); got "
            f"{step_control!r}."
        )
    return step_control


def _check_nstiff(nstiff):
    if isinstance(nstiff, bool) or not isinstance(nstiff, int | np.integer) or nstiff < 0:
        raise ArgumentError(f"`nstiff` must be an int >= 0 (0 disables the test); got {nstiff!r}.")
    return int(nstiff)


def dopri5(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
           max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None,
           nstiff=1000, step_control="i"):
    """Dormand-Prince 5(4) with error control, dense output and stiffness detection.

    Called through :func:`rigidmech.ode.solve` (``method="dopri5"`` or ``"rk45"``), which
    validates the arguments; see its parameters. `nstiff` (int, default 1000) sets how often
    the stiffness test runs; 0 disables it. `step_control` is ``"i"`` (default: the integral
    controller of scipy and Hairer's codes) or ``"pi"`` (Gustafsson's PI controller).

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
    step_control = _check_step_control(step_control)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        ok, f0 = _use_float_path(y0.shape, fun, t_span[0], y0)
        run = _integrate_float if ok else _integrate
        return run(_DP5, fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                   max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                   events=events, nstiff=nstiff, f0=f0, step_control=step_control)


def dop853(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
           max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None,
           nstiff=1000, step_control="i"):
    """Dormand-Prince 8(5,3) (Hairer's DOP853) with error control, 7th-order dense output and
    stiffness detection.

    Called through :func:`rigidmech.ode.solve` (``method="dop853"``, the default), which
    validates the arguments; see its parameters. `nstiff` and `step_control` as in
    :func:`dopri5`.

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
    >>> r = ode.solve(osc, (0.0, 20.0), [1.0, 0.0], rtol=1e-12, atol=1e-14, step_control="pi")
    >>> bool(abs(r.y[0, -1] - np.cos(20.0)) < 1e-11)
    True
    """
    nstiff = _check_nstiff(nstiff)
    step_control = _check_step_control(step_control)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        ok, f0 = _use_float_path(y0.shape, fun, t_span[0], y0)
        run = _integrate_float if ok else _integrate
        return run(_D8, fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                   max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                   events=events, nstiff=nstiff, f0=f0, step_control=step_control)


_registry.register("dopri5", dopri5, kind="adaptive")
_registry.register("rk45", dopri5, kind="adaptive")
_registry.register("dop853", dop853, kind="adaptive")
