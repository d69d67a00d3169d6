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
"""

from __future__ import annotations

import logging

import numpy as np
import sympy as sp

from .. import ode
from .._core.compile import compile_linear_solve
from .._core.errors import ArgumentError, ArgumentTypeError, CompilationError
from .._core.symbolic import atoms_shared, xreplace_shared
from ..vectors import t as _t
from ._singularities import warn_near_singularities
from .simulation import Simulation

__all__ = ["EquationsOfMotion", "Simulation"]

_log = logging.getLogger("rigidmech")


def _name(q):
    """The name of a coordinate: ``q`` for q(t) or for a plain symbol q."""
    return q.func.__name__ if isinstance(q, sp.core.function.AppliedUndef) else q.name


def _is_function_of_time(q):
    return isinstance(q, sp.core.function.AppliedUndef) and q.args == (_t,)



def _trouble(fun, exc, t, shape):
    """An error of the right-hand side during a simulation: kept (the first one) in
    ``fun.trouble`` with its time, and nan returned so that the solver stops there and keeps
    the motion computed so far (the error is named in the simulation's message)."""
    if not fun.trouble:
        fun.trouble.append((f"{type(exc).__name__}: {exc}", float(t)))
    return np.full(shape, np.nan)

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
        self._coordinates = tuple(coordinates)
        self._constraints = constraints
        n = len(self._coordinates)
        for c in self._coordinates:
            if not (_is_function_of_time(c) or isinstance(c, sp.Symbol)):
                raise ArgumentTypeError(
                    f"`coordinates` must be functions of time q(t) (rm.coordinates or "
                    f"dynamicsymbols) or plain symbols; got {c!r}.")
        self._M = sp.ImmutableMatrix(mass_matrix)
        self._f = sp.ImmutableMatrix(forcing)
        if self._M.shape != (n, n) or self._f.shape != (n, 1):
            raise ArgumentError(
                f"`mass_matrix` must be {n}x{n} and `forcing` {n}x1; got {self._M.shape} "
                f"and {self._f.shape}.")
        if q is not None and len(tuple(q)) != n or u is not None and len(tuple(u)) != n:
            raise ArgumentError(f"`q` and `u` must hold {n} symbols, one per coordinate.")
        rates, accs, back = [], [], {}
        for k, c in enumerate(self._coordinates):
            if isinstance(c, sp.Symbol):
                if u is None:
                    raise ArgumentError(
                        f"`u` must name the rates of the plain-symbol coordinates; got none "
                        f"for {c}.")
                rates.append(tuple(u)[k])
                accs.append(None)
            else:
                rates.append(sp.Derivative(c, _t))
                accs.append(sp.Derivative(c, (_t, 2)))
            if q is not None and tuple(q)[k] != c:
                back[tuple(q)[k]] = c
            if u is not None and tuple(u)[k] != rates[-1]:
                back[tuple(u)[k]] = rates[-1]
        self._q, self._u, self._a = self._coordinates, tuple(rates), tuple(accs)
        if back:  # expressions written with stand-in symbols: back to the user's q(t)
            memo = {}
            self._M = sp.ImmutableMatrix(n, n, xreplace_shared(list(self._M), back, memo))
            self._f = sp.ImmutableMatrix(n, 1, xreplace_shared(list(self._f), back, memo))
            if isinstance(energy, sp.Basic):
                energy = xreplace_shared([energy], back, memo)[0]
        self._energy = energy
        extra = [] if constraints is None else (
            list(constraints.jacobian) + list(constraints.stabilized_bias()))
        symbols, functions, derivatives = atoms_shared(list(self._M) + list(self._f) + extra)
        own = {x for x in self._q + self._u if isinstance(x, sp.Symbol)}
        if parameters is None:
            free = symbols - own - {_t}
        else:
            free = set(parameters)
        self._params = tuple(sorted(free, key=lambda s: s.name))
        coords = set(self._coordinates)
        self._inputs = tuple(sorted(functions - coords, key=str))
        self._model = model_parameters
        self._kinetic = kinetic_energy
        self._system = system
        self._cache = {"input_derivatives": tuple(sorted(
            (d for d in derivatives if d.expr not in coords), key=str))}
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
        if self._constraints is not None:
            c = self._constraints
            n, m = len(self._q), len(c)
            K = sp.BlockMatrix([[self._M, c.jacobian.T],
                                [c.jacobian, sp.zeros(m, m)]]).as_explicit()
            sol = K.LUsolve(sp.Matrix(list(self._f) + list(c.bias)))
            acc = sol[:n, :]
            return sp.ImmutableMatrix(sp.simplify(acc) if simplify else acc)
        acc = self._M.LUsolve(self._f)
        return sp.ImmutableMatrix(sp.simplify(acc) if simplify else acc)

    def count_ops(self) -> int:
        """Number of operations in M and f as compiled, q and q' being plain symbols
        (sympy.count_ops)."""
        _, _, _, _, M, f = self._symbolic()
        return int(sp.count_ops(list(M) + list(f)))

    # -- the compiled world -------------------------------------------------------------
    def _stand_ins(self):
        """Plain symbols for q, q', q'' and the inputs inside compiled code, and the rule that
        puts them in place of the user's q(t), Derivative(q(t), t), ... (Dummy symbols: no
        clash with a constant of the same name)."""
        if "stand_ins" not in self._cache:
            rule = {}
            q_s, u_s, a_s = [], [], []
            for q, u, a in zip(self._q, self._u, self._a, strict=True):
                name = _name(q)
                qs = q if isinstance(q, sp.Symbol) else sp.Dummy(name, real=True)
                us = u if isinstance(u, sp.Symbol) else sp.Dummy(name + "_dot", real=True)
                as_ = sp.Dummy(name + "_ddot", real=True)
                if a is not None:
                    rule[a] = as_
                rule[u], rule[q] = us, qs
                q_s.append(qs)
                u_s.append(us)
                a_s.append(as_)
            w_s = []
            for w in self._inputs:
                ws = sp.Dummy(_name(w), real=True)
                rule[w] = ws
                w_s.append(ws)
            self._cache["stand_ins"] = (tuple(q_s), tuple(u_s), tuple(a_s), tuple(w_s), rule)
        return self._cache["stand_ins"]

    def _symbolic(self):
        """M and f with the stand-in symbols (computed once, sharing subexpressions)."""
        if "symbolic" not in self._cache:
            q_s, u_s, a_s, w_s, rule = self._stand_ins()
            n = len(q_s)
            memo = {}
            M = xreplace_shared(list(self._M), rule, memo)
            f = xreplace_shared(list(self._f), rule, memo)
            self._cache["symbolic"] = (q_s, u_s, w_s, rule, sp.ImmutableMatrix(n, n, M),
                                       sp.ImmutableMatrix(n, 1, f))
        return self._cache["symbolic"]

    def _check_compilable(self):
        bad = self._cache["input_derivatives"]
        if bad:
            raise CompilationError(
                f"the equations contain {', '.join(map(str, bad))}: derivatives of inputs "
                "cannot be given as values; substitute an expression of t for the input "
                "first (eqs.forcing.subs(F(t), ...)) or make it a parameter of situation.")

    def _model_names(self):
        if "model" not in self._cache:
            model = self._model() if callable(self._model) else self._model
            self._cache["model"] = {s.name for s in (model or ())}
        return self._cache["model"]

    def _values(self, params):
        """(parameter values, input values, notes) from keyword values, checked."""
        names = {p.name for p in self._params}
        input_names = [_name(w) for w in self._inputs]
        missing = [p.name for p in self._params if p.name not in params]
        missing_inputs = [w for w in input_names if w not in params]
        if missing or missing_inputs:
            parts = []
            if missing:
                parts.append(f"parameters {missing}")
            if missing_inputs:
                parts.append(f"inputs {missing_inputs} (numbers or callables of t)")
            example = ", ".join(f"{m}=1.0" for m in missing + missing_inputs)
            raise ArgumentError(
                f"missing values for {' and '.join(parts)}; pass them as keywords, e.g. "
                f"{example}.")
        extra = sorted(set(params) - names - set(input_names))
        dropped = [x for x in extra if x in self._model_names()]
        unknown = [x for x in extra if x not in dropped]
        if unknown:
            raise ArgumentError(
                f"unknown parameters {unknown}; the equations depend on "
                f"{[p.name for p in self._params] + input_names}.")
        def number(name, kind):
            try:
                return float(params[name])
            except (TypeError, ValueError):
                raise ArgumentTypeError(
                    f"the value of {kind} `{name}` must be a real number"
                    f"{' or a callable of t' if kind == 'input' else ''}; got "
                    f"{params[name]!r}.") from None

        values = [number(p.name, "parameter") for p in self._params]
        inputs = [params[w] if callable(params[w]) else number(w, "input")
                  for w in input_names]
        notes = ()
        if dropped:
            notes = (f"parameters {', '.join(dropped)} do not enter the equations of motion "
                     "(they dropped out of the derivation): their values are ignored.",)
            for note in notes:
                _log.info(note)
        return values, inputs, notes

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

    def _augmented(self):
        """The augmented matrix [[M, A^T], [A, 0]] and right-hand side [f; b_stabilized],
        with the stand-in symbols."""
        q_s, u_s, w_s, rule, M, f = self._symbolic()
        c = self._constraints
        memo = {}
        m, n = len(c), len(q_s)
        A = sp.ImmutableMatrix(m, n, xreplace_shared(list(c.jacobian), rule, memo))
        b = xreplace_shared(list(c.stabilized_bias()), rule, memo)
        K = sp.BlockMatrix([[M, A.T], [A, sp.zeros(m, m)]]).as_explicit()
        F = sp.ImmutableMatrix(n + m, 1, list(f) + b)
        return sp.ImmutableMatrix(K), F

    def _constrained_solver(self):
        q_s, u_s, w_s, _, _, _ = self._symbolic()
        K, F = self._augmented()
        full = compile_linear_solve(
            K, F, [_t, list(q_s), list(u_s), *self._params, *w_s], symmetric=False,
            name="accelerations_and_multipliers")
        n = len(q_s)

        def solve(*args):
            return full(*args)[:n]

        solve.full = full
        return solve

    def _solver(self):
        if "solver" not in self._cache and self._constraints is not None:
            self._check_compilable()
            self._cache["solver"] = self._constrained_solver()
        if "solver" not in self._cache:
            self._check_compilable()
            q_s, u_s, w_s, _, M, f = self._symbolic()
            self._cache["solver"] = compile_linear_solve(
                M, f, [_t, list(q_s), list(u_s), *self._params, *w_s],
                symmetric=True, name="accelerations")
        return self._cache["solver"]

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
        self._check_compilable()
        values, inputs, notes = self._values(params)
        solve = self._solver()
        n = len(self._q)
        if not any(callable(w) for w in inputs):
            values = values + inputs

            def fun(t, y):
                try:  # free unless raised
                    acc = solve(t, y[:n], y[n:], *values)
                except (ArithmeticError, ValueError, TypeError) as exc:
                    if fun.trouble is None:
                        raise
                    return _trouble(fun, exc, t, np.shape(y))
                return np.concatenate((y[n:], acc), axis=0)
        else:
            def fun(t, y):
                try:
                    w = [v(t) if callable(v) else v for v in inputs]
                    acc = solve(t, y[:n], y[n:], *values, *w)
                except (ArithmeticError, ValueError, TypeError) as exc:
                    if fun.trouble is None:
                        raise
                    return _trouble(fun, exc, t, np.shape(y))
                return np.concatenate((y[n:], acc), axis=0)

        fun.notes = notes
        fun.trouble = None  # a list: errors kept there, nan returned (see _trouble)
        return fun

    def _acceleration_only(self, method, params):
        """q'' = a(t, q) for the geometric (second-order) methods, which need accelerations
        independent of the velocities (separable systems)."""
        q_s, u_s, _, _, _, f = self._symbolic()
        if any(f.has(u) for u in u_s):
            raise ArgumentError(
                f"method {method!r} integrates q'' = a(t, q) only, but these equations "
                "depend on q' (velocity products); use an explicit method such as 'dop853'.")
        values, inputs, notes = self._values(params)
        solve = self._solver()
        zeros = np.zeros(len(self._u))

        def acc(t, q):
            try:
                w = [v(t) if callable(v) else v for v in inputs]
                return solve(t, q, np.zeros_like(q) if np.ndim(q) > 1 else zeros, *values, *w)
            except (ArithmeticError, ValueError, TypeError) as exc:
                if acc.trouble is None:
                    raise
                return _trouble(acc, exc, t, np.shape(q))

        acc.notes = notes
        acc.trouble = None
        return acc

    def _initial(self, values, what, default_zero):
        """Initial coordinates or rates from a sequence (in the order of :attr:`coordinates`)
        or a mapping by name (missing names: 0)."""
        n = len(self._q)
        names = self.names
        if values is None:
            if default_zero:
                return np.zeros(n)
            raise ArgumentError(
                f"`{what}` must give {n} initial values (a sequence in the order "
                f"{', '.join(names)}, or a dict by name); got None.")
        if isinstance(values, dict):
            out = np.zeros(n)
            unknown = []
            for key, value in values.items():
                if isinstance(key, str) and key in names:
                    k = names.index(key)
                elif key in self._coordinates:
                    k = self._coordinates.index(key)
                else:
                    unknown.append(key)
                    continue
                out[k] = float(value)
            if unknown:
                raise ArgumentError(
                    f"`{what}` names {', '.join(repr(str(x)) for x in unknown)}, which "
                    f"{'are' if len(unknown) > 1 else 'is'} not a coordinate; the coordinates "
                    f"are {', '.join(names)}.")
            return out
        try:
            out = np.asarray(values, dtype=float)
        except (TypeError, ValueError):
            raise ArgumentError(
                f"`{what}` must be {n} numbers or a dict by name; got {values!r}.") from None
        if out.shape != (n,):
            raise ArgumentError(
                f"`{what}` must give {n} initial values (in the order {', '.join(names)}, or "
                f"a dict by name); got {values!r}.")
        return out

    def simulate(self, t=(0.0, 10.0), q0=None, u0=None, *, method="dop853", rtol=1e-8,
                 atol=1e-10, step=None, n_output=1001, t_eval=None, events=None,
                 max_steps=1_000_000, first_step=None, max_step=None, dense_output=None,
                 progress=None, project=None, raise_on_failure=False, params=None,
                 **values) -> Simulation:
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
            to zeros. An unknown name is refused.
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
            of t, q(t), q'(t), the constants and the inputs, compiled once (an
            :class:`Event` gives them ``terminal`` and ``direction``). Their zeros are in
            :attr:`Simulation.t_events`; a terminal one ends the run with status ``"event"``.
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

        On Ctrl-C (KeyboardInterrupt) the methods built on the solver's one loop (``dop853``,
        ``dopri5``, ``bs32``, ``gbs``, ``radau``, ``rkn64``, ``rkn1210``) keep the samples
        computed so far, status ``"interrupted"``, and so do the one-step fixed-step methods
        (up to the last chunk done); the others (``adams``, multistep methods, a fixed-step
        run with events, ``t_eval`` or dense output) keep only the initial state (the
        message says so).

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
        from ._run import merge_values, run

        values = merge_values(params, values)
        inputs = {_name(w) for w in self._inputs}
        _check_simulation_inputs(len(self._q), t, q0, u0, method, n_output,
                                 {k: v for k, v in values.items() if k not in inputs})
        q0 = self._initial(q0, "q0", default_zero=False)
        u0 = self._initial(u0, "u0", default_zero=True)
        y0 = np.concatenate((q0, u0))
        if not isinstance(method, str):
            raise ArgumentTypeError(f"`method` must be a method name; got {method!r}.")
        if method.lower() in ode.methods("second_order") + ode.methods("adaptive_second_order"):
            fun = self._acceleration_only(method, values)
        else:
            fun = self.rhs(**values)
        if dense_output is None:
            dense_output = bool(self.singular_sets)
        sim = run(self, fun, t, y0, method=method, rtol=rtol, atol=atol, step=step,
                  n_output=n_output, t_eval=t_eval, events=events, max_steps=max_steps,
                  first_step=first_step, max_step=max_step, dense_output=dense_output,
                  progress=progress, values=values, notes=fun.notes, project=project)
        if sim.result is not None and sim.t.size:
            warn_near_singularities(self.singular_sets, self._coordinates, sim.result, values)
        return sim.check() if raise_on_failure else sim

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
        rule = {}
        for q, u, a in zip(self._q, self._u, self._a, strict=True):
            name = _name(q)
            if a is not None:
                rule[a] = sp.Symbol(name + "_ddot", real=True)
            rule[u] = sp.Symbol(name + "_dot", real=True) if not isinstance(u, sp.Symbol) else u
            rule[q] = sp.Symbol(name, real=True) if not isinstance(q, sp.Symbol) else q
        return rule

    def _latex(self, printer=None):
        rule = {}
        for q, u, a in zip(self._q, self._u, self._a, strict=True):
            name = sp.latex(sp.Symbol(_name(q)))
            if a is not None:
                rule[a] = sp.Symbol(rf"\ddot{{{name}}}")
            rule[u] = sp.Symbol(rf"\dot{{{name}}}")
            rule[q] = sp.Symbol(name)
        acc = sp.Matrix([sp.Symbol(rf"\ddot{{{sp.latex(sp.Symbol(_name(q)))}}}")
                         for q in self._q])
        return (sp.latex(sp.Matrix(self._M).xreplace(rule)) + sp.latex(acc) + " = "
                + sp.latex(sp.Matrix(self._f).xreplace(rule)))

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


def _finite_reals(values, argument, n=None):
    """Raise unless ``values`` is a sequence (of length ``n``) of finite real numbers."""
    if isinstance(values, str | bytes) or not hasattr(values, "__len__"):
        raise ArgumentTypeError(
            f"`{argument}` must be a sequence of {n or 'several'} numbers; got "
            f"{type(values).__name__} {values!r}.")
    if n is not None and len(values) != n:
        raise ArgumentError(f"`{argument}` must give {n} initial values; got {values!r}.")
    for v in values:
        _finite_real_number(v, f"`{argument}` must hold finite real numbers")


def _finite_real_number(v, rule):
    if isinstance(v, bool) or not isinstance(v, int | float | np.integer | np.floating
                                             | sp.Number):
        raise ArgumentTypeError(f"{rule}; got {type(v).__name__} {v!r}.")
    if not np.isfinite(float(v)):
        raise ArgumentError(f"{rule}; got {v!r}.")


def _check_simulation_inputs(n, t, q0, u0, method, n_output, params):
    """The checks of :meth:`EquationsOfMotion.simulate` on the values it is given (numbers
    finite and real, a time span of two numbers, a method name, a count of outputs), so that a
    wrong value is an error here rather than a nan motion or an error from numpy."""
    _finite_reals(t, "t", 2)
    if q0 is not None and not isinstance(q0, dict):
        _finite_reals(q0, "q0")
    if u0 is not None and not isinstance(u0, dict):
        _finite_reals(u0, "u0")
    if not isinstance(method, str):
        raise ArgumentTypeError(
            f"`method` must be the name of a method of rigidmech.ode.solve (such as "
            f"'dop853'); got {type(method).__name__} {method!r}.")
    if isinstance(n_output, bool) or not isinstance(n_output, int | np.integer) \
            or n_output < 2:
        raise ArgumentError(
            f"`n_output` must be an integer >= 2 (the output times include both ends of "
            f"`t`); got {n_output!r}.")
    for name, value in params.items():
        _finite_real_number(value, f"`{name}` must be a finite real number")
