"""Assembly of a mechanism with linked parameters: a configuration on the constraints (book,
ch. 13.2, 25.3).

Given values of the independent parameters, the dependent ones solve the holonomic closure
conditions Φ(q) = 0 (Newton's method on the dependent parameters, with the Jacobian Φ_q of
:class:`~rigidmech.dynamics.Constraints`), and the dependent rates solve the velocity
conditions A q' + a = 0 (linear). The independent parameters are the user's, or chosen by
QR factorisation with column pivoting of the Jacobian: its first pivot columns, the best
conditioned, become the dependent ones.

Time: constraints that depend on it explicitly (a driven joint, a pin moving with t) are
assembled at the time ``t`` given; without ``t`` they are refused rather than assembled at an
arbitrary instant. Constraints that do not depend on it need no ``t``.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.compile import compile_expressions
from .._core.errors import ArgumentError, ConnectionError_
from .._core.lazy import lazy_package
from .._core.rules import ON_CONSTRAINTS, magnitude, numeric_rank, on_constraints, rates_for_scale
from ..vectors import t as _t

scipy = lazy_package("scipy")  # lazy: import cost of scipy.linalg (see docs/performance)

__all__ = ["assemble", "Closure", "ON_CONSTRAINTS"]


def _name(q):
    return q.func.__name__


def _by_name(values, coordinates, argument):
    names = [_name(q) for q in coordinates]
    out = {}
    for key, v in (values or {}).items():
        name = key if isinstance(key, str) else (
            _name(key) if hasattr(key, "func") else str(key))
        if name not in names:
            raise ArgumentError(
                f"`{argument}`: {key} is not a coordinate of the system; expected some of "
                f"{names}.")
        out[name] = float(v)
    return out


# A state is on the constraints when every residual Φ(q, t) and A q' + a is at most
# ON_CONSTRAINTS of the magnitude of its terms (the rule of rigidmech._core.rules): what
# assemble reaches, what simulate uses as given and what multipliers requires.


class Closure:
    """The constraints compiled once: ``evaluate(q, t, constants)`` gives the holonomic
    residuals Φ(q, t), the Jacobian A(q, t) and a(q, t) (so that A q' + a = 0); ``timed``
    says whether they depend on the time explicitly.

    Examples
    --------
    >>> import numpy as np
    >>> import rigidmech as rm
    >>> from rigidmech.dynamics import Constraints
    >>> x, y = rm.coordinates("x y")
    >>> phi = x**2 + y**2 - 1
    >>> c = Closure(Constraints((x, y), [("circle", phi.diff(rm.t), phi)]))
    >>> r, J, a = c.evaluate(np.array([0.6, 0.8]), 0.0, [])
    >>> np.round(r, 12).tolist(), J.tolist(), c.timed
    ([0.0], [[1.2, 1.6]], False)
    """

    def __init__(self, constraints):
        coords = constraints.coordinates
        self.names = [_name(q) for q in coords]
        self.n, self.m = len(coords), len(constraints.labels)
        self.labels = constraints.labels
        q_s = [sp.Dummy(nm, real=True) for nm in self.names]
        u_s = [sp.Dummy(nm + "_dot", real=True) for nm in self.names]
        rule = {}
        for qq, qs, us in zip(coords, q_s, u_s, strict=True):
            rule[qq.diff(_t)] = us
            rule[qq] = qs
        self.holo = [i for i, p in enumerate(constraints.position) if p is not None]
        phi = [constraints.position[i].xreplace(rule) for i in self.holo]
        A = constraints.jacobian.xreplace(rule)
        a = [c.xreplace(rule).xreplace(dict.fromkeys(u_s, 0)) for c in constraints.velocity]
        exprs = [*phi, *list(A), *a]
        self.timed = any(_t in sp.sympify(e).free_symbols for e in exprs)
        self.consts = sorted(set().union(*(sp.sympify(e).free_symbols for e in exprs))
                             - set(q_s) - set(u_s) - {_t}, key=lambda s: s.name)
        self._f = compile_expressions(
            (sp.Matrix(len(phi), 1, phi), sp.Matrix(A), sp.Matrix(a)),
            [_t, q_s, *self.consts], name="closure")
        # the magnitudes of the terms of Φ and of a: the scales of the rule on_constraints
        vel = [c.xreplace(rule) for c in constraints.velocity]
        self._scales = compile_expressions(
            (sp.Matrix(len(phi), 1, [magnitude(e) for e in phi]),
             sp.Matrix(len(vel), 1, [magnitude(e) for e in vel])),
            [_t, q_s, u_s, *self.consts], name="closure_scales")

    def constants(self, params):
        """The values of the constants, in order, from ``params`` by name."""
        missing = [c.name for c in self.consts if c.name not in params]
        if missing:
            raise ArgumentError(
                f"give the values of the constants {missing} (keyword arguments).")
        return [float(params[c.name]) for c in self.consts]

    def evaluate(self, q, t, cvals):
        """(Φ, A, a) at (q, t) as float arrays."""
        r, J, a0 = self._f(t, q, *cvals)
        return (np.asarray(r, float).reshape(-1), np.asarray(J, float).reshape(self.m, self.n),
                np.asarray(a0, float).reshape(-1))

    def scales(self, q, u, t, cvals, J=None):
        """The magnitudes of the terms of Φ(q, t) and of A q' + a, the latter with every rate
        at the largest |q'_j| (:func:`~rigidmech._core.rules.rates_for_scale`): the scales of
        the rule :func:`~rigidmech._core.rules.on_constraints`."""
        sq, su = self._scales(t, q, rates_for_scale(u), *cvals)
        return np.asarray(sq, float).reshape(-1), np.asarray(su, float).reshape(-1)

    def off(self, q, u, t, cvals):
        """Labels and residuals of the conditions (q, u) violates at t by the rule
        :func:`~rigidmech._core.rules.on_constraints` (more than ON_CONSTRAINTS of the
        magnitude of their terms): the holonomic ones, then the velocity ones."""
        r, J, a0 = self.evaluate(q, t, cvals)
        sq, su = self.scales(q, u, t, cvals, J)
        v = J @ u + a0
        out = [(self.labels[i], float(x)) for i, x, ok
               in zip(self.holo, r, on_constraints(r, sq), strict=True) if not ok]
        out += [(f"{self.labels[i]} (rate)", float(x)) for i, (x, ok)
                in enumerate(zip(v, on_constraints(v, su), strict=True)) if not ok]
        return out


def explicit_time(exprs, coordinates, inputs=()) -> bool:
    """Whether ``exprs`` depend on the time t explicitly: other than through the coordinates
    q(t) and their derivatives, and the ``inputs`` F(t) (whose values decide for them); any
    other function of time counts as explicit.

    Examples
    --------
    >>> import rigidmech as rm
    >>> x = rm.coordinates("x")
    >>> explicit_time([x.diff(rm.t) * x], [x]), explicit_time([x - rm.t], [x])
    (False, True)
    """
    rule = {}
    for q in coordinates:
        rule[q.diff(_t, 2)] = sp.Dummy()
        rule[q.diff(_t)] = sp.Dummy()
        rule[q] = sp.Dummy()
    for w in inputs:
        rule[w] = sp.Dummy()
    for e in exprs:
        e = sp.sympify(e)
        if isinstance(e, sp.MatrixBase):
            if any(_t in x.xreplace(rule).free_symbols for x in e):
                return True
        elif _t in e.xreplace(rule).free_symbols:
            return True
    return False


def time_of(t, depends, what):
    """The time to evaluate at: ``t`` as a float, or 0.0 when it is None and nothing depends
    on it; refused when ``depends`` and no t is given (one rule for assemble and the
    multipliers)."""
    if t is None:
        if depends:
            raise ArgumentError(
                f"`t` must be given: {what} depend on the time explicitly (a driven joint, a "
                "moving support), so the result depends on the instant; got t=None. Pass "
                "t=<the time of the state>.")
        return 0.0
    try:
        t = float(t)
    except (TypeError, ValueError):
        raise ArgumentError(f"`t` must be a real number; got {t!r}.") from None
    if not np.isfinite(t):
        raise ArgumentError(f"`t` must be finite; got {t}.")
    return t


def assemble(constraints, values, *, independent=None, rates=None, params=None, t=None,
             tol: float = 1e-12, max_iterations: int = 50):
    """(q0, u0) by name satisfying ``constraints`` (see the module notes) at the time ``t``.

    ``t`` is needed (and only then used) when the constraints depend on the time explicitly.

    Raises
    ------
    ConnectionError\\_
        If Newton's method does not reach the constraints (a loop with no solution near the
        given values: the message names the conditions left unsatisfied), or if the
        constraints do not determine the dependent rates at the configuration (the Jacobian
        on the dependent parameters has a lower rank than their number: choose other
        independent parameters).
    ArgumentError
        For an unknown coordinate, a missing constant, or constraints depending on the time
        without ``t``.

    Examples
    --------
    A particle on the unit circle: given x, y follows.

    >>> import rigidmech as rm
    >>> from rigidmech.dynamics import Constraints
    >>> x, y = rm.coordinates("x y")
    >>> phi = x**2 + y**2 - 1
    >>> c = Constraints((x, y), [("circle", phi.diff(rm.t), phi)])
    >>> q0, u0 = assemble(c, {"x": 0.6, "y": 1.0}, independent=["x"], rates={"x": 1.0})
    >>> round(q0["y"], 12), round(u0["y"], 12)
    (0.8, -0.75)
    """
    closure = Closure(constraints)
    names, n, m, holo = closure.names, closure.n, closure.m, closure.holo
    coords = constraints.coordinates
    q = np.zeros(n)
    for name, v in _by_name(values, coords, "values").items():
        q[names.index(name)] = v
    time = time_of(t, closure.timed, "the constraints")
    cvals = closure.constants(params or {})

    def evaluate(qv):
        return closure.evaluate(qv, time, cvals)

    _, J, _ = evaluate(q)
    rank = numeric_rank(J) if m else 0
    if independent is None:
        _, _, piv = scipy.linalg.qr(J, pivoting=True)
        dependent = sorted(piv[:rank].tolist())
    else:
        chosen = {(_name(x) if hasattr(x, "func") else str(x)) for x in independent}
        unknown = chosen - set(names)
        if unknown:
            raise ArgumentError(
                f"`independent`: {sorted(unknown)} are not coordinates; expected some of "
                f"{names}.")
        dependent = [i for i, nm in enumerate(names) if nm not in chosen]
    # Newton on the holonomic rows for the dependent parameters
    zero_u = np.zeros(n)
    for _ in range(max_iterations):  # until |Φ| < tol of the magnitude of its terms
        r, J, _ = evaluate(q)
        if not len(r) or np.all(np.abs(r) < tol * closure.scales(q, zero_u, time, cvals, J)[0]):
            break
        step, *_ = np.linalg.lstsq(J[holo][:, dependent], -r, rcond=None)
        q[dependent] += step
    r, J, a0 = evaluate(q)
    held = on_constraints(r, closure.scales(q, zero_u, time, cvals, J)[0])
    if len(r) and not np.all(held):
        bad = [constraints.labels[i] for i, ok in zip(holo, held, strict=True) if not ok]
        raise ConnectionError_(
            f"the loop cannot be closed near the given values: the closure conditions "
            f"{bad} keep residuals {np.abs(r).max():.3g} after {max_iterations} Newton steps "
            f"on the dependent parameters {[names[i] for i in dependent]}. Check the lengths "
            "(the loop may have no solution) or give values closer to an assembled position.")
    u = np.zeros(n)
    for name, v in _by_name(rates, coords, "rates").items():
        u[names.index(name)] = v
    free = [i for i in range(n) if i not in dependent]
    JD = J[:, dependent]
    # the rank rule of the choice of the dependent set above (rigidmech._core.rules)
    if dependent and numeric_rank(JD) < len(dependent):
        raise ConnectionError_(
            f"the dependent rates {[names[i] for i in dependent]} are not determined by the "
            f"constraints at this configuration (their Jacobian has rank "
            f"{numeric_rank(JD)} < {len(dependent)}; a singular position for this "
            f"choice): choose other independent parameters than "
            f"{[names[i] for i in free]}, or leave `independent` to the default.")
    rhs = -(a0 + J[:, free] @ u[free])
    sol, *_ = np.linalg.lstsq(JD, rhs, rcond=None)
    u[dependent] = sol
    if m and not np.all(on_constraints(J @ u + a0, closure.scales(q, u, time, cvals, J)[1])):
        raise ConnectionError_(
            "the velocity conditions cannot all be satisfied with the given independent rates: "
            f"choose other independent parameters than {[names[i] for i in free]}.")
    return dict(zip(names, q.tolist(), strict=True)), dict(zip(names, u.tolist(), strict=True))
