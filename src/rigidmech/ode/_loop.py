"""The stepper protocol and the one integration loop that drives it (book, ch. 26).

A method is a *stepper*: an object that knows how to attempt ONE step and nothing else. The
loop of :func:`integrate` owns everything around the step, once for all the methods built on
it: the starting step, clamping to the end of ``t_span`` (and to the times a method must land
on), the integral (I) and proportional-integral (PI) step-size controllers, rejections,
``max_steps``, step underflow and non-finite states with their messages, recording of the
accepted steps, the dense output, events, batches, Hairer's stiffness counter, a progress
callback ``progress(t)`` after every accepted step (returning False stops the run) and
interruption (Ctrl-C ends the run with everything computed so far; both give status 2).

The protocol (model: scipy's ``OdeSolver``):

``capabilities``
    A :class:`Capabilities`: error order (for the controller and the starting step),
    stiffness border (or None: no test), form of the dense coefficients.
``begin(prob, t0, y0, f0) -> (y, f)``
    Prepare a run from the flat initial state and its derivative; return both in the
    stepper's own representation (lists of floats or ndarrays).
``attempt(t, y, f, h) -> StepResult``
    One attempted step of signed size `h` from ``(t, y)`` with ``f = f(t, y)`` (the previous
    step's ``StepResult.f``, FSAL); the error norm decides. It may be the generated step
    itself (``nfev_per_attempt`` evaluations each, counted by the loop).
``finite(step) -> bool`` (optional)
    Whether the accepted state (and what the next step needs) is finite; without it the
    state is a list of floats, finite if its sum is.
``accept(step)`` (optional)
    The attempt `step` was accepted (e.g. keep a stage buffer).
``dense(t, y, h, step) -> (y_new, coeffs, exact)``
    The accepted state as a flat ndarray, the step's dense coefficients (or a
    zero-argument callable computing them, evaluated only if needed) and ``exact`` (None, or
    ``s -> y(s)`` as accurate as the step, on which event times are refined).
``hlamb(h_abs, step) -> float or None``
    The estimate ``|h lambda|`` of the stiffness test, or None if it cannot be formed.
``start_order``
    The order used by Hairer's starting step.
``stats() -> dict``
    Method-specific counters for ``OdeResult.stats``.
``nfev``, ``nfev_per_attempt``
    Evaluations of ``fun`` the stepper made itself (not through the loop's counting
    ``prob``), and those of each attempt.
``controller`` (optional)
    An object with ``next(err, h_abs, rejected) -> (h_abs, accepted)`` replacing the loop's
    I/PI :class:`Controller` for a method that chooses its step with its order (extrapolation).
"""

from __future__ import annotations

import contextvars
import math
import warnings
from typing import NamedTuple

import numpy as np
from numpy.exceptions import ComplexWarning

from rigidmech._core.errors import ArgumentError

from ._driver import Problem, Recorder, SampleRecorder, initial_step
from ._warnings import stiffness_count

__all__ = ["Capabilities", "StepResult", "Controller", "integrate", "check_progress",
           "PROJECT"]

#: The ``project(t, y) -> y`` of the run in progress (set by :func:`~rigidmech.ode.solve`
#: around the method's call, read once by :func:`integrate`): a list ``[project, used]``.
PROJECT = contextvars.ContextVar("rigidmech_ode_project", default=None)


def check_progress(progress):
    """`progress` checked once for every method on the loop: None or ``progress(t)``.

    Examples
    --------
    >>> check_progress(None) is None
    True
    """
    if progress is not None and not callable(progress):
        raise ArgumentError(f"`progress` must be a callable progress(t), True (a progress "
                            f"bar, through solve), False or None; got {progress!r}.")
    return progress

SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
#: Gains of the PI step-size controller (Gustafsson 1991; HNW II, IV.2, eq. (2.43)):
#: ``h_new = h * SAFETY * err_n**(-PI_KI / k) * err_{n-1}**(PI_KP / k)``, ``k = q + 1``.
PI_KI = 0.7
PI_KP = 0.4
#: Floor of the previous error in the PI formula (as in Hairer's DOPRI5 code).
PI_ERR_FLOOR = 1e-4


class Capabilities(NamedTuple):
    """What a stepper declares instead of a string kind.

    Examples
    --------
    >>> Capabilities(name="bs32", error_order=2, order=3).dense_form
    'power'
    """

    name: str
    #: order of the error estimator (exponent ``-1/(q+1)`` of the controller)
    error_order: int
    #: order of the propagated solution
    order: int
    #: ``|h lambda|`` beyond which a step counts as stiff (None: no stiffness test)
    stiff_border: float | None = None
    #: form of the dense coefficients (see :class:`~rigidmech.ode._dense.DenseSolution`)
    dense_form: str = "power"
    #: order of the dense output
    dense_order: int = 3


class StepResult(NamedTuple):
    """One attempted step: the new state, its derivative, the error norm and the data the
    stepper needs to build the dense output and the stiffness estimate of this step."""

    y: object
    f: object
    error: float
    data: object


class Controller:
    """The integral (scipy's and Hairer's codes) or PI (Gustafsson) step-size controller.

    ``next(err, h_abs, rejected) -> (h_abs_new, accepted)``: accepted if ``err < 1``; a nan
    or infinite error shrinks the step as much as allowed; never grows just after a
    rejection.

    Examples
    --------
    >>> c = Controller(error_order=4, pi=False)
    >>> c.next(1.0 / 32, 0.1, False)  # 0.9 * 32**(1/5) = 1.8
    (0.18000000000000002, True)
    """

    __slots__ = ("exponent", "pi", "alpha", "beta", "err_old")

    def __init__(self, error_order, pi):
        k = error_order + 1
        self.exponent = -1.0 / k
        self.pi = pi
        self.alpha, self.beta = -PI_KI / k, PI_KP / k
        self.err_old = 1.0

    def next(self, err, h_abs, rejected):
        if err < 1.0:
            if err == 0.0:
                factor = MAX_FACTOR
            elif self.pi:
                factor = min(MAX_FACTOR, SAFETY * err**self.alpha * self.err_old**self.beta)
            else:
                factor = min(MAX_FACTOR, SAFETY * err**self.exponent)
            if rejected:
                factor = min(1.0, factor)
            if self.pi:
                self.err_old = max(err, PI_ERR_FLOOR)
            return h_abs * factor, True
        if math.isfinite(err):
            return h_abs * max(MIN_FACTOR, SAFETY * err**self.exponent), False
        return h_abs * MIN_FACTOR, False


class _Stiffness:
    """Hairer's stiffness counter: a test every `nstiff` accepted steps, then at every step
    while the estimate stays high; warns once (see :func:`stiffness_count`)."""

    __slots__ = ("name", "border", "nstiff", "iasti", "nonsti", "warned")

    def __init__(self, caps, nstiff):
        self.name, self.border = caps.name, caps.stiff_border
        self.nstiff = nstiff if caps.stiff_border is not None else 0
        self.iasti = self.nonsti = 0
        self.warned = False

    def due(self, naccpt):
        return self.nstiff and (naccpt % self.nstiff == 0 or self.iasti > 0)

    def check(self, hlamb, t_new):
        if hlamb is not None:
            self.iasti, self.nonsti, self.warned = stiffness_count(
                self.name, self.border, hlamb, t_new, self.iasti, self.nonsti, self.warned)


def _underflow_reason(err):
    """Why the step fell below the resolution of t: a non-finite error estimate means that
    the right-hand side returned nan or inf in the attempted steps."""
    if err == err and err != math.inf:
        return "The step size fell below the resolution of t (step size underflow)"
    return ("The right-hand side returned non-finite values (nan or inf) in every attempted "
            "step down to the resolution of t (step size underflow), from the state")


def _culprit(step, t_new, rec):
    """A sentence naming the first non-finite component of the last attempted step's
    derivative (else of its state), or ''; the same facts kept as ``rec.culprit`` (a dict:
    ``what`` "derivative" or "state", ``component``, ``value``, ``t``) for the result's
    ``stats["culprit"]``."""
    for what, values in (("derivative", step.f), ("state", step.y)):
        try:
            flat = np.asarray(values, dtype=float).reshape(-1)
        except (TypeError, ValueError):
            continue
        bad = ~np.isfinite(flat)
        if bad.any():
            k = int(np.argmax(bad))
            rec.culprit = {"what": what, "component": k, "value": float(flat[k]),
                           "t": float(t_new)}
            name = "the derivative f(t, y)" if what == "derivative" else "the state"
            return (f" In the last attempted step, {name} was {flat[k]} in component {k} at "
                    f"t = {float(t_new)!r}.")
    return ""


def _probe(fun, t, y, h, shape):
    """Where a failure starts, found on the failure path only (no cost otherwise): `fun` at
    the last accepted state ``(t, y)``, at ``(t + h, y)`` and one Euler step of size `h`
    beyond it. Returns the :func:`_culprit` dict (with ``complex``) of the first evaluation,
    from a finite real state, whose output has a complex or a non-finite component, or None.

    Examples
    --------
    >>> f = lambda t, y: np.array([y[0], 1j if t > 0.5 else 0.0])
    >>> c = _probe(f, 0.4, [1.0, 0.0], 0.2, (2,))
    >>> c["component"], c["complex"], c["t"]
    (1, True, 0.6000000000000001)
    """
    inner, d = getattr(fun, "fun", None), getattr(fun, "d", None)
    if inner is not None and isinstance(d, int):  # q'' = a(t, q) as y' = (v, a): a itself

        def fun(t, y, _a=inner, _d=d):
            return np.concatenate([y[_d:], np.asarray(_a(t, y[:_d].copy()))])

    y = np.array(y, dtype=float).reshape(-1)
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        try:
            points = [(t, y), (t + h, y)]
            for k, (tk, yk) in enumerate(points):
                out = np.asarray(fun(tk, yk.reshape(shape).copy())).reshape(-1)
                found = _bad_component(out, tk)
                if found is not None:
                    return found
                if k == 0:
                    points.append((t + h, y + h * out.real))
        except Exception:  # noqa: BLE001 - a probe: the failure is reported without it
            return None
    return None


def _bad_component(out, t):
    """The first complex, else non-finite, component of `out` as a culprit dict, or None."""
    if np.iscomplexobj(out):
        imag = np.imag(out) != 0
        if imag.any():
            k = int(np.argmax(imag))
            return {"what": "derivative", "component": k, "value": complex(out[k]),
                    "t": float(t), "complex": True}
        out = out.real
    bad = ~np.isfinite(out)
    if bad.any():
        k = int(np.argmax(bad))
        return {"what": "derivative", "component": k, "value": float(out[k]), "t": float(t),
                "complex": False}
    return None


def _complex_failure(rec, culprit, t, y):
    """End the run on a complex value of the right-hand side (status -1, `y` kept)."""
    rec.fail("The right-hand side returned a complex value", t, y)
    rec.culprit = culprit
    rec.message += (f" It was {culprit['value']} in component {culprit['component']} at "
                    f"t = {culprit['t']!r}; the methods integrate real equations only (a "
                    "square root or a logarithm of a negative number?).")


def _nonfinite_culprit(loop, step, t, y, t_new, rec):
    """The sentence naming where a non-finite value started: the probe's evaluation from a
    finite state if it finds one, else the last attempted step (:func:`_culprit`)."""
    found = _probe(loop.fun, t, y, t_new - t, loop.shape)
    if found is None:
        return _culprit(step, t_new, rec)
    return _found_sentence(found, rec)


def _found_sentence(found, rec):
    """The sentence for a culprit found by :func:`_probe` (kept as ``rec.culprit``)."""
    rec.culprit = found
    if found["complex"]:
        return (f" The right-hand side has a complex value ({found['value']}) in "
                f"component {found['component']} at t = {found['t']!r}.")
    return (f" Evaluated again from a finite state, the derivative f(t, y) was "
            f"{found['value']} in component {found['component']} at t = {found['t']!r}.")


def underflow_failure(rec, fun, t, y, h, shape):
    """End a run whose step fell below the resolution of t (for a loop that sees no error
    estimate, adams): the probe from the last accepted state tells a non-finite or complex
    right-hand side, named with its component, from a plain underflow."""
    y = np.array(y, dtype=float)
    found = _probe(fun, t, y, h, shape)
    rec.fail(_underflow_reason(0.0 if found is None else math.nan), t, y)
    if found is not None:
        rec.message += _found_sentence(found, rec)


class Run(NamedTuple):
    """The settings of one run of :func:`integrate` (already validated by ``solve``)."""

    fun: object
    t_span: tuple
    y0: np.ndarray
    rtol: float
    atol: object
    first_step: float | None
    max_step: float
    max_steps: int
    dense_output: bool
    events: object
    nstiff: int = 1000
    step_control: str = "i"
    progress: object = None
    #: times the steps must land on (a :class:`~rigidmech.ode._driver.Stops`), or None
    stops: object = None
    #: times at which to keep the solution, or None (keep every step)
    t_eval: object = None


def integrate(stepper, run, f0=None):
    """Integrate `run` with `stepper` (see the module docstring); return an ``OdeResult``.

    `f0`, if given, is ``fun(t0, y0)`` already evaluated (and counted here).
    """
    caps = stepper.capabilities
    t0, t_end = run.t_span
    direction = 1.0 if t_end > t0 else -1.0
    prob = Problem(run.fun, run.y0.shape)
    y0 = run.y0.reshape(-1).copy()
    t_eval = run.t_eval  # the stops a method lands on are its samples (rkn pairs, gbs)
    if t_eval is None and run.stops is not None:
        t_eval = run.stops.times
    if t_eval is not None and not run.dense_output:  # memory ~ samples, not steps
        rec = SampleRecorder(t0, y0, prob.shape, run.events, t_eval, caps.dense_form,
                             at_steps=run.stops is not None)
    else:
        rec = Recorder(t0, y0, prob.shape, run.dense_output, run.events, caps.dense_form)
    if f0 is None:
        f0 = prob(t0, y0, np.empty_like(y0))
    else:
        prob.nfev += 1
        f0 = np.array(f0, dtype=float).reshape(-1)
    # `project` is taken by this loop even when it stops before its first step (a right-hand
    # side not finite at t0): the caller reports that failure, not a misuse of `project`
    box = PROJECT.get()
    project = None
    if box is not None:
        project, box[1] = box[0], True
    if not np.isfinite(f0).all():
        rec.fail("The right-hand side is not finite", t0, y0)
        return rec.result(caps.name, prob.nfev, 0)
    y, f = stepper.begin(prob, t0, y0, f0)
    if run.first_step is None:
        h_abs = initial_step(prob, t0, y0, f0, direction, stepper.start_order, run.rtol,
                             run.atol, t_end, run.max_step)
    else:
        h_abs = run.first_step
    state = _Loop(stepper, run, rec, direction, prob, project)
    try:
        with warnings.catch_warnings():  # a complex value cast to float raises, not warns
            warnings.simplefilter("error", ComplexWarning)
            state.run(t0, y, f, h_abs)
    except KeyboardInterrupt:  # everything computed so far is kept
        rec.interrupt("The integration was interrupted (KeyboardInterrupt)", state.t)
    nfev = prob.nfev + stepper.nfev + state.attempts * stepper.nfev_per_attempt
    stats = stepper.stats()
    if rec.culprit is not None:
        stats = {**stats, "culprit": rec.culprit}
    return rec.result(caps.name, nfev, state.nrej, stats)


class _Loop:
    """The state of the one loop (kept on an object so that an interruption finds it)."""

    __slots__ = ("stepper", "run_", "rec", "direction", "t", "nrej", "attempts", "fun",
                 "shape", "prob", "project")

    def __init__(self, stepper, run, rec, direction, prob, project=None):
        self.stepper, self.run_, self.rec, self.direction = stepper, run, rec, direction
        self.fun, self.shape, self.prob, self.project = prob.fun, prob.shape, prob, project
        self.t = run.t_span[0]
        self.nrej = self.attempts = 0

    def projected(self, t, y_new):
        """The state `y_new` projected by ``project(t, y)`` (a fresh flat ndarray), or None if
        the projection is not finite (the step is then kept unprojected)."""
        y = np.array(y_new, dtype=float)
        out = np.array(self.project(t, y.reshape(self.shape)), dtype=float).reshape(-1)
        if out.shape != y.shape:
            raise ArgumentError(f"`project(t, y)` must return an array of the shape of y, "
                                f"{self.shape}; got shape {np.shape(out)}.")
        return out if np.isfinite(out).all() else None

    def restart(self, t, y):
        """The stepper restarted from the projected state `y` (its derivative evaluated; a
        stepper's own ``restart`` if it has one, which may keep what the move leaves valid)."""
        prob = self.prob
        again = getattr(self.stepper, "restart", None) or self.stepper.begin
        return again(prob, t, y, prob(t, y, np.empty_like(y)))

    def run(self, t, y, f, h_abs):
        """The loop; on any exit (an interruption too) ``t``, ``nrej`` and ``attempts`` hold
        where it stopped and what it did."""
        stepper, run, rec, direction = self.stepper, self.run_, self.rec, self.direction
        t_end, max_step, max_steps = run.t_span[1], run.max_step, run.max_steps
        control = (getattr(stepper, "controller", None) or Controller(
            stepper.capabilities.error_order, run.step_control == "pi")).next
        stiff = _Stiffness(stepper.capabilities, run.nstiff)
        nstiff, want = stiff.nstiff, rec.needs_dense
        attempt, progress, stops = stepper.attempt, run.progress, run.stops
        project = self.project
        finite = getattr(stepper, "finite", None)  # None: the state is a list of floats
        accept = getattr(stepper, "accept", None)
        isfinite, nextafter, inf = math.isfinite, math.nextafter, math.inf
        t_goal = t_end if stops is None else stops.after(t)
        naccpt = nrej = extra = 0
        t_new = t
        try:
            while direction * (t - t_end) < 0:
                if naccpt >= max_steps:
                    rec.fail(f"The maximum number of steps `max_steps` = {max_steps} was "
                             "reached", t, y)
                    return
                min_step = 10.0 * abs(nextafter(t, direction * inf) - t)
                if h_abs > max_step:
                    h_abs = max_step
                elif h_abs < min_step:
                    h_abs = min_step
                rejected = accepted = False
                while h_abs >= min_step:  # also false for a nan step
                    t_new = t + h_abs * direction
                    if direction * (t_new - t_goal) > 0:
                        t_new = t_goal
                    h = t_new - t
                    h_abs = abs(h)
                    step = attempt(t, y, f, h)
                    y_new, f_new, err, _ = step
                    h_abs, accepted = control(err, h_abs, rejected)
                    if accepted:
                        break
                    rejected = True
                    nrej += 1
                if not accepted:
                    rec.fail(_underflow_reason(err), t, y)
                    rec.message += _nonfinite_culprit(self, step, t, y, t_new, rec)
                    return
                if not (isfinite(sum(y_new)) if finite is None else finite(step)):
                    extra = 1
                    state_ok = bool(np.isfinite(np.asarray(y_new, dtype=float)).all())
                    rec.fail("The right-hand side returned non-finite values (nan or inf) at "
                             "the new state" if state_ok else "The state became non-finite",
                             t_new, y_new)
                    rec.message += _nonfinite_culprit(self, step, t, y, t_new, rec)
                    return
                naccpt += 1
                if nstiff and (naccpt % nstiff == 0 or stiff.iasti > 0):  # stiff.due, inline
                    stiff.check(stepper.hlamb(h_abs, step), t_new)
                y_p = None if project is None else self.projected(t_new, y_new)
                if want:
                    y_rec, coeffs, exact = stepper.dense(t, y, h, step)
                    stop = rec.accept(t_new, y_rec if y_p is None else y_p, coeffs, exact)
                else:
                    stop = rec.accept(t_new, y_new if y_p is None else y_p)
                if accept is not None:
                    accept(step)
                if y_p is not None:
                    y_new, f_new = self.restart(t_new, y_p)
                t, y, f = t_new, y_new, f_new
                if stop:
                    return
                if stops is not None:
                    t_goal = stops.after(t)
                if progress is not None and progress(t) is False:
                    rec.interrupt("The integration was stopped by the `progress` callback", t)
                    return
        except (TypeError, ComplexWarning):  # complex values in the step (cast or summed)
            found = _probe(self.fun, t, y, t_new - t, self.shape)
            if found is None or not found["complex"]:
                raise
            extra = 1
            _complex_failure(rec, found, t, y)
        finally:
            self.t, self.nrej, self.attempts = t, nrej, naccpt + nrej + extra
