"""Gragg-Bulirsch-Stoer extrapolation (the book's Romberg idea, ch. 26.2.3)."""

import numpy as np
import pytest
from _ode_exact import kepler_exact, kepler_initial, kepler_rhs
from numpy.testing import assert_allclose

from rigidmech import ode


@pytest.mark.parametrize("rtol", [1e-6, 1e-9, 1e-12])
def test_kepler_tolerance_proportionality(rtol):
    e, t_end = 0.6, 4 * np.pi
    r = ode.solve(kepler_rhs, (0.0, t_end), kepler_initial(e), method="gbs", rtol=rtol,
                  atol=rtol * 1e-2)
    exact = kepler_exact(t_end, e)
    rel = np.linalg.norm(r.y[:, -1] - exact) / np.linalg.norm(exact)
    # two eccentric orbits amplify the local errors (phase drift): measured factors <= 200
    assert rel < 1000 * rtol, rel


def test_order_rises_with_precision():
    def mean_order(rtol):
        r = ode.solve(kepler_rhs, (0.0, 2 * np.pi), kepler_initial(0.6), method="gbs",
                      rtol=rtol, atol=rtol * 1e-2)
        orders = r.stats["orders"]
        return sum(k * v for k, v in orders.items()) / sum(orders.values())

    assert mean_order(1e-12) > mean_order(1e-5) + 2


def test_high_order_on_a_polynomial_solution_is_exact():
    # y' = 5 t^4 has y = t^5: the midpoint rule's h^2 expansion terminates; extrapolation exact
    r = ode.solve(lambda t, y: 5 * t**4 * np.ones_like(y), (0.0, 2.0), [0.0], method="gbs",
                  rtol=1e-10)
    assert_allclose(r.y[0, -1], 32.0, rtol=1e-12)  # rounding of the tableau: 4e-13 measured


def test_k_max_limits_the_order():
    r = ode.solve(kepler_rhs, (0.0, 2 * np.pi), kepler_initial(0.6), method="gbs", rtol=1e-12,
                  k_max=4)
    assert max(r.stats["orders"]) <= 8


@pytest.mark.parametrize("rtol", [1e-6, 1e-11])
def test_float_and_numpy_paths_agree(rtol, monkeypatch):
    # one small trajectory runs the midpoint substeps and the tableau on lists of floats;
    # the numpy path (batches, n > FLOAT_PATH_MAX_N) is the same algorithm: same steps and
    # orders, states equal to rounding (sums in another order)
    from rigidmech.ode import extrapolation

    kw = dict(method="gbs", rtol=rtol, atol=rtol * 1e-3)
    y0 = kepler_initial(0.9)
    r_float = ode.solve(kepler_rhs, (0.0, 8.0), y0, **kw)
    monkeypatch.setattr(extrapolation, "FLOAT_PATH_MAX_N", 0)
    r_np = ode.solve(kepler_rhs, (0.0, 8.0), y0, **kw)
    assert r_float.nfev == r_np.nfev and r_float.nrejected == r_np.nrejected
    assert r_float.stats["orders"] == r_np.stats["orders"]
    assert_allclose(r_float.t, r_np.t, rtol=1e-9)
    assert_allclose(r_float.y, r_np.y, rtol=1e-9, atol=1e-12)


def test_float_path_keeps_fun_output_fresh():
    # fun returning one buffer reused across calls must not corrupt the float path either
    buf = np.empty(4)

    def same_buffer(t, y):
        buf[...] = kepler_rhs(t, y)
        return buf

    kw = dict(method="gbs", rtol=1e-9, atol=1e-12)
    y0 = kepler_initial(0.6)
    assert_allclose(ode.solve(same_buffer, (0.0, 5.0), y0, **kw).y,
                    ode.solve(kepler_rhs, (0.0, 5.0), y0, **kw).y, rtol=0, atol=0)
