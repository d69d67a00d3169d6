"""One run of :meth:`EquationsOfMotion.simulate` (book, ch. 27): the solver's options kept
apart from the model's values, the right-hand side watched (non-finite and complex values
named, progress shown, a ``progress`` callback able to stop the run), the samples chosen so
that memory follows the samples asked for, Ctrl-C turned into a partial result.
"""

from __future__ import annotations

import inspect
import math
import sys
import time
from math import isfinite

import numpy as np
import sympy as sp

from .. import ode
from .._core.compile import compile_expressions
from .._core.errors import ArgumentError, ArgumentTypeError, CompilationError
from .._core.symbolic import atoms_shared, xreplace_shared
from ..vectors import t as _t
from .simulation import Event, Simulation

__all__ = ["run"]

#: seconds of wall time before a progress bar appears
PROGRESS_DELAY = 2.0
#: seconds between two calls of a ``progress`` callback (or updates of the bar)
PROGRESS_EVERY = 0.1


class _Stopped(Exception):
    pass


class Watch:
    """The right-hand side as the solver sees it, watched.

    * a complex value is not truncated to its real part: it becomes nan (the solver then
      fails) and is named with its time and component;
    * the last non-finite value is named likewise (the solver may recover from one in a
      rejected trial step; if it fails, this says where the trouble was);
    * every :data:`PROGRESS_EVERY` seconds, the progress callback or bar is updated; a
      callback returning False stops the run (as Ctrl-C does).
    """

    __slots__ = ("fun", "labels", "second", "bad", "t", "calls", "callback", "bar", "start", "last",
                 "span", "stopped", "bar_wanted")

    def __init__(self, fun, labels, t_span, progress, second=False):
        self.fun, self.labels, self.second = fun, labels, second
        self.bad = None
        self.t = t_span[0]
        self.calls = 0
        self.span = t_span
        self.callback = progress if callable(progress) else None
        self.bar_wanted = progress is True or (progress is None and _interactive())
        self.bar = None
        self.start = self.last = time.monotonic()
        self.stopped = False

    def __call__(self, t, y):
        try:
            out = self.fun(t, y)
        except (ArithmeticError, ValueError, TypeError) as exc:  # e.g. an input's error
            self.bad = (f"could not be evaluated ({type(exc).__name__}: {exc})", t, None,
                        None)
            return np.full(self.shape(y), np.nan)
        if out.dtype.kind == "c":
            out = self._complex(t, out)
        elif not isfinite(sum(out.tolist() if out.ndim == 1 else out.ravel().tolist())) and (
                np.isfinite(y).all()):  # where it starts (a sum is nan or inf if one is)
            flat = out.reshape(-1)
            bad = ~np.isfinite(flat)
            if bad.any():
                k = int(np.argmax(bad))
                self.bad = ("is not finite", t, k, float(flat[k]))
        self.t = t
        self.calls += 1
        if not self.calls & 31 and (self.callback is not None or self.bar_wanted):
            self._tick(t)
        return out

    def _complex(self, t, out):
        imag = np.imag(out) != 0
        if imag.any():
            k = int(np.argmax(imag.reshape(-1)))
            self.bad = ("has a complex value", t, k, complex(out.reshape(-1)[k]))
        return np.where(imag, np.nan, np.real(out))

    def shape(self, y):
        return np.shape(y) if not self.second else (len(self.labels),) + np.shape(y)[1:]

    def _tick(self, t):
        now = time.monotonic()
        if now - self.last < PROGRESS_EVERY:
            return
        self.last = now
        if self.callback is not None and self.callback(float(t)) is False:
            self.stopped = True
            raise KeyboardInterrupt  # the driver keeps what was computed (status 2)
        if self.bar_wanted and now - self.start >= PROGRESS_DELAY:
            if self.bar is None:
                from tqdm import tqdm  # imported on use

                t0, t1 = self.span
                self.bar = tqdm(total=abs(t1 - t0), unit="s", desc="rigidmech: integrating",
                                file=sys.stderr, leave=False, dynamic_ncols=True,
                                bar_format="{desc} {percentage:3.0f}%|{bar}| t = {n:.4g} of "
                                "{total:.4g} [{elapsed}<{remaining}]")
            self.bar.n = abs(t - self.span[0])
            self.bar.refresh()

    def close(self):
        if self.bar is not None:
            self.bar.close()
            self.bar = None

    def diagnosis(self):
        """A sentence naming the last bad value of the right-hand side, or ''."""
        if self.bad is None:
            return ""
        what, t, k, value = self.bad
        if k is None:
            return f" The right-hand side {what} at t = {float(t)!r}."
        return (f" The right-hand side {what} ({value}) at t = {float(t)!r}, in the "
                f"component {self.labels[k]}.")


def _interactive():
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


def _labels(names, second_order):
    accs = [f"{n}'' (acceleration of {n})" for n in names]
    return accs if second_order else [f"{n}' (rate of {n})" for n in names] + accs


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


def compile_events(eqs, events, values):
    """Callables g(t, y) from `events`: callables kept, sympy expressions (or
    :class:`Event`) compiled once (a non-finite value of one is reported by the solver)."""
    if events is None:
        return None
    items = list(events) if isinstance(events, list | tuple) else [events]
    out = []
    q_s, u_s, _, w_s, rule = eqs._stand_ins()
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
                ": an event may hold t, the coordinates, their rates, constants and inputs.")
        constants = sorted(symbols - set(q_s) - set(u_s) - set(w_s) - {_t},
                           key=lambda s: s.name)
        missing = [c.name for c in constants if c.name not in values]
        if missing:
            raise ArgumentError(f"`events[{i}]` depends on {missing}, which have no value; "
                                "give them to simulate().")
        consts = [float(values[c.name]) for c in constants]
        inputs = [values[ws.name] for ws in w_s]
        f = compile_expressions(expr, [_t, list(q_s), list(u_s), *constants, *w_s],
                                name=f"event{i}")

        def g(t, y, _f=f, _c=consts, _w=inputs):
            w = [v(t) if callable(v) else float(v) for v in _w]
            return float(_f(t, y[:n], y[n:], *_c, *w))

        g.terminal, g.direction = spec.terminal, spec.direction
        out.append(g)
    return out


#: one-step fixed-step methods, which can be run chunk by chunk with the same numbers
ONE_STEP = ("euler", "heun", "midpoint", "rk38", "rk4", "verlet", "yoshida4", "yoshida6")
#: steps per chunk of a one-step fixed-step run
CHUNK = 10_000
#: energy drift beyond which a fixed-step run of a conservative system gets a note
UNSTABLE_DRIFT = 0.5


def _in_chunks(fun, t0, t1, y0, method, nsteps, stride):
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
                      max_steps=k + 1)  # Ctrl-C: status 2, the chunk's steps kept
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


def _takes(method, option):
    from ..ode import _registry

    fn = _registry.get(method).function
    return option in inspect.signature(fn).parameters


def run(eqs, fun, t, y0, *, method, rtol, atol, step, n_output, t_eval, events, max_steps,
        first_step, max_step, dense_output, progress, values, notes):
    """Integrate and wrap the outcome in a :class:`Simulation` (see ``simulate``)."""
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
            nsteps = max(1, math.ceil(abs(t1 - t0) / step * (1 - 1e-12)))
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
    watch = Watch(fun, _labels(eqs.names, second), (t0, t1), progress, second)
    chunks = options.pop("chunks", None)
    if chunks is None:
        options["events"] = compile_events(eqs, events, values)
    start = time.perf_counter()
    try:
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            if chunks is None:
                res = ode.solve(watch, (t0, t1), y0, method=method, **options)
            else:
                res = _in_chunks(watch, t0, t1, y0, method, *chunks)
                stride = 1
    except KeyboardInterrupt:  # a method that keeps no partial result: the initial state
        watch.close()
        elapsed = time.perf_counter() - start
        return Simulation(eqs, None, values, elapsed, notes, status="interrupted",
                          message=f"The integration was interrupted at t = {watch.t!r}; method "
                          f"{method!r} keeps no partial result: only the initial state is "
                          "kept.", t=[t0], y=np.asarray(y0, dtype=float)[:, None],
                          t_events=[], method=method, t_stop=watch.t)
    finally:
        watch.close()
    elapsed = time.perf_counter() - start
    message = res.message
    t_stop = res.t_stop  # the end, the terminal event or the last accepted step
    if res.status == 2:
        t_end = float(res.t[-1]) if len(res.t) else t0
        who = ("the `progress` callback" if watch.stopped else "Ctrl-C (KeyboardInterrupt)")
        message = (f"The integration was stopped by {who} at t = {t_stop!r}; the samples "
                   f"up to t = {t_end!r} are kept.")
    elif res.status == -1:
        message = message + watch.diagnosis()
    status = None  # from the result (an event function's nan: -1, "failed", named by ode)
    t_out, y_out = res.t, res.y
    if not len(t_out):  # stopped before the first sample: the initial state at least
        t_out, y_out = np.array([t0]), np.asarray(y0, dtype=float)[:, None]
    if fixed and stride > 1:
        keep = np.arange(0, len(t_out), stride)
        if keep[-1] != len(t_out) - 1:
            keep = np.append(keep, len(t_out) - 1)
        t_out, y_out = t_out[keep], y_out[:, keep]
    sim = Simulation(eqs, res, values, elapsed, notes, message=message, t=t_out, y=y_out,
                     t_stop=t_stop, status=status)
    if (fixed and sim.status == "finished" and eqs.energy is not None and len(t_out) > 1
            and sim.energy_not_conserved() is None):
        drift = sim.energy_drift()
        if not drift <= UNSTABLE_DRIFT:  # a conservative system: E should stay constant
            sim = Simulation(eqs, res, values, elapsed, (*notes, (
                f"the energy changed by {drift:.3g} times its scale T(0) + |V(0)| with the "
                f"fixed step {step!r}: the step is probably too large for {method!r} (an "
                "unstable explicit method grows without bound); the motion is not to be "
                "trusted.")), message=message, t=t_out, y=y_out, t_stop=t_stop, status=status)
    return sim
