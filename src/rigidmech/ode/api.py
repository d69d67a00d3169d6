"""One entry point for every integration method: :func:`solve` (book, Part VI, ch. 26-27).

:func:`solve` validates its arguments once, at this boundary, then dispatches through the
method registry (:mod:`rigidmech.ode._registry`). The integrators themselves trust their input.

How a method plugs in
---------------------
A method is a function ``fn(fun, t_span, y0, *, step, **options) -> OdeResult`` registered with
``rigidmech.ode._registry.register(name, fn, kind=...)`` at import time of its module (the module
is imported by ``rigidmech/ode/__init__.py``). What it receives depends on its kind:

* ``"fixed"`` - ``fun(t, y)``; ``t_span = (t0, t1)`` floats; ``y0`` a fresh float array of shape
  ``(n,)`` or ``(n, batch)``; ``step`` the *signed* uniform step, already adjusted by
  :func:`solve` so that ``N = round((t1 - t0) / step)`` steps land exactly on ``t1``;
  ``max_steps`` (``N <= max_steps`` is guaranteed). It returns all ``N + 1`` grid points.
* ``"second_order"`` - the same, but ``fun`` is the acceleration ``a(t, q)`` of
  ``q'' = a(t, q)`` and ``y0 = [q0, v0]`` (``n`` even); the result's ``y`` holds ``[q, v]``.
* ``"adaptive_second_order"`` - ``fun`` and ``y0`` as for ``"second_order"``, the options
  as for ``"adaptive"``.
* ``"adaptive"`` / ``"stiff"`` - ``step=None`` and the options ``rtol``, ``atol`` (float or
  array broadcastable to ``y0``), ``first_step`` (None or float > 0), ``max_step``,
  ``max_steps``, ``dense_output`` (bool: fill ``OdeResult.sol``) and ``events`` (None or an
  :class:`~rigidmech.ode.events.EventTracker`, whose ``check`` the method calls after each
  accepted step).

For fixed-step methods, :func:`solve` itself provides ``t_eval``, ``dense_output`` and
``events`` afterwards, by cubic Hermite interpolation on the grid (the derivative at the grid
points costs one extra evaluation of ``fun`` per point); a terminal event truncates the result
at the event, the grid beyond it having been computed for nothing. For adaptive methods
``t_eval`` is evaluated on the method's own dense output.
"""

from __future__ import annotations

import dataclasses
import inspect
import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from rigidmech._core.errors import ArgumentError, ArgumentTypeError

from . import _registry
from ._dense import DenseSolution
from ._fixed import step_count
from ._loop import PROJECT
from ._progress import progress_option
from ._result import OdeResult
from .events import EventTracker
from .runge_kutta import fixed_step_method
from .tableaux import ButcherTableau

__all__ = ["solve", "methods"]


def methods(kind: str | None = None) -> list[str]:
    """Names of the available integration methods, optionally of one `kind`.

    Parameters
    ----------
    kind : {"fixed", "adaptive", "second_order", "adaptive_second_order", "stiff"}, optional

    Examples
    --------
    >>> {"euler", "rk4", "dopri5", "dop853", "gbs", "radau"} <= set(methods())
    True
    >>> methods("stiff")
    ['radau']
    """
    if kind is not None and kind not in _registry.KINDS:
        raise ArgumentError(f"`kind` must be one of {_registry.KINDS} or None; got {kind!r}.")
    return _registry.names(kind)


def _entry(method):
    if isinstance(method, ButcherTableau):
        return _registry.MethodEntry(method.name, fixed_step_method(method), "fixed")
    return _registry.get(method)


_COMMON = {"step", "rtol", "atol", "first_step", "max_step", "max_steps", "dense_output",
           "events", "t_eval"}


def _check_options(entry, options):
    if not options:
        return
    params = inspect.signature(entry.function).parameters
    if any(p.kind is p.VAR_KEYWORD for p in params.values()):
        return
    known = sorted(set(params) - _COMMON - {"fun", "t_span", "y0", "progress"})
    for key in options:
        if key not in params or key in _COMMON:
            raise ArgumentError(
                f"`{key}` is not an option of method {entry.name!r}; its own options are "
                f"{known or 'none'}."
            )


def _float(name, value):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`{name}` must be a real number; got {value!r}.") from None
    return v


def _check_t_span(t_span):
    try:
        t0, t1 = t_span
    except (TypeError, ValueError):
        raise ArgumentError(
            f"`t_span` must be a pair (t0, t1) of finite numbers; got {t_span!r}."
        ) from None
    t0, t1 = _float("t_span[0]", t0), _float("t_span[1]", t1)
    if not (math.isfinite(t0) and math.isfinite(t1)):
        raise ArgumentError(f"`t_span` must hold finite times; got ({t0}, {t1}).")
    return t0, t1


def _check_y0(y0):
    if np.iscomplexobj(np.asarray(y0)) if not isinstance(y0, str) else False:
        raise ArgumentTypeError("`y0` must be real; got a complex array.")
    try:
        y = np.array(y0, dtype=float, copy=True)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"`y0` must be an array of real numbers of shape (n,) or (n, batch); got {y0!r}."
        ) from None
    if y.ndim not in (1, 2) or y.size == 0:
        raise ArgumentError(
            f"`y0` must have shape (n,) or (n, batch) with n >= 1; got shape {y.shape}."
        )
    if not np.all(np.isfinite(y)):
        bad = np.argwhere(~np.isfinite(y))[0]
        raise ArgumentError(
            f"`y0` must be finite; got {y[tuple(bad)]} at index {tuple(int(i) for i in bad)}."
        )
    return y


def _check_tolerances(rtol, atol, y0):
    rtol = _float("rtol", rtol)
    if not (math.isfinite(rtol) and rtol > 0):
        raise ArgumentError(f"`rtol` must be a finite number > 0; got {rtol}.")
    if rtol < 1e-15:
        raise ArgumentError(
            f"`rtol` must be >= 1e-15 (about 5 machine epsilons); got {rtol:g}."
        )
    a = np.asarray(atol, dtype=float)
    if a.ndim == 0:
        if not (math.isfinite(float(a)) and a >= 0):
            raise ArgumentError(f"`atol` must be a finite number >= 0; got {float(a)}.")
        return rtol, float(a)
    try:
        a = np.array(a.reshape(a.shape + (1,) * (y0.ndim - a.ndim)) if a.ndim < y0.ndim else a)
        full = np.broadcast_to(a, y0.shape).astype(float).reshape(-1)
    except ValueError:
        raise ArgumentError(
            f"`atol` must be a number or an array of shape (n,) = ({y0.shape[0]},); "
            f"got shape {np.shape(atol)}."
        ) from None
    if not (np.all(np.isfinite(full)) and np.all(full >= 0)):
        raise ArgumentError(f"`atol` must hold finite numbers >= 0; got {np.asarray(atol)}.")
    return rtol, full


def _check_t_eval(t_eval, t0, t1):
    te = np.array(t_eval, dtype=float, copy=True)
    if te.ndim != 1 or not np.all(np.isfinite(te)):
        raise ArgumentError(
            f"`t_eval` must be a 1-D array of finite times; got shape {te.shape}."
        )
    lo, hi = min(t0, t1), max(t0, t1)
    if te.size and (te.min() < lo or te.max() > hi):
        raise ArgumentError(
            f"`t_eval` must lie within `t_span` [{lo}, {hi}]; got values in "
            f"[{te.min()}, {te.max()}]."
        )
    d = np.diff(te) * (1.0 if t1 > t0 else -1.0)
    if np.any(d <= 0):
        raise ArgumentError(
            "`t_eval` must be strictly monotonic in the direction of `t_span`; "
            f"got a non-monotonic step at index {int(np.argmax(d <= 0))}."
        )
    return te


def _hermite_dense(fun, kind, t, y, shape):
    """Cubic Hermite dense solution on a fixed-step grid (``y`` in user layout (n, m, ...))."""
    m = len(t)
    Y = np.moveaxis(y, 1, 0).reshape(m, -1)
    F = np.empty_like(Y)
    n = shape[0]
    for i in range(m):
        yi = Y[i].reshape(shape)
        if kind == "second_order":
            half = n // 2
            F[i].reshape(shape)[:half] = yi[half:]
            F[i].reshape(shape)[half:] = fun(t[i], yi[:half])
        else:
            F[i].reshape(shape)[...] = fun(t[i], yi)
    h = np.diff(t)[:, None]
    dy = Y[1:] - Y[:-1]
    hf0, hf1 = h * F[:-1], h * F[1:]
    coeffs = np.stack([hf0, 3.0 * dy - 2.0 * hf0 - hf1, hf0 + hf1 - 2.0 * dy], axis=1)
    return DenseSolution(t, Y[:-1], coeffs, "power", shape), m


def _fixed_post(res, fun, kind, shape, events, dense, t_eval):
    """Provide events, dense output and t_eval for a fixed-step result."""
    sol, extra = _hermite_dense(fun, kind, res.t, res.y, shape)
    res = dataclasses.replace(res, stats={**res.stats, "nfev_interpolation": extra})
    if events is not None:
        res = fixed_events(res, shape, events, sol)
    res = dataclasses.replace(res, sol=sol if dense else None)
    if t_eval is not None:
        t, y = _restrict(t_eval, res.t, sol)
        res = dataclasses.replace(res, t=t, y=y)
    return res


def fixed_events(res, shape, events, sol):
    """The events of a fixed-step result located on its continuous solution `sol`, step by
    step to the first non-finite state; the result cut at a terminal event (status 1)."""
    t, y, status, message = res.t, res.y, res.status, res.message
    Y = np.moveaxis(y, 1, 0)
    for i in range(1, len(t)):
        if not np.all(np.isfinite(Y[i])):
            break
        if events.check(t[i - 1], t[i], Y[i], sol):
            t = np.append(t[:i], events.t_stop)
            y = np.concatenate([y[:, :i], events.y_stop.reshape(shape)[:, None]], axis=1)
            status, message = 1, "A terminal event occurred."
            break
    return dataclasses.replace(res, t=t, y=y, status=status, message=message,
                               t_events=events.t_events, y_events=events.y_events,
                               t_stop=float(t[-1]), y_stop=np.array(y[:, -1]))


_SECOND_ORDER = ("second_order", "adaptive_second_order")


def _check_fun_output(fun, t0, y, kind):
    """One call of `fun` at the initial state, to refuse a wrong output shape clearly."""
    if kind in _SECOND_ORDER:
        if y.shape[0] % 2:
            return  # refused with its own message
        arg, want = y[: y.shape[0] // 2].copy(), (y.shape[0] // 2,) + y.shape[1:]
    else:
        arg, want = y.copy(), y.shape
    out = fun(t0, arg)
    if np.iscomplexobj(out) and np.any(np.imag(out) != 0):  # refused, not truncated
        flat = np.asarray(out).reshape(-1)
        k = int(np.argmax(np.imag(flat) != 0))
        raise ArgumentTypeError(
            f"`fun(t0, y0)` returned complex values (component {k}: {flat[k]}); the methods "
            "integrate real equations only (a square root or a logarithm of a negative "
            "number?)."
        )
    try:
        got = np.shape(out)
        arr = np.asarray(out, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"`fun(t0, y0)` must return an array of real numbers of shape {want}; got "
            f"{type(out).__name__}."
        ) from None
    if arr.shape != want:
        raise ArgumentError(
            f"`fun(t0, y0)` must return an array of the shape of its `y` argument, {want}; "
            f"got shape {got}."
        )


def _zero_length(run):
    """The result of an empty `t_span`: the initial state at ``t0`` (or at each of `t_eval`)."""
    t = np.array([run.t0]) if run.t_eval is None else run.t_eval
    ys = np.repeat(run.y[:, None], len(t), axis=1)
    ev = run.tracker
    return OdeResult(
        t=t, y=ys, nfev=0, nsteps=0, nrejected=0, status=0,
        message="`t_span` has zero length: the result is `y0` at `t0`.", method=run.entry.name,
        t_stop=run.t0, y_stop=run.y.copy(),
        t_events=ev.t_events if ev is not None else [],
        y_events=ev.y_events if ev is not None else [],
    )


def _restrict(t_eval, t, sol):
    """``t_eval`` cut to the part of `t_span` actually integrated, and the states there."""
    sign = 1.0 if t[-1] >= t[0] else -1.0
    keep = t_eval[sign * t_eval <= sign * t[-1]]
    return keep, sol(keep)


def solve(fun: Callable, t_span, y0, method: str = "dop853", *, step: float | None = None,
          rtol: float = 1e-6, atol=1e-9, t_eval=None, dense_output: bool = False, events=None,
          first_step: float | None = None, max_step: float = math.inf,
          max_steps: int = 1_000_000, args: tuple = (), project: Callable | None = None,
          **options) -> OdeResult:
    """Integrate ``y' = f(t, y)`` (or ``q'' = a(t, q)``) from ``t_span[0]`` to ``t_span[1]``.

    The equations of motion of Parts IV-V (book, ch. 26-27) by Runge-Kutta methods with fixed
    or adaptive step, extrapolation, Adams, an implicit method for stiff systems (Hairer,
    Norsett and Wanner, *Solving Ordinary Differential Equations* I and II).

    Parameters
    ----------
    fun : callable
        ``fun(t, y, *args) -> dy/dt`` of the shape of `y0` (kind ``"second_order"``: the
        acceleration ``fun(t, q, *args)``, ``y0 = [q0, v0]``); the same buffer may be returned
        every call. One call more than ``nfev`` says checks its output at the initial state.
    t_span : (float, float)
        Initial and final times; ``t1 < t0`` integrates backwards.
    y0 : array_like, shape (n,) or (n, batch)
        Initial state; a 2-D `y0` integrates ``batch`` trajectories at once (``fun`` gets
        ``(n, batch)`` arrays). The embedded pairs (``dopri5``, ``dop853``, ``bs32``) take
        ``stepping``: ``"each"`` gives every trajectory its own step size, the stages of
        the trajectories still running evaluated in one call ``fun(t, y)`` with ``y`` of
        shape ``(n, m)`` and ``t`` an array of their ``m`` times; ``"shared"`` steps the whole
        batch by its largest error norm (the other adaptive methods always do);
        ``"auto"`` (default) is ``"each"`` for a batch sampled at `t_eval` without dense
        output, events or projection (:mod:`rigidmech.ode._ensemble`).
    method : str or ButcherTableau
        One of :func:`methods` (default ``"dop853"``); ``methods("fixed")`` need `step`. A
        :class:`~rigidmech.ode.tableaux.ButcherTableau` runs as a fixed-step method.
    step : float, optional
        Step of a fixed-step method (required by those, refused by the others), at most
        ``|t1 - t0|``, reduced slightly if needed so that equal steps span `t_span`.
    rtol, atol : float, or array of shape (n,) for `atol`
        Adaptive methods: local error kept below ``atol + rtol |y|`` in Hairer's RMS norm.
    t_eval : array_like, optional
        Times of the solution returned (within `t_span`, monotonic; default: the steps).
    dense_output : bool
        Fill ``result.sol``, a callable continuous solution.
    events : callable or list of callable, optional
        Functions ``g(t, y)`` whose zeros are located (:mod:`rigidmech.ode.events`; no batch).
    first_step, max_step : float, optional
        First step (default: Hairer's estimate) and largest step of the adaptive methods.
    max_steps : int
        Largest number of steps (an adaptive run stops there, status -1; a fixed step is refused).
    args : tuple
        Extra arguments passed to `fun`.
    project : callable, optional
        ``project(t, y) -> y``: a projection of the state applied after every accepted step
        (e.g. onto the constraints of a mechanism, whose integration drifts off them). The
        next step starts from the projected state (its derivative evaluated once more, one
        evaluation of `fun` per step); the samples at the steps' ends, ``t_stop``/``y_stop``
        and the states given to event functions at the steps' ends are the projected
        ones, while the dense output *between* two steps (``sol``, samples of ``t_eval``
        inside a step, event location) is that of the unprojected step. A non-finite
        projection is ignored for that step; ``radau`` keeps its Jacobian and factorisations
        across a projection (formed again when Newton converges slowly, as after any step).
        Only for the first-order methods of the one integration loop
        (``dopri5``, ``dop853``, ``bs32``, ``gbs``, ``radau``); refused by the others.
    **options
        Options specific to the method (e.g. ``nstiff`` for ``"dop853"``, ``jac`` for
        ``"radau"``), passed on to it; an option the method does not take is refused. Every
        built-in method takes ``progress``: a callable ``progress(t)`` called after every
        step (a returned False stops the run with status 2 and the steps made so far, as
        Ctrl-C does for every built-in method); ``progress=True`` shows a progress bar
        (tqdm) on stderr once the run has lasted 2 s. Either is checked once per accepted
        step, never per evaluation of `fun`.

    Returns
    -------
    OdeResult
        ``t``, ``y`` (shape ``(n, len(t))`` or ``(n, len(t), batch)``), counters, ``status`` (0
        end reached, 1 terminal event, -1 numerical failure named in ``message`` with its time
        and state, or an event function returned nan, the motion kept; 2 stopped on request),
        ``t_stop``, ``y_stop``, ``sol``, ``t_events``, ``y_events``.

    Raises
    ------
    ArgumentError, ArgumentTypeError
        On any misuse, with the argument, what was expected and what was received.

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> osc = lambda t, y: np.array([y[1], -y[0]])          # harmonic oscillator
    >>> r = ode.solve(osc, (0.0, np.pi), [1.0, 0.0], method="rk4", step=0.01)
    >>> np.round(r.y[:, -1], 6)
    array([-1., -0.])
    >>> r = ode.solve(osc, (0.0, np.pi), [1.0, 0.0], rtol=1e-10)
    >>> bool(abs(r.y[0, -1] + 1) < 1e-9), r.method
    (True, 'dop853')
    """
    run = validate(fun, t_span, y0, method, step=step, rtol=rtol, atol=atol, t_eval=t_eval,
                   dense_output=dense_output, events=events, first_step=first_step,
                   max_step=max_step, max_steps=max_steps, args=args, options=options)
    box = _projection(project, run)
    bar = None  # the bar made here for progress=True, closed at the end
    if "progress" in run.options:  # checked once per accepted step
        given = run.options["progress"]
        run.options["progress"] = progress_option(given, (run.t0, run.t1))
        bar = run.options["progress"] if given is True else None
    try:
        if run.t0 == run.t1:  # nothing to integrate: y0 itself, as scipy's solve_ivp returns
            return _finish(_zero_length(run), run)
        _check_fun_output(run.fun, run.t0, run.y, run.entry.kind)
        token = PROJECT.set(box)
        try:
            res = _run_fixed(run) if run.entry.kind in _FIXED else _run_adaptive(run)
        finally:
            PROJECT.reset(token)
        if box is not None and not box[1]:
            raise ArgumentError(f"`project` is for the methods of the integration loop; "
                                f"method {run.entry.name!r} has its own loop.")
        return _finish(res, run)
    finally:
        if bar is not None:
            bar.close()


def _projection(project, run):
    """The box [project, used] the loop reads, or None; `project` checked against the method."""
    if project is None:
        return None
    if not callable(project):
        raise ArgumentTypeError(f"`project` must be a callable project(t, y) -> y or "
                                f"None; got {project!r}.")
    if run.entry.kind in _FIXED:
        raise ArgumentError(f"`project` is for the methods of the integration loop; "
                            f"method {run.entry.name!r} has a fixed step.")
    if run.entry.kind in _SECOND_ORDER:  # its stepper keeps the acceleration it made
        raise ArgumentError(f"`project` is for first-order methods; method "
                            f"{run.entry.name!r} integrates q'' = a(t, q).")
    return [project, False]


def _finish(res, run):
    """The failed member of a batch named; an event function's failure reported."""
    if res.status < 0 and run.y.ndim == 2 and "failed_members" not in res.stats:
        res = name_failed_member(res, run)  # per-trajectory steps name their own
    failure = run.tracker.failure() if run.tracker is not None else None
    if failure is not None:  # the motion is kept; the events are not to be trusted
        res = dataclasses.replace(res, status=min(res.status, -1) if res.status != 2 else 2,
                                  message=f"{failure} {res.message}")
    return res


_FIXED = ("fixed", "second_order")


class Settings(NamedTuple):
    """The validated arguments of one run of :func:`solve` (built by :func:`validate`)."""

    entry: _registry.MethodEntry
    fun: Callable
    t0: float
    t1: float
    y: np.ndarray
    step: float | None
    rtol: float
    atol: float | np.ndarray
    t_eval: np.ndarray | None
    dense_output: bool
    tracker: EventTracker | None
    first_step: float | None
    max_step: float
    max_steps: int
    options: dict


def validate(fun, t_span, y0, method, *, step, rtol, atol, t_eval, dense_output, events,
             first_step, max_step, max_steps, args, options) -> Settings:
    """Check every argument of :func:`solve` once; return them as :class:`Settings`.

    Raises
    ------
    ArgumentError, ArgumentTypeError
        As documented by :func:`solve`.

    Examples
    --------
    >>> s = validate(lambda t, y: -y, (0, 1), [1.0], "rk4", step=0.3, rtol=1e-6, atol=1e-9,
    ...              t_eval=None, dense_output=False, events=None, first_step=None,
    ...              max_step=math.inf, max_steps=100, args=(), options={})
    >>> s.step, s.entry.kind
    (0.25, 'fixed')
    """
    if not callable(fun):
        raise ArgumentTypeError(f"`fun` must be callable f(t, y); got {type(fun).__name__}.")
    entry = _entry(method)
    _check_options(entry, options)
    t0, t1 = _check_t_span(t_span)
    y = _check_y0(y0)
    if not isinstance(args, tuple):
        raise ArgumentTypeError(f"`args` must be a tuple; got {type(args).__name__}.")
    if args:
        user_fun = fun

        def fun(t, y, _f=user_fun, _a=args):
            return _f(t, y, *_a)

    if isinstance(max_steps, bool) or not isinstance(max_steps, int | np.integer) or (
        max_steps < 1
    ):
        raise ArgumentError(f"`max_steps` must be an int >= 1; got {max_steps!r}.")
    max_steps = int(max_steps)
    te = None if t_eval is None else _check_t_eval(t_eval, t0, t1)
    tracker = None
    if events is not None:
        if y.ndim == 2:
            raise ArgumentError(
                "`events` are not available with a batch `y0` of shape (n, batch); got shape "
                f"{y.shape}: integrate the trajectories one by one to locate events."
            )
        tracker = EventTracker(events, t0, y.copy())
    if entry.kind in _SECOND_ORDER and y.shape[0] % 2:
        raise ArgumentError(
            f"`y0` must be [q0, v0] of even length n for method {entry.name!r}; got n = "
            f"{y.shape[0]}."
        )
    common = dict(entry=entry, fun=fun, t0=t0, t1=t1, y=y, t_eval=te,
                  dense_output=bool(dense_output), tracker=tracker, max_steps=max_steps,
                  options=options)
    if entry.kind in _FIXED:
        h = _check_fixed_step(entry, step, t0, t1, max_steps)
        return Settings(step=h, rtol=rtol, atol=atol, first_step=None, max_step=max_step,
                        **common)
    return Settings(step=None, **_check_adaptive(entry, step, rtol, atol, y, t0, t1,
                                                 first_step, max_step), **common)


def _check_fixed_step(entry, step, t0, t1, max_steps):
    """The signed uniform step of a fixed-step method, landing exactly on ``t1``."""
    if step is None:
        raise ArgumentError(
            f"`step` is required by the fixed-step method {entry.name!r}; got None."
        )
    h = _float("step", step)
    if not (math.isfinite(h) and h > 0):
        raise ArgumentError(f"`step` must be a finite number > 0; got {h}.")
    if t0 != t1 and h > abs(t1 - t0):
        raise ArgumentError(f"`step` = {h!r} exceeds the time span |t1 - t0| = "
                            f"{abs(t1 - t0)!r}: no step would be of the size asked for.")
    nsteps = step_count(abs(t1 - t0), h)
    if nsteps > max_steps:
        raise ArgumentError(
            f"`step` = {h:g} needs {nsteps} steps over `t_span`, more than `max_steps` = "
            f"{max_steps}; use a larger step or raise max_steps."
        )
    return (t1 - t0) / nsteps


def _check_adaptive(entry, step, rtol, atol, y, t0, t1, first_step, max_step):
    """`rtol`, `atol`, `first_step` and `max_step` of an error-controlled method."""
    if step is not None:
        raise ArgumentError(
            f"`step` is only for fixed-step methods; method {entry.name!r} chooses its own "
            f"steps (got step={step!r}): use `first_step` or `max_step` instead."
        )
    rtol, atol = _check_tolerances(rtol, atol, y)
    if np.any((np.asarray(atol) == 0) & (y.reshape(-1) == 0)):
        raise ArgumentError(
            "`atol` must be > 0 for the components of `y0` that are zero (a pure relative "
            "error is undefined at 0); got atol = 0 with y0 = "
            f"{np.array2string(y, threshold=8)}."
        )
    max_step = _float("max_step", max_step)
    if not max_step > 0:
        raise ArgumentError(f"`max_step` must be > 0; got {max_step}.")
    if first_step is not None:
        first_step = _float("first_step", first_step)
        length = abs(t1 - t0)
        if not (math.isfinite(first_step) and 0 < first_step <= max(length, first_step * (
                length == 0))):
            raise ArgumentError(
                f"`first_step` must be in (0, |t1 - t0|] = (0, {length}]; got {first_step}."
            )
    return dict(rtol=rtol, atol=atol, first_step=first_step, max_step=max_step)


def _run_fixed(run):
    res = run.entry.function(run.fun, (run.t0, run.t1), run.y, step=run.step,
                             max_steps=run.max_steps, **run.options)
    if run.tracker is not None or run.dense_output or run.t_eval is not None:
        res = _fixed_post(res, run.fun, run.entry.kind, run.y.shape, run.tracker,
                          run.dense_output, run.t_eval)
    return res


def _run_adaptive(run):
    te, caps = run.t_eval, run.entry.capabilities
    lands, samples = "t_eval_at_steps" in caps, "t_eval" in caps
    own = te is not None and (lands or samples)  # the method takes t_eval itself
    res = run.entry.function(
        run.fun, (run.t0, run.t1), run.y, step=None, rtol=run.rtol, atol=run.atol,
        first_step=run.first_step, max_step=run.max_step, max_steps=run.max_steps,
        dense_output=run.dense_output or (te is not None and not own),
        events=run.tracker, **({"t_eval": te} if own else {}), **run.options,
    )
    if te is None or (samples and not run.dense_output):  # done (or samples kept already)
        return res
    if lands:  # the steps landed on t_eval: keep those steps
        keep = np.isin(res.t, te)
        return dataclasses.replace(res, t=res.t[keep], y=res.y[:, keep])
    if res.sol is not None:
        t_new, y_new = _restrict(te, res.t, res.sol)
    else:  # failed before the first step
        shape = run.y.shape
        t_new, y_new = te[:0], np.empty((shape[0], 0) + shape[1:])
    return dataclasses.replace(res, t=t_new, y=y_new, sol=res.sol if run.dense_output else None)


def name_failed_member(res, run):
    """Name, in the message of a failed batch run, the trajectory that stopped it.

    A batch shares one step, so one diverging member stops them all (the run stops there and
    keeps what was computed). The member named is the first with a non-finite state or
    right-hand side, else the one whose rate of change ``|f| / (atol + rtol |y|)`` is the
    largest at the last accepted state: the member that forces the step down.
    """
    y = np.moveaxis(res.y, 1, 0)[-1] if res.y.shape[1] else run.y  # (n, batch)
    t = float(res.t[-1]) if len(res.t) else run.t0
    with np.errstate(all="ignore"):
        f = np.asarray(run.fun(t, y.copy()), dtype=float)
        atol = np.asarray(run.atol, dtype=float)
        atol = atol.reshape(y.shape) if atol.size == y.size else atol
        rate = np.max(np.abs(f) / (atol + run.rtol * np.abs(y)), axis=0)
    bad = ~(np.all(np.isfinite(y), axis=0) & np.all(np.isfinite(f), axis=0))
    j = int(np.argmax(bad)) if bad.any() else int(np.nanargmax(np.where(np.isnan(rate),
                                                                        np.inf, rate)))
    message = (f"{res.message} The batch shares one step: batch member {j} (of {y.shape[1]},"
               f" y0[:, {j}]) stops it; integrate it alone to see where it fails.")
    return dataclasses.replace(res, message=message,
                               stats={**res.stats, "failed_member": j})
