"""Book ch. 21.4, 23, 24: motions with dry friction that change regime, integrated phase by
phase (:mod:`rigidmech.regimes`).

Expected switching instants and states are closed forms derived in each test's comment from
the equations of each regime (Coulomb's laws, ch. 13.1; the fundamental principle in each
regime). Integrations run at rtol = 1e-12; the event times must match to 1e-9.
"""

import math

import numpy as np
import pytest

from rigidmech.actions import Coulomb
from rigidmech.regimes import (
    Guard,
    Regime,
    block_on_wagon,
    coulomb_oscillator,
    cylinder_on_incline,
    integrate_phases,
    pushed_box,
)

TOL = 1e-9


def turning_points(x0, d_kinetic, d_static):
    # half-cycle n: oscillation about -+d_k, so |x_{n+1}| = |x_n| - 2 d_k with alternating sign;
    # the mass stops at the first turning point with |x_n| <= d_s
    xs = [x0]
    while abs(xs[-1]) > d_static:
        x = xs[-1]
        xs.append(-(abs(x) - 2 * d_kinetic) * math.copysign(1.0, x))
    return xs


@pytest.mark.parametrize("x0, fs, fk", [
    pytest.param(1.0, 0.25, 0.2, id="x0=1-fs0.25-fk0.2"),
    pytest.param(-0.7, 0.2, 0.2, id="x0=-0.7-equal-coefficients"),
    pytest.param(0.3, 0.5, 0.1, id="x0=0.3-stops-early"),
    pytest.param(0.05, 0.25, 0.2, id="starts-inside-the-static-band"),
])
def test_ch21_coulomb_damped_oscillator_stop_time_and_position(x0, fs, fk):
    # m x'' + k x = -+ f_k N, half-period pi/omega (omega = 2): turning points at n pi/omega,
    # amplitude decreasing by 2 f_k N/k per half-cycle, stop at the first |x_n| <= f_s N/k
    m, k, N = 2.0, 8.0, 3.0
    omega = math.sqrt(k / m)
    xs = turning_points(x0, fk * N / k, fs * N / k)
    n = len(xs) - 1
    motion = coulomb_oscillator(mass=m, stiffness=k, friction=Coulomb(fs, fk), normal_force=N,
                                x0=x0, t_end=(n + 2) * math.pi / omega)
    # the physical number of phases: n slides then one stick, no spurious switch
    assert len(motion.phases) == n + 1
    assert motion.regimes[-1] == "stick"
    slides = motion.regimes[:-1]
    assert all(r in ("slide+", "slide-") for r in slides)
    assert all(a != b for a, b in zip(slides, slides[1:], strict=False))     # alternate
    np.testing.assert_allclose(motion.switch_times, [i * math.pi / omega for i in range(1, n + 1)],
                               rtol=TOL, atol=TOL)
    np.testing.assert_allclose([p.y_start[0] for p in motion.phases], xs, rtol=TOL, atol=TOL)
    assert motion.phases[-1].y_end == motion.phases[-1].y_start          # at rest for good


def test_ch21_coulomb_amplitude_decreases_by_4fN_over_k_per_cycle():
    m, k, N, f = 1.0, 4.0, 2.0, 0.1
    motion = coulomb_oscillator(mass=m, stiffness=k, friction=Coulomb(f), normal_force=N,
                                x0=2.0, t_end=40.0)
    amplitudes = np.abs([p.y_start[0] for p in motion.phases])
    np.testing.assert_allclose(amplitudes[:-2] - amplitudes[2:], 4 * f * N / k, rtol=TOL)


def test_ch21_coulomb_oscillator_thrown_from_the_origin():
    # x(0) = 0, v(0) = v0 > 0: slide+ about -d, x = -d (1 - cos wt) + (v0/w) sin wt; stops
    # where v = 0: tan(w t1) = v0 / (d w), x1 = -d + sqrt(d^2 + (v0/w)^2)
    m, k, N, f, v0 = 1.0, 1.0, 1.0, 0.1, 2.0
    w, d = 1.0, f * N / k
    motion = coulomb_oscillator(mass=m, stiffness=k, friction=Coulomb(f), normal_force=N,
                                x0=0.0, v0=v0, t_end=3.0)
    t1 = math.atan2(v0, d * w) / w
    assert motion.regimes[0] == "slide+"
    assert math.isclose(motion.switch_times[0], t1, rel_tol=TOL)
    assert math.isclose(motion.phases[1].y_start[0], -d + math.hypot(d, v0 / w), rel_tol=TOL)


def test_ch21_dry_friction_never_gives_energy():
    # kinetic + elastic energy never increases (friction does no positive work, ch. 11.3)
    m, k = 1.0, 3.0
    motion = coulomb_oscillator(mass=m, stiffness=k, friction=Coulomb(0.3, 0.2),
                                normal_force=1.0, x0=1.5, v0=-1.0, t_end=15.0)
    ts = np.linspace(0, 15.0, 3001)
    x, v = motion(ts)
    E = 0.5 * m * v**2 + 0.5 * k * x**2
    assert np.all(np.diff(E) <= 1e-10)


@pytest.mark.parametrize("ratio, regime", [
    pytest.param(0.5, "rolling", id="tan<3fs-rolls"),
    pytest.param(1 - 1e-6, "rolling", id="just-below-threshold-rolls"),
    pytest.param(1 + 1e-6, "slipping+", id="just-above-threshold-slips"),
    pytest.param(2.0, "slipping+", id="tan>3fs-slips"),
])
def test_ch23_cylinder_on_incline_rolls_or_slips(ratio, regime):
    # solid cylinder (J = m r^2 / 2) from rest: rolling needs T = m g sin(a)/3 <= f_s m g cos(a),
    # i.e. tan(a) <= 3 f_s; rolling: x'' = 2 g sin(a)/3; slipping: x'' = g (sin(a) - f_k cos(a)),
    # r theta'' = 2 f_k g cos(a)
    fs, fk, g, r, T = 0.2, 0.15, 9.81, 0.1, 1.0
    alpha = math.atan(3 * fs * ratio)
    motion = cylinder_on_incline(radius=r, angle=alpha, friction=Coulomb(fs, fk), g=g, t_end=T)
    assert motion.regimes == (regime,)
    x, v, th, om = motion.phases[-1].y_end
    if regime == "rolling":
        acc, ang = 2 * g * math.sin(alpha) / 3, 2 * g * math.sin(alpha) / (3 * r)
    else:
        acc, ang = g * (math.sin(alpha) - fk * math.cos(alpha)), 2 * fk * g * math.cos(alpha) / r
    np.testing.assert_allclose([x, v, th, om], [acc * T**2 / 2, acc * T, ang * T**2 / 2, ang * T],
                               rtol=1e-10)


def test_ch23_cylinder_launched_slipping_catches_rolling():
    # launched with v0 and no spin on a gentle slope: slip s = v - r w decreases at the rate
    # g (sin(a) - 3 f_k cos(a)) until s = 0 at t* = v0 / (g (3 f_k cos(a) - sin(a))), then it rolls
    fs, fk, g, r, v0 = 0.2, 0.15, 9.81, 0.1, 2.0
    alpha = math.atan(0.3)
    motion = cylinder_on_incline(radius=r, angle=alpha, friction=Coulomb(fs, fk), g=g, v0=v0,
                                 t_end=3.0)
    t_star = v0 / (g * (3 * fk * math.cos(alpha) - math.sin(alpha)))
    assert motion.regimes == ("slipping+", "rolling")
    assert math.isclose(motion.switch_times[0], t_star, rel_tol=TOL)
    v_star = v0 + g * (math.sin(alpha) - fk * math.cos(alpha)) * t_star
    assert math.isclose(motion.phases[1].y_start[1], v_star, rel_tol=TOL)


@pytest.mark.parametrize("a0, regimes", [
    pytest.param(2.0, ("stick",), id="a<fs-g-stays"),
    pytest.param(4.0, ("slide-",), id="a>fs-g-slides"),
])
def test_ch24_block_on_a_wagon_constant_acceleration(a0, regimes):
    # in the wagon's frame the block feels -m a0: it stays iff a0 <= f_s g (= 2.943); sliding
    # back, x_r = -(a0 - f_k g) t^2 / 2
    fs, fk, g, T = 0.3, 0.2, 9.81, 2.0
    motion = block_on_wagon(acceleration=a0, friction=Coulomb(fs, fk), g=g, t_end=T)
    assert motion.regimes == regimes
    expected = 0.0 if regimes == ("stick",) else -(a0 - fk * g) * T**2 / 2
    assert math.isclose(motion.phases[-1].y_end[0], expected, rel_tol=1e-10, abs_tol=1e-12)


def test_ch24_block_on_a_wagon_accelerating_ramp():
    # a = J t: sticks until J t_s = f_s g, then slides back with v' = -J t + f_k g:
    # x_r(t) = -J/2 [(t^3 - t_s^3)/3 - t_s^2 (t - t_s)] + f_k g (t - t_s)^2 / 2
    fs, fk, g, J, T = 0.3, 0.2, 9.81, 2.0, 3.0
    motion = block_on_wagon(acceleration=lambda t: J * t, friction=Coulomb(fs, fk), g=g,
                            t_end=T)
    ts = fs * g / J
    assert motion.regimes == ("stick", "slide-")
    assert math.isclose(motion.switch_times[0], ts, rel_tol=TOL)
    x = -J / 2 * ((T**3 - ts**3) / 3 - ts**2 * (T - ts)) + fk * g * (T - ts) ** 2 / 2
    assert math.isclose(motion.phases[-1].y_end[0], x, rel_tol=1e-10)


@pytest.mark.parametrize("f, h, first, P_limit", [
    # m g = 10, a = 0.5: slides at P = f m g, tips at P = m g a / h (moments about the edge)
    pytest.param(0.4, 1.0, "slide", 4.0, id="slides-first"),
    pytest.param(0.6, 1.0, "tip", 5.0, id="tips-first"),
    pytest.param(0.4, 2.0, "tip", 2.5, id="high-push-tips"),
])
def test_ch24_box_pushed_on_a_floor_slides_or_tips_first(f, h, first, P_limit):
    c = 2.0                                       # P = c t
    motion = pushed_box(mass=1.0, half_width=0.5, half_height=0.5, push_height=h,
                        push=lambda t: c * t, friction=Coulomb(f), g=10.0, t_end=4.0)
    assert motion.regimes[:2] == ("rest", first)
    assert math.isclose(motion.switch_times[0], P_limit / c, rel_tol=TOL)


@pytest.mark.parametrize("theta0", [
    pytest.param(0.05, id="from-near-the-top"),
    pytest.param(0.5, id="from-30-degrees"),
])
def test_ch24_particle_leaves_a_smooth_sphere_contact_opens(theta0):
    # a particle slides from rest on a smooth sphere of radius R: N/m = g cos(theta) -
    # v^2/R with v^2 = 2 g R (cos(theta0) - cos(theta)), so the one-sided contact opens
    # (N = 0) at cos(theta) = 2 cos(theta0) / 3; then free flight
    g, R = 9.81, 2.0

    def normal(t, y):                       # N/m, y = (x, z, vx, vz), centre at the origin
        r = math.hypot(y[0], y[1])
        return g * y[1] / r - (y[2] ** 2 + y[3] ** 2) / R

    def on_sphere(t, y):
        r = math.hypot(y[0], y[1])
        n = normal(t, y)
        return np.array([y[2], y[3], n * y[0] / r, -g + n * y[1] / r])

    def flight(t, y):
        return np.array([y[2], y[3], 0.0, -g])

    regimes = [Regime("on the sphere", on_sphere,
                      [Guard("contact opens", normal, target="flight", direction=-1)]),
               Regime("flight", flight)]
    y0 = [R * math.sin(theta0), R * math.cos(theta0), 0.0, 0.0]
    motion = integrate_phases(regimes, "on the sphere", (0.0, 5.0), y0, rtol=1e-12,
                              atol=1e-12)
    assert motion.regimes == ("on the sphere", "flight")
    x, z, _, _ = motion.phases[1].y_start
    assert math.isclose(z / math.hypot(x, z), 2 * math.cos(theta0) / 3, rel_tol=TOL)
