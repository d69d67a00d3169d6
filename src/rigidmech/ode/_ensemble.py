"""Per-trajectory step sizes over a batch, in vectorised form (book, ch. 26.2).

A batch ``y0`` of shape ``(n, batch)`` integrated by an embedded pair (``dopri5``, ``dop853``,
``bs32``) with ``stepping="each"``: every trajectory has its own time, step size, error norm
and accept/reject decision (the same controller as one trajectory alone, column by column),
while the stages of all the trajectories still running are evaluated in ONE call of the
right-hand side on the active columns. A trajectory that reaches the end of ``t_span`` (or
fails) leaves the active set, which is compacted, so that the evaluations follow the work
each trajectory needs, not the hardest one's pace.

What the right-hand side receives: ``fun(t, y)`` with ``y`` of shape ``(n, m)`` (the ``m``
trajectories still running, in their order in the batch) and ``t`` a float64 array of shape
``(m,)``, the time of each column (an autonomous ``fun`` ignores it; a non-autonomous one
must broadcast it over the last axis). A ``fun`` that binds data to the batch's columns
(parameters of shape ``(batch,)``) cannot follow the compaction: use
``stepping="shared"``.

The samples: at ``t_eval`` (each trajectory's interpolant of the step that covers a sample
time; DOP853's seventh-order one costs three more evaluations, made only on the columns that
have a sample in their step), else at ``t0`` and ``t1`` only (the trajectories have no common
steps). No dense output, events, projection or stiffness test in this mode (``solve`` keeps
the one-step-for-all path for those). ``progress(t)`` is called after every pass with the
earliest time of the trajectories still running.
"""

from __future__ import annotations

import math

import numpy as np

from rigidmech._core.errors import ArgumentError

from . import tableaux
from ._dense import evaluate
from ._driver import flat_tolerance
from ._loop import MAX_FACTOR, MIN_FACTOR, PI_ERR_FLOOR, PI_KI, PI_KP, SAFETY
from ._result import OdeResult

__all__ = ["STEPPING", "integrate_each", "choose_stepping"]

#: The values of the option ``stepping`` of the embedded pairs.
STEPPING = ("auto", "each", "shared")


def choose_stepping(stepping, *, batch, t_eval, dense_output, events, project):
    """``"each"`` or ``"shared"``: how the steps of a run are chosen (the one rule).

    ``"auto"`` (the default) is ``"each"`` for a batch sampled at `t_eval` without dense
    output, events or projection, else ``"shared"`` (the outputs ``"each"`` cannot give: a
    common step grid, a continuous solution). ``"each"`` asked for with one of those is
    refused. A single trajectory is always ``"shared"`` (one column).

    Examples
    --------
    >>> choose_stepping("auto", batch=True, t_eval=[1.0], dense_output=False, events=None,
    ...                    project=None)
    'each'
    >>> choose_stepping("auto", batch=True, t_eval=None, dense_output=False, events=None,
    ...                    project=None)
    'shared'
    """
    if not isinstance(stepping, str) or stepping not in STEPPING:
        raise ArgumentError(
            f"`stepping` must be one of {STEPPING} (\"each\": a step size per "
            f"trajectory, \"shared\": one step for the whole batch); got {stepping!r}.")
    if not batch:
        return "shared"
    blockers = [name for name, on in (("dense_output=True", dense_output),
                                      ("events", events is not None),
                                      ("project", project is not None)) if on]
    if stepping == "each" and blockers:
        raise ArgumentError(
            f"`stepping`=\"each\" gives samples at `t_eval` per trajectory; got "
            f"{' and '.join(blockers)}, which need one step grid for the whole batch: pass "
            f"stepping=\"shared\" (or drop {blockers[0]}).")
    if stepping == "auto":
        return "each" if t_eval is not None and not blockers else "shared"
    return stepping


def _initial_steps(fun, t0, y0, f0, direction, order, rtol, atol, t_end, max_step):
    """Hairer's starting step (HNW I, II.4), column by column (`y0`, `f0`: (n, m))."""
    length = abs(t_end - t0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        scale = atol + np.abs(y0) * rtol
        d0 = np.sqrt(np.mean((y0 / scale) ** 2, axis=0))
        d1 = np.sqrt(np.mean((f0 / scale) ** 2, axis=0))
        ok = np.isfinite(d0) & np.isfinite(d1)
        h0 = np.where(~ok | (d0 < 1e-5) | (d1 < 1e-5), 1e-6, 0.01 * d0 / d1)
        h0 = np.minimum(h0, length)
        f1 = np.asarray(fun(t0 + direction * h0, y0 + direction * h0 * f0), dtype=float)
        d2 = np.sqrt(np.mean(((f1 - f0) / scale) ** 2, axis=0)) / h0
        small = ~(ok & np.isfinite(d2)) | ((d1 <= 1e-15) & (d2 <= 1e-15))
        h1 = np.where(small, np.maximum(1e-6, h0 * 1e-3),
                      (0.01 / np.maximum(d1, d2)) ** (1.0 / (order + 1)))
    return np.minimum(np.minimum(100 * h0, h1), min(length, max_step))


class _Columns:
    """``fun`` on the active columns: counts the calls and checks the shape once."""

    __slots__ = ("fun", "batch", "calls", "columns")

    def __init__(self, fun, batch):
        self.fun, self.batch, self.calls, self.columns = fun, batch, 0, 0

    def __call__(self, t, y):
        self.calls += 1
        self.columns += y.shape[1]
        try:
            out = self.fun(t, y)
        except ValueError as exc:  # a broadcast against data bound to the batch's columns
            if y.shape[1] == self.batch:
                raise
            raise ArgumentError(self._hint(y, f"it raised {type(exc).__name__}: {exc}")) from exc
        if (out.shape if type(out) is np.ndarray else np.shape(out)) != y.shape:
            raise ArgumentError(self._hint(y, f"got shape {np.shape(out)}"))
        return out

    def _hint(self, y, what):
        m = y.shape[1]
        return (f"`fun(t, y)` must return an array of the shape of its `y`, {y.shape}; {what}."
                f" With `stepping`=\"each\" fun receives the {m} of {self.batch} "
                f"trajectories still running and their times `t` (shape ({m},)): a fun that "
                "binds data to the batch's columns needs stepping=\"shared\".")


def _error_norms(pair, K, scale, h_abs, n):
    """The error norm of each column (Hairer's RMS norm, or DOP853's combination)."""
    s1 = pair.s + 1
    flat = K[:s1].reshape(s1, -1)
    if len(pair.errors) == 1:
        e = (pair.errors[0] @ flat).reshape(scale.shape) / scale
        return h_abs * np.sqrt(np.mean(e * e, axis=0))
    e53 = (pair.E @ flat).reshape((2,) + scale.shape)
    e53 /= scale
    s5, s3 = np.einsum("kij,kij->kj", e53, e53)
    den = s5 + 0.01 * s3
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(den > 0, h_abs * s5 / np.sqrt(den * n), np.where(den == 0, 0.0, den))


def _dense(pair, cols, t, y, y_new, h, K):
    """Dense coefficients (m, p, n) of the steps of the columns (``t``, ``h``: (m,))."""
    if pair.name == "dopri5":
        c = np.einsum("pk,knm->mpn", tableaux.DOPRI5_P.T, K[: pair.s + 1])
        return c * h[:, None, None], "power"
    if pair.name == "bs32":
        f0, f1 = K[0] * h, K[pair.s] * h
        dy = y_new - y
        c = np.stack([f0, 3.0 * dy - 2.0 * f0 - f1, f0 + f1 - 2.0 * dy])
        return np.transpose(c, (2, 0, 1)), "power"
    Kc = np.empty((16,) + y.shape)
    Kc[:13] = K[:13]
    for j, (a, cj) in enumerate(zip(tableaux.DOP853_A_EXTRA, tableaux.DOP853_C_EXTRA,
                                    strict=True)):
        k = 13 + j
        Kc[k] = cols(t + cj * h, y + h * np.tensordot(a[:k], Kc[:k], axes=1))
    dy = y_new - y
    F = np.empty((7,) + y.shape)
    F[0] = dy
    F[1] = h * Kc[0] - dy
    F[2] = 2.0 * dy - h * (Kc[12] + Kc[0])
    F[3:] = h * np.tensordot(tableaux.DOP853_D, Kc, axes=1)
    return np.transpose(F, (2, 0, 1)), "nested"


class _State:
    """The working arrays of the active columns (compacted together)."""

    def __init__(self, **arrays):
        self.__dict__.update(arrays)

    def keep(self, mask, names):
        for name in names:  # the columns are the last axis of every array
            self.__dict__[name] = self.__dict__[name][..., mask]


def integrate_each(pair, fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps,
                   step_control, progress, t_eval):
    """Integrate the batch `y0` (n, batch) with a step size per trajectory (module docstring).

    Returns an :class:`~rigidmech.ode.OdeResult` whose ``y`` has shape
    ``(n, len(t), batch)``; ``nfev`` counts the calls of `fun` (one call on the active columns
    counts once), ``nsteps``/``nrejected`` are the largest per trajectory; ``stats`` holds the
    per-trajectory ``nsteps_each``, ``nrejected_each``, ``t_stop_each`` and the column
    evaluations ``nfev_columns`` (what a loop of single runs would count, less its checks).

    Examples
    --------
    >>> from rigidmech import ode
    >>> y0 = np.array([[1.0, 2.0]])
    >>> r = ode.solve(lambda t, y: -y, (0.0, 1.0), y0, t_eval=[1.0], stepping="each",
    ...               rtol=1e-10)
    >>> np.round(r.y[0, -1], 8).tolist(), r.stats["stepping"]
    ([0.36787944, 0.73575888], 'each')
    """
    n, batch = y0.shape
    t0, t_end = t_span
    direction = 1.0 if t_end > t0 else -1.0
    t_out = np.array([t0, t_end]) if t_eval is None else np.asarray(t_eval, dtype=float)
    n_out = len(t_out)
    Y = np.full((n, n_out, batch), np.nan)
    cols = _Columns(fun, batch)
    atol_all = flat_tolerance(atol, (n, batch)).reshape(n, batch)
    exponent = -1.0 / (pair.capabilities.error_order + 1)
    k_pi = pair.capabilities.error_order + 1
    alpha, beta, pi = -PI_KI / k_pi, PI_KP / k_pi, step_control == "pi"
    nacc = np.zeros(batch, dtype=np.int64)
    nrej = np.zeros(batch, dtype=np.int64)
    t_stop = np.full(batch, t0)
    y_stop = y0.copy()
    failures = {}  # member -> reason
    status, message = 0, "The solver successfully reached the end of the integration interval."
    # samples at t0
    at0 = np.flatnonzero(t_out == t0)
    Y[:, at0, :] = y0[:, None, :]
    next_k = np.full(batch, len(at0), dtype=np.int64)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        f0 = np.array(cols(np.full(batch, t0), y0.copy()), dtype=float)
        if first_step is None:
            h_abs = _initial_steps(cols, t0, y0, f0, direction, pair.capabilities.error_order,
                                   rtol, atol_all, t_end, max_step)
        else:
            h_abs = np.full(batch, float(first_step))
    s = pair.s
    st = _State(ids=np.arange(batch), t=np.full(batch, t0), y=y0.copy(), f=f0, h=h_abs,
                atol=atol_all, rejected=np.zeros(batch, bool), err_old=np.ones(batch))
    bad0 = ~np.isfinite(f0).all(axis=0)
    if bad0.any():
        for j in np.flatnonzero(bad0):
            failures[int(j)] = f"the right-hand side is not finite at t = {t0!r}"
        st.keep(~bad0, _NAMES)
    Ab, c_nodes = pair.Ab, pair.c
    try:
        while st.ids.size:
            st = _pass(pair, cols, st, t_end, direction, rtol, max_step, max_steps, exponent,
                       alpha, beta, pi, s, Ab, c_nodes, t_out, n_out, Y, next_k, nacc, nrej,
                       t_stop, y_stop, failures)
            if progress is not None and st.ids.size and progress(float(
                    st.t.min() if direction > 0 else st.t.max())) is False:
                status, message = 2, "The integration was stopped by the `progress` callback"
                break
    except KeyboardInterrupt:  # everything computed so far is kept
        status, message = 2, "The integration was interrupted (KeyboardInterrupt)"
    t_stop[st.ids] = st.t  # the columns still running (a run stopped early)
    y_stop[:, st.ids] = st.y
    if status == 2:
        message += (f" at t = {float(t_stop.min() if direction > 0 else t_stop.max())!r} "
                    f"(the earliest of the batch); {int(np.sum(t_stop != t_end))} of "
                    f"{batch} trajectories unfinished.")
    elif failures:
        status = -1
        first = min(failures)
        message = (f"{len(failures)} of {batch} trajectories failed (their samples after the "
                   f"failure are nan; the others are complete). Batch member {first} "
                   f"(y0[:, {first}]): {failures[first]}.")
    stats = {"stepping": "each", "nsteps_each": nacc, "nrejected_each": nrej,
             "t_stop_each": t_stop, "nfev_columns": cols.columns}
    if failures:
        stats["failed_members"] = sorted(failures)
    reached = float(t_stop.min() if direction > 0 else t_stop.max())
    return OdeResult(t=t_out, y=Y, nfev=cols.calls,
                     nsteps=int(nacc.max()), nrejected=int(nrej.max()), status=status,
                     message=message, method=pair.name, stats=stats, t_stop=reached,
                     y_stop=y_stop)


_NAMES = ("ids", "t", "y", "f", "h", "atol", "rejected", "err_old")


def _pass(pair, cols, st, t_end, direction, rtol, max_step, max_steps, exponent, alpha, beta,
          pi, s, Ab, c_nodes, t_out, n_out, Y, next_k, nacc, nrej, t_stop, y_stop, failures):
    """One attempted step of every active column; returns the state, compacted if columns
    finished or failed (a failure removes its column only)."""
    t, y, ids = st.t, st.y, st.ids
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        min_step = 10.0 * np.abs(np.nextafter(t, direction * math.inf) - t)
        h_abs = np.minimum(np.maximum(st.h, min_step), max_step)  # np.clip, less overhead
        t_new = t + h_abs * direction
        past = direction * (t_new - t_end) > 0
        t_new[past] = t_end
        h = t_new - t
        h_abs = np.abs(h)
        K = np.empty((s + 1,) + y.shape)
        K[0] = st.f
        K2, dot, shape = K.reshape(s + 1, -1), np.dot, y.shape  # the stages as rows
        ch = np.multiply.outer(c_nodes, h)  # the stages' c_i h, one operation
        for i in range(1, s):
            ys = dot(Ab[i, :i], K2[:i]).reshape(shape)
            ys *= h
            ys += y
            K[i] = cols(t + ch[i], ys)
        y_new = dot(Ab[s, :s], K2[:s]).reshape(shape)
        y_new *= h
        y_new += y
        K[s] = cols(t_new, y_new)
        scale = st.atol + rtol * np.maximum(np.abs(y), np.abs(y_new))
        err = _error_norms(pair, K, scale, h_abs, y.shape[0])
        accepted = err < 1.0
        # the controller of the loop (rigidmech.ode._loop.Controller), column by column
        plain = SAFETY * err ** exponent  # the integral controller; also the shrink factor
        powered = SAFETY * err ** alpha * st.err_old ** beta if pi else plain
        grow = np.where(err == 0.0, MAX_FACTOR, np.minimum(MAX_FACTOR, powered))
        grow = np.where(st.rejected, np.minimum(1.0, grow), grow)
        shrink = np.where(np.isfinite(err), np.maximum(MIN_FACTOR, plain), MIN_FACTOR)
        h_next = h_abs * np.where(accepted, grow, shrink)
        if pi:
            st.err_old = np.where(accepted, np.maximum(err, PI_ERR_FLOOR), st.err_old)
        # one reduction: finite iff its sum is
        finite = np.isfinite(y_new.sum(axis=0) + K[s].sum(axis=0))
    ok = accepted & finite
    gone = None
    if not ok.all():
        gone = np.zeros(ids.size, bool)
        for j in np.flatnonzero(accepted & ~finite):
            failures[int(ids[j])] = (f"the state or the right-hand side became non-finite at "
                                     f"t = {float(t_new[j])!r}")
            gone[j] = True
        rej = ~accepted
        nrej[ids[rej]] += 1
        under = rej & ~(h_next >= min_step)  # also a nan step
        for j in np.flatnonzero(under):
            failures[int(ids[j])] = (f"the step size fell below the resolution of t (step "
                                     f"size underflow) at t = {float(t[j])!r}")
            gone[j] = True
        st.rejected = rej
    elif st.rejected.any():
        st.rejected = ~accepted
    if ok.any():
        _samples(pair, cols, ok, ids, t, y, y_new, h, t_new, K, t_out, n_out, Y, next_k,
                 direction)
        nacc[ids[ok]] += 1
        if gone is None:  # every column accepted (the common case): no masking
            st.t, st.y, st.f = t_new, y_new, K[s]
            done = t_new == t_end
        else:
            st.t = np.where(ok, t_new, t)
            st.y = np.where(ok, y_new, y)
            st.f = np.where(ok, K[s], st.f)
            done = ok & (t_new == t_end)
        over = ok & ~done & (nacc[ids] >= max_steps)
        for j in np.flatnonzero(over):
            failures[int(ids[j])] = (f"the maximum number of steps `max_steps` = {max_steps} "
                                     f"was reached at t = {float(t_new[j])!r}")
        done |= over
        gone = done if gone is None else gone | done
    st.h = h_next
    if gone is not None and gone.any():
        leaving = ids[gone]
        t_stop[leaving] = st.t[gone]
        y_stop[:, leaving] = st.y[:, gone]
        st.keep(~gone, _NAMES)
    return st


def _samples(pair, cols, ok, ids, t, y, y_new, h, t_new, K, t_out, n_out, Y, next_k,
             direction):
    """The samples of `t_out` inside the accepted steps, from each step's interpolant."""
    kk = next_k[ids]
    has = ok & (kk < n_out)
    has[has] = direction * (t_out[kk[has]] - t_new[has]) <= 0
    if not has.any():
        return
    J = np.flatnonzero(has)
    landed = t_out[kk[J]] == t_new[J]  # the step ends on its only sample: no interpolant
    if landed.any():
        L = J[landed]
        Y[:, kk[L], ids[L]] = y_new[:, L]
        next_k[ids[L]] += 1
        J = J[~landed]
        if not J.size:
            return
    coeffs, form = _dense(pair, cols, t[J], y[:, J], y_new[:, J], h[J], K[:, :, J])
    y0T, ynT = y[:, J].T, y_new[:, J].T
    members = ids[J]
    while J.size:
        k = next_k[members]
        ts = t_out[k]
        vals = evaluate(ts, t[J], h[J], y0T, coeffs, form)  # (m, n)
        exact = ts == t_new[J]
        vals[exact] = ynT[exact]
        Y[:, k, members] = vals.T
        next_k[members] = k + 1
        more = (k + 1 < n_out)
        more[more] = direction * (t_out[k[more] + 1] - t_new[J[more]]) <= 0
        J, members, coeffs = J[more], members[more], coeffs[more]
        y0T, ynT = y0T[more], ynT[more]
