"""Symbolic helpers that keep shared subexpressions shared.

sympy's ``xreplace`` walks an expression as a tree: a subexpression reached along many paths
is rebuilt once per path. Derived equations of motion are DAGs in which the same velocity
components appear in many entries, so a tree walk costs as much as the swollen expression.
:func:`xreplace_shared` walks each distinct node once (memoised), which keeps the cost
proportional to the size of the DAG (ARCHITECTURE.md, principle 5). sympy has no memoised
replacement, hence this small function.
"""

from __future__ import annotations

import sympy as sp

__all__ = ["xreplace_shared", "free_symbols_shared", "atoms_shared"]


def xreplace_shared(exprs, rule, memo=None):
    """Apply ``rule`` (an exact, structural replacement like ``xreplace``) to each expression
    of ``exprs``, rebuilding every distinct subexpression only once.

    Parameters
    ----------
    exprs : iterable of sympy expressions
    rule : dict
        Mapping of subexpressions to replacements; a matched node is not entered.
    memo : dict, optional
        Cache shared between calls (pass the same dict to share work across calls).

    Returns
    -------
    list of sympy expressions

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> f = sp.Function("f")(x)
    >>> xreplace_shared([sp.sin(f) + f**2, f], {f: y})
    [y**2 + sin(y), y]
    """
    memo = {} if memo is None else memo

    def walk(e):
        hit = memo.get(e)
        if hit is not None:
            return hit
        if e in rule:
            out = rule[e]
        elif not e.args or isinstance(e, sp.Symbol):
            out = e
        else:
            args = tuple(walk(a) for a in e.args)
            if all(a is b for a, b in zip(args, e.args, strict=True)):
                out = e
            elif isinstance(e, sp.Add | sp.Mul):
                # Replacing leaves by leaves keeps sums and products as they are: skip the
                # canonical re-sorting that dominates the cost of rebuilding them.
                out = e.func(*args, evaluate=False)
            else:
                out = e.func(*args)
        memo[e] = out
        return out

    return [walk(sp.sympify(e)) for e in exprs]


def free_symbols_shared(exprs) -> set:
    """The free symbols of ``exprs``, visiting every distinct subexpression once.

    ``Expr.free_symbols`` walks a DAG as a tree (every path again); this walk is linear in
    the number of distinct nodes.

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> e = sp.sin(x) * y
    >>> sorted(free_symbols_shared([e + e**2, 3]), key=str)
    [x, y]
    """
    seen = set()
    out = set()
    stack = [sp.sympify(e) for e in exprs]
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if isinstance(e, sp.Symbol):
            out.add(e)
        elif isinstance(e, sp.Derivative | sp.Subs | sp.Integral):
            out |= e.free_symbols
        else:
            stack.extend(e.args)
    return out


def atoms_shared(exprs):
    """The free symbols, the applied undefined functions (``q(t)``) and the derivatives
    (``Derivative(q(t), t)``) of ``exprs``, visiting every distinct subexpression once.

    A derivative is listed as a whole; its expression is not entered.

    Returns
    -------
    (set, set, set)
        Symbols, applied undefined functions, derivatives.

    Examples
    --------
    >>> t, k = sp.symbols("t k")
    >>> q, F = sp.Function("q")(t), sp.Function("F")(t)
    >>> s, f, d = atoms_shared([k * q.diff(t) + F, q])
    >>> sorted(s, key=str), sorted(f, key=str), d
    ([k, t], [F(t), q(t)], {Derivative(q(t), t)})
    """
    seen = set()
    symbols, functions, derivatives = set(), set(), set()
    stack = [sp.sympify(e) for e in exprs]
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if isinstance(e, sp.Symbol):
            symbols.add(e)
        elif isinstance(e, sp.Derivative):
            derivatives.add(e)
            symbols |= e.free_symbols
        elif isinstance(e, sp.core.function.AppliedUndef):
            functions.add(e)
            stack.extend(e.args)
        else:
            stack.extend(e.args)
    return symbols, functions, derivatives
