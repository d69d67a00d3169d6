"""Orbit.from_apsides and Orbit.circular (ch. 8.2): the ellipse from its apsides and the circle
of a given period, checked against the closed forms a = (r_p + r_a)/2,
e = (r_a - r_p)/(r_a + r_p), T = 2 pi sqrt(a^3/mu), vis-viva, and the classical angles."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.kinematics import Orbit, circular_speed


@pytest.mark.parametrize(("rp", "ra", "mu"), [(1.0, 3.0, 1.0), (7000e3, 42164e3, 3.986004418e14),
                                              (2.0, 2.5, 0.3), (1.0, 1e4, 1.0)])
def test_from_apsides_elements(rp, ra, mu):
    o = Orbit.from_apsides(rp, ra, mu=mu)
    a = (rp + ra) / 2
    assert o.kind == "ellipse"
    assert o.periapsis == pytest.approx(rp, rel=1e-12)
    assert o.apoapsis == pytest.approx(ra, rel=1e-12)
    assert o.semi_major_axis == pytest.approx(a, rel=1e-12)
    assert o.eccentricity == pytest.approx((ra - rp) / (ra + rp), rel=1e-12)
    assert o.period == pytest.approx(2 * math.pi * math.sqrt(a**3 / mu), rel=1e-12)
    # vis-viva at the periapsis
    assert np.linalg.norm(o.state_at(0.0)[1]) == pytest.approx(
        math.sqrt(mu * (2 / rp - 1 / a)), rel=1e-12)


def test_from_apsides_default_plane_and_motion():
    o = Orbit.from_apsides(1.0, 3.0, mu=1.0)
    assert_allclose(o.periapsis_direction, [1, 0, 0], atol=1e-15)
    assert_allclose(o.normal, [0, 0, 1], atol=1e-15)        # counterclockwise about z
    r, v = o.state_at(o.period / 2)                          # at the apoapsis, on -x
    assert_allclose(r, [-3, 0, 0], atol=1e-12)
    assert v[1] < 0


def test_from_apsides_epoch_is_the_periapsis_passage():
    o = Orbit.from_apsides(1.0, 3.0, mu=1.0, epoch=5.0)
    assert o.time_of_periapsis == pytest.approx(5.0, abs=1e-12)
    assert_allclose(o.state_at(5.0)[0], [1, 0, 0], atol=1e-15)
    assert_allclose(o.state_at(5.0 + o.period)[0], [1, 0, 0], atol=1e-12)


@pytest.mark.parametrize(("raan", "inc", "argp"), [(0.3, 0.7, 1.1), (2.0, 2.5, 4.0),
                                                   (5.5, math.pi / 2, 0.2), (1.0, 0.1, 6.0)])
def test_from_apsides_angles_round_trip(raan, inc, argp):
    o = Orbit.from_apsides(1.0, 2.0, mu=1.0, raan=raan, inclination=inc,
                           argument_of_periapsis=argp)
    assert o.inclination == pytest.approx(inc, abs=1e-12)
    assert o.argument_of_periapsis == pytest.approx(argp, abs=1e-12)
    expected_normal = [math.sin(raan) * math.sin(inc), -math.cos(raan) * math.sin(inc),
                       math.cos(inc)]
    assert_allclose(o.normal, expected_normal, atol=1e-15)
    # ascending node direction (cos raan, sin raan, 0) lies in the plane
    assert abs(np.dot(o.normal, [math.cos(raan), math.sin(raan), 0])) < 1e-15


def test_equatorial_argument_is_measured_from_x():
    o = Orbit.from_apsides(1.0, 2.0, mu=1.0, raan=0.5, argument_of_periapsis=0.25)
    assert o.argument_of_periapsis == pytest.approx(0.75, abs=1e-12)


def test_apoapsis_equal_to_periapsis_is_a_circle_and_either_side():
    assert Orbit.from_apsides(2.0, 2.0, mu=1.0).kind == "circle"                 # boundary
    o = Orbit.from_apsides(2.0, 2.0 * (1 + 1e-6), mu=1.0)                         # just above
    assert o.kind == "ellipse"
    assert o.eccentricity == pytest.approx(1e-6 / (2 + 1e-6), rel=1e-9)
    with pytest.raises(ArgumentError, match=r"`apoapsis` must be >= `periapsis`.*Swap"):
        Orbit.from_apsides(2.0, 2.0 * (1 - 1e-15), mu=1.0)                        # just below


@pytest.mark.parametrize(("kwargs", "error", "match"), [
    (dict(periapsis=0.0), ArgumentError, r"`periapsis` must be a positive finite number"),
    (dict(apoapsis=math.inf), ArgumentError, r"`apoapsis` must be a positive finite number"),
    (dict(mu=-1.0), ArgumentError, r"`mu` must be a positive finite number"),
    (dict(inclination=-0.1), ArgumentError, r"`inclination` must lie in \[0, pi\]"),
    (dict(inclination=math.pi + 1e-9), ArgumentError, r"`inclination` must lie in \[0, pi\]"),
    (dict(raan=math.nan), ArgumentError, r"`raan` must be finite"),
    (dict(argument_of_periapsis="x"), ArgumentTypeError,
     r"`argument_of_periapsis` must be a real number"),
    (dict(epoch=math.inf), ArgumentError, r"`epoch` must be a finite number"),
])
def test_from_apsides_bad_input(kwargs, error, match):
    args = dict(periapsis=1.0, apoapsis=2.0, mu=1.0) | kwargs
    with pytest.raises(error, match=match):
        Orbit.from_apsides(**args)


def test_inclination_boundaries_accepted():
    assert Orbit.from_apsides(1.0, 2.0, mu=1.0, inclination=0.0).inclination == 0.0
    o = Orbit.from_apsides(1.0, 2.0, mu=1.0, inclination=math.pi)         # retrograde
    assert o.inclination == pytest.approx(math.pi, abs=1e-12)


@pytest.mark.parametrize(("T", "mu"), [(2 * math.pi, 1.0), (1.0, 4.0),
                                       (86164.0905, 3.986004418e14)])
def test_circular_of_period_kepler_third_law(T, mu):
    o = Orbit.circular(T, mu=mu)
    r = (mu * T**2 / (4 * math.pi**2)) ** (1 / 3)
    assert o.kind == "circle"
    assert o.period == pytest.approx(T, rel=1e-12)
    assert o.periapsis == pytest.approx(r, rel=1e-12)
    assert o.apoapsis == pytest.approx(r, rel=1e-12)
    rr, v = o.state_at(np.linspace(0, T, 7))
    assert_allclose(np.linalg.norm(rr, axis=1), r, rtol=1e-12)
    assert_allclose(np.linalg.norm(v, axis=1), circular_speed(mu, r), rtol=1e-12)


def test_geostationary_radius():
    # sidereal day, Earth's mu: the textbook geostationary radius 42 164 km
    o = Orbit.circular(86164.0905, mu=3.986004418e14)
    assert o.periapsis == pytest.approx(42164.17e3, abs=10.0)


def test_circular_position_at_epoch():
    o = Orbit.circular(2 * math.pi, mu=1.0, inclination=math.pi / 2, argument_of_periapsis=0.5,
                       epoch=1.0)
    assert_allclose(o.state_at(1.0)[0], [math.cos(0.5), 0, math.sin(0.5)], atol=1e-15)


@pytest.mark.parametrize(("period", "error", "match"), [
    (0.0, ArgumentError, r"`period` must be a positive finite number"),
    (-1.0, ArgumentError, r"`period` must be a positive finite number"),
    (math.nan, ArgumentError, r"`period` must be a positive finite number"),
    ("day", ArgumentTypeError, r"`period` must be a positive number"),
])
def test_circular_bad_period(period, error, match):
    with pytest.raises(error, match=match):
        Orbit.circular(period, mu=1.0)


def test_elements_are_python_floats():
    # regression: the energy came out as numpy.float64 (r was a numpy scalar), and with it a,
    # the apoapsis, the period
    o = Orbit.from_apsides(1.0, 3.0, mu=1.0)
    for value in (o.specific_energy, o.semi_major_axis, o.apoapsis, o.period, o.periapsis):
        assert type(value) is float


@settings(max_examples=60, deadline=None)
@given(rp=st.floats(0.1, 10), ratio=st.floats(1.0, 50), raan=st.floats(0, 2 * math.pi),
       inc=st.floats(0, math.pi), argp=st.floats(0, 2 * math.pi), epoch=st.floats(-5, 5))
def test_from_apsides_round_trip_property(rp, ratio, raan, inc, argp, epoch):
    ra = rp * ratio
    o = Orbit.from_apsides(rp, ra, mu=1.0, raan=raan, inclination=inc,
                           argument_of_periapsis=argp, epoch=epoch)
    assert o.periapsis == pytest.approx(rp, rel=1e-10)
    assert o.apoapsis == pytest.approx(ra, rel=1e-10)
    r_peri = o.state_at(epoch)[0]
    r_apo = o.state_at(epoch + o.period / 2)[0]
    assert np.linalg.norm(r_peri) == pytest.approx(rp, rel=1e-10)
    if o.kind == "ellipse":
        assert np.linalg.norm(r_apo) == pytest.approx(ra, rel=1e-9)
        assert_allclose(r_apo / ra, -r_peri / rp, atol=1e-8)   # opposite the periapsis
