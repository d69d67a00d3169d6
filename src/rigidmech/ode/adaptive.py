"""Adaptive embedded Runge-Kutta pairs: Dormand-Prince 5(4), DOP853, Bogacki-Shampine 3(2)
(book, ch. 26.2).

Each pair is data (:class:`ExplicitPair`: tableau, error weights, dense output,
:class:`~rigidmech.ode._loop.Capabilities`) run by one of two steppers (plain floats for one
small trajectory, numpy otherwise) through the one loop of :mod:`rigidmech.ode._loop`.

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

Batches: with ``y0`` of shape ``(n, batch)``, the option ``stepping`` chooses how the steps
are chosen across the batch: ``"each"``, a step size, error norm and accept/reject per
trajectory, the stages of the trajectories still running evaluated in one call
(:mod:`rigidmech.ode._ensemble`); ``"shared"``, every trajectory advanced with the same step,
chosen from the largest error norm over the batch (the steps are the output, dense output and
projection available); ``"auto"`` (default), ``"each"`` for a batch sampled at ``t_eval``
without dense output or projection, else ``"shared"``. Measured on 1,000 double pendulums
(``benchmarks/ensemble.py``), per-trajectory steps are the faster on both a regular and a
chaotic ensemble; the measurement is in the performance pages (runs).
"""

from __future__ import annotations

import math

import numpy as np

from rigidmech._core.errors import ArgumentError

from . import _registry, tableaux
from ._ensemble import choose_stepping, integrate_each
from ._floatpath import FLOAT_PATH_MAX_N, error_norm, make_pair_step
from ._loop import (
    MAX_FACTOR,
    MIN_FACTOR,
    PI_ERR_FLOOR,
    PI_KI,
    PI_KP,
    PROJECT,
    SAFETY,
    Capabilities,
    Run,
    StepResult,
    check_progress,
    integrate,
)

__all__ = ["dopri5", "dop853", "bs32", "ExplicitPair", "PAIRS"]

_new = tuple.__new__  # a StepResult without the call of its generated __new__

#: Kept here for the code and the tests that read them from this module.
CONTROL_CONSTANTS = (SAFETY, MIN_FACTOR, MAX_FACTOR, PI_KI, PI_KP, PI_ERR_FLOOR)
STEP_CONTROLS = ("i", "pi")


class ExplicitPair:
    """An embedded explicit Runge-Kutta pair as data: its tableau, error weights, dense output
    and capabilities. Everything else (the loop, the controllers, the kernels) is shared.

    Parameters
    ----------
    capabilities : Capabilities
    tableau : ButcherTableau
        With the FSAL stage ``f(t + h, y1)`` as its last stage when `fsal` is True.
    errors : sequence of ndarray
        Error weight vectors over the stages and the FSAL stage; one vector: Hairer's RMS norm
        of ``h sum e_i k_i``; two (``E5``, ``E3``): DOP853's combined estimate.
    fsal : bool
        Whether the tableau's last stage is the evaluation at ``(t + h, y1)``.
    dense : callable
        ``dense(pair, prob, t, y, y_new, h, K) -> coefficients`` (or a lazy callable).

    Examples
    --------
    >>> BS32.capabilities.order, BS32.s
    (3, 3)
    """

    def __init__(self, capabilities, tableau, errors, *, fsal, dense):
        self.capabilities = capabilities
        self.name = capabilities.name
        self.s = tableau.stages - 1 if fsal else tableau.stages  # stages before f(t+h, y1)
        self.c = tableau.c[: self.s].copy()
        self.b = tableau.b[: self.s].copy()
        self.Ab = np.zeros((self.s + 1, self.s))
        self.Ab[: self.s] = tableau.A[: self.s, : self.s]
        self.Ab[self.s] = self.b
        self.A = tableau.A
        self.errors = [np.asarray(e, dtype=float) for e in errors]
        self.E = np.stack(self.errors)
        self.dense = dense
        #: ``error_norm(h_abs, s0, s1, n)``: the norm the generated steps compute inline
        self.error_norm = error_norm(len(self.errors))

    def kernel(self, n):
        """The plain-float step for `n` equations, ``bind(fun, rtol, atols) -> step`` (generated
        once by the shared generator)."""
        return make_pair_step(self.name, self.A, self.b, self.c, self.s, self.errors, n)


class _FloatStepper:
    """A pair on lists of plain floats (one small trajectory): its attempt is the generated
    step itself, bound to `fun` and the tolerances (:func:`make_pair_step`)."""

    def __init__(self, pair, fun, n, rtol, atol):
        self.pair, self.n = pair, n
        self.capabilities = pair.capabilities
        self.start_order = pair.capabilities.error_order
        atols = list(np.broadcast_to(np.asarray(atol, dtype=float), (n,)).tolist())
        self.attempt = pair.kernel(n)(fun, rtol, atols)
        self.nfev_per_attempt = pair.s
        self.nfev = 0

    def begin(self, prob, t0, y0, f0):
        self.prob = prob
        return y0.tolist(), f0.tolist()

    def stats(self):
        return {}

    def hlamb(self, h_abs, step):
        ks, ys = step.data
        den = sum((a - b_) ** 2 for a, b_ in zip(step.y, ys, strict=True))
        if den > 0:
            num = sum((a - b_) ** 2 for a, b_ in zip(ks[-1], ks[-2], strict=True))
            return h_abs * math.sqrt(num / den)
        return None

    def dense(self, t, y, h, step):
        ya, yna = np.array(y), np.array(step.y)
        return yna, self.pair.dense(self.pair, self.prob, t, ya, yna, h,
                                    np.array(step.data[0])), None


class _ArrayStepper:
    """A pair on flat ndarrays (batches, larger systems): numpy products over the stages."""

    def __init__(self, pair, fun, shape, rtol, atol):
        self.pair, self.fun, self.shape, self.rtol, self.atol = pair, fun, shape, rtol, atol
        self.capabilities = pair.capabilities
        self.n = shape[0]
        self.nfev = 0

    def begin(self, prob, t0, y0, f0):
        self.prob = prob
        self.flat = not prob.batch  # single trajectory: call fun directly, copy into K
        self.K = np.empty((max(16, self.pair.s + 1), y0.size))
        self.K[0] = f0
        self.start_order = self.capabilities.error_order
        self.nfev_per_attempt = 0
        return y0, None

    def finite(self, step):
        return bool(np.isfinite(step.y).all())

    def stats(self):
        return {}

    def attempt(self, t, y, f, h):
        """One attempt; `f` is unused: the derivative at `y` is kept in ``K[0]``."""
        pair, K, s = self.pair, self.K, self.pair.s
        dot, fun, prob, flat, c = np.dot, self.fun, self.prob, self.flat, pair.c
        hA = h * pair.Ab  # one product for all the stages of this attempt
        ys = y
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
            K[s] = fun(t + h, y_new)
            self.nfev += s
        else:
            prob(t + h, y_new, K[s])
        scale = np.abs(y)
        np.maximum(scale, np.abs(y_new), out=scale)
        scale *= self.rtol
        scale += self.atol
        return StepResult(y_new, K[s], self._error(abs(h), K[: s + 1], scale), ys)

    def _error(self, h_abs, K, scale):
        errors = self.pair.errors
        if len(errors) == 1:  # Hairer's RMS norm (max over a batch)
            e = np.dot(errors[0], K)
            e /= scale
            return h_abs * self.prob.norm(e)
        e53 = np.dot(self.pair.E, K)  # DOP853: the 5th- and 3rd-order estimates combined
        e53 /= scale
        if not self.prob.batch:
            s5, s3 = np.einsum("ij,ij->i", e53, e53).tolist()
            return self.pair.error_norm(h_abs, s5, s3, e53.shape[1])
        s5, s3 = (e53 * e53).reshape((2,) + self.shape).sum(axis=1)
        return batch_error_norm(h_abs, s5, s3, self.n)

    def accept(self, step):
        self.K[0] = self.K[self.pair.s]

    def hlamb(self, h_abs, step):
        d_y = step.y - step.data
        den = float(np.dot(d_y, d_y))
        if den > 0:
            d = self.K[self.pair.s] - self.K[self.pair.s - 1]
            return h_abs * math.sqrt(float(np.dot(d, d)) / den)
        return None

    def dense(self, t, y, h, step):
        return step.y, self.pair.dense(self.pair, self.prob, t, y, step.y, h, self.K), None


def batch_error_norm(h_abs, s5, s3, n):
    """DOP853's error norm (:data:`~rigidmech.ode._floatpath.ERROR_NORM_LINES`) member by
    member over a batch, the largest (nan if one is): its array form, tested equal to it.

    Examples
    --------
    >>> float(batch_error_norm(0.5, np.array([4.0, 0.0]), np.array([0.0, 0.0]), 1))
    1.0
    """
    den = s5 + 0.01 * s3
    with np.errstate(invalid="ignore", divide="ignore"):
        err = np.where(den > 0, h_abs * s5 / np.sqrt(den * n), np.where(den == 0, 0.0, den))
    return float(np.max(err))


def _dense_shampine(pair, prob, t, y, y_new, h, K):
    """Shampine's 4th-order interpolant of DOPRI5 (free: it reuses the stages)."""
    return (h * _DP5_P) @ K[: pair.s + 1]


def _dense_hermite(pair, prob, t, y, y_new, h, K):
    """The cubic Hermite interpolant through ``y, f`` at both ends (free with FSAL)."""
    f0, f1 = K[0], K[pair.s]
    dy = y_new - y
    return np.stack([h * f0, 3.0 * dy - 2.0 * h * f0 - h * f1, h * f0 + h * f1 - 2.0 * dy])


def _dense_dop853(pair, prob, t, y, y_new, h, K):
    """DOP853's interpolation coefficients, computed lazily (3 more evaluations of f)."""
    Kc = np.empty((16, y.size))
    Kc[:13] = K[:13]

    def coeffs():
        for j, (a, cj) in enumerate(zip(_D853_A_EXTRA, tableaux.DOP853_C_EXTRA, strict=True)):
            prob(t + cj * h, y + (h * a) @ Kc[: 13 + j], Kc[13 + j])
        F = np.empty((7, y.size))
        dy = y_new - y
        F[0] = dy
        F[1] = h * Kc[0] - dy
        F[2] = 2.0 * dy - h * (Kc[12] + Kc[0])
        F[3:] = h * (tableaux.DOP853_D @ Kc)
        return F

    return coeffs


_DP5_P = tableaux.DOPRI5_P.T.copy()  # (4, 7)
_D853_A_EXTRA = [np.ascontiguousarray(a[: 13 + i])
                 for i, a in enumerate(tableaux.DOP853_A_EXTRA)]

DOPRI5 = ExplicitPair(
    Capabilities("dopri5", error_order=4, order=5, stiff_border=3.25, dense_order=4),
    tableaux.DOPRI5, [tableaux.DOPRI5_E], fsal=True, dense=_dense_shampine)
DOP853 = ExplicitPair(
    Capabilities("dop853", error_order=7, order=8, stiff_border=6.1, dense_form="nested",
                 dense_order=7),
    tableaux.DOP853, [tableaux.DOP853_E5, tableaux.DOP853_E3], fsal=False,
    dense=_dense_dop853)
#: Bogacki-Shampine 3(2), FSAL (the proof of the protocol: coefficients and capabilities
#: only). Its last two stages do not share a time: no stiffness test.
BS32 = ExplicitPair(
    Capabilities("bs32", error_order=2, order=3, dense_order=3),
    tableaux.BS32, [tableaux.BS32_E], fsal=True, dense=_dense_hermite)
#: The pairs, by name.
PAIRS = {p.name: p for p in (DOPRI5, DOP853, BS32)}


def _stepper(pair, fun, t0, y0, rtol, atol):
    """The plain-float stepper for one small trajectory whose `fun` returns a float64
    ndarray, else the numpy stepper; and ``f(t0, y0)`` when it was evaluated to decide."""
    shape = y0.shape
    if len(shape) != 1 or shape[0] > FLOAT_PATH_MAX_N:
        return _ArrayStepper(pair, fun, shape, rtol, atol), None
    f0 = fun(t0, y0.copy())
    if type(f0) is np.ndarray and f0.shape == shape and f0.dtype == np.float64:
        return _FloatStepper(pair, fun, shape[0], rtol, atol), f0.copy()  # fun may reuse it
    return _ArrayStepper(pair, fun, shape, rtol, atol), f0


def _solve_pair(pair, fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps,
                dense_output, events, nstiff, step_control, progress, t_eval, stepping):
    nstiff = _check_nstiff(nstiff)
    step_control = _check_step_control(step_control)
    progress = check_progress(progress)
    box = PROJECT.get()
    if choose_stepping(stepping, batch=y0.ndim == 2, t_eval=t_eval,
                          dense_output=dense_output, events=events,
                          project=None if box is None else box[0]) == "each":
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            return integrate_each(pair, fun, t_span, y0, rtol=rtol, atol=atol,
                                  first_step=first_step, max_step=max_step,
                                  max_steps=max_steps, step_control=step_control,
                                  progress=progress, t_eval=t_eval)
    run = Run(fun, t_span, y0, rtol, atol, first_step, max_step, max_steps, dense_output,
              events, nstiff, step_control, progress, None, t_eval)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        stepper, f0 = _stepper(pair, fun, t_span[0], y0, rtol, atol)
        return integrate(stepper, run, f0)


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
           nstiff=1000, step_control="i", progress=None, t_eval=None,
         stepping="auto"):
    """Dormand-Prince 5(4) with error control, dense output and stiffness detection.

    Called through :func:`rigidmech.ode.solve` (``method="dopri5"`` or ``"rk45"``), which
    validates the arguments; see its parameters. `nstiff` (int, default 1000) sets how often
    the stiffness test runs; 0 disables it. `step_control` is ``"i"`` (default: the integral
    controller of scipy and Hairer's codes) or ``"pi"`` (Gustafsson's PI controller).
    `progress` (callable ``progress(t)``, optional) is called after every accepted step; the
    run stops, with status 2 and the steps made so far, when it returns False (Ctrl-C does
    the same).

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
    return _solve_pair(DOPRI5, fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                       max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                       events=events, nstiff=nstiff, step_control=step_control,
                       progress=progress, t_eval=t_eval, stepping=stepping)


def dop853(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
           max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None,
           nstiff=1000, step_control="i", progress=None, t_eval=None,
         stepping="auto"):
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
    return _solve_pair(DOP853, fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                       max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                       events=events, nstiff=nstiff, step_control=step_control,
                       progress=progress, t_eval=t_eval, stepping=stepping)


def bs32(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
         max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None,
         nstiff=1000, step_control="i", progress=None, t_eval=None,
         stepping="auto"):
    """Bogacki-Shampine 3(2) with error control and cubic Hermite dense output.

    Called through :func:`rigidmech.ode.solve` (``method="bs32"``, scipy's ``RK23``): four
    stages with FSAL (three evaluations a step), order 3 propagated, order 2 for the error
    estimate (P. Bogacki, L. F. Shampine, *A 3(2) pair of Runge-Kutta formulas*, Appl. Math.
    Lett. 2 (1989) 321-325). Cheap per step, for loose tolerances. The dense output is the
    cubic Hermite interpolant (order 3, that of the method, free with FSAL). The method is
    only its coefficients and capabilities (:data:`BS32`) on the shared loop; `nstiff` is
    accepted for uniformity (no stiffness test: its last stages do not share a time).

    Returns
    -------
    OdeResult

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> r = ode.solve(lambda t, y: -y, (0.0, 2.0), [1.0], method="bs32", rtol=1e-8)
    >>> bool(abs(r.y[0, -1] - np.exp(-2.0)) < 1e-7), r.status
    (True, 0)
    """
    return _solve_pair(BS32, fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                       max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                       events=events, nstiff=nstiff, step_control=step_control,
                       progress=progress, t_eval=t_eval, stepping=stepping)


_registry.register("bs32", bs32, kind="adaptive", capabilities=("t_eval",))
_registry.register("dopri5", dopri5, kind="adaptive", capabilities=("t_eval",))
_registry.alias("rk45", "dopri5")
_registry.register("dop853", dop853, kind="adaptive", capabilities=("t_eval",))
