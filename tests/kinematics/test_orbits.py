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


# --- trust at the edges: classification by the energy, state_at by universal variables ------

def _integrate(r0, v0, mu, t0, ts):
    """Reference: DOP853 at rtol 1e-13 from the state at t0 to the times ts (sorted)."""
    ts = np.atleast_1d(np.asarray(ts, dtype=float))
    y0 = np.concatenate([np.asarray(r0, float), np.asarray(v0, float)])
    out = np.empty((ts.size, 6))
    for sign in (1, -1):
        sel = (ts - t0) * sign >= 0
        if not sel.any():
            continue
        t_end = ts[sel].max() if sign > 0 else ts[sel].min()
        if t_end == t0:
            out[sel] = y0
            continue
        sol = solve_ivp(_rhs(mu), (t0, t_end), y0, method="DOP853", rtol=1e-13,
                        atol=1e-15, dense_output=True)
        assert sol.success
        out[sel] = sol.sol(ts[sel]).T
    return out[:, :3], out[:, 3:]


@pytest.mark.parametrize("vt", [1e-6, 1e-12])
def test_nearly_radial_bound_orbit_is_an_ellipse(vt):
    """r0 = (1, 0, 0), v0 = (0.5, vt, 0), mu = 1: energy 0.125 - 1 = -0.875 < 0, a bound
    orbit whatever the small tangential speed: a = 1/1.75, period 2 pi a^(3/2), apoapsis
    a (1 + e) ~ 2a; the state at t = 0.5 is that of a tight integration (r = 1.139...),
    and after one period (through the near-collision at the periapsis) the point is back."""
    o = Orbit([1.0, 0, 0], [0.5, vt, 0], mu=1.0)
    eps = (0.25 + vt**2) / 2 - 1
    a = -1 / (2 * eps)
    assert o.kind == "ellipse" and o.is_bound
    assert_allclose(o.specific_energy, eps, rtol=1e-15)
    assert_allclose(o.semi_major_axis, a, rtol=1e-14)
    assert_allclose(o.period, 2 * math.pi * a**1.5, rtol=1e-14)
    e = math.sqrt(1 + 2 * eps * vt**2)    # e^2 = 1 + 2 eps h^2 / mu^2, h = vt
    assert o.eccentricity < 1 or vt < 1e-8  # 1 - 8.75e-25 rounds to 1.0 for vt = 1e-12
    assert_allclose(o.eccentricity, e, rtol=1e-15)
    assert_allclose(o.apoapsis, a * (1 + e), rtol=1e-14)
    assert_allclose(o.periapsis, vt**2 / (1 + e), rtol=1e-12)
    ts = np.array([-0.3, 0.2, 0.5, 1.0])
    r, v = o.state_at(ts)
    r_ref, v_ref = _integrate([1.0, 0, 0], [0.5, vt, 0], 1.0, 0.0, ts)
    assert_allclose(np.linalg.norm(r[2]), 1.1392, rtol=1e-4)
    assert_allclose(r, r_ref, rtol=0, atol=1e-10)
    assert_allclose(v, v_ref, rtol=0, atol=1e-10)
    r1, v1 = o.state_at(o.period)
    assert_allclose(r1, [1.0, 0, 0], atol=1e-9)
    assert_allclose(v1, [0.5, vt, 0], atol=1e-9)
    # one revolution earlier, through the near-collision at the periapsis (t = -0.76)
    r1, v1 = o.state_at(-1.0)
    r_ref, v_ref = _integrate([1.0, 0, 0], [0.5, vt, 0], 1.0, 0.0, [o.period - 1.0])
    assert_allclose(r1, r_ref[0], atol=1e-9)
    assert_allclose(v1, v_ref[0], atol=1e-9)


def _at_energy_ratio(rho, mu=2.0):
    """A state at r0 = (1.5, 0, 0) whose energy ratio eps / (v^2/2 + mu/r) is rho."""
    r = 1.5
    v = math.sqrt(2 * mu / r * (1 + rho) / (1 - rho))
    direction = np.array([0.6, 0.8, 0.0])
    return np.array([r, 0.0, 0.0]), v * direction


def test_kind_decided_by_the_energy_at_the_boundary():
    """kind is 'parabola' when |eps| <= parabolic_tol (v^2/2 + mu/r), otherwise the sign of
    the energy decides; at the boundary itself (parabolic_tol = the ratio) it is a parabola."""
    mu = 2.0
    for rho, kind in [(0.0, "parabola"), (0.5e-12, "parabola"), (-0.5e-12, "parabola"),
                      (2e-12, "hyperbola"), (-2e-12, "ellipse"),
                      (1e-6, "hyperbola"), (-1e-6, "ellipse")]:
        o = Orbit(*_at_energy_ratio(rho, mu), mu=mu)
        assert o.kind == kind, (rho, o)
        assert o.is_bound == (kind == "ellipse")
        assert (o.period < math.inf) == o.is_bound
        assert (o.eccentricity < 1) == (kind == "ellipse")
        assert (o.eccentricity > 1) == (kind == "hyperbola")
    r0, v0 = _at_energy_ratio(-1e-9, mu)
    ratio = abs(v0 @ v0 / 2 - mu / 1.5) / (v0 @ v0 / 2 + mu / 1.5)
    assert Orbit(r0, v0, mu=mu, parabolic_tol=ratio).kind == "parabola"
    assert Orbit(r0, v0, mu=mu, parabolic_tol=ratio * (1 - 1e-6)).kind == "ellipse"
    assert Orbit(r0, v0, mu=mu, parabolic_tol=0).kind == "ellipse"


def test_state_at_continuous_across_the_parabolic_boundary():
    """Energy ratios 0, +-1e-12, +-1e-6 (parabola, both sides of the band, ellipse and
    hyperbola): the state at several times agrees with a tight integration to 1e-9 (relative
    to the distance), and moves with rho by no more than a Lipschitz bound (continuity)."""
    mu = 2.0
    ts = np.array([-1.0, 0.0, 0.7, 3.0, 10.0])
    states = {}
    for rho in (-1e-6, -1e-12, 0.0, 1e-12, 1e-6):
        r0, v0 = _at_energy_ratio(rho, mu)
        o = Orbit(r0, v0, mu=mu, epoch=0.0)
        r, v = o.state_at(ts)
        r_ref, v_ref = _integrate(r0, v0, mu, 0.0, ts)
        scale = np.linalg.norm(r_ref, axis=1)[:, None]
        assert np.all(np.abs(r - r_ref) <= 1e-9 * scale), (rho, r - r_ref)
        assert np.all(np.abs(v - v_ref) <= 1e-9 * np.linalg.norm(v_ref, axis=1)[:, None])
        states[rho] = (r, v)
    r_0, v_0 = states[0.0]
    for rho in (-1e-12, 1e-12, -1e-6, 1e-6):
        r, v = states[rho]
        # d(state)/d(rho) is O(t) here: 100 |rho| (t <= 10, r <= 20) bounds the change
        assert np.all(np.abs(r - r_0) <= 100 * abs(rho) * 20 + 1e-13), rho
        assert np.all(np.abs(v - v_0) <= 100 * abs(rho) * 20 + 1e-13), rho


def test_radial_motion_threshold():
    """h below 1e-14 r max(v, sqrt(mu/r)) is radial motion and refused; just above, the orbit
    is accepted and its state is right."""
    with pytest.raises(ArgumentError, match="radial motion"):
        Orbit([1.0, 0, 0], [0.5, 0.5e-14, 0], mu=1.0)
    o = Orbit([1.0, 0, 0], [0.5, 2e-14, 0], mu=1.0)
    assert o.kind == "ellipse"
    r, v = o.state_at(0.5)
    r_ref, v_ref = _integrate([1.0, 0, 0], [0.5, 2e-14, 0], 1.0, 0.0, [0.5])
    assert_allclose(r, r_ref[0], atol=1e-10)
    assert_allclose(v, v_ref[0], atol=1e-10)


def test_time_of_periapsis_is_the_last_before_the_epoch():
    """On an ellipse the documented passage is the last one at or before the epoch, also
    when the point is falling towards the periapsis at the epoch."""
    o = Orbit([1.0, 0.3, 0.0], [-0.4, -1.0, 0.0], mu=1.0, epoch=5.0)   # r . v < 0
    assert o.time_of_periapsis <= 5.0 < o.time_of_periapsis + o.period
    r, v = o.state_at(o.time_of_periapsis)
    assert_allclose(np.linalg.norm(r), o.periapsis, rtol=1e-12)
    assert abs(r @ v) < 1e-12


def test_radius_at_outside_a_hyperbola_is_refused():
    """r = p / (1 + e cos nu) is negative beyond the asymptotes: no point of the conic."""
    o = Orbit([1.0, 0, 0], [0, 2.0, 0], mu=1.0)     # e = 3
    assert_allclose(o.radius_at(0.5), 4 / (1 + 3 * math.cos(0.5)), rtol=1e-15)
    with pytest.raises(ArgumentError, match="`true_anomaly` must lie between the asymptotes"):
        o.radius_at(2.5)


def test_hyperbola_far_from_the_epoch():
    """e = 3 hyperbola (v_inf = sqrt(2)): at t = 1e6 the distance is v_inf t to 1e-5, the energy
    is kept; beyond double precision the error is named, not an overflow."""
    o = Orbit([1.0, 0, 0], [0, 2.0, 0], mu=1.0)
    r, v = o.state_at(1e6)
    assert_allclose(np.linalg.norm(r), math.sqrt(2) * 1e6, rtol=1e-5)
    assert_allclose(v @ v / 2 - 1 / np.linalg.norm(r), 1.0, rtol=1e-12)
    from rigidmech._core.errors import NumericalError
    with pytest.raises(NumericalError, match="too far from the epoch"):
        o.state_at(1e305)


@pytest.mark.parametrize("epoch", [math.nan, math.inf, "0"])
def test_epoch_must_be_a_finite_number(epoch):
    with pytest.raises(ArgumentError, match="`epoch` must be a finite"):
        Orbit([1.0, 0, 0], [0, 1.0, 0], mu=1.0, epoch=epoch)


@pytest.mark.parametrize("alpha", [0.0, 0.3, 2.0])
def test_a_circular_orbit_is_a_circle_whatever_its_phase(alpha):
    """The state at circular speed is a circle for every position on it (e is 1e-16 of
    rounding, not 0, once rotated), its periapsis the position at the epoch (as documented),
    not the direction of the rounding noise."""
    mu, r = 8.0, 2.0
    c, s = math.cos(alpha), math.sin(alpha)
    v = circular_speed(mu, r)
    o = Orbit([r * c, r * s, 0], [-v * s, v * c, 0], mu=mu, epoch=1.5)
    assert o.kind == "circle" and o.is_bound and o.eccentricity < 1e-15
    assert_allclose(o.argument_of_periapsis, alpha, atol=1e-15)
    assert o.time_of_periapsis == 1.5 and abs(o.true_anomaly_at_epoch) < 1e-15


@pytest.mark.parametrize("e, kind", [(0.5e-12, "circle"), (0.99e-12, "circle"),
                                     (1.01e-12, "ellipse"), (2e-12, "ellipse")])
def test_circle_threshold(e, kind):
    """From the periapsis (1, 0, 0) with v^2 = 1 + e (mu = 1) the eccentricity is e (to 2e-4
    relative: 1 + e is rounded): a circle up to e = 1e-12, an ellipse above (either side of
    the boundary by 1 %)."""
    o = Orbit([1.0, 0, 0], [0, math.sqrt(1 + e), 0], mu=1.0)
    assert o.kind == kind
    assert_allclose(o.eccentricity, e, rtol=1e-3)
