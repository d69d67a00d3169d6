"""Events: zeros of g(t, y) located on the dense output, direction and terminal honoured."""

import numpy as np
import pytest
from _ode_exact import oscillator_rhs
from numpy.testing import assert_allclose

from rigidmech import ode
from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.ode.events import EventTracker

G, H = 9.81, 20.0


def fall(t, y):
    return np.array([y[1], -G])


@pytest.mark.parametrize(
    ("method", "kw"),
    [("dop853", {}), ("dopri5", {}), ("radau", {}), ("gbs", {}), ("rk4", {"step": 0.05}),
     ("euler", {"step": 0.01})],
)
def test_ball_hits_the_ground_at_sqrt_2h_over_g(method, kw):
    ground = ode.event(lambda t, y: y[0], terminal=True, direction=-1)
    r = ode.solve(fall, (0.0, 10.0), [H, 0.0], method=method, events=ground, **kw)
    t_hit = np.sqrt(2 * H / G)
    # the motion is a parabola: every method except Euler and every interpolant (cubic
    # Hermite included) is exact on it, so the root is found to Brent's tolerance
    tol = 1e-10 if method != "euler" else 0.06  # Euler: O(h) error in the motion itself
    assert r.status == 1 and "terminal event" in r.message
    assert_allclose(r.t_events[0], [t_hit], atol=tol)
    assert r.t[-1] == r.t_events[0][0]
    assert_allclose(r.y[:, -1], r.y_events[0][0])
    if method != "euler":
        assert_allclose(r.y_events[0][0], [0.0, -G * t_hit], atol=1e-9)


def test_direction_selects_crossings():
    # x = cos t crosses zero at pi/2 (downwards), 3pi/2 (upwards), 5pi/2 (downwards) ...
    def down(t, y):
        return y[0]

    down.direction = -1

    def up(t, y):
        return y[0]

    up.direction = 1

    def both(t, y):
        return y[0]

    r = ode.solve(oscillator_rhs, (0.0, 10.0), [1.0, 0.0], rtol=1e-12, atol=1e-12,
                  events=[down, up, both])
    assert r.status == 0
    # dense output of DOP853 at rtol 1e-12: roots to ~1e-11
    assert_allclose(r.t_events[0], [np.pi / 2, 5 * np.pi / 2], atol=1e-10)
    assert_allclose(r.t_events[1], [3 * np.pi / 2], atol=1e-10)
    assert_allclose(r.t_events[2], np.arange(1, 7, 2) * np.pi / 2, atol=1e-10)
    assert r.y_events[0].shape == (2, 2) and r.y_events[1].shape == (1, 2)


def test_terminal_count_stops_at_the_kth_zero():
    g = ode.event(lambda t, y: y[0], terminal=2)
    r = ode.solve(oscillator_rhs, (0.0, 10.0), [1.0, 0.0], rtol=1e-12, atol=1e-12, events=g)
    assert r.status == 1
    assert_allclose(r.t[-1], 3 * np.pi / 2, atol=1e-10)


def test_terminal_event_with_t_eval_and_dense_output():
    ground = ode.event(lambda t, y: y[0], terminal=True, direction=-1)
    te = np.linspace(0, 10, 101)
    r = ode.solve(fall, (0.0, 10.0), [H, 0.0], events=ground, t_eval=te, dense_output=True)
    t_hit = np.sqrt(2 * H / G)
    assert r.t[-1] <= t_hit and len(r.t) == np.sum(te <= t_hit)
    assert_allclose(r.y[0], H - G * r.t**2 / 2, atol=1e-9)
    assert_allclose(r.sol(1.0)[0], H - G / 2, atol=1e-12)


def test_no_event_found_gives_empty_arrays():
    r = ode.solve(fall, (0.0, 1.0), [H, 0.0], events=lambda t, y: y[0])
    assert r.status == 0 and r.t_events[0].shape == (0,) and r.y_events[0].shape == (0, 2)


def test_event_misuse():
    def bad(t, y):
        return y[0]

    bad.terminal = -1
    with pytest.raises(ArgumentError, match=r"`events\[0\].terminal` must be a bool or an int"):
        ode.solve(fall, (0.0, 1.0), [H, 0.0], events=[bad])
    with pytest.raises(ArgumentTypeError, match=r"event function `events\[0\]` must return a "
                       r"real scalar; got array"):
        ode.solve(fall, (0.0, 1.0), [H, 0.0], events=lambda t, y: y)
    with pytest.raises(ArgumentTypeError, match=r"`fn` must be callable; got int"):
        ode.event(3)


def test_tracker_reports_zero_at_step_end_once():
    tr = EventTracker(lambda t, y: y[0] - 1.0, 0.0, np.array([0.0]))
    assert not tr.check(0.0, 1.0, np.array([1.0]), lambda t: np.array([t]))
    assert not tr.check(1.0, 2.0, np.array([2.0]), lambda t: np.array([t]))
    assert [list(v) for v in tr.t_events] == [[1.0]]


def test_events_and_t_eval_for_a_second_order_method():
    # q'' = -g with Stormer-Verlet (part B): exact on a parabola, like its Hermite interpolant
    ground = ode.event(lambda t, y: y[0], terminal=True, direction=-1)
    r = ode.solve(lambda t, q: np.array([-G]), (0.0, 10.0), [H, 0.0], method="verlet",
                  step=0.05, events=ground, t_eval=[0.5, 1.0])
    assert r.status == 1
    assert_allclose(r.t_events[0], [np.sqrt(2 * H / G)], atol=1e-10)
    assert_allclose(r.y, [[H - G / 8, H - G / 2], [-G / 2, -G]], atol=1e-12)


def test_zero_at_the_initial_state_is_not_an_event():
    # thrown upwards from the ground: lands at 2 v0 / g, not at t = 0
    ground = ode.event(lambda t, y: y[0], terminal=True)
    r = ode.solve(fall, (0.0, 10.0), [0.0, 10.0], events=ground)
    assert_allclose(r.t_events[0], [2 * 10.0 / G], atol=1e-10)


@pytest.mark.parametrize(("method", "kw"), [("dop853", {}), ("radau", {}), ("rk4", {"step": 0.01})])
def test_events_when_integrating_backwards(method, kw):
    # y' = -y from y(2) = exp(-2) back to t = 0: y = 1/2 at t = ln 2
    g = ode.event(lambda t, y: y[0] - 0.5, terminal=True)
    r = ode.solve(lambda t, y: -y, (2.0, 0.0), [np.exp(-2.0)], method=method, rtol=1e-10,
                  atol=1e-12, events=g, **kw)
    assert r.status == 1
    # root of the interpolant: as accurate as the solution there (RK4 h = 0.01: ~1e-9)
    assert_allclose(r.t_events[0], [np.log(2.0)], atol=1e-8)
