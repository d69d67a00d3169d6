"""Shared machinery of the step-by-step integrators: error norm, initial step, recording.

Internally every integrator works on a *flat* state of length ``N = n * batch`` so that one
code path serves a single trajectory and a batch; :class:`Problem` reshapes to the user's shape
``(n,)`` or ``(n, batch)`` only when calling ``fun`` and when returning results.
"""

from __future__ import annotations

import math

import numpy as np

from ._dense import DenseSolution, evaluate
from ._result import OdeResult

__all__ = ["Problem", "Recorder", "SampleRecorder", "Stops", "initial_step", "fail_message",
           "flat_tolerance"]


class Stops:
    """Times the steps must land on (``t_eval`` of a method sampled at its steps), in order.

    Examples
    --------
    >>> s = Stops([0.5, 1.0, 1.5], (0.0, 2.0))
    >>> s.after(0.0), s.after(0.5), s.after(1.7)
    (0.5, 1.0, 2.0)
    """

    __slots__ = ("_times", "_i", "_end", "_sign")

    def __init__(self, t_eval, t_span):
        self._times = [] if t_eval is None else [float(v) for v in t_eval]
        self._i = 0
        self._end = float(t_span[1])
        self._sign = 1.0 if t_span[1] >= t_span[0] else -1.0

    @property
    def times(self):
        """The stops, in order (the samples a method landing on them keeps)."""
        return self._times

    def after(self, t):
        """The first stop strictly beyond `t` in the direction of integration, else the end."""
        times, sign = self._times, self._sign
        while self._i < len(times) and sign * (times[self._i] - t) <= 0:
            self._i += 1
        return times[self._i] if self._i < len(times) else self._end


def flat_tolerance(atol, shape):
    """`atol` as a fresh flat array of ``prod(shape)`` floats.

    `atol` is a number, an array of the flat size (as :func:`~rigidmech.ode.solve` passes it),
    an array of shape ``(n,)`` (one tolerance per component, shared by a batch) or of `shape`.

    Examples
    --------
    >>> flat_tolerance([1.0, 2.0], (2, 3)).tolist()
    [1.0, 1.0, 1.0, 2.0, 2.0, 2.0]
    """
    a = np.asarray(atol, dtype=float)
    size = math.prod(shape)
    if a.size == size:
        return a.reshape(-1).copy()
    if a.ndim == 1 and len(shape) == 2:
        a = a[:, None]
    return np.broadcast_to(a, shape).reshape(-1).copy()


class Problem:
    """The right-hand side seen through the flat state, plus the norm used for error control.

    Parameters
    ----------
    fun : callable
        ``fun(t, y)`` with ``y`` of shape `shape`.
    shape : tuple
        ``(n,)`` or ``(n, batch)``.

    Notes
    -----
    The error norm is Hairer's weighted root-mean-square norm
    ``sqrt(mean((e / (atol + rtol max(|y0|, |y1|)))**2))``; for a batch it is taken per
    trajectory and the maximum over the batch drives the shared step.

    Examples
    --------
    >>> import numpy as np
    >>> p = Problem(lambda t, y: -y, (2, 3))
    >>> p.norm(np.ones(6)), p.nfev
    (1.0, 0)
    """

    __slots__ = ("fun", "shape", "batch", "nfev")

    def __init__(self, fun, shape):
        self.fun = fun
        self.shape = tuple(shape)
        self.batch = len(self.shape) == 2
        self.nfev = 0

    def __call__(self, t, y, out):
        """Evaluate ``fun(t, y)`` and COPY the result into `out` (never keep fun's array)."""
        self.nfev += 1
        if self.batch:
            f = self.fun(t, y.reshape(self.shape))
            out.reshape(self.shape)[...] = f
        else:
            out[...] = self.fun(t, y)
        return out

    def norm(self, x):
        """Weighted RMS norm of an already scaled vector `x` (max over a batch)."""
        if self.batch:
            x = x.reshape(self.shape)
            return float(np.sqrt(np.max(np.mean(x * x, axis=0))))
        return float(np.sqrt(np.dot(x, x) / x.size))


def initial_step(problem, t0, y0, f0, direction, order, rtol, atol, t_bound, max_step):
    """Hairer's starting step size (HNW I, II.4, algorithm of p. 169).

    Returns
    -------
    float
        Absolute value of the first step.
    """
    length = abs(t_bound - t0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        scale = atol + np.abs(y0) * rtol
        d0 = problem.norm(y0 / scale)
        d1 = problem.norm(f0 / scale)
        ok = math.isfinite(d0) and math.isfinite(d1)
        h0 = 1e-6 if (not ok or d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
        h0 = min(h0, length)
        f1 = problem(t0 + direction * h0, y0 + direction * h0 * f0, np.empty_like(y0))
        d2 = problem.norm((f1 - f0) / scale) / h0
        if not (ok and math.isfinite(d2)):
            h1 = max(1e-6, h0 * 1e-3)
        elif d1 <= 1e-15 and d2 <= 1e-15:
            h1 = max(1e-6, h0 * 1e-3)
        else:
            h1 = (0.01 / max(d1, d2)) ** (1.0 / (order + 1))
    return min(100 * h0, h1, length, max_step)


def fail_message(reason, t, y, shape):
    """One sentence naming the reason, the time and the state of a numerical failure."""
    state = np.array2string(np.asarray(y).reshape(shape), precision=6, threshold=12)
    return f"{reason} at t = {float(t)!r}; state y = {state}."


class Recorder:
    """Collects accepted steps, dense coefficients and events, then builds the result.

    Parameters
    ----------
    t0 : float
    y0 : ndarray, shape (N,)
    shape : tuple
        User shape of a state.
    dense : bool
        Whether per-step coefficients are collected (dense output, ``t_eval`` or events).
    events : EventTracker or None
    form : {"power", "nested"}
        Form of the dense coefficients (see :class:`DenseSolution`).
    """

    __slots__ = ("ts", "ys", "cs", "shape", "events", "form", "status", "message",
                 "_last_full_end", "culprit")

    def __init__(self, t0, y0, shape, dense, events, form="power"):
        self.ts = [t0]
        self.ys = [y0.copy()]
        self.cs = [] if dense else None
        self.shape = shape
        self.events = events
        self.form = form
        self.status = 0
        self.message = "The integration reached the end of `t_span`."
        #: where a run failed on a non-finite or complex value (see ``OdeResult.stats``)
        self.culprit = None

    def accept(self, t_new, y_new, coeffs=None, exact=None):
        """Record one accepted step; return True if a terminal event fired.

        `y_new` is kept as it is: the integrators pass a fresh array that they never modify.

        `coeffs` holds the dense coefficients of the step, or a zero-argument callable
        computing them (called only if they are needed: dense output, or a sign change of an
        event function). `exact`, if given, is ``s -> y(s)`` inside the step as accurate as the
        step (for a method whose interpolant is less so): event times are refined on it.
        """
        t_old = self.ts[-1]
        y_old = self.ys[-1]
        self.ts.append(t_new)
        self.ys.append(y_new)
        if self.cs is not None:
            if callable(coeffs):
                coeffs = coeffs()
            self.cs.append(coeffs)
        if self.events is not None:
            box = [coeffs]

            def interp(t):
                if callable(box[0]):
                    box[0] = box[0]()
                step = DenseSolution([t_old, t_new], y_old[None], box[0][None], self.form,
                                     self.shape)
                return step(t)

            if self.events.check(t_old, t_new, y_new.reshape(self.shape), interp, exact):
                if callable(box[0]):
                    box[0] = box[0]()
                if self.cs is not None:
                    self.cs[-1] = box[0]
                self._last_full_end = t_new
                self.ts[-1] = self.events.t_stop
                self.ys[-1] = self.events.y_stop.reshape(-1)
                self.status = 1
                self.message = "A terminal event occurred."
                return True
        return False

    def fail(self, reason, t, y):
        """Mark the integration as failed (status -1) at time `t`, state `y`."""
        self.status = -1
        self.message = fail_message(reason, t, y, self.shape)

    @property
    def needs_dense(self):
        """Whether the steps' dense coefficients are needed (dense output or events)."""
        return self.cs is not None or self.events is not None

    def interrupt(self, reason, t):
        """Mark the integration as stopped early on request (status 2) at time `t`; what was
        computed so far is kept."""
        self.status = 2
        self.message = f"{reason} at t = {float(t)!r}; the result holds the steps made so far."

    def result(self, method, nfev, nrejected, stats=None):
        """Build the :class:`OdeResult` (fresh arrays, user shapes)."""
        t = np.array(self.ts, dtype=float)
        Y = np.array(self.ys, dtype=float)  # (m, N)
        y = np.ascontiguousarray(np.moveaxis(Y.reshape((len(t),) + self.shape), 0, 1))
        sol = None
        if self.cs is not None and len(self.cs):
            t_nodes = np.array(self.ts, dtype=float)
            if self.status == 1:  # the last step's polynomial is normalised on its full length
                t_nodes[-1] = self._last_full_end
            sol = DenseSolution(t_nodes, np.array(self.ys[:-1]), np.array(self.cs), self.form,
                                self.shape)
        ev = self.events
        return OdeResult(
            t=t, y=y, nfev=nfev, nsteps=len(t) - 1, nrejected=nrejected, status=self.status,
            message=self.message, method=method, sol=sol,
            t_events=ev.t_events if ev is not None else [],
            y_events=ev.y_events if ev is not None else [],
            stats=dict(stats or {}), **self.reached(),
        )

    def reached(self):
        """``t_stop`` and ``y_stop`` of the result: the last accepted step (or event)."""
        return {"t_stop": float(self.ts[-1]),
                "y_stop": np.array(self.ys[-1], dtype=float).reshape(self.shape)}


class SampleRecorder(Recorder):
    """A :class:`Recorder` that keeps only the states at `t_eval`: memory proportional to the
    samples asked for, not to the number of steps.

    Each sample is evaluated on the dense polynomial of the step that contains it, as the
    full dense output would (a sample at a step's end belongs to the next step, the last ones
    to the last step), so the numbers are the same as with full recording. With
    ``at_steps=True`` the steps land on the samples (see :class:`Stops`) and the samples are
    the steps' own states.

    Examples
    --------
    >>> import numpy as np
    >>> rec = SampleRecorder(0.0, np.array([1.0]), (1,), None, [0.25, 1.0])
    >>> rec.accept(1.0, np.array([2.0]), np.array([[1.0]]))  # y = 1 + x on the step
    False
    >>> r = rec.result("demo", 1, 0)
    >>> r.t.tolist(), r.y.tolist(), r.nsteps
    ([0.25, 1.0], [[1.25, 2.0]], 1)
    """

    __slots__ = ("_samples", "_next", "_n", "_i", "_sign", "_t_prev", "_y_prev",
                 "_last", "_at_steps", "_nsteps", "_queue")

    def __init__(self, t0, y0, shape, events, t_eval, form="power", at_steps=False):
        super().__init__(t0, y0, shape, False, events, form)
        self._samples = np.asarray(t_eval, dtype=float)
        n = len(self._samples)
        self._sign = -1.0 if n >= 2 and self._samples[-1] < self._samples[0] else 1.0
        self._next, self._n = self._samples.tolist(), n
        self._i = 0
        self._t_prev, self._y_prev = t0, self.ys[0]
        self._last = None  # [t_old, t_new, y_old, coeffs] of the last accepted step
        self._at_steps = at_steps
        self._nsteps = 0
        self._queue = []  # (time, step) of samples not yet evaluated
        self.ts, self.ys = [], []
        if at_steps:
            self._take_exact(t0, self._y_prev)

    @property
    def needs_dense(self):
        return not self._at_steps or self.events is not None

    def _take_exact(self, t, y):
        samples = self._samples
        while self._i < len(samples) and samples[self._i] == t:
            self.ts.append(float(t))
            self.ys.append(np.array(y, dtype=float).reshape(-1))
            self._i += 1

    def _coeffs(self):
        last = self._last
        if callable(last[3]):
            last[3] = last[3]()
        return last[3]

    def _poly(self):
        t_old, t_new, y_old, _ = self._last
        y_old = np.asarray(y_old, dtype=float).reshape(-1)
        return DenseSolution([t_old, t_new], y_old[None], self._coeffs()[None], self.form,
                             self.shape)

    def _take(self, t_hi, inclusive):
        """Queue the samples before `t_hi` (and at it if `inclusive`) on the last step."""
        i, sign, nxt, n = self._i, self._sign, self._next, self._n
        j = i  # the samples as floats: a few per step at most, a scan beats a search
        while j < n and (sign * (nxt[j] - t_hi) < 0 or (inclusive and nxt[j] == t_hi)):
            j += 1
        if j > self._i:
            t_old, t_new, y_old, coeffs = self._last
            if type(y_old) is not np.ndarray:  # a list of floats (first step of the float path)
                y_old = np.asarray(y_old, dtype=float).reshape(-1)
            if callable(coeffs):
                coeffs = self._coeffs()
            self._queue.append((t_old, t_new - t_old, y_old, coeffs, self._i, j))
            self._i = j
            if len(self._queue) >= 256:
                self._flush()

    def _flush(self):
        """Evaluate the queued samples at once (the same arithmetic as the dense output)."""
        q = self._queue
        if not q:
            return
        lo, hi = q[0][4], q[-1][5]
        idx = np.repeat(np.arange(len(q)), [e[5] - e[4] for e in q])
        t = self._samples[lo:hi]
        values = evaluate(t, np.array([e[0] for e in q])[idx], np.array([e[1] for e in q])[idx],
                          np.array([e[2] for e in q])[idx], np.array([e[3] for e in q])[idx],
                          self.form)
        self.ts.extend(t.tolist())
        self.ys.extend(values)
        self._queue = []

    def accept(self, t_new, y_new, coeffs=None, exact=None):
        t_old, y_old = self._t_prev, self._y_prev
        self._nsteps += 1
        self._last = [t_old, t_new, y_old, coeffs]
        stop = self.events is not None and self.events.check(
            t_old, t_new, np.asarray(y_new).reshape(self.shape),
            lambda t: self._poly()(t), exact)
        t_end, y_end = (self.events.t_stop, self.events.y_stop) if stop else (t_new, y_new)
        if self._at_steps:
            self._take_exact(t_end, y_end)
        else:
            self._take(t_end, stop)
        self._t_prev, self._y_prev = t_end, y_end
        if stop:
            self.status = 1
            self.message = "A terminal event occurred."
        return stop

    def result(self, method, nfev, nrejected, stats=None):
        if self._last is not None and not self._at_steps:
            self._take(self._t_prev, True)  # the end (or where the run stopped)
            self._flush()
        t = np.array(self.ts, dtype=float)
        Y = np.array(self.ys, dtype=float).reshape((len(t),) + self.shape)
        ev = self.events
        return OdeResult(
            t=t, y=np.ascontiguousarray(np.moveaxis(Y, 0, 1)), nfev=nfev, nsteps=self._nsteps,
            nrejected=nrejected, status=self.status, message=self.message, method=method,
            t_events=ev.t_events if ev is not None else [],
            y_events=ev.y_events if ev is not None else [], stats=dict(stats or {}),
            **self.reached(),
        )

    def reached(self):
        return {"t_stop": float(self._t_prev),
                "y_stop": np.array(self._y_prev, dtype=float).reshape(self.shape)}
