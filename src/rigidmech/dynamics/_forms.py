"""The symbolic forms of :class:`~rigidmech.dynamics.EquationsOfMotion` (book, ch. 20, 27):
the equations read from their arguments and written with the user's q(t), q'(t) (stand-in
symbols put back), solved for q'' symbolically, and printed with plain symbols.

Functions called by the methods of :class:`~rigidmech.dynamics.EquationsOfMotion` that carry
the documentation (the numeric side is :mod:`rigidmech.dynamics._compiled`).

Examples
--------
>>> import sympy as sp
>>> import rigidmech as rm
>>> x = rm.coordinates("x"); xs, us = sp.symbols("xs us")
>>> coords, M, f, *_ = read((x,), sp.ImmutableMatrix([[1]]), sp.ImmutableMatrix([[-xs * us]]),
...                         None, None, (xs,), (us,), None)
>>> f
Matrix([[-x(t)*Derivative(x(t), t)]])
"""

from __future__ import annotations

import sympy as sp
from sympy.matrices.exceptions import NonInvertibleMatrixError

from .._core.errors import ArgumentError, ArgumentTypeError, SingularMassMatrixError
from .._core.symbolic import atoms_shared, xreplace_shared
from ..vectors import t as _t
from ._compiled import coordinate_name as _name

__all__ = ["accelerations", "display_rule", "latex", "read"]


def _is_function_of_time(q):
    return isinstance(q, sp.core.function.AppliedUndef) and q.args == (_t,)


def read(coordinates, mass_matrix, forcing, energy, parameters, q, u, constraints):
    """The arguments of :class:`~rigidmech.dynamics.EquationsOfMotion`, checked and written
    with the coordinates q(t) and their rates: ``(coordinates, M, f, rates, accelerations,
    energy, parameters, inputs, derivatives of inputs)``."""
    coordinates = tuple(coordinates)
    n = len(coordinates)
    for c in coordinates:
        if not (_is_function_of_time(c) or isinstance(c, sp.Symbol)):
            raise ArgumentTypeError(
                f"`coordinates` must be functions of time q(t) (rm.coordinates or "
                f"dynamicsymbols) or plain symbols; got {c!r}.")
    M = sp.ImmutableMatrix(mass_matrix)
    f = sp.ImmutableMatrix(forcing)
    if M.shape != (n, n) or f.shape != (n, 1):
        raise ArgumentError(
            f"`mass_matrix` must be {n}x{n} and `forcing` {n}x1; got {M.shape} "
            f"and {f.shape}.")
    if q is not None and len(tuple(q)) != n or u is not None and len(tuple(u)) != n:
        raise ArgumentError(f"`q` and `u` must hold {n} symbols, one per coordinate.")
    rates, accs, back = [], [], {}
    for k, c in enumerate(coordinates):
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
    if back:  # expressions written with stand-in symbols: back to the user's q(t)
        memo = {}
        M = sp.ImmutableMatrix(n, n, xreplace_shared(list(M), back, memo))
        f = sp.ImmutableMatrix(n, 1, xreplace_shared(list(f), back, memo))
        if isinstance(energy, sp.Basic):
            energy = xreplace_shared([energy], back, memo)[0]
    # the constants of the constraints too: the projection and the assembly of the initial
    # state need them even where Baumgarte's terms (hence Φ) are not in the bias
    extra = [] if constraints is None else (
        list(constraints.jacobian) + list(constraints.stabilized_bias())
        + list(constraints.velocity) + [p for p in constraints.position if p is not None])
    symbols, functions, derivatives = atoms_shared(list(M) + list(f) + extra)
    own = {x for x in coordinates + tuple(rates) if isinstance(x, sp.Symbol)}
    if parameters is None:
        free = symbols - own - {_t}
    else:
        free = set(parameters)
    params = tuple(sorted(free, key=lambda s: s.name))
    coords = set(coordinates)
    inputs = tuple(sorted(functions - coords, key=str))
    input_derivatives = tuple(sorted(
        (d for d in derivatives if d.expr not in coords), key=str))
    return (coordinates, M, f, tuple(rates), tuple(accs), energy, params, inputs,
            input_derivatives)


def accelerations(eqs, simplify):
    """q'' = M^-1 f symbolically; with constraints, the first n unknowns of the augmented
    eqs (see :meth:`EquationsOfMotion.accelerations
    <rigidmech.dynamics.EquationsOfMotion.accelerations>`)."""
    try:
        if eqs._constraints is not None:
            c = eqs._constraints
            n, m = len(eqs._q), len(c)
            K = sp.BlockMatrix([[eqs._M, c.jacobian.T],
                                [c.jacobian, sp.zeros(m, m)]]).as_explicit()
            sol = K.LUsolve(sp.Matrix(list(eqs._f) + list(c.bias)))
            acc = sol[:n, :]
        else:
            acc = eqs._M.LUsolve(eqs._f)
    except (NonInvertibleMatrixError, ValueError) as exc:
        raise _singular(eqs) from exc
    return sp.ImmutableMatrix(sp.simplify(acc) if simplify else acc)


def _singular(eqs):
    """The error of a mass (or augmented) matrix singular at every configuration, naming the
    coordinates whose row of M is zero (they move no mass) when there are some."""
    names = [_name(q) for q in eqs._q]
    zero = [nm for nm, row in zip(names, eqs._M.tolist(), strict=True)
            if all(x == 0 for x in row)]
    what = ("the augmented matrix [[M, A^T], [A, 0]]" if eqs._constraints is not None
            else "the mass matrix M")
    cause = (f" (the row of {', '.join(zero)} is zero: no body with mass or inertia moves "
             "with it)" if zero else "")
    return SingularMassMatrixError(
        f"`accelerations()`: {what} is singular at every configuration of "
        f"[{', '.join(names)}]{cause}, so q'' is not determined. Give mass or inertia to "
        "the bodies that move with each coordinate, remove a coordinate that moves nothing, "
        "or a linking connection that repeats others.")


def display_rule(eqs) -> dict:
    """Symbols to print q(t), q'(t), q''(t) as q, q_dot, q_ddot (see
    :meth:`EquationsOfMotion.display_rule
    <rigidmech.dynamics.EquationsOfMotion.display_rule>`)."""
    rule = {}
    for q, u, a in zip(eqs._q, eqs._u, eqs._a, strict=True):
        name = _name(q)
        if a is not None:
            rule[a] = sp.Symbol(name + "_ddot", real=True)
        rule[u] = sp.Symbol(name + "_dot", real=True) if not isinstance(u, sp.Symbol) else u
        rule[q] = sp.Symbol(name, real=True) if not isinstance(q, sp.Symbol) else q
    return rule


def latex(eqs):
    """M(q) q'' = f(q, q', t) in LaTeX, q(t) and its rates printed q, q dot, q double dot."""
    rule = {}
    for q, u, a in zip(eqs._q, eqs._u, eqs._a, strict=True):
        name = sp.latex(sp.Symbol(_name(q)))
        if a is not None:
            rule[a] = sp.Symbol(rf"\ddot{{{name}}}")
        rule[u] = sp.Symbol(rf"\dot{{{name}}}")
        rule[q] = sp.Symbol(name)
    acc = sp.Matrix([sp.Symbol(rf"\ddot{{{sp.latex(sp.Symbol(_name(q)))}}}")
                     for q in eqs._q])
    return (sp.latex(sp.Matrix(eqs._M).xreplace(rule)) + sp.latex(acc) + " = "
            + sp.latex(sp.Matrix(eqs._f).xreplace(rule)))
