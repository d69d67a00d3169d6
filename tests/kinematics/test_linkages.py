"""The four-bar from its lengths (ch. 9.4, 25.3.3): Grashof's classification, transmission
angle, dead points. Independent route: the linkage assembled numerically (C at the
intersection of the circles about B and D), the angle BCD measured on the positions, and the
range of crank angles at which it can be assembled."""

import math
from fractions import Fraction

import numpy as np
import pytest

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.kinematics.linkages import (
    GRASHOF_TYPES,
    UNIT_TOL,
    _within_unit,
    dead_points,
    grashof_type,
    is_grashof,
    transmission_angle,
)


def assemble(g, a, b, c, theta):
    """C of the open branch at crank angle theta (None if the circles do not meet)."""
    B = np.array([a * math.cos(theta), a * math.sin(theta)])
    D = np.array([g, 0.0])
    d = np.linalg.norm(D - B)
    x = (b * b - c * c + d * d) / (2 * d)
    h2 = b * b - x * x
    if h2 < 0:
        return None, B, D
    u = (D - B) / d
    n = np.array([-u[1], u[0]])
    return B + x * u + math.sqrt(h2) * n, B, D


@pytest.mark.parametrize("lengths", [(2.0, 1.0, 2.0, 1.5), (1.0, 2.0, 2.5, 3.0),
                                     (2.0, 3.0, 3.5, 1.8), (3.0, 2.0, 1.0, 2.5)])
def test_transmission_angle_against_assembled_positions(lengths):
    thetas = np.linspace(0, 2 * np.pi, 73)
    mu = transmission_angle(*lengths, thetas)
    for theta, m in zip(thetas, mu, strict=True):
        C, B, D = assemble(*lengths, theta)
        if C is None:
            assert math.isnan(m)
            continue
        u, v = B - C, D - C
        expected = math.acos(np.clip(u @ v / (np.linalg.norm(u) * np.linalg.norm(v)), -1, 1))
        assert m == pytest.approx(expected, abs=1e-9)


@pytest.mark.parametrize(("lengths", "kind"), [
    ((2.0, 1.0, 2.0, 1.5), "crank-rocker"),
    ((1.0, 2.0, 2.5, 3.0), "double-crank"),
    ((3.0, 2.0, 1.0, 2.5), "double-rocker"),
    ((2.0, 1.5, 2.0, 1.0), "rocker-crank"),
    ((2.0, 3.0, 3.5, 1.8), "triple-rocker"),
    ((1, 3, 2, 2), "change-point"),
    ((2.0, 1.0, 2.0, 1.0), "change-point"),          # parallelogram
])
def test_grashof_types(lengths, kind):
    assert grashof_type(*lengths) == kind
    assert kind in GRASHOF_TYPES
    assert is_grashof(*lengths) == (kind != "triple-rocker")


@pytest.mark.parametrize(("lengths", "crank_turns"), [
    ((2.0, 1.0, 2.0, 1.5), True), ((1.0, 2.0, 2.5, 3.0), True),
    ((3.0, 2.0, 1.0, 2.5), False), ((2.0, 1.5, 2.0, 1.0), False), ((2.0, 3.0, 3.5, 1.8), False),
])
def test_the_crank_turns_fully_exactly_for_crank_rocker_and_double_crank(lengths, crank_turns):
    mu = transmission_angle(*lengths, np.linspace(0, 2 * np.pi, 3601))
    assert bool(np.all(np.isfinite(mu))) == crank_turns


def test_change_point_boundary_exact_and_either_side():
    # s + l = p + q: 1 + 3 = 2 + 2; moving the longest by one float either side
    assert grashof_type(1.0, 3.0, 2.0, 2.0) == "change-point"
    assert grashof_type(1.0, np.nextafter(3.0, 0), 2.0, 2.0) == "double-crank"   # ground s
    assert grashof_type(1.0, np.nextafter(3.0, 4), 2.0, 2.0) == "triple-rocker"
    # exact rationals: 1/10 + 4/10 = 2/10 + 3/10 is a change point, the floats are not
    tenths = [Fraction(k, 10) for k in (1, 4, 2, 3)]
    assert grashof_type(*tenths) == "change-point"
    assert grashof_type(0.1, 0.4, 0.2, 0.3) in ("triple-rocker", "double-crank")


def test_loop_closure_boundary():
    assert grashof_type(1.0, 1.0, 1.0, np.nextafter(3.0, 0)) == "triple-rocker"   # just closes
    with pytest.raises(ArgumentError, match=r"cannot close a loop: `rocker` = 3.0 must be "
                                            r"shorter than the sum of the three others"):
        grashof_type(1.0, 1.0, 1.0, 3.0)                                           # flat
    with pytest.raises(ArgumentError, match=r"cannot close a loop"):
        grashof_type(1.0, 1.0, 1.0, 3.5)


@pytest.mark.parametrize(("args", "error", "match"), [
    ((0.0, 1.0, 1.0, 1.0), ArgumentError, r"`ground` must be a positive finite length"),
    ((1.0, -1.0, 1.0, 1.0), ArgumentError, r"`crank` must be a positive finite length"),
    ((1.0, 1.0, math.inf, 1.0), ArgumentError, r"`coupler` must be a positive finite length"),
    ((1.0, 1.0, 1.0, math.nan), ArgumentError, r"`rocker` must be a positive finite length"),
    ((1.0, "1", 1.0, 1.0), ArgumentTypeError, r"`crank` must be a positive number"),
    ((1.0, True, 1.0, 1.0), ArgumentTypeError, r"`crank` must be a positive number"),
])
def test_bad_lengths(args, error, match):
    with pytest.raises(error, match=match):
        grashof_type(*args)
    with pytest.raises(error, match=match):
        transmission_angle(*args, 0.0)
    with pytest.raises(error, match=match):
        dead_points(*args)


def test_bad_crank_angle():
    with pytest.raises(ArgumentError, match=r"`crank_angle` must be finite"):
        transmission_angle(2.0, 1.0, 2.0, 1.5, [0.0, math.nan])
    with pytest.raises(ArgumentTypeError, match=r"`crank_angle` must be a number"):
        transmission_angle(2.0, 1.0, 2.0, 1.5, "quarter")


def test_no_dead_points_when_the_crank_turns():
    assert dead_points(2.0, 1.0, 2.0, 1.5) == ()       # crank-rocker
    assert dead_points(1.0, 2.0, 2.5, 3.0) == ()       # double-crank


@pytest.mark.parametrize("lengths", [(3.0, 2.0, 1.0, 2.5), (2.0, 1.5, 2.0, 1.0),
                                     (2.0, 3.0, 3.5, 1.8)])
def test_dead_points_are_the_ends_of_the_reachable_range(lengths):
    points = dead_points(*lengths)
    assert points
    for theta, mu in points:
        assert transmission_angle(*lengths, theta) == pytest.approx(mu, abs=1e-6)
        # the crank cannot go past: reachable on one side, not on the other
        side = [math.isnan(transmission_angle(*lengths, theta + s * 1e-6)) for s in (-1, 1)]
        assert sorted(side) == [False, True]
        assert mu in (0.0, math.pi)


def test_dead_point_at_an_exact_toggle():
    # g = 2, a = 1, b = 2, c = 1 at theta = 0: BD = 1 = b - c, cos theta = 1 exactly, mu = 0
    points = dead_points(2.0, 1.0, 2.0, 1.0)
    assert (0.0, 0.0) in points
    assert transmission_angle(2.0, 1.0, 2.0, 1.0, 0.0) == 0.0
    # mu = pi where BD = b + c = 3: theta = pi exactly (BD = g + a)
    assert (math.pi, math.pi) in points
    assert transmission_angle(2.0, 1.0, 2.0, 1.0, math.pi) == math.pi


def test_transmission_angle_shapes():
    assert isinstance(transmission_angle(2.0, 1.0, 2.0, 1.5, 0.3), float)
    assert transmission_angle(2.0, 1.0, 2.0, 1.5, np.zeros((2, 3))).shape == (2, 3)


def test_the_one_reachability_rule_at_its_threshold():
    assert _within_unit(1.0 + UNIT_TOL) and _within_unit(-1.0 - UNIT_TOL)
    assert not _within_unit(np.nextafter(1.0 + UNIT_TOL, 2))
    assert not _within_unit(np.nextafter(-1.0 - UNIT_TOL, -2))
    assert _within_unit(np.nextafter(1.0 + UNIT_TOL, 0))
