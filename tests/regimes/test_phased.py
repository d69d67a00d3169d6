"""The phase-by-phase integrator (rigidmech.regimes.phased)."""

import math

import matplotlib
import matplotlib.pyplot
import numpy as np
import pytest

from rigidmech._core.errors import ArgumentError, ArgumentTypeError, NumericalError
from rigidmech.actions import Coulomb
from rigidmech.regimes import Guard, PhasedMotion, Regime, coulomb_oscillator, integrate_phases

matplotlib.use("Agg")


def bouncing_ball(restitution=0.5):
    # free fall from 1 m, bounces with v -> -e v: the n-th impact at closed-form instants
    fall = Regime("flight", lambda t, y: np.array([y[1], -9.81]),
                  [Guard("impact", lambda t, y: y[0], target="flight", direction=-1,
                         reset=lambda t, y: [0.0, -restitution * y[1]])])
    return fall


def test_bouncing_ball_impacts_match_closed_form():
    # first impact at sqrt(2h/g), then flights of 2 e^k v1 / g
    e, g = 0.5, 9.81
    m = integrate_phases([bouncing_ball(e)], "flight", (0.0, 1.5), [1.0, 0.0], rtol=1e-12)
    t1 = math.sqrt(2 / g)
    v1 = g * t1
    expected = [t1]
    for k in range(1, len(m.switch_times)):
        expected.append(expected[-1] + 2 * e**k * v1 / g)
    np.testing.assert_allclose(m.switch_times, expected, rtol=1e-9)
    assert set(m.regimes) == {"flight"} and len(m.phases) == len(expected) + 1


def test_motion_evaluates_prints_and_plots():
    m = coulomb_oscillator(mass=1.0, stiffness=1.0, friction=Coulomb(0.15), normal_force=1.0,
                           x0=1.0, t_end=12.0)
    assert isinstance(m, PhasedMotion)
    assert repr(m) == "PhasedMotion(4 phases: slide- -> slide+ -> slide- -> stick)"
    text = m.table()
    assert text.splitlines()[0].split() == ["phase", "regime", "start", "end", "ended", "by"]
    assert "stops" in text and str(m) == text
    x = m([0.0, math.pi / 2, 11.0])
    np.testing.assert_allclose(x[0], [1.0, 0.15, -0.1], atol=1e-10)   # 0.15 + 0.85 cos(pi/2)
    assert m.t.shape[0] == m.y.shape[1]
    (ax,) = m.plot(component=0, label="x")
    assert ax.get_ylabel() == "x" and len(ax.get_lines()) >= 4
    matplotlib.pyplot.close("all")


def test_bad_input():
    r = Regime("a", lambda t, y: -y)
    with pytest.raises(ArgumentError, match=r"unknown regime 'b'; the regimes are a"):
        integrate_phases([r], "b", (0.0, 1.0), [1.0])
    with pytest.raises(ArgumentError, match=r"`t_span` must run forward"):
        integrate_phases([r], "a", (1.0, 0.0), [1.0])
    with pytest.raises(ArgumentTypeError, match=r"`guards\[0\]` must be a Guard"):
        Regime("a", None, ["not a guard"])
    with pytest.raises(ArgumentTypeError, match=r"`function` must be callable"):
        Guard("g", 3.0)
    with pytest.raises(ArgumentTypeError, match=r"`regimes` must hold Regime"):
        integrate_phases(["a"], "a", (0.0, 1.0), [1.0])


def test_too_many_phases_is_reported():
    with pytest.raises(NumericalError, match=r"more than `max_phases` = 3 phases"):
        integrate_phases([bouncing_ball()], "flight", (0.0, 5.0), [1.0, 0.0], max_phases=3)


def test_a_guard_exactly_zero_at_the_start_of_a_phase_does_not_fire_again():
    # the guard that ended a phase is zero where the next one starts: that zero is not an
    # event, so the motion does not switch again at the same instant
    flip = Regime("up", lambda t, y: np.array([1.0]),
                  [Guard("g", lambda t, y: 1.0 - t, target="up", direction=-1)])
    m = integrate_phases([flip], "up", (0.0, 2.0), [0.0])
    assert m.regimes == ("up", "up") and math.isclose(m.switch_times[0], 1.0, rel_tol=1e-12)
