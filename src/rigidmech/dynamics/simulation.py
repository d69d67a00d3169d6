"""A numerically integrated motion and what is computed along it (book, ch. 27).

:class:`Simulation` is what :meth:`EquationsOfMotion.simulate` returns, whatever the outcome:
its :attr:`~Simulation.status` says how the run ended (``"finished"``, ``"event"``,
``"failed"``, ``"interrupted"``) and it keeps everything computed until then. Along the motion
it evaluates any expression of the motion (:meth:`~Simulation.evaluate`), the energy and its
drift, the action of a connection (:meth:`~Simulation.connection_action`); it saves to and loads
from ``.npz`` and ``.csv`` files.

Developers: this module holds the result value (and :class:`Event`); what is computed along
the motion is in :mod:`rigidmech.dynamics._along`, saving, loading and plotting in
:mod:`rigidmech.dynamics._files` (see "Where each concern lives" in the API docs).
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .._core.errors import ArgumentTypeError, NumericalError
from . import _along, _files

__all__ = ["Simulation", "Event", "load_simulation"]

#: ``OdeResult.status`` -> :attr:`Simulation.status`
_STATUS = {0: "finished", 1: "event", -1: "failed", 2: "interrupted"}


class Event:
    """An event of a simulation written as an expression of the motion (ch. 27): the times
    where ``expr`` (of t, the coordinates q(t), their rates q'(t), the constants and the inputs)
    crosses zero are located; ``terminal`` stops the run there. The expression may also hold
    the accelerations q''(t), the solution of the equations of motion at the state (an event
    on an acceleration or on a connection action written with q'', such as a normal force
    that vanishes). The states at the events: :meth:`Simulation.at_events`.

    Parameters
    ----------
    expr : sympy expression
    terminal : bool or int
        Stop at the first zero (or at the ``terminal``-th one).
    direction : float
        ``> 0`` only crossings from negative to positive, ``< 0`` the other way, 0 both.

    Examples
    --------
    >>> import sympy as sp, rigidmech as rm
    >>> x = rm.coordinates("x")
    >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
    ...                            forcing=sp.ImmutableMatrix([[-9.81]]))
    >>> ground = Event(x, terminal=True, direction=-1)
    >>> sim = eqs.simulate(t=(0, 10), q0=[20.0], events=[ground])
    >>> sim.status, round(float(sim.t_events[0][0]), 8)          # sqrt(2 h / g)
    ('event', 2.01927511)
    """

    __slots__ = ("expr", "terminal", "direction")

    def __init__(self, expr, *, terminal=False, direction=0.0):
        try:
            expr = sp.sympify(expr)
        except (sp.SympifyError, TypeError):
            raise ArgumentTypeError(
                f"`expr` must be a sympy expression of the motion; got {expr!r}.") from None
        object.__setattr__(self, "expr", expr)
        object.__setattr__(self, "terminal", terminal)
        object.__setattr__(self, "direction", float(direction))

    def __setattr__(self, name, value):
        raise AttributeError(f"Event is immutable; cannot set {name!r}.")

    def __repr__(self):
        return f"Event({self.expr}, terminal={self.terminal!r}, direction={self.direction:g})"


class Simulation:
    """A numerically integrated motion: times, states, how the run ended, and what can be
    computed along it (ch. 27).

    Attributes
    ----------
    t : ndarray, shape (n_points,)
        The sample times (see :meth:`EquationsOfMotion.simulate` for where they come from).
    q, u : ndarray, shape (n, n_points)
        Coordinates and rates at ``t``.
    status : {"finished", "event", "failed", "interrupted"}
        How the run ended: the end of the time span reached; a terminal event; a numerical
        failure (:attr:`message` says what and at which t); stopped on request (Ctrl-C, or a
        ``progress`` callback returning False). In every case the samples computed so far
        are kept, and the state reached when the run stopped early (see :attr:`t_stop`).
    message : str
        Why the run ended, in words.
    result : rigidmech.ode.OdeResult or None
        The solver's result (None for a simulation loaded from a file).
    elapsed : float
        Wall time of the integration, seconds.
    notes : tuple of str
        What the run noted without failing: values given for constants that dropped out of
        the equations (ignored); an initial state off the constraints, assembled on them
        (what moved; see :attr:`q0_given`); Baumgarte's stabilisation unable to act within
        a run without projection; a fixed step too large for a conservative system.

    Examples
    --------
    >>> import sympy as sp, numpy as np
    >>> import rigidmech as rm
    >>> x = rm.coordinates("x"); k = sp.Symbol("k")
    >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
    ...     forcing=sp.ImmutableMatrix([[-k * x]]),
    ...     energy=(x.diff(rm.t)**2 + k * x**2) / 2)
    >>> sim = eqs.simulate(t=(0, 3), q0=[1.0], rtol=1e-10, atol=1e-12, k=4.0)
    >>> sim.status, bool(abs(sim.q[0, -1] - np.cos(6.0)) < 1e-8), sim.energy_drift() < 1e-9
    ('finished', True, True)
    >>> bool(np.allclose(sim.evaluate(x.diff(rm.t, 2)), -4.0 * sim.q[0]))
    True
    """

    __slots__ = ("_eqs", "result", "t", "q", "u", "_params", "elapsed", "notes", "status",
                 "message", "_names", "_t_events", "_y_events", "_method", "_t_stop",
                 "_given")

    def __init__(self, eqs, result, params, elapsed, notes=(), *, status=None, message=None,
                 names=None, t=None, y=None, t_events=None, method=None, t_stop=None,
                 given=None, y_events=None):
        self._eqs = eqs
        self.result = result
        self._names = tuple(names) if names is not None else tuple(eqs.names)
        n = len(self._names)
        t = result.t if t is None else np.asarray(t, dtype=float)
        y = result.y if y is None else np.asarray(y, dtype=float).reshape(2 * n, len(t))
        self.t, self.q, self.u = t, y[:n], y[n:]
        self._params = dict(params)
        self.elapsed = float(elapsed)
        self.notes = tuple(notes)
        self.status = status if status is not None else _STATUS.get(result.status, "failed")
        self.message = message if message is not None else result.message
        self._t_events = (list(t_events) if t_events is not None else
                          [np.asarray(x) for x in result.t_events] if result is not None
                          else [])
        if y_events is None and t_events is None and result is not None:
            y_events = [np.asarray(ye, dtype=float).reshape(-1, 2 * n).T
                        for ye in result.y_events]
        self._y_events = (None if y_events is None else
                          [np.asarray(ye, dtype=float).reshape(2 * n, -1) for ye in y_events])
        self._method = method if method is not None else (result.method if result else None)
        self._t_stop = float(t_stop) if t_stop is not None else (
            float(self.t[-1]) if self.t.size else math.nan)
        self._given = None if given is None else tuple(np.array(g, dtype=float)
                                                       for g in given)

    # -- what the run was ---------------------------------------------------------------
    @property
    def equations(self):
        """The equations that were integrated (None for a simulation loaded from a file)."""
        return self._eqs

    @property
    def names(self) -> tuple:
        """The names of the coordinates, in the order of the rows of :attr:`q`."""
        return self._names

    @property
    def parameters(self) -> dict:
        """The values of the constants (and of the inputs) the run was given (a copy)."""
        return dict(self._params)

    @property
    def method(self):
        """The integration method's name."""
        return self._method

    @property
    def success(self) -> bool:
        """True if the run reached the end of its span or a terminal event."""
        return self.status in ("finished", "event")

    @property
    def t_stop(self) -> float:
        """The time the integration reached: the end of the span, the terminal event, or the
        last step accepted before a failure or an interruption. A run stopped early (Ctrl-C,
        the ``progress`` callback, ``max_steps``, a failure of the right-hand side) keeps the
        state it reached there as its last sample, after the samples asked for: ``t[-1] ==
        t_stop``; after a plain step size underflow (a singularity the last step may have
        jumped) the last sample, ``t[-1]``, is earlier and the message gives that state.

        Examples
        --------
        >>> import sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                            forcing=sp.ImmutableMatrix([[-x]]))
        >>> sim = eqs.simulate(t=(0, 10), q0=[1.0], n_output=3, max_steps=5)
        >>> sim.status, len(sim.t), 0 < sim.t_stop < 10, bool(sim.t[-1] == sim.t_stop)
        ('failed', 2, True, True)
        """
        return self._t_stop

    @property
    def q0_given(self):
        """The initial coordinates as given to ``simulate`` (an array in the order of
        :attr:`names`; written by :meth:`save` and read back by :meth:`load`, None for
        a file written before it was saved). The run starts from
        ``q[:, 0]``, which differs when the values given were off the constraints and were
        assembled on them (a note says what moved; see :meth:`EquationsOfMotion.simulate`'s
        ``independent``).

        Examples
        --------
        >>> import sympy as sp, rigidmech as rm
        >>> from rigidmech.dynamics import Constraints
        >>> x, y = rm.coordinates("x y")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
        ...     forcing=sp.Matrix([0, -1]), constraints=Constraints((x, y),
        ...     [("line", x.diff(rm.t) - y.diff(rm.t), x - y)]))
        >>> sim = eqs.simulate(t=(0, 1), q0=[1.0, 0.0], n_output=2, independent=["x"])
        >>> sim.q0_given.tolist(), sim.q[:, 0].tolist()
        ([1.0, 0.0], [1.0, 1.0])
        """
        return None if self._given is None else self._given[0].copy()

    @property
    def u0_given(self):
        """The initial rates as given to ``simulate`` (see :attr:`q0_given`)."""
        return None if self._given is None else self._given[1].copy()

    @property
    def t_events(self) -> list:
        """For each event given to ``simulate``, the times where it occurred (the states
        there: :meth:`at_events`)."""
        return list(self._t_events)

    def at_events(self, which=0) -> Simulation:
        """The states at the occurrences of the event ``which`` (its index in the list of
        ``events`` given to ``simulate``), as a :class:`Simulation` whose samples are those
        states (ch. 27): its :attr:`t` is :attr:`t_events` ``[which]``, its :attr:`q` and
        :attr:`u` the coordinates and rates located there, and every computation along a
        motion (:meth:`evaluate` with q'', :meth:`energy`, :meth:`connection_action`) works
        on it. The states are the solver's, at the located zeros (the accuracy of the run),
        not interpolated from the samples.

        Parameters
        ----------
        which : int
            The index of the event, in the order given to ``simulate``.

        Examples
        --------
        >>> import numpy as np, sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                            forcing=sp.ImmutableMatrix([[-x]]))
        >>> sim = eqs.simulate(t=(0, 7), q0=[1.0], events=[x], rtol=1e-10, atol=1e-12)
        >>> at = sim.at_events(0)               # x = cos t crosses 0 at pi/2 and 3 pi/2
        >>> at.t.round(8).tolist(), at.u.round(8).tolist()
        ([1.57079633, 4.71238898], [[-1.0, 1.0]])
        >>> (at.evaluate(x.diff(rm.t, 2)) + at.q[0]).round(12).tolist()
        [0.0, 0.0]
        """
        return _along.at_events(self, which)

    def check(self):
        """Raise :class:`~rigidmech._core.errors.NumericalError` if the run failed (status
        ``"failed"``), with this simulation, holding the motion up to the failure, attached
        as the error's ``simulation`` attribute; return the simulation otherwise (an
        interruption is not a failure: it was asked for).

        Examples
        --------
        >>> import sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                            forcing=sp.ImmutableMatrix([[2 * x**3]]))  # x = 1/(1 - t)
        >>> sim = eqs.simulate(t=(0, 2), q0=[1.0], u0=[1.0])
        >>> sim.status, bool(0.99 < sim.t_stop < 1.01)
        ('failed', True)
        >>> try:
        ...     sim.check()
        ... except NumericalError as exc:
        ...     exc.simulation is sim
        True
        """
        if self.status == "failed":
            exc = NumericalError(f"integration failed: {self.message}")
            exc.simulation = self
            raise exc
        return self

    # -- along the motion ---------------------------------------------------------------
    def evaluate(self, expr, frame=None):
        """Evaluate a symbolic expression along the motion; returns an array over the sample
        times (for a Matrix, its shape followed by the times; for a
        :class:`~rigidmech.vectors.Vector`, its three components in the basis of ``frame``,
        shape (3, n_points)). Compiled once per call.

        The expression may hold t, the coordinates q(t) and their first and second
        derivatives (q'' is the solution of the equations of motion), the inputs and
        constants given to :meth:`EquationsOfMotion.simulate` (including those that dropped
        out of the equations).

        Examples
        --------
        >>> import sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[2]]),
        ...                            forcing=sp.ImmutableMatrix([[-8 * x]]))
        >>> sim = eqs.simulate(t=(0, 1), q0=[1.0], n_output=3)
        >>> sim.evaluate(x.diff(rm.t, 2) + 4 * x).round(12).tolist()
        [0.0, 0.0, 0.0]
        >>> R0 = rm.Frame("R0"); P = R0.point("P", x, 0, 0)
        >>> sim.evaluate(P.velocity(R0), frame=R0).shape     # (vx, vy, vz) at the 3 samples
        (3, 3)
        """
        return _along.evaluate(self, expr, frame)

    def connection_action(self, parent, child, *, basis=None, system=None,
                          label=None, at=None) -> dict:
        """The action of ``parent`` on ``child`` through their connection (ch. 18.2) along the
        motion: its six components as time series, in one call (compiled once).

        Parameters
        ----------
        parent, child : Body or Frame
            The two solids of the connection, as given to ``System.connect``.
        basis : Frame, optional
            Components of the resultant (X, Y, Z) and of the moment at the joint's point
            (L, M, N) along the axes of this frame; default: the joint's own basis (u, v, w),
            as :meth:`System.connection_components`.
        system : System, optional
            The system the equations were derived from; by default the one they remember
            (equations derived by ``System.equations_of_motion``). It must not have changed
            since (an action or a connection added): its equations would differ.
        label : str, optional
            The connection's label, when several connections join the same two solids (as
            :meth:`System.connection_action`).
        at : Point, optional
            The point of the moment (L, M, N), with ``basis``; default: the joint's point.

        In a system with linking connections (closed loops, rolling, gears) the Lagrange
        multipliers the actions are written with are evaluated at each sample from the
        stored state (as :meth:`System.multipliers`).

        Returns
        -------
        dict
            ``{"X": array, "Y": ..., "Z": ..., "L": ..., "M": ..., "N": ...}`` over :attr:`t`.

        Examples
        --------
        >>> import numpy as np, rigidmech as rm
        >>> q = rm.coordinates("q"); m, L, g = rm.constants("m L g", positive=True)
        >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> bob = rm.Body("bob", frame=R1, mass=m, centre=R0.origin.moved("G", L * R1.i))
        >>> s = rm.System(galilean=R0)
        >>> s.connect(R0, bob, rm.joints.Pivot(at=R0.origin, axis=R0.k))
        >>> s.act(rm.gravity(g * R0.i))
        >>> sim = s.equations_of_motion().simulate(t=(0, 1), q0=[0.0], m=2.0, L=1.0, g=9.81)
        >>> N = sim.connection_action(R0, bob, basis=R0)
        >>> bool(np.allclose(N["X"], -2.0 * 9.81))       # at rest below the pivot: -m g
        True

        The resultant R and the moment M(A) at a point A as vectors in R0, shape (3, n):

        >>> A = R0.point("A", 0, 0.5, 0)
        >>> N = sim.connection_action(R0, bob, basis=R0, at=A)
        >>> R, M_A = np.array([N[k] for k in "XYZ"]), np.array([N[k] for k in "LMN"])
        >>> bool(np.allclose(M_A[2], -0.5 * 2.0 * 9.81))  # M(A) = M(O) + R x OA, OA = 0.5 j
        True
        """
        return _along.connection_action(self, parent, child, basis, system, label, at)

    def energy(self):
        """Total mechanical energy T + V along the motion."""
        return _along.energy(self)

    def energy_scale(self) -> float:
        """The scale of :meth:`energy_drift`, the natural magnitude of the energy along the
        run: the larger of ``T(0) + |V(0)|`` (the kinetic energy plus the magnitude of the
        potential energy at the start, ``V = E - T``) and ``max_t T`` over the samples (the
        largest kinetic energy the motion reaches: a body released at rest where V = 0
        turns its potential energy into T, which is then the energy at stake, m g L / 2 for
        a rod of length L released horizontal). When the equations do not know their kinetic
        energy (written by hand): ``|E(0)|``, or ``max_t |E|`` if that is 0.

        Examples
        --------
        >>> import sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...     forcing=sp.ImmutableMatrix([[-4 * x]]), energy=(x.diff(rm.t)**2 + 4 * x**2) / 2)
        >>> eqs.simulate(t=(0, 1), q0=[1.0], n_output=3).energy_scale()   # |E(0)| = 2
        2.0
        """
        return _along.energy_scale(self)

    def energy_drift(self, scale=None) -> float:
        """Largest change of the total energy along the motion, relative to ``scale``:
        ``max_t |E(t) - E(0)| / scale``.

        ``scale`` defaults to :meth:`energy_scale` (``max(T(0) + |V(0)|, max_t T)``): the
        drift then reads as a relative error of the energy at stake in the run, also for a
        motion released where T + V = 0. If the scale is 0 (nothing moves, V = 0), the drift
        is 0 if E stays 0, infinite otherwise. The energy is evaluated at the samples :attr:`t` (see
        :meth:`EquationsOfMotion.simulate` for their accuracy).

        Examples
        --------
        >>> import sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...     forcing=sp.ImmutableMatrix([[-x]]), energy=(x.diff(rm.t)**2 + x**2) / 2)
        >>> sim = eqs.simulate(t=(0, 1), q0=[0.0], u0=[0.0])        # at rest, E = 0
        >>> sim.energy_drift()
        0.0

        Raises
        ------
        ArgumentError
            If the energy is not conserved along an exact motion (see
            :meth:`energy_not_conserved`): the bodies' motion or a potential depends on time
            explicitly (a prescribed motion, a field that turns), or a damper of the system
            dissipates. Use :meth:`energy_balance`.
        """
        return _along.energy_drift(self, scale)

    def energy_not_conserved(self):
        """Why T + V is not conserved along an exact motion, or None: :meth:`time_dependence`,
        or the dissipative actions (those with a dissipation function, the dampers) of the
        system the equations were derived from. Equations given directly carry no actions:
        only their time dependence is decided.

        Examples
        --------
        >>> import sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...     forcing=sp.ImmutableMatrix([[-x]]), energy=(x.diff(rm.t)**2 + x**2) / 2)
        >>> eqs.simulate(t=(0, 1), q0=[1.0], n_output=3).energy_not_conserved() is None
        True
        """
        return _along.energy_not_conserved(self)

    def time_dependence(self):
        """Why T + V changes along a correct motion even without non-conservative actions,
        or None: the kinetic energy is not quadratic in the rates (a motion prescribed with
        time) or T + V depends on time explicitly (a gravity field that turns, an attracting
        body that moves). Decided on the equations' energy and kinetic energy.

        Examples
        --------
        >>> import sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...     forcing=sp.ImmutableMatrix([[-x + sp.cos(rm.t)]]),
        ...     energy=(x.diff(rm.t)**2 + x**2) / 2 - x * sp.cos(rm.t))
        >>> eqs.simulate(t=(0, 1), q0=[0.0], n_output=3).time_dependence()
        'the energy T + V depends on time explicitly (a prescribed motion or a field that varies)'
        """
        return _along.time_dependence(self)

    def energy_balance(self):
        """The energy balance along the motion, E(t) - E(0) - W(t), a time series that stays
        near 0 for a correct run (theorem of power and energy, ch. 18.3): E is the mechanical
        energy T + V of the actions with a potential and W(t) the work since t0 of the
        others (dampers, given forces and inputs, inertial actions without potential).
        When the bodies' motion or a potential depends on time explicitly, E is Painlevé's
        energy function sum q' dT/dq' - T + V and W includes the work of the explicit time
        dependence (:func:`rigidmech.dynamics.energy.energy_terms`).

        The power is evaluated at the samples :attr:`t` and integrated by Simpson's rule
        (trapezoids for fewer than 3 samples): the balance also carries that quadrature's
        error, small when the samples are fine relative to the motion (ask for more with
        ``n_output``).

        Raises
        ------
        ArgumentError
            Equations not derived by ``System.equations_of_motion()`` (the split of the
            actions is unknown), or a system changed since.

        Examples
        --------
        >>> import numpy as np, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> R0 = rm.Frame("R0"); P = R0.point("P", x, 0, 0)
        >>> s = rm.System(galilean=R0)
        >>> b = rm.Body("b", frame=R0.translated("R1", P), mass=1, centre=P); s.add(b)
        >>> s.act(rm.Spring(4, 0, a=R0.origin, b=P, on_b=b))
        >>> s.act(rm.actions.Damper(0.5, a=R0.origin, b=P, on_b=b))
        >>> sim = s.equations_of_motion().simulate(t=(0, 5), q0=[1.0], n_output=2001,
        ...                                         rtol=1e-10, atol=1e-12)
        >>> bool(np.max(np.abs(sim.energy_balance())) < 1e-8)
        True
        """
        return _along.energy_balance(self)

    # -- files --------------------------------------------------------------------------
    def save(self, path, *, units=None) -> str:
        """Write the samples to ``path``: ``.npz`` (arrays, names, parameters, status) or
        ``.csv`` (a header line of comments with the status and the parameters, then the
        columns ``t [s]``, each coordinate, each rate ``<name>_dot``, with their units where
        known; a parameter given as a callable is written as its repr). Returns the path.

        `units` (a dict by coordinate name, e.g. ``{"x": "m"}``) gives the unit of a
        coordinate; its rate's is that unit per second. Without it, a coordinate that is the
        angle of rotation of a body's frame (or of a frame it is built from) is in rad
        (rate rad/s), the others have no unit in the header: the library does not know the
        unit system of the model's constants.

        Examples
        --------
        >>> import os, tempfile, sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x"); k = sp.Symbol("k")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                            forcing=sp.ImmutableMatrix([[-k * x]]))
        >>> sim = eqs.simulate(t=(0, 1), q0=[1.0], n_output=5, k=4.0)
        >>> path = sim.save(os.path.join(tempfile.mkdtemp(), "run.csv"))
        >>> back = Simulation.load(path)
        >>> bool((back.q == sim.q).all()), back.names, back.parameters, back.status
        (True, ('x',), {'k': 4.0}, 'finished')
        """
        return _files.save(self, path, units)

    @classmethod
    def load(cls, path) -> Simulation:
        """Read a simulation written by :meth:`save`: the arrays, the names of the
        coordinates, the parameters, the status and its message, the method and the
        notes (and, from ``.npz``, the event times). What a file cannot hold is not restored:
        the equations of motion (so :meth:`evaluate`, :meth:`energy` and
        :meth:`connection_action` need a new simulation) and the solver's result
        (:attr:`result` is None).

        Examples
        --------
        >>> import os, tempfile, sympy as sp, rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                            forcing=sp.ImmutableMatrix([[-x]]))
        >>> path = eqs.simulate(t=(0, 1), q0=[1.0], n_output=4).save(
        ...     os.path.join(tempfile.mkdtemp(), "run.npz"))
        >>> back = Simulation.load(path)
        >>> back.t.tolist() == [0.0, 1 / 3, 2 / 3, 1.0], back.equations, back.method
        (True, None, 'dop853')
        """
        return _files.load(cls, path)

    # -- display ------------------------------------------------------------------------
    def plot(self, path=None, *, ax=None, coordinates=None, kind="time", degrees=False,
             units=None):
        """Plot the motion; save to ``path`` if given. Returns the Axes, a tuple (one per
        panel).

        Parameters
        ----------
        path : str or path-like, optional
            Write the figure there (drawn off-screen: no pyplot state, works headless).
            Without it (and without ``ax``) pyplot makes a figure to show.
        ax : Axes or sequence of Axes, optional
            Draw there, one Axes per panel.
        coordinates : str or sequence of str, optional
            The coordinates to draw (default: all), by name.
        kind : {"time", "phase", "energy"}
            ``"time"``: one panel per coordinate against t; ``"phase"``: one phase portrait
            (q', q) per coordinate, the start marked; ``"energy"``: the total energy
            E = T + V and its change relative to :meth:`energy_scale` against t.
        degrees : bool
            Draw the angles (unit rad) in degrees.
        units : dict, optional
            Units by coordinate name, decided as for :meth:`save`: given units first, else
            rad for an angle of rotation of a body's frame, else none shown.

        Each panel is labelled with the coordinate's name and unit (its rate's with ``/s``),
        the time axis ``t [s]``; new figures use matplotlib's constrained layout, so no label
        is cut (book, ch. 27: the numerical results of a motion).

        Examples
        --------
        >>> import matplotlib
        >>> matplotlib.use("Agg")
        >>> import rigidmech as rm
        >>> x, th = rm.coordinates("x theta")
        >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=th)
        >>> s = rm.System(galilean=R0)
        >>> s.add(rm.Body("b", frame=R1, mass=1,
        ...               inertia=rm.InertiaOperator.from_products(1, 1, 1, frame=R1)))
        >>> P = R0.point("P", x, 1, 0)
        >>> s.add(rm.Body("c", frame=R0.translated("R2", P), mass=1, centre=P))
        >>> sim = s.equations_of_motion().simulate(t=(0, 1), q0=[0.0, 0.5], u0=[1.0, 2.0])
        >>> axes = sim.plot(units={"x": "m"}, degrees=True)
        >>> [a.get_ylabel() for a in axes]
        ['$x$ [m]', '$\\\\theta$ [deg]']
        >>> sim.plot(kind="phase", coordinates="theta")[0].get_ylabel()
        "$\\\\theta'$ [rad/s]"
        >>> len(sim.plot(kind="energy"))
        2
        >>> import matplotlib.pyplot as plt; plt.close("all")
        """
        return _files.plot(self, path, ax, coordinates=coordinates, kind=kind,
                           degrees=degrees, units=units)

    def __repr__(self):
        span = f"[{self.t[0]}, {self.t[-1]}]" if self.t.size else "[]"
        nfev = f", nfev={self.result.nfev}" if self.result is not None else ""
        return (f"Simulation(status={self.status!r}, t={span}, points={self.t.size}{nfev}, "
                f"method={self._method!r})")


def load_simulation(path) -> Simulation:
    """Read a simulation saved by :meth:`Simulation.save` (same as :meth:`Simulation.load`).

    Examples
    --------
    >>> load_simulation("missing.txt")
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `path` must end in .npz or .csv; got 'missing.txt'.
    """
    return Simulation.load(path)
