"""Stormer-Verlet and its symmetric compositions (rigidmech.ode.geometric, book ch. 27)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from rigidmech import ode
from rigidmech._core.errors import ArgumentError
from rigidmech.ode import geometric as G
from rigidmech.testing.problems import kepler, pendulum

# step counts per orbit in the asymptotic range (checked: the error ratio per halving of h is
# 2**order to 1 %), above the rounding floor of about 1e-12 for Kepler e = 0.6
ORDERS = [
    ("verlet", 2, [400, 800, 1600, 3200]),
    ("yoshida4", 4, [200, 400, 800, 1600]),
    ("yoshida6", 6, [100, 200, 400, 800]),
]


@pytest.mark.parametrize(("method", "order", "counts"), ORDERS, ids=[o[0] for o in ORDERS])
def test_observed_convergence_order_on_kepler(method, order, counts):
    p = kepler(0.6, orbits=1)  # exact through Kepler's equation (27.3.1)
    hs, errs = [], []
    for n in counts:
        h = p.t_span[1] / n
        r = ode.solve(p.acceleration, p.t_span, p.y0, method=method, step=h)
        hs.append(h)
        errs.append(p.final_error(r.y[:, -1]))
    slope = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert abs(slope - order) <= 0.05 * order, (slope, errs)


@pytest.mark.parametrize(("method", "order", "counts"),
                         [("verlet", 2, [50, 100, 200, 400]), ("yoshida4", 4, [50, 100, 200, 400]),
                          ("yoshida6", 6, [50, 100, 200, 400])])
def test_observed_order_with_a_time_dependent_force(method, order, counts):
    # x'' = -x + cos 2t, x(0) = 1, x'(0) = 0: x = 4/3 cos t - 1/3 cos 2t (book 21.2.3)
    def exact(t):
        return np.array([4 / 3 * np.cos(t) - np.cos(2 * t) / 3,
                         -4 / 3 * np.sin(t) + 2 / 3 * np.sin(2 * t)])

    hs, errs = [], []
    for n in counts:
        r = ode.solve(lambda t, q: -q + np.cos(2 * t), (0.0, 5.0), [1.0, 0.0], method=method,
                      step=5.0 / n)
        hs.append(5.0 / n)
        errs.append(np.max(np.abs(r.y[:, -1] - exact(5.0))))
    slope = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert abs(slope - order) <= 0.05 * order, (slope, errs)


def test_composition_weights_satisfy_the_order_conditions():
    for name in ("yoshida4", "yoshida6"):
        w = np.array(G.COMPOSITIONS[name])
        assert_allclose(w.sum(), 1.0, rtol=1e-15)
        assert_allclose(w, w[::-1], rtol=0)  # symmetric
        assert abs(np.sum(w**3)) < 1e-14  # kills the h^3 error term
    assert abs(np.sum(np.array(G.COMPOSITIONS["yoshida6"]) ** 5)) < 1e-13  # and the h^5 one


@pytest.mark.parametrize("method", ["verlet", "yoshida4", "yoshida6"])
def test_time_reversible(method):
    # symmetric methods: one step back undoes one step forward, to rounding
    p = kepler(0.6, orbits=0.3)
    fwd = ode.solve(p.acceleration, p.t_span, p.y0, method=method, step=0.01)
    back = ode.solve(p.acceleration, p.t_span[::-1], fwd.y[:, -1], method=method, step=0.01)
    assert_allclose(back.y[:, -1], p.y0, rtol=0, atol=1e-12)


@pytest.mark.parametrize("method", ["verlet", "yoshida4", "yoshida6"])
def test_symplectic_area_preservation(method):
    # the flow map of a 1-dof system preserves area: det of its Jacobian is 1 (to the finite
    # difference error 1e-7 and rounding); RK4 would give 1 + O(h^4) per step, visible here
    p = pendulum(120.0)
    eps = 1e-6

    def phi(y):
        return ode.solve(p.acceleration, (0.0, 3.0), y, method=method, step=0.3).y[:, -1]

    y0 = np.array([1.0, 0.5])
    J = np.column_stack([(phi(y0 + eps * e) - phi(y0 - eps * e)) / (2 * eps)
                         for e in np.eye(2)])
    assert_allclose(np.linalg.det(J), 1.0, atol=1e-7)


@settings(max_examples=15, deadline=None)
@given(st.floats(0.3, 1.2), st.floats(-0.5, 0.5), st.sampled_from(["verlet", "yoshida4"]))
def test_batch_equals_single_runs(r0, v0, method):
    p = kepler(0.6, orbits=0.2)
    y0 = np.stack([p.y0, [r0, 0.0, v0, 1.0]], axis=1)
    rb = G.compose(p.acceleration, p.t_span, y0, step=0.05, weights=G.COMPOSITIONS[method])
    for j in range(2):
        r = G.compose(p.acceleration, p.t_span, y0[:, j], step=0.05,
                      weights=G.COMPOSITIONS[method])
        assert_allclose(rb.y[:, :, j], r.y, rtol=1e-14, atol=1e-14)


def test_evaluations_save_every_and_dense_output():
    p = kepler(0.6, orbits=1)
    r = G.yoshida6(p.acceleration, p.t_span, p.y0, step=p.t_span[1] / 1000, save_every=100,
                   dense_output=True)
    assert r.nfev == 1 + 7 * 1000 and r.nsteps == 1000 and len(r.t) == 11
    assert r.stats["stages"] == 7
    # Hermite over T/10-long intervals is coarse for e = 0.6, but exact at the nodes
    assert_allclose(r.sol(r.t[3]), r.y[:, 3], rtol=1e-15)
    assert r.sol(np.array([1.0, 2.0])).shape == (4, 2)


def test_non_finite_state_is_reported():
    r = ode.solve(lambda t, q: q**3, (0.0, 10.0), [1.0, 1.0], method="verlet", step=1e-2)
    assert r.status == -1 and "non-finite at t = " in r.message and r.t[-1] < 10.0


def test_odd_state_is_refused():
    with pytest.raises(ArgumentError, match=r"`y0` must be \[q0, v0\]"):
        G.verlet(lambda t, q: -q, (0.0, 1.0), [1.0, 0.0, 2.0], step=0.1)
