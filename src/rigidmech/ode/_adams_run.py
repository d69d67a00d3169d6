"""The steps of the adaptive Adams method (:mod:`rigidmech.ode.adams`, book 26.3): one PECE
attempt, and the *runs* of steps at constant spacing -- generated plain-float code for a few
equations, numpy arrays for batches and larger systems.

Also the rules the driver applies after a step (order: ``_next_order``, ``_lower_order``;
step size: ``_next_ratio``), which the generated runs repeat. Private: the driver,
:mod:`rigidmech.ode.adams`, calls these and re-exports them.
"""

from __future__ import annotations

import math

import numpy as np

from ._adams_tables import _G, _GS, MAX_ORDER, RESAMPLE_DOUBLING_MAX_ORDER, STIFF_MAX_ORDER
from ._floatpath import cached, compile_function

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


# --- the driver's rules of order and step size (the runs above apply the same) -------------


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
