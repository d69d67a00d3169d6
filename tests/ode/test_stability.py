"""Stability function, real stability interval and observed order (ch. 26; rigidmech.ode.stability).

Reference values: a method of order p with p stages has R(z) = sum_{k<=p} z^k/k!; DOPRI5 has
R(z) = sum_{k<=5} z^k/k! + z^6/600 (Hairer-Wanner II, Sec. IV.2); the ends of the real
stability intervals are roots of R(x) - 1 or R(x) + 1, found here independently by numpy.roots.
"""

import math

import numpy as np
import pytest

from rigidmech import ode
from rigidmech._core.errors import ArgumentError, ArgumentTypeError, NumericalError
from rigidmech.ode import tableaux as T
from rigidmech.ode.stability import (
    is_stable,
    observed_order,
    real_stability_interval,
    stability_function,
    stability_polynomial,
)
from rigidmech.testing import problems

ZS = np.array([-2.5, -1.0 + 1.0j, 0.3 - 2.0j, 1.5j, 0.0])


def taylor(z, p):
    return sum(z**k / math.factorial(k) for k in range(p + 1))


@pytest.mark.parametrize(("tab", "p"), [(T.EULER, 1), (T.HEUN, 2), (T.MIDPOINT, 2), (T.RK4, 4),
                                        (T.RK38, 4), (T.BS32, 3)])
def test_stability_function_is_the_taylor_polynomial_when_stages_equal_order(tab, p):
    np.testing.assert_allclose(stability_function(tab, ZS), taylor(ZS, p), rtol=0, atol=1e-13)


def test_dopri5_stability_function_hairer_wanner():
    expected = taylor(ZS, 5) + ZS**6 / 600
    np.testing.assert_allclose(stability_function(T.DOPRI5, ZS), expected, rtol=0, atol=1e-13)
    np.testing.assert_allclose(stability_polynomial(T.DOPRI5)[:7],
                               [1, 1, 1 / 2, 1 / 6, 1 / 24, 1 / 120, 1 / 600], rtol=1e-13)
    assert stability_polynomial(T.DOPRI5)[7] == pytest.approx(0.0, abs=1e-15)  # FSAL: b_7 = 0


@pytest.mark.parametrize("tab", list(T.ALL.values()), ids=list(T.ALL))
def test_polynomial_and_resolvent_forms_agree(tab):
    poly = np.polynomial.polynomial.polyval(ZS, stability_polynomial(tab))
    np.testing.assert_allclose(stability_function(tab, ZS), poly, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("name", ["euler", "heun", "midpoint", "rk4", "rk38"])
def test_one_step_of_the_solver_multiplies_by_R(name):
    lam, h = -1.7 + 0.4j, 0.8
    # y' = lam y in real form: y = [Re, Im]
    a = np.array([[lam.real, -lam.imag], [lam.imag, lam.real]])
    r = ode.solve(lambda t, y: a @ y, (0.0, h), np.array([1.0, 0.0]), method=name, step=h)
    y1 = complex(r.y[0, -1], r.y[1, -1])
    assert abs(y1 - complex(stability_function(name, lam * h))) < 1e-14


def test_shapes_scalar_and_grid():
    assert stability_function(T.RK4, -1.0).shape == ()
    grid = np.zeros((3, 5))
    assert stability_function(T.RK4, grid).shape == (3, 5)
    assert is_stable(T.RK4, -1.0) is True
    assert is_stable(T.RK4, grid).shape == (3, 5)


def _interval_end(gamma):
    """Largest-magnitude-first free route: the negative real root of R -+ 1 closest to 0 beyond
    which |R| > 1 (checked just past it)."""
    poly = np.polynomial.Polynomial(gamma)
    roots = []
    for shifted in (poly - 1, poly + 1):
        for r in shifted.roots():
            if abs(r.imag) < 1e-9 and r.real < -1e-9:
                roots.append(r.real)
    for r in sorted(roots, reverse=True):
        if abs(poly(r - 1e-6)) > 1:
            return r
    raise AssertionError


@pytest.mark.parametrize(("tab", "expected"), [
    (T.EULER, -2.0), (T.HEUN, -2.0), (T.MIDPOINT, -2.0),
    (T.RK4, -2.785293563405282),   # real root of x^3 + 4x^2 + 12x + 24
    (T.RK38, -2.785293563405282),
    (T.DOPRI5, -3.3066),           # Hairer-Wanner II, Sec. IV.2 (to 4 decimals)
    (T.BS32, -2.5127),             # real root of x^2 + 3x + 6 = ... (R = 1 + x + x^2/2 + x^3/6)
])
def test_real_stability_interval_known_values(tab, expected):
    x_min, right = real_stability_interval(tab)
    assert right == 0.0
    assert x_min == pytest.approx(expected, abs=1e-4)
    assert x_min == pytest.approx(_interval_end(stability_polynomial(tab)), abs=1e-12)


def test_euler_and_heun_ends_are_exact():
    assert real_stability_interval(T.EULER) == (-2.0, 0.0)
    assert real_stability_interval("heun") == (-2.0, 0.0)


def test_rk4_end_is_the_real_root_of_the_cubic():
    (root,) = [r.real for r in np.roots([1, 4, 12, 24]) if abs(r.imag) < 1e-12]
    assert real_stability_interval(T.RK4)[0] == pytest.approx(root, abs=1e-13)


@pytest.mark.parametrize("tab", list(T.ALL.values()), ids=list(T.ALL))
def test_boundary_of_the_interval_and_either_side(tab):
    x_min, _ = real_stability_interval(tab)
    assert is_stable(tab, x_min)                                   # the end itself
    assert not is_stable(tab, np.nextafter(x_min, -np.inf))        # one float beyond
    assert is_stable(tab, x_min + 1e-9)                            # just inside
    assert not is_stable(tab, x_min - 1e-9)                        # just outside
    assert abs(abs(complex(stability_function(tab, x_min))) - 1) < 1e-12
    inside = np.linspace(x_min, 0, 2001)
    assert is_stable(tab, inside).all()


def test_is_stable_boundary_rule_on_euler():
    # |R| = |1 + z| <= 1: the closed disc of centre -1, radius 1
    assert is_stable(T.EULER, -2.0) and is_stable(T.EULER, 0.0) and is_stable(T.EULER, -1 + 1j)
    assert not is_stable(T.EULER, np.nextafter(-2.0, -3.0))
    assert not is_stable(T.EULER, 1e-12)


def test_inconsistent_and_trivial_tableaux():
    backwards = T.ButcherTableau("backwards", [[0.0]], [-1.0], [0.0], order=1)
    x_min, right = real_stability_interval(backwards)   # R = 1 - x: unstable left of 0
    assert right == 0.0 and -1e-15 < x_min <= 0.0          # rounding of 1 - x only
    still = T.ButcherTableau("still", [[0.0]], [0.0], [0.0], order=1)
    assert real_stability_interval(still) == (-math.inf, 0.0)


@pytest.mark.parametrize(("args", "error", "match"), [
    ((42, -1.0), ArgumentTypeError, r"`tableau` must be a ButcherTableau or the name"),
    (("rk5", -1.0), ArgumentError, r"`tableau` must be a ButcherTableau or one of \["),
    ((T.RK4, np.nan), ArgumentError, r"`z` must be finite; got nan"),
    ((T.RK4, "abc"), ArgumentTypeError, r"`z` must be a complex number"),
])
def test_bad_input_refused(args, error, match):
    with pytest.raises(error, match=match):
        stability_function(*args)


# --- observed order ---------------------------------------------------------------------------

OSC = problems.damped_oscillator(t_end=1.0)


@pytest.mark.parametrize(("method", "order", "steps"), [
    ("euler", 1, [2e-4, 1e-4, 5e-5]),
    ("heun", 2, [2e-3, 1e-3, 5e-4]),
    ("midpoint", 2, [2e-3, 1e-3, 5e-4]),
    ("rk4", 4, [1e-2, 5e-3, 2.5e-3]),
    (T.RK38, 4, [1e-2, 5e-3, 2.5e-3]),
])
def test_observed_order_on_the_damped_oscillator(method, order, steps):
    c = observed_order(method, OSC.fun, OSC.t_span, OSC.y0, OSC.exact, steps)
    assert c.order == pytest.approx(order, abs=0.05)
    assert len(c.errors) == len(c.steps) == 3 and len(c.slopes) == 2
    assert all(e2 < e1 for e1, e2 in zip(c.errors, c.errors[1:], strict=False))


def test_observed_order_on_kepler_with_exact_final_state_array():
    p = problems.kepler(0.3, orbits=1.0)
    steps = [p.t_span[1] / n for n in (800, 1600, 3200)]
    c = observed_order("rk4", p.fun, p.t_span, p.y0, p.exact(p.t_span[1]), steps)
    assert c.order == pytest.approx(4.0, abs=0.05)
    assert c.slopes[1] < c.slopes[0]        # the local slopes tend to 4 from above
    assert c.steps == pytest.approx(tuple(steps), rel=1e-12)


def test_steps_reported_are_those_taken():
    # 0.3 does not divide 1: solve takes 4 steps of 0.25
    c = observed_order("euler", lambda t, y: -y, (0.0, 1.0), [1.0],
                       lambda t: np.exp(-np.array([t])), [0.3, 0.1])
    assert c.steps[0] == pytest.approx(0.25)


@pytest.mark.parametrize(("steps", "error", "match"), [
    ([0.1], ArgumentError, r"`steps` must hold at least two steps"),
    ([0.1, -0.05], ArgumentError, r"`steps` must be finite and > 0"),
    ([0.1, np.inf], ArgumentError, r"`steps` must be finite and > 0"),
    ([0.1, 0.1], ArgumentError, r"`steps` must be distinct"),
    ([0.1, "a"], ArgumentTypeError, r"`steps` must be a sequence of numbers"),
])
def test_observed_order_bad_steps(steps, error, match):
    with pytest.raises(error, match=match):
        observed_order("rk4", lambda t, y: -y, (0.0, 1.0), [1.0], [math.exp(-1)], steps)


def test_observed_order_bad_t_span():
    with pytest.raises(ArgumentTypeError, match=r"`t_span` must be a pair of numbers"):
        observed_order("rk4", lambda t, y: -y, None, [1.0], [1.0], [0.1, 0.05])
    with pytest.raises(ArgumentTypeError, match=r"`t_span` must be a pair of numbers"):
        observed_order("rk4", lambda t, y: -y, (0.0, 1.0, 2.0), [1.0], [1.0], [0.1, 0.05])


def test_observed_order_bad_exact_shape():
    with pytest.raises(ArgumentError, match=r"`exact` must give a state of the shape"):
        observed_order("rk4", lambda t, y: -y, (0.0, 1.0), [1.0], [1.0, 2.0], [0.1, 0.05])


def test_observed_order_refuses_a_zero_error():
    # Euler is exact on y' = 1
    with pytest.raises(ArgumentError, match=r"the error is exactly 0 at `step`"):
        observed_order("euler", lambda t, y: np.ones_like(y), (0.0, 1.0), [0.0], [1.0],
                       [0.5, 0.25])


def test_observed_order_reports_a_failed_run():
    # h lambda = -1e5: far outside Euler's interval, the state overflows
    with pytest.raises(NumericalError, match=r"the run with `step` = 0.1 failed"):
        observed_order("euler", lambda t, y: -1e6 * y, (0.0, 100.0), [1.0], [0.0], [0.1, 0.05])
