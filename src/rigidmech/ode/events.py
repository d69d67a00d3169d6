"""Events: the times where functions ``g(t, y)`` of the motion cross zero (book, ch. 27).

An event function is any callable ``g(t, y) -> float``. Two optional attributes, as in scipy's
``solve_ivp``, tell the solver what to do with it:

``terminal`` : bool or int
    ``True`` (or ``1``) stops the integration at the first zero; an integer ``k > 1`` stops it at
    the ``k``-th zero. Default ``False``.
``direction`` : float
    ``> 0``: only zeros where ``g`` goes from negative to positive; ``< 0``: from positive to
    negative; ``0`` (default): both.

A zero of ``g`` at the initial state is not an event (a ball thrown from the ground does not
land at ``t0``), but a crossing later in the first step is. Each step is scanned on the dense
output at :attr:`EventTracker.SAMPLES` - 1 interior points as well as at its ends, so that two
zeros inside one step (``g`` of the same sign at both ends, a ``- + -`` pattern in between)
are seen; zeros closer together than a quarter of a step can still be missed. Each zero is
located with Brent's method (:func:`scipy.optimize.brentq`) on the dense output between two
samples of opposite signs, to a tolerance of a few ulps of ``t``; its accuracy is therefore
that of the dense output.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech._core.lazy import lazy_functions

# lazy: import cost (scipy.optimize takes ~0.3 s; see docs/performance)
brentq, = lazy_functions(globals(), "scipy.optimize", "brentq")

__all__ = ["EventTracker", "event"]


def event(fn: Callable | None = None, *, terminal: bool | int = False, direction: float = 0.0):
    """Mark `fn` as an event function with the given `terminal` and `direction` attributes.

    Usable as ``event(g, terminal=True)`` or as a decorator ``@event(direction=-1)``.

    Parameters
    ----------
    fn : callable, optional
        ``g(t, y) -> float``.
    terminal : bool or int
        Stop the integration at the first (or the `terminal`-th) zero.
    direction : float
        Sign of the crossings that count (see the module docstring).

    Returns
    -------
    callable
        `fn` with the two attributes set (or a decorator doing so).

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> ground = event(lambda t, y: y[0], terminal=True, direction=-1)
    >>> r = ode.solve(lambda t, y: np.array([y[1], -9.81]), (0.0, 10.0), [20.0, 0.0],
    ...               method="dop853", events=ground)
    >>> round(float(r.t_events[0][0]), 10), r.status        # sqrt(2 h / g)
    (2.0192751094, 1)
    """

    def mark(f):
        if not callable(f):
            raise ArgumentTypeError(f"`fn` must be callable; got {type(f).__name__}.")
        f.terminal = terminal
        f.direction = direction
        return f

    return mark if fn is None else mark(fn)


def _as_event_list(events) -> list[Callable]:
    if callable(events):
        return [events]
    if isinstance(events, Sequence) and all(callable(g) for g in events):
        return list(events)
    raise ArgumentTypeError(
        "`events` must be a callable g(t, y) or a sequence of such callables; "
        f"got {type(events).__name__}."
    )


class EventTracker:
    """Watches event functions step after step and locates their zeros.

    Built once by :func:`rigidmech.ode.solve`; the integrators call :meth:`check` after every
    accepted step with the step's interpolant.

    Parameters
    ----------
    events : callable or sequence of callable
        Event functions ``g(t, y)`` (see the module docstring).
    t0 : float
        Initial time.
    y0 : ndarray
        Initial state.

    Examples
    --------
    >>> import numpy as np
    >>> tr = EventTracker(lambda t, y: y[0] - 0.5, 0.0, np.array([0.0]))
    >>> tr.check(0.0, 1.0, np.array([1.0]), lambda t: np.array([t]))
    False
    >>> [float(v) for v in tr.t_events[0]]
    [0.5]
    """

    def __init__(self, events, t0: float, y0: np.ndarray):
        self.functions = _as_event_list(events)
        self._n = int(np.size(y0))
        self._t0 = t0
        self.terminal = []
        self.direction = []
        for i, g in enumerate(self.functions):
            term = getattr(g, "terminal", False)
            if isinstance(term, bool | np.bool_):
                count = int(term)
            elif isinstance(term, int | np.integer) and term >= 0:
                count = int(term)
            else:
                raise ArgumentError(
                    f"`events[{i}].terminal` must be a bool or an int >= 0; got {term!r}."
                )
            self.terminal.append(count)
            self.direction.append(float(getattr(g, "direction", 0.0)))
        self.nan = None  # (index, t, value) of the first non-finite value of an event function
        self.g = np.array([self._call(i, t0, y0) for i in range(len(self.functions))])
        self.times: list[list[float]] = [[] for _ in self.functions]
        self.states: list[list[np.ndarray]] = [[] for _ in self.functions]
        self.hits = [0] * len(self.functions)
        self.t_stop: float | None = None
        self.y_stop: np.ndarray | None = None

    def _call(self, i, t, y):
        v = self.functions[i](t, y)
        try:
            value = float(v)
        except (TypeError, ValueError):
            raise ArgumentTypeError(
                f"event function `events[{i}]` must return a real scalar; got {v!r}."
            ) from None
        if not math.isfinite(value) and self.nan is None:  # noted, see :meth:`failure`
            self.nan = (i, float(t), value)
        return value

    def failure(self):
        """A sentence naming the first event function that returned nan (or an infinity), and
        where, or None.

        Its zeros cannot be located there (a nan has no sign): :func:`~rigidmech.ode.solve`
        then reports the run as failed (status -1), the motion computed being kept.

        Examples
        --------
        >>> import numpy as np
        >>> tr = EventTracker(lambda t, y: np.nan if t > 0.5 else 1.0, 0.0, np.array([0.0]))
        >>> tr.check(0.0, 1.0, np.array([1.0]), lambda t: np.array([t]))
        False
        >>> tr.failure()[:50]
        'The event function events[0] returned nan at t = 1'
        """
        if self.nan is None:
            return None
        i, t, value = self.nan
        return (f"The event function events[{i}] returned {value} at t = {t!r}: its zeros "
                "cannot be located, events may be missing.")

    #: Sub-intervals of a step on which the event functions are sampled (on the interpolant),
    #: so that two zeros inside one step (``g`` negative at both ends) are seen.
    SAMPLES = 4

    def check(self, t_old: float, t_new: float, y_new: np.ndarray, interp: Callable,
              exact: Callable | None = None) -> bool:
        """Look for zeros in ``(t_old, t_new]``; return True if a terminal event stops here.

        `interp(t)` must return the state (in the user's shape) anywhere in the step. The
        functions are sampled at :attr:`SAMPLES` - 1 interior points of the step (on
        `interp`), so that a pair of zeros inside one step (a sign pattern ``- + -`` of the
        samples) is found and each zero refined, on `exact(t)` if given (the solution inside
        the step as accurate as the step, for methods whose interpolant is less accurate; the
        state reported at the event is taken there too). After a True return, :attr:`t_stop` and
        :attr:`y_stop` hold the time and the state of the terminal event.
        """
        g_old = self.g
        g_new = np.array([self._call(i, t_new, y_new) for i in range(len(self.functions))])
        self.g = g_new
        ts, gs = self._samples(t_old, t_new, g_old, g_new, interp)
        found = []
        for i in range(len(g_new)):
            found += [(te, i) for te in self._zeros(i, ts, gs[:, i], interp, exact)]
        if not found:
            return False
        sign = 1.0 if t_new >= t_old else -1.0
        found.sort(key=lambda p: sign * p[0])
        for te, i in found:
            ye = (exact or interp)(te)
            self.times[i].append(te)
            self.states[i].append(np.array(ye, dtype=float, copy=True))
            self.hits[i] += 1
            if self.terminal[i] and self.hits[i] >= self.terminal[i]:
                self.t_stop, self.y_stop = te, np.array(ye, dtype=float, copy=True)
                return True
        return False

    def _samples(self, t_old, t_new, g_old, g_new, interp):
        """Times ``(SAMPLES + 1,)`` across the step and the event values there."""
        m = self.SAMPLES
        ts = [t_old + (t_new - t_old) * (k / m) for k in range(m)] + [t_new]
        rows = [g_old]
        for tk in ts[1:-1]:
            yk = interp(tk)
            rows.append([self._call(i, tk, yk) for i in range(len(self.functions))])
        rows.append(g_new)
        return ts, np.array(rows, dtype=float)

    def _zeros(self, i, ts, g, interp, exact):
        """Zeros of function `i` between consecutive samples, in the directions it watches."""
        d = self.direction[i]
        out = []
        for k in range(len(ts) - 1):
            ga, gb = g[k], g[k + 1]
            if ga == 0.0:
                continue  # reported as the end of the previous interval (or t0: not an event)
            up, down = ga < 0.0 <= gb, ga > 0.0 >= gb
            if not ((d >= 0 and up) or (d <= 0 and down)):
                continue
            if gb == 0.0:
                out.append(ts[k + 1])
                continue
            te = self._refine(i, ts[k], ts[k + 1], interp)
            out.append(te if exact is None else self._secant(i, te, ts[0], ts[-1], exact))
        return out

    def _refine(self, i, ta, tb, interp):
        """The zero of function `i` in ``(ta, tb)`` by Brent's method on the interpolant."""

        def g(s):
            return self._call(i, s, interp(s))

        ga, gb = g(ta), g(tb)
        if ga == 0.0 or gb == 0.0 or (ga > 0) == (gb > 0):  # the interpolant's rounding
            return tb if abs(gb) <= abs(ga) else ta
        return brentq(g, ta, tb, xtol=4 * np.finfo(float).eps * max(abs(ta), abs(tb), 1e-300),
                      rtol=4 * np.finfo(float).eps)

    def _secant(self, i, te, t_old, t_new, exact):
        """The zero of function `i` on the accurate solution `exact`, by secant iterations
        from `te` (the zero on the interpolant); `te` itself if they leave the step."""
        lo, hi = min(t_old, t_new), max(t_old, t_new)
        eps = np.finfo(float).eps
        a, b = te, te + 1e-6 * (t_new - t_old)
        ga, gb = self._call(i, a, exact(a)), self._call(i, b, exact(b))
        for _ in range(30):
            if gb == ga or not np.isfinite(gb):
                break
            a, b, ga = b, b - gb * (b - a) / (gb - ga), gb
            if not lo <= b <= hi:
                return te
            if abs(b - a) <= 4 * eps * max(abs(b), 1e-300):
                return b
            gb = self._call(i, b, exact(b))
            if gb == 0.0:
                return b
        return b if lo <= b <= hi and abs(gb) <= abs(ga) else te

    @property
    def t_events(self) -> list[np.ndarray]:
        """For each event function, the array of times of its zeros."""
        return [np.array(ts, dtype=float) for ts in self.times]

    @property
    def y_events(self) -> list[np.ndarray]:
        """For each event function, the array of states at its zeros, shape (k, n)."""
        return [np.array(ys) if ys else np.empty((0, self._n)) for ys in self.states]
