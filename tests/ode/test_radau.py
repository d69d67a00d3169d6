"""Radau IIA (order 5) on stiff problems; comparison with explicit methods and with scipy."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp
from scipy.linalg import expm

from rigidmech import ode
from rigidmech._core.errors import ArgumentError

# stiff linear system y' = M y, eigenvalues -1, -100, -1e4 mixed by a rotation
_c, _s = np.cos(0.3), np.sin(0.3)
_Q = np.array([[_c, -_s, 0.0], [_s, _c, 0.0], [0.0, 0.0, 1.0]]) @ np.array(
    [[1.0, 0.0, 0.0], [0.0, _c, -_s], [0.0, _s, _c]])
M = _Q @ np.diag([-1.0, -100.0, -1.0e4]) @ _Q.T
Y0 = np.array([1.0, 2.0, -1.0])


def linear(t, y):
    return M @ y


def vdp(t, y, mu=1000.0):
    return np.array([y[1], mu * (1 - y[0] ** 2) * y[1] - y[0]])


def test_stiff_linear_system_against_matrix_exponential():
    r = ode.solve(linear, (0.0, 10.0), Y0, method="radau", rtol=1e-8, atol=1e-12)
    exact = expm(10.0 * M) @ Y0
    assert r.status == 0
    # global error of an L-stable order-5 method at rtol 1e-8: measured 3e-10 relative
    assert_allclose(r.y[:, -1], exact, rtol=1e-7, atol=1e-12)
    # the step is driven by accuracy, not by the eigenvalue -1e4: an explicit method would
    # need h < 3.3e-4, i.e. > 30000 steps (measured here: about 800, mostly in the transients)
    assert r.nsteps < 1500
    assert r.stats["njev"] >= 1 and r.stats["nlu"] >= 1


def test_explicit_method_needs_far_more_steps_and_warns():
    with pytest.warns(ode.StiffnessWarning, match=r"use method='radau'"):
        re = ode.solve(linear, (0.0, 1.0), Y0, method="dop853", rtol=1e-6, nstiff=10)
    ri = ode.solve(linear, (0.0, 1.0), Y0, method="radau", rtol=1e-6)
    assert re.nsteps > 10 * ri.nsteps


def test_van_der_pol_mu_1000_matches_scipy_radau():
    r = ode.solve(vdp, (0.0, 3000.0), [2.0, 0.0], method="radau", rtol=1e-6, atol=1e-6)
    s = solve_ivp(vdp, (0.0, 3000.0), [2.0, 0.0], method="Radau", rtol=1e-6, atol=1e-6)
    assert r.status == 0
    # same method, same controller: final states agree to the tolerance level, similar work
    assert_allclose(r.y[0, -1], s.y[0, -1], rtol=1e-5)
    assert 0.8 < r.nsteps / (len(s.t) - 1) < 1.25


def test_user_jacobian_gives_the_same_solution():
    calls = []

    def jac(t, y):
        calls.append(t)
        return M

    r1 = ode.solve(linear, (0.0, 1.0), Y0, method="radau", rtol=1e-8, jac=jac)
    r2 = ode.solve(linear, (0.0, 1.0), Y0, method="radau", rtol=1e-8)
    assert calls and r1.stats["njev"] == len(calls)
    assert_allclose(r1.y[:, -1], r2.y[:, -1], rtol=1e-8, atol=1e-12)
    with pytest.raises(ArgumentError, match=r"`jac\(t, y\)` must return an array of shape "
                       r"\(3, 3\); got \(2, 2\)"):
        ode.solve(linear, (0.0, 1.0), Y0, method="radau", jac=lambda t, y: np.eye(2))


def test_batch_jacobian_and_dense_output():
    y0 = np.stack([Y0, 2 * Y0], axis=1)  # (3, 2); linear: second column is twice the first
    r = ode.solve(linear, (0.0, 2.0), y0, method="radau", rtol=1e-9, atol=1e-12,
                  dense_output=True)
    assert_allclose(r.y[:, -1, 1], 2 * r.y[:, -1, 0], rtol=1e-9, atol=1e-14)
    exact = expm(1.0 * M) @ Y0
    # collocation polynomial (order 3 in x, stage order 3): 1e-6 relative inside steps
    assert_allclose(r.sol(1.0)[:, 0], exact, rtol=1e-6, atol=1e-9)


def test_projection_keeps_the_jacobian():
    """A projection moves the state by about the tolerance: radau keeps its Jacobian and
    factorisations across it (one more evaluation per step, for the derivative at the
    projected state), it does not form them again after every step. With a projection that
    changes nothing, the run is the unprojected one."""
    free = ode.solve(vdp, (0.0, 300.0), [2.0, 0.0], method="radau", rtol=1e-6, atol=1e-6)
    same = ode.solve(vdp, (0.0, 300.0), [2.0, 0.0], method="radau", rtol=1e-6, atol=1e-6,
                     project=lambda t, y: y)
    assert same.nsteps == free.nsteps
    assert same.stats["njev"] == free.stats["njev"]
    assert same.nfev == free.nfev + same.nsteps
    assert_allclose(same.y[:, -1], free.y[:, -1], rtol=1e-12)
