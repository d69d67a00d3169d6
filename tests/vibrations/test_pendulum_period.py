"""The period of the simple pendulum (ch. 27.1.3): the exact 4 K(k)/omega0 against an
independent integration of theta'' = -omega0^2 sin(theta) (scipy, event at theta = 0, a quarter
period), and the small-amplitude series against Legendre's series of K expanded by sympy and
against the exact period to the stated order."""

import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from rigidmech._core.errors import ArgumentError
from rigidmech.vibrations import pendulum_period, pendulum_period_series
from rigidmech.vibrations.pendulum import PERIOD_SERIES


def integrated_period(theta0, omega0):
    def rhs(t, y):
        return [y[1], -omega0**2 * math.sin(y[0])]

    def crossing(t, y):
        return y[0]

    crossing.terminal, crossing.direction = True, -1
    sol = solve_ivp(rhs, (0, 100 / omega0), [theta0, 0.0], method="DOP853", rtol=1e-13,
                    atol=1e-14, events=crossing)
    return 4 * sol.t_events[0][0]


@pytest.mark.parametrize(("theta0", "omega0"), [(0.1, 1.0), (1.0, 3.0), (2.0, 0.5),
                                                (math.radians(170), 1.0), (3.1, 2.0)])
def test_exact_period_against_integration(theta0, omega0):
    assert pendulum_period(theta0, omega0) == pytest.approx(integrated_period(theta0, omega0),
                                                            rel=1e-10)


def test_zero_amplitude_is_the_linear_period_exactly():
    assert pendulum_period(0.0, 2.0) == math.pi
    assert pendulum_period_series(0.0, 2.0, order=8) == math.pi


def test_series_coefficients_are_legendres_series_of_K():
    th = sp.Symbol("theta0")
    k2 = sp.sin(th / 2) ** 2
    legendre = sum((sp.binomial(2 * j, j) / 4**j) ** 2 * k2**j for j in range(6))
    expansion = sp.series(legendre, th, 0, 10).removeO()
    assert [expansion.coeff(th, 2 * n) for n in range(5)] == list(PERIOD_SERIES)


@pytest.mark.parametrize("order", [0, 2, 4, 6, 8])
def test_series_error_is_of_the_stated_order(order):
    # (T_exact - T_series) / (T0 theta0^(order + 2)) -> next coefficient as theta0 -> 0
    next_coefficient = {0: 1 / 16, 2: 11 / 3072, 4: 173 / 737280, 6: 22931 / 1321205760,
                        8: None}[order]
    if next_coefficient is None:
        # the theta^10 coefficient of Legendre's series, from sympy
        th = sp.Symbol("t")
        k2 = sp.sin(th / 2) ** 2
        legendre = sum((sp.binomial(2 * j, j) / 4**j) ** 2 * k2**j for j in range(7))
        next_coefficient = float(sp.series(legendre, th, 0, 12).removeO().coeff(th, 10))
    theta0 = 0.05 if order < 6 else 0.2
    T0 = 2 * math.pi
    ratio = (pendulum_period(theta0, 1.0) - pendulum_period_series(theta0, 1.0, order)) / (
        T0 * theta0 ** (order + 2))
    assert ratio == pytest.approx(next_coefficient, rel=0.02)


def test_borda_at_ten_degrees():
    # at 10 degrees the linear period is short by about theta0^2/16 = 0.19 %, Borda's formula by
    # about 11 theta0^4/3072 = 3.3e-6 (the first terms left out)
    theta0 = math.radians(10)
    exact = pendulum_period(theta0, 1.0)
    assert 1 - pendulum_period_series(theta0, 1.0, 0) / exact == pytest.approx(
        theta0**2 / 16, rel=0.01)
    assert 1 - pendulum_period_series(theta0, 1.0, 2) / exact == pytest.approx(
        11 * theta0**4 / 3072, rel=0.01)


def test_arrays_broadcast():
    theta = np.array([0.0, 0.5, 1.0, 2.0])
    out = pendulum_period(theta, 1.0)
    assert out.shape == (4,)
    assert out[1] == pendulum_period(0.5, 1.0)
    assert pendulum_period_series(theta, 1.0, 4).shape == (4,)


def test_symbolic_series():
    th, w = sp.symbols("theta0 omega0", positive=True)
    T = pendulum_period_series(th, w, order=2)
    assert sp.simplify(T - 2 * sp.pi / w * (1 + th**2 / 16)) == 0


def test_amplitude_boundaries():
    assert pendulum_period(0.0, 1.0) == 2 * math.pi                       # lower end accepted
    near = pendulum_period(np.nextafter(math.pi, 0), 1.0)                  # just below pi
    assert math.isfinite(near) and near > 50
    with pytest.raises(ArgumentError, match=r"`amplitude` must lie in \[0, pi\) radians"):
        pendulum_period(math.pi, 1.0)                                      # at pi
    with pytest.raises(ArgumentError, match=r"`amplitude` must lie in \[0, pi\)"):
        pendulum_period(-1e-300, 1.0)                                      # just below 0


def test_near_separatrix_log_growth():
    # T omega0 = 4 K ~ 4 ln(4 / cos(theta0/2)) as theta0 -> pi (K(m) ~ ln(4 / sqrt(1 - m)))
    theta0 = math.pi - 1e-6
    expected = 4 * math.log(4 / math.cos(theta0 / 2))
    assert pendulum_period(theta0, 1.0) == pytest.approx(expected, rel=1e-10)


@pytest.mark.parametrize(("call", "match"), [
    (lambda: pendulum_period(4.0, 1.0), r"`amplitude` must lie in \[0, pi\).*revolves"),
    (lambda: pendulum_period(math.nan, 1.0), r"`amplitude` must lie in \[0, pi\)"),
    (lambda: pendulum_period("big", 1.0), r"`amplitude` must be a number"),
    (lambda: pendulum_period(0.5, 0.0), r"`omega0` must be finite and > 0"),
    (lambda: pendulum_period_series(0.5, 1.0, order=3), r"`order` must be one of 0, 2, 4, 6, 8"),
    (lambda: pendulum_period_series(0.5, 1.0, order=True), r"`order` must be one of"),
    (lambda: pendulum_period_series(0.5, -1.0), r"`omega0` must be finite and > 0"),
    (lambda: pendulum_period_series([0.5, 3.2], 1.0), r"`amplitude` must lie in \[0, pi\)"),
])
def test_bad_input(call, match):
    with pytest.raises(ArgumentError, match=match):
        call()
