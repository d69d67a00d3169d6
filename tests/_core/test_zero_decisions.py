"""One "is it zero?" function per meaning, all in rigidmech._core.symbolic (issue 15)."""

import ast
import pathlib

import pytest
import sympy as sp

import rigidmech
from rigidmech._core.symbolic import (
    is_exactly_zero,
    is_identically_zero,
    simplifies_to_zero,
    zero_decision,
)

a = sp.Symbol("a")
positive = sp.Symbol("p", positive=True)
PYTHAGORAS = sp.sin(a) ** 2 + sp.cos(a) ** 2 - 1


def test_no_other_zero_decision_in_the_package():
    package = pathlib.Path(rigidmech.__file__).parent
    defined = []
    for path in package.rglob("*.py"):
        for node in ast.parse(path.read_text()).body:  # module-level functions
            if isinstance(node, ast.FunctionDef) and node.name in ("_is_zero", "is_zero"):
                defined.append(f"{path.relative_to(package)}:{node.name}")
    assert defined == []


def test_the_four_meanings_differ_where_they_should():
    # structural: no algebra
    assert is_exactly_zero(sp.Float(0.0)) and not is_exactly_zero(PYTHAGORAS)
    # identically zero (simplify), exact numbers to 25 digits
    assert is_identically_zero(PYTHAGORAS)
    assert is_identically_zero(sp.cos(sp.pi / 5) - (1 + sp.sqrt(5)) / 4)
    assert not is_identically_zero(a)
    # trigonometric canonical form first: double angles
    assert simplifies_to_zero(sp.cos(2 * a) - sp.cos(a) ** 2 + sp.sin(a) ** 2)
    assert not simplifies_to_zero(sp.cos(a))
    # three-valued
    assert zero_decision(PYTHAGORAS) is True
    assert zero_decision(positive + 1) is False
    assert zero_decision(sp.Integer(3)) is False
    assert zero_decision(a) is None


def test_nonzero_somewhere_decides_cheaply_and_soundly():
    from rigidmech._core.symbolic import nonzero_somewhere
    from rigidmech.vectors import coordinates, t

    q = coordinates("q")
    a = sp.Symbol("a", positive=True)
    # identities are never reported non-zero
    assert not nonzero_somewhere(sp.sin(q) ** 2 + sp.cos(q) ** 2 - 1)
    assert not nonzero_somewhere(sp.cos(2 * q) - 1 + 2 * sp.sin(q) ** 2)
    assert not nonzero_somewhere(sp.sqrt(a**2) - a)
    # what does not vanish is seen at a sample point, derivatives and t included
    assert nonzero_somewhere(sp.sin(q) * q.diff(t) - a * q.diff(t))
    assert nonzero_somewhere(sp.Abs(sp.cos(q)) + t)
    # t can be kept out of the sample (then an expression in t only is not decided)
    assert not nonzero_somewhere(t, skip=(t,))
    # samples honour the assumptions: zero for every negative b, or every integer n
    b = sp.Symbol("b", negative=True)
    n = sp.Symbol("n", integer=True)
    assert not nonzero_somewhere(sp.Abs(b) + b + sp.Max(b, 0))
    assert not nonzero_somewhere(sp.Function("f")(n) * sp.sin(sp.pi * n))


def test_fold_numbers_zero_threshold_at_its_boundary():
    """An expression vanishes for fold_numbers when its value is at most FOLD_ZERO_RELATIVE
    times the largest magnitude met evaluating it, at both probe points (the per-point rule
    fold_numbers applies through probes.sampled_decisions)."""
    import mpmath

    from rigidmech._core.probes import _point_verdict
    from rigidmech._core.symbolic import FOLD_DIGITS, FOLD_ZERO_RELATIVE

    def _vanishes(value, largest):
        if value is None:
            return False
        return all(_point_verdict(v, m) is True for v, m in zip(value, largest, strict=True))

    with mpmath.workdps(FOLD_DIGITS):
        edge = FOLD_ZERO_RELATIVE * 7
        assert _vanishes([edge, -edge], [7, 7])
        assert not _vanishes([edge * (1 + mpmath.mpf(10) ** -20), 0], [7, 7])
        assert _vanishes([edge * (1 - mpmath.mpf(10) ** -20), 0], [7, 7])
        assert not _vanishes(None, None)


def test_fold_numbers_keeps_small_values_that_are_not_zero():
    from rigidmech._core.symbolic import fold_numbers

    tiny = sp.sqrt(2) * sp.Rational(1, 10**30)          # 1e-30 of itself: not a cancellation
    residue = (sp.sqrt(2) + a) ** 2 - a**2 - 2 * sp.sqrt(2) * a - 2 + sp.Rational(1, 10**30)
    folded = fold_numbers([tiny * a, residue])
    assert folded[0] != 0 and folded[1] != 0
    assert float(folded[0].subs(a, 1)) == pytest.approx(1.4142135623730951e-30, rel=1e-15)


def test_vanishes_with_scale_samples_the_symbols_of_the_expression(monkeypatch):
    """With ``scale``, the float path of ``vanishes`` evaluates the expression and its
    reference magnitude at the same sample point. The symbols were drawn from the magnitudes
    only, which turn sin and cos into 1: an angle inside a sine had no value, and every such
    row went to ``simplify(nsimplify(...))`` (a four-bar's closure conditions: 0.17 of its
    0.2 s), where float rounding counts as a term. Now: the four-bar's open rows are not zero,
    a rounding residue 6.9e-18 cos(q) next to terms cos(q) is, 1e-6 cos(q) is not, and
    ``simplify`` is not called."""
    import rigidmech as rm
    from rigidmech._core.symbolic import vanishes

    q1, q2, q3 = rm.coordinates("q1 q2 q3")
    x = -2.0 * sp.cos(q1 + q2) - 1.0 * sp.cos(q1) + 1.5 * sp.cos(q3) + 2.0
    y = -2.0 * sp.sin(q1 + q2) - 1.0 * sp.sin(q1) + 1.5 * sp.sin(q3)

    def refuse(*args, **kwargs):
        raise AssertionError("sympy.simplify called")

    monkeypatch.setattr(sp, "simplify", refuse)
    assert not vanishes(x, scale=[x, y]) and not vanishes(y, scale=[x, y])
    assert vanishes(6.9e-18 * sp.cos(q1), scale=[sp.cos(q1)])
    assert not vanishes(1e-6 * sp.cos(q1), scale=[sp.cos(q1)])
