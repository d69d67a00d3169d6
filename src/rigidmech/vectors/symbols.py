"""Time, parameters of situation and constants (book, ch. 3 and 9.1.2).

The parameters of situation of a mechanical system (the book's name for generalized
coordinates) are functions of time. rigidmech represents them as sympy undefined functions
applied to the time symbol :data:`t`, so that sympy's differentiation applies the chain rule.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError

__all__ = ["t", "coordinates", "constants", "is_coordinate", "time_derivative"]

#: The time variable shared by every time-dependent quantity of rigidmech.
t = sp.Symbol("t", real=True)


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
    return out[0] if len(out) == 1 else out


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
    """
    return isinstance(expr, sp.core.function.AppliedUndef) and expr.args == (t,)


def time_derivative(expr, order: int = 1):
    """Derivative of a scalar expression with respect to :data:`t`.

    Examples
    --------
    >>> q = coordinates("q")
    >>> time_derivative(sp.sin(q))
    cos(q(t))*Derivative(q(t), t)
    """
    if not isinstance(order, int) or order < 0:
        raise ArgumentError(f"`order` must be a non-negative integer; got {order!r}.")
    try:
        expr = sp.sympify(expr)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`expr` must be a scalar sympy expression; got {type(expr).__name__}."
        ) from exc
    return sp.diff(expr, t, order) if order else expr
