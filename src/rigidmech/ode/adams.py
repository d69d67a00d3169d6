r"""Adaptive Adams method: variable order and step, on Newton's backward differences (26.3).

The book builds the multistep methods (26.3.2) on Newton's backward-difference interpolation
polynomial of :math:`f` through equally spaced points; :mod:`~rigidmech.ode.multistep` uses them
with a fixed step and order. This module makes them a general-purpose integrator,
``method="adams"``, in the manner of Shampine and Gordon's code DE/STEP (*Computer Solution of
Ordinary Differential Equations*, 1975) but with the step changed by *re-interpolation*
instead of variable-coefficient formulas:

* **Step.** A predictor-corrector pair in PECE mode (predict, evaluate, correct, evaluate),
  two evaluations of :math:`f` per step. With the backward differences
  :math:`\nabla^j f_n` (:math:`j = 0, \dots, k`) the predictor is Adams-Bashforth of order
  :math:`k`,

  .. math:: p = y_n + h\sum_{j=0}^{k-1}\gamma_j\nabla^j f_n ,

  and the corrector adds the next term with the predicted :math:`f(t_{n+1}, p)`:
  :math:`y_{n+1} = p + h\gamma_k\,\nabla^k f^{p}_{n+1}` (Adams-Moulton of order :math:`k+1`,
  local extrapolation). The local error of order :math:`k` is estimated by
  :math:`h(\gamma_{k-1}-\gamma_k)\|\nabla^k f^p_{n+1}\|` and must stay below 1 in the
  weighted RMS norm of :mod:`~rigidmech.ode.adaptive` (weights ``atol + rtol |y_n|``).
* **Order** :math:`k = 1, \dots, 12`, chosen from the estimates the differences give at orders
  :math:`k-2, k-1, k, k+1` (the rules of DE/STEP): the integration starts at order 1 and, in its
  first phase, raises the order and doubles the step at every step.
* **Step size.** Kept constant as long as possible, which keeps the formulas' coefficients
  constant (the book's equal spacing): doubled when the estimate is 2^(k+1) times below the
  tolerance, reduced by a factor 0.5-0.9 (rounded down to tenths) when the estimate exceeds
  half of it, halved on a rejected step. A change computes the differences at the new spacing
  from the *known* values of :math:`f`: exactly (every other value, or Newton's polynomial
  re-sampled, :func:`resample_matrix`) when the last values are equally spaced, else by
  Lagrange interpolation through the past values nearest to the new grid, at their true
  times (:func:`_reinterpolation_matrix`, cached by pattern). Shampine and Gordon reach the
  same end with variable-coefficient formulas at every step after a change; here the step
  itself keeps constant coefficients and the cost falls on the change alone. Only at the
  start, before the values reach back over the new span, is a doubling made by extrapolating
  the polynomial backwards, and only up to order 4; above it the doubling waits. (Measured:
  re-sampling the previous differences at every change, as a first version did, took 20-35 %
  more evaluations at the same errors on the reference problems.)
* **Dense output** is the integral of the same interpolation polynomial over the step, adjusted
  by a linear term so that it passes exactly through both ends of the step.

Why not only Runge-Kutta: on smooth problems an Adams code of high order needs far fewer
evaluations of :math:`f` than a Runge-Kutta pair at tight tolerances (two per step instead of
twelve for DOP853); that is how LSODA, whose non-stiff half is such a code, beats DOP853 on the
damped forced oscillator (``benchmarks/work_precision.py``). For one small trajectory the
integration goes by *runs*: one generated plain-float function per system size, every order
unrolled in it, which takes steps at constant spacing and changes the order itself, and
returns to the driver only when the spacing must change (re-sampling, doubling), at a
rejection or before the last step (as in :mod:`~rigidmech.ode._floatpath`); batches and larger
systems use numpy arrays with the same algorithm, a step at a time. Measured on the damped
oscillator: about half of LSODA's evaluations at equal error, about 3.5 us of Python per
evaluation (LSODA 3.9 us, ``dop853`` 2 us), of which 1.4 us are the call of ``fun`` and its
ndarray round trip (docs, performance page). That Python cost grows with the number of
equations, about 1.4 us per equation and evaluation at order 10 (``dop853``: about 0.2 us), so
the method pays where ``fun`` costs more than that and the motion is smooth: on rigidmech's
4-link pendulum (8 equations, 15 us a call, regular motion) it needs a third fewer
evaluations than ``dop853`` at errors of 1e-10 and is the cheapest there; on a chaotic
release of the same chain ``dop853`` is cheaper at every level (``benchmarks/costly_rhs.py``).

Batches: with ``y0`` of shape ``(n, batch)`` every trajectory advances with the same step and
order, chosen from the largest error estimates over the batch.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from numpy.exceptions import ComplexWarning

from rigidmech._core.errors import ArgumentError

from . import _registry
from ._adams_run import (
    RUN_DECIDE,
    RUN_NONFINITE,
    RUN_REJECTED,
    _array_run,
    _float_run,
    _lower_order,
    _next_order,
    _next_ratio,
)
from ._adams_tables import (  # noqa: F401  (the tables the tests read stay importable here)
    _DELTA,
    _G,
    _GS,
    _PECE_REAL_INTERVAL,
    _REINTERP,
    _STIFF_BORDER,
    HISTORY,
    RESAMPLE_DOUBLING_MAX_ORDER,
    STIFF_MAX_ORDER,
    STIFF_MIN_ESTIMATE,
    _lazy_dense,
    _reinterpolation_matrix,
    _resample_cached,
    resample_matrix,
)
from ._adams_tables import MAX_ORDER as _MAX_ORDER
from ._driver import Recorder, SampleRecorder, flat_tolerance
from ._floatpath import FLOAT_PATH_MAX_N
from ._loop import _complex_failure, _probe, check_progress, underflow_failure
from ._warnings import stiffness_count
from .adaptive import _check_nstiff

__all__ = ["adams", "resample_matrix", "MAX_ORDER"]

#: Highest order of the Adams formulas used (as in DE/STEP: beyond it the stability region of
#: the PECE pair becomes too small to gain anything). The tables (``_adams_tables``), the steps
#: and the rules of order and step (``_adams_run``) and this driver are split by concern.
MAX_ORDER = _MAX_ORDER


# --- the driver ----------------------------------------------------------------------------


def _check_max_order(max_order):
    if isinstance(max_order, bool) or not isinstance(max_order, int | np.integer) or not (
        1 <= max_order <= MAX_ORDER
    ):
        raise ArgumentError(
            f"`max_order` must be an int in 1..{MAX_ORDER}; got {max_order!r}."
        )
    return int(max_order)



def adams(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
          max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None,
          max_order=MAX_ORDER, nstiff=1000, progress=None, t_eval=None):
    r"""Adaptive Adams-Bashforth-Moulton (PECE), variable order 1-12 and step, dense output.

    Called through :func:`rigidmech.ode.solve` (``method="adams"``), which validates the
    arguments; see its parameters. `max_order` (int, 1..12, default 12) caps the order.
    `nstiff` (int, default 1000, as for ``"dop853"``): 0 switches the stiffness test off; any
    other value keeps it on (it runs whenever the step size is about to change, not every
    `nstiff` steps: at a constant step size the Adams code does not look back).
    With `t_eval` (passed by :func:`~rigidmech.ode.solve`) the samples are evaluated on each
    step's dense polynomial as the steps pass and only they are kept (memory proportional to
    the samples); the steps are those of a run with dense output.

    Returns
    -------
    OdeResult
        ``stats`` holds ``"order_changes"``, ``"step_changes"`` (re-interpolations) and
        ``"max_order_used"``.

    Notes
    -----
    See the module docstring for the algorithm.

    Stiffness test: a PECE step evaluates :math:`f` at the predicted and at the corrected
    values, :math:`h\gamma_k e` apart, so :math:`h\rho = \|\Delta f\| / (\gamma_k\|e\|)`
    estimates the step times the local Lipschitz constant. A stiff problem holds the step at
    the border of stability and the order low: a check counts as stiff when the order is at
    most ``STIFF_MAX_ORDER`` (4) and :math:`h\rho` exceeds 0.8 times the real stability
    interval of that order's PECE pair (2, 2.4, 1.94, 1.41 for orders 1-4). Checks are made
    where the step size may change, after the first phase, on steps whose error estimate is
    at least ``STIFF_MIN_ESTIMATE`` (1e-3) of the tolerance (below, :math:`e` is mostly
    rounding). 15 stiff checks (6 others in a row reset the count, as in Hairer's test) raise a
    :class:`~rigidmech.ode.StiffnessWarning`. Measured on Van der Pol (mu = 1000), Robertson's
    kinetics and a stiff linear equation: the warning comes after 20-160 checks at rtol 1e-3
    to 1e-12; never on the reference problems of :mod:`~rigidmech.testing.problems`.

    The first step is Shampine and Gordon's
    ``0.25 / sqrt(||f(t0, y0)||)`` (weighted norm), bounded by the interval, `max_step` and
    `first_step`; the first phase then doubles it at every step while raising the order.

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> osc = lambda t, y: np.array([y[1], -y[0]])
    >>> r = ode.solve(osc, (0.0, 20.0), [1.0, 0.0], method="adams", rtol=1e-12, atol=1e-14)
    >>> bool(abs(r.y[0, -1] - np.cos(20.0)) < 1e-10), r.status
    (True, 0)
    """
    max_order = _check_max_order(max_order)
    nstiff = _check_nstiff(nstiff)
    progress = check_progress(progress)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        return _integrate(fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                          max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                          events=events, max_order=max_order, nstiff=nstiff,
                          progress=progress, t_eval=t_eval)



def _start(fun, t_span, y0, rtol, atol, first_step, max_step, dense_output, events, t_eval):
    """The first evaluation, the recorder and the first step (Shampine and Gordon's
    ``0.25 / sqrt(||f0||)`` when the interval is longer): the settings of an :class:`_Run`,
    or the failed result if ``f(t0, y0)`` is not finite."""
    t0, t_end = (float(v) for v in t_span)
    shape, y = y0.shape, y0.reshape(-1).astype(float)
    f_raw = fun(t0, y.reshape(shape).copy())
    floats = (len(shape) == 1 and y.size <= FLOAT_PATH_MAX_N and type(f_raw) is np.ndarray
              and f_raw.shape == shape and f_raw.dtype == np.float64)
    f0 = np.array(f_raw, dtype=float).reshape(-1)
    if t_eval is not None and not dense_output:  # keep the samples only
        rec = SampleRecorder(t0, y, shape, events, t_eval, "power")
    else:
        rec = Recorder(t0, y, shape, dense_output, events, "power")
    if not np.isfinite(f0).all():
        rec.fail("The right-hand side is not finite", t0, y)
        return rec.result("adams", 1, 0)
    atol_arr = flat_tolerance(atol, shape)
    norm, call = _norm_and_call(fun, shape)
    s0 = norm(f0 / (atol_arr + rtol * np.abs(y)))
    h_abs = abs(t_end - t0) if first_step is None else float(first_step)
    if first_step is None and 16.0 * s0 * h_abs * h_abs > 1.0:
        h_abs = 0.25 / math.sqrt(s0)
    h = (1.0 if t_end > t0 else -1.0) * min(h_abs, max_step, abs(t_end - t0))
    return rec, (t0, t_end, y, f0, h, floats, atol_arr, norm, call)


def _norm_and_call(fun, shape):
    """The weighted RMS norm (the largest over a batch) and ``fun`` on flat arrays."""
    N = math.prod(shape)
    if len(shape) == 2:
        def norm(v):
            v = v.reshape(shape)
            return float(np.sqrt(np.max(np.mean(v * v, axis=0))))

        def call(t, v):
            return np.array(fun(t, v.reshape(shape)), dtype=float).reshape(-1)
    else:
        def norm(v):
            return math.sqrt(float(np.dot(v, v)) / N)

        def call(t, v):
            return np.array(fun(t, v), dtype=float)
    return norm, call


class _Run:
    """The state of one adams integration, between the runs of steps (on an object so that
    an interruption finds it). The outer loop (:meth:`loop`) owns what every method's loop
    owns: the end of ``t_span`` (clamping the last step), `max_steps`, failures with the
    shared messages, recording (dense output, ``t_eval``, events, through the recorders of
    :mod:`~rigidmech.ode._driver`), ``progress`` and Ctrl-C (:func:`_integrate`); the runs
    (:func:`_float_run`, :func:`_array_run`) make the steps, :meth:`attempt` the rejections,
    :meth:`record` and :meth:`next_step` what follows an accepted step."""

    __slots__ = ("atol", "atols", "call", "D", "direction", "erk", "erkm1", "erkp1", "floats",
                 "fun", "h", "history", "hrho", "iasti", "k", "kmax_used", "knew", "max_order",
                 "max_step", "max_steps", "n_order", "n_resample", "naccpt", "nfev", "nonsti",
                 "norm", "nrej", "ns", "nstiff", "phase1", "progress", "rec", "rtol", "run",
                 "sampling", "steps_t", "t", "t_end", "ts_append", "want_dense", "warned", "y",
                 "ys_append", "N", "hist_append", "far")

    def __init__(self, fun, rec, start, rtol, max_step, max_steps, max_order, nstiff,
                 progress):
        t0, self.t_end, y, f0, self.h, self.floats, self.atol, self.norm, self.call = start
        self.fun, self.rec, self.rtol, self.max_step = fun, rec, rtol, max_step
        self.max_steps, self.max_order, self.nstiff, self.progress = (
            max_steps, max_order, nstiff, progress)
        self.N, self.t, self.k, self.ns, self.phase1 = y.size, t0, 1, 0, True
        self.direction = 1.0 if self.t_end > t0 else -1.0
        self.sampling = isinstance(rec, SampleRecorder)
        self.steps_t = [t0] if self.sampling else rec.ts  # times of the last steps (`change`)
        self.nfev, self.naccpt, self.nrej, self.n_order, self.n_resample = 1, 0, 0, 0, 0
        self.iasti = self.nonsti = 0
        self.warned = False
        self.kmax_used = 1
        # the differences D_0 .. D_{k+1} at spacing h (D_{k+1}: 0 if unknown), a flat list of
        # floats (plain-float path) or a (k + 2, N) array
        D = np.zeros((3, self.N))
        D[0] = f0
        self.y, self.D = (y.tolist(), D.reshape(-1).tolist()) if self.floats else (y, D)
        self.atols = self.atol.tolist()
        # values of f at the current spacing since its last change: doubling the step above
        # order RESAMPLE_DOUBLING_MAX_ORDER takes every other one (re-sampling would
        # extrapolate the polynomial backwards over twice its span, which amplifies its error
        # about 2**k times)
        self.history = [self.D[:self.N] if self.floats else f0]
        self.hist_append = self.history.append  # the list is trimmed in place, never replaced
        self.far = self.direction * math.inf
        self.want_dense = rec.needs_dense
        if self.want_dense:  # the loop records every step itself, through rec.accept
            self.ts_append = self.ys_append = _ignore
        else:  # the runs record their steps (the float path's lists are fresh, never modified)
            self.ts_append, self.ys_append = rec.ts.append, rec.ys.append
        self.run = _float_run(self.N) if self.floats else None

    def stats(self):
        return {"order_changes": self.n_order, "step_changes": self.n_resample,
                "max_order_used": self.kmax_used}

    def change(self, ratio):
        """Move the differences to the spacing ``ratio * h`` (k + 2 rows; D_{k+1} unknown:
        0), and h with them.

        Exact when the values of f they need are known: every other one of the last 2k + 1
        at constant spacing (doubling), Newton's polynomial of the differences re-sampled when
        the last k + 1 are at constant spacing (reduction), else Lagrange's polynomial through
        the known values nearest to the new grid (:func:`_reinterpolation_matrix`). Only in
        the first steps, when no known values reach back over the new span, is the polynomial
        of the differences extrapolated backwards.
        """
        k, N, h, history = self.k, self.N, self.h, self.history
        out = np.zeros((k + 2, N))
        m = min(len(history), HISTORY)
        T = self.steps_t[-m:]
        if ratio == 2.0 and self.ns >= 2 * k:
            vals = np.array(history[-1: -2 * k - 2: -2], dtype=float)  # f_n, f_{n-2}, ...
            out[: k + 1] = _DELTA[k] @ vals
        elif (ratio < 1.0 and self.ns >= k) or m < k + 1 or (
                abs(T[-1] - T[0]) < k * abs(ratio * h) * (1.0 - 1e-12)):
            rows = np.asarray(self.D, dtype=float).reshape(-1, N)
            out[: k + 1] = _resample_cached(k, ratio) @ rows[: k + 1]
        else:
            M, idx = _reinterpolation_matrix(T, k, ratio * h)
            out[: k + 1] = M @ np.asarray([history[i] for i in idx], dtype=float).reshape(
                k + 1, N)
        self.D = out.reshape(-1).tolist() if self.floats else out
        self.n_resample += 1
        self.h = h * ratio
        self.ns = 0

    def loop(self):
        """Runs of steps to the end of ``t_span``, or to a failure or a stop."""
        rec, direction, t_end, progress = self.rec, self.direction, self.t_end, self.progress
        while direction * (self.t - t_end) < 0:
            if self.naccpt >= self.max_steps:
                rec.fail(f"The maximum number of steps `max_steps` = {self.max_steps} was "
                         "reached", self.t, np.array(self.y))
                return
            single = self.phase1 or self.want_dense or progress is not None  # a step a run
            if direction * (self.t + self.h - t_end) >= 0:  # last step: end exactly at t_end
                if direction * (self.t + self.h - t_end) > 0:
                    self.change((t_end - self.t) / self.h)
                    self.h = t_end - self.t
                single = True
            code, y_old = self.attempt(single)
            if code is None:
                # probed over the last accepted step's length (the failing h has underflowed)
                ts = self.steps_t
                h = ts[-1] - ts[-2] if len(ts) >= 2 and ts[-1] != ts[-2] else self.h
                underflow_failure(rec, self.fun, self.t, self.y, h, rec.shape)
                return
            if code == RUN_NONFINITE:
                self.nfev += 2
                rec.fail("The state became non-finite", self.t, np.array(self.y))
                return
            if code == RUN_DECIDE and (self.nstiff or self.want_dense) and self.record(y_old):
                return
            if progress is not None and progress(self.t) is False:
                rec.interrupt("The integration was stopped by the `progress` callback", self.t)
                return
            if code == RUN_DECIDE:
                self.next_step()

    def attempt(self, single):
        """One run from the current state (plain floats or arrays), repeated on rejections
        (the step halved; from the third failure in a row on, at order 1). Returns ``(code,
        y_old)`` (`y_old`: the state before the last step, for the dense output); code None on
        a step size underflow."""
        tiny, y_old, ifail = _TINY, self.y, 0
        while True:
            h, t = self.h, self.t
            if abs(h) <= tiny * abs(t) or h == 0.0 or h != h:  # underflow (or nan)
                return None, y_old
            if self.floats:
                out = self.run(self.fun, t, h, self.y, self.D, self.k, self.ns,
                               1 if single else self.max_steps - self.naccpt,
                               self.far if single else self.t_end, single, self.max_order,
                               self.rtol, self.atols, self.max_step, self.ts_append,
                               self.ys_append, self.hist_append)
            else:
                out = _array_run(self.k, self.call, self.norm, t, h, self.y, self.D, self.ns,
                                 self.rtol, self.atol, self.ts_append, self.ys_append,
                                 self.hist_append)
            (code, self.t, self.y, self.D, k, self.ns, nacc, nord, kmaxu, err, erk, erkm1,
             erkm2, self.erkp1, self.hrho) = out
            self.k, self.erk, self.erkm1 = k, erk, erkm1
            self.knew = _lower_order(k, erk, erkm1, erkm2)
            if nord:
                self.n_order += nord
                if kmaxu > self.kmax_used:
                    self.kmax_used = kmaxu
            if nacc:
                ifail = 0
                self.naccpt += nacc
                self.nfev += 2 * nacc
                if len(self.history) > 2 * HISTORY:
                    del self.history[:-HISTORY]
            if code != RUN_REJECTED:
                return code, y_old
            ifail += 1
            self.reject(ifail, err)
            y_old = self.y

    def reject(self, ifail, err):
        """After the `ifail`-th rejection in a row: a smaller step, perhaps a lower order."""
        self.nfev += 1
        self.nrej += 1
        self.phase1 = False
        ratio = 0.5
        if ifail > 3 and 0.5 < 0.25 * self.erk:
            ratio = math.sqrt(0.5 / self.erk)
        self.k = 1 if ifail >= 3 else self.knew
        if not math.isfinite(err):
            ratio, self.k = 0.25, 1
        self.change(ratio)

    def record(self, y_old):
        """The stiffness test and, with dense output, the step from `y_old` recorded (and
        the events found); True if a terminal event stops the run."""
        k, t = self.k, self.t
        if not self.phase1 and self.erk >= STIFF_MIN_ESTIMATE:
            # stiffness: h rho near the stability border at a low order (not in the first
            # phase, nor with an error estimate so small that e is mostly rounding)
            self.iasti, self.nonsti, self.warned = stiffness_count(
                "adams", _STIFF_BORDER[k] if k <= STIFF_MAX_ORDER else math.inf, self.hrho,
                t, self.iasti, self.nonsti, self.warned)
        if not self.want_dense:
            return False
        y_rec = np.array(self.y) if self.floats else self.y  # a single step from y_old
        coeffs = _lazy_dense(np.array(y_old), y_rec, np.array(self.D).reshape(-1, self.N), k,
                             self.h)
        if self.sampling:
            self.steps_t.append(t)
            if len(self.steps_t) > 2 * HISTORY:
                del self.steps_t[:-HISTORY]
        return self.rec.accept(t, y_rec, coeffs)

    def next_step(self):
        """The order and the spacing of the next step (:func:`_next_order`,
        :func:`_next_ratio`), the differences changed to match."""
        k_old, N = self.k, self.N
        k, self.erk, self.phase1 = _next_order(k_old, self.knew, self.phase1, self.ns,
                                               self.erk, self.erkm1, self.erkp1,
                                               self.max_order)
        if k > k_old:  # one more difference, unknown
            self.n_order += 1
            self.kmax_used = max(self.kmax_used, k)
            self.D = self.D + [0.0] * N if self.floats else np.vstack([self.D, np.zeros((1, N))])
        elif k < k_old:
            self.n_order += 1
            self.D = self.D[: (k + 2) * N] if self.floats else self.D[: k + 2]
        self.k = k
        reach = abs(self.t - self.steps_t[-min(len(self.history), HISTORY)])
        ratio = _next_ratio(k, self.erk, self.phase1, reach, abs(self.h), self.max_step)
        if ratio != 1.0:
            self.change(ratio)

    def interrupted(self):
        """Ctrl-C: everything computed so far is kept."""
        rec, reason = self.rec, "The integration was interrupted (KeyboardInterrupt)"
        if self.sampling:
            rec.interrupt(reason, rec.reached()["t_stop"])
            return
        m = min(len(rec.ts), len(rec.ys))  # a run may have been stopped between two appends
        del rec.ts[m:], rec.ys[m:]
        rec.interrupt(reason, rec.ts[-1])


def _ignore(value):
    pass


_TINY = 4.0 * np.finfo(float).eps  # a step below _TINY |t| is a step size underflow


def _integrate(fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps,
               dense_output, events, max_order, nstiff, progress=None, t_eval=None):
    started = _start(fun, t_span, y0, rtol, atol, first_step, max_step, dense_output, events,
                     t_eval)
    if not isinstance(started, tuple):  # f(t0, y0) is not finite
        return started
    rec, start = started
    run = _Run(fun, rec, start, rtol, max_step, max_steps, max_order, nstiff, progress)
    try:
        with warnings.catch_warnings():  # a complex value cast to float raises, not warns
            warnings.simplefilter("error", ComplexWarning)
            run.loop()
    except KeyboardInterrupt:
        run.interrupted()
    except (TypeError, ComplexWarning):  # complex values in a step (cast or compared)
        found = _probe(fun, run.t, np.array(run.y, dtype=float), run.h, rec.shape)
        if found is None or not found["complex"]:
            raise
        _complex_failure(rec, found, run.t, np.array(run.y, dtype=float))
    stats = run.stats()
    if rec.culprit is not None:
        stats["culprit"] = rec.culprit
    return rec.result("adams", run.nfev, run.nrej, stats)


_registry.register("adams", adams, kind="adaptive", capabilities=("t_eval",))
