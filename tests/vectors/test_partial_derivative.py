"""partial_derivative: the same result as sympy's diff (q and q' independent), on random
expressions of the kind the equations of motion hold."""

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidmech.errors import ArgumentTypeError
from rigidmech.vectors import coordinates, partial_derivative, t

q1, q2 = coordinates("q1 q2")
a = sp.Symbol("a", positive=True)
LEAVES = [q1, q2, q1.diff(t), q2.diff(t), a, sp.Integer(2), sp.Float(0.5), t]
UNARY = [sp.sin, sp.cos, sp.tan, sp.exp, sp.sqrt, lambda x: x**3, lambda x: 1 / (2 + x**2)]


def expressions():
    leaf = st.sampled_from(LEAVES)
    return st.recursive(
        leaf,
        lambda inner: st.one_of(
            st.builds(lambda f, x: f(x), st.sampled_from(UNARY), inner),
            st.builds(lambda x, y: x + y, inner, inner),
            st.builds(lambda x, y: x * y, inner, inner)),
        max_leaves=8)


@settings(max_examples=150, deadline=None, derandomize=True)
@given(expressions(), st.sampled_from([q1, q2, q1.diff(t), a, t]))
def test_partial_derivative_is_sympy_diff(expr, variable):
    ours, theirs = partial_derivative(expr, variable), sp.diff(expr, variable)
    if sp.expand(ours - theirs) == 0:
        return
    # equal in another form (exp(x) / sqrt(exp(x)) against sqrt(exp(x))): compare values
    leaves = [*sorted(ours.atoms(sp.Derivative) | theirs.atoms(sp.Derivative), key=str),
              q1, q2, a, t]  # derivatives of any order first: xreplace matches whole trees
    for seed in (0.3, 0.7):
        rule = {x: seed + 0.1 * i for i, x in enumerate(leaves)}
        x, y = complex(ours.xreplace(rule).evalf()), complex(theirs.xreplace(rule).evalf())
        assert abs(x - y) <= 1e-9 * (1 + abs(y))


def test_rates_and_coordinates_are_independent():
    assert partial_derivative(q1.diff(t) * sp.sin(q1), q1) == q1.diff(t) * sp.cos(q1)
    assert partial_derivative(q1.diff(t) ** 2, q1) == 0
    assert partial_derivative(q1.diff(t) ** 2, q1.diff(t)) == 2 * q1.diff(t)


def test_partial_derivative_refuses_an_expression_as_variable():
    with pytest.raises(ArgumentTypeError, match=r"`variable` must be a symbol, a parameter"):
        partial_derivative(q1, q1 + q2)
