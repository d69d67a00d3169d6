"""Validation shared by the inertia layer: scalars, points, and the conditions that make a
symmetric matrix the operator of inertia of some body (book, ch. 15.3.2).

A matrix J in the book's layout is the operator of inertia of a body if and only if its
principal moments are non-negative and each is at most the sum of the other two (the
triangle inequalities, ch. 15.3.2): these say that the second moments of the mass,
:math:`\\int x^2\\,dm = (B + C - A)/2` and so on, are non-negative. Numeric entries are checked
with a small relative tolerance; symbolic entries are checked only where sympy's assumptions
decide the sign.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, FrameError
from ..vectors import Frame, Point

__all__ = ["scalar", "nonnegative", "check_point", "check_frame", "check_inertia",
           "PRODUCT_NAMES", "REL_TOL"]

#: Relative tolerance (to the largest entry) of the numeric sign checks: floating-point
#: round-off of a rotation or of a sum stays far below it.
REL_TOL = 1e-10

#: Book's name of the product of inertia at an off-diagonal position (row, column).
PRODUCT_NAMES = {(0, 1): "F", (1, 0): "F", (0, 2): "E", (2, 0): "E", (1, 2): "D", (2, 1): "D"}
_MOMENT_NAMES = "ABC"


def scalar(x, argument):
    """``x`` as a sympy expression, or ArgumentTypeError naming ``argument``."""
    try:
        value = sp.sympify(x, strict=True)
    except (sp.SympifyError, TypeError, ValueError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got {type(x).__name__}."
        ) from exc
    if not isinstance(value, sp.Expr):
        raise ArgumentTypeError(
            f"`{argument}` must be a scalar (number or sympy expression); "
            f"got {type(x).__name__}."
        )
    if value.is_number and (value.is_finite is not True or value.is_real is False):
        raise ArgumentError(f"`{argument}` must be a finite real number; got {x}.")
    return value


def nonnegative(x, argument):
    """``x`` as a sympy expression known not to be negative (undecidable signs pass)."""
    value = scalar(x, argument)
    if value.is_negative:
        raise ArgumentError(f"`{argument}` must be >= 0; got {x}.")
    return value


def check_point(p, argument):
    if not isinstance(p, Point):
        raise ArgumentTypeError(
            f"`{argument}` must be a Point (for example R0.origin or "
            f"A.moved(name, vector)); got {type(p).__name__}."
        )
    return p


def check_frame(frame, argument):
    if not isinstance(frame, Frame):
        raise ArgumentTypeError(f"`{argument}` must be a Frame; got {type(frame).__name__}.")
    return frame


def check_same_tree(frame, point, argument):
    if point.root != frame.root:
        raise FrameError(
            f"`{argument}` lives in the frame tree rooted at {point.root.name}, but the "
            f"frame {frame.name} belongs to the tree rooted at {frame.root.name}."
        )


def _numeric(matrix):
    if all(x.is_number for x in matrix):
        try:
            return np.array([[float(matrix[r, c]) for c in range(3)] for r in range(3)])
        except TypeError:
            return None
    return None


def _sign(e):
    """-1, 0, 1 when decided structurally, else None.

    sympy's ``is_negative`` on a new expression runs the assumptions system (tens of
    milliseconds each time a body brings new symbols); products and sums of numbers and
    symbols declared positive are decided here by their structure, and only what this cannot
    decide goes to sympy.
    """
    if e.is_Number:
        return 1 if e > 0 else (-1 if e < 0 else 0)
    if e.is_Symbol:
        return 1 if e.is_positive else (-1 if e.is_negative else None)
    if e.is_Pow:
        b = _sign(e.base)
        if b == 1:
            return 1
        return 1 if (e.exp.is_Integer and e.exp % 2 == 0 and b is not None and b != 0) \
            else None
    if e.is_Mul:
        out = 1
        for a in e.args:
            sa = _sign(a)
            if sa is None:
                return None
            out *= sa
        return out
    if e.is_Add:
        signs = {_sign(a) for a in e.args}
        if signs <= {0, 1}:
            return 1 if 1 in signs else 0
        if signs <= {0, -1}:
            return -1 if -1 in signs else 0
        return None
    return None


def check_inertia(matrix, argument, *, products=False, scale=None):
    """Raise ArgumentError unless the symmetric ``matrix`` can be an operator of inertia.

    ``products=True`` words the messages for :meth:`InertiaOperator.from_products`
    (arguments ``A``, ``B``, ``C``); otherwise they name ``argument``. ``scale``, a matrix,
    sets the size of the round-off tolerance when ``matrix`` is a difference (a hole, the
    operator brought back to the mass centre) whose entries may cancel to nearly zero.
    """
    diag = [matrix[n, n] for n in range(3)]
    values = _numeric(matrix)
    if values is not None and not np.isfinite(values).all():
        raise ArgumentError(
            f"`{argument}` gives moments or products of inertia that overflow floating-point "
            f"numbers (|value| > 1.8e308); got A={sp.sstr(diag[0])}, B={sp.sstr(diag[1])}, "
            f"C={sp.sstr(diag[2])}. Choose other units.")
    if values is not None:
        size = float(np.max(np.abs(values)))
        reference = None if scale is None else _numeric(scale)
        if reference is not None:
            size = max(size, float(np.max(np.abs(reference))))
        tol = REL_TOL * size
        negative = [n for n in range(3) if values[n, n] < -tol]
        triangle = [n for n in range(3)
                    if values[n, n] > values[(n + 1) % 3, (n + 1) % 3]
                    + values[(n + 2) % 3, (n + 2) % 3] + tol]
    else:
        negative = [n for n in range(3) if _sign(diag[n]) == -1]
        # The triangle inequality with symbols needs new sums, whose construction costs
        # more than the rest of a body's set-up; it is checked once numbers are given.
        triangle = []
    if negative:
        n = negative[0]
        name = _MOMENT_NAMES[n]
        if products:
            raise ArgumentError(f"`{name}` must be >= 0; got {sp.sstr(diag[n])}.")
        raise ArgumentError(
            f"`{argument}` must have non-negative moments of inertia on its diagonal; got "
            f"{name}={sp.sstr(diag[n])}."
        )
    if triangle:
        n = triangle[0]
        name, o1, o2 = (_MOMENT_NAMES[k % 3] for k in (n, n + 1, n + 2))
        got = ", ".join(f"{x}={sp.sstr(diag[k])}" for x, k in zip("ABC", range(3), strict=True))
        subject = f"`{name}`" if products else f"the moment {name} of `{argument}`"
        raise ArgumentError(
            f"{subject} must be <= {o1} + {o2} (triangle inequality of the moments of "
            f"inertia, ch. 15.3.2); got {got}."
        )
    if values is not None:
        principal = np.linalg.eigvalsh(values)
        if principal[0] < -tol or principal[2] > principal[0] + principal[1] + tol:
            got = ", ".join(f"{x:.6g}" for x in principal)
            if products:
                raise ArgumentError(
                    f"the products of inertia `D`, `E`, `F` are too large for the moments A, "
                    f"B, C: the principal moments must be >= 0 and each at most the sum of "
                    f"the other two (ch. 15.3.2); got principal moments {got}."
                )
            raise ArgumentError(
                f"`{argument}` is not the operator of inertia of any body: its principal "
                f"moments must be >= 0 and each at most the sum of the other two "
                f"(ch. 15.3.2); got principal moments {got}."
            )
