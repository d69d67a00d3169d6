"""`OdeResult.t_stop` and `y_stop`: where the integration got to, for every way a run ends
(issue 10: no need to parse "at t = ..." from the message)."""

import math
import re

import numpy as np
import pytest
from numpy.testing import assert_allclose

from rigidmech import ode


def osc(t, y):
    return np.array([y[1], -y[0]])


def acc(t, q):
    return -q


@pytest.mark.parametrize("method,kw", [
    ("dopri5", {}), ("dop853", {}), ("radau", {}), ("adams", {}), ("gbs", {}),
    ("rk4", {"step": 0.01}), ("ab4", {"step": 0.01}),
])
@pytest.mark.parametrize("t_eval", [None, np.linspace(0.0, 4.0, 9)], ids=["steps", "t_eval"])
def test_t_stop_is_the_end_of_a_finished_run(method, kw, t_eval):
    r = ode.solve(osc, (0.0, 4.0), [1.0, 0.0], method=method, t_eval=t_eval, **kw)
    assert r.status == 0 and r.t_stop == 4.0
    assert_allclose(r.y_stop, [math.cos(4.0), -math.sin(4.0)], atol=1e-4)
    assert r.y_stop.shape == (2,)


@pytest.mark.parametrize("method", ["dopri5", "dop853", "gbs", "radau", "adams"])
def test_t_stop_after_a_failure_is_the_last_accepted_step(method):
    # y' = y^2, y(0) = 1: y = 1 / (1 - t) blows up at t = 1; samples asked for every 0.25
    t_eval = np.linspace(0.0, 2.0, 9)
    r = ode.solve(lambda t, y: y * y, (0.0, 2.0), [1.0], method=method, t_eval=t_eval)
    assert r.status == -1
    # the numerical solution may cross the singularity by a rounding-size margin
    assert 0.99 < r.t_stop < 1.0 + 1e-5 and r.t[-1] <= r.t_stop
    assert r.y_stop.shape == (1,) and 1e6 < r.y_stop[0] < math.inf
    found = re.search(r"at t = (\S+?)[;,]", r.message)  # the message names the same time
    assert float(found.group(1)) == r.t_stop


def test_t_stop_of_a_terminal_event_is_the_event_time():
    def ground(t, y):
        return y[0]

    ground.terminal = True
    r = ode.solve(lambda t, y: np.array([y[1], -9.81]), (0.0, 5.0), [10.0, 0.0],
                  method="dop853", events=ground, rtol=1e-10, t_eval=np.linspace(0, 5, 11))
    assert r.status == 1
    assert_allclose(r.t_stop, math.sqrt(2 * 10.0 / 9.81), rtol=1e-9)
    assert r.t_stop == r.t_events[0][0]
    assert_allclose(r.y_stop[0], 0.0, atol=1e-8)


@pytest.mark.parametrize("method,fun", [("dopri5", osc), ("adams", osc), ("rk4", osc),
                                        ("verlet", acc)])
def test_t_stop_of_an_early_stop_is_the_last_step_made(method, fun):
    kw = {"step": 0.01} if method in ("rk4", "verlet") else {"rtol": 1e-9, "atol": 1e-12}
    r = ode.solve(fun, (0.0, 10.0), [1.0, 0.0], method=method, t_eval=[0.0, 5.0, 10.0],
                  progress=lambda t: t < 2.0, **kw)
    assert r.status == 2
    assert 2.0 <= r.t_stop < 2.5 and r.t.tolist() == [0.0]
    assert_allclose(r.y_stop, [math.cos(r.t_stop), -math.sin(r.t_stop)], atol=1e-4)
    assert f"at t = {r.t_stop!r}" in r.message


def test_t_stop_of_a_fixed_step_blow_up_is_the_last_finite_step():
    r = ode.solve(lambda t, y: y * y, (0.0, 2.0), [1.0], method="rk4", step=0.01)
    assert r.status == -1 and r.t_stop == r.t[-1] and np.isfinite(r.y_stop).all()


def test_t_stop_of_an_empty_span_is_t0_and_a_batch_keeps_its_shape():
    r = ode.solve(osc, (1.0, 1.0), [1.0, 0.0])
    assert r.t_stop == 1.0 and r.y_stop.tolist() == [1.0, 0.0]
    y0 = np.array([[1.0, 2.0], [0.0, 0.0]])
    b = ode.solve(lambda t, y: np.stack([y[1], -y[0]]), (0.0, 1.0), y0, method="dopri5")
    assert b.y_stop.shape == (2, 2) and b.t_stop == 1.0
