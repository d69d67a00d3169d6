"""Inverse dynamics: the generalised forces that produce a prescribed motion (book, ch. 20.2,
25.3).

With the motion q(t) prescribed, the equations of motion M(q) q'' = f(q, q', t) + Q give the
generalised forces Q (actuator torques, driving forces, in the power coefficients of the
coordinates, ch. 25.1.3) that must be added to the given actions:

.. math:: Q(t) = M(q(t))\\,\\ddot q(t) - f(q(t), \\dot q(t), t).

When only some coordinates are prescribed (the driven joints), the others move freely: their
rows of the equations, M_ff q_f'' = f_f - M_fp q_p''(t), are a differential equation for them;
Q on the prescribed rows then depends on the free coordinates' motion. Symbolically it is
written with them (q_f(t) and its derivatives); numerically the free coordinates are integrated
from their initial state (``scipy.integrate.solve_ivp``, DOP853) and Q is evaluated along.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..vectors import t as _t
from .equations import EquationsOfMotion

__all__ = ["inverse_dynamics"]


def _names(eqs):
    return tuple(eqs.names)


def _index(eqs, key):
    names = _names(eqs)
    for i, (c, name) in enumerate(zip(eqs.coordinates, names, strict=True)):
        if key is c or key == name or key == c or getattr(key, "name", None) == name:
            return i
        if isinstance(key, sp.core.function.AppliedUndef) and key.func.__name__ == name:
            return i
    raise ArgumentError(f"`prescribed` names an unknown coordinate {key!r}; the equations have "
                        f"{list(names)}.")


def _symbolic_forces(eqs, prescribed):
    """Q on every row, the prescribed coordinates replaced by their expressions of t, the free
    ones written as functions of t (the user's coordinates, or f(t) for plain symbols)."""
    q_s, u_s, _, rule, M, f = eqs._symbolic()
    n = len(q_s)
    names = _names(eqs)
    motion = []
    for i in range(n):
        if i in prescribed:
            expr = sp.sympify(prescribed[i])
            motion.append(expr)
        else:
            c = eqs.coordinates[i]
            motion.append(c if c.has(_t) else sp.Function(names[i])(_t))
    point = {}
    for i in range(n):
        point[q_s[i]] = motion[i]
        point[u_s[i]] = motion[i].diff(_t)
    acc = sp.Matrix([motion[i].diff(_t, 2) for i in range(n)])
    Q = M.xreplace(point) * acc - f.xreplace(point)
    back = {v: k for k, v in rule.items() if k in set(eqs.inputs)}
    return sp.ImmutableMatrix(Q.xreplace(back)), motion


def inverse_dynamics(eqs, prescribed, *, times=None, free_initial=None, simplify=True,
                     rtol=1e-10, atol=1e-12, **params):
    """The generalised forces that give the prescribed motion (ch. 20.2, 25.3).

    Parameters
    ----------
    eqs : EquationsOfMotion
        Without constraints (reduce them first: ``eqs.reduced()``).
    prescribed : dict
        Coordinate (q(t), symbol or name) -> its motion, an expression of ``rigidmech.t``.
        Every coordinate, or some (the driven ones): the others move freely.
    times : array, optional
        Times at which to evaluate the forces numerically (then give the parameters'
        values as keywords). Without it the forces are returned symbolically.
    free_initial : dict, optional
        Numeric evaluation with free coordinates: coordinate -> (q0, q'0) at ``times[0]``.
    simplify : bool
        Simplify the symbolic forces (``sympy.simplify``, entry by entry).
    rtol, atol : float
        Tolerances of the integration of the free coordinates.
    **params
        Values of the parameters (numeric evaluation).

    Returns
    -------
    sympy.ImmutableMatrix (k, 1) or ndarray (k, len(times))
        The generalised forces on the k prescribed coordinates, in the order of the
        equations' coordinates (the ones on the free coordinates are zero by construction).

    Raises
    ------
    ArgumentError
        An unknown coordinate or parameter, a prescription that is not an expression of t,
        equations with constraints, a missing initial state of a free coordinate.

    Examples
    --------
    A pendulum driven at the constant rate ω needs τ = m g L sin(ω t):

    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> from rigidmech import EquationsOfMotion
    >>> th = rm.coordinates("theta"); m, g, L, w = sp.symbols("m g L omega", positive=True)
    >>> eqs = EquationsOfMotion(coordinates=(th,), mass_matrix=sp.Matrix([[m * L**2]]),
    ...                         forcing=sp.Matrix([[-m * g * L * sp.sin(th)]]))
    >>> inverse_dynamics(eqs, {th: w * rm.t})
    Matrix([[L*g*m*sin(omega*t)]])
    >>> inverse_dynamics(eqs, {"theta": 2 * rm.t}, times=[0.25], m=1, g=9.81, L=1).round(6)
    array([[4.703165]])
    """
    if not isinstance(eqs, EquationsOfMotion):
        raise ArgumentTypeError(f"`eqs` must be an EquationsOfMotion; got "
                                f"{type(eqs).__name__}.")
    if eqs.constraints is not None and len(eqs.constraints) > 0:
        raise ArgumentError("`eqs` has constraints: prescribe the motion on the reduced "
                            "equations (eqs.reduced()) or on a system without them.")
    if not isinstance(prescribed, dict) or not prescribed:
        raise ArgumentError(f"`prescribed` must be a non-empty dict coordinate -> expression "
                            f"of t; got {prescribed!r}.")
    by_index = {}
    for key, expr in prescribed.items():
        expr = sp.sympify(expr)
        extra = expr.free_symbols - {_t} - set(eqs.parameters)
        if any(c in expr.atoms(sp.Function) for c in eqs.coordinates) or extra & set(eqs.q):
            raise ArgumentError(f"`prescribed` must give expressions of t; got {expr} for "
                                f"{key!r}.")
        by_index[_index(eqs, key)] = expr
    Q, motion = _symbolic_forces(eqs, by_index)
    rows = sorted(by_index)
    if times is None:
        out = [Q[i] for i in rows]
        return sp.ImmutableMatrix(len(rows), 1, [sp.simplify(e) if simplify else e
                                                 for e in out])
    return _numeric(eqs, Q, motion, by_index, np.asarray(times, dtype=float), free_initial,
                    rtol, atol, params)


def _values(eqs, params):
    by_name = {p.name: p for p in eqs.parameters}
    by_name |= {getattr(w, "name", None) or w.func.__name__: w for w in eqs.inputs}
    unknown = sorted(set(params) - set(by_name))
    if unknown:
        raise ArgumentError(f"unknown parameters {unknown}; the equations depend on "
                            f"{sorted(by_name)}.")
    missing = sorted(set(by_name) - set(params))
    if missing:
        raise ArgumentError(f"missing values for parameters {missing}; pass them as "
                            f"keywords, e.g. {', '.join(f'{m}=1.0' for m in missing)}.")
    return {by_name[k]: sp.Float(v) for k, v in params.items()}


def _numeric(eqs, Q, motion, prescribed, times, free_initial, rtol, atol, params):
    values = _values(eqs, params)
    n = len(motion)
    rows = sorted(prescribed)
    free = [i for i in range(n) if i not in prescribed]
    Q = Q.xreplace(values)
    if not free:
        fun = sp.lambdify(_t, list(Q[i] for i in rows), modules="numpy")
        return np.array([np.broadcast_to(np.asarray(v, dtype=float), times.shape)
                         for v in fun(times)])
    import scipy.integrate  # imported on use (slow import)

    free_initial = {_index(eqs, k): v for k, v in dict(free_initial or {}).items()}
    lacking = [eqs.names[i] for i in free if i not in free_initial]
    if lacking:
        raise ArgumentError(f"`free_initial` must give (q0, q'0) of the free coordinates "
                            f"{lacking} at times[0].")
    # the free coordinates as plain symbols: the rows of Q on them vanish (no actuator)
    qf = [sp.Dummy(f"q{i}") for i in free]
    uf = [sp.Dummy(f"u{i}") for i in free]
    af = [sp.Dummy(f"a{i}") for i in free]
    rule = {}
    for k, i in enumerate(free):
        m = motion[i]
        rule[m.diff(_t, 2)] = af[k]
        rule[m.diff(_t)] = uf[k]
        rule[m] = qf[k]
    Qp = sp.Matrix(n, 1, [e.subs(rule) for e in Q])
    Mff = Qp.extract(free, [0]).jacobian(af)
    rest = Qp.extract(free, [0]).xreplace(dict.fromkeys(af, 0))
    acc = sp.lambdify((_t, qf, uf), [list(Mff), list(rest)], modules="numpy")
    k = len(free)

    def rhs(time, y):
        Mv, rv = acc(time, list(y[:k]), list(y[k:]))
        a = np.linalg.solve(np.asarray(Mv, dtype=float).reshape(k, k),
                            -np.asarray(rv, dtype=float).reshape(k))
        return np.concatenate((y[k:], a))

    y0 = [float(free_initial[i][0]) for i in free] + [float(free_initial[i][1]) for i in free]
    sol = scipy.integrate.solve_ivp(rhs, (times[0], times[-1]), y0, method="DOP853",
                                    t_eval=times, rtol=rtol, atol=atol)
    if not sol.success:
        raise ArgumentError(f"the free coordinates could not be integrated: {sol.message}")
    forces = sp.lambdify((_t, qf, uf, af), [Qp[i] for i in rows], modules="numpy")
    out = np.empty((len(rows), times.size))
    for j, time in enumerate(times):
        y = sol.y[:, j]
        a = rhs(time, y)[k:]
        out[:, j] = np.asarray(forces(time, list(y[:k]), list(y[k:]), list(a)), dtype=float)
    return out
