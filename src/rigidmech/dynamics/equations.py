"""Equations of motion M(q) q'' = f(q, q', t) and their numerical integration (book, ch. 20,
27).

:class:`EquationsOfMotion` is an immutable value: the parameters of situation, the mass matrix
and the forcing, written with the user's own q(t), q'(t) = ``Derivative(q(t), t)`` and t (one
symbol world: ``subs``, evaluation and compilation accept them). Numbers come from compiling
them once (common subexpressions shared, :mod:`rigidmech._core.compile`) into a first-order
right-hand side y' = (q', M^-1 f) that the solvers of :mod:`rigidmech.ode` integrate; plain
symbols stand for q and q' only inside the compiled code.

Functions of time that are not parameters of situation, such as a force ``F(t)`` or a control
torque ``u(t)``, are the *inputs* of the equations: their values are given with the
parameters' (a number, or a Python callable of t).

Developers: this module holds the value type; the compiled world is in
:mod:`rigidmech.dynamics._compiled`, the symbolic forms (arguments read, symbolic
accelerations, printing) in :mod:`rigidmech.dynamics._forms`, the entry of ``simulate`` in
:mod:`rigidmech.dynamics._simulate` (see "Where each concern lives" in the API docs).
"""

from __future__ import annotations

import numpy as np  # noqa: F401 (the doctest of simulate uses np)
import sympy as sp

from . import _compiled, _forms, _simulate
from ._compiled import coordinate_name as _name
from .simulation import Simulation

__all__ = ["EquationsOfMotion", "Simulation"]


class EquationsOfMotion:
    """M(q) q'' = f(q, q', t), free of connection unknowns (ch. 20.2, 27.2.1).

    Parameters
    ----------
    coordinates : tuple of q(t)
        The parameters of situation: functions of :data:`rigidmech.t` (``rm.coordinates`` or
        ``sympy.physics.mechanics.dynamicsymbols``), or plain symbols for equations written
        by hand (then ``u`` names their rates).
    mass_matrix : sympy.ImmutableMatrix, shape (n, n)
    forcing : sympy.ImmutableMatrix, shape (n, 1)
        Written with the coordinates, their rates ``Derivative(q(t), t)``, t, constant
        symbols (the parameters) and functions of t that are not coordinates (the inputs).
    energy : sympy expression, callable returning one, or None, optional
        Total mechanical energy (for the energy drift of a simulation). A callable is called
        once, on first use: it must be a snapshot, independent of later changes elsewhere.
    parameters : iterable of sympy.Symbol, optional
        The constant symbols of the equations, when the caller knows them already; found in
        ``mass_matrix`` and ``forcing`` otherwise.
    q, u : tuple of sympy.Symbol, optional
        Symbols that stand for the coordinates and their rates in ``mass_matrix``,
        ``forcing`` and ``energy``: with coordinates q(t) the expressions are rewritten with
        q(t) and q'(t); with plain-symbol coordinates ``u`` gives the rates.
    model_parameters : iterable of sympy.Symbol or callable returning one, optional
        Every constant of the model the equations come from. A value given for one of them
        that is not in :attr:`parameters` (it dropped out of the equations) is accepted and
        ignored with a note; any other unknown name is refused.
    singular_sets : sequence of OrientationSingularity, or callable returning one, optional
        Singular sets of the orientation angles among the coordinates (ch. 9.1.2), derived
        on demand; :meth:`simulate` warns when the motion comes near one.
    kinetic_energy : sympy expression, callable returning one, or None, optional
        Kinetic energy T (with q(t), q'(t)): the scale of a simulation's energy drift.
    system : System, optional
        The system the equations were derived from (for the connection actions along a
        simulated motion, :meth:`Simulation.connection_action`).
    constraints : rigidmech.dynamics.Constraints, optional
        Constraints A q'' = b between the coordinates (closed loops, rolling, gears): the
        equations are then M q'' = f + A^T lambda (see :mod:`rigidmech.dynamics.constraints`)
        and the compiled right-hand side solves the augmented system, with Baumgarte's
        stabilisation of the drift.

    Notes
    -----
    Values are substituted with sympy, in the user's symbols: ``eqs.forcing.subs(q, 0.3)``.
    To give q and q' together, pass a dict (sympy substitutes the derivatives first):
    ``eqs.forcing.subs({q.diff(t): 1.0, q: 0.3})``.

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> x = rm.coordinates("x"); k = sp.Symbol("k")
    >>> eqs = EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
    ...                         forcing=sp.ImmutableMatrix([[-k * x]]))
    >>> eqs.parameters
    (k,)
    >>> eqs.accelerations()
    Matrix([[-k*x(t)]])
    >>> eqs.accelerations().subs(x, 2)
    Matrix([[-2*k]])
    """

    __slots__ = ("_coordinates", "_q", "_u", "_a", "_M", "_f", "_energy", "_params",
                 "_inputs", "_model", "_cache", "_singular", "_kinetic", "_system",
                 "_constraints")

    def __init__(self, *, coordinates, mass_matrix, forcing, energy=None, parameters=None,
                 q=None, u=None, model_parameters=None, singular_sets=None,
                 kinetic_energy=None, system=None, constraints=None):
        (self._coordinates, self._M, self._f, self._u, self._a, self._energy, self._params,
         self._inputs, input_derivatives) = _forms.read(
            coordinates, mass_matrix, forcing, energy, parameters, q, u, constraints)
        self._q = self._coordinates
        self._constraints = constraints
        self._model = model_parameters
        self._kinetic = kinetic_energy
        self._system = system
        self._cache = {"input_derivatives": input_derivatives}
        self._singular = singular_sets

    @property
    def coordinates(self):
        """The parameters of situation q(t)."""
        return self._coordinates

    @property
    def names(self) -> tuple:
        """The names of the coordinates (``"q"`` for q(t)): the keys of ``q0`` and ``u0`` in
        :meth:`simulate`.

        Examples
        --------
        >>> import sympy as sp
        >>> import rigidmech as rm
        >>> x, y = rm.coordinates("x y")
        >>> eqs = EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
        ...                         forcing=sp.Matrix([-x, -y]))
        >>> eqs.names
        ('x', 'y')
        >>> sim = eqs.simulate(t=(0, 1), q0={"y": 1.0}, n_output=3)
        >>> sim.q[:, 0].tolist()
        [0.0, 1.0]
        """
        return tuple(_name(q) for q in self._coordinates)

    @property
    def q(self):
        """What stands for the parameters of situation in the expressions: q(t)."""
        return self._q

    @property
    def u(self):
        """What stands for their rates in the expressions: ``Derivative(q(t), t)``."""
        return self._u

    @property
    def mass_matrix(self) -> sp.ImmutableMatrix:
        """M(q), symmetric."""
        return self._M

    @property
    def forcing(self) -> sp.ImmutableMatrix:
        """f(q, q', t)."""
        return self._f

    @property
    def parameters(self) -> tuple:
        """Constant symbols (masses, lengths, ...) the equations depend on, sorted by name."""
        return self._params

    @property
    def inputs(self) -> tuple:
        """Functions of time in the equations that are not parameters of situation (a force
        F(t), a control torque u(t)), sorted by name; give their values like parameters'.

        Examples
        --------
        >>> import sympy as sp
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x"); F = sp.Function("F")(rm.t)
        >>> eqs = EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[2]]),
        ...                         forcing=sp.ImmutableMatrix([[F]]))
        >>> eqs.inputs
        (F(t),)
        >>> eqs.rhs(F=lambda t: 4 * t)(0.5, [0.0, 0.0])
        array([0., 1.])
        """
        return self._inputs

    @property
    def energy(self):
        """Total mechanical energy T + V (with q(t), q'(t)), or None if an action has no
        potential energy. Taken from the system when the equations were derived."""
        if "energy" not in self._cache:
            e = self._energy() if callable(self._energy) else self._energy
            self._cache["energy"] = e
        return self._cache["energy"]

    @property
    def singular_sets(self) -> tuple:
        """Singular sets of the orientation angles (ch. 9.1.2), as
        :class:`~rigidmech.vectors.OrientationSingularity`; empty if none is known.

        Examples
        --------
        >>> import rigidmech as rm
        >>> psi, theta, phi = rm.coordinates("psi theta phi")
        >>> R0 = rm.Frame("R0"); R = R0.euler("R", psi, theta, phi)
        >>> system = rm.System(galilean=R0)
        >>> system.add(rm.Body("b", frame=R, mass=1,
        ...     inertia=rm.InertiaOperator.from_products(1, 2, 3, frame=R)))
        >>> system.equations_of_motion().singular_sets[0].condition
        Eq(sin(theta(t)), 0)
        """
        if "singular_sets" not in self._cache:
            s = self._singular() if callable(self._singular) else self._singular
            self._cache["singular_sets"] = tuple(s or ())
        return self._cache["singular_sets"]

    @property
    def kinetic_energy(self):
        """Kinetic energy T (with q(t), q'(t)), or None if not known (equations written by
        hand). Taken from the system when the equations were derived.

        Examples
        --------
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x"); m = rm.constants("m", positive=True)
        >>> R0 = rm.Frame("R0"); P = R0.point("P", x, 0, 0)
        >>> s = rm.System(galilean=R0)
        >>> s.add(rm.Body("b", frame=R0.translated("R1", P), mass=m, centre=P))
        >>> eqs = s.equations_of_motion()
        >>> eqs.kinetic_energy, eqs.system is s
        (m*Derivative(x(t), t)**2/2, True)
        """
        if "kinetic" not in self._cache:
            e = self._kinetic() if callable(self._kinetic) else self._kinetic
            self._cache["kinetic"] = e
        return self._cache["kinetic"]

    @property
    def system(self):
        """The system the equations were derived from, or None."""
        return self._system

    def accelerations(self, simplify: bool = False) -> sp.ImmutableMatrix:
        """q'' = M^-1 f symbolically (small systems: the expressions grow fast); with
        constraints, the first n unknowns of the augmented system."""
        return _forms.accelerations(self, simplify)

    def count_ops(self) -> int:
        """Number of operations in M and f as compiled, q and q' being plain symbols
        (sympy.count_ops)."""
        _, _, _, _, M, f = self._symbolic()
        return int(sp.count_ops(list(M) + list(f)))

    # -- the compiled world -------------------------------------------------------------
    def _stand_ins(self):
        """Plain symbols for q, q', q'' and the inputs inside compiled code, and the rule that
        puts them in place of the user's q(t), Derivative(q(t), t), ... (cached)."""
        return _compiled.stand_ins(self)

    def _symbolic(self):
        """M and f with the stand-in symbols (computed once, sharing subexpressions)."""
        return _compiled.symbolic(self)

    def _values(self, params):
        """(parameter values, input values, notes) from keyword values, checked."""
        return _compiled.given_values(self, params)

    def _solver(self):
        """The compiled q''(t, q, q', parameters, inputs) (with constraints, its ``full``
        gives the multipliers as well)."""
        return _compiled.solver(self)

    @property
    def constraints(self):
        """The constraints between the coordinates (:class:`Constraints`), or None."""
        return self._constraints

    def reduced(self, independent=None):
        """The equations reduced to the independent speeds, M_r u' = f_r, constraint actions
        and dependent rates eliminated (:func:`rigidmech.dynamics.reduced.reduce_equations`,
        ch. 25.3): ``independent`` names the n - m coordinates whose rates are free."""
        from .reduced import reduce_equations

        key = ("reduced", None if independent is None else tuple(map(str, independent)))
        if key not in self._cache:
            self._cache[key] = reduce_equations(self, independent)
        return self._cache[key]

    def rhs(self, **params):
        """The first-order right-hand side ``f(t, y)`` with y = (q, q'), compiled once.

        Works on a single state (shape (2n,)) or a batch (shape (2n, batch)); returns a
        fresh array each call. ``params`` give the values of :attr:`parameters` and of the
        :attr:`inputs` (a number, or a callable of t). A value for a constant of the model
        that dropped out of the equations is ignored, with a note kept in the attribute
        ``notes`` of the returned function (and logged by the ``"rigidmech"`` logger).

        Examples
        --------
        >>> import sympy as sp, numpy as np
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x"); k = sp.Symbol("k")
        >>> eqs = EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                         forcing=sp.ImmutableMatrix([[-k * x]]))
        >>> eqs.rhs(k=4.0)(0.0, np.array([1.0, 0.0]))
        array([ 0., -4.])
        """
        return _compiled.rhs(self, params)

    def simulate(self, t=(0.0, 10.0), q0=None, u0=None, *, method="dop853", rtol=1e-8,
                 atol=1e-10, step=None, n_output=1001, t_eval=None, events=None,
                 max_steps=1_000_000, first_step=None, max_step=None, dense_output=None,
                 progress=None, project=None, raise_on_failure=False, params=None,
                 independent=None, **values) -> Simulation:
        """Integrate the equations from (q0, u0) over ``t`` (ch. 27.2.2).

        The run never loses work: it returns a :class:`Simulation` however it ends (its
        :attr:`~Simulation.status`: ``"finished"``, ``"event"``, ``"failed"`` with the reason
        and the time in :attr:`~Simulation.message`, ``"interrupted"`` by Ctrl-C or by the
        ``progress`` callback), holding every sample computed until then. It raises only on
        misuse, or on failure if ``raise_on_failure`` (see :meth:`Simulation.check`).

        Parameters
        ----------
        t : (t0, t1)
        q0, u0 : sequence of n floats, or dict by coordinate name
            Initial coordinates and rates: a sequence in the order of :attr:`coordinates`,
            or a dict ``{"x": 1.0, "psi": 0.2}`` keyed by :attr:`names` (or by the
            coordinates q(t)) in which a coordinate not named starts at 0. ``u0`` defaults
            to zeros. An unknown name is refused. With :attr:`constraints`, a state off them
            (a closure condition or a velocity condition beyond 1e-9) is assembled on them
            before the run, the ``independent`` coordinates and their rates kept, and a note
            says what moved (the values given stay in :attr:`Simulation.q0_given`); a loop
            that cannot be closed is refused (see "Constraints: the initial state, the
            projection, Baumgarte" in the API docs).
        method : str
            A method of :func:`rigidmech.ode.solve` ("dop853", "dopri5", "rk4", ...).
        rtol, atol : float
            Tolerances of the adaptive methods.
        step : float
            Step of the fixed-step methods (required by those); a step larger than the time
            span is refused.
        n_output : int
            Number of evenly spaced sample times (ignored if ``t_eval`` is given).
        t_eval : array_like, optional
            The sample times, instead of ``n_output`` evenly spaced ones.
        events : callable, sympy expression, :class:`Event`, or a list of those, optional
            Functions ``g(t, y)`` of the state y = (q, q') (with scipy's attributes
            ``terminal`` and ``direction``, see :func:`rigidmech.ode.event`), or expressions
            of t, q(t), q'(t), q''(t) (solved from the equations at the state), the
            constants and the inputs, compiled once (an :class:`Event` gives them
            ``terminal`` and ``direction``). Their zeros are in :attr:`Simulation.t_events`,
            the states there in :meth:`Simulation.at_events`; a terminal one ends the run
            with status ``"event"``.
        max_steps : int
            Largest number of steps (default 10^6); beyond it the run stops with status
            ``"failed"`` and the samples so far.
        first_step, max_step : float, optional
            First and largest step of the adaptive methods.
        dense_output : bool or None
            Keep the solver's continuous solution (``sim.result.sol``); memory then grows
            with the number of steps. ``None`` (default): only for equations whose
            orientation angles have a singular set (:attr:`singular_sets`), so that a close
            pass between two samples is found; ``False`` then checks the samples only.
        progress : None, bool or callable
            ``None`` (default): a progress bar on stderr for runs longer than 2 s, only when
            stderr is a terminal; ``True``: the bar even when it is not; ``False``: none; a
            callable ``progress(t)``: called about every 0.1 s with the time reached,
            returning False stops the run (status ``"interrupted"``).
        project : bool or None
            For equations with :attr:`constraints` (closed loops, rolling): after every step,
            project the positions onto the closure conditions Φ(q, t) = 0 (Gauss-Newton
            steps with the constraint Jacobian, compiled once) and the rates onto
            A(q, t) q' + a = 0, so that the drift of the constraints does not grow (see
            :func:`rigidmech.ode.solve`'s ``project``); the samples, taken between two
            steps from the unprojected step's dense output, are projected the same way.
            ``None``
            (default): on for constrained equations with a method of the solver's loop
            (``dop853``, ``dopri5``, ``bs32``, ``gbs``, ``radau``); ``False``: off (Baumgarte's
            stabilisation alone).
        independent : sequence of coordinates or names, optional
            With :attr:`constraints`: the coordinates kept when ``q0`` is off the
            constraints (the others are moved onto them). Default: the coordinates a dict
            ``q0`` names, else the first ones (the dependent ones are taken from the last
            backwards). Refused for equations without constraints.
        raise_on_failure : bool
            Raise :class:`~rigidmech._core.errors.NumericalError` on failure (the partial simulation
            attached as its ``simulation`` attribute) instead of returning it.
        params : dict, optional
            Values of :attr:`parameters` and :attr:`inputs` by name. Needed for a constant
            whose name is also an argument of ``simulate`` (``params={"step": 0.2}``); the
            others may also be given as keywords.
        **values
            Values of :attr:`parameters` and :attr:`inputs` (numbers, or callables of t for
            the inputs). Values for constants of the model that dropped out of the equations
            are ignored with a note (:attr:`Simulation.notes`).

        Returns
        -------
        Simulation

        Notes
        -----
        Where the samples come from: ``dop853``, ``dopri5`` and ``bs32`` evaluate their dense
        output at the sample times while they integrate, so memory follows the number of
        samples (and events), not the number of steps; its order is the method's own for
        ``bs32`` (3), one less for ``dopri5`` (4) and ``dop853`` (7 for an order-8 method):
        ``dop853``'s samples are 1.4-1.7 times less accurate than its steps (measured on
        x'' = -x over [0, 20], 2001 samples, rtol 1e-6 to 1e-10, by
        ``benchmarks/dense_vs_steps.py``), ``dopri5``'s and ``bs32``'s as accurate.
        ``gbs``, ``rkn64`` and ``rkn1210`` land their steps on the sample times: the samples
        are as accurate as the steps, memory follows the samples. ``radau`` and ``adams``
        keep their whole dense output and evaluate it at the end (memory grows with the
        steps; ``radau``'s interpolant is cubic, less accurate than its steps). Fixed-step
        methods sample their own grid points (about ``n_output`` of them, evenly spaced by a
        whole number of steps; with ``t_eval``, a cubic Hermite interpolant of the grid); the
        one-step ones (``rk4``, ``verlet``, ...) run chunk by chunk (10^4 steps each, same
        numbers), so memory follows the samples, the multistep ones (``ab4``, ...) keep every
        ``stride``-th point as they go.

        On Ctrl-C (KeyboardInterrupt), a ``progress`` callback that stops the run,
        ``max_steps`` or a failure of the right-hand side (an error, a non-finite or complex
        value), the samples computed so far are kept and the state the run reached (its last
        accepted step, :attr:`Simulation.t_stop`) is appended as the last sample, also with
        ``t_eval``; the one-step fixed-step methods keep the chunks done and the steps of the
        interrupted one. After a plain step size underflow (a singularity, which the last
        accepted step may have jumped) only the samples are kept; the message gives the state.
        (A method registered by a plug-in that lets Ctrl-C escape keeps only the initial
        state; the message says so.)

        Examples
        --------
        >>> import sympy as sp
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x"); step = sp.Symbol("step")   # a constant named `step`
        >>> eqs = EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                         forcing=sp.ImmutableMatrix([[-step * x]]))
        >>> sim = eqs.simulate(t=(0, 1), q0=[1.0], method="rk4", step=0.01,
        ...                    params={"step": 4.0})
        >>> sim.status, round(float(sim.q[0, -1]), 6), round(float(np.cos(2.0)), 6)
        ('finished', -0.416147, -0.416147)
        """
        return _simulate.simulate(
            self, t, q0, u0, method=method, rtol=rtol, atol=atol, step=step,
            n_output=n_output, t_eval=t_eval, events=events, max_steps=max_steps,
            first_step=first_step, max_step=max_step, dense_output=dense_output,
            progress=progress, project=project, raise_on_failure=raise_on_failure,
            params=params, values=values, independent=independent)

    def display_rule(self) -> dict:
        """Symbols to print q(t), q'(t), q''(t) as q, q_dot, q_ddot (for reading only: they
        are not the symbols of any computation).

        Examples
        --------
        >>> import sympy as sp
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x"); k = sp.Symbol("k")
        >>> eqs = EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                         forcing=sp.ImmutableMatrix([[-k * x * x.diff(rm.t)]]))
        >>> eqs.forcing.xreplace(eqs.display_rule())
        Matrix([[-k*x*x_dot]])
        """
        return _forms.display_rule(self)

    def _latex(self, printer=None):
        return _forms.latex(self)

    def _repr_latex_(self):
        """M(q) q'' = f(q, q', t) rendered in Jupyter and in the docs, q(t) and its rates
        printed q, q dot, q double dot.

        Examples
        --------
        >>> import sympy as sp
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x"); k = sp.Symbol("k")
        >>> eqs = EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
        ...                         forcing=sp.ImmutableMatrix([[-k * x]]))
        >>> eqs._repr_latex_().startswith(r"$\\displaystyle \\left[\\begin{matrix}1")
        True
        >>> r"\\ddot{x}" in eqs._repr_latex_()
        True
        """
        return f"$\\displaystyle {self._latex()}$"

    def __repr__(self):
        inputs = f", inputs={list(self._inputs)}" if self._inputs else ""
        return (f"EquationsOfMotion(coordinates={list(self._coordinates)}, "
                f"n={len(self._q)}, parameters={list(self._params)}{inputs})")
