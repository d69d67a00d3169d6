"""Adams-Bashforth and Adams-Bashforth-Moulton PECE (rigidmech.ode.multistep, book 26.3)."""

from fractions import Fraction as Fr

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from rigidmech import ode
from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.ode import multistep as M
from rigidmech.testing.problems import damped_oscillator

# Classical tables (Hairer-Norsett-Wanner I, III.1, Tables 1.1 and 1.2; the book's 26.3.4).
AB_TABLE = {
    1: [Fr(1)],
    2: [Fr(3, 2), Fr(-1, 2)],
    3: [Fr(23, 12), Fr(-16, 12), Fr(5, 12)],
    4: [Fr(55, 24), Fr(-59, 24), Fr(37, 24), Fr(-9, 24)],
    5: [Fr(1901, 720), Fr(-2774, 720), Fr(2616, 720), Fr(-1274, 720), Fr(251, 720)],
}
AM_TABLE = {
    1: [Fr(1)],
    2: [Fr(1, 2), Fr(1, 2)],
    3: [Fr(5, 12), Fr(8, 12), Fr(-1, 12)],
    4: [Fr(9, 24), Fr(19, 24), Fr(-5, 24), Fr(1, 24)],
    5: [Fr(251, 720), Fr(646, 720), Fr(-264, 720), Fr(106, 720), Fr(-19, 720)],
}


@pytest.mark.parametrize("k", range(1, 6))
def test_derived_coefficients_equal_the_classical_tables(k):
    assert list(M.adams_bashforth_coefficients(k)) == AB_TABLE[k]
    assert list(M.adams_moulton_coefficients(k)) == AM_TABLE[k]


@pytest.mark.parametrize("k", range(1, 7))
def test_coefficients_integrate_polynomials_exactly(k):
    # order k <=> exact for y' = s^q, q < k: sum_i beta_i (-i)^q = int_0^1 s^q ds (AB),
    # sum_i beta*_i (1 - i)^q = 1 / (q + 1) (AM)
    ab = M.adams_bashforth_coefficients(k)
    am = M.adams_moulton_coefficients(k)
    for q in range(k):
        assert sum(b * Fr(-i) ** q for i, b in enumerate(ab)) == Fr(1, q + 1)
        assert sum(b * Fr(1 - i) ** q for i, b in enumerate(am)) == Fr(1, q + 1)
    # and not of order k + 1: the error constant is gamma_k
    assert sum(b * Fr(-i) ** k for i, b in enumerate(ab)) != Fr(1, k + 1)


# (method, order, step counts in the asymptotic range above the rounding floor of about 1e-13;
# the errors were checked to halve by 2**order per halving of h there)
ORDERS = [
    ("ab1", 1, [1600, 3200, 6400, 12800]),
    ("ab2", 2, [800, 1600, 3200, 6400]),
    ("ab3", 3, [1600, 3200, 6400, 12800]),
    ("ab4", 4, [800, 1600, 3200, 6400]),
    ("ab5", 5, [400, 800, 1600, 3200]),
    ("abm2", 2, [800, 1600, 3200, 6400]),
    ("abm3", 3, [1600, 3200, 6400, 12800]),
    ("abm4", 4, [800, 1600, 3200, 6400]),
    ("abm5", 5, [400, 800, 1600, 3200]),
]


@pytest.mark.parametrize(("method", "order", "counts"), ORDERS, ids=[o[0] for o in ORDERS])
def test_observed_convergence_order(method, order, counts):
    p = damped_oscillator(t_end=1.0)  # smooth, closed form with transient (21.3.3)
    hs, errs = [], []
    for n in counts:
        h = 1.0 / n
        r = ode.solve(p.fun, p.t_span, p.y0, method=method, step=h)
        hs.append(h)
        errs.append(p.final_error(r.y[:, -1]))
    slope = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert abs(slope - order) <= 0.05 * order, (slope, errs)


def test_pece_is_more_accurate_than_its_predictor():
    # error constants: |gamma*_4| = 19/720 vs gamma_4 = 251/720 (about 13x)
    p = damped_oscillator(t_end=1.0)
    e_ab = p.final_error(ode.solve(p.fun, p.t_span, p.y0, method="ab4", step=1e-3).y[:, -1])
    e_abm = p.final_error(ode.solve(p.fun, p.t_span, p.y0, method="abm4", step=1e-3).y[:, -1])
    assert 5 < e_ab / e_abm < 30


@pytest.mark.parametrize("method", ["ab3", "abm4"])
def test_batch_equals_single_runs(method):
    p = damped_oscillator(t_end=1.0)
    y0 = np.stack([p.y0, [0.0, 1.0], [2.0, -3.0]], axis=1)
    rb = ode.solve(p.fun, p.t_span, y0, method=method, step=0.01)
    assert rb.y.shape == (2, 101, 3)
    for j in range(3):
        r = ode.solve(p.fun, p.t_span, y0[:, j], method=method, step=0.01)
        assert_allclose(rb.y[:, :, j], r.y, rtol=1e-14, atol=1e-14)
        assert r.nfev == rb.nfev


def test_evaluation_counts_and_grid():
    f = lambda t, y: -y  # noqa: E731
    r = M.adams_bashforth(f, (0.0, 1.0), [1.0], step=0.1, order=5)
    # 1 at t0, 4 starting RK4 steps x 4 + 1 each, then 1 per step
    assert r.nfev == 1 + 4 * 5 + 6
    assert r.nsteps == 10 and len(r.t) == 11 and r.t[-1] == 1.0
    r = M.adams_bashforth_moulton(f, (0.0, 1.0), [1.0], step=0.1, order=2)
    assert r.nfev == 1 + 5 + 2 * 9
    assert r.method == "abm2" and r.success


def test_backwards_in_time():
    r = ode.solve(lambda t, y: -y, (1.0, 0.0), [np.exp(-1.0)], method="abm5", step=1e-3)
    assert_allclose(r.y[0, -1], 1.0, rtol=1e-12)  # local errors ~ h^6, 1000 steps


def test_save_every_and_dense_output():
    r = M.adams_bashforth(lambda t, y: np.cos(t) * np.ones_like(y), (0.0, 1.0), [0.0],
                          step=0.001, order=4, save_every=100, dense_output=True)
    assert len(r.t) == 11 and r.nsteps == 1000
    # cubic Hermite over 0.1-wide intervals: error <= h^4 max|y''''| / 384 = 2.6e-7
    assert_allclose(r.sol(0.55)[0], np.sin(0.55), atol=3e-7)


def test_non_finite_state_is_reported():
    r = ode.solve(lambda t, y: y * y, (0.0, 2.0), [1.0], method="ab2", step=1e-3)
    assert r.status == -1 and not r.success
    assert "non-finite at t = " in r.message
    assert r.t[-1] < 2.0


@settings(max_examples=20, deadline=None)
@given(st.integers(1, 5), st.lists(st.floats(-3, 3), min_size=1, max_size=5))
def test_polynomial_right_hand_sides_are_integrated_exactly(k, c):
    # y' = polynomial in t of degree < k: AB of order k is exact; so is the RK4 start
    # (Simpson's rule) up to degree 3, hence degree < min(k, 4)
    deg = min(len(c), k, 4) - 1
    poly = np.polynomial.Polynomial(c[: deg + 1])
    r = M.adams_bashforth(lambda t, y: poly(t) * np.ones_like(y), (0.0, 2.0), [0.0],
                          step=0.125, order=k)
    expected = poly.integ()(2.0)
    assert_allclose(r.y[0, -1], expected, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda: M.adams_bashforth(np.sin, (0, 1), [1.0], step=0.1, order=6), ArgumentError,
         r"`order` must be an integer in 1..5; got 6"),
        (lambda: M.adams_bashforth_moulton(np.sin, (0, 1), [1.0], step=0.1, order=1),
         ArgumentError, r"`order` must be an integer in 2..5; got 1"),
        (lambda: M.adams_bashforth(np.sin, (0, 1), [1.0], step=None), ArgumentTypeError,
         r"`step` must be a number > 0"),
        (lambda: M.adams_bashforth(np.sin, (0, 1), [1.0], step=0.0), ArgumentError,
         r"`step` must be a finite nonzero number"),
        (lambda: M.adams_bashforth(np.sin, (1, 1), [1.0], step=0.1), ArgumentError,
         r"`t_span` must be two distinct finite times"),
        (lambda: M.adams_bashforth(np.sin, (0, 1), [1.0], step=0.1, max_steps=5),
         ArgumentError, r"needs 10 steps .* more than `max_steps` = 5"),
        (lambda: M.adams_bashforth(np.sin, (0, 1), [1.0], step=0.1, save_every=0),
         ArgumentError, r"`save_every` must be an integer >= 1"),
        (lambda: M.adams_bashforth(np.sin, (0, 1), [np.nan], step=0.1), ArgumentError,
         r"`y0` must be finite"),
    ],
)
def test_errors(call, exc, match):
    with pytest.raises(exc, match=match):
        call()
