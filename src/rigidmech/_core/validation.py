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

__all__ = ["finite_real", "nonnegative"]


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

