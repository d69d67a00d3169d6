"""The constraint Jacobian at a generic point (the rank checks of the reduction) is evaluated
in one double-precision walk over its distinct subexpressions, not with sympy's ``evalf``
(issue 20: a second of the bicycle's linearisation); the values are evalf's to rounding."""

import numpy as np
import sympy as sp

from rigidmech import models
from rigidmech._core.symbolic import complex_values
from rigidmech.dynamics import reduced


def _jacobian():
    eqs = models.rolling_disc().system.equations_of_motion()
    A = reduced.plain_constraints(eqs)[0]
    return eqs, A, sorted(A.free_symbols, key=str)


def test_generic_jacobian_equals_evalf_without_calling_it(monkeypatch):
    eqs, A, symbols = _jacobian()
    rng = np.random.default_rng(20260)
    point = {s: sp.Float(v) for s, v in zip(symbols, rng.uniform(0.3, 1.3, len(symbols)),
                                            strict=True)}
    reference = np.array(A.xreplace(point).evalf().tolist(), dtype=complex).real

    def refuse(*args, **kwargs):
        raise AssertionError("evalf called")

    monkeypatch.setattr(sp.matrices.matrixbase.MatrixBase, "evalf", refuse)
    got = reduced._generic_jacobian(A, symbols)
    np.testing.assert_allclose(got, reference, rtol=1e-13, atol=1e-14)
    assert eqs.reduced().independent  # the reduction still chooses its dependent rates


def test_complex_values_falls_back_on_sympy_for_what_it_does_not_know():
    x = sp.Symbol("x")
    values = complex_values([sp.besselj(0, x) + x, sp.sqrt(x) * 2], {x: 0.25})
    assert abs(values[0] - (float(sp.besselj(0, 0.25)) + 0.25)) < 1e-15
    assert values[1] == 1.0


def test_generic_values_of_the_rank_checks_without_evalf(monkeypatch):
    from rigidmech import coordinates, t
    from rigidmech.systems.mobility import GenericValues

    q = coordinates("q")
    a = sp.Symbol("a", positive=True)
    expr = a * sp.cos(q) * q.diff(t) + sp.sqrt(a)
    numbers = GenericValues({a: 2.0}, seed=0)
    expected = None

    def refuse(*args, **kwargs):
        raise AssertionError("sympy.N called")

    monkeypatch.setattr(sp, "N", refuse)
    value = numbers(expr)
    monkeypatch.undo()
    rule = numbers._rule
    expected = float(sp.N(expr.xreplace(rule)))
    assert abs(value - expected) <= 1e-15 * abs(expected)
    assert numbers(expr) == value                      # the same configuration again
