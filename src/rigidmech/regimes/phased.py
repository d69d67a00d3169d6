"""Motion that changes regime: integration phase by phase (book, ch. 21.4, 23, 24).

With dry friction, contacts that may open or bodies that may tip, the equations of motion
change with the state of the contacts: a block slides or sticks, a cylinder rolls or slips,
a box slides or tips. The book solves such motions **phase by phase**: in each phase one set
of equations holds; the phase ends where a condition of that regime stops holding (the
sliding velocity vanishes, the friction needed to stick exceeds f_s N, a normal force would
become negative), and the next regime is chosen from the state at that instant.

:class:`Regime` holds the right-hand side of one phase and its :class:`Guard` functions
g(t, y), each a condition that ends the phase where it crosses zero, with the rule that
picks the next regime (and, optionally, a reset of the state, e.g. the sliding velocity set
to exactly zero when a body sticks). :func:`integrate_phases` integrates the phases one after
the other with :func:`rigidmech.ode.solve`, its events locating the switching instants, and
returns a :class:`PhasedMotion` that records the phases (start, end, regime, the guard that
ended it), prints them as a table and plots them.

Chattering: a guard that fires at the very start of a phase would switch back and forth at
one instant without the motion advancing. The guards of a new phase are ignored where they
are exactly zero at its start (a zero at the initial time is not an event), which is why the
transition rules reset the state exactly onto the switching surface; and a run of more than
``max_instant_switches`` switches without the time advancing raises an error instead of
looping.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from .. import ode
from .._core.errors import ArgumentError, ArgumentTypeError, NumericalError
from ..dynamics import _run  # the progress delays of simulate (one rule)
from ..ode._progress import Progress, for_run

__all__ = ["Guard", "Regime", "Phase", "PhasedMotion", "integrate_phases"]


class Guard:
    """A condition that ends a phase where ``function(t, y)`` crosses zero.

    Parameters
    ----------
    name : str
        What happens there (``"stops"``, ``"starts slipping"``, ...).
    function : callable
        ``g(t, y) -> float``.
    target : str, callable or None
        The next regime: its name, or ``target(t, y) -> name`` chosen from the state at the
        switch; None stops the motion there.
    direction : float
        Only crossings from negative to positive (> 0), positive to negative (< 0), or both
        (0, default).
    reset : callable, optional
        ``reset(t, y) -> y``: the state the next phase starts from (e.g. a velocity set to
        exactly zero).

    Examples
    --------
    >>> g = Guard("stops", lambda t, y: y[1], target="stick", direction=-1)
    >>> g
    Guard('stops', target='stick', direction=-1)
    """

    __slots__ = ("_name", "_function", "_target", "_direction", "_reset")

    def __init__(self, name: str, function: Callable, *, target=None, direction: float = 0.0,
                 reset: Callable | None = None):
        if not callable(function):
            raise ArgumentTypeError(f"`function` must be callable g(t, y); got "
                                    f"{type(function).__name__}.")
        if not (target is None or isinstance(target, str) or callable(target)):
            raise ArgumentTypeError(f"`target` must be a regime name, a callable or None; got "
                                    f"{type(target).__name__}.")
        if reset is not None and not callable(reset):
            raise ArgumentTypeError(f"`reset` must be callable; got {type(reset).__name__}.")
        self._name, self._function, self._target = str(name), function, target
        self._direction, self._reset = float(direction), reset

    name = property(lambda self: self._name, doc="What the guard detects.")
    function = property(lambda self: self._function, doc="g(t, y).")
    direction = property(lambda self: self._direction, doc="Direction of the crossings.")

    def next_regime(self, t, y):
        """The regime that follows, from the state at the switch.

        Examples
        --------
        >>> g = Guard("stops", lambda t, y: y[1], target=lambda t, y: "a" if y[0] > 0 else "b")
        >>> g.next_regime(1.0, [2.0, 0.0])
        'a'
        """
        return self._target(t, y) if callable(self._target) else self._target

    def reset(self, t, y):
        """The state the next phase starts from.

        Examples
        --------
        >>> g = Guard("stops", lambda t, y: y[1], reset=lambda t, y: [y[0], 0.0])
        >>> g.reset(1.0, [2.0, 1e-17])
        array([2., 0.])
        """
        return np.array(self._reset(t, y) if self._reset else y, dtype=float)

    def __repr__(self):
        target = self._target if not callable(self._target) else "<rule>"
        return f"Guard({self._name!r}, target={target!r}, direction={self._direction:g})"


class Regime:
    """One set of equations of motion, ``y' = rhs(t, y)``, and the guards that end it.

    Parameters
    ----------
    name : str
    rhs : callable or None
        ``rhs(t, y) -> dy/dt``; None for a state at rest (dy/dt = 0), which still watches
        its guards (a block stuck on a wagon whose acceleration grows).
    guards : sequence of Guard

    Examples
    --------
    >>> Regime("stick", None, [Guard("slips", lambda t, y: t - 1.0, target="slide")])
    Regime('stick', guards=['slips'])
    """

    __slots__ = ("_name", "_rhs", "_guards")

    def __init__(self, name: str, rhs: Callable | None = None, guards=()):
        if rhs is not None and not callable(rhs):
            raise ArgumentTypeError(f"`rhs` must be callable or None; got {type(rhs).__name__}.")
        guards = tuple(guards)
        for i, g in enumerate(guards):
            if not isinstance(g, Guard):
                raise ArgumentTypeError(f"`guards[{i}]` must be a Guard; got "
                                        f"{type(g).__name__}.")
        self._name, self._rhs, self._guards = str(name), rhs, guards

    name = property(lambda self: self._name, doc="Name of the regime.")
    guards = property(lambda self: self._guards, doc="The guards that end the regime.")

    def rhs(self, t, y):
        """dy/dt in this regime.

        Examples
        --------
        >>> import numpy as np
        >>> Regime("rest").rhs(0.0, np.array([1.0, 2.0]))
        array([0., 0.])
        """
        return np.zeros_like(y) if self._rhs is None else self._rhs(t, y)

    def __repr__(self):
        return f"Regime({self._name!r}, guards={[g.name for g in self._guards]!r})"


class Phase(NamedTuple):
    """One phase of a motion: the regime that held from ``start`` to ``end``, the states
    there, and the guard that ended it (None if the motion reached the end of the interval
    or a regime without successor).

    Examples
    --------
    >>> p = Phase("slide", 0.0, 1.5, (1.0, 0.0), (0.2, 0.0), "stops", None)
    >>> p.duration
    1.5
    """

    regime: str
    start: float
    end: float
    y_start: tuple
    y_end: tuple
    ended_by: str | None
    solution: object

    @property
    def duration(self) -> float:
        """end - start."""
        return self.end - self.start


class PhasedMotion:
    """The motion phase by phase (see :func:`integrate_phases`).

    Attributes
    ----------
    phases : tuple of Phase
    t : ndarray
        The times of every phase's steps, concatenated (switching instants appear twice,
        once at the end of a phase and once at the start of the next).
    y : ndarray, shape (n, len(t))

    Keyword ``regimes``: the :class:`Regime` of each name, for :meth:`derivative`.

    Examples
    --------
    >>> import numpy as np
    >>> fall = Regime("fall", lambda t, y: np.array([y[1], -10.0]),
    ...               [Guard("lands", lambda t, y: y[0], target="rest", direction=-1,
    ...                      reset=lambda t, y: [0.0, 0.0])])
    >>> m = integrate_phases([fall, Regime("rest")], "fall", (0.0, 2.0), [5.0, 0.0])
    >>> m.regimes, m.switch_times                    # lands at sqrt(2 h / g) = 1
    (('fall', 'rest'), (1.0,))
    >>> m.phases[0].ended_by, m(0.5).round(6)        # state at t = 0.5 from dense output
    ('lands', array([ 3.75, -5.  ]))
    >>> m.t[0], m.y.shape[0], m.names
    (np.float64(0.0), 2, ('y[0]', 'y[1]'))
    >>> axes = m.plot(components=[0], names=("height", "rate"))   # a tuple of Axes
    >>> import matplotlib.pyplot as plt; plt.close("all")
    >>> print(m.table())
    phase  regime  start  end  ended by
    1      fall    0      1    lands
    2      rest    1      2    -
    """

    __slots__ = ("_phases", "_names", "_regimes", "status", "message")

    def __init__(self, phases, names=None, *, status="finished", message="", regimes=None):
        self._phases = tuple(phases)
        self._names = tuple(names) if names is not None else None
        self._regimes = None if regimes is None else dict(regimes)
        #: how the run ended: "finished" (the end of the interval, or a regime without
        #: successor), "interrupted" (Ctrl-C, the progress callback) or "failed" (a phase
        #: failed, too many phases, chattering: see :func:`integrate_phases`); the last
        #: phase of a run stopped early ends where it stopped (``ended_by`` "interrupted"
        #: or "failed")
        self.status = status
        #: why the run ended early, in words ("" when it finished)
        self.message = message

    phases = property(lambda self: self._phases, doc="The phases, in time order.")

    @property
    def regimes(self) -> tuple:
        """The regime of each phase."""
        return tuple(p.regime for p in self._phases)

    @property
    def switch_times(self) -> tuple:
        """The instants where a phase ended and another began."""
        return tuple(float(p.end) for p in self._phases[:-1])

    @property
    def t(self) -> np.ndarray:
        return np.concatenate([p.solution.t for p in self._phases])

    @property
    def y(self) -> np.ndarray:
        return np.concatenate([p.solution.y for p in self._phases], axis=1)

    def __call__(self, t):
        """The state at time(s) ``t`` from the phases' dense outputs (n,) or (n, len(t))."""
        ts = np.atleast_1d(np.asarray(t, dtype=float))
        out = np.empty((len(self._phases[0].y_start), ts.size))
        for i, s in enumerate(ts):
            out[:, i] = self._phases[self._phase_at(s)].solution.sol(s)
        return out[:, 0] if np.ndim(t) == 0 else out

    def _phase_at(self, s):
        """The index of the phase at time ``s`` (at a switch, the phase that ends there)."""
        ends = np.array([p.end for p in self._phases])
        return min(int(np.searchsorted(ends, s, side="left")), len(self._phases) - 1)

    def derivative(self, t):
        """dy/dt at time(s) ``t`` from the equations of the regime of the phase then (at a
        switching instant, the phase that ends there), evaluated on the state of the
        phases' dense outputs; shape (n,) or (n, len(t)). For a state y = (q, q') its last
        half is q'', the accelerations along each phase (ch. 21.4, 23).

        Examples
        --------
        >>> import numpy as np
        >>> fall = Regime("fall", lambda t, y: np.array([y[1], -10.0]),
        ...               [Guard("lands", lambda t, y: y[0], target="rest", direction=-1,
        ...                      reset=lambda t, y: [0.0, 0.0])])
        >>> m = integrate_phases([fall, Regime("rest")], "fall", (0.0, 2.0), [5.0, 0.0])
        >>> m.derivative([0.5, 1.0, 1.5]).round(9).tolist()     # the switch at 1: falling
        [[-5.0, -10.0, 0.0], [-10.0, -10.0, 0.0]]
        """
        if self._regimes is None:
            raise ArgumentError(
                "derivative() needs the equations of the regimes, which this motion was not "
                "given; build it with integrate_phases() (or pass regimes= to PhasedMotion).")
        ts = np.atleast_1d(np.asarray(t, dtype=float))
        out = np.empty((len(self._phases[0].y_start), ts.size))
        for i, s in enumerate(ts):
            phase = self._phases[self._phase_at(s)]
            out[:, i] = self._regimes[phase.regime].rhs(s, phase.solution.sol(s))
        return out[:, 0] if np.ndim(t) == 0 else out

    def table(self) -> str:
        """The phases as a text table: regime, start, end, and what ended each."""
        rows = [("phase", "regime", "start", "end", "ended by")]
        for i, p in enumerate(self._phases):
            rows.append((str(i + 1), p.regime, f"{p.start:.10g}", f"{p.end:.10g}",
                         p.ended_by or "-"))
        widths = [max(len(r[c]) for r in rows) for c in range(5)]
        return "\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()
                         for r in rows)

    def __str__(self):
        return self.table()

    def __repr__(self):
        return f"PhasedMotion({len(self._phases)} phases: {' -> '.join(self.regimes)})"

    @property
    def names(self) -> tuple:
        """The names of the state components: those given, else ``y[0]``, ``y[1]``, ..."""
        if self._names is not None:
            return self._names
        return tuple(f"y[{i}]" for i in range(len(self._phases[0].y_start)))

    def plot(self, ax=None, *, components=None, names=None, units=None, degrees=False,
             path=None, samples: int = 200, component=None, label=None):
        """Plot the motion, one panel per state component, on the conventions of
        :meth:`Simulation.plot <rigidmech.dynamics.Simulation.plot>` (ch. 21.4, 23, 24).

        Each panel is labelled with its component's name and unit; each phase is drawn and
        shaded in its regime's colour, the switching instants dotted, the regimes named in a
        legend above the panels (off the data); a new figure has a constrained layout, so no
        label is cut.

        Parameters
        ----------
        ax : Axes or sequence of Axes, optional
            One per panel; default a new figure.
        components : sequence of int or str, optional
            The components drawn (indices or names), default all.
        names : sequence of str, optional
            A name for every state component (default :attr:`names`).
        units : dict, optional
            Name -> unit (``{"x": "m", "x'": "m/s"}``).
        degrees : bool
            Components in rad (rad/s) drawn in degrees (deg/s).
        path : str or path, optional
            Save the figure there.
        samples : int
            Points per phase (from its dense output).
        component, label : one component and its axis label verbatim (the former interface)

        Returns
        -------
        tuple of Axes

        Examples
        --------
        >>> import numpy as np
        >>> fall = Regime("fall", lambda t, y: np.array([y[1], -10.0]),
        ...               [Guard("lands", lambda t, y: y[0], target="rest", direction=-1,
        ...                      reset=lambda t, y: [0.0, 0.0])])
        >>> m = integrate_phases([fall, Regime("rest")], "fall", (0.0, 2.0), [5.0, 0.0])
        >>> axes = m.plot(names=("z", "z'"), units={"z": "m", "z'": "m/s"})
        >>> [a.get_ylabel() for a in axes], axes[-1].get_xlabel()
        (['$z$ [m]', "$z'$ [m/s]"], 't [s]')
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """
        from ._phase_plot import plot_phases

        return plot_phases(self, ax, components=components, names=names, units=units,
                           degrees=degrees, path=path, samples=samples, component=component,
                           label=label)


def _terminal(fn, direction):
    def g(t, y):
        return fn(t, y)

    g.terminal = True
    g.direction = direction
    return g


def integrate_phases(regimes, start, t_span, y0, *, method: str = "dop853",
                     rtol: float = 1e-10, atol: float = 1e-12, max_step: float = math.inf,
                     max_phases: int = 10_000, max_instant_switches: int = 4,
                     progress=None) -> PhasedMotion:
    """Integrate a motion phase by phase (ch. 21.4, 23, 24).

    Parameters
    ----------
    regimes : sequence of Regime
    start : str or callable
        The first regime, or ``start(t0, y0) -> name``.
    t_span : (float, float)
        Start and end times (forward).
    y0 : array_like, shape (n,)
    method, rtol, atol, max_step
        Passed to :func:`rigidmech.ode.solve` (an adaptive method: its events locate the
        switches on its dense output).
    max_phases : int
        Largest number of phases.
    max_instant_switches : int
        Largest number of successive switches that do not advance the time.
    progress : None, bool, callable or rigidmech.ode._progress.Progress
        As ``simulate``'s, over the whole interval (all the phases): None (default) a bar on
        stderr for runs longer than 2 s when stderr is a terminal, True the bar, False
        nothing, a callable ``progress(t)`` called about every 0.1 s (returning False stops
        the run).

    Returns
    -------
    PhasedMotion
        With ``status`` "finished", or "interrupted" (Ctrl-C or the progress callback): the
        phases finished and the one under way up to the time reached (``ended_by``
        "interrupted").

    Raises
    ------
    ArgumentError
        Unknown regime name, bad interval.
    NumericalError
        A failed phase, too many phases, or switches that do not advance the time
        (chattering). The error's ``motion`` attribute holds the motion computed until then
        (status "failed"): the phases finished and the failed one up to its last state
        reached (``ended_by`` "failed").

    Examples
    --------
    A body thrown up at 5 m/s that sticks to a ceiling at height 1 m:

    >>> import numpy as np
    >>> fly = Regime("flight", lambda t, y: np.array([y[1], -9.81]),
    ...              [Guard("hits the ceiling", lambda t, y: y[0] - 1.0, target="stuck",
    ...                     direction=1, reset=lambda t, y: [1.0, 0.0])])
    >>> stuck = Regime("stuck")
    >>> m = integrate_phases([fly, stuck], "flight", (0.0, 2.0), [0.0, 5.0], rtol=1e-12)
    >>> m.regimes, round(m.switch_times[0], 10)    # (5 - sqrt(25 - 2 g)) / g
    (('flight', 'stuck'), 0.2732433536)
    >>> print(m)
    phase  regime  start         end           ended by
    1      flight  0             0.2732433536  hits the ceiling
    2      stuck   0.2732433536  2             -
    """
    by_name = {}
    for r in regimes:
        if not isinstance(r, Regime):
            raise ArgumentTypeError(f"`regimes` must hold Regime objects; got "
                                    f"{type(r).__name__}.")
        by_name[r.name] = r
    try:
        t0, t1 = (float(v) for v in t_span)
    except (TypeError, ValueError):
        raise ArgumentError(f"`t_span` must be a pair of times; got {t_span!r}.") from None
    if not t1 > t0:
        raise ArgumentError(f"`t_span` must run forward, t1 > t0; got {t_span!r}.")
    y = np.array(y0, dtype=float)
    current = start(t0, y) if callable(start) else start

    def check(name):
        if name not in by_name:
            raise ArgumentError(f"unknown regime {name!r}; the regimes are "
                                f"{', '.join(by_name)}.")
        return by_name[name]

    prog = progress if isinstance(progress, Progress) else for_run(
        progress, (t0, t1), every=_run.PROGRESS_EVERY, delay=_run.PROGRESS_DELAY)
    try:
        return _phases(check, current, t0, t1, y, prog, method=method, rtol=rtol, atol=atol,
                       max_step=max_step, max_phases=max_phases,
                       max_instant_switches=max_instant_switches, regimes=by_name)
    finally:
        if prog is not None and prog is not progress:
            prog.close()


def _stopped(phases, name, t, y, res, how):
    """The phases followed by the one under way (``name`` from (t, y)) up to the last state
    it reached, if it made a step (its dense output covers it), ``ended_by`` `how`."""
    if res.t_stop is not None and res.y_stop is not None and res.t_stop != t \
            and getattr(res, "sol", None) is not None:
        phases = [*phases, Phase(name, t, float(res.t_stop), tuple(float(v) for v in y),
                                 tuple(float(v) for v in np.ravel(res.y_stop)), how, res)]
    return phases


def _fail(phases, message, regimes=None):
    exc = NumericalError(message)
    exc.motion = PhasedMotion(phases, status="failed", message=message, regimes=regimes)
    return exc


def _phases(check, current, t, t1, y, prog, *, method, rtol, atol, max_step, max_phases,
            max_instant_switches, regimes=None):
    phases, instant = [], 0
    while True:
        regime = check(current)
        guards = regime.guards
        events = [_terminal(g.function, g.direction) for g in guards] or None
        res = ode.solve(regime.rhs, (t, t1), y, method=method, rtol=rtol, atol=atol,
                        max_step=max_step, events=events, dense_output=True,
                        **({} if prog is None else {"progress": prog}))
        if res.status == 2:  # Ctrl-C or the progress callback: what was computed is kept
            phases = _stopped(phases, regime.name, t, y, res, "interrupted")
            who = ("the `progress` callback" if prog is not None and prog.stopped
                   else "Ctrl-C (KeyboardInterrupt)")
            return PhasedMotion(phases, status="interrupted", message=(
                f"The integration was stopped by {who} at t = {res.t_stop!r}, in phase "
                f"{len(phases)} ({regime.name}); the phases up to there are kept."),
                regimes=regimes)
        if not res.success:
            message = (f"phase {len(phases) + 1} ({regime.name}) failed at t = "
                       f"{res.t[-1] if len(res.t) else t}: {res.message}")
            raise _fail(_stopped(phases, regime.name, t, y, res, "failed"), message, regimes)
        t_end, y_end = float(res.t[-1]), res.y[:, -1].copy()
        fired = None
        if res.status == 1:
            fired = min((i for i in range(len(guards)) if len(res.t_events[i])
                         and res.t_events[i][-1] == t_end), default=None)
        phases.append(Phase(regime.name, t, t_end, tuple(float(v) for v in y),
                            tuple(float(v) for v in y_end),
                            None if fired is None else guards[fired].name, res))
        if fired is None:
            break
        guard = guards[fired]
        nxt = guard.next_regime(t_end, y_end)
        instant = instant + 1 if t_end == t else 0
        if instant > max_instant_switches:
            raise _fail(phases,
                f"chattering: {instant} switches at t = {t_end} without the time advancing "
                f"(last: {regime.name} -> {nxt} by '{guard.name}'); the transition rules "
                "must leave the state where the new regime's guards do not fire at once.",
                regimes)
        if nxt is None or t_end >= t1:
            break
        if len(phases) >= max_phases:
            raise _fail(phases, f"more than `max_phases` = {max_phases} phases before t = "
                                f"{t1}; last regime {regime.name} at t = {t_end}.", regimes)
        y, t, current = guard.reset(t_end, y_end), t_end, nxt
    return PhasedMotion(phases, regimes=regimes)
