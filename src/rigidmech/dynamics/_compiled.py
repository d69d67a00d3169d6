"""The compiled world of :class:`~rigidmech.dynamics.EquationsOfMotion` (book, ch. 27):
numbers from the symbolic equations.

Functions of the equations, called by the methods of
:class:`~rigidmech.dynamics.EquationsOfMotion` that carry the documentation, each result
cached in the equations' cache:

* the stand-ins: plain (Dummy) symbols for q, q', q'' and the inputs inside compiled code, and
  M and f written with them once, common subexpressions shared;
* the values of the parameters and inputs given by name, checked (a value for a constant of
  the model that dropped out of the equations is noted and ignored);
* the solver: M q'' = f, or the augmented eqs [[M, A^T], [A, 0]] with Baumgarte's
  stabilisation of the constraints, compiled once (:mod:`rigidmech._core.compile`);
* the right-hand sides the solvers of :mod:`rigidmech.ode` integrate: y' = (q', q'') for the
  first-order methods, q'' = a(t, q) for the second-order ones. They are the per-step code of
  a simulation: one call of the compiled solver, nothing wrapped around it; an error raised
  inside is kept (:func:`trouble`) and nan returned, so that the solver stops there.

Examples
--------
>>> import sympy as sp, numpy as np
>>> import rigidmech as rm
>>> x = rm.coordinates("x"); k = sp.Symbol("k")
>>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[2]]),
...                            forcing=sp.ImmutableMatrix([[-k * x]]))
>>> rhs(eqs, {"k": 8.0})(0.0, np.array([1.0, 0.0]))
array([ 0., -4.])
"""

from __future__ import annotations

import logging

import numpy as np
import sympy as sp

from .._core.compile import CompiledLinearSolve, compile_expressions, compile_linear_solve
from .._core.errors import (
    ArgumentError,
    ArgumentTypeError,
    CompilationError,
    SingularMassMatrixError,
)
from .._core.symbolic import xreplace_shared
from ..systems.mobility import numeric_rank
from ..vectors import t as _t

__all__ = ["acceleration_only", "check_compilable", "coordinate_name", "rhs", "solver",
           "stand_ins", "symbolic", "trouble", "given_values"]

_log = logging.getLogger("rigidmech")


def coordinate_name(q):
    """The name of a coordinate: ``q`` for q(t) or for a plain symbol q."""
    return q.func.__name__ if isinstance(q, sp.core.function.AppliedUndef) else q.name


def trouble(fun, exc, t, shape):
    """An error of the right-hand side during a simulation: kept (the first one) in
    ``fun.trouble`` with its time, and nan returned so that the solver stops there and keeps
    the motion computed so far (the error is named in the simulation's message)."""
    if not fun.trouble:
        when = float(np.min(t)) if np.ndim(t) else float(t)  # a time per column: the first
        fun.trouble.append((f"{type(exc).__name__}: {exc}", when))
    return np.full(shape, np.nan)


def stand_ins(eqs):
    """Plain symbols for q, q', q'' and the inputs inside compiled code, and the rule that
    puts them in place of the user's q(t), Derivative(q(t), t), ... (Dummy symbols: no
    clash with a constant of the same name)."""
    if "stand_ins" not in eqs._cache:
        rule = {}
        q_s, u_s, a_s = [], [], []
        for q, u, a in zip(eqs._q, eqs._u, eqs._a, strict=True):
            name = coordinate_name(q)
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
        for w in eqs._inputs:
            ws = sp.Dummy(coordinate_name(w), real=True)
            rule[w] = ws
            w_s.append(ws)
        eqs._cache["stand_ins"] = (tuple(q_s), tuple(u_s), tuple(a_s), tuple(w_s), rule)
    return eqs._cache["stand_ins"]


def symbolic(eqs):
    """M and f with the stand-in symbols (computed once, sharing subexpressions)."""
    if "symbolic" not in eqs._cache:
        q_s, u_s, a_s, w_s, rule = stand_ins(eqs)
        n = len(q_s)
        memo = {}
        M = xreplace_shared(list(eqs._M), rule, memo, evaluate=False)
        f = xreplace_shared(list(eqs._f), rule, memo, evaluate=False)
        eqs._cache["symbolic"] = (q_s, u_s, w_s, rule, sp.ImmutableMatrix(n, n, M),
                                  sp.ImmutableMatrix(n, 1, f))
    return eqs._cache["symbolic"]


def check_compilable(eqs):
    """Refuse equations holding derivatives of inputs (no value can be given for them)."""
    bad = eqs._cache["input_derivatives"]
    if bad:
        raise CompilationError(
            f"the equations contain {', '.join(map(str, bad))}: derivatives of inputs "
            "cannot be given as values; substitute an expression of t for the input "
            "first (eqs.forcing.subs(F(t), ...)) or make it a parameter of situation.")


def model_names(eqs):
    """The names of every constant of the model the equations come from (cached)."""
    if "model" not in eqs._cache:
        model = eqs._model() if callable(eqs._model) else eqs._model
        eqs._cache["model"] = {s.name for s in (model or ())}
    return eqs._cache["model"]


def given_values(eqs, params):
    """(parameter values, input values, notes) from keyword values, checked."""
    names = {p.name for p in eqs._params}
    input_names = [coordinate_name(w) for w in eqs._inputs]
    missing = [p.name for p in eqs._params if p.name not in params]
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
    dropped = [x for x in extra if x in model_names(eqs)]
    unknown = [x for x in extra if x not in dropped]
    if unknown:
        raise ArgumentError(
            f"unknown parameters {unknown}; the equations depend on "
            f"{[p.name for p in eqs._params] + input_names}.")
    def number(name, kind):
        try:
            return float(params[name])
        except (TypeError, ValueError):
            raise ArgumentTypeError(
                f"the value of {kind} `{name}` must be a real number"
                f"{' or a callable of t' if kind == 'input' else ''}; got "
                f"{params[name]!r}.") from None

    values = [number(p.name, "parameter") for p in eqs._params]
    inputs = [params[w] if callable(params[w]) else number(w, "input")
              for w in input_names]
    notes = ()
    if dropped:
        notes = (f"parameters {', '.join(dropped)} do not enter the equations of motion "
                 "(they dropped out of the derivation): their values are ignored.",)
        for note in notes:
            _log.info(note)
    return values, inputs, notes


def augmented(eqs):
    """The augmented matrix [[M, A^T], [A, 0]] and right-hand side [f; b_stabilized],
    with the stand-in symbols."""
    q_s, u_s, w_s, rule, M, f = symbolic(eqs)
    c = eqs._constraints
    memo = {}
    m, n = len(c), len(q_s)
    A = sp.ImmutableMatrix(m, n, xreplace_shared(list(c.jacobian), rule, memo))
    b = xreplace_shared(list(c.stabilized_bias()), rule, memo)
    K = sp.BlockMatrix([[M, A.T], [A, sp.zeros(m, m)]]).as_explicit()
    F = sp.ImmutableMatrix(n + m, 1, list(f) + b)
    return sp.ImmutableMatrix(K), F


def constrained_solver(eqs):
    """The compiled solution of the augmented system: q'' (its ``full`` gives the
    multipliers as well)."""
    q_s, u_s, w_s, _, _, _ = symbolic(eqs)
    K, F = augmented(eqs)
    full = compile_linear_solve(
        K, F, [_t, list(q_s), list(u_s), *eqs._params, *w_s], symmetric=False,
        name="accelerations_and_multipliers", saddle=len(q_s))
    n = len(q_s)

    def checked(*args):
        try:
            return full(*args)
        except SingularMassMatrixError as exc:
            raise locked(eqs, exc, args) from exc

    def solve(*args):  # checked's body again: one call less per evaluation
        try:
            return full(*args)[:n]
        except SingularMassMatrixError as exc:
            raise locked(eqs, exc, args) from exc

    solve.full = checked
    solve.linear = full  # its generated first-order form for rhs (the errors as above)
    return solve


def locked(eqs, exc, args):
    """The error of a singular augmented matrix at the state ``args`` (t, q, u, parameters,
    inputs): a constraint Jacobian A of lower rank than its rows there (a singular
    configuration of the loop) is named with the conditions, otherwise ``exc`` (M singular
    on the motions the constraints allow). The rank is decided by the rule of
    :func:`rigidmech.systems.analyse`."""
    if "jacobian_compiled" not in eqs._cache:
        q_s, u_s, w_s, rule, _, _ = symbolic(eqs)
        c = eqs._constraints
        A = sp.ImmutableMatrix(len(c), len(q_s), xreplace_shared(list(c.jacobian), rule))
        eqs._cache["jacobian_compiled"] = compile_expressions(
            A, [_t, list(q_s), list(u_s), *eqs._params, *w_s])
    A = np.asarray(eqs._cache["jacobian_compiled"](*args), dtype=float)
    t, q = args[0], np.asarray(args[1], dtype=float)
    samples = [None] if A.ndim == 2 else range(A.shape[-1])
    for k in samples:
        Ak = A if k is None else A[..., k]
        if not np.all(np.isfinite(Ak)) or numeric_rank(Ak) == Ak.shape[0]:
            continue
        tk = t if k is None or np.ndim(t) == 0 else np.asarray(t)[k]
        qk = q if k is None else q[:, k]
        state = ", ".join(f"{coordinate_name(x)}={v:.6g}"
                          for x, v in zip(eqs.coordinates, qk, strict=True))
        labels = ", ".join(eqs._constraints.labels)
        return SingularMassMatrixError(
            f"the augmented matrix [[M, A^T], [A, 0]] is singular at t={float(tk):.6g}, "
            f"{state}: the constraint Jacobian A has rank {numeric_rank(Ak)} < {Ak.shape[0]} there "
            f"(conditions {labels}), a singular configuration of the loop (bars aligned, a "
            "dead point) where the multipliers are not determined. Start from a "
            "configuration away from it (System.assemble), or check the dimensions of the "
            "loop.")
    return exc


def solver(eqs):
    """The compiled q''(t, q, q', parameters, inputs), compiled once (cached)."""
    if "solver" not in eqs._cache and eqs._constraints is not None:
        check_compilable(eqs)
        eqs._cache["solver"] = constrained_solver(eqs)
    if "solver" not in eqs._cache:
        check_compilable(eqs)
        q_s, u_s, w_s, _, M, f = symbolic(eqs)
        eqs._cache["solver"] = compile_linear_solve(
            M, f, [_t, list(q_s), list(u_s), *eqs._params, *w_s],
            symmetric=True, name="accelerations")
    return eqs._cache["solver"]


def batched_first_order(solve, n):
    """``step(t, y, values)``: y' = (q', q'') of a float64 batch y of shape (2n, *batch) from
    the generated batched code of `solve` (a :class:`CompiledLinearSolve`) called directly,
    without the argument handling of ``solve(...)``; ``values`` the arguments after q' (floats
    or arrays along the batch). ``step`` returns None when the generated code hands A and b
    back (a pivot too small) or raises: the caller then takes the checked call, which decides.
    A symmetric system's code writes q'' into the rows of the output it is given (no
    concatenation after it). None for a solve without generated batched code."""
    if not isinstance(solve, CompiledLinearSolve):
        return None
    batched, into = solve.batched, solve.symmetric
    empty, errstate = np.empty, np.errstate

    def step(t, y, values):
        u = y[n:]
        try:
            with errstate(all="ignore"):
                if into:
                    out = empty(y.shape)
                    out[:n] = u
                    acc = batched(t, y[:n], u, *values, y.shape[1:], out[n:])
                else:
                    acc = batched(t, y[:n], u, *values, y.shape[1:])
        except (ArithmeticError, ValueError, TypeError):
            return None
        if type(acc) is tuple:
            return None
        return out if into else np.concatenate((u, acc), axis=0)

    return step


def rhs(eqs, params):
    """The first-order right-hand side ``f(t, y)`` with y = (q, q') (see
    :meth:`EquationsOfMotion.rhs <rigidmech.dynamics.EquationsOfMotion.rhs>`)."""
    check_compilable(eqs)
    values, inputs, notes = given_values(eqs, params)
    solve = solver(eqs)
    n = len(eqs._q)
    if not any(callable(w) for w in inputs):
        values = values + inputs
        # one state of float64 (what the integrators pass, call after call): the generated
        # code's first-order form, y' = (q', q'') from y and the values bound once, without
        # the argument parsing of solve(...) and the arrays around it (a quarter of an
        # integration's time at n = 6, a third of a call of the squeezer's); anything else,
        # or a failure there (A and b handed back: a pivot too small), takes the general
        # path below
        # likewise a batch (2n, m) of float64 with one time or a time per column (the
        # integrators' batches): the generated batched code without the argument checks
        # (a symmetric system's batched code writes the accelerations into the rows of the
        # output it is given: no concatenation after it)
        compiled = isinstance(solve, CompiledLinearSolve)
        linear = solve if compiled else getattr(solve, "linear", None)
        tail = tuple(float(v) for v in values)
        first_order = linear.first_order(tail) if linear is not None else None
        batch_step = batched_first_order(solve, n)
        size, f64, ndarray, scalar = 2 * n, np.float64, np.ndarray, (float, np.float64)
        shape = (size,)

        def fun(t, y):
            if type(y) is ndarray and y.dtype == f64:
                if y.shape == shape and type(t) in scalar:
                    if first_order is not None:
                        try:
                            dy = first_order(t, y)
                        except (ArithmeticError, ValueError, TypeError):
                            dy = None
                        if type(dy) is ndarray:
                            return dy
                elif batch_step is not None and y.ndim == 2 and y.shape[0] == size and (
                        type(t) in scalar or (
                        type(t) is ndarray and t.shape == y.shape[1:] and t.dtype == f64)):
                    dy = batch_step(t, y, tail)
                    if dy is not None:
                        return dy
            try:  # free unless raised
                acc = solve(t, y[:n], y[n:], *values)
            except (ArithmeticError, ValueError, TypeError) as exc:
                if fun.trouble is None:
                    raise
                return trouble(fun, exc, t, np.shape(y))
            return np.concatenate((y[n:], acc), axis=0)
    else:
        def fun(t, y):
            try:
                w = [v(t) if callable(v) else v for v in inputs]
                acc = solve(t, y[:n], y[n:], *values, *w)
            except (ArithmeticError, ValueError, TypeError) as exc:
                if fun.trouble is None:
                    raise
                return trouble(fun, exc, t, np.shape(y))
            return np.concatenate((y[n:], acc), axis=0)

    fun.notes = notes
    fun.trouble = None  # a list: errors kept there, nan returned (see trouble)
    return fun


def acceleration_only(eqs, method, params):
    """q'' = a(t, q) for the geometric (second-order) methods, which need accelerations
    independent of the velocities (separable systems)."""
    q_s, u_s, _, _, _, f = symbolic(eqs)
    if any(f.has(u) for u in u_s):
        raise ArgumentError(
            f"method {method!r} integrates q'' = a(t, q) only, but these equations "
            "depend on q' (velocity products); use an explicit method such as 'dop853'.")
    values, inputs, notes = given_values(eqs, params)
    solve = solver(eqs)
    zeros = np.zeros(len(eqs._u))

    def acc(t, q):
        try:
            w = [v(t) if callable(v) else v for v in inputs]
            return solve(t, q, np.zeros_like(q) if np.ndim(q) > 1 else zeros, *values, *w)
        except (ArithmeticError, ValueError, TypeError) as exc:
            if acc.trouble is None:
                raise
            return trouble(acc, exc, t, np.shape(q))

    acc.notes = notes
    acc.trouble = None
    return acc
