"""Shared checks and output recording of the fixed-step methods of :mod:`rigidmech.ode`.

Used by :mod:`~rigidmech.ode.runge_kutta`, :mod:`~rigidmech.ode.multistep`,
:mod:`~rigidmech.ode.geometric` and the constant step of :mod:`~rigidmech.ode.rkn`: validation
of ``t_span``, ``y0`` and ``step``, the uniform grid, the one fixed-step loop
(:func:`fixed_loop`: finiteness, progress, Ctrl-C), thinning of the output (``save_every``) and
the assembly of the :class:`~rigidmech.ode.OdeResult` with an optional dense output (cubic
Hermite, or the method's own polynomial).
"""

from __future__ import annotations

import math

import numpy as np

from rigidmech._core.errors import ArgumentError, ArgumentTypeError

from ._dense import DenseSolution, hermite_coefficients
from ._driver import fail_message
from ._loop import _found_sentence, _probe
from ._result import OdeResult

__all__ = ["check_fixed", "FixedRecorder", "fixed_loop", "step_count"]

#: relative slack of :func:`step_count`: a step that divides the span to this is exact
STEP_SLACK = 1e-12


def step_count(length, h):
    """The number of fixed steps of size about `h` over a span of `length`:
    ``ceil(length / h (1 - STEP_SLACK))``, at least 1, so that a step dividing the span up
    to rounding (0.1 over 1) gives the whole number (10), not one more. One rule for the
    fixed-step methods and ``simulate``'s sampling of their grid.

    Examples
    --------
    >>> step_count(1.0, 0.1), step_count(1.0, 0.1 * (1 - 1e-6)), step_count(1.0, 2.0)
    (10, 11, 1)
    """
    return max(1, math.ceil(length / h * (1.0 - STEP_SLACK)))


def check_fixed(t_span, y0, step, max_steps, save_every, *, even=False):
    """Validate the arguments of a fixed-step method and build its uniform grid.

    Returns
    -------
    t0 : float
    h : float
        Signed step, ``(t1 - t0) / nsteps``: the size ``|step|`` rounded down so that the grid
        ends exactly at ``t1`` (the sign of `step` is ignored: ``t_span`` gives the direction).
    nsteps : int
    y0 : ndarray, shape (n,) or (n, batch)
        Fresh float copy.
    save_every : int

    Examples
    --------
    >>> check_fixed((0.0, 1.0), [1.0, 0.0], 0.3, None, 1)[:3]
    (0.0, 0.25, 4)
    """
    try:
        t0, t1 = (float(v) for v in t_span)
    except (TypeError, ValueError):
        raise ArgumentError(f"`t_span` must be two numbers (t0, t1); got {t_span!r}.") from None
    if not (math.isfinite(t0) and math.isfinite(t1)) or t0 == t1:
        raise ArgumentError(f"`t_span` must be two distinct finite times; got {t_span!r}.")
    y = np.array(y0, dtype=float)
    if y.ndim not in (1, 2) or y.shape[0] == 0:
        raise ArgumentError(
            f"`y0` must have shape (n,) or (n, batch); got shape {np.shape(y0)}."
        )
    if even and y.shape[0] % 2:
        raise ArgumentError(
            f"`y0` must be [q0, v0] with as many velocities as positions (an even length); "
            f"got {y.shape[0]} components."
        )
    if not np.all(np.isfinite(y)):
        raise ArgumentError("`y0` must be finite; got a NaN or an infinity.")
    if step is None or isinstance(step, bool):
        raise ArgumentTypeError(
            f"`step` must be a number > 0 for a fixed-step method; got {step!r}."
        )
    try:
        h_req = float(step)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`step` must be a number > 0; got {step!r}.") from None
    h_req = abs(h_req)  # rigidmech.ode.solve passes the signed step
    if not (h_req > 0.0 and math.isfinite(h_req)):
        raise ArgumentError(f"`step` must be a finite nonzero number; got {step!r}.")
    length = abs(t1 - t0)
    nsteps = step_count(length, h_req)
    if max_steps is not None and nsteps > max_steps:
        raise ArgumentError(
            f"`step` = {h_req:g} needs {nsteps} steps over `t_span` {t_span!r}, more than "
            f"`max_steps` = {max_steps}; increase `step` or `max_steps`."
        )
    if isinstance(save_every, bool) or not isinstance(save_every, int | np.integer) or (
        save_every < 1
    ):
        raise ArgumentError(f"`save_every` must be an integer >= 1; got {save_every!r}.")
    return t0, (t1 - t0) / nsteps, nsteps, y, int(save_every)


class FixedRecorder:
    """Collects the states of a fixed-step run and builds the :class:`OdeResult`.

    States are kept every `save_every` steps and at the last step; with `dense` the derivative
    is kept too, and the result carries a ``sol(t)`` through the kept points: cubic Hermite,
    or the polynomial of ``coefficients(y0, y1, f0, f1, h)`` (power form, as
    :func:`~rigidmech.ode._dense.hermite_coefficients`) if given. The states are kept as given
    (fresh arrays, or lists of floats), in the flat or the user shape.
    """

    __slots__ = ("ts", "ys", "fs", "dense", "save_every", "status", "message", "shape",
                 "coefficients", "culprit")

    def __init__(self, t0, y0, f0, save_every, dense, shape=None, coefficients=None):
        self.ts = [t0]
        self.ys = [y0.copy()]
        self.dense = bool(dense)
        self.fs = [np.array(f0, dtype=float)] if self.dense else None
        self.save_every = save_every
        self.status = 0
        self.message = "The integration reached the end of `t_span`."
        self.shape = y0.shape if shape is None else shape
        self.coefficients = coefficients or hermite_coefficients
        self.culprit = None  # where a non-finite right-hand side was found (fixed_loop)

    def add(self, t, y, f=None):
        """Record the state `y` (a fresh array or list, kept) at `t`, with `f` if dense."""
        self.ts.append(t)
        self.ys.append(y)
        if self.dense:
            self.fs.append(np.array(f, dtype=float))

    def result(self, method, nfev, nsteps, stats=None):
        """Build the result: ``y`` of shape (n, m) or (n, m, batch), fresh arrays."""
        t = np.array(self.ts, dtype=float)
        Y = np.array(self.ys, dtype=float).reshape((len(t),) + self.shape)
        y = np.ascontiguousarray(np.moveaxis(Y, 0, 1))
        sol = None
        if self.dense and len(t) > 1:
            flat = Y.reshape(len(t), -1)
            F = np.array(self.fs, dtype=float).reshape(len(t), -1)
            h = np.diff(t)
            coeffs = np.stack(
                [self.coefficients(flat[i], flat[i + 1], F[i], F[i + 1], h[i])
                 for i in range(len(h))]
            )
            sol = DenseSolution(t, flat[:-1], coeffs, "power", self.shape)
        return OdeResult(
            t=t, y=y, nfev=int(nfev), nsteps=int(nsteps),
            nrejected=0, status=self.status, message=self.message, method=method, sol=sol,
            stats={**(stats or {}), **({"culprit": self.culprit} if self.culprit else {})},
            t_stop=float(t[-1]), y_stop=Y[-1].copy(),
        )


def _array_finite(y):
    return math.isfinite(y.sum())  # a sum is nan or inf if one term is


def _small_finite(y):
    return math.isfinite(sum(y.tolist()))  # faster than y.sum() for a few components


def _list_finite(y):
    return math.isfinite(sum(y))


def fixed_loop(advance, rec, t0, h, nsteps, *, t1=None, progress=None, finite=None,
               fun=None):
    """The one loop of the fixed-step methods: `nsteps` steps of size `h` from `t0`.

    ``advance(t, h) -> (y, f)`` makes the step from ``t = t0 + (i - 1) h`` (the method keeps
    its own history) and returns the new state (a fresh array, or a list of floats) and its
    derivative (None unless ``rec.dense``). The loop owns, once for every fixed-step method:
    recording (every ``rec.save_every`` steps and the last), the finiteness of the state at
    every step (status -1 at the first non-finite state: the last finite one ends the
    result), the ``progress(t)`` callback after every step (False stops the run) and Ctrl-C
    (status 2; both keep everything computed so far, the last step made included). The time
    of step ``i`` is ``t0 + i h``; the last one is `t1` if given.

    `finite(y)` defaults to a check of the sum of an array. Given the right-hand side `fun`
    of y' = f(t, y), a non-finite state is explained by evaluating it again from the last
    finite state (a nan or complex component of f named, ``stats["culprit"]``). Returns the
    number of steps made.

    Examples
    --------
    >>> import numpy as np
    >>> rec = FixedRecorder(0.0, np.array([1.0]), None, 1, False)
    >>> fixed_loop(lambda t, h: (np.array([2.0 ** (t + h)]), None), rec, 0.0, 0.5, 2)
    2
    >>> rec.ts, [float(v[0]) for v in rec.ys]
    ([0.0, 0.5, 1.0], [1.0, 1.4142135623730951, 2.0])
    """
    if finite is None:
        y0 = rec.ys[0]
        finite = _small_finite if y0.ndim == 1 and y0.size <= 32 else _array_finite
    every, dense = rec.save_every, rec.dense
    ts_append, ys_append = rec.ts.append, rec.ys.append
    t_prev, y_last, f_last = t0, None, None  # the last step made
    i = 0
    try:
        for i in range(1, nsteps + 1):
            y, f = advance(t0 + (i - 1) * h, h)
            t = t1 if i == nsteps and t1 is not None else t0 + i * h
            if not finite(y):
                _keep(rec, t_prev, y_last, f_last)
                bad = y if isinstance(y, np.ndarray) else np.array(y, dtype=float)
                rec.status = -1
                rec.message = fail_message("The state became non-finite", t, bad, rec.shape)
                if fun is not None:
                    _explain(rec, fun, t_prev, rec.ys[-1] if y_last is None else y_last, h)
                return i - 1
            if every == 1 or i % every == 0 or i == nsteps:
                if dense:
                    rec.add(t, y, f)
                else:
                    ts_append(t)
                    ys_append(y)
            t_prev, y_last, f_last = t, y, f
            if progress is not None and progress(t) is False:
                _keep(rec, t, y, f)
                _interrupt(rec, "The integration was stopped by the `progress` callback", t)
                return i
    except KeyboardInterrupt:  # during step i: steps up to i - 1 are kept
        _keep(rec, t_prev, y_last, f_last)
        _interrupt(rec, "The integration was interrupted (KeyboardInterrupt)", t_prev)
        return i - 1
    return nsteps


def _explain(rec, fun, t, y, h):
    """Name the component of `fun` that is not finite (or complex) near the last finite
    state ``(t, y)``, on the failure path only (:func:`rigidmech.ode._loop._probe`)."""
    found = _probe(fun, t, np.asarray(y, dtype=float).reshape(-1), h, rec.shape)
    if found is not None:
        rec.message += _found_sentence(found, rec)


def _keep(rec, t, y, f):
    """Record the last step made, if it was not recorded (thinned output)."""
    if rec.ts[-1] != t and y is not None:
        rec.add(t, y, f)


def _interrupt(rec, reason, t):
    rec.status = 2
    rec.message = f"{reason} at t = {float(t)!r}; the result holds the steps made so far."
