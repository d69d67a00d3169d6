"""Time, parameters of situation and constants (book, ch. 3 and 9.1.2).

The parameters of situation of a mechanical system (the book's name for generalized
coordinates) are functions of time. rigidmech represents them as sympy undefined functions
applied to the time symbol :data:`t`, so that sympy's differentiation applies the chain rule.

:data:`t` is sympy's own time symbol, ``sympy.physics.mechanics.dynamicsymbols._t``: the
``dynamicsymbols`` of :mod:`sympy.physics.mechanics` are parameters of situation of rigidmech
too, and expressions of either library mix freely.
"""

from __future__ import annotations

from functools import lru_cache
from itertools import count

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError

__all__ = ["t", "coordinates", "constants", "is_coordinate", "time_derivative",
           "partial_derivative", "declared_order", "declared_ranks"]

#: The time variable shared by every time-dependent quantity of rigidmech: ``Symbol("t")``,
#: the same symbol as ``sympy.physics.mechanics.dynamicsymbols._t``.
t = sp.Symbol("t")


def _split_names(names, argument):
    if isinstance(names, str):
        parts = names.replace(",", " ").split()
    else:
        parts = list(names)
    if not parts or not all(isinstance(p, str) and p.isidentifier() for p in parts):
        raise ArgumentError(
            f"`{argument}` must be identifiers separated by spaces or commas; got {names!r}."
        )
    return parts


def coordinates(names):
    """Create parameters of situation: real functions of time (book, ch. 9.1.2).

    Parameters
    ----------
    names : str or sequence of str
        Names separated by spaces or commas, e.g. ``"q1 q2"``.

    Returns
    -------
    sympy expression or tuple of sympy expressions
        ``q(t)`` for each name; a single one is returned bare.

    Examples
    --------
    >>> q1, q2 = coordinates("q1 q2")
    >>> q1
    q1(t)
    >>> q1.diff(t)
    Derivative(q1(t), t)
    """
    parts = _split_names(names, "names")
    out = tuple(sp.Function(n, real=True)(t) for n in parts)
    for q in out:  # the latest declaration of a name sets its rank (see declared_order)
        _DECLARED[q] = next(_RANKS)
    return out[0] if len(out) == 1 else out


# Rank of each parameter of situation in the order of declaration by `coordinates`.
_DECLARED: dict = {}
_RANKS = count()


def declared_ranks(coordinates) -> dict:
    """The current declaration rank of each of ``coordinates`` made by :func:`coordinates`
    (the others are left out): a snapshot for :func:`declared_order`, so that a model's order
    does not change when a name is declared again later.

    Examples
    --------
    >>> a, b = coordinates("a b")
    >>> ranks = declared_ranks([b, a])
    >>> b_again = coordinates("a")
    >>> declared_order([b, a]), declared_order([b, a], ranks=ranks)
    ((b(t), a(t)), (a(t), b(t)))
    """
    return {q: _DECLARED[q] for q in coordinates if q in _DECLARED}


def declared_order(coordinates, ranks=None) -> tuple:
    """Sort parameters of situation in the order they were declared with
    :func:`coordinates`: by call, then by position in the call. A name declared again takes
    the rank of its latest declaration (``ranks``, a snapshot from :func:`declared_ranks`,
    fixes them instead). Functions of time not made by :func:`coordinates`
    (``sympy.physics.mechanics.dynamicsymbols``) come after, in their given order. The
    ranks are shared by the whole session: to fix the order of a model whatever else was
    declared, give it explicitly (``System(coordinates=...)``).

    Examples
    --------
    >>> theta, x = coordinates("theta x")
    >>> psi = coordinates("psi")
    >>> declared_order([psi, x, theta])
    (theta(t), x(t), psi(t))
    """
    given = list(coordinates)
    ranks = _DECLARED if ranks is None else ranks
    ranked = sorted((q for q in given if q in ranks), key=ranks.__getitem__)
    return tuple(ranked + [q for q in given if q not in ranks])


def constants(names, **assumptions):
    """Create constant parameters (masses, lengths, ...) as sympy symbols.

    Parameters
    ----------
    names : str or sequence of str
        Names separated by spaces or commas.
    **assumptions
        sympy assumptions, e.g. ``positive=True``. ``real=True`` is the default.

    Returns
    -------
    sympy.Symbol or tuple of sympy.Symbol

    Examples
    --------
    >>> m, L = constants("m L", positive=True)
    >>> m.is_positive
    True
    """
    parts = _split_names(names, "names")
    assumptions.setdefault("real", True)
    out = tuple(sp.Symbol(n, **assumptions) for n in parts)
    return out[0] if len(out) == 1 else out


def is_coordinate(expr) -> bool:
    """Tell whether ``expr`` is a parameter of situation ``q(t)``.

    Examples
    --------
    >>> is_coordinate(coordinates("q"))
    True
    >>> is_coordinate(t)
    False
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> is_coordinate(dynamicsymbols("q"))
    True
    """
    return isinstance(expr, sp.core.function.AppliedUndef) and expr.args == (t,)


def time_derivative(expr, order: int = 1):
    """Derivative of a scalar expression with respect to :data:`t`.

    The chain rule is applied structurally (sums, products, powers, sin, cos, tan, exp, log,
    sqrt) with the derivatives of the parameters of situation built directly; anything else
    goes to sympy's ``diff``. sympy's general ``diff`` costs about 0.4 ms per call on a warm
    cache and 17 ms on a cold one for a typical velocity component; this walk costs a few
    tens of microseconds, and equations of motion need thousands of such derivatives.

    Examples
    --------
    >>> q = coordinates("q")
    >>> time_derivative(sp.sin(q))
    cos(q(t))*Derivative(q(t), t)
    >>> time_derivative(q, 2)
    Derivative(q(t), (t, 2))
    """
    if not isinstance(order, int) or order < 0:
        raise ArgumentError(f"`order` must be a non-negative integer; got {order!r}.")
    try:
        expr = sp.sympify(expr)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`expr` must be a scalar sympy expression; got {type(expr).__name__}."
        ) from exc
    for _ in range(order):
        expr = _dt(expr)
    return expr


_ONE, _ZERO = sp.S.One, sp.S.Zero
_SIMPLE = {
    sp.sin: lambda a: sp.cos(a),
    sp.cos: lambda a: -sp.sin(a),
    sp.tan: lambda a: 1 + sp.tan(a) ** 2,
    sp.exp: lambda a: sp.exp(a),
    sp.log: lambda a: 1 / a,
}


@lru_cache(maxsize=262144)
def _dt(e):
    if e is t:
        return _ONE
    if not e.has(t):
        return _ZERO
    if isinstance(e, sp.core.function.AppliedUndef) and e.args == (t,):
        return sp.Derivative(e, t)
    if isinstance(e, sp.Derivative) and len(e.variable_count) == 1 \
            and e.variable_count[0][0] is t and is_coordinate(e.expr):
        return sp.Derivative(e.expr, (t, e.variable_count[0][1] + 1))
    if isinstance(e, sp.Add):
        return sp.Add(*[_dt(a) for a in e.args])
    if isinstance(e, sp.Mul):
        args = e.args
        terms = []
        for n, a in enumerate(args):
            da = _dt(a)
            if da != 0:
                terms.append(sp.Mul(*args[:n], da, *args[n + 1:]))
        return sp.Add(*terms)
    if isinstance(e, sp.Pow) and not e.exp.has(t):
        db = _dt(e.base)
        return e.exp * e.base ** (e.exp - 1) * db if db != 0 else _ZERO
    if isinstance(e, sp.Function) and len(e.args) == 1 and e.func in _SIMPLE:
        da = _dt(e.args[0])
        return _SIMPLE[e.func](e.args[0]) * da if da != 0 else _ZERO
    return sp.diff(e, t)


def _is_rate(x):
    """Whether ``x`` is a parameter of situation q(t) or one of its time derivatives."""
    return is_coordinate(x) or (isinstance(x, sp.Derivative) and is_coordinate(x.expr)
                                and all(v is t for v, _ in x.variable_count))


def partial_derivative(expr, variable):
    """Partial derivative of a scalar expression with respect to a symbol, a parameter of
    situation q(t) or one of its derivatives q'(t) (q and q' independent, as in Lagrange's
    and Kane's equations).

    Like :func:`time_derivative`, the rules are applied structurally (sums, products,
    powers with a constant exponent, sin, cos, tan, exp, log) and anything else goes to
    sympy's ``diff``, which gives the same result at several times the cost on a cold cache
    (it builds and evaluates a ``Derivative`` at each level).

    Examples
    --------
    >>> q = coordinates("q")
    >>> partial_derivative(sp.sin(q) * q.diff(t) ** 2, q.diff(t))
    2*sin(q(t))*Derivative(q(t), t)
    >>> partial_derivative(sp.sin(q) * q.diff(t) ** 2, q)
    cos(q(t))*Derivative(q(t), t)**2
    """
    expr, variable = sp.sympify(expr), sp.sympify(variable)
    if not (isinstance(variable, sp.Symbol) or _is_rate(variable)):
        raise ArgumentTypeError(
            f"`variable` must be a symbol, a parameter of situation q(t) or a derivative "
            f"q'(t); got {variable!r}.")
    return _partial(expr, variable, _is_rate(variable))


def _partial(e, x, rate):
    if e == x:
        return _ONE
    if not e.has(x):
        return _ZERO
    if e.is_Add:
        return sp.Add(*[_partial(a, x, rate) for a in e.args])
    if e.is_Mul:
        args = e.args
        terms = []
        for n, a in enumerate(args):
            da = _partial(a, x, rate)
            if da != 0:
                terms.append(sp.Mul(*args[:n], da, *args[n + 1:]))
        return sp.Add(*terms)
    if e.is_Pow and not e.exp.has(x):
        db = _partial(e.base, x, rate)
        return e.exp * e.base ** (e.exp - 1) * db if db != 0 else _ZERO
    if isinstance(e, sp.Function) and len(e.args) == 1 and e.func in _SIMPLE:
        da = _partial(e.args[0], x, rate)
        return _SIMPLE[e.func](e.args[0]) * da if da != 0 else _ZERO
    if rate and _is_rate(e):  # q' does not depend on q, nor q on q'
        return _ZERO
    return sp.diff(e, x)
