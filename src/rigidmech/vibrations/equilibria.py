"""Equilibria of equations of motion, their stability and their bifurcations (book, ch. 14,
20, 21.1, 25).

A position ``q*`` is an equilibrium when the system can stay there at rest: q' = q'' = 0 solves
M(q) q'' = f(q, q', t), that is ``f(q*, 0) = 0`` (with every input at its nominal value). In a
reference that turns at a prescribed rate (a bead on a rotating hoop) these are the relative
equilibria.

Where sympy solves f(q, 0) = 0 the equilibria are symbolic; otherwise, with numbers for the
parameters, they are found numerically in a given box:

- one degree of freedom: f is sampled on a grid of the range and every sign change is refined
  by ``scipy.optimize.brentq`` (all the roots where f changes sign, not one; a root where f
  touches zero without crossing is found only if it falls on a grid point);
- several: ``scipy.optimize.root`` started from every point of a grid of the box (``samples``
  per coordinate), keeping the converged roots inside the box, merged within ``xtol``. This
  finds the roots whose basin of attraction contains a grid point: refine the grid to be
  surer.

Stability: by the linearised equations (eigenvalues of A), and for conservative systems by the
potential energy (Lagrange–Dirichlet: a strict minimum of V is stable).
"""

from __future__ import annotations

import itertools

import numpy as np
import sympy as sp

from .._core.compile import compile_expressions
from .._core.errors import ArgumentError
from .._core.rules import vanishes
from .._core.validation import as_declared
from ._symbols import normalise
from .critical import growth
from .linearize import _ROUNDING, _values, linearize, rounding_allowance
from .modes import is_symmetric

__all__ = ["equilibria", "stability", "potential_stability", "Bifurcation", "bifurcation"]


def _params(norm, params, exclude=()):
    names = {p.name: p for p in norm.parameters}
    missing = sorted(set(names) - set(params) - set(exclude))
    unknown = sorted(set(params) - set(names))
    if missing:
        raise ArgumentError(
            f"missing values for parameters {missing}; pass them as keywords, e.g. "
            f"{', '.join(f'{m}=1.0' for m in missing)}.")
    if unknown:
        raise ArgumentError(f"unknown parameters {unknown}; the equations depend on "
                            f"{sorted(names)}.")
    for key, value in params.items():
        as_declared(names[key], value, "params")
    return names


def _static_forcing(norm):
    return [e.xreplace(dict.fromkeys(norm.u, 0)) for e in norm.f]


def _symbolic(norm):
    f = [sp.simplify(e) for e in _static_forcing(norm)]
    try:
        sols = sp.solve(f, list(norm.q), dict=True)
    except NotImplementedError as exc:
        raise ArgumentError(
            f"sympy cannot solve f(q, 0) = 0 symbolically ({exc}); give values for the "
            "parameters and a range `within` for a numeric search.") from None
    out = []
    for s in sols:
        if set(s) != set(norm.q):
            free = [norm.names[i] for i, q in enumerate(norm.q) if q not in s]
            out.append({name: s.get(q, sp.Symbol(name)) for name, q in
                        zip(norm.names, norm.q, strict=True)})
            out[-1]["free"] = free
            continue
        out.append({name: s[q] for name, q in zip(norm.names, norm.q, strict=True)})
    return out


def _box(within, n):
    if within is None:
        raise ArgumentError(
            "a numeric search needs `within`: a range (low, high) for 1 degree of freedom, "
            "or one per coordinate.")
    box = [within] if n == 1 and len(within) == 2 and np.ndim(within[0]) == 0 else list(within)
    if len(box) != n or any(len(b) != 2 or not float(b[0]) < float(b[1]) for b in box):
        raise ArgumentError(
            f"`within` must give {n} range(s) (low, high) with low < high; got {within!r}.")
    return [(float(a), float(b)) for a, b in box]


def _static_function(norm, syms):
    n = len(norm.q)
    return compile_expressions(sp.ImmutableMatrix(n, 1, _static_forcing(norm)),
                               [list(norm.q), *syms], name="static_forcing")


def _jacobian(fun, x):
    """Central differences (steps 1e-7 max(|x_j|, 1)): for the rounding allowance and the
    polishing Newton steps only."""
    n = x.size
    J = np.empty((n, n))
    for j in range(n):
        h = 1e-7 * max(abs(x[j]), 1.0)
        e = np.zeros(n)
        e[j] = h
        J[:, j] = (fun(x + e) - fun(x - e)) / (2 * h)
    return J


def _accepted(fun, x, tol=1e-9):
    """The root ``x`` polished by up to 3 Newton steps, and whether it is an equilibrium by
    the rule of :func:`~rigidmech.vibrations.linearize` (absolute ``tol`` plus the rounding
    allowance of x, taken at half its size so that a point accepted here is accepted there)."""
    x = np.asarray(x, dtype=float)
    r = fun(x)
    for _ in range(3):
        J = _jacobian(fun, x)
        allowance = _ROUNDING / 2 * (np.abs(J) @ np.maximum(np.abs(x), 1.0))
        if np.all(np.abs(r) <= allowance):
            break
        step = np.linalg.lstsq(J, -r, rcond=None)[0]
        y = x + step
        ry = fun(y)
        if not np.all(np.isfinite(ry)) or np.max(np.abs(ry)) >= np.max(np.abs(r)):
            break
        x, r = y, ry
    J = _jacobian(fun, x)
    allowance = _ROUNDING / 2 * (np.abs(J) @ np.maximum(np.abs(x), 1.0))
    return x, bool(np.all(np.abs(r) <= tol + allowance))


def _search(norm, f, values, within, samples, xtol):
    """All the roots of the compiled f(q, *values) in the box (the strategy of the module's
    docstring)."""
    import scipy.optimize  # imported on use (slow import)

    n = len(norm.q)
    box = _box(within, n)
    roots = []

    def fun(x):
        return np.asarray(f(np.asarray(x, dtype=float), *values), dtype=float).reshape(n)

    if n == 1:
        lo, hi = box[0]
        grid = np.linspace(lo, hi, samples or 2001)
        y = np.asarray(f(grid[None, :], *values), dtype=float).reshape(-1)
        scale = max(np.max(np.abs(y)), 1e-300)
        for k in range(grid.size - 1):
            if y[k] == 0 or abs(y[k]) <= 1e-14 * scale:
                roots.append(grid[k])
            elif y[k] * y[k + 1] < 0:
                roots.append(scipy.optimize.brentq(lambda x: fun([x])[0], grid[k],
                                                   grid[k + 1], xtol=xtol, rtol=1e-15))
        if y[-1] == 0 or abs(y[-1]) <= 1e-14 * scale:
            roots.append(grid[-1])
        points = []
        for r in roots:
            x, ok = _accepted(fun, np.array([r]))
            if ok:
                points.append(x)
    else:
        axes = [np.linspace(a, b, samples or 7) for a, b in box]
        points = []
        for start in itertools.product(*axes):
            sol = scipy.optimize.root(fun, np.array(start), method="hybr", tol=xtol * 1e-2)
            x = sol.x
            if not sol.success or not all(a - xtol <= xi <= b + xtol
                                          for xi, (a, b) in zip(x, box, strict=True)):
                continue
            x, ok = _accepted(fun, x)
            if ok:
                points.append(x)
    merged = []
    for x in sorted(points, key=lambda p: tuple(p)):
        if not any(np.max(np.abs(x - y)) <= 10 * xtol for y in merged):
            merged.append(x)
    return [{name: float(x[i]) for i, name in enumerate(norm.names)} for x in merged]


def _numeric(norm, params, within, samples, xtol):
    names = _params(norm, params)
    syms = [names[k] for k in sorted(names)]
    values = [float(params[k]) for k in sorted(names)]
    return _search(norm, _static_function(norm, syms), values, within, samples, xtol)


def equilibria(eqs, *, within=None, samples=None, xtol=1e-12, **params) -> list:
    """The equilibrium positions of ``eqs``: the solutions ``q*`` of ``f(q*, 0) = 0``
    (ch. 20, 25).

    Parameters
    ----------
    eqs : EquationsOfMotion
    within : (low, high) or sequence of them, optional
        The box searched numerically (one range per coordinate). Without it and without
        parameter values, the equilibria are solved for symbolically.
    samples : int, optional
        Grid points per coordinate (default 2001 for 1 dof, 7 per coordinate beyond).
    xtol : float
        Absolute tolerance on the positions (numeric search).
    **params
        Values of the parameters (numeric search).

    Returns
    -------
    list of dict
        Coordinate name -> position, one dict per equilibrium (increasing for 1 dof). A
        symbolic family that leaves a coordinate free lists it under the key ``"free"``.
        A numeric root is polished by Newton steps and kept only if it is an equilibrium by
        the rule of :func:`~rigidmech.vibrations.linearize` (its default tolerance), so that
        :func:`stability` accepts it.

    Raises
    ------
    ArgumentError
        Missing or unknown parameter values, a bad range, or a system sympy cannot solve
        (then pass numbers and ``within``).

    Examples
    --------
    A bead on a hoop of radius R turning at Ω about its vertical diameter:
    m R² θ'' = m R sin θ (R Ω² cos θ - g).

    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion, coordinates
    >>> th = coordinates("theta")
    >>> q, u = sp.symbols("theta theta_dot")
    >>> m, R, g, W = sp.symbols("m R g Omega", positive=True)
    >>> eqs = EquationsOfMotion(coordinates=(th,), q=(q,), u=(u,),
    ...     mass_matrix=sp.ImmutableMatrix([[m * R**2]]),
    ...     forcing=sp.ImmutableMatrix([[m * R * sp.sin(q) * (R * W**2 * sp.cos(q) - g)]]))
    >>> [e["theta"] for e in equilibria(eqs)]
    [0, pi, -acos(g/(Omega**2*R)) + 2*pi, acos(g/(Omega**2*R))]
    >>> [round(e["theta"], 9) for e in equilibria(eqs, within=(-3, 3), m=1, R=1, g=9.81,
    ...                                              Omega=2 * 9.81**0.5)]
    [-1.318116072, 0.0, 1.318116072]
    """
    norm = normalise(eqs)
    if within is None and not params:
        return _symbolic(norm)
    return _numeric(norm, params, within, samples, xtol)


def stability(eqs, at, *, tol=1e-9, **params) -> str:
    """Stability of the equilibrium ``at`` by the linearised equations (ch. 21.1, 25.4).

    The eigenvalues s of the linearised first-order system decide: all Re s < 0 is
    'asymptotically stable', one Re s > 0 'unstable'. When they lie on the imaginary axis
    (no damping) the linear test is inconclusive; for C = 0 and symmetric K it is the
    Lagrange–Dirichlet test on the quadratic potential δqᵀKδq/2: K positive definite is
    'stable', otherwise 'undecided'.

    Parameters
    ----------
    eqs : EquationsOfMotion
    at : dict or sequence
        The equilibrium (as returned by :func:`equilibria`).
    tol : float
        Relative tolerance on the real parts.
    **params : values of the parameters

    Returns
    -------
    {'asymptotically stable', 'stable', 'unstable', 'undecided'}

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion, coordinates
    >>> th = coordinates("theta"); q, u = sp.symbols("theta theta_dot")
    >>> eqs = EquationsOfMotion(coordinates=(th,), q=(q,), u=(u,),
    ...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-sp.sin(q)]]))
    >>> stability(eqs, [0]), stability(eqs, [sp.pi])
    ('stable', 'unstable')
    """
    at = {k: v for k, v in at.items() if k != "free"} if isinstance(at, dict) else at
    lin = linearize(eqs, at, parameters=params, simplify=False)
    M, C, K, _ = lin.numeric()
    return _classify(M, C, K, tol)


# Relative tolerance of the Lagrange-Dirichlet decision on a symmetric K (or Hessian of V):
# eigenvalues within 1e-12 of the largest one in magnitude are not told from zero. One rule for
# stability (C = 0, K symmetric) and potential_stability.
_DEFINITE_TOL = 1e-12


def _definiteness(k):
    """'stable' (positive definite), 'unstable' (a negative eigenvalue) or 'undecided', from
    the eigenvalues ``k`` of a symmetric stiffness, relative tolerance _DEFINITE_TOL."""
    scale = max(float(np.max(np.abs(k))), 1e-300)
    if np.min(k) > _DEFINITE_TOL * scale:
        return "stable"
    return "unstable" if np.min(k) < -_DEFINITE_TOL * scale else "undecided"


def _classify(M, C, K, tol=1e-9):
    """The verdict of :func:`stability` from numeric M, C, K.

    Conservative (C zero to _DEFINITE_TOL relative to sqrt(|M| |K|), K symmetric by the rule
    of :func:`~rigidmech.vibrations.modes.is_symmetric`): the Lagrange-Dirichlet rule on K,
    the one of
    :func:`potential_stability` (a negative eigenvalue of K is a real positive exponent:
    unstable). Otherwise the real parts of the exponents, relative tolerance ``tol``."""
    n = M.shape[0]
    Kscale = float(np.max(np.abs(K), initial=0.0))
    Cscale = float(np.max(np.abs(C), initial=0.0))
    Mscale = float(np.max(np.abs(M), initial=0.0))
    if Cscale <= _DEFINITE_TOL * np.sqrt(Mscale * Kscale) and is_symmetric(K):
        return _definiteness(np.linalg.eigvalsh((K + K.T) / 2))
    try:
        A = np.block([[np.zeros((n, n)), np.eye(n)],
                      [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    except np.linalg.LinAlgError:
        return "undecided"
    s = np.linalg.eigvals(A)
    scale = max(np.max(np.abs(s)), 1e-300)
    if growth(s, tol) > 0:   # the rule of critical_value
        return "unstable"
    if np.max(s.real) < -tol * scale:
        return "asymptotically stable"
    return "undecided"


def potential_stability(eqs, potential, at, *, tol=1e-9, **params) -> str:
    """Stability of an equilibrium of a conservative system by its potential energy V
    (Lagrange–Dirichlet, ch. 25.2.3): a strict minimum of V (Hessian positive definite) is
    stable; a Hessian with a negative eigenvalue (V not a minimum) unstable; otherwise
    'undecided' (higher-order terms decide).

    Parameters
    ----------
    eqs : EquationsOfMotion
        Gives the coordinates (V may use q(t) or the equations' symbols).
    potential : sympy expression
    at : dict or sequence
        The position.
    tol : float
        Absolute tolerance on each numeric dV/dq at ``at`` (plus the rounding allowance of
        ``at``), the rule of :func:`~rigidmech.vibrations.linearize` on the residual
        f = -dV/dq; the Hessian's eigenvalues are decided to 1e-12 relative to the largest
        one, as in :func:`stability`.
    **params : values of the parameters (optional; symbolic otherwise, when sympy decides
        the signs)

    Raises
    ------
    ArgumentError
        If ``at`` is not a stationary point of V (dV/dq ≠ 0), or the signs are undecidable.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion, coordinates
    >>> th = coordinates("theta"); q, u = sp.symbols("theta theta_dot")
    >>> m, g, L = sp.symbols("m g L", positive=True)
    >>> eqs = EquationsOfMotion(coordinates=(th,), q=(q,), u=(u,),
    ...     mass_matrix=sp.ImmutableMatrix([[m * L**2]]),
    ...     forcing=sp.ImmutableMatrix([[-m * g * L * sp.sin(q)]]))
    >>> V = -m * g * L * sp.cos(th)
    >>> potential_stability(eqs, V, [0]), potential_stability(eqs, V, [sp.pi])
    ('stable', 'unstable')
    """
    norm = normalise(eqs)
    V = norm.to_plain(potential)
    at = {k: v for k, v in at.items() if k != "free"} if isinstance(at, dict) else at
    lin_point = _values(at, norm, "at")
    point = dict(zip(norm.q, lin_point, strict=True))
    subs = {}
    if params:
        names = {p.name: p for p in (V.free_symbols - set(norm.q))}
        subs = {names[k]: as_declared(names[k], v, "params") for k, v in params.items()
                if k in names}
    grad = [sp.simplify(V.diff(q).xreplace(point).xreplace(subs)) for q in norm.q]
    H = sp.Matrix(len(norm.q), len(norm.q),
                  lambda i, j: sp.simplify(V.diff(norm.q[i], norm.q[j]).xreplace(point)
                                           .xreplace(subs)))
    if not all(vanishes(x, tol, rounding_allowance(H.row(i), lin_point))
               for i, x in enumerate(grad)):
        raise ArgumentError(f"`at` is not a stationary point of the potential: dV/dq = {grad} "
                            f"(tolerance {tol}).")
    if all(x.is_number for x in H):
        return _definiteness(np.linalg.eigvalsh(np.array(H.tolist(), dtype=float)))
    minors = [sp.simplify(H[:r, :r].det()) for r in range(1, H.shape[0] + 1)]
    if all(m.is_positive for m in minors):
        return "stable"
    if H.shape[0] == 1 and minors[0].is_negative:
        return "unstable"
    if any(H[i, i].is_negative for i in range(H.shape[0])):
        return "unstable"
    raise ArgumentError(
        f"the sign of the Hessian of V at `at` is undecided symbolically (leading minors "
        f"{minors}); give values for the parameters.")


class Bifurcation:
    """Equilibria and their stability along a range of a parameter: data to plot.

    Attributes
    ----------
    parameter : str
    values : ndarray (m,)
    equilibria : list of lists of dict
        For each parameter value, its equilibria.
    stabilities : list of lists of str
        For each parameter value, the stability of each equilibrium (:func:`stability`).

    Examples
    --------
    >>> b = Bifurcation("p", [0.0], [[{"x": 0.0}]], [["stable"]])
    >>> b.points("x")
    (array([0.]), array([0.]), array([ True]))
    """

    __slots__ = ("parameter", "values", "equilibria", "stabilities")

    def __init__(self, parameter, values, equilibria_, stabilities):
        self.parameter = parameter
        self.values = np.asarray(values, dtype=float)
        self.equilibria = equilibria_
        self.stabilities = stabilities

    def __setattr__(self, name, value):
        if hasattr(self, name):
            raise AttributeError(f"Bifurcation is immutable: cannot set `{name}`.")
        object.__setattr__(self, name, value)

    def points(self, coordinate):
        """Flat arrays (parameter value, position of ``coordinate``, stable?) for a scatter
        plot; 'stable' and 'asymptotically stable' count as stable."""
        p, x, s = [], [], []
        for v, eqs_, stab in zip(self.values, self.equilibria, self.stabilities, strict=True):
            for e, st in zip(eqs_, stab, strict=True):
                p.append(v)
                x.append(e[coordinate])
                s.append(st in ("stable", "asymptotically stable"))
        return np.array(p), np.array(x), np.array(s, dtype=bool)

    def plot(self, coordinate, *, ax=None, path=None):
        """Bifurcation diagram: stable equilibria filled, others hollow. Returns the Axes."""
        if ax is None:
            from matplotlib.figure import Figure  # imported on use (slow import)

            ax = Figure(figsize=(7, 4)).subplots()
        p, x, s = self.points(coordinate)
        ax.plot(p[s], x[s], "o", ms=3, label="stable")
        ax.plot(p[~s], x[~s], "o", ms=3, mfc="none", label="unstable or undecided")
        ax.set_xlabel(self.parameter)
        ax.set_ylabel(coordinate)
        ax.legend()
        ax.grid(True, alpha=0.3)
        if path is not None:
            ax.figure.tight_layout()
            ax.figure.savefig(path, dpi=100)
        return ax

    def __repr__(self):
        return (f"Bifurcation(parameter={self.parameter!r}, values={self.values.size}, "
                f"equilibria={sum(len(e) for e in self.equilibria)})")


def bifurcation(eqs, parameter, values, *, within, samples=None, **params) -> Bifurcation:
    """Equilibria and their stability for each value of ``parameter`` (ch. 25): the data of
    a bifurcation diagram (:meth:`Bifurcation.plot`).

    Parameters
    ----------
    eqs : EquationsOfMotion
    parameter : str or Symbol
        The parameter that varies.
    values : array of its values
    within, samples : as in :func:`equilibria`
    **params : values of the other parameters

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion, coordinates
    >>> th = coordinates("theta"); q, u = sp.symbols("theta theta_dot")
    >>> W = sp.Symbol("Omega", positive=True)
    >>> eqs = EquationsOfMotion(coordinates=(th,), q=(q,), u=(u,),
    ...     mass_matrix=sp.ImmutableMatrix([[1]]),
    ...     forcing=sp.ImmutableMatrix([[sp.sin(q) * (W**2 * sp.cos(q) - 1)]]))
    >>> b = bifurcation(eqs, "Omega", [0.5, 2.0], within=(-1.5, 1.5))
    >>> [len(e) for e in b.equilibria], b.stabilities[1]
    ([1, 3], ['stable', 'unstable', 'stable'])
    """
    name = parameter.name if isinstance(parameter, sp.Symbol) else str(parameter)
    norm = normalise(eqs)
    names = _params(norm, params, exclude=(name,))
    if name not in names:
        raise ArgumentError(f"`parameter` must be one of {sorted(names)}; got {parameter!r}.")
    syms = [names[k] for k in sorted(names)]
    # compiled once: f(q, 0) and the matrices of the linearised equations at (q, 0)
    f = _static_function(norm, syms)
    n = len(norm.q)
    at_rest = dict.fromkeys(norm.u, 0)
    f_rest = sp.Matrix(_static_forcing(norm))
    K = -f_rest.jacobian(list(norm.q))
    C = -sp.Matrix(list(norm.f)).jacobian(list(norm.u)).xreplace(at_rest)
    M = norm.M
    matrices = compile_expressions((sp.ImmutableMatrix(M), sp.ImmutableMatrix(C),
                                    sp.ImmutableMatrix(K)), [list(norm.q), *syms],
                                   name="linearised")
    found, stab = [], []
    for v in np.asarray(values, dtype=float):
        p = dict(params, **{name: float(v)})
        vals = [float(p[k]) for k in sorted(names)]
        e = _search(norm, f, vals, within, samples, 1e-12)
        found.append(e)
        verdicts = []
        for x in e:
            Mn, Cn, Kn = (np.asarray(X, dtype=float).reshape(n, n) for X in
                          matrices(np.array([x[k] for k in norm.names]), *vals))
            verdicts.append(_classify(Mn, Cn, Kn))
        stab.append(verdicts)
    return Bifurcation(name, values, found, stab)

