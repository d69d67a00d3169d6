"""Book ch. 12: gravitation between point masses, the field of a solid sphere, gravity as
the local approximation (ch. 12.1.1-12.2.1).

Conventions: G = 6.67430e-11 m^3 kg^-1 s^-2 (CODATA 2018); the Earth homogeneous,
M = 5.972e24 kg, R = 6.371e6 m; the Moon m = 7.342e22 kg at d = 3.844e8 m.
Closed forms: F = G m1 m2 / d^2; g(r) = G M / r^2 outside, G M r / R^3 inside;
E_p = -G M m / r; escape speed from E_k + E_p = 0.
"""

import math

import pytest
import sympy as sp
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech._core.errors import ArgumentError
from rigidmech.actions import (
    GRAVITATIONAL_CONSTANT,
    NewtonAttraction,
    SphericalBodyAttraction,
    homogeneous_sphere_attractor,
    point_mass_attractor,
    spherical_shell_attractor,
    surface_gravity,
)
from rigidmech.kinematics import escape_speed

G = 6.67430e-11
M_EARTH, R_EARTH = 5.972e24, 6.371e6
M_MOON, D_MOON = 7.342e22, 3.844e8


def test_earth_moon_attraction():
    """F = G M m / d^2 = 1.98e20 N, on each body towards the other (ch. 12.1.1)."""
    R0 = rm.Frame("R0")
    earth = rm.Body("earth", frame=R0, mass=M_EARTH)
    moon = rm.Body("moon", frame=R0.translated("Rm", R0.point("L", D_MOON, 0, 0)),
                   mass=M_MOON)
    (_, on_moon), (_, on_earth) = NewtonAttraction(earth, moon).contributions([earth, moon])
    F = G * M_EARTH * M_MOON / D_MOON**2
    assert_allclose(float(on_moon.resultant.components(R0)[0]), -F, rtol=1e-14)
    assert_allclose(float(on_earth.resultant.components(R0)[0]), F, rtol=1e-14)
    assert round(F / 1e20, 2) == 1.98
    assert GRAVITATIONAL_CONSTANT == G


@pytest.mark.parametrize("depth_fraction, expected_ratio", [
    pytest.param(0.0, 1.0, id="surface"),
    pytest.param(0.5, 0.5, id="half-radius"),
    pytest.param(1.0, 0.0, id="centre"),
])
def test_gravity_inside_the_homogeneous_earth(depth_fraction, expected_ratio):
    """g(r) = g0 r / R inside a homogeneous sphere (ch. 12.1.3)."""
    earth = homogeneous_sphere_attractor(M_EARTH, R_EARTH)
    r = R_EARTH * (1 - depth_fraction)
    g0 = G * M_EARTH / R_EARTH**2
    assert_allclose(float(earth.field_magnitude(r)), expected_ratio * g0, rtol=1e-13)


def test_gravity_at_the_surface_and_with_altitude():
    """g0 = G M / R^2 = 9.82 m/s^2 (ch. 12.2.1); at 400 km (ISS) g = g0 (R/(R+h))^2 = 8.69."""
    g0 = float(surface_gravity(M_EARTH, R_EARTH))
    assert_allclose(g0, G * M_EARTH / R_EARTH**2, rtol=1e-14)
    assert round(g0, 2) == 9.82
    g400 = float(point_mass_attractor(M_EARTH).field_magnitude(R_EARTH + 400e3))
    assert_allclose(g400, g0 * (R_EARTH / (R_EARTH + 400e3)) ** 2, rtol=1e-13)
    assert round(g400, 2) == 8.69


def test_spherical_shell_theorem():
    """No field inside a shell; outside as a point mass (ch. 12.1.3)."""
    shell = spherical_shell_attractor(1.0e3, 2.0)
    assert shell.field_magnitude(1.0) == 0
    assert_allclose(float(shell.field_magnitude(4.0)), G * 1.0e3 / 16, rtol=1e-14)


def test_escape_speed_from_the_energy():
    """E_k + E_p = 0: m v^2/2 - G M m / R = 0 gives v = sqrt(2 G M / R) = 11.19 km/s, the
    same as the kinematic escape speed with mu = G M (ch. 8.2.3, 12.1)."""
    m, v = sp.symbols("m v", positive=True)
    R0 = rm.Frame("R0")
    probe = rm.Body("probe", frame=R0.translated("Rp", R0.point("P", R_EARTH, 0, 0)), mass=m)
    earth = SphericalBodyAttraction(homogeneous_sphere_attractor(M_EARTH, R_EARTH),
                                    centre=R0.origin)
    Ep = earth.potential_energy([probe], R0)
    (v_esc,) = sp.solve(m * v**2 / 2 + Ep, v)
    assert_allclose(float(v_esc), escape_speed(G * M_EARTH, R_EARTH), rtol=1e-13)
    assert round(float(v_esc) / 1e3, 2) == 11.19


def test_negative_mass_is_refused():
    with pytest.raises(ArgumentError, match="`mass` must be >= 0; got -5.972e\\+24"):
        homogeneous_sphere_attractor(-M_EARTH, R_EARTH)
    with pytest.raises(ArgumentError, match="`mass` must be >= 0"):
        point_mass_attractor(-1.0)
    R0 = rm.Frame("R0")
    with pytest.raises(ArgumentError, match="`mass` must be >= 0"):
        NewtonAttraction(rm.Body("a", frame=R0, mass=-1), rm.Body("b", frame=R0, mass=1))
    assert math.isfinite(float(surface_gravity(1, 1)))
