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
land at ``t0``). The zeros are located with Brent's method (:func:`scipy.optimize.brentq`) on
the dense output of the step where ``g`` changed sign, to a tolerance of a few ulps of ``t``;
their accuracy is therefore that of the dense output.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from scipy.optimize import brentq

from rigidmech._core.errors import ArgumentError, ArgumentTypeError

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
        self.g = np.array([self._call(i, t0, y0) for i in range(len(self.functions))])
        self.times: list[list[float]] = [[] for _ in self.functions]
        self.states: list[list[np.ndarray]] = [[] for _ in self.functions]
        self.hits = [0] * len(self.functions)
        self.t_stop: float | None = None
        self.y_stop: np.ndarray | None = None

    def _call(self, i, t, y):
        v = self.functions[i](t, y)
        try:
            return float(v)
        except (TypeError, ValueError):
            raise ArgumentTypeError(
                f"event function `events[{i}]` must return a real scalar; got {v!r}."
            ) from None

    def check(self, t_old: float, t_new: float, y_new: np.ndarray, interp: Callable) -> bool:
        """Look for zeros in ``(t_old, t_new]``; return True if a terminal event stops here.

        `interp(t)` must return the state (in the user's shape) anywhere in the step. After a
        True return, :attr:`t_stop` and :attr:`y_stop` hold the time and the state of the
        terminal event.
        """
        g_old = self.g
        g_new = np.array([self._call(i, t_new, y_new) for i in range(len(self.functions))])
        self.g = g_new
        up = (g_old <= 0) & (g_new >= 0)
        down = (g_old >= 0) & (g_new <= 0)
        found = []
        for i in range(len(g_new)):
            d = self.direction[i]
            if g_old[i] == 0.0 and g_new[i] == 0.0:
                continue
            if g_old[i] == 0.0 and (
                t_old == self._t0 or (len(self.times[i]) and self.times[i][-1] == t_old)
            ):
                continue  # a zero at the initial time, or already reported
            if (d > 0 and up[i]) or (d < 0 and down[i]) or (d == 0 and (up[i] or down[i])):
                if g_new[i] == 0.0:
                    te = t_new
                elif g_old[i] == 0.0:
                    te = t_old
                else:
                    te = brentq(
                        lambda s, i=i: self._call(i, s, interp(s)),
                        t_old,
                        t_new,
                        xtol=4 * np.finfo(float).eps * max(abs(t_old), abs(t_new), 1e-300),
                        rtol=4 * np.finfo(float).eps,
                    )
                found.append((te, i))
        if not found:
            return False
        sign = 1.0 if t_new >= t_old else -1.0
        found.sort(key=lambda p: sign * p[0])
        for te, i in found:
            ye = interp(te)
            self.times[i].append(te)
            self.states[i].append(np.array(ye, dtype=float, copy=True))
            self.hits[i] += 1
            if self.terminal[i] and self.hits[i] >= self.terminal[i]:
                self.t_stop, self.y_stop = te, np.array(ye, dtype=float, copy=True)
                return True
        return False

    @property
    def t_events(self) -> list[np.ndarray]:
        """For each event function, the array of times of its zeros."""
        return [np.array(ts, dtype=float) for ts in self.times]

    @property
    def y_events(self) -> list[np.ndarray]:
        """For each event function, the array of states at its zeros, shape (k, n)."""
        return [np.array(ys) if ys else np.empty((0, self._n)) for ys in self.states]
