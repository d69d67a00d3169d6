"""The accelerations along the phases of a motion that changes regime
(PhasedMotion.derivative, ContactMotion.accelerations), issue 22: a block on a rough incline
(book, ch. 13.1, 23): a = g (sin alpha - f cos alpha) sliding down, g (sin alpha + f cos alpha)
(deceleration) sliding up, 0 while it sticks."""

import math

import numpy as np
import pytest

import rigidmech as rm
from rigidmech.actions import Coulomb, FrictionContact
from rigidmech.errors import ArgumentError
from rigidmech.kinematics import ContactKinematics
from rigidmech.regimes import PhasedMotion, contact_motion

G_ = 9.81


def _block(alpha, f, mass=2.0):
    """A block on a plane inclined by alpha: R0.i down the slope, R0.j its normal; gravity
    g (sin alpha R0.i - cos alpha R0.j)."""
    x, y = rm.coordinates("x y")
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, 0)
    Rb = R0.translated("Rb", G)
    s = rm.System(galilean=R0)
    s.connect(R0, rm.Body("block", frame=Rb, mass=mass, centre=G), FrictionContact(
        ContactKinematics(Rb, R0, at=R0.point("I", x, y, 0), normal=R0.j),
        friction=Coulomb(f)))
    s.act(rm.gravity(G_ * (math.sin(alpha) * R0.i - math.cos(alpha) * R0.j)))
    return s


def test_sliding_down_a_rough_incline_accelerates_at_the_closed_form():
    alpha, f = 0.6, 0.3                                   # tan alpha = 0.68 > f
    m = contact_motion(_block(alpha, f), 1.5, {"x": 0.0, "y": 0.0}, {"x": 0.5, "y": 0.0})
    assert m.regimes == ("slip+",)
    ts = np.linspace(0.0, 1.5, 31)
    acc = m.accelerations(ts)
    assert acc.shape == (2, 31)
    np.testing.assert_allclose(acc[0], G_ * (math.sin(alpha) - f * math.cos(alpha)),
                               rtol=1e-12)
    np.testing.assert_allclose(acc[1], 0.0, atol=1e-12)
    # an independent route: the slope of the velocity of the dense output
    h = 1e-4
    slope = (m(0.8 + h)[2] - m(0.8 - h)[2]) / (2 * h)
    assert slope == pytest.approx(acc[0, 16], rel=1e-6)
    # a single time gives the vector of the accelerations
    assert m.accelerations(0.8).shape == (2,)


def test_thrown_up_it_decelerates_then_sticks_where_tan_alpha_is_below_f():
    alpha, f = 0.3, 0.5                                   # tan alpha = 0.31 < f: it stays
    m = contact_motion(_block(alpha, f), 2.0, {"x": 0.0, "y": 0.0}, {"x": -3.0, "y": 0.0})
    assert m.regimes == ("slip-", "stick")
    a_up = G_ * (math.sin(alpha) + f * math.cos(alpha))
    t_stop = 3.0 / a_up                                   # v = -3 + a_up t = 0
    assert m.switch_times[0] == pytest.approx(t_stop, rel=1e-9)
    before, at, after = m.accelerations([0.5 * t_stop, m.switch_times[0], 1.5])[0]
    assert before == pytest.approx(a_up, rel=1e-12)
    assert at == pytest.approx(a_up, rel=1e-12)           # the phase that ends there
    assert after == pytest.approx(0.0, abs=1e-12)
    # the same instants' contact actions: T = -m g sin alpha holds it while it sticks
    N, T, _ = m.contact_actions(1.5)["I"]
    assert float(N) == pytest.approx(2.0 * G_ * math.cos(alpha), rel=1e-12)
    assert float(T[0]) == pytest.approx(-2.0 * G_ * math.sin(alpha), rel=1e-12)


def test_the_derivative_needs_the_regimes():
    done = contact_motion(_block(0.6, 0.3), 0.5, {"x": 0.0, "y": 0.0})
    bare = PhasedMotion(done.phases)
    with pytest.raises(ArgumentError, match=r"derivative\(\) needs the equations of the "
                                            r"regimes"):
        bare.derivative(0.1)


def test_an_expression_of_the_motion_along_the_phases():
    # m x'' - m g sin(alpha) is the friction force T: -f N sliding up... stuck: -m g sin(alpha)
    alpha, f, mass = 0.3, 0.5, 2.0
    s = _block(alpha, f, mass)
    m = contact_motion(s, 2.0, {"x": 0.0, "y": 0.0}, {"x": -3.0, "y": 0.0})
    x, y = s.coordinates
    ts = np.array([0.1, 0.3, 1.0, 1.9])
    friction = m.evaluate(mass * x.diff(rm.t, 2) - mass * G_ * math.sin(alpha), ts)
    T = [float(m.contact_actions(t)["I"][1][0]) for t in ts]
    np.testing.assert_allclose(friction, T, rtol=1e-12, atol=1e-12)
    assert friction[0] == pytest.approx(f * mass * G_ * math.cos(alpha), rel=1e-12)
    assert friction[-1] == pytest.approx(-mass * G_ * math.sin(alpha), rel=1e-12)
    assert m.evaluate(x.diff(rm.t) + rm.t, 0.0) == pytest.approx(-3.0)    # a single time


def test_evaluate_refuses_what_the_motion_does_not_know():
    s = _block(0.6, 0.3)
    m = contact_motion(s, 0.5, {"x": 0.0, "y": 0.0})
    x, y = s.coordinates
    k = rm.constants("k")
    with pytest.raises(ArgumentError, match=r"`expr` depends on \['k'\]"):
        m.evaluate(k * x, 0.1)
    with pytest.raises(ArgumentError, match="neither a coordinate of the system"):
        m.evaluate(x.diff(rm.t, 3), 0.1)
