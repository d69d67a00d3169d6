"""The exact zero decision by values at random points (issue 20): identities that need
trigonometric simplification are decided without ``simplify``; what vanishes only on a set of
measure zero, or only on the sampled interval, is never called zero."""

import mpmath
import pytest
import sympy as sp

import rigidmech._core.symbolic as symbolic
from rigidmech._core.probes import (
    FOLD_DIGITS,
    FOLD_ZERO_RELATIVE,
    SAMPLED_NONZERO_RELATIVE,
    _point_verdict,
    sampled_zero_decision,
)
from rigidmech._core.symbolic import vanishes
from rigidmech.vectors import coordinates, t

a, b, c = sp.symbols("a b c")
m, k = sp.symbols("m k", positive=True)
x, y = sp.symbols("x y", real=True)


def _rotation(angle, axis):
    cs, sn = sp.cos(angle), sp.sin(angle)
    if axis == 2:
        return sp.Matrix([[cs, -sn, 0], [sn, cs, 0], [0, 0, 1]])
    return sp.Matrix([[1, 0, 0], [0, cs, -sn], [0, sn, cs]])


@pytest.fixture
def no_simplify(monkeypatch):
    """Fail if vanishes falls back on sympy.simplify."""

    def refuse(*args, **kwargs):
        raise AssertionError("simplify called")

    monkeypatch.setattr(symbolic.sp, "simplify", refuse)


def test_identities_inside_big_expressions_are_zero_without_simplify(no_simplify):
    q1, q2, q3 = coordinates("q1 q2 q3")
    # a rotation composition: Rz(q1) Rx(q2) Rz(q3) is orthogonal, and Rz(q1) Rz(q3) = Rz(q1+q3)
    R = _rotation(q1, 2) * _rotation(q2, 0) * _rotation(q3, 2)
    gram = (R.T * R - sp.eye(3)).applyfunc(sp.expand)
    composed = (_rotation(q1, 2) * _rotation(q3, 2) - _rotation(q1 + q3, 2))
    pythagoras = sp.sin(q2) ** 2 + sp.cos(q2) ** 2 - 1
    big = sp.expand((1 + q1.diff(t) * m + sp.sqrt(m * k)) ** 4) * pythagoras + gram[0, 1]
    assert sp.count_ops(big) > 100
    for e in [*gram, *composed, big]:
        assert vanishes(e)
        assert sampled_zero_decision(e) in (True, None if e == 0 else True)


def test_zero_only_on_a_set_of_measure_zero_is_not_zero():
    q = coordinates("q")
    for e in (sp.sin(a - b), (a - b) ** 2 * sp.cos(c), sp.cos(q) ** 2 - 1,
              sp.sin(q) * q.diff(t) - sp.sin(q) * t, a * b - 1):
        assert sampled_zero_decision(e) is False
        assert not vanishes(e)


def test_zero_on_the_sampled_interval_only_is_not_decided_zero():
    # atan(tan(a)) = a on (-pi/2, pi/2) only; |x| = x for x > 0 only; sqrt((x+y)^2) = |x+y|
    for e in (sp.atan(sp.tan(a)) - a, sp.Abs(x) - x, sp.sqrt((x + y) ** 2) - x - y,
              sp.Max(x, 0) - x):
        assert sampled_zero_decision(e) is None
        assert not vanishes(e)


def test_square_roots_and_abs_of_positive_constants():
    # the base is positive for every admissible value: the sample decides
    assert sampled_zero_decision(sp.sqrt(m**2 + 2 * m * k + k**2) - m - k) is True
    assert sampled_zero_decision(sp.sqrt(m * k) * sp.sqrt(m / k) - m) is True
    assert sampled_zero_decision(sp.Abs(m + k) - m - k) is True        # sympy: 0
    # the same with real symbols is not an identity (x + y < 0)
    assert not vanishes(sp.sqrt(x**2 + 2 * x * y + y**2) - x - y)
    # Abs of a difference of positive constants: not zero where m < k
    assert not vanishes(sp.Abs(m - k) - (m - k))
    # exact algebraic numbers: cos(pi/5) = (1 + sqrt(5))/4
    assert sampled_zero_decision(sp.cos(sp.pi / 5) * a - (1 + sp.sqrt(5)) / 4 * a) is True


def test_negative_and_integer_symbols_respect_their_assumptions():
    n = sp.Symbol("n", integer=True)
    neg = sp.Symbol("g", negative=True)
    # not sampled: integers are not a connected set (sin(pi (n + a)) = (-1)^n sin(pi a) for
    # integers only); simplify decides
    shift = sp.sin(sp.pi * (n + a)) - (-1) ** n * sp.sin(sp.pi * a)
    assert sampled_zero_decision(shift) is None
    assert vanishes(shift)
    # sampled negative: sqrt(g^2) = -g
    assert sampled_zero_decision(sp.sqrt(neg**2 + neg**4) + neg * sp.sqrt(1 + neg**2)) is True


def test_float_constants_keep_their_rounding_rule():
    q = coordinates("q")
    assert vanishes(0.1 * q + 0.2 * q - 0.3 * q)
    assert vanishes(sp.Float(6.9e-18) * q)
    assert not vanishes(sp.Float(1e-6) * q)


def test_functions_of_time_and_skipped_symbols():
    q = coordinates("q")
    unevaluated = sp.Derivative(sp.sin(q), t) - sp.cos(q) * q.diff(t)
    assert sampled_zero_decision(unevaluated) is None       # not a leaf: not decided here
    assert sampled_zero_decision(sp.cos(t) ** 2 + sp.sin(t) ** 2 - 1) is True
    assert sampled_zero_decision(sp.cos(t) ** 2 + sp.sin(t) ** 2 - 1, skip=(t,)) is None
    assert vanishes(sp.cos(t) ** 2 + sp.sin(t) ** 2 - 1, skip=(t,))
    assert not vanishes(t, skip=(t,))


def test_near_cancellation_and_tiny_exact_constants():
    pythagoras = sp.sin(a) ** 2 + sp.cos(a) ** 2 - 1
    # 1e-35 of the terms: between the thresholds, simplify decides (not zero)
    near = 10**35 * pythagoras + a
    assert sampled_zero_decision(near) is None
    assert not vanishes(near)
    # 1e-12 of the terms: plainly not zero
    assert sampled_zero_decision(sp.Rational(1, 10**12) * a + pythagoras) is False
    # the documented limit: 1e-45 of the terms is taken for zero
    assert sampled_zero_decision(10**45 * pythagoras + a) is True


def test_poles_at_no_sample_point_and_singular_expressions():
    e = (sp.sin(a) ** 2 + sp.cos(a) ** 2 - 1) / (a - b)
    assert sampled_zero_decision(e) is True
    assert sampled_zero_decision(sp.tan(a) * sp.cos(a) - sp.sin(a)) is True


def test_point_verdict_thresholds_at_their_boundaries():
    with mpmath.workdps(FOLD_DIGITS):
        largest = mpmath.mpf(7)
        zero_edge = FOLD_ZERO_RELATIVE * largest
        nonzero_edge = SAMPLED_NONZERO_RELATIVE * largest
        just = mpmath.mpf(10) ** -20
        assert _point_verdict(zero_edge, largest) is True
        assert _point_verdict(-zero_edge * (1 - just), largest) is True
        assert _point_verdict(zero_edge * (1 + just), largest) is None
        assert _point_verdict(nonzero_edge, largest) is None
        assert _point_verdict(nonzero_edge * (1 - just), largest) is None
        assert _point_verdict(-nonzero_edge * (1 + just), largest) is False
        assert _point_verdict(mpmath.mpf(0), mpmath.mpf(0)) is True
        assert _point_verdict(None, largest) is None
        assert _point_verdict(mpmath.inf, mpmath.inf) is None


def test_unevaluated_derivatives_follow_the_chain_rule():
    """An unevaluated derivative of an expression (not of a coordinate) is not an independent
    atom: d/dt sin(q) - cos(q) q' is the chain rule, zero; d/dt sin(q) - q' is not."""
    q = coordinates("q")
    identity = sp.Derivative(sp.sin(q), t) - sp.cos(q) * q.diff(t)
    assert not symbolic.nonzero_somewhere(identity)
    assert vanishes(identity)
    assert vanishes(sp.Derivative(q**2 * sp.cos(q), t) - q.diff(t) * sp.diff(q**2 * sp.cos(q), q))
    assert symbolic.nonzero_somewhere(sp.Derivative(sp.sin(q), t) - q.diff(t))
    assert not vanishes(sp.Derivative(sp.sin(q), t) - q.diff(t))
    # a derivative with respect to a symbol, and a second derivative of a coordinate (a leaf)
    assert vanishes(sp.Derivative(a * sp.sin(b), a) - sp.sin(b))
    assert not vanishes(sp.Derivative(q, (t, 2)) - q.diff(t))


def test_unevaluated_derivatives_follow_the_chain_rule_with_floats():
    """The same decision on the float path of vanishes (an expression with Float constants):
    0.5 d/dt sin(q) - 0.5 cos(q) q' is zero by the chain rule, 0.5 d/dt sin(q) - 0.5 q' is not."""
    q = coordinates("q")
    assert vanishes(0.5 * sp.Derivative(sp.sin(q), t) - 0.5 * sp.cos(q) * q.diff(t))
    assert not vanishes(0.5 * sp.Derivative(sp.sin(q), t) - 0.5 * q.diff(t))


def test_fold_numbers_folds_to_zero_only_what_the_sampled_rule_calls_zero():
    """fold_numbers and sampled_zero_decision make the same decision by the same rule: an
    expression that vanishes on the sampled interval only (Abs(v) - v is 0 for v > 0, and every
    sample of a symbol without a sign is in (0.5, 1.5)) is not folded to 0; an identity is."""
    v = sp.Symbol("v")
    pythagoras = sp.sin(v) ** 2 + sp.cos(v) ** 2 - 1
    cases = [sp.Abs(v) - v, sp.atan(sp.tan(v)) - v, sp.sqrt(v**2) - v, pythagoras,
             sp.Abs(m) - m]
    folded = symbolic.fold_numbers(cases)
    assert folded[0] == sp.Abs(v) - v
    assert folded[1] != 0 and folded[2] != 0
    assert folded[3] == 0 and folded[4] == 0
    assert [f == 0 for f in folded] == [sampled_zero_decision(e) is True for e in cases]


def test_fold_numbers_respects_integer_symbols_as_the_sampled_rule_does():
    """An integer symbol is not sampled (the rule of sampled_zero_decision): n - 1 is not 0
    (it was folded to 0, n being given the value 1 at both points)."""
    n = sp.Symbol("n", integer=True)
    v = sp.Symbol("v")
    assert sampled_zero_decision(n - 1) is None
    assert symbolic.fold_numbers([n - 1, v * (n - 1)]) == [n - 1, v * (n - 1)]
