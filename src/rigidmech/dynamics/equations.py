"""Equations of motion M(q) q'' = f(q, q', t) and their numerical integration (book, ch. 20,
27).

:class:`EquationsOfMotion` is an immutable value: the parameters of situation, the symbols
standing for q and q', the mass matrix and the forcing. Numbers come from compiling them once
(common subexpressions shared, :mod:`rigidmech._core.compile`) into a first-order right-hand
side y' = (q', M^-1 f) that the solvers of :mod:`rigidmech.ode` integrate.
"""

from __future__ import annotations

import time as _time

import numpy as np
import sympy as sp

from .. import ode
from .._core.compile import compile_expressions, compile_linear_solve
from .._core.errors import ArgumentError, NumericalError
from .._core.symbolic import free_symbols_shared
from ..vectors import t as _t
from ._singularities import warn_near_singularities

__all__ = ["EquationsOfMotion", "Simulation"]


class EquationsOfMotion:
    """M(q) q'' = f(q, q', t), free of connection unknowns (ch. 20.2, 27.2.1).

    Parameters
    ----------
    coordinates : tuple of q(t)
        The parameters of situation.
    q, u : tuple of sympy.Symbol
        Symbols standing for q and q' in ``mass_matrix`` and ``forcing``.
    mass_matrix : sympy.ImmutableMatrix, shape (n, n)
    forcing : sympy.ImmutableMatrix, shape (n, 1)
    energy : callable returning a sympy expression or None, optional
        Total mechanical energy, derived on demand (for the energy drift of a simulation).
    parameters : iterable of sympy.Symbol, optional
        The constant symbols of the equations, when the caller knows them already; found in
        ``mass_matrix`` and ``forcing`` otherwise.
    singular_sets : sequence of OrientationSingularity, or callable returning one, optional
        Singular sets of the orientation angles among the coordinates (ch. 9.1.2), derived
        on demand; :meth:`simulate` warns when the motion comes near one.

    Examples
    --------
    >>> import sympy as sp
    >>> x, v, k = sp.symbols("x x_dot k")
    >>> eqs = EquationsOfMotion(coordinates=(sp.Function("x")(sp.Symbol("t")),), q=(x,),
    ...                         u=(v,), mass_matrix=sp.ImmutableMatrix([[1]]),
    ...                         forcing=sp.ImmutableMatrix([[-k * x]]))
    >>> eqs.parameters
    (k,)
    >>> eqs.accelerations()
    Matrix([[-k*x]])
    """

    __slots__ = ("_coordinates", "_q", "_u", "_M", "_f", "_energy", "_params", "_cache",
                 "_singular")

    def __init__(self, *, coordinates, q, u, mass_matrix, forcing, energy=None,
                 parameters=None, singular_sets=None):
        self._coordinates = tuple(coordinates)
        self._q, self._u = tuple(q), tuple(u)
        self._M = sp.ImmutableMatrix(mass_matrix)
        self._f = sp.ImmutableMatrix(forcing)
        n = len(self._q)
        if self._M.shape != (n, n) or self._f.shape != (n, 1):
            raise ArgumentError(
                f"`mass_matrix` must be {n}x{n} and `forcing` {n}x1; got {self._M.shape} "
                f"and {self._f.shape}.")
        self._energy = energy
        known = set(self._q) | set(self._u) | {_t}
        if parameters is None:
            free = free_symbols_shared(list(self._M) + list(self._f)) - known
        else:
            free = set(parameters)
        self._params = tuple(sorted(free, key=lambda s: s.name))
        self._cache = {}
        self._singular = singular_sets

    @property
    def coordinates(self):
        """The parameters of situation q(t)."""
        return self._coordinates

    @property
    def q(self):
        """Symbols standing for the parameters of situation."""
        return self._q

    @property
    def u(self):
        """Symbols standing for their time derivatives."""
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
    def energy(self):
        """Total mechanical energy T + V in symbol form, or None if an action has no
        potential energy."""
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

    def accelerations(self, simplify: bool = False) -> sp.ImmutableMatrix:
        """q'' = M^-1 f symbolically (small systems: the expressions grow fast)."""
        acc = self._M.LUsolve(self._f)
        return sp.ImmutableMatrix(sp.simplify(acc) if simplify else acc)

    def count_ops(self) -> int:
        """Number of operations in M and f as derived (sympy.count_ops)."""
        return int(sp.count_ops(list(self._M) + list(self._f)))

    # -- numbers ------------------------------------------------------------------------
    def _param_values(self, params):
        missing = [p.name for p in self._params if p.name not in params]
        unknown = sorted(set(params) - {p.name for p in self._params})
        if missing:
            raise ArgumentError(
                f"missing values for parameters {missing}; pass them as keywords, e.g. "
                f"{', '.join(f'{m}=1.0' for m in missing)}.")
        if unknown:
            raise ArgumentError(
                f"unknown parameters {unknown}; the equations depend on "
                f"{[p.name for p in self._params]}.")
        return [float(params[p.name]) for p in self._params]

    def _solver(self):
        if "solver" not in self._cache:
            self._cache["solver"] = compile_linear_solve(
                self._M, self._f, [_t, list(self._q), list(self._u), *self._params],
                symmetric=True, name="accelerations")
        return self._cache["solver"]

    def rhs(self, **params):
        """The first-order right-hand side ``f(t, y)`` with y = (q, q'), compiled once.

        Works on a single state (shape (2n,)) or a batch (shape (2n, batch)); returns a
        fresh array each call.

        Examples
        --------
        >>> import sympy as sp, numpy as np
        >>> x, v, k = sp.symbols("x x_dot k")
        >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
        ...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-k * x]]))
        >>> eqs.rhs(k=4.0)(0.0, np.array([1.0, 0.0]))
        array([ 0., -4.])
        """
        values = self._param_values(params)
        solve = self._solver()
        n = len(self._q)

        def fun(t, y):
            acc = solve(t, y[:n], y[n:], *values)
            return np.concatenate((y[n:], acc), axis=0)

        return fun

    def _acceleration_only(self, method, params):
        """q'' = a(t, q) for the geometric (second-order) methods, which need accelerations
        independent of the velocities (separable systems)."""
        if any(self._f.has(u) for u in self._u):
            raise ArgumentError(
                f"method {method!r} integrates q'' = a(t, q) only, but these equations "
                "depend on q' (velocity products); use an explicit method such as 'dop853'.")
        values = self._param_values(params)
        solve = self._solver()
        zeros = np.zeros(len(self._u))

        def acc(t, q):
            return solve(t, q, np.zeros_like(q) if np.ndim(q) > 1 else zeros, *values)

        return acc

    def simulate(self, t=(0.0, 10.0), q0=None, u0=None, *, method="dop853", rtol=1e-8,
                 atol=1e-10, step=None, n_output=1001, **params) -> Simulation:
        """Integrate the equations from (q0, u0) over ``t`` (ch. 27.2.2).

        Parameters
        ----------
        t : (t0, t1)
        q0, u0 : sequences of n floats (u0 defaults to zeros)
        method : str
            A method of :func:`rigidmech.ode.solve` ("dop853", "dopri5", "rk4", ...).
        rtol, atol, step
            Passed to the solver (``step`` for fixed-step methods).
        n_output : int
            Number of evenly spaced output times.
        **params
            Values of :attr:`parameters`.

        Returns
        -------
        Simulation
        """
        n = len(self._q)
        if q0 is None or len(q0) != n:
            raise ArgumentError(f"`q0` must give {n} initial values; got {q0!r}.")
        u0 = np.zeros(n) if u0 is None else np.asarray(u0, dtype=float)
        if u0.shape != (n,):
            raise ArgumentError(f"`u0` must give {n} initial values; got {u0.tolist()!r}.")
        y0 = np.concatenate((np.asarray(q0, dtype=float), u0))
        if method.lower() in ode.methods("second_order") + ode.methods("adaptive_second_order"):
            fun = self._acceleration_only(method, params)
        else:
            fun = self.rhs(**params)
        t_eval = np.linspace(t[0], t[1], int(n_output))
        kwargs = {"step": step} if step is not None else {"rtol": rtol, "atol": atol}
        start = _time.perf_counter()
        res = ode.solve(fun, (float(t[0]), float(t[1])), y0, method=method, t_eval=t_eval,
                        dense_output=True, **kwargs)
        elapsed = _time.perf_counter() - start
        if not res.success:
            raise NumericalError(f"integration failed: {res.message}")
        warn_near_singularities(self.singular_sets, self._coordinates, res, params)
        return Simulation(self, res, params, elapsed)

    def _latex(self, printer=None):
        acc = sp.Matrix([sp.Symbol(rf"\ddot{{{sp.latex(q)}}}") for q in self._q])
        return (sp.latex(sp.Matrix(self._M)) + sp.latex(acc) + " = "
                + sp.latex(sp.Matrix(self._f)))

    def _repr_latex_(self):
        """M(q) q'' = f(q, q', t) rendered in Jupyter and in the docs.

        Examples
        --------
        >>> import sympy as sp
        >>> x, v, k = sp.symbols("x x_dot k")
        >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
        ...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-k * x]]))
        >>> eqs._repr_latex_().startswith(r"$\\displaystyle \\left[\\begin{matrix}1")
        True
        >>> r"\\ddot{x}" in eqs._repr_latex_()
        True
        """
        return f"$\\displaystyle {self._latex()}$"

    def __repr__(self):
        return (f"EquationsOfMotion(coordinates={list(self._coordinates)}, "
                f"n={len(self._q)}, parameters={list(self._params)})")


class Simulation:
    """A numerically integrated motion: times, states, and what can be computed along it.

    Attributes
    ----------
    t : ndarray, shape (n_points,)
    q, u : ndarray, shape (n, n_points)
    result : rigidmech.ode.OdeResult
    elapsed : float
        Wall time of the integration, seconds.

    Examples
    --------
    >>> import sympy as sp
    >>> x, v, k = sp.symbols("x x_dot k")
    >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
    ...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-k * x]]),
    ...     energy=(v**2 + k * x**2) / 2)
    >>> sim = eqs.simulate(t=(0, 3), q0=[1.0], rtol=1e-10, atol=1e-12, k=4.0)
    >>> bool(abs(sim.q[0, -1] - np.cos(6.0)) < 1e-8), sim.energy_drift() < 1e-9
    (True, True)
    """

    __slots__ = ("_eqs", "result", "t", "q", "u", "_params", "elapsed")

    def __init__(self, eqs, result, params, elapsed):
        self._eqs = eqs
        self.result = result
        n = len(eqs.q)
        self.t = result.t
        self.q = result.y[:n]
        self.u = result.y[n:]
        self._params = dict(params)
        self.elapsed = elapsed

    @property
    def equations(self) -> EquationsOfMotion:
        """The equations that were integrated."""
        return self._eqs

    def evaluate(self, expr):
        """Evaluate a symbolic expression of q, q' (symbols), t and the parameters along the
        motion; returns an array over the output times."""
        eqs = self._eqs
        f = compile_expressions(sp.sympify(expr),
                                [_t, list(eqs.q), list(eqs.u), *eqs.parameters])
        values = [self._params[p.name] for p in eqs.parameters]
        return np.broadcast_to(f(self.t, self.q, self.u, *values), self.t.shape).copy()

    def energy(self):
        """Total mechanical energy along the motion."""
        e = self._eqs.energy
        if e is None:
            raise ArgumentError("the system's actions have no potential energy: no energy "
                                "to follow.")
        return self.evaluate(e)

    def energy_drift(self) -> float:
        """Relative drift of the energy: ``max |E(t) - E(0)| / max(|E(0)|, max |E|)``."""
        e = self.energy()
        scale = max(abs(e[0]), np.max(np.abs(e)), np.finfo(float).tiny)
        return float(np.max(np.abs(e - e[0])) / scale)

    def plot(self, path=None, *, ax=None):
        """Plot the parameters of situation against time; save to ``path`` if given.

        With ``path`` and no ``ax`` the figure is drawn off-screen (no pyplot state, works
        headless); with neither, pyplot makes a figure to show. Returns the Axes.
        """
        if ax is None:
            if path is not None:
                from matplotlib.figure import Figure  # imported on use (slow import)

                ax = Figure(figsize=(7, 4)).subplots()
            else:
                import matplotlib.pyplot as plt  # imported on use (slow import)

                ax = plt.subplots(figsize=(7, 4))[1]
        for i, q in enumerate(self._eqs.q):
            ax.plot(self.t, self.q[i], label=f"${sp.latex(q)}$")
        ax.set_xlabel("t")
        ax.set_ylabel("parameters of situation")
        ax.legend()
        ax.grid(True, alpha=0.3)
        if path is not None:
            ax.figure.tight_layout()
            ax.figure.savefig(path, dpi=100)
        return ax

    def __repr__(self):
        return (f"Simulation(t=[{self.t[0]}, {self.t[-1]}], points={self.t.size}, "
                f"nfev={self.result.nfev}, method={self.result.method!r})")
