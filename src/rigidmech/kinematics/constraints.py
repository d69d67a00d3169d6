"""Kinematic constraints between parameters of situation: holonomic or not (book, ch. 10.1.3,
25.3).

A condition of rolling without slipping, or the ratio of a gear mesh, is a linear relation
between the derivatives of the parameters q_i(t):

.. math:: \\sum_i a_i(q, t)\\, \\dot q_i + a_0(q, t) = 0 .

When the differential form :math:`\\sum_i a_i\\,dq_i + a_0\\,dt` is **exact** it is the
derivative of a function f(q, t), and the constraint integrates to the **holonomic**
(geometric) relation f(q, t) = f(q_0, t_0): one parameter can be eliminated (a wheel rolling on
a line, two gears in mesh). Otherwise the constraint is kept as a relation between velocities
(the book's linked parameters, ch. 25.3; a disc rolling on a plane).

:class:`VelocityConstraint` tests exactness exactly (equality of the cross derivatives,
decided by ``sympy.simplify``) and integrates the form with sympy. A constraint that becomes
exact only after multiplication by a factor is reported as not holonomic: it remains a
correct velocity constraint, only its elimination is not offered.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from .._core.symbolic import vanishes
from ..vectors import t
from ..vectors.symbols import is_coordinate

__all__ = ["VelocityConstraint"]


def _speeds_and_coordinates(expr):
    qs = sorted({a for a in expr.atoms(sp.Function) if is_coordinate(a)}, key=str)
    derivs = [d for d in expr.atoms(sp.Derivative)]
    for d in derivs:
        if not (is_coordinate(d.expr) and d.variable_count == ((t, 1),)):
            raise ArgumentError(
                f"`expression` must hold the parameters q(t) and their first derivatives only; "
                f"got {d}.")
    return qs


class VelocityConstraint:
    """A constraint linear in the derivatives of the parameters of situation, which must
    vanish (ch. 10.1.3, 25.3).

    Parameters
    ----------
    expression : sympy expression
        sum_i a_i(q, t) q_i'(t) + a_0(q, t), written with the parameters q(t) of
        :func:`rigidmech.coordinates`.

    Raises
    ------
    ArgumentError
        If ``expression`` is not linear in the q_i', or holds second derivatives.

    Examples
    --------
    A wheel of radius r rolling on a line: x' + r theta' = 0 is holonomic, x + r theta = const.

    >>> import sympy as sp
    >>> from rigidmech import coordinates, t
    >>> x, theta = coordinates("x theta"); r = sp.Symbol("r", positive=True)
    >>> c = VelocityConstraint(x.diff(t) + r * theta.diff(t))
    >>> c.holonomic, c.position_form
    (True, r*theta(t) + x(t))
    """

    __slots__ = ("_expr", "_coordinates", "_coefficients", "_term", "_position")

    def __init__(self, expression):
        try:
            expr = sp.sympify(expression)
        except (sp.SympifyError, TypeError) as exc:
            raise ArgumentTypeError(
                f"`expression` must be a sympy expression; got {type(expression).__name__}."
            ) from exc
        if not isinstance(expr, sp.Expr):
            raise ArgumentTypeError(
                f"`expression` must be a sympy expression; got {type(expression).__name__}.")
        expr = sp.expand(expr)
        qs = _speeds_and_coordinates(expr)
        speeds = [q.diff(t) for q in qs]
        coeffs = []
        for v in speeds:
            a = expr.coeff(v)
            if a.has(*speeds):
                raise ArgumentError(
                    f"`expression` must be linear in the derivatives of the parameters; got the "
                    f"coefficient {a} of {v}.")
            coeffs.append(a)
        rest = sp.expand(expr - sum(a * v for a, v in zip(coeffs, speeds, strict=True)))
        if rest.has(*speeds):
            raise ArgumentError(
                "`expression` must be linear in the derivatives of the parameters; got "
                f"{expression}.")
        self._expr = expr
        self._coordinates = tuple(qs)
        self._coefficients = tuple(coeffs)
        self._term = rest
        self._position = self._integrate()

    def _integrate(self):
        xs = [sp.Dummy(str(q.func), real=True) for q in self._coordinates]
        to_x = dict(zip(self._coordinates, xs, strict=True))
        forms = [sp.sympify(a).xreplace(to_x) for a in self._coefficients]
        variables = list(xs)
        if self._term != 0:
            forms.append(self._term.xreplace(to_x))
            variables.append(t)
        for i, (ai, xi) in enumerate(zip(forms, variables, strict=True)):
            for aj, xj in zip(forms[i + 1:], variables[i + 1:], strict=True):
                if not vanishes(ai.diff(xj) - aj.diff(xi)):  # the one exact zero rule
                    return None
        f = sp.S.Zero
        for ai, xi in zip(forms, variables, strict=True):
            rest = sp.simplify(ai - f.diff(xi))
            if rest == 0:
                continue
            part = sp.integrate(rest, xi)
            if part.has(sp.Integral):
                return None
            f = f + part
        back = {x: q for q, x in zip(self._coordinates, xs, strict=True)}
        return sp.simplify(f.xreplace(back))

    @property
    def expression(self):
        """The expression that must vanish."""
        return self._expr

    @property
    def coordinates(self) -> tuple:
        """The parameters q_i(t) that appear (differentiated or not)."""
        return self._coordinates

    @property
    def coefficients(self) -> tuple:
        """The coefficients a_i(q, t) of the q_i', in the order of :attr:`coordinates`."""
        return self._coefficients

    @property
    def holonomic(self) -> bool:
        """True when the constraint is the derivative of a relation between the parameters
        (its form is exact and sympy integrated it)."""
        return self._position is not None

    @property
    def position_form(self):
        """f(q, t) with df/dt equal to the constraint, or None when not holonomic."""
        return self._position

    def position_constraint(self, initial: dict | None = None):
        """The holonomic relation f(q, t) - f(q0, t0), which must vanish (ch. 25.3).

        Parameters
        ----------
        initial : dict, optional
            Values of the parameters (and of ``t``) at a known configuration; without it the
            relation is f(q, t) - C with a constant symbol C.

        Raises
        ------
        ConnectionError\\_
            If the constraint is not holonomic.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech import coordinates, t
        >>> x, theta = coordinates("x theta"); r = sp.Symbol("r", positive=True)
        >>> VelocityConstraint(x.diff(t) + r * theta.diff(t)).position_constraint({x: 0, theta: 0})
        r*theta(t) + x(t)
        """
        if self._position is None:
            raise ConnectionError_(
                f"the constraint {self._expr} = 0 is not holonomic (its form is not exact): it "
                "cannot be written between the parameters; keep it as a velocity constraint.")
        if initial is None:
            return self._position - sp.Symbol("C", real=True)
        if not isinstance(initial, dict):
            raise ArgumentTypeError(f"`initial` must be a dict; got {type(initial).__name__}.")
        return sp.simplify(self._position - self._position.subs(initial))

    def __repr__(self):
        return f"VelocityConstraint({self._expr})"
