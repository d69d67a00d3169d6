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
from ._driver import Problem, Recorder, Stops, initial_step
from ._floatpath import FLOAT_PATH_MAX_N, make_midpoint

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
                    events=events, k_max=k_max, stops=Stops(t_eval, t_span))


def _gbs(fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps, dense_output, events,
         k_max, stops):
    if isinstance(k_max, bool) or not isinstance(k_max, int | np.integer) or not (
        3 <= k_max <= 12
    ):
        raise ArgumentError(f"`k_max` must be an int in [3, 12]; got {k_max!r}.")
    k_max = int(k_max)
    t0, t_end = t_span
    direction = 1.0 if t_end > t0 else -1.0
    shape = y0.shape
    prob = Problem(fun, shape)
    y = y0.reshape(-1).copy()
    N = y.size
    want_dense = dense_output or events is not None
    rec = Recorder(t0, y, shape, dense_output, events, "power")
    nseq = [2 * (j + 1) for j in range(k_max + 1)]  # 2, 4, 6, ...
    # work: A_1 = n_1 evaluations (f0 included), A_j = A_{j-1} + n_j - 1
    work = [1 + sum(n - 1 for n in nseq[: j + 1]) for j in range(k_max + 1)]
    # Aitken-Neville coefficients 1 / ((n_j / n_{j-k})^2 - 1)
    coef = [[0.0] * (k_max + 1) for _ in range(k_max + 1)]
    for j in range(k_max + 1):
        for k in range(1, j + 1):
            coef[j][k] = 1.0 / ((nseq[j] / nseq[j - k]) ** 2 - 1.0)
    floats = False
    if len(shape) == 1 and N <= FLOAT_PATH_MAX_N:
        # one small trajectory: the midpoint substeps run on lists of floats (no numpy
        # overhead per substep) when `fun` returns a float64 ndarray of the right shape
        raw = fun(t0, y.copy())
        prob.nfev += 1
        floats = type(raw) is np.ndarray and raw.shape == shape and raw.dtype == np.float64
        f0 = np.array(raw, dtype=float).reshape(N)
    else:
        f0 = prob(t0, y, np.empty(N))
    if not np.isfinite(f0).all():
        rec.fail("The right-hand side is not finite", t0, y)
        return rec.result("gbs", prob.nfev, 0)
    tol = rtol
    k = int(np.clip(int(-math.log10(tol + 1e-40) * 0.6 + 1.5) - 1, 1, k_max - 1))  # ODEX
    if first_step is None:
        h_abs = initial_step(prob, t0, y, f0, direction, 2 * k - 1, rtol, atol, t_end, max_step)
    else:
        h_abs = first_step
    t = t0
    nrej = naccpt = 0
    orders = {}
    fi = np.empty(N)
    row = np.empty((k_max + 1, N))
    prev = np.empty((k_max + 1, N))
    inf = math.inf
    isfinite = math.isfinite
    if floats:
        atols = np.broadcast_to(np.asarray(atol, dtype=float), (N,)).tolist()
        midpoint = make_midpoint(N)
    t_goal = stops.after(t0)
    while direction * (t - t_end) < 0:
        if naccpt >= max_steps:
            rec.fail(f"The maximum number of steps `max_steps` = {max_steps} was reached", t, y)
            break
        min_step = 10 * abs(math.nextafter(t, direction * math.inf) - t)
        h_abs = min(max(h_abs, min_step), max_step)
        last_rejected = False
        accepted_col = -1
        while True:
            h = h_abs * direction
            t_new = t + h
            if direction * (t_new - t_goal) >= 0:
                t_new = t_goal
                h = t_new - t
                h_abs = abs(h)
            errs = [inf] * (k_max + 1)
            reject = False
            if floats:
                y_list, f0_list = y.tolist(), f0.tolist()
                rows = []
            for j in range(k + 2 if k + 1 <= k_max else k + 1):
                # column j: midpoint rule with n_j substeps (f0 shared)
                nj = nseq[j]
                hs = h / nj
                if floats:  # the same tableau on lists of floats
                    prev_rows = rows
                    rows = [midpoint(fun, t, y_list, f0_list, hs, nj)]
                    prob.nfev += nj - 1
                    cj = coef[j]
                    for m in range(1, j + 1):  # Aitken-Neville
                        c_m = cj[m]
                        rows.append([a + (a - b) * c_m
                                     for a, b in zip(rows[m - 1], prev_rows[m - 1], strict=True)])
                    if j == 0:
                        continue
                    e = _norm_floats(rows[j], rows[j - 1], y_list, atols, rtol)
                else:
                    row, prev = prev, row  # row: T_{j,0..j}; prev: T_{j-1,0..j-1}
                    y_prev = y
                    y_cur = y + hs * f0
                    for i in range(1, nj):
                        prob(t + i * hs, y_cur, fi)
                        y_prev, y_cur = y_cur, y_prev + (2.0 * hs) * fi
                    row[0] = y_cur
                    for m in range(1, j + 1):  # Aitken-Neville
                        row[m] = row[m - 1] + (row[m - 1] - prev[m - 1]) * coef[j][m]
                    if j == 0:
                        continue
                    scale = atol + rtol * np.maximum(np.abs(y), np.abs(row[j]))
                    e = prob.norm((row[j] - row[j - 1]) / scale)
                errs[j] = e if e == e else inf
                if j >= k - 1:
                    if errs[j] <= 1.0:
                        accepted_col = j
                        break
                    if j == k - 1 and errs[j] > ((nseq[k + 1] * nseq[k]) / (nseq[0] ** 2)) ** 2:
                        reject = True
                        break
                    if j == k and errs[j] > (nseq[min(k + 1, k_max)] / nseq[0]) ** 2:
                        reject = True
                        break
            else:
                reject = True
            # candidate steps and work of the columns computed
            facs = [_FAC_MIN] * (k_max + 1)
            for j in range(1, k_max + 1):
                if isfinite(errs[j]):
                    f = _S1 * (_S2 / max(errs[j], 1e-300)) ** (1.0 / (2 * j + 1))
                    facs[j] = min(_FAC_MAX, max(_FAC_MIN, f))
            if not reject and accepted_col >= 0:
                break
            # rejected: new order among the computed columns, smaller step
            nrej += 1
            last_rejected = True
            cand = [j for j in range(1, k + 1) if isfinite(errs[j])]
            if cand:
                k = max(1, min(cand, key=lambda j: work[j] / facs[j]))
                h_abs *= min(facs[k], 0.5)
            else:
                h_abs *= _FAC_MIN
            k = max(1, min(k, k_max - 1))
            if not h_abs >= min_step:
                break
        if accepted_col < 0:
            rec.fail("The step size fell below the resolution of t (step size underflow)", t, y)
            break
        y_new = np.array(rows[accepted_col]) if floats else row[accepted_col].copy()
        f_new = prob(t_new, y_new, np.empty(N))
        if not (np.isfinite(y_new).all() and np.isfinite(f_new).all()):
            rec.fail("The state became non-finite", t_new, y_new)
            break
        naccpt += 1
        kc = accepted_col
        orders[2 * (kc + 1)] = orders.get(2 * (kc + 1), 0) + 1
        # order and step for the next step (HNW II.9, eq. (9.27)-(9.28))
        if kc >= 2 and work[kc - 1] / facs[kc - 1] < 0.8 * work[kc] / facs[kc]:
            k_new, fac = kc - 1, facs[kc - 1]
        elif kc + 1 <= k_max - 1 and work[kc] / facs[kc] < 0.9 * work[kc - 1] / facs[kc - 1]:
            k_new, fac = kc + 1, facs[kc] * work[kc + 1] / work[kc]
        else:
            k_new, fac = kc, facs[kc]
        k_new = max(1, min(k_new, k_max - 1))
        if last_rejected:
            fac = min(fac, 1.0)
            k_new = min(k_new, kc)
        coeffs = hermite_coefficients(y, y_new, f0, f_new, h) if want_dense else None
        exact = _point(prob, t, y, f0, kc, nseq, coef) if events is not None else None
        stop = rec.accept(t_new, y_new, coeffs, exact=exact)
        t_goal = stops.after(t_new)
        t, y, f0 = t_new, y_new, f_new
        k = k_new
        h_abs = min(h_abs * fac, max_step)
        if stop:
            break
    stats = {"orders": dict(sorted(orders.items()))}
    return rec.result("gbs", prob.nfev, nrej, stats)


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


_registry.register("gbs", gbs, kind="adaptive", capabilities=("t_eval_at_steps",))
