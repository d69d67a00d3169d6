"""Exact solutions of the reference problems (rigidmech.testing.problems, book ch. 27).

Each closed form is checked against an independent route: scipy's DOP853 at rtol = atol = 1e-13
(global error about 1e-11 over one or two periods, measured while writing these tests), its
conserved quantities, and the differential equation itself by central differences.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from rigidmech._core.errors import ArgumentError
from rigidmech.testing import problems as P

SMOOTH = [
    pytest.param(lambda: P.pendulum(170.0, periods=2), id="pendulum-170deg"),
    pytest.param(lambda: P.pendulum(30.0, omega0=3.0, periods=2), id="pendulum-30deg"),
    pytest.param(lambda: P.kepler(0.6, orbits=2), id="kepler-0.6"),
    pytest.param(lambda: P.kepler(0.9, orbits=2), id="kepler-0.9"),
    pytest.param(lambda: P.kepler(0.3, orbits=1, mu=3.986e14, a=7.0e6), id="satellite"),
    pytest.param(lambda: P.damped_oscillator(t_end=3.0), id="oscillator"),
    pytest.param(lambda: P.free_rigid_body(periods=2), id="body-about-A"),
    pytest.param(lambda: P.free_rigid_body(omega0=(0.3, -0.4, -1.2), periods=2),
                 id="body-about-C"),
    pytest.param(lambda: P.free_rigid_body((2.0, 3.0, 7.0), (-1.0, -0.4, 0.2), periods=2),
                 id="body-signs"),
]

# the problems that have a conserved energy / a separable form q'' = a(t, q): the properties
# are tested on those; the others must say they have none (not a silent skip)
CONSERVATIVE = [p for p in SMOOTH if p.values[0]().energy is not None]
SEPARABLE = [p for p in SMOOTH if p.values[0]().acceleration is not None]


@pytest.mark.parametrize("make", SMOOTH)
def test_problems_without_energy_or_separable_form_say_so(make):
    p = make()
    # the damped oscillator dissipates (no energy) and its q'' depends on q' (not separable);
    # the free rigid body (Euler's equations) is first order: no q'' = a(t, q) either
    assert (p.energy is None) == p.name.startswith("oscillator")
    assert (p.acceleration is None) == (p.name.startswith("oscillator") or "rigid-body" in p.name)


def _scale(p, y):
    return np.max(np.abs(y), axis=1, keepdims=True)


@pytest.mark.parametrize("make", SMOOTH)
def test_exact_matches_tight_dop853(make):
    p = make()
    ts = np.linspace(*p.t_span, 41)
    s = solve_ivp(p.fun, p.t_span, p.y0, method="DOP853", rtol=1e-13, atol=1e-13 * _scale(
        p, p.exact(ts)).ravel(), t_eval=ts)
    assert s.success
    ex = p.exact(ts)
    # DOP853 at 1e-13 is accurate to ~1e-10 relative over two periods (Kepler e = 0.9 at the
    # pericentre is the worst case, 4e-10); a wrong formula is off by O(1).
    assert_allclose(s.y, ex, rtol=0, atol=2e-9 * float(np.max(np.abs(ex))))


@pytest.mark.parametrize("make", SMOOTH)
def test_exact_satisfies_the_equation(make):
    p = make()
    t = np.linspace(p.t_span[0] + 0.1, p.t_span[1] - 0.1, 17)
    dt = 1e-5 * (p.t_span[1] - p.t_span[0]) / 10
    deriv = (p.exact(t + dt) - p.exact(t - dt)) / (2 * dt)
    scale = float(np.max(np.abs(deriv)))
    # central differences: truncation dt^2 y'''/6 and rounding eps*|y|/dt, both < 1e-6 scale
    assert_allclose(deriv, p.fun(t, p.exact(t)), rtol=0, atol=1e-6 * scale)


@pytest.mark.parametrize("make", SMOOTH)
def test_initial_state_and_shapes(make):
    p = make()
    assert_allclose(p.exact(p.t_span[0]), p.y0, rtol=0, atol=1e-14 * np.max(np.abs(p.y0)))
    assert p.exact(0.3).shape == p.y0.shape
    assert p.exact(np.array([0.1, 0.2, 0.3])).shape == (p.y0.size, 3)
    batch = np.stack([p.y0, 1.01 * p.y0], axis=1)
    f = p.fun(0.3, batch)
    assert f.shape == batch.shape
    assert_allclose(f[:, 1], p.fun(0.3, batch[:, 1]), rtol=1e-15)


@pytest.mark.parametrize("make", CONSERVATIVE)
def test_conserved_quantity_along_the_exact_motion(make):
    p = make()
    E = p.energy(p.exact(np.linspace(*p.t_span, 101)))
    # evaluated in floating point: a few ulps of the largest term
    assert_allclose(E, p.energy(p.y0), rtol=1e-13, atol=1e-13 * abs(p.energy(p.y0)) + 1e-15)


@pytest.mark.parametrize("make", SEPARABLE)
def test_acceleration_is_the_second_half_of_fun(make):
    p = make()
    y = p.exact(np.array([0.5, 1.0]))
    d = y.shape[0] // 2
    assert_allclose(p.acceleration(0.5, y[:d]), p.fun(0.5, y)[d:], rtol=1e-15)
    assert_allclose(p.fun(0.5, y)[:d], y[d:], rtol=0)


def test_periods():
    # 4 K(k) / omega0 (27.1.3); the linear period 2 pi is the small-amplitude limit
    assert_allclose(P.pendulum(1e-4).period, 2 * math.pi, rtol=1e-9)
    assert_allclose(P.pendulum(170.0).period, 15.326968, rtol=1e-7)
    for make in (P.pendulum, lambda: P.kepler(0.9), P.free_rigid_body,
                 lambda: P.free_rigid_body(omega0=(0.3, -0.4, -1.2))):
        p = make()
        assert_allclose(p.exact(p.period), p.y0, rtol=0, atol=1e-12 * np.max(np.abs(p.y0)))


def test_body_angular_momentum_conserved_in_both_cases():
    for w0 in [(1.0, 0.2, 0.5), (0.3, -0.4, -1.2)]:
        p = P.free_rigid_body((1.0, 2.0, 3.0), w0)
        w = p.exact(np.linspace(0, p.period, 50))
        L2 = (w[0] ** 2 + 4 * w[1] ** 2 + 9 * w[2] ** 2)
        assert_allclose(L2, L2[0], rtol=1e-13)


def test_arenstorf_is_periodic():
    # published periodic orbit (Hairer-Norsett-Wanner I, II.0): y(T) = y0
    p = P.arenstorf()
    s = solve_ivp(p.fun, p.t_span, p.y0, method="DOP853", rtol=1e-13, atol=1e-13)
    assert_allclose(s.y[:, -1], p.exact(p.period), rtol=0, atol=1e-8)
    assert_allclose(p.energy(s.y), p.energy(p.y0), rtol=1e-11)
    assert p.acceleration is None
    with pytest.raises(ArgumentError, match=r"`t` must be a multiple of the period"):
        p.exact(1.0)
    assert p.exact(np.array([0.0, 2 * p.period])).shape == (4, 2)


@settings(max_examples=40, deadline=None)
@given(st.floats(0.0, 0.99), st.floats(-50.0, 50.0))
def test_kepler_equation_solved_to_machine_precision(e, M):
    E = P.solve_kepler_equation(M, e)
    assert abs(E - e * np.sin(E) - M) <= 4e-15 * max(1.0, abs(M))


@settings(max_examples=30, deadline=None)
@given(st.tuples(*[st.floats(-2.0, 2.0).filter(lambda x: abs(x) > 0.05)] * 3))
def test_body_exact_solution_for_random_initial_rotation(w0):
    try:
        p = P.free_rigid_body((1.0, 2.0, 3.0), w0)
    except ArgumentError:  # on the separatrix
        return
    assert_allclose(p.exact(0.0), w0, rtol=0, atol=1e-12)
    t = np.linspace(0.05, 3.0, 7)
    dt = 1e-6
    deriv = (p.exact(t + dt) - p.exact(t - dt)) / (2 * dt)
    # central differences: |w'''| dt^2 / 6 < 1e-9 here, rounding 1e-16 / dt = 1e-10
    assert_allclose(deriv, p.fun(t, p.exact(t)), rtol=0, atol=1e-7 * (1 + np.max(np.abs(w0))) ** 3)


def test_problem_is_immutable_and_reads_like_a_call():
    p = P.kepler(0.6)
    assert repr(p) == "ReferenceProblem('kepler-e0.6', n=4, t_span=(0.0, 62.83185307179586))"
    with pytest.raises(AttributeError, match="immutable"):
        p.y0 = np.zeros(4)
    with pytest.raises(ValueError, match="read-only"):
        p.y0[0] = 1.0
    assert p.final_error(p.exact(p.t_span[1])) == 0.0


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: P.pendulum(180.0), r"`theta0_deg` must be in \(0, 180\)"),
        (lambda: P.pendulum(90.0, omega0=-1.0), r"`omega0` must be a finite number > 0"),
        (lambda: P.kepler(1.0), r"`e` must be in \[0, 1\)"),
        (lambda: P.kepler(0.5, orbits=0), r"`orbits` must be a finite number > 0"),
        (lambda: P.damped_oscillator(zeta=1.5), r"`zeta` must be in \[0, 1\)"),
        (lambda: P.arenstorf(0), r"`orbits` must be a positive integer"),
        (lambda: P.free_rigid_body((3.0, 2.0, 1.0)), r"`inertia` must be principal moments"),
        (lambda: P.free_rigid_body(omega0=(1.0, 2.0)), r"`omega0` must be 3 finite numbers"),
        (lambda: P.free_rigid_body(omega0=(0.0, 1.0, 0.0)), r"lies on the separatrix"),
    ],
)
def test_errors(call, match):
    with pytest.raises(ArgumentError, match=match):
        call()
