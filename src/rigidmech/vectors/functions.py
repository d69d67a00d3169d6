"""Vector functions and their derivatives relative to a frame (book, ch. 3).

A vector function of one variable u(t), of two variables u(q1, q2) or of n variables
(ch. 3.1-3.3) is a :class:`~rigidmech.vectors.Vector` whose components depend on those
variables, possibly through bases that themselves depend on them. Its derivative depends on the
frame relative to which it is taken: these thin functions make the frame explicit and delegate to
:meth:`Vector.dt <rigidmech.vectors.Vector.dt>` (time) and
:meth:`Vector.diff <rigidmech.vectors.Vector.diff>` (any variable).

The derivatives of one vector relative to two frames R0 and R1 are related by the derivation
formula (ch. 3.1.4, 9.2.3)

.. math:: \\left.\\frac{d\\mathbf{u}}{dt}\\right|_{R_0} =
          \\left.\\frac{d\\mathbf{u}}{dt}\\right|_{R_1}
          + \\boldsymbol{\\omega}(R_1/R_0)\\wedge\\mathbf{u},

available as :func:`derivation_formula` to check or to use explicitly.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .symbols import t
from .vector import Vector, _check_frame, _check_vector, rotation_vector

__all__ = ["derivative", "partial", "jacobian", "derivation_formula"]


def _variable(v, argument):
    try:
        v = sp.sympify(v)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be a sympy symbol or a parameter q(t); got {type(v).__name__}."
        ) from exc
    if not (v.is_Symbol or isinstance(v, sp.core.function.AppliedUndef | sp.Derivative)):
        raise ArgumentError(
            f"`{argument}` must be a symbol, a parameter q(t) or a derivative q'(t); got {v}."
        )
    return v


def derivative(u: Vector, variable, frame, order: int = 1) -> Vector:
    """Derivative of a vector function of one variable relative to ``frame`` (ch. 3.1.2).

    Parameters
    ----------
    u : Vector
    variable : sympy symbol, parameter q(t) or :data:`t`
        The variable of differentiation. With :data:`rigidmech.vectors.t` the time derivative
        is taken part by part with the derivation formula (:meth:`Vector.dt`), so that vectors
        of moving bases stay in their bases; with any other variable, the parts whose bases
        depend on it are first expressed in ``frame`` (:meth:`Vector.diff`).
    frame : Frame
        Frame relative to which the derivative is taken.
    order : int, optional
        Order of the derivative (>= 0; 0 returns ``u``).

    Returns
    -------
    Vector

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates, t
    >>> q = coordinates("q")
    >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> derivative(R1.i, t, R0)
    Derivative(q(t), t)*R1.j
    >>> derivative(R1.i, q, R0, order=2).equals(-R1.i)
    True
    >>> derivative(R1.i, q, R1)
    0
    """
    _check_vector(u, "u")
    _check_frame(frame, "frame")
    variable = _variable(variable, "variable")
    if not isinstance(order, int) or isinstance(order, bool) or order < 0:
        raise ArgumentError(f"`order` must be a non-negative integer; got {order!r}.")
    for _ in range(order):
        u = u.dt(frame) if variable == t else u.diff(variable, frame)
    return u


def partial(u: Vector, variables, frame) -> Vector:
    """Successive partial derivatives of a vector function of n variables (ch. 3.2.2, 3.3).

    Parameters
    ----------
    u : Vector
    variables : sequence of sympy symbols or parameters
        Differentiate with respect to ``variables[0]``, then ``variables[1]``, ...: a mixed
        partial derivative such as d2u / dq1 dq2 is ``partial(u, (q1, q2), R0)``. A single
        variable may be passed bare.
    frame : Frame

    Returns
    -------
    Vector

    Notes
    -----
    For functions of class C2 the order does not matter (Schwarz), which the tests check.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> x, y = sp.symbols("x y")
    >>> R0 = Frame("R0")
    >>> partial(x**2 * y * R0.i + sp.sin(x * y) * R0.j, (x, y), R0)
    2*x*R0.i + (-x*y*sin(x*y) + cos(x*y))*R0.j
    """
    if isinstance(variables, str) or not hasattr(variables, "__iter__"):
        variables = (variables,)
    variables = tuple(variables)
    if not variables:
        raise ArgumentError("`variables` must hold at least one variable; got none.")
    for v in variables:
        u = derivative(u, v, frame)
    return u


def jacobian(u: Vector, variables, frame) -> sp.ImmutableMatrix:
    """Matrix of the partial derivatives of u, in components of ``frame`` (ch. 3.3).

    Parameters
    ----------
    u : Vector
    variables : sequence of n sympy symbols or parameters
    frame : Frame
        Frame relative to which the derivatives are taken, and whose basis gives the
        components.

    Returns
    -------
    sympy.ImmutableMatrix, shape (3, n)
        Column j holds the components in ``frame`` of du / d(variables[j]).

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> r, th = sp.symbols("r theta")
    >>> R0 = Frame("R0")
    >>> jacobian(R0.vector(r * sp.cos(th), r * sp.sin(th), 0), (r, th), R0)
    Matrix([
    [cos(theta), -r*sin(theta)],
    [sin(theta),  r*cos(theta)],
    [         0,             0]])
    """
    _check_frame(frame, "frame")
    if isinstance(variables, str) or not hasattr(variables, "__iter__"):
        variables = (variables,)
    variables = tuple(variables)
    if not variables:
        raise ArgumentError("`variables` must hold at least one variable; got none.")
    cols = [derivative(u, v, frame).components(frame) for v in variables]
    return sp.ImmutableMatrix.hstack(*cols)


def derivation_formula(u: Vector, relative_to, via) -> Vector:
    """The time derivative of u relative to ``relative_to`` computed through the frame ``via``
    by the derivation formula (ch. 3.1.4, 9.2.3).

    ``d/dt|R0 u = d/dt|R1 u + omega(R1/R0) ^ u``, with R0 = ``relative_to`` and R1 = ``via``.

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates, t
    >>> q = coordinates("q")
    >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> derivation_formula(2 * R1.i, R0, R1)
    2*Derivative(q(t), t)*R1.j
    """
    _check_vector(u, "u")
    _check_frame(relative_to, "relative_to")
    _check_frame(via, "via")
    return u.dt(via) + rotation_vector(via, relative_to).cross(u)
