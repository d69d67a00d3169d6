"""Linearisation of equations of motion about an equilibrium or a steady motion (book,
ch. 21.1, 25.4, 27.5.2).

Near a state :math:`(q^*, \\dot q^*)` with :math:`\\ddot q^* = 0` that satisfies
:math:`M(q^*)\\,\\ddot q^* = f(q^*, \\dot q^*)`, i.e. :math:`f(q^*, \\dot q^*) = 0`, the
small deviations :math:`\\delta q` obey

.. math:: M\\,\\delta\\ddot q + C\\,\\delta\\dot q + K\\,\\delta q = B\\,\\delta w,\\qquad
          M = M(q^*),\\ C = -\\frac{\\partial f}{\\partial \\dot q},\\
          K = -\\frac{\\partial f}{\\partial q},\\ B = \\frac{\\partial f}{\\partial w},

all at the reference state (the term :math:`\\partial M/\\partial q\\,\\ddot q^*` vanishes
since :math:`\\ddot q^* = 0`), w being the inputs (forces or torques named by symbols). The
first-order form for x = (δq, δq') is :math:`\\dot x = A x + B_1 w` with
:math:`A = [[0, I], [-M^{-1}K, -M^{-1}C]]`, :math:`B_1 = [[0], [M^{-1}B]]`.

The derivatives are taken at the point in one pass over the expression DAG (values and
gradients together), so M, C, K, B come out symbolic in the parameters without differentiating
the full expressions. Equations with constraints (closed loops, rolling, gears: M q'' = f +
A^T λ) are linearised on their independent speeds, the multipliers and the dependent
parameters eliminated (:mod:`rigidmech.vibrations.constrained`).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, SingularMassMatrixError
from .._core.rules import vanishes
from .._core.symbolic import is_identically_zero
from .._core.validation import as_declared
from ._jet import values_and_jacobian
from ._numeric import compiled_matrices, state_matrix
from ._symbols import normalise
from .modes import Modes, harmonic_response_direct, natural_modes

__all__ = ["LinearSystem", "linearize"]


_ROUNDING = 8 * float(np.finfo(float).eps)


def rounding_allowance(jac_row, values) -> float:
    """What a residual f_i may keep because q* is rounded: 8 eps sum_j |df_i/dq_j|
    max(|q_j*|, 1) (the backward error of a point given in floats: pi is not representable,
    so k sin(pi) = 1.2e-16 k). Zero when an entry is not a number."""
    total = 0.0
    for d, v in zip(jac_row, values, strict=True):
        d, v = sp.sympify(d), sp.sympify(v)
        if not (d.is_number and v.is_number):
            return 0.0
        total += abs(complex(d)) * max(abs(complex(v)), 1.0)
    return _ROUNDING * total


def _steady(residual, rate, rates, tol, jac=None, q=None):
    """The one rule of steadiness, for the equations (no constraints) or the reduced ones:
    the residual f(q*, q'*) and its rate along the motion (df/dq) q'* both vanish
    (:func:`rigidmech._core.rules.vanishes`; with ``jac`` the rows df_i/dq and ``q`` = q*,
    the residual may keep the rounding of q* and the rate that of q'*). Returns (ok, moving,
    residual, rate), simplified."""
    residual = [r if sp.sympify(r).is_number else sp.simplify(r) for r in residual]
    rate = [r if sp.sympify(r).is_number else sp.simplify(r) for r in rate]
    if jac is None:
        slack_q = slack_u = [0.0] * len(residual)
    else:
        slack_q = [rounding_allowance(row, q) for row in jac]
        slack_u = [rounding_allowance(row, rates) for row in jac]
    ok = all(vanishes(r, tol, a) for r, a in zip(residual, slack_q, strict=True)) \
        and all(vanishes(r, tol, a) for r, a in zip(rate, slack_u, strict=True))
    moving = any(not vanishes(v, 0.0) for v in rates)
    return ok, moving, residual, rate


class LinearSystem:
    """M δq'' + C δq' + K δq = B δw about a reference state (ch. 25.4).

    Attributes
    ----------
    coordinates : tuple
        The parameters of situation q(t) of the equations, in order; for equations with
        constraints, the independent ones (the rows of M, C, K).
    about : dict
        Name of each coordinate (every one, dependent ones included) -> its value ``q*`` at
        the reference state.
    velocities : dict
        Name -> ``q'*`` (zero for an equilibrium; for equations with constraints the
        dependent rates are the ones the constraints give).
    M, C, K : sympy.ImmutableMatrix (n, n)
    B : sympy.ImmutableMatrix (n, p)
        One column per input.
    inputs : tuple of sympy.Symbol
    parameters : tuple of sympy.Symbol
        Symbols left in M, C, K, B.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion
    >>> x, v, k, c, m, F = sp.symbols("x x_dot k c m F")
    >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
    ...     mass_matrix=sp.ImmutableMatrix([[m]]),
    ...     forcing=sp.ImmutableMatrix([[-k * x - c * v + F]]))
    >>> lin = linearize(eqs, inputs=[F])
    >>> lin.M, lin.C, lin.K, lin.B
    (Matrix([[m]]), Matrix([[c]]), Matrix([[k]]), Matrix([[1]]))
    >>> lin.first_order()[0]
    Matrix([
    [   0,    1],
    [-k/m, -c/m]])
    """

    __slots__ = ("coordinates", "about", "velocities", "M", "C", "K", "B", "inputs",
                 "parameters", "_cache")

    def __init__(self, coordinates, about, velocities, M, C, K, B, inputs):
        self.coordinates = tuple(coordinates)
        self.about = dict(about)
        self.velocities = dict(velocities)
        self.M, self.C, self.K, self.B = (sp.ImmutableMatrix(X) for X in (M, C, K, B))
        self.inputs = tuple(inputs)
        free = set()
        for X in (self.M, self.C, self.K, self.B):
            free |= X.free_symbols
        self.parameters = tuple(sorted(free, key=lambda s: s.name))
        self._cache = {}

    def __setattr__(self, name, value):
        if hasattr(self, name):
            raise AttributeError(f"LinearSystem is immutable: cannot set `{name}`.")
        object.__setattr__(self, name, value)

    @property
    def n(self) -> int:
        """Number of degrees of freedom."""
        return self.M.shape[0]

    @property
    def is_symmetric(self) -> bool:
        """Whether M and K are symmetric (they are for conservative holonomic systems about
        an equilibrium; a gyroscopic or circulatory system has C or K not symmetric)."""
        return all(is_identically_zero(X[i, j] - X[j, i]) for X in (self.M, self.K)
                   for i in range(self.n) for j in range(i))

    def first_order(self):
        """(A, B1) of the first-order form x' = A x + B1 w, x = (δq, δq').

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech import EquationsOfMotion
        >>> x, v = sp.symbols("x x_dot")
        >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
        ...     mass_matrix=sp.ImmutableMatrix([[2]]), forcing=sp.ImmutableMatrix([[-8 * x]]))
        >>> linearize(eqs).first_order()
        (Matrix([
        [ 0, 1],
        [-4, 0]]), Matrix(2, 0, []))
        """
        if "first" not in self._cache:
            n = self.n
            MK = self.M.LUsolve(self.K).applyfunc(sp.simplify)
            MC = self.M.LUsolve(self.C).applyfunc(sp.simplify)
            MB = self.M.LUsolve(self.B).applyfunc(sp.simplify) if self.B.shape[1] else self.B
            A = sp.ImmutableMatrix(sp.BlockMatrix([[sp.zeros(n), sp.eye(n)],
                                                   [-MK, -MC]]).as_explicit())
            B1 = sp.ImmutableMatrix.vstack(sp.zeros(n, self.B.shape[1]), MB)
            self._cache["first"] = (A, sp.ImmutableMatrix(B1))
        return self._cache["first"]

    def numeric(self, **params):
        """(M, C, K, B) as float arrays, with values for :attr:`parameters` given by name.

        The matrices are compiled on the first call and cached (constant subexpressions
        evaluated with 64 digits, entries that vanish made exact zeros: ``fold_numbers`` of
        ``rigidmech._core.symbolic``); a call then costs float arithmetic only, and a
        compiled system pickles with its generated code. Values for names that are not
        parameters are ignored; a missing one raises ArgumentError.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech import EquationsOfMotion
        >>> x, v, k = sp.symbols("x x_dot k")
        >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
        ...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-k * x]]))
        >>> linearize(eqs).numeric(k=4.0)[2].tolist()
        [[4.0]]
        """
        return compiled_matrices(self)(params)

    def modes(self, **params) -> Modes:
        """Natural modes of M δq'' + K δq = 0 (damping ignored): closed form for symbolic
        2-dof, numeric otherwise (values of the parameters as keywords).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech import EquationsOfMotion
        >>> x, v, k, m = sp.symbols("x x_dot k m", positive=True)
        >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
        ...     mass_matrix=sp.ImmutableMatrix([[m]]), forcing=sp.ImmutableMatrix([[-k * x]]))
        >>> linearize(eqs).modes().frequencies
        (sqrt(k)/sqrt(m),)
        >>> linearize(eqs).modes(k=4.0, m=1.0).frequencies.tolist()
        [2.0]
        """
        if params or not self.parameters:
            M, _, K, _ = self.numeric(**params)
            return natural_modes(M, K)
        return natural_modes(self.M, self.K)

    def eigenvalues(self, **params):
        """Eigenvalues of A (numeric): the exponents of the free motions about the reference
        state. All real parts < 0: asymptotically stable; one > 0: unstable.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech import EquationsOfMotion
        >>> x, v = sp.symbols("x x_dot")
        >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
        ...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-x - 2*v]]))
        >>> linearize(eqs).eigenvalues().real.round(6).tolist()
        [-1.0, -1.0]
        """
        M, C, K, _ = self.numeric(**params)
        return np.linalg.eigvals(state_matrix(M, C, K))

    def frequency_response(self, omega, force=None, *, input=None, **params):
        """Complex amplitudes of the steady response to a harmonic force
        :math:`\\Re(F e^{i\\omega t})` (direct solution with C, ch. 21.3.3), shape (n, m).

        Parameters
        ----------
        omega : array of angular frequencies
        force : array (n,), optional
            Generalised force amplitudes; or
        input : symbol or name, optional
            One of :attr:`inputs` with unit amplitude (the column of B).
        **params : values of the parameters

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech import EquationsOfMotion
        >>> x, v, F = sp.symbols("x x_dot F")
        >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
        ...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-4*x + F]]))
        >>> abs(linearize(eqs, inputs=[F]).frequency_response([1.0], input="F")).tolist()
        [[0.3333333333333333]]
        """
        M, C, K, B = self.numeric(**params)
        if (force is None) == (input is None):
            raise ArgumentError("give exactly one of `force` (an array) and `input` (a name).")
        if input is not None:
            names = [s.name for s in self.inputs]
            key = input.name if isinstance(input, sp.Symbol) else input
            if key not in names:
                raise ArgumentError(f"`input` must be one of {names}; got {input!r}.")
            force = B[:, names.index(key)]
        return harmonic_response_direct(M, C, K, force, omega)

    def __repr__(self):
        return (f"LinearSystem(coordinates={list(self.coordinates)}, about={self.about}, "
                f"inputs={list(self.inputs)})")


def _values(spec, norm, name, default=0):
    n = len(norm.q)
    if spec is None:
        return [sp.sympify(default)] * n
    if isinstance(spec, dict):
        out = [sp.sympify(default)] * n
        for key, value in spec.items():
            out[norm.index(key)] = sp.sympify(value)
        return out
    values = list(spec) if not isinstance(spec, sp.Basic | int | float) else [spec]
    if len(values) != n:
        raise ArgumentError(f"`{name}` must give {n} values (or a dict by coordinate); got "
                            f"{len(values)}: {spec!r}.")
    return [sp.sympify(v) for v in values]


def _input_symbols(inputs, eqs):
    by_name = {p.name: p for p in eqs.parameters}
    out = []
    for w in inputs:
        key = w.name if isinstance(w, sp.Symbol) else w
        if key not in by_name:
            raise ArgumentError(
                f"`inputs` must name parameters of the equations {sorted(by_name)}; got "
                f"{w!r}.")
        out.append(by_name[key])
    return out


def linearize(eqs, about=None, *, velocities=None, inputs=(), input_values=None,
              parameters=None, check=True, tol=1e-9, simplify=None,
              independent=None) -> LinearSystem:
    """Linearise equations of motion about an equilibrium or a steady motion (ch. 25.4).

    Parameters
    ----------
    eqs : EquationsOfMotion
    about : dict or sequence, optional
        The reference configuration ``q*`` (by coordinate q(t), symbol or name); default 0.
        Values may be symbolic (a symbolic equilibrium).
    velocities : dict or sequence, optional
        Constant rates ``q'*`` of a steady motion (a cyclic coordinate turning at a constant
        rate); default 0 (an equilibrium).
    inputs : sequence of symbols or names
        Parameters of the equations that are inputs (forces, torques): their column of B.
    input_values : dict, optional
        Nominal values of the inputs (default 0).
    parameters : dict, optional
        Values of some parameters (by name), substituted before linearising.
    check : bool
        Check that the reference state is one and that ``M(q*)`` is invertible. One rule on
        both paths (with and without constraints): the residual ``f(q*, q'*)`` (of the
        reduced equations with constraints) **and its rate along the motion**
        ``(df/dq)(q*, q'*) q'*`` vanish, so that q* + q'* t satisfies the equations to first
        order in t: a rate on a coordinate the equations depend on is refused (the pendulum
        at θ = 0 with θ' = 2), one on a cyclic coordinate is a steady motion. The test is
        first order: it is exact when the moving coordinates are cyclic (absent from M and
        f), the usual steady motion.
    tol : float
        Absolute tolerance on each numeric entry of the residual and of its rate (a
        numerically found equilibrium satisfies f = 0 to round-off only): ``abs(x) <= tol +
        8 eps sum_j |df_i/dq_j| max(|q_j|, 1)`` passes, the second term being what the
        rounding of q* (of q'* for the rate) leaves in f_i (k sin(pi) = 1.2e-16 k for a
        stiff pendulum). Symbolic entries must vanish identically. (For equations with
        constraints, q* on the closure conditions and the rates given on the velocity
        conditions are judged by the rule on the constraints, relative to the magnitude of
        their terms: :func:`rigidmech._core.rules.on_constraints`.)
    simplify : bool, optional
        Simplify the entries of M, C, K, B; by default only up to 4 degrees of freedom
        (``sympy.simplify`` costs more than the linearisation beyond).
    independent : sequence of coordinates (q(t) or names), optional
        For equations with constraints (closed loops, rolling): the parameters whose rates
        are the independent speeds (default: see
        :func:`rigidmech.dynamics.reduce_equations`). The equations are reduced to them,
        then linearised (:mod:`rigidmech.vibrations.constrained`): the LinearSystem's
        coordinates are these parameters; ``about`` gives every coordinate (on the
        constraints), ``velocities`` every rate or only the independent ones (the others
        follow from the constraints).

    Returns
    -------
    LinearSystem

    Raises
    ------
    ArgumentError
        If the state is not an equilibrium / steady motion: the message gives the residual
        ``f(q*, q'*)`` and its rate ``(df/dq) q'*``; with constraints, if it violates them
        (the residual Φ(q*) or A q'* + a), or if the reduced equations are not steady along it.
    SingularMassMatrixError
        If ``M(q*)`` is singular.

    Examples
    --------
    The simple pendulum m L^2 θ'' = -m g L sin θ about θ = 0 and θ = π:

    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion, coordinates
    >>> th = coordinates("theta")
    >>> q, u = sp.symbols("theta theta_dot")
    >>> m, g, L = sp.symbols("m g L", positive=True)
    >>> eqs = EquationsOfMotion(coordinates=(th,), q=(q,), u=(u,),
    ...     mass_matrix=sp.ImmutableMatrix([[m * L**2]]),
    ...     forcing=sp.ImmutableMatrix([[-m * g * L * sp.sin(q)]]))
    >>> linearize(eqs).K, linearize(eqs, about={th: sp.pi}).K
    (Matrix([[L*g*m]]), Matrix([[-L*g*m]]))
    >>> linearize(eqs, about=[1])
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `about` is not an equilibrium ...
    f(q*, q'*) = [-L*g*m*sin(1)] ...
    """
    norm = normalise(eqs)
    n = len(norm.q)
    q_star = _values(about, norm, "about")
    constrained = eqs.constraints is not None and len(eqs.constraints) > 0
    # with constraints, the rates may be the independent ones only (checked there)
    u_star = _values(None if constrained else velocities, norm, "velocities")
    w = _input_symbols(inputs, eqs)
    w_star = [sp.sympify((input_values or {}).get(s.name, (input_values or {}).get(s, 0)))
              for s in w]
    point = dict(zip(norm.q, q_star, strict=True))
    point |= dict(zip(norm.u, u_star, strict=True))
    point |= dict(zip(w, w_star, strict=True))
    if parameters:
        by_name = {p.name: p for p in eqs.parameters}
        unknown = sorted(set(parameters) - set(by_name))
        if unknown:
            raise ArgumentError(f"unknown parameters {unknown}; the equations depend on "
                                f"{sorted(by_name)}.")
        point |= {by_name[k]: as_declared(by_name[k], v, "parameters")
                  for k, v in parameters.items()}
    if constrained:
        return _constrained(eqs, norm, about, velocities, w, w_star, point, check=check,
                            tol=tol, simplify=simplify, independent=independent)
    if independent is not None:
        raise ArgumentError("`independent` applies to equations with constraints only; "
                            "these have none.")
    variables = list(norm.q) + list(norm.u) + w
    f_values, jac = values_and_jacobian(list(norm.f), point, variables)
    M0 = sp.ImmutableMatrix(n, n, values_and_jacobian(list(norm.M), point, [])[0])
    leftover = set()
    for e in list(M0) + f_values:
        leftover |= e.free_symbols & (set(norm.q) | set(norm.u) | set(norm.a))
    if leftover:
        raise ArgumentError(f"the equations depend on {leftover} beyond q and q'.")
    about_named = dict(zip(norm.names, q_star, strict=True))
    vel_named = dict(zip(norm.names, u_star, strict=True))
    if check:
        rate = [sum((jac[i][j] * u_star[j] for j in range(n)), sp.S.Zero) for i in range(n)]
        ok, moving, residual, rate = _steady(f_values, rate, u_star, tol,
                                             [row[:n] for row in jac], q_star)
        if not ok:
            kind = "a steady motion" if moving else "an equilibrium"
            raise ArgumentError(
                f"`about` is not {kind} (q''* = 0 along q* + q'* t needs f = 0 and its rate "
                f"df/dt = 0 along the motion): f(q*, q'*) = {residual} and its rate "
                f"(df/dq) q'* = {rate} at q* = {about_named}, q'* = {vel_named} (tolerance "
                f"{tol} plus what the rounding of q* leaves). A rate is steady only on a "
                f"coordinate the equations do not depend on; find the equilibria with "
                f"rigidmech.vibrations.equilibria.")
        _check_mass(M0, about_named)
    if simplify is None:
        simplify = n <= 4
    post = sp.simplify if simplify else (lambda x: x)
    K = sp.ImmutableMatrix(n, n, lambda i, j: post(-jac[i][j]))
    C = sp.ImmutableMatrix(n, n, lambda i, j: post(-jac[i][n + j]))
    B = sp.ImmutableMatrix(n, len(w), lambda i, j: post(jac[i][2 * n + j]))
    M = M0.applyfunc(post)
    return LinearSystem(eqs.coordinates, about_named, vel_named, M, C, K, B, w)


def _constrained(eqs, norm, about, velocities, w, w_star, point, *, check, tol, simplify,
                 independent):
    from .constrained import linearize_constrained

    extra = {k: v for k, v in point.items() if k in set(eqs.parameters)}
    independent, M0, C, K, B, about_named, vel_named = linearize_constrained(
        eqs, about, velocities, w, w_star, extra, check=check, tol=tol,
        independent=independent, values_of=_values, normalise=lambda e: norm)
    if check:
        _check_mass(M0, about_named)
    k = M0.shape[0]
    if simplify is None:
        simplify = k <= 4
    post = sp.simplify if simplify else (lambda x: x)
    M, C, K, B = (sp.ImmutableMatrix(X).applyfunc(post) for X in (M0, C, K, B))
    return LinearSystem(independent, about_named, vel_named, M, C, K, B, w)


def _check_mass(M0, about):
    n = M0.shape[0]
    if all(x.is_number for x in M0):
        Mn = np.array(M0.tolist(), dtype=float)
        s = np.linalg.svd(Mn, compute_uv=False)
        singular = s[-1] <= 1e-12 * max(s[0], 1e-300)
    elif n <= 3:
        singular = is_identically_zero(M0.det())
    else:
        return
    if singular:
        raise SingularMassMatrixError(
            f"the mass matrix is singular at q* = {about}: M(q*) = {M0.tolist()}; the "
            "accelerations are not defined there (a degenerate configuration of the "
            "parameters of situation, such as a gimbal lock). Linearise about another state "
            "or choose other coordinates.")
