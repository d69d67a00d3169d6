"""Batches: y0 of shape (n, batch) integrates many initial states at once."""

import numpy as np
import pytest
from _ode_exact import kepler_initial, kepler_rhs
from numpy.testing import assert_allclose

from rigidmech import ode


def pendulum(t, y):
    """Works on (2,) and on (2, batch) arrays alike."""
    return np.stack([y[1], -np.sin(y[0])])


ANGLES = np.array([0.1, 1.0, 2.0, 3.0])
Y0 = np.stack([ANGLES, np.zeros_like(ANGLES)])  # (2, 4)


@pytest.mark.parametrize("method", ["euler", "heun", "rk4", "rk38"])
def test_fixed_step_batch_equals_loop(method):
    rb = ode.solve(pendulum, (0.0, 5.0), Y0, method=method, step=0.01)
    assert rb.y.shape == (2, 501, 4)
    for j in range(Y0.shape[1]):
        rj = ode.solve(pendulum, (0.0, 5.0), Y0[:, j], method=method, step=0.01)
        # the same floating-point operations per column: equal to rounding
        assert_allclose(rb.y[:, :, j], rj.y, rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize("method", ["dopri5", "dop853", "gbs", "radau"])
def test_adaptive_batch_of_copies_equals_single(method):
    # identical trajectories: the max norm over the batch is the single norm, so the same
    # steps are taken. The error estimates cancel ~8 digits, so the different order of the
    # floating-point sums in the batched code shows in the 8th digit of the step sizes (and
    # of the states at those slightly shifted times); at the common final time the states
    # agree to rounding (measured <= 1e-13)
    y0 = np.repeat(kepler_initial(0.6)[:, None], 3, axis=1)
    rb = ode.solve(kepler_rhs, (0.0, 7.0), y0, method=method, rtol=1e-8)
    rs = ode.solve(kepler_rhs, (0.0, 7.0), y0[:, 0], method=method, rtol=1e-8)
    assert rb.nsteps == rs.nsteps and rb.nfev == rs.nfev
    assert_allclose(rb.t, rs.t, rtol=1e-6)
    for j in range(3):
        assert_allclose(rb.y[:, -1, j], rs.y[:, -1], rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("method", ["dopri5", "dop853", "gbs", "radau"])
def test_adaptive_batch_shared_step_meets_tolerance_for_each(method):
    rb = ode.solve(pendulum, (0.0, 5.0), Y0, method=method, rtol=1e-9, atol=1e-12,
                   dense_output=True)
    for j in range(Y0.shape[1]):
        rj = ode.solve(pendulum, (0.0, 5.0), Y0[:, j], method=method, rtol=1e-11, atol=1e-13)
        # shared steps are at least as small as each trajectory needs: error ~ rtol
        assert_allclose(rb.y[:, -1, j], rj.y[:, -1], atol=1e-7)
    assert rb.sol(2.5).shape == (2, 4)
    assert rb.sol([1.0, 2.0]).shape == (2, 2, 4)


def test_batch_t_eval_shape():
    r = ode.solve(pendulum, (0.0, 1.0), Y0, method="dop853", t_eval=[0.25, 0.5])
    assert r.y.shape == (2, 2, 4)
    r = ode.solve(pendulum, (0.0, 1.0), Y0, method="rk4", step=0.01, t_eval=[0.25, 0.5])
    assert r.y.shape == (2, 2, 4)
