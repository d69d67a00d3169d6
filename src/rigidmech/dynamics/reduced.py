"""Equations of motion reduced to the independent speeds: the constraint actions and the
dependent rates eliminated (book, ch. 25.3; Kane's and Appell's form).

With m constraints A(q, t) q' + a(q, t) = 0 on n parameters (the velocity form of closed
loops, rolling, gears, see :mod:`rigidmech.dynamics.constraints`), choose n - m
**independent** parameters I whose rates u = q'_I are free; the m others, D, have their rates
fixed by the constraints:

.. math:: q'_D = -A_D^{-1}(A_I\\,u + a),\\qquad q' = T(q, t)\\,u + s(q, t),\\qquad
          T = \\begin{pmatrix} I \\\\ -A_D^{-1} A_I \\end{pmatrix}

(rows in the order of the parameters). The columns of T span the motions the constraints
allow: :math:`A T = 0`, so T is a basis of the null space of A and
:math:`T^T A^T \\lambda = 0`. Its columns are the partial velocities of Kane's method.
Multiplying :math:`M q'' = f + A^T \\lambda` by :math:`T^T` removes the multipliers, and the
acceleration form :math:`A q'' = b` gives :math:`q'' = T u' + c` with
:math:`c_I = 0,\\ c_D = A_D^{-1} b`:

.. math:: M_r\\, u' = f_r,\\qquad M_r = T^T M T,\\qquad f_r = T^T (f - M c),

everything written with q and u only (q'_D replaced by its expression). M_r is symmetric and
positive definite where A_D is invertible. The state is (q, u): n + (n - m) first-order
equations, q' = T u + s and u' = M_r^{-1} f_r. For a holonomic constraint the dependent
parameters also follow from the independent ones (through Φ(q, t) = 0, not imposed by the
reduced equations: the integration keeps it to its own accuracy, as for the velocity level
of the multiplier form); for a nonholonomic one (a disc rolling on a plane) they are new
parameters whose rates are given.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, SingularMassMatrixError
from .._core.rules import numeric_rank
from .._core.symbolic import complex_values, xreplace_shared
from ..vectors import t as _t

__all__ = ["ReducedEquations", "plain_constraints", "reduce_equations", "split_coordinates"]


def _index(eqs, coordinate):
    names = eqs.names
    for k, (c, name) in enumerate(zip(eqs.coordinates, names, strict=True)):
        if coordinate is c or coordinate == c or coordinate == name:
            return k
        if isinstance(coordinate, sp.Basic) and getattr(coordinate, "name", None) == name:
            return k
    raise ArgumentError(
        f"`independent` names {coordinate!r}, which is not a coordinate; the coordinates are "
        f"{', '.join(names)}.")


def _generic_jacobian(A, symbols):
    """A at a generic point (random values of every symbol): the structural rank."""
    rng = np.random.default_rng(20260)
    point = dict(zip(symbols, rng.uniform(0.3, 1.3, len(symbols)), strict=True))
    values = complex_values(list(A), point)  # one double-precision walk, not evalf
    return np.array(values, dtype=complex).reshape(A.shape).real


def _choose_dependent(eqs, A, symbols):
    """Dependent parameters: scanning the coordinates in order, each whose column of A adds
    to the rank (at a generic point), until the rank is m (Kane's usual choice of the
    first ones as dependent when they are the positions of a rolling contact)."""
    An = _generic_jacobian(A, symbols)
    m = An.shape[0]
    chosen = []
    for j in range(An.shape[1]):
        cols = An[:, chosen + [j]]
        if numeric_rank(cols) == len(chosen) + 1:
            chosen.append(j)
        if len(chosen) == m:
            return chosen
    raise ArgumentError(
        f"the {m} constraints {', '.join(eqs.constraints.labels)} are not independent (rank "
        f"{len(chosen)} of their Jacobian at a generic point): remove the redundant ones.")


class ReducedEquations:
    """M_r(q, t) u' = f_r(q, u, t) on the independent speeds u = q'_I (ch. 25.3).

    Built by :meth:`EquationsOfMotion.reduced`; see :mod:`rigidmech.dynamics.reduced`.

    Attributes
    ----------
    coordinates : tuple of q(t)
        Every parameter of situation.
    independent, dependent : tuple of q(t)
        The parameters whose rates are the independent speeds, and the others.
    mass_matrix : sympy.ImmutableMatrix (n - m, n - m)
    forcing : sympy.ImmutableMatrix (n - m, 1)
        Written with q(t), the independent rates ``Derivative(q_I(t), t)``, t, the
        parameters and the inputs.
    basis : sympy.ImmutableMatrix (n, n - m)
        T, the partial velocities: q' = T u + s (the columns span the null space of A).
    dependent_rates : dict
        q_D(t) -> the expression of q'_D(t) in q(t) and the independent rates.
    equations : EquationsOfMotion
        The multiplier form the reduction comes from.
    """

    __slots__ = ("equations", "coordinates", "independent", "dependent", "mass_matrix",
                 "forcing", "basis", "dependent_rates", "_plain", "_cache")

    def __init__(self, equations, independent, dependent, plain, back):
        self.equations = equations
        self.coordinates = tuple(equations.coordinates)
        self.independent = tuple(self.coordinates[k] for k in independent)
        self.dependent = tuple(self.coordinates[k] for k in dependent)
        # plain: (q_s, u_I symbols, u_D expressions, T, M_r, f_r) with stand-in symbols
        self._plain = plain
        q_s, uI_s, uD, T, Mr, fr = plain
        memo = {}
        k = len(independent)
        self.mass_matrix = sp.ImmutableMatrix(k, k, xreplace_shared(list(Mr), back, memo))
        self.forcing = sp.ImmutableMatrix(k, 1, xreplace_shared(list(fr), back, memo))
        self.basis = sp.ImmutableMatrix(T.shape[0], k, xreplace_shared(list(T), back, memo))
        self.dependent_rates = dict(zip(self.dependent, xreplace_shared(uD, back, memo),
                                        strict=True))
        self._cache = {}

    def __setattr__(self, name, value):
        if hasattr(self, name):
            raise AttributeError(f"ReducedEquations is immutable: cannot set `{name}`.")
        object.__setattr__(self, name, value)

    @property
    def plain(self):
        """(q, u_I, q'_D, T, M_r, f_r) written with plain symbols: q stands for every
        parameter, u_I for the independent rates (for the analyses built on this form)."""
        return self._plain

    def rhs(self, **params):
        """First-order right-hand side ``f(t, y)``, y = (q (n values), u (n - m independent
        rates)) -> (q', u'), for one state. ``params``: values of the parameters of the
        equations (numbers) and of their inputs (numbers or callables of t).

        M, f, A, a and b are compiled once; each evaluation solves the constraints for the
        dependent rates and accelerations and forms M_r and f_r numerically (the symbolic
        :attr:`mass_matrix` and :attr:`forcing` may have removable 0/0 at special states,
        the numbers do not); a block A_D singular at the state is reported.

        Examples
        --------
        A wheel of radius r rolling down a slope of angle α: one independent speed, the
        acceleration 2/3 g sin α of the centre (x' = -r θ' with x the distance along it).

        >>> import numpy as np, sympy as sp
        >>> import rigidmech as rm
        >>> x, th = rm.coordinates("x theta")
        >>> m, g, r = rm.constants("m g r", positive=True)
        >>> R0 = rm.Frame("R0"); Ri = R0.rotated("Ri", about=R0.k, angle=-sp.pi / 6)
        >>> C = R0.origin.moved("C", x * Ri.i + r * Ri.j)
        >>> R1 = Ri.rotated("R1", about=R0.k, angle=th, origin=C)
        >>> wheel = rm.Body("wheel", frame=R1, mass=m, centre=C,
        ...                 inertia=rm.inertia.disk(m, r, axis=R1.k, centre=C))
        >>> s = rm.System(galilean=R0)
        >>> contact = rm.kinematics.ContactKinematics.between(
        ...     R1, rm.kinematics.Circle(C, r, normal=R0.k), R0, rm.Line(R0.origin, Ri.i))
        >>> s.connect(R0, wheel, rm.actions.RollingContact(contact))
        >>> s.act(rm.gravity(-g * R0.j))
        >>> red = s.equations_of_motion().reduced(independent=[x])
        >>> red.independent, red.dependent_rates
        ((x(t),), {theta(t): -Derivative(x(t), t)/r})
        >>> round(float(red.rhs(m=1.0, g=9.81, r=0.5)(0.0, np.zeros(3))[2]), 6)
        3.27
        """
        eqs = self.equations
        values, inputs, notes = eqs._values(params)
        geometry, dynamics = self._compiled()
        n = len(self.coordinates)
        ind = [self.coordinates.index(c) for c in self.independent]
        dep = [self.coordinates.index(c) for c in self.dependent]
        m = len(dep)

        def fun(t, y):
            w = [v(t) if callable(v) else v for v in inputs]
            q, u = np.asarray(y[:n], dtype=float), np.asarray(y[n:], dtype=float)
            A, a = geometry(t, q, *values, *w)
            A = np.asarray(A, dtype=float).reshape(m, n)
            AD = A[:, dep]
            try:
                sol = np.linalg.solve(AD, np.column_stack(
                    [-A[:, ind], -(A[:, ind] @ u + np.asarray(a, dtype=float).ravel())]))
            except np.linalg.LinAlgError:
                raise SingularMassMatrixError(
                    f"the constraints cannot be solved for the rates of "
                    f"{[str(c) for c in self.dependent]} at t = {t}, q = {q.tolist()}: "
                    "their Jacobian block is singular there.") from None
            v = np.empty(n)
            v[ind], v[dep] = u, sol[:, -1]
            M, f, b = dynamics(t, q, v, *values, *w)
            M = np.asarray(M, dtype=float).reshape(n, n)
            T = np.zeros((n, len(ind)))
            T[ind, range(len(ind))] = 1.0
            T[dep] = sol[:, :-1]
            cD = np.linalg.solve(AD, np.asarray(b, dtype=float).ravel())
            Mr = T.T @ M @ T
            fr = T.T @ (np.asarray(f, dtype=float).ravel() - M[:, dep] @ cD)
            return np.concatenate((v, np.linalg.solve(Mr, fr)))

        fun.notes = notes
        return fun

    def _full_state(self, params):
        """``full(t, Y)``: the states (q, q') of samples Y = (q, u) (columns, t their times),
        the dependent rates solved from the constraints."""
        values, inputs, _ = self.equations._values(params)
        geometry, _ = self._compiled()
        n = len(self.coordinates)
        ind = [self.coordinates.index(c) for c in self.independent]
        dep = [self.coordinates.index(c) for c in self.dependent]

        def full(t, Y):
            Y = np.asarray(Y, dtype=float)
            out = np.full((2 * n, Y.shape[1]), np.nan)
            out[:n] = Y[:n]
            for j, tj in enumerate(np.asarray(t, dtype=float).tolist()):
                w = [v(tj) if callable(v) else v for v in inputs]
                A, a = geometry(tj, Y[:n, j], *values, *w)
                A = np.asarray(A, dtype=float).reshape(len(dep), n)
                u = Y[n:, j]
                out[n + np.array(ind), j] = u
                try:
                    out[n + np.array(dep), j] = np.linalg.solve(
                        A[:, dep], -(A[:, ind] @ u + np.asarray(a, dtype=float).ravel()))
                except np.linalg.LinAlgError:  # A_D singular there: the rates left nan
                    pass
            return out

        return full

    def simulate(self, t=(0.0, 10.0), q0=None, u0=None, *, method="dop853", rtol=1e-8,
                 atol=1e-10, step=None, n_output=1001, t_eval=None, events=None,
                 max_steps=1_000_000, first_step=None, max_step=None, dense_output=None,
                 progress=None, project=None, raise_on_failure=False, params=None, **values):
        """Integrate the reduced equations from (q0, u0) over ``t`` (ch. 25.3, 27.2.2): the
        state (q, u) of n + (n - m) values, q' = T u + s and u' = M_r^-1 f_r.

        The arguments, the run and the result are those of
        :meth:`EquationsOfMotion.simulate <rigidmech.dynamics.EquationsOfMotion.simulate>`
        (one run helper): ``q0`` and ``u0`` give every coordinate and rate (a state off the
        constraints is assembled on them, the :attr:`independent` coordinates and their
        rates kept), the :class:`~rigidmech.dynamics.Simulation` holds (q, q') at the
        samples (the dependent rates solved from the constraints), and by default the
        positions are projected onto the closure conditions after every step (``project``;
        the independent speeds are free: nothing to project at the velocity level). Event
        callables ``g(t, y)`` receive the run's state (q, u); expressions are evaluated on
        (q, q'). Second-order methods (``verlet``, ``rkn64``, ...) are refused: the reduced
        equations are first order in (q, u).

        Examples
        --------
        A particle on the unit circle under gravity -g j, x independent, released at rest
        below the centre: the loop stays closed.

        >>> import numpy as np, sympy as sp, rigidmech as rm
        >>> from rigidmech.dynamics import Constraints
        >>> x, y = rm.coordinates("x y")
        >>> phi = (x**2 + y**2 - 1) / 2
        >>> eqs = rm.EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
        ...     forcing=sp.Matrix([0, -9.81]), constraints=Constraints((x, y),
        ...     [("circle", phi.diff(rm.t), phi)]))
        >>> red = eqs.reduced(independent=[x])
        >>> sim = red.simulate(t=(0, 0.5), q0=[0.6, -0.8], n_output=6, rtol=1e-10)
        >>> bool(np.abs(sim.q[0]**2 + sim.q[1]**2 - 1).max() < 1e-12), sim.u.shape
        (True, (2, 6))
        """
        from ._simulate import simulate_reduced

        return simulate_reduced(
            self, t, q0, u0, method=method, rtol=rtol, atol=atol, step=step,
            n_output=n_output, t_eval=t_eval, events=events, max_steps=max_steps,
            first_step=first_step, max_step=max_step, dense_output=dense_output,
            progress=progress, project=project, raise_on_failure=raise_on_failure,
            params=params, values=values)

    def _compiled(self):
        if "compiled" not in self._cache:
            from .._core.compile import compile_expressions

            eqs = self.equations
            q_s, u_s, w_s, _, M, f = eqs._symbolic()
            A, b, vel = plain_constraints(eqs)
            a = vel.xreplace({u: 0 for u in u_s})
            params = [*eqs.parameters, *w_s]
            geometry = compile_expressions((list(A), list(a)), [_t, list(q_s), *params],
                                           name="constraint_jacobian")
            dynamics = compile_expressions((list(M), list(f), list(b)),
                                           [_t, list(q_s), list(u_s), *params],
                                           name="mass_forcing_bias")
            self._cache["compiled"] = (geometry, dynamics)
        return self._cache["compiled"]

    def __repr__(self):
        return (f"ReducedEquations(independent={list(self.independent)}, "
                f"dependent={list(self.dependent)})")


def plain_constraints(eqs):
    """(A, b, c) of the constraints of ``eqs`` written with the stand-in symbols of its
    compiled world (q, q' plain symbols): A q'' = b, c = A q' + a."""
    c = eqs.constraints
    if c is None or len(c) == 0:
        raise ArgumentError(
            "the equations have no constraints: there is nothing to reduce (they are "
            "already M q'' = f on independent parameters).")
    q_s, u_s, w_s, rule, _, _ = eqs._symbolic()
    n, m = len(q_s), len(c)
    memo = {}
    A = sp.Matrix(m, n, xreplace_shared(list(c.jacobian), rule, memo))
    b = sp.Matrix(m, 1, xreplace_shared(list(c.bias), rule, memo))
    vel = sp.Matrix(m, 1, xreplace_shared(list(c.velocity), rule, memo))
    return A, b, vel


def split_coordinates(eqs, independent, A=None):
    """(indices of the independent parameters, of the dependent ones) for ``independent``
    (default: see :func:`reduce_equations`), checked against the constraint Jacobian A."""
    if A is None:
        A = plain_constraints(eqs)[0]
    m, n = A.shape
    if independent is None:
        dep = _choose_dependent(eqs, A, sorted(A.free_symbols, key=str))
        ind = [j for j in range(n) if j not in dep]
    else:
        ind = [_index(eqs, x) for x in independent]
        if len(set(ind)) != len(ind) or len(ind) != n - m:
            raise ArgumentError(
                f"`independent` must name {n - m} distinct coordinates (n = {n} parameters, "
                f"m = {m} constraints); got {list(independent)!r}.")
        dep = [j for j in range(n) if j not in ind]
    AD = A[:, dep]
    ADn = _generic_jacobian(AD, sorted(AD.free_symbols, key=str))
    if numeric_rank(ADn) < m:
        names = [eqs.names[j] for j in dep]
        raise ArgumentError(
            f"the constraints cannot be solved for the rates of {names} (their Jacobian "
            f"block is singular at a generic point): choose other `independent` coordinates.")
    return ind, dep


def reduce_equations(eqs, independent=None) -> ReducedEquations:
    """The equations ``eqs`` (with constraints) reduced to the independent speeds (ch. 25.3).

    Parameters
    ----------
    eqs : EquationsOfMotion
        With :attr:`~EquationsOfMotion.constraints`.
    independent : sequence of coordinates (q(t) or names), optional
        n - m parameters whose rates are free. Default: the dependent ones are the first
        coordinates, in order, whose columns of the constraint Jacobian are independent.

    Returns
    -------
    ReducedEquations

    Raises
    ------
    ArgumentError
        No constraints, a wrong number of independent parameters, or a choice for which the
        constraints cannot be solved for the dependent rates (A_D singular).
    """
    q_s, u_s, w_s, rule, M, f = eqs._symbolic()
    n = len(q_s)
    A, b, vel = plain_constraints(eqs)
    m = A.shape[0]
    a = vel.xreplace({u: 0 for u in u_s})
    ind, dep = split_coordinates(eqs, independent, A)
    AD, AI = A[:, dep], A[:, ind]
    k = n - m
    uI = [u_s[j] for j in ind]
    sol = AD.LUsolve(sp.Matrix.hstack(-AI, -a, b))      # one factorisation for all columns
    TD, sD, cD = sol[:, :k], sol[:, k], sol[:, k + 1]
    uD = list(TD * sp.Matrix(uI) + sD)
    to_ind = dict(zip([u_s[j] for j in dep], uD, strict=True))
    T = sp.zeros(n, k)
    cacc = sp.zeros(n, 1)
    for r, j in enumerate(ind):
        T[j, r] = 1
    for r, j in enumerate(dep):
        T[j, :] = TD[r, :]
        cacc[j] = cD[r]
    memo2 = {}
    T = sp.ImmutableMatrix(n, k, xreplace_shared(list(T), to_ind, memo2))
    cacc = sp.Matrix(n, 1, xreplace_shared(list(cacc), to_ind, memo2))
    f = sp.Matrix(n, 1, xreplace_shared(list(f), to_ind, memo2))
    Mr = T.T * M * T
    fr = T.T * (f - M * cacc)
    Mr = sp.ImmutableMatrix(k, k, lambda i, j: Mr[min(i, j), max(i, j)])
    plain = (tuple(q_s), tuple(uI), tuple(uD), T, Mr, sp.ImmutableMatrix(fr))
    back = {v: key for key, v in rule.items() if key in set(eqs.q) | set(eqs.u)
            or key in set(eqs.inputs)}
    back |= {w: x for w, x in zip(w_s, eqs.inputs, strict=True)}
    return ReducedEquations(eqs, ind, dep, plain, back)
