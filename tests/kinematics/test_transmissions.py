"""Transmissions (book, ch. 10.2): gear pairs, trains, Willis' relation, belts.

Expected values: r = m z / 2; external ratio -r1/r2, internal r1/r2; centre distance r1 + r2
or r2 - r1; Willis' relation solved by hand; belt lengths checked against an independent
numerical construction (tests/textbook/test_ch10_contact.py) and simple limits here."""

import math

import pytest
import sympy as sp
from hypothesis import example, given
from hypothesis import strategies as st

from rigidmech.kinematics import BeltDrive, EpicyclicTrain, Gear, GearPair, GearTrain


def test_gear_pair_from_teeth_and_module():
    pair = GearPair(Gear(18, 3), Gear(54, 3))
    assert pair.radii == (27, 81)
    assert pair.ratio == sp.Rational(-1, 3) and pair.centre_distance == 108
    ring = GearPair(Gear(18, 3), Gear(54, 3), internal=True)
    assert ring.ratio == sp.Rational(1, 3) and ring.centre_distance == 54
    m, z1, z2 = sp.symbols("m z1 z2", positive=True)
    assert GearPair(Gear(z1, m), Gear(z2, m)).ratio == -z1 / z2


def test_gear_train_ratio_is_the_product_and_idlers_only_change_the_sign():
    a, b, c = Gear(12, 1), Gear(36, 1), Gear(24, 1)
    # A -> B (idler) -> C: ratio (-12/36)(-36/24) = 12/24, the idler's size drops out
    train = GearTrain(GearPair(a, b), GearPair(b, c))
    assert train.ratio == sp.Rational(1, 2) and train.external_meshes == 2
    three = GearTrain(GearPair(a, b), GearPair(b, c), GearPair(c, a))
    assert three.ratio == -1 and three.external_meshes == 3


def test_willis_solves_each_unknown():
    lam = sp.Rational(-1, 4)
    train = EpicyclicTrain(lam)
    # (w3 - wc) = lam (w1 - wc), worked by hand for (w1, w3, wc) = (100, 0, 20)
    assert train.solve(first=100, last=0) == {"carrier": 20}
    assert train.solve(last=0, carrier=20) == {"first": 100}
    assert train.solve(first=100, carrier=20) == {"last": 0}
    assert train.relation(100, 0, 20) == 0


def test_open_belt_with_equal_pulleys_and_limits():
    belt = BeltDrive(2, 2, 10)
    assert belt.ratio == 1 and belt.length == 20 + 4 * sp.pi
    crossed = BeltDrive(1, 2, 5, crossed=True)
    assert crossed.ratio == sp.Rational(-1, 2)
    beta = math.asin(3 / 5)  # (r1 + r2) / a
    assert math.isclose(float(crossed.length), 2 * 4 + (math.pi + 2 * beta) * 3, rel_tol=1e-14)
    assert crossed.belt_speed(sp.Symbol("w")) == sp.Symbol("w")


@given(r1=st.floats(0.1, 5), r2=st.floats(0.1, 5), extra=st.floats(0.01, 10))
# radii 1 ulp apart: w2 - w1 = 4 beta = -5.6e-17 is below half an ulp of pi, so float(w1) and
# float(w2) are both the double nearest pi; the order is read from w2 - w1 itself (the wrap
# angles are pi -+ 2 beta: sympy cancels pi exactly and the sign of beta is that of r2 - r1)
@example(r1=math.nextafter(0.1, 1.0), r2=0.1, extra=1.0)
def test_open_belt_wrap_angles_sum_to_two_pi(r1, r2, extra):
    belt = BeltDrive(r1, r2, abs(r2 - r1) + extra)
    w1, w2 = belt.wrap_angles
    assert math.isclose(float(w1 + w2), 2 * math.pi, rel_tol=1e-12)
    # the larger pulley is wrapped more, equal pulleys equally
    assert sp.sign(w2 - w1) == sp.sign(r2 - r1)


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="gears mesh only with equal modules; got `first` of "
                                         "module 2 and `second` of module 3"):
        GearPair(Gear(20, 2), Gear(30, 3))
    with pytest.raises(ValueError, match="`teeth` must be a positive integer; got 12.5"):
        Gear(12.5, 1)
    with pytest.raises(ValueError, match="`module` must be positive; got -1"):
        Gear(12, -1)
    with pytest.raises(ValueError, match="`first` must be positive; got -3"):
        GearPair.from_radii(-3, 2)
    with pytest.raises(ValueError, match="internal pair needs the ring"):
        GearPair.from_radii(3, 2, internal=True)
    with pytest.raises(TypeError, match="`first` must be a Gear"):
        GearPair(20, Gear(30, 1))
    with pytest.raises(ValueError, match="exactly one of `first`, `last`, `carrier`"):
        EpicyclicTrain(-2).solve(first=1)
    with pytest.raises(ValueError, match="`ratio` must not be 1"):
        EpicyclicTrain(1)
    with pytest.raises(ValueError, match="`centre_distance` must exceed r1 \\+ r2 = 3"):
        BeltDrive(1, 2, 3, crossed=True)
    with pytest.raises(ValueError, match="`centre_distance` must exceed abs\\(r2 - r1\\)"):
        BeltDrive(1, 5, 2)
    with pytest.raises(ValueError, match="`second` must be positive; got 0"):
        BeltDrive(1, 0, 2)
    with pytest.raises(ValueError, match="at least one GearPair"):
        GearTrain()
