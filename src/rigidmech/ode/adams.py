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
from fractions import Fraction

import numpy as np
from numpy.exceptions import ComplexWarning

from rigidmech._core.errors import ArgumentError

from . import _registry
from ._driver import Recorder, SampleRecorder, flat_tolerance
from ._floatpath import FLOAT_PATH_MAX_N, cached, compile_function
from ._loop import _complex_failure, _probe, check_progress, underflow_failure
from ._warnings import stiffness_count
from .adaptive import _check_nstiff
from .multistep import adams_gamma

__all__ = ["adams", "resample_matrix", "MAX_ORDER"]

#: Highest order of the Adams formulas used (as in DE/STEP: beyond it the stability region of
#: the PECE pair becomes too small to gain anything).
MAX_ORDER = 12

#: Up to this order the step may be doubled before the known values of f reach back over 2k
#: steps (the interpolation polynomial is then extrapolated backwards); above it, the doubling
#: waits for them.
RESAMPLE_DOUBLING_MAX_ORDER = 4

#: Number of past values of f (with their times) kept for changes of the step size.
HISTORY = 4 * MAX_ORDER + 1

#: Stiffness test (see :func:`adams`): only steps of order <= STIFF_MAX_ORDER are examined
#: (stiffness drives an Adams code to low orders, as Shampine and Gordon's DE uses), against
#: 0.8 times the real stability interval of the PECE pair of order k (k = 1 .. 4), the roots
#: of its step on y' = lambda y (recomputed in the tests).
STIFF_MAX_ORDER = 4
#: ... and only steps whose error estimate is at least this fraction of the tolerance: below,
#: the difference of the two evaluations is mostly rounding and h rho means nothing.
STIFF_MIN_ESTIMATE = 1e-3
_PECE_REAL_INTERVAL = {1: 2.0, 2: 2.4, 3: 1.935, 4: 1.411}
_STIFF_BORDER = {k: 0.8 * v for k, v in _PECE_REAL_INTERVAL.items()}

#: gamma_j of Adams-Bashforth and |gamma*_j| of Adams-Moulton, j = 0 .. MAX_ORDER + 1
_G = [float(adams_gamma(j)) for j in range(MAX_ORDER + 2)]
_GS = [abs(float(adams_gamma(j, implicit=True))) for j in range(MAX_ORDER + 2)]


def _backward_difference_matrix(m):
    """``Delta`` with ``Delta @ [v_0, v_1, ..., v_m] = [nabla^0 v_0, ..., nabla^m v_0]``."""
    D = np.zeros((m + 1, m + 1))
    for j in range(m + 1):
        for i in range(j + 1):
            D[j, i] = (-1) ** i * math.comb(j, i)
    return D


_DELTA = [_backward_difference_matrix(m) for m in range(MAX_ORDER + 2)]


def resample_matrix(m: int, ratio: float) -> np.ndarray:
    r"""Map the backward differences at spacing :math:`h` to those at spacing ``ratio * h``.

    The differences :math:`\nabla^j f_n` (:math:`j = 0, \dots, m`) define Newton's backward
    interpolation polynomial (book, 26.3.2)

    .. math:: P(t_n + s h) = \sum_{j=0}^{m}\binom{s + j - 1}{j}\nabla^j f_n ;

    sampled at :math:`t_n - i\,r h` (:math:`i = 0, \dots, m`) it gives new values whose backward
    differences are the new :math:`\nabla^j f_n`. The map is linear; this is its matrix.

    Parameters
    ----------
    m : int
        Highest difference, ``0 <= m <= MAX_ORDER + 1``.
    ratio : float
        New step over old step, ``> 0``.

    Returns
    -------
    ndarray, shape (m + 1, m + 1)

    Examples
    --------
    >>> import numpy as np
    >>> f = lambda t: 1.0 + 2.0 * t + 3.0 * t**2          # degree 2: resampling is exact
    >>> def diffs(h):
    ...     v = np.array([f(-i * h) for i in range(3)])
    ...     return np.array([v[0], v[0] - v[1], v[0] - 2 * v[1] + v[2]])
    >>> bool(np.allclose(resample_matrix(2, 0.5) @ diffs(0.2), diffs(0.1)))
    True
    """
    s = -ratio * np.arange(m + 1, dtype=float)
    B = np.ones((m + 1, m + 1))
    for j in range(1, m + 1):  # binom(s + j - 1, j) = binom(s + j - 2, j - 1) (s + j - 1) / j
        B[:, j] = B[:, j - 1] * (s + (j - 1)) / j
    return _DELTA[m] @ B


_REINTERP = {}
_REINTERP_MAX = 4096  # cached matrices (the patterns of past times repeat: ratios are few)


def _reinterpolation_matrix(T, k, h_new):
    """Differences on the grid ``T[-1] - i h_new`` (i = 0..k) from values at past times.

    `T` holds the times of the known values of f, oldest first (the last is the current
    point; at least k + 1 of them). Chosen: the last k + 1 when they reach back over the new
    span (a reduction), else, walking back, for each grid node the nearest older time (a
    doubling). Returns ``(M, idx)``: the backward differences on the grid are ``M @ f[idx]``
    (negative indices into `T`), ``M = Delta_k L`` with ``L`` Lagrange's interpolation matrix
    from the chosen times to the grid (exact on polynomials of degree k; its first row is
    ``e_0``: the current value is kept). Matrices are cached by the chosen times relative to
    the grid, which repeat along an integration.
    """
    m = len(T)
    tn = T[-1]
    span = k * abs(h_new)
    if m >= k + 1 and abs(tn - T[-k - 1]) >= span * (1.0 - 1e-12):
        idx = list(range(-1, -k - 2, -1))
    else:  # walk back: for each node the nearest older time, leaving enough for the rest
        idx = [-1]
        j = -1
        for i in range(1, k + 1):
            node = tn - i * h_new
            j -= 1
            lowest = -m + (k - i)
            while j > lowest and abs(T[j - 1] - node) <= abs(T[j] - node):
                j -= 1
            idx.append(j)
    u = [(T[j] - tn) / h_new for j in idx]  # chosen times, in new steps from the current one
    key = (k, *(round(x, 12) for x in u))
    M = _REINTERP.get(key)
    if M is None:
        n1 = k + 1
        ua = np.array(key[1:])  # from the key: the matrix depends on it alone
        du = ua[:, None] - ua[None, :]
        du.flat[:: n1 + 1] = 1.0
        w = 1.0 / du.prod(axis=1)  # barycentric weights
        # L[i, j] = w_j prod_{m != j} (v_i - u_m) at v_i = -i, by prefix and suffix products
        # (no division: exact where a grid node falls on a known time)
        dv = -np.arange(n1, dtype=float)[:, None] - ua[None, :]
        pre = np.ones((n1, n1 + 1))
        suf = np.ones((n1, n1 + 1))
        np.cumprod(dv, axis=1, out=pre[:, 1:])
        np.cumprod(dv[:, ::-1], axis=1, out=suf[:, 1:])
        L = pre[:, :-1] * suf[:, -2::-1] * w
        L[0] = 0.0  # the grid starts at the current point: its value is kept, bit for bit
        L[0, 0] = 1.0
        M = _DELTA[k] @ L
        if len(_REINTERP) >= _REINTERP_MAX:
            _REINTERP.clear()
        _REINTERP[key] = M
    return M, idx


def _dense_table():
    """``C[j]``: power coefficients in x (x**1 .. x**(j+1)) of ``c_j(x - 1) - c_j(-1)``.

    ``c_j(theta) = int_0^theta binom(s + j - 1, j) ds``, so that over the step ending at
    ``t_{n+1}``, ``y(t_{n+1} + theta h) = y_{n+1} + h sum_j c_j(theta) nabla^j f_{n+1}``
    (``theta`` in [-1, 0], ``x = theta + 1``).
    """
    table = []
    for j in range(MAX_ORDER + 2):
        p = [Fraction(1)]  # binom(s + j - 1, j) as a polynomial in s, ascending
        for i in range(j):
            q = [Fraction(0)] * (len(p) + 1)
            for d, a in enumerate(p):
                q[d] += a * i
                q[d + 1] += a
            p = q
        p = [a / math.factorial(j) for a in p]
        c = [Fraction(0)] + [a / (d + 1) for d, a in enumerate(p)]  # integral from 0
        # substitute theta = x - 1: sum_d c_d (x - 1)^d
        out = [Fraction(0)] * len(c)
        for d, a in enumerate(c):
            for e in range(d + 1):
                out[e] += a * math.comb(d, e) * (-1) ** (d - e)
        table.append(np.array([float(a) for a in out[1:]]))  # drop the constant term
    return table


_DENSE = _dense_table()


# --- the step ------------------------------------------------------------------------------
#
# One attempted step of order k from (t, y) with the differences D_0 .. D_{k+1} at spacing h:
#   q_j = D_j + q_{j+1} (q_{k-1} = D_{k-1})       predicted differences at t + h
#   p = y + h sum_{j<k} gamma_j D_j                 Adams-Bashforth predictor
#   e = f(t + h, p) - q_0                           nabla^k f^p_{n+1}
#   err = |h| (gamma_{k-1} - gamma_k) ||e|| = erk = |h| |gamma*_k| ||e||  (gamma*_k =
#   gamma_k - gamma_{k-1}: the error of order k is the estimate at order k, one number),
#   erkm1 = |h| |gamma*_{k-1}| ||q_{k-1} + e||, erkm2 = |h| |gamma*_{k-2}| ||q_{k-2} + e||
# and, if err <= 1:
#   y_new = p + h gamma_k e;  c = f(t + h, y_new) - q_0
#   D'_j = q_j + c (j < k), D'_k = c, D'_{k+1} = c - D_k,
#   erkp1 = |h| |gamma*_{k+1}| ||D'_{k+1}||
# A rejected attempt leaves the differences as they were.
#
# A *run* repeats such steps at constant spacing, changing the order by the driver's rules
# (`_lower_order`, `_next_order`) as it goes, for as long as `_next_ratio` keeps the spacing.
# It returns at the first step after which the spacing would change (before changing the
# order: the driver takes that decision whole), at a rejection, before a step reaching
# `t_stop`, after `limit` steps, or after one step if `single`. It returns
#   (code, t, y, D, k, ns, nacc, n_order, k_max, err, erk, erkm1, erkm2, erkp1, hrho)
# with code RUN_STOPPED (no decision needed), RUN_REJECTED (the state is the last accepted
# one), RUN_DECIDE (the last accepted step needs the driver's decisions) or RUN_NONFINITE
# (t and y are the failed step's); nacc counts the steps the run accepted, n_order its
# changes of order, k_max the highest order it reached, ns the steps since the last change of
# spacing. Every accepted step is passed to ``ts_append``, ``ys_append`` (t and a fresh y) and
# ``hist_append`` (f at the new point).

RUN_STOPPED, RUN_REJECTED, RUN_DECIDE, RUN_NONFINITE = 0, 1, 2, 3


def _hrho(dF, e, gamma_k):
    r"""Estimate of :math:`h\rho` (step times the local Lipschitz constant of f) from a step.

    The two evaluations of a PECE step are at the predicted and the corrected values, which
    differ by :math:`h\gamma_k e`: :math:`h\rho \approx \|dF\| / (\gamma_k \|e\|)` with
    :math:`dF = f(y_{n+1}) - f(p)` (Euclidean norms; 0 if :math:`e = 0`). On a stiff problem
    the stiff components dominate both, and the estimate approaches :math:`h|\lambda|`.
    """
    num = math.fsum(float(v) * float(v) for v in np.ravel(dF))
    den = math.fsum(float(v) * float(v) for v in np.ravel(e))
    return math.sqrt(num / den) / gamma_k if den > 0.0 else 0.0


def _float_run_source(n):
    """Source of the plain-float run for `n` equations: every order unrolled, one function.

    Why generated code: for a few equations the cost of an Adams step is Python's, not the
    arithmetic's. With every difference a local variable, unrolled for each order, and the
    order changed inside the run, a step costs about as much as the two calls of ``fun``
    (damped oscillator, docs' performance page); loops over lists of differences, or a return
    to the driver at every change of order, cost several times more. The error estimates are
    kept squared inside the run (no square roots; the comparisons are the same). The body of
    order k is :func:`_attempt_lines`, :func:`_accept_lines` and :func:`_order_lines`, chosen
    by a binary tree of tests on k.
    """
    r = range(n)
    rows = _rows(n)
    L = [
        f"def adams_run_{n}(fun, t, h, y, D, k, ns, limit, t_stop, single, kmax, rtol, atols,"
        " max_step, ts_append, ys_append, hist_append):",
        f"    {', '.join(f'y{i}' for i in r)}, = y",
        f"    {rows}, = D + _ZEROS[len(D):]",
        f"    {', '.join(f'at{i}' for i in r)}, = atols",
        "    h2 = h*h",
        "    double_ok = 4.0*h2 <= max_step*max_step",
        "    nacc = nord = kmaxu = 0",
        "    erkm1 = erkm2 = erkp1 = 0.0",
        "    while True:",
        "        t_new = t + h",
        "        if (t_new - t_stop)*h >= 0.0 or nacc >= limit:",
        f"            return {RUN_STOPPED}, t, {_state(n)}, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0",
    ]

    def tree(lo, hi, ind):
        if lo == hi:
            return [ind + line for line in (_attempt_lines(lo, n) + _accept_lines(lo, n)
                                            + _order_lines(lo, n))]
        mid = (lo + hi) // 2
        return ([f"{ind}if k <= {mid}:"] + tree(lo, mid, ind + "    ")
                + [f"{ind}else:"] + tree(mid + 1, hi, ind + "    "))

    L += tree(1, MAX_ORDER, "        ")
    return "\n".join(L)


#: the squared estimates returned by a run: err (= erk), erk, erkm1, erkm2
_EST = "_sqrt(erk), _sqrt(erk), _sqrt(erkm1), _sqrt(erkm2)"


def _rows(n):
    return ", ".join(f"D{j}_{i}" for j in range(MAX_ORDER + 2) for i in range(n))


def _state(n):
    return "y, [" + _rows(n) + f"][:(k + 2)*{n}], k, ns, nacc, nord, kmaxu"


def _q(k, j, i):
    """The predicted difference q_j of component i (q_{k-1} is D_{k-1} itself)."""
    return f"D{k - 1}_{i}" if j == k - 1 else f"q{j}_{i}"


def _sq(expr, c, n):
    """``c h^2 sum (v_i w_i)^2 = (|h| sqrt(c n) ||v||)^2``: a squared RMS norm."""
    terms = " + ".join(f"(a{i} := ({expr(i)})*w{i})*a{i}" for i in range(n))
    return f"{c / n!r}*h2*({terms})"


def _attempt_lines(k, n):
    """Order k: predict, evaluate, estimate at orders k, k-1, k-2; return if rejected."""
    r, out = range(n), []
    for i in r:
        for j in range(k - 2, -1, -1):
            out.append(f"q{j}_{i} = D{j}_{i} + {_q(k, j + 1, i)}")
        terms = " + ".join(("" if j == 0 else f"{_G[j]!r}*") + f"D{j}_{i}" for j in range(k))
        out.append(f"p{i} = y{i} + h*({terms})")
    out.append(f"{', '.join(f'f{i}' for i in r)}, = "
               f"_tolist(fun(t_new, _arr([{', '.join(f'p{i}' for i in r)}])))")
    for i in r:
        out.append(f"e{i} = f{i} - {_q(k, 0, i)}")
        out.append(f"w{i} = 1.0/(at{i} + rtol*(y{i} if y{i} >= 0.0 else -y{i}))")
    out.append(f"erk = {_sq(lambda i: f'e{i}', _GS[k] ** 2, n)}")  # also the step's error
    if k >= 2:
        out.append(f"erkm1 = {_sq(lambda i: f'{_q(k, k - 1, i)} + e{i}', _GS[k - 1] ** 2, n)}")
    if k >= 3:
        out.append(f"erkm2 = {_sq(lambda i: f'{_q(k, k - 2, i)} + e{i}', _GS[k - 2] ** 2, n)}")
    out.append("if not erk <= 1.0:")
    out.append(f"    return {RUN_REJECTED}, t, {_state(n)}, {_EST}, 0.0, 0.0")
    return out


def _accept_lines(k, n):
    """Order k, accepted: correct, evaluate, update the differences, record the step."""
    r, out = range(n), []
    for i in r:
        out.append(f"yn{i} = p{i} + {_G[k]!r}*h*e{i}")
    yn = ", ".join(f"yn{i}" for i in r)
    out.append(f"yn = [{yn}]")
    out.append(f"{', '.join(f'c{i}' for i in r)}, = _tolist(fun(t_new, _arr(yn)))")
    out.append(f"if {' + '.join(f'0.0*yn{i}' for i in r)} != 0.0:  # inf or nan")
    out.append(f"    return {RUN_NONFINITE}, t_new, yn, [{_rows(n)}][:(k + 2)*{n}], k, ns, nacc, "
               f"nord, kmaxu, {_EST}, 0.0, 0.0")
    for i in r:
        out.append(f"c{i} = c{i} - {_q(k, 0, i)}")
        out.append(f"D{k + 1}_{i} = c{i} - D{k}_{i}")
        out.append(f"D{k}_{i} = c{i}")
        for j in range(k - 1, -1, -1):
            out.append(f"D{j}_{i} = {_q(k, j, i)} + c{i}")
    out += ["t = t_new", "y = yn", f"{', '.join(f'y{i}' for i in r)}, = {yn},", "ns += 1",
            "nacc += 1", "ts_append(t)", "ys_append(yn)",
            f"hist_append([{', '.join(f'D0_{i}' for i in r)}])"]
    return out


def _order_lines(k, n):
    """Order k, after an accepted step: the next order (``_lower_order``, then
    ``_next_order``, out of the first phase, which is `single`); return to the driver where
    the spacing would change."""
    r, out = range(n), []
    erkp1 = _sq(lambda i: f"D{k + 1}_{i}", _GS[k + 1] ** 2, n)
    hrho = "0.0"  # the stiffness test looks at low orders only
    if k <= STIFF_MAX_ORDER:
        hrho = (f"_hrho(({', '.join(f'c{i} - e{i}' for i in r)},), "
                f"({', '.join(f'e{i}' for i in r)},), {_G[k]!r})")
    decide = f"return {RUN_DECIDE}, t, {_state(n)}, {_EST}, _sqrt(erkp1), {hrho}"
    out += ["if single:", f"    erkp1 = {erkp1}", f"    {decide}"]

    def choose(kk, e, ind):  # next order kk with estimate e; leave the run if h would change
        # (a wanted doubling leaves the run even when the driver will wait for the known
        # values of f to reach back far enough: the driver alone knows them)
        return [ind + line for line in (
            f"k2, e2 = {kk}, {e}",
            f"if not 0.25 >= e2 or (double_ok and 0.25 >= {4.0 ** (kk + 1)!r}*e2):",
            f"    {decide}")]

    if k >= 3:
        out.append("if erkm1 <= erk and erkm2 <= erk:")
    elif k == 2:
        out.append("if erkm1 <= 0.25*erk:")
    if k >= 2:
        out += choose(k - 1, "erkm1", "    ")
        out.append(f"elif ns > {k}:")
    else:
        out.append(f"if ns > {k}:")
    out.append(f"    erkp1 = {erkp1}")
    if k == 1:
        out.append("    if kmax > 1 and erkp1 < 0.25*erk:")
        out += choose(2, "erkp1", "        ")
    else:
        out.append("    if erkm1 <= erk and erkm1 <= erkp1:")
        out += choose(k - 1, "erkm1", "        ")
        out.append(f"    elif erkp1 < erk and kmax > {k}:")
        out += choose(k + 1, "erkp1", "        ")
    out.append("    else:")
    out += choose(k, "erk", "        ")
    out.append("else:")
    out += choose(k, "erk", "    ")
    out += [f"if k2 != {k}:", "    nord += 1", "    k = k2"]
    if k < MAX_ORDER:
        out += [f"    if k2 > {k}:  # one more difference, unknown",
                f"        {', '.join(f'D{k + 2}_{i}' for i in r)} = {', '.join('0.0' for i in r)}",
                "        if k2 > kmaxu:", "            kmaxu = k2"]
    return out


def _float_run(n):
    """The plain-float run for `n` equations (generated once by the shared compiler)."""
    return cached(("adams", n), lambda: compile_function(
        _float_run_source(n).split("\n"), f"adams_run_{n}", f"adams, {n} equations",
        {"_sqrt": math.sqrt, "_hrho": _hrho, "_ZEROS": [0.0] * ((MAX_ORDER + 2) * n)}))


def _array_run(k, call, norm, t, h, y, D, ns, rtol, atol, ts_append, ys_append, hist_append):
    """One step on arrays (batches, larger systems): `D` of shape (k + 2, N).

    Returns after one attempt (as a ``single`` run), with the codes of the plain-float run.
    """
    ah = abs(h)
    t_new = t + h
    q = np.cumsum(D[k - 1::-1], axis=0)[::-1]  # q_j = sum_{m=j}^{k-1} D_m, j = 0..k-1
    p = y + h * (np.asarray(_G[:k]) @ D[:k])
    e = call(t_new, p) - q[0]
    w = 1.0 / (atol + rtol * np.abs(y))
    erk = err = _GS[k] * ah * norm(e * w)  # err = erk (see "the step" above)
    erkm1 = _GS[k - 1] * ah * norm((q[k - 1] + e) * w) if k >= 2 else 0.0
    erkm2 = _GS[k - 2] * ah * norm((q[k - 2] + e) * w) if k >= 3 else 0.0
    est = (err, erk, erkm1, erkm2)
    if not err <= 1.0:
        return (RUN_REJECTED, t, y, D, k, ns, 0, 0, 0) + est + (0.0, 0.0)
    y_new = p + (h * _G[k]) * e
    c = call(t_new, y_new) - q[0]
    if not np.isfinite(y_new).all():
        return (RUN_NONFINITE, t_new, y_new, D, k, ns, 0, 0, 0) + est + (0.0, 0.0)
    Dn = np.empty_like(D)
    Dn[:k] = q + c
    Dn[k] = c
    Dn[k + 1] = c - D[k]
    erkp1 = _GS[k + 1] * ah * norm(Dn[k + 1] * w)
    ts_append(t_new)
    ys_append(y_new)
    hist_append(Dn[0])
    hrho = _hrho(c - e, e, _G[k]) if k <= STIFF_MAX_ORDER else 0.0
    return (RUN_DECIDE, t_new, y_new, Dn, k, ns + 1, 1, 0, 0) + est + (erkp1, hrho)


# --- the driver ----------------------------------------------------------------------------


def _check_max_order(max_order):
    if isinstance(max_order, bool) or not isinstance(max_order, int | np.integer) or not (
        1 <= max_order <= MAX_ORDER
    ):
        raise ArgumentError(
            f"`max_order` must be an int in 1..{MAX_ORDER}; got {max_order!r}."
        )
    return int(max_order)


def _dense_coefficients(y_old, y_new, D, k, h):
    """Power-form coefficients ``Q`` (``y(x) = y_old + sum_m Q[m] x**(m+1)``) of one step."""
    Q = np.zeros((MAX_ORDER + 1, y_old.size))  # one shape for every step, whatever k
    for j in range(k + 1):
        Q[: j + 1] += np.multiply.outer(_DENSE[j], h * D[j])
    # the integrated polynomial anchored at y_new, moved to pass through y_old at x = 0:
    # y(x) = y_old + x (y_new - y_old - sum(Q)) + sum_m Q[m] x^(m+1)
    Q[0] += (y_new - y_old) - Q.sum(axis=0)
    return Q


def _lazy_dense(y_old, y_new, D, k, h):
    """A zero-argument callable computing :func:`_dense_coefficients` when needed."""
    return lambda: _dense_coefficients(y_old, y_new, D, k, h)


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


#: cache of re-sampling matrices for the usual ratios: 0.25, 0.5 ... 0.9, 2 (the ratios of a
#: reduction are rounded down to tenths for that); other ratios (the last step) are not kept
_RESAMPLE = {}
_USUAL_RATIOS = frozenset([0.25, 0.5, 0.6, 0.7, 0.8, 0.9, 2.0])


def _resample_cached(k, ratio):
    if ratio not in _USUAL_RATIOS:
        return resample_matrix(k, ratio)
    T = _RESAMPLE.get((k, ratio))
    if T is None:
        T = _RESAMPLE[(k, ratio)] = resample_matrix(k, ratio)
    return T


def _next_order(k, knew, phase1, ns, erk, erkm1, erkp1, max_order):
    """Order of the next step after an accepted one, DE/STEP's block 4.

    Returns ``(k_next, erk_next, phase1)``: the order, the error estimate at that order, and
    whether the first phase (raising the order and doubling the step at every step) goes on.
    `knew` is ``k - 1`` when the attempt's estimates asked for a lower order.
    """
    if knew == k - 1 or k == max_order:
        phase1 = False
    if phase1:
        return k + 1, erkp1, True
    if knew == k - 1:
        return k - 1, erkm1, False
    if k + 1 <= ns:
        if k == 1:
            if erkp1 < 0.5 * erk and max_order > 1:
                return 2, erkp1, False
        elif erkm1 <= min(erk, erkp1):
            return k - 1, erkm1, False
        elif erkp1 < erk and k < max_order:
            return k + 1, erkp1, False
    return k, erk, False


def _lower_order(k, erk, erkm1, erkm2):
    """The order the attempt's estimates ask for: ``k`` or ``k - 1`` (DE/STEP, block 2)."""
    if k > 2:
        return k - 1 if max(erkm1, erkm2) <= erk else k
    if k == 2 and erkm1 <= 0.5 * erk:
        return 1
    return k


def _next_ratio(k, erk, phase1, reach, h_abs, max_step):
    """New spacing over old after an accepted step of order `k` (DE/STEP, block 4).

    Doubled when the estimate is 2**(k+1) below half the tolerance (above order
    RESAMPLE_DOUBLING_MAX_ORDER only once the known values of f `reach` back over 2k steps),
    kept while it is below half, else reduced by 0.5..0.9 rounded down to tenths.
    """
    if ((phase1 or 0.5 >= erk * 2.0 ** (k + 1)) and 2.0 * h_abs <= max_step
            and (k <= RESAMPLE_DOUBLING_MAX_ORDER or reach >= 2 * k * h_abs)):
        return 2.0
    if 0.5 >= erk:
        return 1.0
    return max(0.5, min(0.9, math.floor(10.0 * (0.5 / erk) ** (1.0 / (k + 1))) / 10.0))


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
