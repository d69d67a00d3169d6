"""Gragg-Bulirsch-Stoer extrapolation, adaptive in order and step (book, ch. 26.2.3).

The book's Romberg idea applied to differential equations: a basic method whose error is an
expansion in *even* powers of its step is run over one big step ``H`` with ``n_j`` substeps,
for ``n_j = 2, 4, 6, 8, ...`` (the harmonic sequence), and the results are extrapolated to a
zero substep by the Aitken-Neville scheme

.. math::

    T_{j,k+1} = T_{j,k} + \\frac{T_{j,k} - T_{j-1,k}}{(n_j / n_{j-k})^2 - 1},

so that ``T_{k,k}`` has order ``2k``. The basic method is Gragg's explicit midpoint rule
``y_1 = y_0 + h f(y_0)``, ``y_{i+1} = y_{i-1} + 2 h f(y_i)``, whose error expands in ``h^2``
for an even number of substeps (Gragg 1965).

Order and step are chosen as in Hairer, Norsett, Wanner I, Sec. II.9 (code ODEX): the error
of column ``k`` is ``||T_{k,k} - T_{k,k-1}||`` in the weighted RMS norm, the candidate step
of column ``k`` is ``H_k = H * 0.94 (0.65 / err_k)^(1/(2k-1))``, and the order minimising the
work per unit step ``A_k / H_k`` (``A_k`` evaluations of ``f``) is kept, with a convergence
monitor in the window ``k-1, k, k+1`` that rejects a hopeless step early.

For one small trajectory (``n <= FLOAT_PATH_MAX_N``) whose ``fun`` returns a float64 ndarray,
the midpoint substeps, the tableau and the error norms run on lists of plain floats: a substep
then costs one call of ``fun`` plus about 1 us, instead of several small numpy operations.

The dense output is the cubic Hermite interpolant between accepted steps (order 3, not the
order of the steps: ask ``"dop853"`` for an accurate continuous solution). Batches share the
step and the order, driven by the largest error norm over the batch.
"""

from __future__ import annotations

import math

import numpy as np

from rigidmech._core.errors import ArgumentError

from . import _registry
from ._dense import hermite_coefficients
from ._driver import Stops
from ._floatpath import FLOAT_PATH_MAX_N, make_midpoint
from ._loop import Capabilities, Run, StepResult, integrate

__all__ = ["gbs"]

_S1, _S2 = 0.94, 0.65  # safety factors of HNW II.9, eq. (9.25)
_FAC_MIN, _FAC_MAX = 0.02, 4.0


def gbs(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
        max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None, k_max=8,
        t_eval=None):
    """Gragg-Bulirsch-Stoer extrapolation with adaptive order and step.

    Called through :func:`rigidmech.ode.solve` (``method="gbs"``), which validates the common
    arguments. `k_max` (int in [3, 12], default 8) is the largest number of columns of the
    extrapolation tableau (order ``2 k_max``). ``stats["orders"]`` gives how many accepted
    steps used each order.

    The dense output ``sol`` is the cubic Hermite interpolant (order 3, less accurate than
    the steps). So that samples and events are as accurate as the steps, the steps land on
    the times of `t_eval` (passed by :func:`~rigidmech.ode.solve`, which returns the values
    of those steps), and each event time located on the interpolant is refined on the
    extrapolated solution itself (one extrapolation from the step's start to each trial
    time, at the step's order).

    Returns
    -------
    OdeResult

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> osc = lambda t, y: np.array([y[1], -y[0]])
    >>> r = ode.solve(osc, (0.0, 20.0), [1.0, 0.0], method="gbs", rtol=1e-12, atol=1e-14)
    >>> bool(abs(r.y[0, -1] - np.cos(20.0)) < 1e-10)
    True
    """
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        return _gbs(fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                    max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                    events=events, k_max=k_max, t_eval=t_eval)


class _GbsStepper:
    """Gragg-Bulirsch-Stoer on the one loop: an attempt builds the extrapolation tableau up to
    the column that converges; the order and the step are chosen with it (its own
    ``controller``, HNW II.9), the loop does the rest."""

    def __init__(self, fun, shape, rtol, atol, k_max, floats):
        self.capabilities = _CAPS
        self.fun, self.shape, self.rtol, self.atol = fun, shape, rtol, atol
        self.k_max, self.floats = k_max, floats
        self.nseq = [2 * (j + 1) for j in range(k_max + 1)]  # 2, 4, 6, ...
        # work: A_1 = n_1 evaluations (f0 included), A_j = A_{j-1} + n_j - 1
        self.work = [1 + sum(n - 1 for n in self.nseq[: j + 1]) for j in range(k_max + 1)]
        # Aitken-Neville coefficients 1 / ((n_j / n_{j-k})^2 - 1)
        self.coef = [[0.0] * (k_max + 1) for _ in range(k_max + 1)]
        for j in range(k_max + 1):
            for k in range(1, j + 1):
                self.coef[j][k] = 1.0 / ((self.nseq[j] / self.nseq[j - k]) ** 2 - 1.0)
        self.k = int(np.clip(int(-math.log10(rtol + 1e-40) * 0.6 + 1.5) - 1, 1, k_max - 1))
        self.start_order = 2 * self.k - 1  # ODEX's first order, for the starting step
        self.orders = {}
        self.nfev = 0
        self.controller = self

    def begin(self, prob, t0, y0, f0):
        n = y0.size
        self.prob, self.f0 = prob, f0
        self.fi, self.row, self.prev = np.empty(n), np.empty((self.k_max + 1, n)), \
            np.empty((self.k_max + 1, n))
        if self.floats:
            self.atols = np.broadcast_to(np.asarray(self.atol, dtype=float), (n,)).tolist()
            self.midpoint = make_midpoint(n)
        return y0

    def attempt(self, t, y, h):
        """Columns ``0 .. k + 1`` at most, stopped as soon as one converges (error <= 1) or
        the convergence monitor gives up; the error returned is 0.5 (accept) or 2 (reject)."""
        k, k_max, nseq = self.k, self.k_max, self.nseq
        errs = [math.inf] * (k_max + 1)
        self.errs, self.col, reject = errs, -1, False
        columns = self._columns_floats(t, y, h) if self.floats else self._columns(t, y, h)
        for j, e in columns:
            errs[j] = e if e == e else math.inf
            if j >= k - 1:
                if errs[j] <= 1.0:
                    self.col = j
                    break
                if j == k - 1 and errs[j] > ((nseq[k + 1] * nseq[k]) / (nseq[0] ** 2)) ** 2:
                    reject = True
                    break
                if j == k and errs[j] > (nseq[min(k + 1, k_max)] / nseq[0]) ** 2:
                    reject = True
                    break
        else:
            reject = True
        self.facs = [_FAC_MIN] * (k_max + 1)
        for j in range(1, k_max + 1):
            if math.isfinite(errs[j]):
                f = _S1 * (_S2 / max(errs[j], 1e-300)) ** (1.0 / (2 * j + 1))
                self.facs[j] = min(_FAC_MAX, max(_FAC_MIN, f))
        if reject or self.col < 0:
            return StepResult(None, None, 2.0, None)
        y_new = np.array(self.rows[self.col]) if self.floats else self.row[self.col].copy()
        f_new = self.prob(t + h, y_new, np.empty(y_new.size))
        return StepResult(y_new, f_new, 0.5, (self.col, h))

    def _columns(self, t, y, h):
        """Column ``j`` of the tableau on arrays, then its error norm (from ``j = 1``)."""
        prob, fi, f0, coef = self.prob, self.fi, self.f0, self.coef
        row, prev = self.row, self.prev
        for j in range(self.k + 2 if self.k + 1 <= self.k_max else self.k + 1):
            nj = self.nseq[j]
            hs = h / nj
            row, prev = prev, row  # row: T_{j,0..j}; prev: T_{j-1,0..j-1}
            self.row, self.prev = row, prev
            y_prev = y
            y_cur = y + hs * f0
            for i in range(1, nj):
                prob(t + i * hs, y_cur, fi)
                y_prev, y_cur = y_cur, y_prev + (2.0 * hs) * fi
            row[0] = y_cur
            for m in range(1, j + 1):  # Aitken-Neville
                row[m] = row[m - 1] + (row[m - 1] - prev[m - 1]) * coef[j][m]
            if j:
                scale = self.atol + self.rtol * np.maximum(np.abs(y), np.abs(row[j]))
                yield j, prob.norm((row[j] - row[j - 1]) / scale)

    def _columns_floats(self, t, y, h):
        """The same tableau on lists of floats (one small trajectory)."""
        y_list, f0_list = y.tolist(), self.f0.tolist()
        rows = []
        for j in range(self.k + 2 if self.k + 1 <= self.k_max else self.k + 1):
            nj = self.nseq[j]
            prev_rows = rows
            rows = [self.midpoint(self.fun, t, y_list, f0_list, h / nj, nj)]
            self.prob.nfev += nj - 1
            cj = self.coef[j]
            for m in range(1, j + 1):  # Aitken-Neville
                c_m = cj[m]
                rows.append([a + (a - b) * c_m
                             for a, b in zip(rows[m - 1], prev_rows[m - 1], strict=True)])
            self.rows = rows
            if j:
                yield j, _norm_floats(rows[j], rows[j - 1], y_list, self.atols, self.rtol)

    def next(self, err, h_abs, rejected):
        """Order and step after an attempt (HNW II.9, eq. (9.27)-(9.28))."""
        k, k_max, work, facs = self.k, self.k_max, self.work, self.facs
        if err > 1.0:  # rejected: new order among the computed columns, smaller step
            cand = [j for j in range(1, k + 1) if math.isfinite(self.errs[j])]
            if cand:
                k = max(1, min(cand, key=lambda j: work[j] / facs[j]))
                h_abs *= min(facs[k], 0.5)
            else:
                h_abs *= _FAC_MIN
            self.k = max(1, min(k, k_max - 1))
            return h_abs, False
        kc = self.col
        if kc >= 2 and work[kc - 1] / facs[kc - 1] < 0.8 * work[kc] / facs[kc]:
            k_new, fac = kc - 1, facs[kc - 1]
        elif kc + 1 <= k_max - 1 and work[kc] / facs[kc] < 0.9 * work[kc - 1] / facs[kc - 1]:
            k_new, fac = kc + 1, facs[kc] * work[kc + 1] / work[kc]
        else:
            k_new, fac = kc, facs[kc]
        k_new = max(1, min(k_new, k_max - 1))
        if rejected:
            fac = min(fac, 1.0)
            k_new = min(k_new, kc)
        self.k = k_new
        return h_abs * fac, True

    def finite(self, step):
        return bool(np.isfinite(step.y).all() and np.isfinite(step.f).all())

    def accept(self, step):
        kc = step.data[0]
        self.orders[2 * (kc + 1)] = self.orders.get(2 * (kc + 1), 0) + 1
        self.f0 = step.f

    def hlamb(self, h_abs, step):
        return None

    def dense(self, t, y, h, step):
        exact = _point(self.prob, t, y, self.f0, step.data[0], self.nseq, self.coef)
        return step.y, hermite_coefficients(y, step.y, self.f0, step.f, h), exact

    def stats(self):
        return {"orders": dict(sorted(self.orders.items()))}


_CAPS = Capabilities("gbs", error_order=1, order=2, dense_order=3)


def _gbs(fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps, dense_output, events,
         k_max, t_eval):
    if isinstance(k_max, bool) or not isinstance(k_max, int | np.integer) or not (
        3 <= k_max <= 12
    ):
        raise ArgumentError(f"`k_max` must be an int in [3, 12]; got {k_max!r}.")
    shape, t0 = y0.shape, t_span[0]
    floats, f0 = False, None
    if len(shape) == 1 and y0.size <= FLOAT_PATH_MAX_N:
        # one small trajectory: the midpoint substeps run on lists of floats (no numpy
        # overhead per substep) when `fun` returns a float64 ndarray of the right shape
        f0 = fun(t0, y0.copy())
        floats = type(f0) is np.ndarray and f0.shape == shape and f0.dtype == np.float64
    stepper = _GbsStepper(fun, shape, rtol, atol, int(k_max), floats)
    run = Run(fun, t_span, y0, rtol, atol, first_step, max_step, max_steps, dense_output,
              events, 0, "i", None, Stops(t_eval, t_span) if t_eval is not None else None,
              t_eval)
    return integrate(stepper, run, f0)


def _point(prob, t, y, f0, kc, nseq, coef):
    """``s -> y(s)`` by one extrapolation of columns ``0..kc`` from ``(t, y)`` (order
    ``2 (kc + 1)``, that of the accepted step): the solution inside a step as accurate as the
    step itself, for the refinement of event times."""
    y, f0 = y.copy(), f0.copy()

    def at(s):
        h = s - t
        if h == 0.0:
            return y.reshape(prob.shape).copy()
        fi = np.empty_like(y)
        rows = []
        for j in range(kc + 1):
            nj = nseq[j]
            hs = h / nj
            y_prev, y_cur = y, y + hs * f0
            for i in range(1, nj):
                prob(t + i * hs, y_cur, fi)
                y_prev, y_cur = y_cur, y_prev + (2.0 * hs) * fi
            row = [y_cur]
            for m in range(1, j + 1):
                row.append(row[m - 1] + (row[m - 1] - rows[m - 1]) * coef[j][m])
            rows = row
        return rows[kc].reshape(prob.shape)

    return at


def _norm_floats(a, b, y, atols, rtol):
    """Hairer's RMS norm of ``a - b`` scaled by ``atol + rtol max(|y|, |a|)`` (float lists)."""
    acc = 0.0
    for ai, bi, yi, at in zip(a, b, y, atols, strict=True):
        acc += ((ai - bi) / (at + rtol * max(abs(yi), abs(ai)))) ** 2
    return math.sqrt(acc / len(a))


_registry.register("gbs", gbs, kind="adaptive", capabilities=("t_eval", "t_eval_at_steps"))
