"""Validation of the numbers a user gives at the public boundary (book conventions aside).

rigidmech computes with sympy expressions; a number given by the user becomes one with
``sympy.sympify``. That is also where wrong input used to slip through silently: a string
becomes a symbol (``mass='heavy'``, an angle ``'q'`` that is not a parameter of situation), a
``nan`` or an ``inf`` is carried into every result, a complex number makes energies complex.
:func:`finite_real` is the one gate for such values: an expression, and, when it is a number, a
finite real one. Symbols pass: their values are checked when numbers are given for them.
"""

from __future__ import annotations

import sympy as sp

from .errors import ArgumentError, ArgumentTypeError

__all__ = ["finite_real", "nonnegative", "as_declared", "substitutions"]


def finite_real(x, argument, *, hint=""):
    """``x`` as a sympy expression; if it is a number, a finite real one.

    Parameters
    ----------
    x : number or sympy expression
    argument : str
        The name of the argument, for the messages.
    hint : str, optional
        A sentence appended to the message for a value of the wrong type.

    Raises
    ------
    ArgumentTypeError
        For a string, a bool, a container, or anything sympy cannot read as a scalar.
    ArgumentError
        For a number that is not finite (nan, inf) or not real.

    Examples
    --------
    >>> finite_real(0.5, "mass")
    0.500000000000000
    >>> finite_real(float("nan"), "mass")
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `mass` must be a finite real number; got nan.
    """
    if isinstance(x, str | bytes | bool):
        shown = f" {x!r}" if isinstance(x, str) and len(x) < 40 else ""
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got "
            f"{type(x).__name__}{shown}.{' ' + hint if hint else ''}")
    try:
        value = sp.sympify(x, strict=True)
    except (sp.SympifyError, TypeError, ValueError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got {type(x).__name__}."
            f"{' ' + hint if hint else ''}") from exc
    if not isinstance(value, sp.Expr):
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got {type(x).__name__}."
            f"{' ' + hint if hint else ''}")
    if value.is_number and (value.is_finite is not True or value.is_real is False):
        raise ArgumentError(f"`{argument}` must be a finite real number; got {x}.")
    return value


def nonnegative(x, argument):
    """:func:`finite_real`, and not known to be negative (an undecidable sign passes).

    Examples
    --------
    >>> nonnegative(-1, "stiffness")
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `stiffness` must be >= 0; got -1.
    """
    value = finite_real(x, argument)
    if value.is_negative:
        raise ArgumentError(f"`{argument}` must be >= 0; got {x}.")
    return value



_DECLARED = (("positive", "> 0"), ("negative", "< 0"), ("nonnegative", ">= 0"),
             ("nonpositive", "<= 0"), ("nonzero", "!= 0"), ("integer", "an integer"),
             ("real", "real"))


def as_declared(symbol, value, argument):
    """``value`` (sympified) for ``symbol``, refused when it is a number that contradicts what
    the symbol declares (``rm.constants("m", positive=True)``: a mass given as -1): the
    derivation may have used the declaration (sqrt(m**2) = m), so the result would be wrong.
    A symbolic value passes.

    Examples
    --------
    >>> m = sp.Symbol("m", positive=True)
    >>> as_declared(m, 2, "values")
    2
    >>> as_declared(m, -1.0, "values")
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `values`: the value of `m` must be > 0 ...
    """
    v = sp.sympify(value)
    if not getattr(v, "is_number", False):
        return v
    for attribute, expected in _DECLARED:
        if getattr(symbol, f"is_{attribute}", None) is True \
                and getattr(v, f"is_{attribute}", None) is False:
            raise ArgumentError(
                f"`{argument}`: the value of `{symbol}` must be {expected} (declared "
                f"{attribute}); got {value}.")
    return v


def substitutions(values, symbols, argument="values"):
    """``{symbol: value}`` from ``values`` keyed by symbol or by name: a name is resolved
    among ``symbols`` (those of the problem), so that ``{"m": 2}`` reaches a symbol declared
    ``positive`` (sympify would make a new plain symbol that matches nothing, or read "Q" as
    sympy's assumptions object); every value is checked by :func:`as_declared`. A name of no
    symbol of the problem is refused; a symbol key passes as it is.

    Examples
    --------
    >>> m = sp.Symbol("m", positive=True)
    >>> substitutions({"m": 2}, {m})
    {m: 2}
    """
    by_name = {s.name: s for s in symbols if isinstance(s, sp.Symbol)}
    out = {}
    for key, value in (values or {}).items():
        if isinstance(key, str):
            if key not in by_name:
                raise ArgumentError(
                    f"`{argument}`: {key!r} names no symbol of the problem; expected some of "
                    f"{sorted(by_name)} (or pass the symbol itself).")
            key = by_name[key]
        else:
            key = sp.sympify(key)
        out[key] = as_declared(key, value, argument)
    return out
