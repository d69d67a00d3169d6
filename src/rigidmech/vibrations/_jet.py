"""Values and first derivatives of sympy expressions at a point, in one memoised pass.

Forward-mode differentiation over the expression DAG: every distinct node is visited once
and carries its value at the point and its gradient with respect to the chosen variables
(a sparse dict). Evaluating at the point while differentiating lets the numbers simplify as
they go (sin(0) = 0, products with a zero factor vanish), so linearising a large system
never builds the derivative of the whole expression (what ``sympy.diff`` followed by
``subs`` would do, once per path through the DAG).
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef

from .._core.errors import ArgumentError

__all__ = ["values_and_jacobian"]


def _add_grads(grads):
    out = {}
    for g in grads:
        for k, v in g.items():
            out.setdefault(k, []).append(v)
    return {k: sp.Add(*v) for k, v in out.items()}


def _scale(g, factor):
    if factor == 0:
        return {}
    if factor == 1:
        return g
    return {k: factor * v for k, v in g.items()}


def _node(e, vals, grads):
    """(value, gradient) of node e from those of its arguments."""
    if e.is_Add:
        return sp.Add(*vals), _add_grads(grads)
    if e.is_Mul:
        value = sp.Mul(*vals)
        k = len(vals)
        if not any(grads):
            return value, {}
        prefix = [sp.S.One] * (k + 1)
        for i in range(k):
            prefix[i + 1] = prefix[i] * vals[i]
        suffix = [sp.S.One] * (k + 1)
        for i in reversed(range(k)):
            suffix[i] = suffix[i + 1] * vals[i]
        parts = [_scale(g, prefix[i] * suffix[i + 1]) for i, g in enumerate(grads) if g]
        return value, _add_grads(parts)
    if e.is_Pow:
        (b, x), (gb, gx) = vals, grads
        value = b**x
        parts = []
        if gb:
            parts.append(_scale(gb, x * b ** (x - 1)))
        if gx:
            parts.append(_scale(gx, value * sp.log(b)))
        return value, _add_grads(parts)
    if isinstance(e, AppliedUndef | sp.Derivative):
        raise ArgumentError(
            f"cannot differentiate through {e}: an unknown function or a derivative is left "
            "in the equations.")
    value = e.func(*vals)
    parts = []
    if any(grads):
        rule = {a: v for a, v in zip(e.args, vals, strict=True)}
        for i, g in enumerate(grads):
            if g:
                parts.append(_scale(g, e.fdiff(i + 1).xreplace(rule)))
    return value, _add_grads(parts)


def values_and_jacobian(exprs, point, variables):
    """Values of ``exprs`` at ``point`` and their derivatives with respect to ``variables``.

    Parameters
    ----------
    exprs : sequence of sympy expressions
    point : dict
        Values of the symbols (every variable must have one; other symbols stay symbolic).
    variables : sequence of symbols

    Returns
    -------
    values : list
    jacobian : list of lists, ``jacobian[i][j]`` = d exprs[i] / d variables[j] at the point

    Examples
    --------
    >>> x, y, a = sp.symbols("x y a")
    >>> values_and_jacobian([a * sp.sin(x) * y + x**2], {x: 0, y: 2}, [x, y])
    ([0], [[2*a, 0]])
    """
    index = {v: i for i, v in enumerate(variables)}
    memo = {}
    for root in exprs:
        root = sp.sympify(root)
        stack = [root]
        while stack:
            node = stack[-1]
            if node in memo:
                stack.pop()
                continue
            if node in point:
                memo[node] = (point[node], {index[node]: sp.S.One} if node in index else {})
                stack.pop()
                continue
            if not node.args or node.is_Symbol:
                memo[node] = (node, {})
                stack.pop()
                continue
            pending = [a for a in node.args if a not in memo]
            if pending:
                stack.extend(pending)
                continue
            stack.pop()
            vals = [memo[a][0] for a in node.args]
            grads = [memo[a][1] for a in node.args]
            memo[node] = _node(node, vals, grads)
    values, jac = [], []
    n = len(variables)
    for root in exprs:
        v, g = memo[sp.sympify(root)]
        values.append(v)
        jac.append([g.get(j, sp.S.Zero) for j in range(n)])
    return values, jac
