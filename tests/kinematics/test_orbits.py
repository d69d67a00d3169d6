"""Kepler orbits (ch. 8.4, 27): Kepler's equation, the conic from a state, the state at a
time, checked against closed forms and against a numerical integration of r'' = -mu r/r^3."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from rigidmech._core.errors import ArgumentError
from rigidmech.kinematics import (
    Orbit,
    circular_speed,
    escape_speed,
    hohmann_transfer,
    kepler_elliptic,
    kepler_hyperbolic,
)


@settings(max_examples=300)
@given(M=st.floats(-50, 50), e=st.floats(0, 0.99))
def test_kepler_elliptic_round_trip(M, e):
    """E - e sin E = M to 1e-12 (M reduced modulo 2 pi), and E -> M -> E."""
    E = kepler_elliptic(M, e)
    assert abs(E - e * math.sin(E) - M) <= 1e-12 * max(1.0, abs(M))
    assert abs(E - M) <= math.pi + 1e-12
    M2 = E - e * math.sin(E)
    assert abs(kepler_elliptic(M2, e) - E) <= 1e-12 * max(1.0, abs(E)) / (1 - e)


@settings(max_examples=300)
@given(M=st.floats(-200, 200), e=st.floats(1.0001, 30))
def test_kepler_hyperbolic_round_trip(M, e):
    """e sinh H - H = M to 1e-12 relative, and H -> M -> H."""
    H = kepler_hyperbolic(M, e)
    assert abs(e * math.sinh(H) - H - M) <= 1e-12 * max(1.0, abs(M))
    M2 = e * math.sinh(H) - H
    assert abs(kepler_hyperbolic(M2, e) - H) <= 1e-12 * max(1.0, abs(H)) / (e - 1)


def test_kepler_arrays_and_near_parabolic_corner():
    M = np.linspace(-7, 7, 101)
    for e in (0.0, 0.5, 0.999999):
        E = kepler_elliptic(M, e)
        assert_allclose(E - e * np.sin(E), M, rtol=0, atol=1e-12)
    H = kepler_hyperbolic(M, 1.000001)
    assert_allclose(1.000001 * np.sinh(H) - H, M, rtol=0, atol=1e-12)
    # e may be an array too
    e = np.array([0.1, 0.9])
    assert_allclose(kepler_elliptic([1.0, 1.0], e) - e * np.sin(kepler_elliptic(1.0, e)),
                    [1.0, 1.0], atol=1e-12)


def test_kepler_bad_eccentricity():
    with pytest.raises(ArgumentError, match=r"`e` must lie in \[0.0, 1.0\)"):
        kepler_elliptic(1.0, 1.2)
    with pytest.raises(ArgumentError, match=r"`e` must lie in \(1.0, inf\)"):
        kepler_hyperbolic(1.0, 0.5)
    with pytest.raises(ArgumentError, match="`mean_anomaly` must be finite"):
        kepler_elliptic(np.nan, 0.5)
    with pytest.raises(ArgumentError, match="`mean_anomaly` must be finite"):
        kepler_hyperbolic([1.0, np.inf], 2.0)
    with pytest.raises(ArgumentError, match=r"`e` must lie in \(1.0, inf\)"):
        kepler_hyperbolic(1.0, np.inf)


def _rhs(mu):
    def f(t, y):
        r = y[:3]
        return np.concatenate([y[3:], -mu * r / np.linalg.norm(r) ** 3])
    return f


def _apsides(r0, v0, mu, t_end):
    """Times and distances of the apsides (r . v = 0) found by DOP853 at rtol 1e-12."""
    def apsis(t, y):
        return y[:3] @ y[3:]
    sol = solve_ivp(_rhs(mu), (0, t_end), np.concatenate([r0, v0]), method="DOP853",
                    rtol=1e-13, atol=1e-15, events=apsis, dense_output=True)
    assert sol.success
    t_ev = sol.t_events[0]
    y_ev = sol.y_events[0]
    return t_ev, np.linalg.norm(y_ev[:, :3], axis=1), sol


@pytest.mark.parametrize("r0, v0, mu", [
    pytest.param([1.0, 0.2, 0.1], [-0.1, 1.1, 0.3], 1.0, id="inclined-ellipse"),
    pytest.param([7000e3, 0, 0], [0, 7.5e3, 2.0e3], 3.986004418e14, id="leo-si-units"),
    pytest.param([2.0, -1.0, 0.0], [0.3, 0.45, 0.0], 1.5, id="planar-eccentric"),
])
def test_elements_against_numerical_integration(r0, v0, mu):
    """Periapsis, apoapsis and period of the conic from the state agree with those of a
    DOP853 integration of the same state (rtol 1e-13) to 1e-9."""
    o = Orbit(r0, v0, mu=mu)
    assert o.is_bound
    t_ev, r_ev, sol = _apsides(np.asarray(r0), np.asarray(v0), mu, 2.2 * o.period)
    assert_allclose(r_ev.min(), o.periapsis, rtol=1e-9)
    assert_allclose(r_ev.max(), o.apoapsis, rtol=1e-9)
    # two successive passages at the same apsis are one period apart
    peri = t_ev[np.isclose(r_ev, o.periapsis, rtol=1e-6)]
    assert_allclose(np.diff(peri), o.period, rtol=1e-9)
    # and the state at a time matches the integration
    ts = np.linspace(0, 2 * o.period, 7)
    r, v = o.state_at(ts)
    scale = np.linalg.norm(r0)
    assert_allclose(r, sol.sol(ts)[:3].T, rtol=0, atol=1e-9 * scale)
    assert_allclose(v, sol.sol(ts)[3:].T, rtol=0, atol=1e-9 * np.linalg.norm(v0) * 10)


@pytest.mark.parametrize("speed_factor", [
    pytest.param(1.6, id="hyperbola"),
    pytest.param(1.0, id="parabola"),
])
def test_unbound_state_at_against_integration(speed_factor):
    mu = 2.0
    r0 = np.array([1.0, 0.5, 0.0])
    rn = np.linalg.norm(r0)
    v0 = speed_factor * escape_speed(mu, rn) * np.array([-0.3, 1.0, 0.2]) / math.sqrt(1.13)
    o = Orbit(r0, v0, mu=mu, epoch=0.5)
    assert not o.is_bound and o.period == math.inf and o.apoapsis == math.inf
    assert o.kind == ("parabola" if speed_factor == 1.0 else "hyperbola")
    ts = np.array([0.5, 1.0, 2.0, 4.0])
    r, v = o.state_at(ts)
    sol = solve_ivp(_rhs(mu), (0.5, 4.0), np.concatenate([r0, v0]), method="DOP853",
                    rtol=1e-13, atol=1e-15, dense_output=True)
    assert_allclose(r, sol.sol(ts)[:3].T, rtol=1e-9, atol=1e-12)
    assert_allclose(v, sol.sol(ts)[3:].T, rtol=1e-9, atol=1e-12)


def test_elements_closed_form_planar():
    """From the periapsis r0 = (1, 0, 0), v0 = (0, v, 0), mu = 1: h = v, p = v^2,
    e = v^2 - 1, a = 1 / (2 - v^2), energy v^2/2 - 1, period 2 pi a^(3/2) (ch. 8.4)."""
    v = 1.2
    o = Orbit([1.0, 0, 0], [0, v, 0], mu=1.0)
    assert_allclose(o.angular_momentum, [0, 0, v], rtol=1e-15)
    assert_allclose(o.semi_latus_rectum, v**2, rtol=1e-15)
    assert_allclose(o.eccentricity, v**2 - 1, rtol=1e-14)
    assert_allclose(o.semi_major_axis, 1 / (2 - v**2), rtol=1e-14)
    assert_allclose(o.specific_energy, v**2 / 2 - 1, rtol=1e-15)
    assert_allclose(o.period, 2 * math.pi * (1 / (2 - v**2)) ** 1.5, rtol=1e-14)
    assert_allclose(o.time_of_periapsis, 0.0, atol=1e-15)
    assert_allclose(o.radius_at(math.pi), o.apoapsis, rtol=1e-14)
    assert o.inclination == 0.0
    # the state at the epoch is the initial state
    r, w = o.state_at(0.0)
    assert_allclose(r, [1, 0, 0], atol=1e-15)
    assert_allclose(w, [0, v, 0], atol=1e-15)


@pytest.mark.parametrize("alpha", [0.3, 2.0, 4.0, 6.0])
def test_argument_of_periapsis_in_the_plane(alpha):
    """Rotating the state by alpha about z rotates the periapsis: omega = alpha."""
    c, s = math.cos(alpha), math.sin(alpha)
    o = Orbit([c, s, 0.0], [-1.2 * s, 1.2 * c, 0.0], mu=1.0)
    assert_allclose(o.argument_of_periapsis, alpha, rtol=1e-12)
    assert_allclose(o.periapsis_direction, [c, s, 0], atol=1e-14)


def test_argument_of_periapsis_inclined():
    """Orbit in the plane x = 0 (h along x, inclination pi/2, node along y... ) started at its
    periapsis on the z axis: omega = pi/2 from the ascending node."""
    o = Orbit([0.0, 0.0, 1.0], [0.0, -1.2, 0.0], mu=1.0)
    assert_allclose(o.inclination, math.pi / 2, rtol=1e-14)
    assert_allclose(o.normal, [1, 0, 0], atol=1e-15)
    assert_allclose(o.argument_of_periapsis, math.pi / 2, rtol=1e-14)


def test_circular_orbit():
    o = Orbit([2.0, 0, 0], [0, circular_speed(8.0, 2.0), 0], mu=8.0)
    assert o.eccentricity < 1e-15 and o.is_bound
    r, _ = o.state_at(o.period / 4)
    assert_allclose(r, [0, 2, 0], atol=1e-14)


def test_speeds_closed_form():
    """v_c = sqrt(mu/r), v_esc = sqrt(2 mu/r) = sqrt(2) v_c; the Earth's surface
    (mu = 3.986004418e14 m^3/s^2, R = 6371 km): 7.91 and 11.19 km/s."""
    mu, R = 3.986004418e14, 6.371e6
    assert_allclose(circular_speed(mu, R), math.sqrt(mu / R), rtol=1e-15)
    assert_allclose(escape_speed(mu, R) / circular_speed(mu, R), math.sqrt(2), rtol=1e-15)
    assert round(escape_speed(mu, R) / 1e3, 2) == 11.19
    o = Orbit([R, 0, 0], [0, escape_speed(mu, R), 0], mu=mu)
    assert o.kind == "parabola" and abs(o.specific_energy) < 1e-6


def test_hohmann_against_orbit():
    """The transfer ellipse started on the inner circle with v_c1 + dv1 reaches r2 at its
    apoapsis after the transfer time, where adding dv2 gives the circular speed at r2."""
    mu, r1, r2 = 3.986004418e14, 6678e3, 42164e3
    h = hohmann_transfer(mu, r1, r2)
    o = Orbit([r1, 0, 0], [0, circular_speed(mu, r1) + h.delta_v1, 0], mu=mu)
    assert_allclose(o.periapsis, r1, rtol=1e-12)
    assert_allclose(o.apoapsis, r2, rtol=1e-12)
    assert_allclose(o.period / 2, h.time, rtol=1e-12)
    r, v = o.state_at(h.time)
    assert_allclose(np.linalg.norm(r), r2, rtol=1e-12)
    assert_allclose(np.linalg.norm(v) + h.delta_v2, circular_speed(mu, r2), rtol=1e-12)
    assert_allclose(h.total_delta_v, h.delta_v1 + h.delta_v2, rtol=1e-15)
    assert "HohmannTransfer" in repr(h) and h.r1 == r1 and h.r2 == r2 and h.mu == mu
    down = hohmann_transfer(mu, r2, r1)
    assert down.delta_v1 < 0 and down.delta_v2 < 0
    assert_allclose(down.total_delta_v, h.total_delta_v, rtol=1e-12)


def test_bad_input():
    with pytest.raises(ArgumentError, match="angular momentum r0 \\^ v0 is zero"):
        Orbit([1.0, 0, 0], [2.0, 0, 0], mu=1.0)
    with pytest.raises(ArgumentError, match="`mu` must be a positive"):
        Orbit([1.0, 0, 0], [0, 1.0, 0], mu=-1.0)
    with pytest.raises(ArgumentError, match="`position` must hold 3 components"):
        Orbit([1.0, 0], [0, 1.0, 0], mu=1.0)
    with pytest.raises(ArgumentError, match="`position` must not be the attracting centre"):
        Orbit([0.0, 0, 0], [0, 1.0, 0], mu=1.0)
    with pytest.raises(ArgumentError, match="`r` must be a positive"):
        escape_speed(1.0, 0.0)
    with pytest.raises(ArgumentError, match="`time` must be finite"):
        Orbit([1.0, 0, 0], [0, 1.0, 0], mu=1.0).state_at(np.nan)
    with pytest.raises(ArgumentError, match="`parabolic_tol` must be a number in"):
        Orbit([1.0, 0, 0], [0, 1.0, 0], mu=1.0, parabolic_tol=-1)
    o = Orbit([1.0, 0, 0], [0, 1.0, 0], mu=1.0)
    assert "Orbit(" in repr(o)
    with pytest.raises(AttributeError):
        o.eccentricity = 0.5


@settings(max_examples=60)
@given(r=st.tuples(*[st.floats(-3, 3)] * 3), v=st.tuples(*[st.floats(-1.5, 1.5)] * 3),
       t=st.floats(-20, 20))
def test_state_at_conserves_energy_and_angular_momentum(r, v, t):
    """Along the Kepler motion the specific energy and r ^ v are invariant (ch. 8.1.4,
    8.2.3), and the conic found again from the propagated state is the same (to 1e-9)."""
    r, v = np.array(r), np.array(v)
    rn = np.linalg.norm(r)
    h = np.cross(r, v)
    if rn < 0.1 or np.linalg.norm(h) < 0.05 * rn * max(np.linalg.norm(v), 1.0):
        return  # too close to the centre or nearly radial: outside the tested domain
    o = Orbit(r, v, mu=1.0)
    if o.is_bound and o.eccentricity > 0.99 or abs(o.eccentricity - 1) < 1e-3:
        return  # the near-parabolic band is tested separately
    r1, v1 = o.state_at(t)
    assert_allclose(v1 @ v1 / 2 - 1 / np.linalg.norm(r1), o.specific_energy, rtol=1e-9,
                    atol=1e-10)
    assert_allclose(np.cross(r1, v1), o.angular_momentum, rtol=1e-9, atol=1e-10)
    o1 = Orbit(r1, v1, mu=1.0, epoch=t)
    assert_allclose(o1.eccentricity_vector, o.eccentricity_vector, rtol=1e-8, atol=1e-9)
    r2, _ = o1.state_at(0.0)
    assert_allclose(r2, r, rtol=1e-8, atol=1e-8 * max(1.0, rn))
