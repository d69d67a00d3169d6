"""Critical damping and the damping ratio <-> coefficient conversions (ch. 21.3.2).

Independent check: c_c is the damping at which the characteristic equation m s^2 + c s + k = 0
has a double root (zero discriminant), i.e. where the free motion stops oscillating."""

import math

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

from rigidmech._core.errors import ArgumentError
from rigidmech.vibrations import (
    critical_damping,
    damping_case,
    damping_coefficient,
    damping_ratio,
)


def test_critical_damping_is_the_double_root_of_the_characteristic_equation():
    k, m, s = sp.symbols("k m s", positive=True)
    c_c = critical_damping(k, m)
    assert sp.simplify(sp.discriminant(m * s**2 + c_c * s + k, s)) == 0


@pytest.mark.parametrize(("k", "m"), [(400.0, 4.0), (1.0, 1.0), (2.5e6, 0.03)])
def test_critical_damping_numeric_and_either_side(k, m):
    c_c = critical_damping(k, m)
    assert c_c == pytest.approx(2 * math.sqrt(k * m), rel=1e-15)
    # just below: complex roots (oscillation); just above: two distinct real roots
    below = np.roots([m, c_c * (1 - 1e-6), k])
    above = np.roots([m, c_c * (1 + 1e-6), k])
    assert np.all(np.abs(below.imag) > 0)
    assert np.all(above.imag == 0) and above[0] != above[1]


def test_critical_damping_gives_ratio_one_and_the_critical_case():
    k, m = 400.0, 4.0
    assert damping_ratio(critical_damping(k, m), k, m) == 1.0
    assert damping_case(damping_ratio(critical_damping(k, m), k, m)) == "critical"
    assert damping_case(damping_ratio(np.nextafter(80.0, 0), k, m)) == "underdamped"
    assert damping_case(damping_ratio(np.nextafter(80.0, 100), k, m)) == "overdamped"


def test_damping_coefficient_inverts_damping_ratio():
    zeta = np.array([0.0, 0.05, 0.7, 1.0, 3.0])
    c = damping_coefficient(zeta, 400.0, 4.0)
    assert_allclose(c, zeta * 80.0, rtol=1e-15)
    assert_allclose(damping_ratio(c, 400.0, 4.0), zeta, rtol=1e-15)


def test_symbolic_round_trip():
    z, c, k, m = sp.symbols("zeta c k m", positive=True)
    assert sp.simplify(damping_ratio(damping_coefficient(z, k, m), k, m) - z) == 0
    assert sp.simplify(damping_coefficient(damping_ratio(c, k, m), k, m) - c) == 0
    assert critical_damping(sp.Integer(4), sp.Integer(1)) == 4


def test_zero_zeta_accepted_negative_refused():
    assert damping_coefficient(0.0, 1.0, 1.0) == 0.0                      # boundary
    assert damping_coefficient(1e-300, 1.0, 1.0) > 0                       # just inside
    with pytest.raises(ArgumentError, match=r"`zeta` must be finite and >= 0; got -1e-300"):
        damping_coefficient(-1e-300, 1.0, 1.0)                             # just outside


@pytest.mark.parametrize(("call", "match"), [
    (lambda: critical_damping(0.0, 1.0), r"`stiffness` must be finite and > 0; got 0.0"),
    (lambda: critical_damping(1.0, -1.0), r"`mass` must be finite and > 0; got -1.0"),
    (lambda: critical_damping(math.inf, 1.0), r"`stiffness` must be finite and > 0"),
    (lambda: critical_damping(1.0, [1.0, 0.0]), r"`mass` must be finite and > 0"),
    (lambda: critical_damping(sp.Symbol("k", negative=True), 1.0), r"`stiffness` must be > 0"),
    (lambda: damping_coefficient(math.nan, 1.0, 1.0), r"`zeta` must be finite and >= 0"),
    (lambda: damping_coefficient(sp.Symbol("z", negative=True), 1.0, 1.0),
     r"`zeta` must be >= 0"),
    (lambda: damping_coefficient(0.1, 1.0, 0.0), r"`mass` must be finite and > 0"),
    (lambda: damping_ratio(1.0, 0.0, 1.0), r"`stiffness` must be finite and > 0"),
])
def test_bad_input_refused(call, match):
    with pytest.raises(ArgumentError, match=match):
        call()


def test_tiny_positive_stiffness_accepted():
    assert critical_damping(1e-300, 1.0) == pytest.approx(2e-150)
