"""Steady motions with q' ≠ 0 and their stability (book, ch. 20, 25.4; Routh's method).

A steady motion keeps some parameters of situation constant (the *fixed* ones, q' = 0) while
others turn at constant rates (the *cyclic* ones, absent from M and f): a heavy top's steady
precession (θ fixed, ψ' and φ' constant), a disc rolling in a circle, a conical pendulum. Then
q'' = 0 and M q'' = f reduces to

.. math:: f(q^*, \\dot q^*) = 0,

algebraic equations in the fixed positions and the cyclic rates: given some of them,
:func:`steady_motions` solves for the others (symbolically, or numerically in a box). For
equations with constraints (rolling), f is the reduced forcing on the independent speeds
(:mod:`rigidmech.dynamics.reduced`), the dependent rates following the constraints.

Stability (:func:`steady_stability`): the equations are linearised about the motion
(:func:`~rigidmech.vibrations.linearize`), M δq'' + C δq' + K δq = 0. The positions of the cyclic
coordinates do not enter (their columns of K vanish); when their rows have no stiffness and no
damping of the cyclic rates (K_c = 0, C_cc = 0) each integrates to a constant "momentum"
M_c δq' + C_cs δq_s, and at its reference value (Routh: the other values lead to a
neighbouring steady motion) the cyclic rates follow the fixed coordinates,
δv_c = -M_cc⁻¹ (M_cs δq_s' + C_cs δq_s). What remains is

.. math:: M_r\\,\\delta\\ddot q_s + C_r\\,\\delta\\dot q_s + K_r\\,\\delta q_s = 0

on the fixed coordinates, decided as follows: C_r skew-symmetric (gyroscopic) and K_r symmetric
positive definite is 'stable' (Kelvin–Tait–Chetaev; it includes Lagrange–Dirichlet, C_r = 0);
an exponent with a positive real part is 'unstable'; all with negative real parts
'asymptotically stable'; a gyroscopic system whose exponents are distinct and on the imaginary
axis although K_r is not positive definite is 'linearly stable' (gyroscopic stabilisation, the
sleeping top: lost to any damping); anything else 'undecided'.
"""

from __future__ import annotations

import itertools

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError
from .._core.rules import vanishes
from .._core.symbolic import is_identically_zero
from ._numeric import state_matrix
from ._symbols import normalise
from .equilibria import _DEFINITE_TOL, _accepted
from .linearize import linearize
from .modes import is_symmetric

__all__ = ["SteadyMotion", "steady_motions", "steady_stability"]

#: Absolute tolerance on f(q*, q'*) where a root is not polished by the rule of
#: :func:`~rigidmech.vibrations.equilibria` (more equations than unknowns: a least-squares
#: root is a steady motion when every residual is within it, boundary included), and on the
#: dependence of f on a coordinate that is not fixed; the default of linearize's ``tol``.
_TOL = 1e-9


class SteadyMotion:
    """A steady motion: constant positions of the fixed coordinates, constant rates of the
    cyclic ones (ch. 20).

    Attributes
    ----------
    positions : dict
        Coordinate name -> ``q*`` (the cyclic coordinates at 0: they do not enter the equations).
    rates : dict
        Coordinate name -> ``q'*`` (zero for the fixed ones); with constraints, the independent
        rates (the dependent ones follow from the constraints).
    cyclic : tuple of str
        The names of the cyclic coordinates.

    Examples
    --------
    >>> s = SteadyMotion({"theta": 0.5, "phi": 0}, {"theta": 0, "phi": 2.0}, ("phi",))
    >>> s.rates["phi"], s
    (2.0, SteadyMotion(positions={'theta': 0.5, 'phi': 0}, rates={'theta': 0, 'phi': 2.0}))
    """

    __slots__ = ("positions", "rates", "cyclic")

    def __init__(self, positions, rates, cyclic):
        object.__setattr__(self, "positions", dict(positions))
        object.__setattr__(self, "rates", dict(rates))
        object.__setattr__(self, "cyclic", tuple(cyclic))

    def __setattr__(self, name, value):
        raise AttributeError(f"SteadyMotion is immutable: cannot set `{name}`.")

    def __repr__(self):
        return f"SteadyMotion(positions={self.positions}, rates={self.rates})"


def _form(eqs):
    """(names of all coordinates, q symbols, names of the speeds, speed symbols, f rows) with
    plain symbols: the equations themselves, or the reduced ones with constraints."""
    if eqs.constraints is not None and len(eqs.constraints) > 0:
        red = eqs.reduced()
        q, uI, _, _, _, fr = red.plain
        names = tuple(eqs.names)
        speed_names = tuple(_name(c) for c in red.independent)
        return names, tuple(q), speed_names, tuple(uI), list(fr)
    norm = normalise(eqs)
    return norm.names, norm.q, norm.names, norm.u, list(norm.f)


def _by_name(mapping, names, argument):
    out = {}
    for key, value in dict(mapping or {}).items():
        name = key if isinstance(key, str) else getattr(key, "name", None)
        if name is None and isinstance(key, sp.core.function.AppliedUndef):
            name = key.func.__name__
        if name not in names:
            raise ArgumentError(f"`{argument}` names an unknown coordinate {key!r}; the "
                                f"equations have {list(names)}.")
        out[name] = value
    return out


def _parse(eqs, fixed, cyclic):
    names, q, speed_names, u, f = _form(eqs)
    fixed = _by_name(fixed, names, "fixed")
    cyclic = _by_name(cyclic, names, "cyclic")
    both = sorted(set(fixed) & set(cyclic))
    if both:
        raise ArgumentError(f"{both} are both `fixed` and `cyclic`; a coordinate is one or "
                            "the other.")
    missing = [s for s in speed_names if s not in fixed and s not in cyclic]
    if missing:
        raise ArgumentError(
            f"every independent coordinate must be `fixed` (constant, with its position or "
            f"None for unknown) or `cyclic` (turning at a constant rate, or None); "
            f"{missing} are neither.")
    return names, q, speed_names, u, f, fixed, cyclic


def _param_values(f, q, u, params):
    free = set().union(*(sp.sympify(e).free_symbols for e in f)) - set(q) - set(u)
    by_name = {s.name: s for s in free}
    unknown = sorted(set(params) - set(by_name))
    if unknown:
        raise ArgumentError(f"unknown parameters {unknown}; the equations depend on "
                            f"{sorted(by_name)}.")
    return {by_name[k]: sp.sympify(v) for k, v in params.items()}


def steady_motions(eqs, *, fixed, cyclic, within=None, samples=None, xtol=1e-12,
                   **params) -> list:
    """The steady motions of ``eqs`` with the given fixed coordinates and cyclic rates:
    the solutions of ``f(q*, q'*) = 0`` for the unknowns (ch. 20, 25.4).

    Parameters
    ----------
    eqs : EquationsOfMotion
    fixed : dict
        Coordinate (q(t), symbol or name) -> its constant position, or None when unknown.
    cyclic : dict
        Coordinate -> its constant rate, or None when unknown. Every independent coordinate
        is fixed or cyclic; a cyclic coordinate must not enter the equations (checked at each
        solution: the rate of f along the motion vanishes).
    within : dict or (low, high), optional
        With numbers for the parameters: the box searched, one range per unknown by name (a
        pair for a single unknown). Without it and without parameter values, the unknowns are
        solved for symbolically.
    samples, xtol : as in :func:`~rigidmech.vibrations.equilibria`
    **params : values of the parameters

    Returns
    -------
    list of SteadyMotion
        Numerically, the roots found from a grid of the box: as many equations that do not
        vanish as unknowns, polished and accepted by the rule of
        :func:`~rigidmech.vibrations.equilibria`; more equations, a least-squares root kept
        when every residual is within 1e-9.

    Raises
    ------
    ArgumentError
        An unknown coordinate or parameter, a coordinate neither fixed nor cyclic, no
        unknown, a bad box, or equations sympy cannot solve.

    Examples
    --------
    The conical pendulum (polar angle θ, azimuth φ, length L): φ'² = g / (L cos θ).

    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion
    >>> th, ph, thd, phd = sp.symbols("theta phi theta_dot phi_dot")
    >>> m, g, L = sp.symbols("m g L", positive=True)
    >>> eqs = EquationsOfMotion(coordinates=(th, ph), q=(th, ph), u=(thd, phd),
    ...     mass_matrix=sp.diag(m * L**2, m * L**2 * sp.sin(th)**2),
    ...     forcing=sp.Matrix([m * L**2 * sp.sin(th) * sp.cos(th) * phd**2
    ...                        - m * g * L * sp.sin(th),
    ...                        -2 * m * L**2 * sp.sin(th) * sp.cos(th) * thd * phd]))
    >>> [s.rates["phi"] for s in steady_motions(eqs, fixed={th: sp.pi / 3},
    ...                                          cyclic={ph: None})]
    [-sqrt(2)*sqrt(g)/sqrt(L), sqrt(2)*sqrt(g)/sqrt(L)]
    >>> [round(s.positions["theta"], 9) for s in steady_motions(eqs, fixed={"theta": None},
    ...     cyclic={"phi": 4.0}, within=(0.1, 1.5), m=1, g=9.81, L=1)]
    [0.910786013]
    """
    names, q, speed_names, u, f, fixed, cyclic = _parse(eqs, fixed, cyclic)
    q_of = dict(zip(names, q, strict=True))
    u_of = dict(zip(speed_names, u, strict=True))
    unknowns = [(n, q_of[n]) for n in names if n in fixed and fixed[n] is None]
    unknowns += [(n, u_of[n]) for n in speed_names if n in cyclic and cyclic[n] is None]
    if not unknowns:
        raise ArgumentError("no unknown: give None for the position of a `fixed` coordinate "
                            "or the rate of a `cyclic` one to solve for it.")
    point = {q_of[n]: sp.sympify(v) for n, v in fixed.items() if v is not None}
    point |= {u_of[n]: 0 for n in fixed if n in u_of}
    point |= {u_of[n]: sp.sympify(v) for n, v in cyclic.items() if v is not None}
    point |= {q_of[n]: 0 for n in names if n not in fixed}
    values = _param_values(f, q, u, params)
    rows = [sp.sympify(e).xreplace(point).xreplace(values) for e in f]
    xs = [x for _, x in unknowns]
    if within is None and not params:
        found = _solve_symbolic(rows, xs)
    else:
        found = _solve_numeric(rows, xs, unknowns, within, samples, xtol)
    # the cyclic coordinates and, with constraints, the dependent ones (their positions
    # are set to 0): the equations must not depend on them
    moving = [q_of[n] for n in names if n not in fixed]
    out = []
    for sol in found:
        full = point | sol
        if not all(vanishes(sp.sympify(e).diff(c).xreplace(full).xreplace(values),
                                      _TOL) for e in f for c in moving):
            raise ArgumentError(
                f"the equations depend on the position of a coordinate that is not `fixed` "
                f"({[n for n in names if n not in fixed]}): a steady rate is possible only "
                "on a coordinate absent from them (cyclic); make it `fixed` instead.")
        numeric = within is not None or bool(params)
        positions = {n: _plain(full[q_of[n]], numeric) for n in names}
        rates = {n: _plain(full[u_of[n]], numeric) for n in speed_names}
        out.append(SteadyMotion(positions, rates, tuple(cyclic)))
    return out


def _plain(value, numeric):
    """A float for a number of a numeric search, the sympy value otherwise."""
    value = sp.sympify(value)
    return float(value) if numeric and value.is_number else value


def _solve_symbolic(rows, xs):
    rows = [sp.simplify(r) for r in rows]
    rows = [r for r in rows if not is_identically_zero(r)]
    if not rows:
        raise ArgumentError(f"f vanishes whatever {xs}: every value is a steady motion.")
    try:
        sols = sp.solve(rows, xs, dict=True)
    except NotImplementedError as exc:
        raise ArgumentError(
            f"sympy cannot solve f = 0 for the unknowns symbolically ({exc}); give values "
            "for the parameters and a box `within`.") from None
    return [s for s in sols if set(s) == set(xs)]


def _box(within, unknowns):
    if within is None:
        raise ArgumentError("a numeric search needs `within`: a range (low, high) per "
                            f"unknown {[n for n, _ in unknowns]}.")
    if not isinstance(within, dict):
        if len(unknowns) != 1:
            raise ArgumentError("`within` must be a dict {name: (low, high)} for several "
                                f"unknowns {[n for n, _ in unknowns]}; got {within!r}.")
        within = {unknowns[0][0]: within}
    box = []
    for name, _ in unknowns:
        b = within.get(name)
        if b is None or len(b) != 2 or not float(b[0]) < float(b[1]):
            raise ArgumentError(f"`within` must give a range (low, high), low < high, for "
                                f"`{name}`; got {b!r}.")
        box.append((float(b[0]), float(b[1])))
    return box


def _solve_numeric(rows, xs, unknowns, within, samples, xtol):
    """Every root in the box: scipy.optimize.root ('lm', which takes more equations than
    unknowns) from each point of a grid, polished and accepted by the rule of
    :func:`~rigidmech.vibrations.equilibria`, merged within 10 xtol."""
    import scipy.optimize  # imported on use (slow import)

    box = _box(within, unknowns)
    leftover = set().union(*(r.free_symbols for r in rows)) - set(xs)
    if leftover:
        raise ArgumentError(f"missing values for {sorted(map(str, leftover))}; pass them as "
                            "keywords (parameters) or in `fixed` / `cyclic`.")
    rows = [r for r in rows if r != 0]
    if len(rows) < len(xs):
        raise ArgumentError(
            f"{len(rows)} equation(s) that do not vanish for {len(xs)} unknowns "
            f"{[n for n, _ in unknowns]}: the steady motions form a family; give a value to "
            "some of the unknowns.")
    fun_ = sp.lambdify([xs], rows, modules="numpy")

    def fun(x):
        return np.asarray(fun_(list(x)), dtype=float).reshape(len(rows))

    axes = [np.linspace(a, b, samples or (41 if len(xs) == 1 else 9)) for a, b in box]
    points = []
    for start in itertools.product(*axes):
        sol = scipy.optimize.root(fun, np.array(start), tol=xtol * 1e-2,
                                  method="hybr" if len(rows) == len(xs) else "lm")
        x = sol.x
        if not all(a - xtol <= xi <= b + xtol for xi, (a, b) in zip(x, box, strict=True)):
            continue
        if len(rows) == len(xs):
            x, ok = _accepted(fun, x)
        else:
            ok = bool(np.all(np.abs(fun(x)) <= _TOL))
        if ok:
            points.append(x)
    merged = []
    for x in sorted(points, key=tuple):
        if not any(np.max(np.abs(x - y)) <= 10 * xtol for y in merged):
            merged.append(x)
    return [dict(zip(xs, map(float, x), strict=True)) for x in merged]


def _reduce_cyclic(M, C, K, c, tol):
    """Routh's reduction of the linear system on the fixed coordinates (module docstring), or
    None when the cyclic rows are not momenta (stiffness or damping of the cyclic rates)."""
    n = M.shape[0]
    s = [i for i in range(n) if i not in c]
    scale = max(float(np.max(np.abs(K), initial=0.0)), float(np.max(np.abs(C), initial=0.0)),
                float(np.max(np.abs(M), initial=0.0)), 1e-300)
    if c and (np.max(np.abs(K[c, :])) > tol * scale or np.max(np.abs(C[np.ix_(c, c)])) >
              tol * scale):
        return None
    if not c:
        return M, C, K, float(np.max(np.abs(K), initial=0.0))
    Mcc_inv = np.linalg.inv(M[np.ix_(c, c)])
    Msc, Mcs, Csc, Ccs = M[np.ix_(s, c)], M[np.ix_(c, s)], C[np.ix_(s, c)], C[np.ix_(c, s)]
    Mr = M[np.ix_(s, s)] - Msc @ Mcc_inv @ Mcs
    Cr = C[np.ix_(s, s)] - Msc @ Mcc_inv @ Ccs - Csc @ Mcc_inv @ Mcs
    gyro = Csc @ Mcc_inv @ Ccs
    Kr = K[np.ix_(s, s)] - gyro
    kscale = max(float(np.max(np.abs(K), initial=0.0)), float(np.max(np.abs(gyro))))
    return Mr, Cr, Kr, kscale


def _verdict(M, C, K, scale, tol):
    """The decision of the module docstring on M δq'' + C δq' + K δq = 0 (numbers);
    ``scale`` is the size of the stiffness terms before Routh's reduction (the reference of
    the tolerances on K, so that a K that vanishes by cancellation is told from zero)."""
    n = M.shape[0]
    if n == 0:
        return "stable"
    mscale = max(float(np.max(np.abs(M))), 1e-300)
    cscale = float(np.max(np.abs(C), initial=0.0))
    scale = max(scale, 1e-300)
    rate = np.sqrt(scale / mscale) + cscale / mscale     # the size of the exponents
    gyroscopic = (float(np.max(np.abs(C + C.T), initial=0.0))
                  <= _DEFINITE_TOL * np.sqrt(mscale * scale) and is_symmetric(K))
    if gyroscopic:
        k = np.linalg.eigvalsh((K + K.T) / 2)
        if np.min(k) > _DEFINITE_TOL * scale:
            return "stable"
        if abs(np.min(k)) <= _DEFINITE_TOL * scale:
            return "undecided"
    s = np.linalg.eigvals(state_matrix(M, C, K))
    if np.max(s.real) > tol * rate:
        return "unstable"
    if np.max(s.real) < -tol * rate:
        return "asymptotically stable"
    gaps = np.abs(s[:, None] - s[None, :]) + np.eye(s.size) * rate
    if gyroscopic and np.min(np.abs(s)) > tol * rate and np.min(gaps) > np.sqrt(tol) * rate:
        return "linearly stable"
    return "undecided"


def steady_stability(eqs, motion, *, tol=1e-9, **params) -> str:
    """Stability of a steady motion by its linearised equations, the cyclic coordinates
    eliminated by Routh's method (ch. 25.4; the decision of the module docstring).

    Parameters
    ----------
    eqs : EquationsOfMotion
    motion : SteadyMotion
        As returned by :func:`steady_motions` (with numbers).
    tol : float
        Relative tolerance on the real parts of the exponents (and on the vanishing of the
        cyclic rows' stiffness and damping).
    **params : values of the parameters

    Returns
    -------
    {'stable', 'asymptotically stable', 'linearly stable', 'unstable', 'undecided'}

    Examples
    --------
    The conical pendulum is stable (its θ oscillates about the cone):

    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion
    >>> th, ph, thd, phd = sp.symbols("theta phi theta_dot phi_dot")
    >>> eqs = EquationsOfMotion(coordinates=(th, ph), q=(th, ph), u=(thd, phd),
    ...     mass_matrix=sp.diag(1, sp.sin(th)**2),
    ...     forcing=sp.Matrix([sp.sin(th) * sp.cos(th) * phd**2 - sp.sin(th),
    ...                        -2 * sp.sin(th) * sp.cos(th) * thd * phd]))
    >>> motion, = steady_motions(eqs, fixed={"theta": 1.0}, cyclic={"phi": None},
    ...                          within=(0.0, 5.0))
    >>> steady_stability(eqs, motion)
    'stable'
    """
    if not isinstance(motion, SteadyMotion):
        raise ArgumentError(f"`motion` must be a SteadyMotion (from steady_motions); got "
                            f"{type(motion).__name__}.")
    lin = linearize(eqs, about=motion.positions, velocities=motion.rates, parameters=params or None,
                    simplify=False)
    M, C, K, _ = lin.numeric()
    coords = [_name(c) for c in lin.coordinates]
    c = [i for i, n in enumerate(coords) if n in motion.cyclic]
    reduced = _reduce_cyclic(M, C, K, c, tol)
    if reduced is not None:
        return _verdict(*reduced, tol)
    # the cyclic rates have stiffness or damping: decide on (δq_s, δq_s', δv_c)
    s_ = [i for i in range(len(coords)) if i not in c]
    Ks = K.copy()
    Ks[:, c] = 0.0
    A = state_matrix(M, C, Ks)
    keep = s_ + list(range(len(coords), 2 * len(coords)))
    ev = np.linalg.eigvals(A[np.ix_(keep, keep)])
    size = max(float(np.max(np.abs(ev))), 1e-300)
    if np.max(ev.real) > tol * size:
        return "unstable"
    if np.max(ev.real) < -tol * size:
        return "asymptotically stable"
    return "undecided"


def _name(coordinate) -> str:
    """The name of a coordinate q(t) or symbol."""
    if isinstance(coordinate, sp.core.function.AppliedUndef):
        return coordinate.func.__name__
    return str(coordinate)
