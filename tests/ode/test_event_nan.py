"""An event function returning NaN is reported (issue 10): its zeros cannot be located, so the
run is not called a success, and the message names the event and the time."""

import math
import re
import warnings

import numpy as np
import pytest

from rigidmech import ode


def osc(t, y):
    return np.array([y[1], -y[0]])


@pytest.mark.parametrize("method,kw", [("dop853", {}), ("dopri5", {}), ("radau", {}),
                                       ("adams", {}), ("gbs", {}), ("rk4", {"step": 0.01})])
def test_an_event_returning_nan_is_a_failure_naming_it(method, kw):
    def fine(t, y):
        return y[0]  # zeros at pi/2, 3 pi/2, ...

    def broken(t, y):
        return math.nan if t > 2.0 else y[0] - 2.0

    r = ode.solve(osc, (0.0, 3.0), [1.0, 0.0], method=method, events=[fine, broken], **kw)
    assert r.status == -1 and not r.success
    found = re.search(r"The event function events\[1\] returned nan at t = (\S+?)[:;,]",
                      r.message)
    assert found and 2.0 < float(found.group(1)) <= 3.0
    assert "events may be missing" in r.message
    assert r.t[-1] == 3.0  # the motion itself is complete
    np.testing.assert_allclose(r.t_events[0], [math.pi / 2], rtol=1e-5)


def test_an_event_returning_nan_at_t0_is_reported_too():
    r = ode.solve(osc, (0.0, 1.0), [1.0, 0.0], events=lambda t, y: math.nan)
    assert r.status == -1 and "events[0] returned nan at t = 0.0" in r.message


@pytest.mark.parametrize("method,kw", [("dop853", {}), ("radau", {}), ("rk4", {"step": 0.1}),
                                       ("verlet", {"step": 0.1})])
def test_a_complex_right_hand_side_is_refused_not_truncated(method, kw):
    from rigidmech._core.errors import ArgumentTypeError

    def fun(t, y):  # sqrt of a negative number: complex, as numpy's emath gives it
        return np.emath.sqrt(-np.abs(y) - 1.0)  # sqrt(-2) = 1.41421356... j at y0[0] = 1

    with pytest.raises(ArgumentTypeError, match=r"`fun\(t0, y0\)` returned complex values "
                                                 r"\(component 0: 1\.41421356\d*j\)"):
        ode.solve(fun, (0.0, 1.0), [1.0, 0.0], method=method, **kw)


@pytest.mark.parametrize("method", ["dopri5", "dop853", "bs32", "gbs"])
def test_a_non_finite_right_hand_side_names_its_component(method):
    # y0' = 1; y1' = 1 while y0 < 1.5, nan beyond: component 1 is the culprit (radau's
    # Newton iterations spread a nan to every component: not tested here)
    def f(t, y):
        return np.array([1.0, 1.0 if y[0] < 1.5 else np.nan])

    r = ode.solve(f, (0.0, 3.0), [0.0, 0.0], method=method, rtol=1e-6)
    assert r.status == -1
    found = re.search(r"the derivative f\(t, y\) was nan in component 1 at t = (\S+?)\.( |$)",
                      r.message)
    assert found, r.message
    assert r.t_stop < float(found.group(1)) <= 3.0 and float(found.group(1)) >= 1.5 - 1e-8


def test_adams_names_a_non_finite_right_hand_side_not_underflow_alone():
    """adams has its own outer loop: a nan of the right-hand side must not be reported as a
    bare step size underflow either; the component and t are named (stats["culprit"])."""

    def f(t, y):
        return np.array([1.0, 1.0 if y[0] < 1.5 else np.nan])

    r = ode.solve(f, (0.0, 3.0), [0.0, 0.0], method="adams", rtol=1e-6)
    assert r.status == -1
    assert "The right-hand side returned non-finite values (nan or inf)" in r.message
    found = re.search(r"the derivative f\(t, y\) was nan in component 1 at t = (\S+?)\.( |$)",
                      r.message)
    assert found, r.message
    assert r.stats["culprit"]["component"] == 1 and not r.stats["culprit"]["complex"]
    assert r.t_stop < float(found.group(1)) <= 3.0 and float(found.group(1)) >= 1.5 - 1e-8


def test_adams_names_a_complex_right_hand_side_after_t0():
    def f(t, y):
        out = np.array([y[1], -y[0]])
        return out + np.array([0.0, 1e-3j]) if t > 0.5 else out

    with warnings.catch_warnings():
        warnings.simplefilter("error")  # not one ComplexWarning either
        r = ode.solve(f, (0.0, 2.0), [1.0, 0.0], method="adams", rtol=1e-10, atol=1e-12)
    assert r.status == -1 and "complex" in r.message and "component 1" in r.message
    assert r.stats["culprit"]["complex"] and 0.0 < r.t_stop <= 0.5 + 1e-12
    np.testing.assert_allclose(r.y[0], np.cos(r.t), atol=1e-8)  # the motion is kept


@pytest.mark.parametrize("method", ["euler", "rk4", "ab4", "abm4"])
def test_a_fixed_step_run_names_the_non_finite_component(method):
    """A fixed step that meets a nan of the right-hand side says which component and when,
    not only that the state became non-finite."""

    def f(t, y):
        return np.array([1.0, 1.0 if y[0] < 1.5 else np.nan])

    r = ode.solve(f, (0.0, 3.0), [0.0, 0.0], method=method, step=0.01)
    assert r.status == -1 and "The state became non-finite" in r.message
    found = re.search(r"the derivative f\(t, y\) was nan in component 1 at t = (\S+?)\.( |$)",
                      r.message)
    assert found, r.message
    assert r.stats["culprit"]["component"] == 1
    assert 1.5 - 1e-9 <= float(found.group(1)) <= 1.5 + 0.02 + 1e-9
