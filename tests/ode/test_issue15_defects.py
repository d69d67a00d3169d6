"""Regression tests of the ten defects found by the stress tests of ``rigidmech.ode`` (issue 15).

Each expected value is a closed form, an invariance (the same run written two ways gives the
same numbers) or an independent computation (scipy at tight tolerance, mpmath at 30 digits).
"""

import math

import mpmath
import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal
from scipy.integrate import solve_ivp

from rigidmech import ode
from rigidmech.testing import problems as P

ALL_FIRST_ORDER_ADAPTIVE = ["dopri5", "dop853", "gbs", "adams", "radau"]


# --- 1. a right-hand side returning the same buffer at every call -----------------------------

def _oscillator_fresh(t, y):
    return np.array([y[1], -y[0]])


def _oscillator_shared():
    buf = np.empty(2)

    def f(t, y):
        buf[0] = y[1]
        buf[1] = -y[0]
        return buf

    return f


@pytest.mark.parametrize("method", ALL_FIRST_ORDER_ADAPTIVE + ["bs32"])
def test_shared_buffer_rhs_gives_the_same_run_as_fresh_arrays(method):
    # the docs allow `fun` to return one buffer: the run must not depend on it
    fresh = ode.solve(_oscillator_fresh, (0.0, 10.0), [1.0, 0.0], method=method, rtol=1e-6)
    shared = ode.solve(_oscillator_shared(), (0.0, 10.0), [1.0, 0.0], method=method,
                       rtol=1e-6)
    assert shared.nfev == fresh.nfev
    assert_array_equal(shared.t, fresh.t)
    assert_array_equal(shared.y, fresh.y)


# --- 2. an event function that is zero at t0 --------------------------------------------------

def _g_zero_at_start(t, y):
    return t * (t - 0.3)  # zero at t0 = 0 (not an event) and at t = 0.3 (an event)


@pytest.mark.parametrize("method, opts", [
    ("rk4", {"step": 1.0}),
    ("euler", {"step": 1.0}),
    ("dop853", {"first_step": 1.0}),
    ("dopri5", {"first_step": 1.0}),
])
def test_event_zero_at_t0_does_not_hide_a_crossing_in_the_first_step(method, opts):
    r = ode.solve(lambda t, y: np.ones(1), (0.0, 2.0), [0.0], method=method,
                  events=_g_zero_at_start, **opts)
    assert_allclose(r.t_events[0], [0.3], rtol=1e-12)


# --- 3. radau with an error estimate exactly zero ---------------------------------------------

@pytest.mark.parametrize("fun, y0, exact", [
    (lambda t, y: np.ones(1), [0.0], [10.0]),                                # y' = 1
    (lambda t, y: np.array([y[1], -9.81]), [0.0, 0.0], [-0.5 * 9.81 * 100, -98.1]),  # free fall
])
def test_radau_zero_error_estimate(fun, y0, exact):
    r = ode.solve(fun, (0.0, 10.0), y0, method="radau")
    assert r.status == 0
    assert_allclose(r.y[:, -1], exact, rtol=1e-12)


# --- 4. adams with a batch and a vector atol --------------------------------------------------

def test_adams_batch_with_vector_atol():
    y0 = np.array([[1.0, 2.0, 0.5], [0.0, 0.0, 0.0]])
    r = ode.solve(lambda t, y: np.stack([y[1], -y[0]]), (0.0, 5.0), y0, method="adams",
                  rtol=1e-9, atol=[1e-10, 1e-9])
    assert r.status == 0
    assert_allclose(r.y[:, -1, :], np.stack([y0[0] * math.cos(5.0), -y0[0] * math.sin(5.0)]),
                    atol=1e-6)


# --- 5. radau's finite-difference Jacobian and the scale of y ---------------------------------

def _vdp(mu):
    def f(t, y):
        return np.array([y[1], mu * (1.0 - y[0] ** 2) * y[1] - y[0]])
    return f


def _scaled(fun, s):
    def f(t, y):
        return s * fun(t, y / s)
    return f


@pytest.mark.parametrize("s", [2e-20, 1e17])
def test_radau_steps_do_not_depend_on_the_scale_of_y(s):
    # y = s u with u a Van der Pol solution: with atol scaled too, the same steps are taken
    # (up to rounding), and the same numbers up to the factor s
    mu, span, y0 = 100.0, (0.0, 50.0), np.array([2.0, 0.0])
    ref = ode.solve(_vdp(mu), span, y0, method="radau", rtol=1e-6, atol=1e-6)
    got = ode.solve(_scaled(_vdp(mu), s), span, s * y0, method="radau", rtol=1e-6,
                    atol=s * 1e-6)
    assert got.status == 0, got.message
    assert abs(got.nsteps - ref.nsteps) <= 0.05 * ref.nsteps
    assert_allclose(got.y[:, -1] / s, ref.y[:, -1], rtol=1e-3, atol=1e-4)


def _robertson(t, y):
    return np.array([-0.04 * y[0] + 1e4 * y[1] * y[2],
                     0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] ** 2,
                     3e7 * y[1] ** 2])


def test_radau_robertson_costs_about_what_scipy_pays():
    # scipy's Radau (the same method, scaled finite differences) as the yardstick
    kw = dict(rtol=1e-6, atol=1e-10)
    ref = solve_ivp(_robertson, (0.0, 1e5), [1.0, 0.0, 0.0], method="Radau", **kw)
    got = ode.solve(_robertson, (0.0, 1e5), [1.0, 0.0, 0.0], method="radau", **kw)
    assert got.status == 0
    assert got.nfev <= 1.5 * ref.nfev
    assert_allclose(got.y[:, -1], ref.y[:, -1], rtol=1e-3, atol=1e-9)


def test_radau_accepts_a_user_jacobian_and_uses_it():
    mu = 100.0

    def jac(t, y):
        return np.array([[0.0, 1.0], [-2.0 * mu * y[0] * y[1] - 1.0, mu * (1.0 - y[0] ** 2)]])

    fd = ode.solve(_vdp(mu), (0.0, 20.0), [2.0, 0.0], method="radau", rtol=1e-6)
    r = ode.solve(_vdp(mu), (0.0, 20.0), [2.0, 0.0], method="radau", rtol=1e-6, jac=jac)
    assert r.stats["njev"] >= 1 and r.nfev < fd.nfev  # no evaluation spent on differences
    assert_allclose(r.y[:, -1], fd.y[:, -1], rtol=1e-4, atol=1e-5)


# --- 6. one diverging member of a batch -------------------------------------------------------

@pytest.mark.parametrize("method", ["dopri5", "dop853", "gbs", "adams", "radau"])
def test_a_diverging_batch_member_is_named(method):
    # y' = y^2 blows up at t = 1 / y0: member 1 (y0 = 2) at t = 0.5, member 0 (y0 = 0.5) at 2
    y0 = np.array([[0.5, 2.0, 0.25]])
    with np.errstate(all="ignore"):
        r = ode.solve(lambda t, y: y * y, (0.0, 1.0), y0, method=method, rtol=1e-6)
    assert r.status == -1
    assert "batch member 1" in r.message
    assert r.t[-1] < 0.5 + 1e-6 and r.t[-1] > 0.45  # everything computed so far is kept
    assert_allclose(r.y[0, -1, 0], 0.5 / (1 - 0.5 * r.t[-1]), rtol=1e-4)


# --- 7. dense output of gbs and rkn1210 -------------------------------------------------------

@pytest.mark.parametrize("method", ["gbs", "rkn1210"])
def test_t_eval_values_are_as_accurate_as_the_steps(method):
    # harmonic oscillator, closed form; fun is the acceleration for the RKN pair
    t_eval = np.linspace(0.0, 20.0, 37)
    if method == "rkn1210":
        fun = lambda t, q: -q  # noqa: E731
    else:
        fun = _oscillator_fresh
    r = ode.solve(fun, (0.0, 20.0), [1.0, 0.0], method=method, rtol=1e-12, atol=1e-14,
                  t_eval=t_eval)
    steps = ode.solve(fun, (0.0, 20.0), [1.0, 0.0], method=method, rtol=1e-12, atol=1e-14)
    err_steps = np.max(np.abs(steps.y[0] - np.cos(steps.t)))
    err_eval = np.max(np.abs(r.y[0] - np.cos(t_eval)))
    assert err_eval <= 10 * max(err_steps, 1e-14)


@pytest.mark.parametrize("method", ["gbs", "rkn1210"])
def test_event_times_are_as_accurate_as_the_steps(method):
    # y = cos t crosses 0 at pi/2 + k pi
    if method == "rkn1210":
        fun = lambda t, q: -q  # noqa: E731
    else:
        fun = _oscillator_fresh
    r = ode.solve(fun, (0.0, 20.0), [1.0, 0.0], method=method, rtol=1e-12, atol=1e-14,
                  events=lambda t, y: y[0])
    expected = np.pi / 2 + np.pi * np.arange(6)
    assert_allclose(r.t_events[0], expected, rtol=0, atol=1e-10)


# --- 8. closely spaced zeros of an event function inside one step -----------------------------

@pytest.mark.parametrize("method", ["dop853", "dopri5", "gbs"])
def test_close_event_zeros_near_a_maximum_are_found(method):
    # y = sin t, y = c: zeros asin(c) + 2 k pi and pi - asin(c) + 2 k pi, 32 over 16 periods
    c = 0.9
    r = ode.solve(lambda t, y: np.array([y[1], -y[0]]), (0.0, 32 * np.pi), [0.0, 1.0],
                  method=method, rtol=1e-6, events=lambda t, y: y[0] - c)
    k = np.arange(16)
    expected = np.sort(np.concatenate([np.arcsin(c) + 2 * np.pi * k,
                                       np.pi - np.arcsin(c) + 2 * np.pi * k]))
    assert len(r.t_events[0]) == 32
    assert_allclose(r.t_events[0], expected, atol=1e-3)


# --- 9. free rigid body: an exact reference near the separatrix -------------------------------

def _free_body_mpmath(inertia, omega0, t):
    """The same closed form (Landau-Lifshitz 37) at 30 digits, independent of float rounding."""
    mpmath.mp.dps = 30
    A, B, C = (mpmath.mpf(v) for v in inertia)
    w1, w2, w3 = (mpmath.mpf(v) for v in omega0)
    T2 = A * w1**2 + B * w2**2 + C * w3**2
    L2 = A**2 * w1**2 + B**2 * w2**2 + C**2 * w3**2
    assert T2 * B - L2 < 0  # the case tested: about the C axis
    lam = mpmath.sqrt((C - B) * (L2 - T2 * A) / (A * B * C))
    m = (B - A) * (T2 * C - L2) / ((C - B) * (L2 - T2 * A))
    a1 = mpmath.sqrt((T2 * C - L2) / (A * (C - A)))
    a2 = mpmath.sqrt((T2 * C - L2) / (B * (C - B)))
    a3 = mpmath.sqrt((L2 - T2 * A) / (C * (C - A)))
    s = 1 if w3 >= 0 else -1
    phi0 = mpmath.atan2(w2 / a2, s * w1 / a1)
    u = lam * mpmath.mpf(t) + mpmath.ellipf(phi0, m)
    sn, cn, dn = (mpmath.ellipfun(k, u, m=m) for k in ("sn", "cn", "dn"))
    return np.array([float(s * a1 * cn), float(a2 * sn), float(s * a3 * dn)])


def test_free_rigid_body_exact_near_the_separatrix():
    # (A, B, C) = (1, 2, 3), omega = (1, 0.2, w3): 2TB - L^2 = A(B-A) w1^2 - C(C-B) w3^2 = 0
    # for w3 = 1/sqrt(3); just above it the body turns about C with m = 1 - O(1e-9)
    inertia, w = (1.0, 2.0, 3.0), (1.0, 0.2, 1.0 / math.sqrt(3.0) + 1e-9)
    p = P.free_rigid_body(inertia, w, periods=1.0)
    for t in p.period * np.arange(7) / 6:  # the flips of the rotation are the sensitive parts
        assert_allclose(p.exact(t), _free_body_mpmath(inertia, w, t), rtol=0, atol=1e-13)


# --- 10. zero-length t_span -------------------------------------------------------------------

@pytest.mark.parametrize("method, opts", [("dop853", {}), ("rk4", {"step": 0.1}),
                                          ("radau", {}), ("rkn64", {})])
def test_zero_length_t_span_returns_y0_like_scipy(method, opts):
    # scipy returns y0 (at t0, twice); we return it once, with no evaluation of `fun`
    ref = solve_ivp(lambda t, y: -y, (1.0, 1.0), [1.0, 2.0])
    assert ref.success and np.all(ref.y[:, -1] == [1.0, 2.0])
    r = ode.solve(lambda t, y: -y, (1.0, 1.0), [1.0, 2.0], method=method, **opts)
    assert r.status == 0 and r.success
    assert_array_equal(r.t, [1.0])
    assert_array_equal(r.y, [[1.0], [2.0]])
    assert r.nsteps == 0 and r.nfev == 0
