"""adams like the loop's methods (issues 15 and 10): `progress` after every step and Ctrl-C
kept as status 2 with the steps made so far."""

import numpy as np
import pytest
from numpy.testing import assert_array_equal

from rigidmech import ode


def osc(t, y):
    return np.array([y[1], -y[0]])


@pytest.mark.parametrize("y0", [[1.0, 0.0], [[1.0, 2.0], [0.0, 0.0]]], ids=["one", "batch"])
def test_progress_is_called_once_per_step_and_can_stop_adams(y0):
    fun = (lambda t, y: np.stack([y[1], -y[0]])) if np.ndim(y0) == 2 else osc
    full = ode.solve(fun, (0.0, 10.0), y0, method="adams", rtol=1e-8)
    seen = []

    def progress(t):
        seen.append(t)
        return t < 3.0

    r = ode.solve(fun, (0.0, 10.0), y0, method="adams", rtol=1e-8, progress=progress)
    assert r.status == 2 and "stopped by the `progress` callback" in r.message
    assert seen == list(r.t[1:])
    assert 3.0 <= r.t[-1] < 10.0
    m = len(r.t)  # the same steps as without the callback
    assert_array_equal(r.t, full.t[:m])
    assert_array_equal(r.y, full.y[:, :m])


def test_keyboard_interrupt_keeps_the_steps_adams_made():
    full = ode.solve(osc, (0.0, 50.0), [1.0, 0.0], method="adams", rtol=1e-8)
    calls = [0]

    def interrupted(t, y):
        calls[0] += 1
        if calls[0] == 300:
            raise KeyboardInterrupt
        return osc(t, y)

    r = ode.solve(interrupted, (0.0, 50.0), [1.0, 0.0], method="adams", rtol=1e-8)
    assert r.status == 2 and "interrupted (KeyboardInterrupt)" in r.message
    m = len(r.t)
    assert 10 < m < len(full.t) and r.y.shape == (2, m)
    assert_array_equal(r.t, full.t[:m])
    assert_array_equal(r.y, full.y[:, :m])
    assert f"at t = {float(r.t[-1])!r}" in r.message
