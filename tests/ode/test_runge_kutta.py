"""Fixed-step explicit Runge-Kutta methods: observed orders of convergence (book, ch. 26.2)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from rigidmech import ode
from rigidmech.ode import runge_kutta, tableaux
from rigidmech.ode.runge_kutta import fixed_step_method


def rhs(t, y):
    """y' = y cos t, exact solution y = exp(sin t) (smooth, non-autonomous)."""
    return y * np.cos(t)


T_END = 2.0
EXACT = np.exp(np.sin(T_END))


@pytest.mark.parametrize(
    ("method", "order", "steps"),
    [
        # step ranges chosen in the asymptotic regime and far above rounding (errors 1e-3..1e-11)
        ("euler", 1, [400, 800, 1600, 3200, 6400]),
        ("heun", 2, [50, 100, 200, 400, 800]),
        ("midpoint", 2, [50, 100, 200, 400, 800]),
        ("rk4", 4, [40, 80, 160, 320]),
        ("rk38", 4, [40, 80, 160, 320]),
    ],
)
def test_observed_order_within_five_percent(method, order, steps):
    errors = []
    for n in steps:
        r = ode.solve(rhs, (0.0, T_END), [1.0], method=method, step=T_END / n)
        assert len(r.t) == n + 1
        errors.append(abs(r.y[0, -1] - EXACT))
    slope = np.polyfit(np.log(T_END / np.array(steps)), np.log(errors), 1)[0]
    assert abs(slope - order) < 0.05 * order, (slope, errors)


def test_nfev_is_stages_times_steps():
    r = ode.solve(rhs, (0.0, 1.0), [1.0], method="rk4", step=0.1)
    assert r.nfev == 40 and r.nsteps == 10 and r.nrejected == 0


def test_step_is_reduced_to_land_on_t1():
    r = ode.solve(rhs, (0.0, 1.0), [1.0], method="euler", step=0.3)
    assert_allclose(np.diff(r.t), 0.25)
    assert r.t[-1] == 1.0


def test_fixed_step_method_of_a_user_tableau():
    ralston = tableaux.ButcherTableau("ralston", [[0, 0], [2 / 3, 0]], [1 / 4, 3 / 4],
                                      [0, 2 / 3], order=2)
    fn = fixed_step_method(ralston)
    r = fn(rhs, (0.0, T_END), np.array([1.0]), step=T_END / 400)
    # second order: error ~ C h^2 with h = 5e-3; measured 3e-6
    assert_allclose(r.y[0, -1], EXACT, rtol=1e-5)
    with pytest.raises(TypeError, match=r"`tableau` must be a ButcherTableau; got str"):
        fixed_step_method("rk4")


def test_same_result_as_a_hand_written_rk4():
    h, y, t = 0.1, 1.0, 0.0
    for _ in range(20):
        k1 = y * np.cos(t)
        k2 = (y + h / 2 * k1) * np.cos(t + h / 2)
        k3 = (y + h / 2 * k2) * np.cos(t + h / 2)
        k4 = (y + h * k3) * np.cos(t + h)
        y, t = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4), t + h
    r = ode.solve(rhs, (0.0, 2.0), [1.0], method="rk4", step=0.1)
    assert_allclose(r.y[0, -1], y, rtol=1e-14)


@pytest.mark.parametrize("method", ["euler", "heun", "midpoint", "rk4", "rk38"])
def test_float_and_numpy_kernels_agree(method, monkeypatch):
    def osc(t, y):
        return np.array([y[1], -y[0] + np.sin(t)])

    r_float = ode.solve(osc, (0.0, 3.0), [1.0, 0.0], method=method, step=0.01)
    monkeypatch.setattr(runge_kutta, "FLOAT_PATH_MAX_N", 0)  # force the numpy kernel
    r_np = ode.solve(osc, (0.0, 3.0), [1.0, 0.0], method=method, step=0.01)
    assert r_float.nfev == r_np.nfev == 300 * tableaux.ALL[method].stages
    # same operations in another order: rounding only, over 300 steps
    assert_allclose(r_float.y, r_np.y, rtol=1e-12, atol=1e-13)


def test_float_kernel_not_used_when_fun_returns_a_list():
    r = ode.solve(lambda t, y: [-y[0]], (0.0, 1.0), [1.0], method="rk4", step=0.1)
    assert_allclose(r.y[0, -1], 0.36787977441, rtol=1e-10)  # same as the ndarray version
