"""Book ch. 8 (motions with central acceleration) and ch. 27.3 (satellites): areal law,
Binet's formulas, Kepler's laws, orbit elements from an initial state, circular, escape and
Hohmann transfer speeds.

Conventions: centre O fixed, C = r^2 theta' the areal constant (ch. 8.1.3), u = 1/r;
a = -K OM / r^3 (ch. 8.2) with K = mu = G M; conic r = p / (1 + e cos(theta - omega)),
p = C^2 / mu; the Earth: mu = 3.986004418e14 m^3/s^2, R = 6371 km.
"""

import math

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech.kinematics import (
    Orbit,
    areal_constant,
    binet_acceleration,
    binet_speed_squared,
    circular_speed,
    escape_speed,
    hohmann_transfer,
    is_central,
)

MU_EARTH = 3.986004418e14
R_EARTH = 6.371e6


def test_binet_law_of_a_conic_is_newtons_inverse_square():
    """Ch. 8.2.1: with u = (1 + e cos theta)/p Binet's formula gives a = -(C^2/p) u^2, the
    inverse-square law with K = C^2 / p; and v^2 = (C^2/p)(2u - (1 - e^2)/p) (vis-viva,
    ch. 8.2.3)."""
    th = sp.Symbol("theta", real=True)
    p, e, C = sp.symbols("p e C", positive=True)
    u = (1 + e * sp.cos(th)) / p
    assert sp.simplify(binet_acceleration(u, th, C) + C**2 / p * u**2) == 0
    K = C**2 / p
    assert sp.simplify(binet_speed_squared(u, th, C) - K * (2 * u - (1 - e**2) / p)) == 0


def test_uniform_circular_motion_is_central_with_constant_areal_velocity():
    """Ch. 8.1.7: a = -w^2 OM (here a circle) is central; C = R^2 w."""
    w, R = sp.symbols("omega R", positive=True)
    R0 = rm.Frame("R0")
    M = R0.point("M", R * sp.cos(w * rm.t), R * sp.sin(w * rm.t), 0)
    assert is_central(M, centre=R0.origin, frame=R0)
    assert areal_constant(M, centre=R0.origin, frame=R0).equals(R**2 * w * R0.k)


@pytest.mark.parametrize("rp, vp", [
    pytest.param(7000e3, 8.0e3, id="satellite-7000km-8kms"),
    pytest.param(6678e3, 10.0e3, id="satellite-6678km-10kms"),
])
def test_kepler_orbit_elements_from_the_perigee_state(rp, vp):
    """Started at the perigee (r perpendicular to v): h = rp vp, e = rp vp^2 / mu - 1,
    a = rp / (1 - e), apogee a (1 + e), T = 2 pi sqrt(a^3 / mu) (Kepler's third law,
    ch. 8.2.4), energy v^2/2 - mu/r = -mu/(2a)."""
    o = Orbit([rp, 0, 0], [0, vp, 0], mu=MU_EARTH)
    e = rp * vp**2 / MU_EARTH - 1
    a = rp / (1 - e)
    assert_allclose(o.eccentricity, e, rtol=1e-13)
    assert_allclose(o.semi_major_axis, a, rtol=1e-13)
    assert_allclose(o.periapsis, rp, rtol=1e-13)
    assert_allclose(o.apoapsis, a * (1 + e), rtol=1e-13)
    assert_allclose(o.period, 2 * math.pi * math.sqrt(a**3 / MU_EARTH), rtol=1e-13)
    assert_allclose(o.specific_energy, -MU_EARTH / (2 * a), rtol=1e-13)
    assert_allclose(np.linalg.norm(o.angular_momentum), rp * vp, rtol=1e-15)


def test_area_law_along_the_orbit():
    """Kepler's second law (ch. 8.1.4, 8.2.4): r ^ v is the same all along the orbit, and
    the area swept in one period, (h/2) T, is that of the ellipse, pi a b."""
    o = Orbit([7000e3, 1000e3, 0], [-1.0e3, 7.9e3, 0.5e3], mu=MU_EARTH)
    r, v = o.state_at(np.linspace(0, o.period, 9))
    h = np.cross(r, v)
    assert_allclose(h, np.broadcast_to(o.angular_momentum, h.shape), rtol=1e-11)
    a, e = o.semi_major_axis, o.eccentricity
    b = a * math.sqrt(1 - e**2)
    assert_allclose(np.linalg.norm(o.angular_momentum) / 2 * o.period, math.pi * a * b,
                    rtol=1e-12)


def test_circular_and_escape_speeds_at_the_earths_surface():
    """v_c = sqrt(mu/R) = 7.91 km/s and v_esc = sqrt(2 mu/R) = 11.19 km/s (ch. 8.2.3)."""
    assert round(circular_speed(MU_EARTH, R_EARTH) / 1e3, 2) == 7.91
    assert round(escape_speed(MU_EARTH, R_EARTH) / 1e3, 2) == 11.19
    # a bit below escape: bound; a bit above: hyperbolic
    ve = escape_speed(MU_EARTH, R_EARTH)
    assert Orbit([R_EARTH, 0, 0], [0, 0.999 * ve, 0], mu=MU_EARTH).is_bound
    assert Orbit([R_EARTH, 0, 0], [0, 1.001 * ve, 0], mu=MU_EARTH).kind == "hyperbola"


@pytest.mark.parametrize("r1, r2", [
    pytest.param(6678e3, 42164e3, id="hohmann-leo-geo"),
    pytest.param(7000e3, 384400e3, id="hohmann-leo-moon-distance"),
])
def test_hohmann_transfer(r1, r2):
    """Ch. 27.3: by the vis-viva law v^2 = mu (2/r - 1/a) on the transfer ellipse
    a = (r1 + r2)/2: dv1 = v_t(r1) - v_c(r1), dv2 = v_c(r2) - v_t(r2), time pi sqrt(a^3/mu);
    LEO (300 km) to GEO: 2.43 + 1.47 = 3.89 km/s in 5.28 h."""
    h = hohmann_transfer(MU_EARTH, r1, r2)
    a = (r1 + r2) / 2
    vt = lambda r: math.sqrt(MU_EARTH * (2 / r - 1 / a))  # noqa: E731
    assert_allclose(h.delta_v1, vt(r1) - math.sqrt(MU_EARTH / r1), rtol=1e-12)
    assert_allclose(h.delta_v2, math.sqrt(MU_EARTH / r2) - vt(r2), rtol=1e-12)
    assert_allclose(h.time, math.pi * math.sqrt(a**3 / MU_EARTH), rtol=1e-14)
    if r2 == 42164e3:
        assert round(h.delta_v1 / 1e3, 2) == 2.43 and round(h.delta_v2 / 1e3, 2) == 1.47
        assert round(h.total_delta_v / 1e3, 2) == 3.89
        assert round(h.time / 3600, 2) == 5.28
