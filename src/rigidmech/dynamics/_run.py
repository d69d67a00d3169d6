"""One run of :meth:`EquationsOfMotion.simulate` (book, ch. 27): the solver's options kept
apart from the model's values, the samples chosen so that memory follows the samples asked
for, a failure's non-finite or complex value named by coordinate, progress shown (a bar or a
``progress`` callback able to stop the run, both checked by the solver once per accepted
step), Ctrl-C turned into a partial result. Nothing wraps the right-hand side: the solver's
loop does the watching, once per accepted step.
"""

from __future__ import annotations

import inspect
import math
import time

import numpy as np
import sympy as sp

from .. import ode
from .._core.compile import compile_expressions
from .._core.errors import ArgumentError, ArgumentTypeError, CompilationError
from .._core.lazy import lazy_functions
from .._core.rules import magnitude
from .._core.symbolic import atoms_shared, xreplace_shared
from ..ode._fixed import step_count
from ..ode._progress import for_run
from ..vectors import t as _t
from ._stops import meeting_ends
from .simulation import Event, Simulation

__all__ = ["Reduced", "canonical_method", "run"]

# lazy: import cost of scipy.linalg (see docs/performance); rebound on first call
(_dposv,) = lazy_functions(globals(), "scipy.linalg.lapack", "dposv")

#: seconds of wall time before a progress bar appears
PROGRESS_DELAY = 2.0
#: seconds between two calls of a ``progress`` callback (or updates of the bar)
PROGRESS_EVERY = 0.1


def _labels(names, second_order, rate_names=None):
    accs = [f"{n}'' (acceleration of {n})" for n in rate_names or names]
    return accs if second_order else [f"{n}' (rate of {n})" for n in names] + accs


def _diagnosis(trouble, culprit, names, second, rate_names=None):
    """A sentence naming why the right-hand side failed: the error it raised (with its time),
    else the non-finite or complex value the solver found, by coordinate; or ''."""
    if trouble:
        what, t = trouble[0]
        return f" The right-hand side could not be evaluated ({what}) at t = {t!r}."
    if culprit is None:
        return ""
    k, value, t = culprit["component"], culprit["value"], culprit["t"]
    if culprit["what"] == "derivative":
        labels = _labels(names, second, rate_names)
        label = labels[k] if k < len(labels) else f"component {k}"
        kind = "has a complex value" if culprit.get("complex") else "is not finite"
        return (f" The right-hand side {kind} ({value}) at t = {t!r}, in the component "
                f"{label}.")
    states = list(names) + [f"{n}'" for n in rate_names or names]
    label = states[k] if k < len(states) else f"component {k}"
    return f" The state became non-finite ({value}) at t = {t!r}, in the component {label}."


def merge_values(params, values):
    """The model's values: ``params={...}`` and the keywords, a name given twice refused."""
    if params is None:
        return dict(values)
    if not isinstance(params, dict):
        raise ArgumentTypeError(f"`params` must be a dict of values by name; got "
                                f"{type(params).__name__}.")
    twice = sorted(set(params) & set(values))
    if twice:
        raise ArgumentError(f"the values of {twice} are given twice, in `params` and as "
                            "keywords; give each once.")
    return {**{str(k): v for k, v in params.items()}, **values}


def compile_events(eqs, events, values, full=None):
    """Callables g(t, y) from `events`: callables kept, sympy expressions (or
    :class:`Event`) compiled once (a non-finite value of one is reported by the solver; an
    expression holding q'' gets it from the equations' compiled solver at each call);
    ``full(t, Y)``: the state (q, q') from the run's state (reduced equations)."""
    if events is None:
        return None
    items = list(events) if isinstance(events, list | tuple) else [events]
    out = []
    q_s, u_s, a_s, w_s, rule = eqs._stand_ins()
    n = len(q_s)
    for i, item in enumerate(items):
        if callable(item) and not isinstance(item, sp.Basic):
            out.append(item)
            continue
        spec = item if isinstance(item, Event) else Event(item)
        expr = xreplace_shared([spec.expr], rule)[0]
        symbols, functions, derivatives = atoms_shared([expr])
        if functions or derivatives:
            raise CompilationError(
                f"`events[{i}]` contains {', '.join(sorted(map(str, functions | derivatives)))}"
                ": an event may hold t, the coordinates, their first two derivatives, "
                "constants and inputs.")
        constants = sorted(symbols - set(q_s) - set(u_s) - set(a_s) - set(w_s) - {_t},
                           key=lambda s: s.name)
        missing = [c.name for c in constants if c.name not in values]
        if missing:
            raise ArgumentError(f"`events[{i}]` depends on {missing}, which have no value; "
                                "give them to simulate().")
        consts = [float(values[c.name]) for c in constants]
        inputs = [values[ws.name] for ws in w_s]
        f = compile_expressions(expr, [_t, list(q_s), list(u_s), list(a_s), *constants,
                                       *w_s], name=f"event{i}")
        # q'' from the equations at the event's state, only when the event holds it
        solve = eqs._solver() if any(expr.has(a) for a in a_s) else None
        params = ([float(values[p.name]) for p in eqs.parameters] if solve is not None
                  else [])

        def g(t, y, _f=f, _c=consts, _w=inputs, _solve=solve, _p=params):
            w = [v(t) if callable(v) else float(v) for v in _w]
            if full is not None:
                y = full(np.array([t]), np.asarray(y, dtype=float)[:, None])[:, 0]
            q, u = y[:n], y[n:]
            acc = _solve(t, q, u, *_p, *w) if _solve is not None else np.zeros(n)
            return float(_f(t, q, u, acc, *_c, *w))

        g.terminal, g.direction = spec.terminal, spec.direction
        out.append(g)
    return out


#: largest number of Gauss-Newton iterations of the position projection per step
PROJECTION_ITERATIONS = 3
#: first-order methods on the solver's one loop, which take ``project``
PROJECTING = ("dop853", "dopri5", "bs32", "gbs", "radau")


def _closure_rows(eqs):
    """(indices of the holonomic rows, arguments (t, q, params, inputs), arguments (t, q, q',
    params, inputs), the holonomic rows Φ and the velocity rows A q' + a on the stand-in
    symbols, the stand-ins' rule): what the projector and the closure scales compile."""
    c = eqs.constraints
    q_s, u_s, _, w_s, rule = eqs._stand_ins()
    hol = [i for i, p in enumerate(c.position) if p is not None]
    args_q = [_t, list(q_s), *eqs._params, *w_s]
    args_u = [_t, list(q_s), list(u_s), *eqs._params, *w_s]
    phi = xreplace_shared([c.position[i] for i in hol], rule) if hol else []
    vel = xreplace_shared(list(c.velocity), rule)
    return hol, args_q, args_u, phi, vel, rule


def closure_functions(eqs):
    """(rows of Φ, Φ(t, q, *params, *inputs), A(t, q, ...), c(t, q, u, ...)) of the
    constraints of `eqs`, compiled once (cached): Φ the holonomic rows (None if there are
    none), A the Jacobian of every row, c = A q' + a the velocity residual."""
    key = "projector"
    if key not in eqs._cache:
        c = eqs.constraints
        hol, args_q, args_u, phi, vel, rule = _closure_rows(eqs)
        A = xreplace_shared(list(c.jacobian), rule)
        m, n = len(c), len(args_q[1])
        eqs._cache[key] = (
            hol,
            compile_expressions(sp.ImmutableMatrix(len(hol), 1, phi), args_q,
                                name="closure") if hol else None,
            compile_expressions(sp.ImmutableMatrix(m, n, A), args_q, name="constraint_jacobian"),
            compile_expressions(sp.ImmutableMatrix(m, 1, vel), args_u, name="velocity_residual"))
    return eqs._cache[key]


def closure_scales(eqs):
    """(Φ scales(t, q, *params, *inputs), velocity scales(t, q, u, ...)): the magnitudes of
    the terms of the holonomic rows Φ and of the velocity rows A q' + a (see
    :func:`~rigidmech._core.rules.magnitude`), compiled once (cached): the scales of the rule
    :func:`~rigidmech._core.rules.on_constraints`."""
    key = "closure_scales"
    if key not in eqs._cache:
        hol, args_q, args_u, phi, vel, _ = _closure_rows(eqs)
        eqs._cache[key] = (
            compile_expressions(sp.ImmutableMatrix(len(hol), 1, [magnitude(e) for e in phi]),
                                args_q, name="closure_scales") if hol else None,
            compile_expressions(sp.ImmutableMatrix(len(vel), 1, [magnitude(e) for e in vel]),
                                args_u, name="velocity_scales"))
    return eqs._cache[key]


def _row_solve(J):
    """(J J^T)^-1 J, so that ``r @ X`` is J^T (J J^T)^-1 r, the smallest dx with J dx = r:
    by LAPACK's Cholesky solve (dposv, about a third of the cost of numpy.linalg.solve for
    a few rows, measured with benchmarks/squeezer.py), by numpy.linalg.solve when J J^T is
    not positive definite to LAPACK (a rank-deficient J: what numpy does with it)."""
    G = np.dot(J, J.T)
    _, X, info = _dposv(G, J)
    if info != 0:
        X = np.linalg.solve(G, J)
    return X


def _at(f, flat, args):
    """f on one state: its generated single-state code on the floats `flat` (the arguments
    `args` flattened; a state of a step), or the call f(*args) when that fails (a value the
    floats cannot take: its vectorised path decides); a float array."""
    try:
        out = f.single(*flat)
    except (ArithmeticError, ValueError, TypeError):
        out = f(*args)
    return np.asarray(out, dtype=float)


def projector(eqs, values, rates=True):
    """``project(t, y)`` onto the constraints of `eqs` (book, ch. 25.3), compiled once: the
    positions onto Φ(q, t) = 0 by Gauss-Newton steps q <- q - J^T (J J^T)^-1 Φ (J = Φ_q, the
    smallest correction; at most :data:`PROJECTION_ITERATIONS`, stopped when |Φ| no longer
    decreases), then the rates onto A(q, t) q' + a(q, t) = 0 by the same least-norm step
    (exact: c is linear in q'); with ``rates=False`` the positions only, the rest of the
    state kept (the independent speeds of reduced equations, free by construction). None if
    `eqs` has no constraints.

    When every row is holonomic (A = J) and the iteration stopped by its rule (|Φ| no
    longer decreasing: settled to rounding), the rates' step uses the factor of the last
    position step, J at the q before its correction: that correction was the last of a
    converged Newton iteration (the size of the residual it removed, at most about a
    step's tolerance), A(q) differs from that J by as much relative, and the rates'
    residual left, that difference times the residual removed, is of the second order.
    One evaluation of A and one factorisation less per step; an iteration that used all
    its steps evaluates A at the final q."""
    if eqs.constraints is None:
        return None
    q_s = eqs._stand_ins()[0]
    hol, phi_f, A_f, c_f = closure_functions(eqs)
    consts, inputs, _ = eqs._values(values)
    n = len(q_s)
    rows = None if len(hol) == len(eqs.constraints) else hol  # None: every row holonomic

    def project(t, y):
        w = [v(t) if callable(v) else v for v in inputs]
        rest = [*consts, *w]
        q, u = y[:n].copy(), y[n:]
        X = None  # (J J^T)^-1 J of the last position step
        if phi_f is not None:
            last = math.inf
            for _ in range(PROJECTION_ITERATIONS):
                flat = [t, *q.tolist(), *rest]
                r = _at(phi_f, flat, (t, q, *rest)).reshape(-1)
                listed = r.tolist()  # max(|r|) on floats: a fifth of numpy's cost here
                size, total = max(map(abs, listed)), sum(listed)
                if not size < last or size == 0.0 or not total - total == 0.0:
                    break  # settled, or a residual not finite (the sum: inf or nan)
                last = size
                J = _at(A_f, flat, (t, q, *rest))
                X = _row_solve(J if rows is None else J[rows])
                q -= np.dot(r, X)
            else:
                X = None  # not settled in the steps allowed: A at the final q below
        if not rates:
            return np.concatenate((q, u))
        r = _at(c_f, [t, *q.tolist(), *u.tolist(), *rest], (t, q, u, *rest)).reshape(-1)
        if X is None or rows is not None:
            X = _row_solve(_at(A_f, [t, *q.tolist(), *rest], (t, q, *rest)))
        return np.concatenate((q, u - np.dot(r, X)))

    return project


#: one-step fixed-step methods, which can be run chunk by chunk with the same numbers
ONE_STEP = ("euler", "heun", "midpoint", "rk38", "rk4", "verlet", "yoshida4", "yoshida6")
#: steps per chunk of a one-step fixed-step run
CHUNK = 10_000
#: energy drift beyond which a fixed-step run of a conservative system gets a note
UNSTABLE_DRIFT = 0.5


def _in_chunks(fun, t0, t1, y0, method, nsteps, stride, progress=None):
    """A one-step fixed-step run as successive runs of about :data:`CHUNK` steps (a whole
    number of `stride` steps each), keeping every `stride`-th grid point: memory follows the
    samples, and Ctrl-C keeps the chunks done and the steps of the interrupted one."""
    h = (t1 - t0) / nsteps
    per = stride * max(1, math.ceil(CHUNK / stride))
    ts, ys = [np.array([t0])], [np.asarray(y0, dtype=float)[:, None]]
    y, done, nfev = np.asarray(y0, dtype=float), 0, 0
    status, message = 0, "The integration reached the end of `t_span`."
    t_stop, y_stop = t1, None
    while done < nsteps:
        k = min(per, nsteps - done)
        ta, tb = t0 + done * h, (t0 + (done + k) * h) if done + k < nsteps else t1
        r = ode.solve(fun, (ta, tb), y, method=method, step=abs(tb - ta) / k,
                      max_steps=k + 1, progress=progress)  # Ctrl-C: status 2, steps kept
        nfev += r.nfev
        keep = np.arange(stride, len(r.t), stride)
        ts.append(r.t[keep])
        ys.append(r.y[:, keep])
        if r.status != 0:
            status, message, t_stop, y_stop = r.status, r.message, r.t_stop, r.y_stop
            if len(r.t) and (len(r.t) - 1) % stride:
                ts.append(r.t[-1:])
                ys.append(r.y[:, -1:])
            break
        y = r.y[:, -1]
        done += k
    t_all = np.concatenate(ts)
    if status == 0 and t_all[-1] != t1:  # the end, if not a sample already
        t_all = np.append(t_all, t1)
        ys.append(y[:, None])
    return ode.OdeResult(t=t_all, y=np.concatenate(ys, axis=1), nfev=nfev, nsteps=done,
                         nrejected=0, status=status, message=message, method=method,
                         t_stop=t_stop, y_stop=y if y_stop is None else y_stop)


def _project_samples(project, t, y):
    """The samples projected onto the constraints as the steps' ends are (those inside a
    step come from the unprojected step's dense output); a non-finite one is kept as is."""
    out = np.array(y, dtype=float)
    with np.errstate(all="ignore"):
        for k, tk in enumerate(np.asarray(t, dtype=float).tolist()):
            try:
                p = project(tk, out[:, k])
            except np.linalg.LinAlgError:
                continue
            if np.isfinite(p).all():
                out[:, k] = p
    return out


class Reduced:
    """The state of a run of reduced equations (:mod:`rigidmech.dynamics.reduced`): (q, u)
    with u the rates of the coordinates ``rate_names`` only; ``full(t, Y)`` gives (q, q')
    for samples Y (columns), ``project`` projects the positions (None without holonomic
    rows)."""

    __slots__ = ("rate_names", "full", "project")

    def __init__(self, rate_names, full, project):
        self.rate_names, self.full, self.project = tuple(rate_names), full, project


def _trusted_stop(res, trouble, max_steps):
    """Whether the state a stopped run reached is one to keep: after Ctrl-C or the
    ``progress`` callback, ``max_steps``, or a failure of the right-hand side (an error, a
    non-finite or complex value: the state it started from passed the error control). Not
    after a plain step size underflow: the solver could not resolve the motion from there, a
    singularity its last accepted step may have jumped (x'' = 2 x^3, x = 1/(1 - t), accepted
    at t = 1 + 5e-10 with x = 8e13 > 0); the message gives that state."""
    if res.status == 2:
        return True
    return res.status == -1 and (bool(trouble) or res.stats.get("culprit") is not None
                                 or int(getattr(res, "nsteps", 0) or 0) >= max_steps)


def _with_stop(res, t_out, y_out, t0, t1):
    """(t, y, appended): the samples of a run stopped early (a failure, ``max_steps``,
    Ctrl-C, the ``progress`` callback) followed by the state it reached, ``(t_stop,
    y_stop)`` (the last accepted step, already projected), when that is beyond the last
    sample and finite: a stopped run keeps everything it computed."""
    if res.status not in (-1, 2) or res.t_stop is None or res.y_stop is None:
        return t_out, y_out, False
    y_stop = np.asarray(res.y_stop, dtype=float).reshape(-1)
    t_stop = float(res.t_stop)
    beyond = (not len(t_out)) or (t_stop - float(t_out[-1])) * (1.0 if t1 >= t0 else -1.0) > 0
    if not (beyond and np.isfinite(y_stop).all() and y_stop.size == y_out.shape[0]):
        return t_out, y_out, False
    return (np.append(t_out, t_stop), np.concatenate((y_out, y_stop[:, None]), axis=1),
            True)


def _baumgarte_note(eqs, options, t0, t1):
    """A note when Baumgarte's stabilisation is the run's only drift control (no projection)
    and cannot act within it: its time scale 1/alpha (alpha = the larger coefficient) longer
    than the run, alpha |t1 - t0| < 1 (the boundary acts)."""
    c = eqs.constraints
    if c is None or options.get("project") is not None:
        return ()
    alpha = max(c.stabilization)
    span = abs(t1 - t0)
    if not (alpha > 0 and span > 0 and alpha * span < 1.0):
        return ()
    return (f"Baumgarte's stabilisation (alpha, beta) = {c.stabilization} acts on the time "
            f"scale 1/alpha = {1 / alpha:.3g}, longer than this run ({span:.3g}): it cannot "
            "hold the constraints here. Use a method that projects (dop853, dopri5, bs32, "
            "gbs, radau: project=True) or System(stabilization=(a, a)) with a about "
            f"5/{span:.3g} (for a fixed step, keep a * step below 1).",)


def _loop_options(options, eqs, method, project, progress, span, values, reduced=None):
    """Add to `options` the projection (by default for constrained equations and a method
    of the solver's loop) and the progress (a :class:`~rigidmech.ode._progress.Progress`,
    returned, or None) of a run."""
    if project is None:
        project = eqs.constraints is not None and method in PROJECTING
    elif project and method not in PROJECTING:
        raise ArgumentError(f"`project` needs a method of the solver's loop "
                            f"({', '.join(PROJECTING)}); got method {method!r}.")
    if project and eqs.constraints is not None:
        options["project"] = (projector(eqs, values) if reduced is None
                              else reduced.project)
    prog = for_run(progress, span, every=PROGRESS_EVERY, delay=PROGRESS_DELAY)
    if prog is not None:
        options["progress"] = prog
    return prog


def canonical_method(method):
    """The registered name of `method` (lower case, an alias such as ``"rk45"`` resolved to
    its method ``"dopri5"``): one name for every decision of a run made by method (projection,
    fixed step, second order), so that an alias or another case behaves exactly as its
    method."""
    from ..ode import _registry

    return _registry.get(method).name


def _keeps_nothing(method):
    """Whether `method` is a user's (registered from outside :mod:`rigidmech.ode`), whose
    result may be lost to Ctrl-C: every method of rigidmech.ode keeps its steps."""
    from ..ode import _registry

    return not _registry.get(method).function.__module__.startswith("rigidmech.ode")


class _Reached:
    """The right-hand side of a user's method, keeping the last state (t, y) it was evaluated
    at to completion: what a method that keeps no partial result reached when Ctrl-C stops
    it (for explicit Euler, its last step; for a multistage method, a stage of the step)."""

    __slots__ = ("_rhs", "last")

    def __init__(self, fun):
        self._rhs, self.last = fun, (None, None)

    def __call__(self, t, *y):
        out = self._rhs(t, *y)
        state = np.concatenate([np.asarray(x, dtype=float).reshape(-1) for x in y])
        if np.all(np.isfinite(state)):  # (t, y), or (t, q, q') for second-order methods
            self.last = (float(t), state)
        return out

    def __getattr__(self, name):  # the attributes of the compiled right-hand side
        return getattr(self._rhs, name)


def _takes(method, option):
    from ..ode import _registry

    fn = _registry.get(method).function
    return option in inspect.signature(fn).parameters


def run(eqs, fun, t, y0, *, method, rtol, atol, step, n_output, t_eval, events, max_steps,
        first_step, max_step, dense_output, progress, values, notes, project=None,
        given=None, reduced=None):
    """Integrate and wrap the outcome in a :class:`Simulation` (see ``simulate``)."""
    method = canonical_method(method)
    t0, t1 = float(t[0]), float(t[1])
    kinds = {k: ode.methods(k) for k in ("fixed", "second_order")}
    fixed = method in kinds["fixed"] + kinds["second_order"]
    second = method in kinds["second_order"] + ode.methods("adaptive_second_order")
    if progress is not None and not isinstance(progress, bool) and not callable(progress):
        raise ArgumentTypeError(f"`progress` must be None, True, False or a callable "
                                f"progress(t); got {progress!r}.")
    n_output = int(n_output)
    if n_output < 2 and t_eval is None:
        raise ArgumentError(f"`n_output` must be >= 2; got {n_output}.")
    options = dict(max_steps=max_steps, dense_output=dense_output)
    if fixed:
        if step is None:
            raise ArgumentError(f"method {method!r} has a fixed step: give `step`.")
        if first_step is not None or max_step is not None:
            raise ArgumentError(f"`first_step` and `max_step` are for adaptive methods; "
                                f"{method!r} has the fixed step {step!r}.")
        if t0 != t1 and not step <= abs(t1 - t0):
            raise ArgumentError(f"`step` = {step!r} exceeds the time span |t1 - t0| = "
                                f"{abs(t1 - t0)!r}: no step would be of the size asked for.")
        options["step"] = step
        stride = 1
        if t_eval is None:  # samples at the method's own grid points, about n_output of them
            nsteps = step_count(abs(t1 - t0), step)
            stride = max(1, nsteps // (n_output - 1))
            if stride > 1 and _takes(method, "save_every") and events is None:
                options["save_every"], stride = stride, 1
            elif (method in ONE_STEP and events is None and not dense_output
                  and nsteps > CHUNK):
                if nsteps > max_steps:
                    raise ArgumentError(
                        f"`step` = {step:g} needs {nsteps} steps over `t_span`, more than "
                        f"`max_steps` = {max_steps}; use a larger step or raise max_steps.")
                options = {"chunks": (nsteps, stride)}
        else:
            options["t_eval"] = t_eval
    else:
        options.update(rtol=rtol, atol=atol, first_step=first_step,
                       max_step=math.inf if max_step is None else max_step,
                       t_eval=np.linspace(t0, t1, n_output) if t_eval is None else t_eval)
    prog = _loop_options(options, eqs, method, project, progress, (t0, t1), values, reduced)
    if reduced is None:  # reduced equations have no Baumgarte terms
        notes = (*notes, *_baumgarte_note(eqs, options, t0, t1))
    chunks = options.pop("chunks", None)
    if chunks is None:
        options["events"] = compile_events(eqs, events, values,
                                           None if reduced is None else reduced.full)
    full = (lambda _t, y: y) if reduced is None else reduced.full
    fun.trouble = []  # an error of the right-hand side: kept there, nan returned
    solved = _Reached(fun) if _keeps_nothing(method) else fun
    start = time.perf_counter()
    try:
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            if chunks is None:
                res = ode.solve(solved, (t0, t1), y0, method=method, **options)
            else:
                res = _in_chunks(fun, t0, t1, y0, method, *chunks, progress=prog)
                stride = 1
    except KeyboardInterrupt:  # a method that keeps no partial result: what it reached
        elapsed = time.perf_counter() - start
        t_at, y_at = solved.last if isinstance(solved, _Reached) else (None, None)
        ts, ys = [t0], [np.asarray(y0, dtype=float)]
        if t_at is not None and t_at != t0:
            ts.append(t_at)
            ys.append(y_at)
        kept = (f"the initial state and the last state it evaluated the right-hand side at "
                f"(t = {t_at!r}) are kept" if len(ts) > 1 else "only the initial state is kept")
        return Simulation(eqs, None, values, elapsed, notes, status="interrupted",
                          message=f"The integration was interrupted (Ctrl-C); method "
                          f"{method!r} keeps no partial result: {kept}.", t=ts,
                          y=full(np.array(ts), np.stack(ys, axis=1)),
                          t_events=[], y_events=[], method=method, t_stop=ts[-1], given=given)
    finally:
        fun.trouble, trouble = None, fun.trouble
        if prog is not None:
            prog.close()
    elapsed = time.perf_counter() - start
    message = res.message
    t_stop = res.t_stop  # the end, the terminal event or the last accepted step
    if res.status == 2:
        t_end = float(res.t[-1]) if len(res.t) else t0
        who = ("the `progress` callback" if prog is not None and prog.stopped
               else "Ctrl-C (KeyboardInterrupt)")
        message = (f"The integration was stopped by {who} at t = {t_stop!r}; the samples "
                   f"up to t = {t_end!r} are kept.")
    elif res.status == -1:
        message = message + _diagnosis(trouble, res.stats.get("culprit"), eqs.names, second,
                                       None if reduced is None else reduced.rate_names)
        if reduced is None and res.y_stop is not None and not trouble:
            message += meeting_ends(eqs, res.t_stop, res.y_stop, values)
    status = None  # from the result (an event function's nan: -1, "failed", named by ode)
    t_out, y_out = res.t, res.y
    if not len(t_out):  # stopped before the first sample: the initial state at least
        t_out, y_out = np.array([t0]), np.asarray(y0, dtype=float)[:, None]
    if options.get("project") is not None and len(t_out):  # samples inside steps too
        y_out = _project_samples(options["project"], t_out, y_out)
        if t_out[0] == t0:  # the run started from y0 itself
            y_out[:, 0] = y0
    if fixed and stride > 1:
        keep = np.arange(0, len(t_out), stride)
        if keep[-1] != len(t_out) - 1:
            keep = np.append(keep, len(t_out) - 1)
        t_out, y_out = t_out[keep], y_out[:, keep]
    t_out, y_out, kept = (_with_stop(res, t_out, y_out, t0, t1)
                          if _trusted_stop(res, trouble, max_steps) else (t_out, y_out, False))
    if kept:  # said where the message named the samples kept
        message = (message.replace(" are kept.", ", and the state reached at t = "
                                   f"{t_stop!r} as the last sample.")
                   if res.status == 2 else
                   f"{message} The last state reached (t = {t_stop!r}) is kept as the last "
                   "sample.")
    y_out = full(t_out, y_out)
    y_events = [full(np.asarray(te, dtype=float), np.asarray(ye, dtype=float).T)
                if len(te) else np.empty((y_out.shape[0], 0))
                for te, ye in zip(res.t_events, res.y_events, strict=True)]
    sim = Simulation(eqs, res, values, elapsed, notes, message=message, t=t_out, y=y_out,
                     t_stop=t_stop, status=status, given=given, y_events=y_events)
    if (fixed and sim.status == "finished" and eqs.energy is not None and len(t_out) > 1
            and sim.energy_not_conserved() is None):
        drift = sim.energy_drift()
        if not drift <= UNSTABLE_DRIFT:  # a conservative system: E should stay constant
            sim = Simulation(eqs, res, values, elapsed, (*notes, (
                f"the energy changed by {drift:.3g} times its scale (energy_scale()) with the "
                f"fixed step {step!r}: the step is probably too large for {method!r} (an "
                "unstable explicit method grows without bound); the motion is not to be "
                "trusted.")), message=message, t=t_out, y=y_out, t_stop=t_stop, status=status,
                given=given, y_events=y_events)
    return sim
