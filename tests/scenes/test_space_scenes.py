"""Tests of the satellite, Moon-probe and Foucault-pendulum scenes (issue 13; book ch. 8, 19,
24, 27), each against a closed form or an independent computation."""

import math
import re

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import rigidmech as rm
from rigidmech import scenes
from rigidmech._core import errors as scenes_errors
from rigidmech.dynamics.simulation import Event
from rigidmech.kinematics.orbits import Orbit
from rigidmech.scenes import cli
from rigidmech.scenes.space_scenes import EARTH_MOON_MU, EARTH_MU_KM


# -- satellite: the simulated orbit vs the Kepler conic of the same initial state -----------
@pytest.mark.parametrize(("q0", "u0"), [
    pytest.param((7000.0, 0.0), (0.0, 8.0), id="ellipse-e0.14"),
    pytest.param((6800.0, 0.0), (0.0, 10.0), id="ellipse-e0.7"),
])
def test_satellite_orbit_vs_kepler(q0, u0):
    scene = scenes.get("satellite")
    eqs = scene.build().system.equations_of_motion()
    mu = EARTH_MU_KM
    orbit = Orbit([*q0, 0.0], [*u0, 0.0], mu=mu)
    x, y = eqs.coordinates
    tt = rm.t
    crossing = Event(y, direction=1)                           # y = 0 upwards: once a turn
    apsis = Event(x * x.diff(tt) + y * y.diff(tt))             # r r' = 0: peri- and apoapsis
    T = orbit.period
    sim = eqs.simulate(t=(0.0, 1.5 * T), q0=q0, u0=u0, params={"m": 1.0, "mu": mu},
                       rtol=1e-13, atol=1e-10, events=[crossing, apsis], n_output=201)
    assert sim.status == "finished"
    turns = [t for t in sim.t_events[0] if t > 1.0]
    assert turns[0] == pytest.approx(T, rel=1e-8)               # the period
    t_aps = [t for t in sim.t_events[1] if t > 1.0]
    at = eqs.simulate(t=(0.0, t_aps[-1]), q0=q0, u0=u0, params={"m": 1.0, "mu": mu},
                      rtol=1e-13, atol=1e-10, t_eval=[0.0, *t_aps])
    r = np.hypot(*at.q[:, 1:])
    np.testing.assert_allclose(r.max(), orbit.apoapsis, rtol=1e-8)
    np.testing.assert_allclose(r.min(), orbit.periapsis, rtol=1e-8)
    # energy per unit mass: the orbit's, conserved along the motion
    E = sim.energy()
    np.testing.assert_allclose(E, orbit.specific_energy, rtol=1e-10)
    # the state after one period: back to the start
    one = eqs.simulate(t=(0.0, T), q0=q0, u0=u0, params={"m": 1.0, "mu": mu}, rtol=1e-13,
                       atol=1e-10, n_output=2)
    np.testing.assert_allclose(one.q[:, -1], q0, rtol=0, atol=1e-8 * np.hypot(*q0))
    np.testing.assert_allclose(one.u[:, -1], u0, rtol=0, atol=1e-8 * np.hypot(*u0))


def test_satellite_run_from_the_catalogue():
    report = scenes.run("satellite", t_end=1000.0)
    assert report.status == "finished" and report.energy_drift < 1e-9
    assert scenes.get("satellite").defaults == {"m": 1.0, "mu": EARTH_MU_KM}


# -- Moon probe: Jacobi's integral, and the motion vs the rotating-frame equations ----------
def _jacobi(t, x, y, vx, vy, mE, mM):
    """C = W^2 (ξ² + η²) + 2 mE/r_E + 2 mM/r_M - |v relative to R1|², R1 turning at W about k,
    W^2 = mE + mM (G = 1, D = 1), E at (-mu, 0), M at (1 - mu, 0) in R1."""
    W, mu = math.sqrt(mE + mM), mM / (mE + mM)
    c, s = np.cos(W * t), np.sin(W * t)
    xi, eta = c * x + s * y, -s * x + c * y
    wx, wy = vx + W * y, vy - W * x              # v - W k ^ OP, the velocity relative to R1
    vxi, veta = c * wx + s * wy, -s * wx + c * wy
    rE = np.hypot(xi + mu, eta)
    rM = np.hypot(xi - 1 + mu, eta)
    return W**2 * (xi**2 + eta**2) + 2 * mE / rE + 2 * mM / rM - (vxi**2 + veta**2)


def _rotating_frame_motion(state0, t_end, mu):
    """The textbook's equations of the restricted three-body problem in R1, in the units
    where the Moon's angular rate is 1 (scipy)."""
    def f(_, s):
        xi, eta, u, v = s
        rE3 = np.hypot(xi + mu, eta) ** 3
        rM3 = np.hypot(xi - 1 + mu, eta) ** 3
        ax = 2 * v + xi - (1 - mu) * (xi + mu) / rE3 - mu * (xi - 1 + mu) / rM3
        ay = -2 * u + eta - (1 - mu) * eta / rE3 - mu * eta / rM3
        return [u, v, ax, ay]
    return solve_ivp(f, (0.0, t_end), state0, method="DOP853", rtol=1e-13, atol=1e-14).y[:, -1]


@pytest.mark.parametrize(("mE", "mM", "state"), [
    pytest.param(1 - EARTH_MOON_MU, EARTH_MOON_MU, None, id="earth-moon"),
    pytest.param(2.0, 0.5, (-0.7, 0.0, 0.0, -2.0), id="other-masses"),
])
def test_moon_probe_jacobi_constant_is_conserved(mE, mM, state):
    scene = scenes.get("moon-probe")
    eqs = scene.build().system.equations_of_motion()
    q0, u0 = (scene.q0, scene.u0) if state is None else (state[:2], state[2:])
    sim = eqs.simulate(t=(0.0, scene.t_end), q0=q0, u0=u0,
                       params={"m": 1.0, "mE": mE, "mM": mM}, rtol=1e-12, atol=1e-14,
                       n_output=2001)
    assert sim.status == "finished"
    C = _jacobi(sim.t, *sim.q, *sim.u, mE, mM)
    assert np.max(np.abs(C - C[0])) < 1e-9 * abs(C[0])
    # the probe goes far from the Earth: a real three-body motion, not a Kepler ellipse
    assert np.max(np.hypot(*sim.q)) > 0.5


def test_moon_probe_agrees_with_the_rotating_frame_equations():
    scene = scenes.get("moon-probe")
    mu, T = 0.2, 2.0                                   # a heavy "moon" to make it count
    x0, y0, vx0, vy0 = 0.4, 0.1, -0.3, 1.1
    eqs = scene.build().system.equations_of_motion()
    sim = eqs.simulate(t=(0.0, T), q0=[x0, y0], u0=[vx0, vy0],
                       params={"m": 2.0, "mE": 1 - mu, "mM": mu}, rtol=1e-13, atol=1e-14,
                       n_output=2)
    # at t = 0, R1 = R0: ξ = x, η = y, ξ' = vx + y, η' = vy - x
    xi, eta, u, v = _rotating_frame_motion([x0, y0, vx0 + y0, vy0 - x0], T, mu)
    c, s = math.cos(T), math.sin(T)
    x, y = c * xi - s * eta, s * xi + c * eta
    vx, vy = c * (u - eta) - s * (v + xi), s * (u - eta) + c * (v + xi)
    np.testing.assert_allclose([*sim.q[:, -1], *sim.u[:, -1]], [x, y, vx, vy], rtol=0,
                               atol=1e-9)


def test_moon_probe_refuses_a_negative_mass():
    with pytest.raises(scenes_errors.SceneError, match=r"parameter `mM` must be > 0"):
        scenes.run("moon-probe", params={"mM": -0.1})


# -- Foucault pendulum: the swing plane turns at -Omega sin(lat) ----------------------------
def _precession_rate(sim):
    """Slope of the azimuth of the bob at its turning points (largest distance from the
    vertical), the azimuth taken modulo pi (both ends of the swing)."""
    a, b = sim.q
    X, Y = -np.sin(b), np.sin(a) * np.cos(b)         # east, north (in units of L)
    r2 = X**2 + Y**2
    i = np.where((r2[1:-1] > r2[:-2]) & (r2[1:-1] >= r2[2:]))[0] + 1
    phi = np.unwrap(2 * np.arctan2(Y[i], X[i])) / 2
    return np.polyfit(sim.t[i], phi, 1)[0]


@pytest.mark.parametrize("lat", [pytest.param(math.pi / 4, id="45N"),
                                 pytest.param(-math.pi / 3, id="60S"),
                                 pytest.param(1.2, id="69N")])
def test_foucault_precession_rate(lat):
    # Tolerance 1e-2 (relative): Omega sin(lat) is the first-order rate; with the exaggerated
    # Omega = 0.05 rad/s against omega0 = sqrt(g/L) = 3.13 rad/s, the centrifugal terms of the
    # Earth's rotation and the own (Airy) precession of the slightly elliptic swing,
    # 3/8 alpha0^2 of the rate, shift it by parts in 10^3 (measured: about 8e-4 at 45 N).
    scene = scenes.get("foucault-pendulum")
    params = scene.defaults | {"lat": lat}
    eqs = scene.build().system.equations_of_motion()
    sim = eqs.simulate(t=(0.0, 40.0), q0=scene.q0, u0=scene.u0, params=params, rtol=1e-10,
                       atol=1e-12, n_output=8001)
    expected = -params["Omega"] * math.sin(lat)
    assert _precession_rate(sim) == pytest.approx(expected, rel=1e-2)


def test_foucault_no_precession_at_the_equator():
    scene = scenes.get("foucault-pendulum")
    eqs = scene.build().system.equations_of_motion()
    sim = eqs.simulate(t=(0.0, 40.0), q0=scene.q0, u0=scene.u0,
                       params=scene.defaults | {"lat": 0.0}, rtol=1e-10, atol=1e-12,
                       n_output=8001)
    assert abs(_precession_rate(sim)) < 1e-2 * scene.defaults["Omega"]


def test_wagon_pendulum_swings_about_its_relative_equilibrium():
    """Ch. 19, 24: from theta = 0 at rest in the wagon, the pendulum swings between 0 and
    2 theta* (tan theta* = -a/g: a symmetric swing about the relative equilibrium) with the
    period 2 pi sqrt(L / g_a) of small oscillations corrected by the amplitude (the exact
    pendulum period with g_a = sqrt(g^2 + a^2)); the energy relative to the wagon is
    conserved."""
    scene = scenes.get("wagon-pendulum")
    p = scene.defaults
    eqs = scene.build().system.equations_of_motion()
    sim = eqs.simulate(t=(0.0, 10.0), q0=scene.q0, u0=scene.u0, params=p, rtol=1e-11,
                       atol=1e-12, n_output=20001)
    theta_star = -math.atan(p["a"] / p["g"])
    assert sim.q[0].min() == pytest.approx(2 * theta_star, rel=1e-6)
    assert sim.energy_drift() < 1e-9
    assert np.max(np.abs(sim.energy_balance())) < 1e-8
    # period of the pendulum of amplitude |theta*| in the apparent gravity g_a
    ga = math.hypot(p["g"], p["a"])
    k = math.sin(abs(theta_star) / 2)
    period = 4 * math.sqrt(p["L"] / ga) * float(sp.elliptic_k(k**2))
    crossings = sim.t[1:][(np.diff(np.sign(sim.q[0] - theta_star)) > 0)]
    assert np.diff(crossings).mean() == pytest.approx(period, rel=1e-4)


# -- command line ---------------------------------------------------------------------------
@pytest.mark.parametrize("name", ["satellite", "moon-probe", "foucault-pendulum",
                                  "wagon-pendulum"])
def test_run_new_scenes(capsys, name):
    assert cli.main(["run", name, "--t-end", "1", "--no-progress"]) == 0
    out = capsys.readouterr().out
    assert f"({name}, book ch. " in out and "final state: " in out


@pytest.mark.parametrize(("name", "match"), [
    pytest.param("satellite", r"rigidmech: error: scene 'satellite' has no equilibrium at "
                 r"q = 0 \(q' = 0\): there f\(0, 0\) = \[not finite, not finite\]",
                 id="satellite"),
    pytest.param("foucault-pendulum", r"rigidmech: error: scene 'foucault-pendulum' has no "
                 r"equilibrium at q = 0 \(q' = 0\): there f\(0, 0\) = \[0\.00125, 0\]",
                 id="foucault"),
    pytest.param("moon-probe", r"rigidmech: error: scene 'moon-probe' has equations that "
                 r"depend on the time t explicitly", id="moon-probe"),
])
def test_modes_refuses_a_scene_without_equilibrium_at_zero(capsys, name, match):
    assert cli.main(["modes", name]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and re.match(match, err)
