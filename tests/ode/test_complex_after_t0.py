"""A right-hand side that turns complex after t0 (issue 10): refused at t0 already, it was
truncated to its real part after t0 (one ComplexWarning per step, a wrong motion called a
success) or raised a TypeError from inside the step (the plain-float path), losing the run.
The one loop now ends the run with status -1, a message naming the time and the component,
and keeps the motion up to the last accepted step, as any failure.

Reference: y = (cos t, -sin t) solves y' = (y1, -y0) exactly; the complex part is switched
on at t = 0.5 in the second component.
"""

import warnings

import numpy as np
import pytest

from rigidmech import ode


def osc_turning_complex(t, y):
    out = np.array([y[1], -y[0]])
    if t > 0.5:
        out = out + np.array([0.0, 1e-3j])
    return out


def accel_turning_complex(t, q):
    a = -q
    if t > 0.5:
        a = a + 1e-3j
    return a


@pytest.mark.parametrize("method", ["dop853", "dopri5", "bs32", "gbs", "radau"])
def test_complex_after_t0_fails_with_time_and_component(method):
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # not one ComplexWarning either
        r = ode.solve(osc_turning_complex, (0.0, 2.0), [1.0, 0.0], method=method,
                      rtol=1e-10, atol=1e-12)
    assert r.status == -1
    assert "complex" in r.message and "component 1" in r.message
    culprit = r.stats["culprit"]
    assert culprit["component"] == 1 and culprit["complex"]
    assert 0.5 < culprit["t"] <= 0.5 + 0.5  # within the step that crossed 0.5
    assert 0.0 < r.t_stop <= 0.5 + 1e-12 and r.t[-1] == r.t_stop
    np.testing.assert_allclose(r.y[0], np.cos(r.t), atol=1e-8)  # the motion is kept
    np.testing.assert_allclose(r.y[1], -np.sin(r.t), atol=1e-8)


def test_complex_acceleration_of_a_second_order_pair_after_t0():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = ode.solve(accel_turning_complex, (0.0, 2.0), [1.0, 0.0], method="rkn64",
                      rtol=1e-10, atol=1e-12)
    assert r.status == -1 and "complex" in r.message
    assert r.stats["culprit"]["component"] == 1  # y' = (v, a): the acceleration
    assert 0.0 < r.t_stop <= 0.5 + 1e-12
    np.testing.assert_allclose(r.y[0], np.cos(r.t), atol=1e-8)


def test_complex_after_t0_with_t_eval_keeps_the_samples_before():
    te = np.linspace(0.0, 2.0, 41)
    r = ode.solve(osc_turning_complex, (0.0, 2.0), [1.0, 0.0], method="dop853", t_eval=te,
                  rtol=1e-10, atol=1e-12)
    assert r.status == -1 and "complex" in r.message
    assert 0.0 < r.t_stop <= 0.5 + 1e-12
    np.testing.assert_array_equal(r.t, te[te <= r.t_stop])  # every sample before it
    np.testing.assert_allclose(r.y[0], np.cos(r.t), atol=1e-8)
