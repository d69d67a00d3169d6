"""The fixed-step methods run like the loop's methods (issues 15 and 10): `progress` through
`solve`, Ctrl-C kept as status 2 with the partial result, a step larger than the span
refused, finiteness checked at every step."""

import math

import numpy as np
import pytest
from numpy.testing import assert_array_equal

from rigidmech import ode
from rigidmech._core.errors import ArgumentError
from rigidmech.ode import tableaux


def osc(t, y):
    return np.array([y[1], -y[0]])


def acc(t, q):
    return -q


FIRST = ["euler", "heun", "rk4", "rk38", "ab4", "abm4", tableaux.RK4]
SECOND = ["verlet", "yoshida4", "yoshida6"]
ALL = FIRST + SECOND


def _fun(method):
    return acc if method in SECOND else osc


def _id(m):
    return m if isinstance(m, str) else m.name + "-tableau"


@pytest.mark.parametrize("method", ALL, ids=_id)
def test_progress_is_called_once_per_step_and_can_stop_the_run(method):
    full = ode.solve(_fun(method), (0.0, 5.0), [1.0, 0.0], method=method, step=0.01)
    seen = []

    def progress(t):
        seen.append(t)
        return t < 2.0

    r = ode.solve(_fun(method), (0.0, 5.0), [1.0, 0.0], method=method, step=0.01,
                  progress=progress)
    assert r.status == 2 and not r.success
    assert "stopped by the `progress` callback" in r.message
    assert seen == list(r.t[1:])  # once per step, with its time
    assert 2.0 <= r.t[-1] < 2.02
    # everything computed so far is kept: the same numbers as the full run's first steps
    m = len(r.t)
    assert_array_equal(r.t, full.t[:m])
    assert_array_equal(r.y, full.y[:, :m])


@pytest.mark.parametrize("method", ALL, ids=_id)
def test_keyboard_interrupt_keeps_the_steps_made(method):
    base = _fun(method)
    full = ode.solve(base, (0.0, 5.0), [1.0, 0.0], method=method, step=0.01)
    calls = [0]

    def interrupted(t, y):
        calls[0] += 1
        if calls[0] == 300:
            raise KeyboardInterrupt
        return base(t, y)

    r = ode.solve(interrupted, (0.0, 5.0), [1.0, 0.0], method=method, step=0.01)
    assert r.status == 2
    assert "interrupted (KeyboardInterrupt)" in r.message
    m = len(r.t)
    assert 10 < m < len(full.t)
    assert_array_equal(r.t, full.t[:m])
    assert_array_equal(r.y, full.y[:, :m])
    assert f"at t = {float(r.t[-1])!r}" in r.message


def test_progress_must_be_callable_for_a_fixed_step_method_too():
    with pytest.raises(ArgumentError, match=r"`progress` must be a callable progress\(t\)"):
        ode.solve(osc, (0.0, 1.0), [1.0, 0.0], method="rk4", step=0.1, progress=3)


@pytest.mark.parametrize("method", ["euler", "rk4", "ab2", "verlet"])
def test_a_step_larger_than_the_span_is_refused(method):
    # it used to be shrunk silently to the span: no step of the size asked for was made
    with pytest.raises(ArgumentError, match=r"`step` = 2.0 exceeds the time span "
                                            r"\|t1 - t0\| = 1.0"):
        ode.solve(_fun(method), (0.0, 1.0), [1.0, 0.0], method=method, step=2.0)


def test_a_step_equal_to_the_span_is_accepted():
    r = ode.solve(osc, (0.0, 1.0), [1.0, 0.0], method="euler", step=1.0)
    assert r.success and r.nsteps == 1


def _first_overflow(h, y0):
    """Euler on y' = y**2 in plain floats: the first step whose state is not finite."""
    y, k = y0, 0
    while math.isfinite(y):
        try:
            y = y + h * y * y
        except OverflowError:
            y = math.inf
        k += 1
    return k


@pytest.mark.parametrize("method,fun,y0", [
    ("ab1", lambda t, y: y * y, [1.0]),          # AB1 is Euler
    ("verlet", lambda t, q: q ** 3, [3.0, 0.0]),
])
def test_a_blow_up_in_few_steps_is_reported_where_it_happens(method, fun, y0):
    # fewer steps than the old check interval (32): the run used to be called a success
    r = ode.solve(fun, (0.0, 20.0), y0, method=method, step=1.0)
    assert r.status == -1 and not r.success
    assert "The state became non-finite at t = " in r.message
    assert np.isfinite(r.y).all()  # the result ends at the last finite state
    if method == "ab1":  # the failure is reported at the first bad step
        k = _first_overflow(1.0, 1.0)
        assert r.nsteps == k - 1 and r.t[-1] == k - 1.0
        assert f"at t = {float(k)!r}" in r.message


@pytest.mark.parametrize("method", ode.methods())
def test_every_method_takes_progress_through_solve(method):
    second = method in ode.methods("second_order") + ode.methods("adaptive_second_order")
    fixed = method in ode.methods("fixed") + ode.methods("second_order")
    kw = {"step": 0.01} if fixed else {"rtol": 1e-6}
    seen = []

    def progress(t):
        seen.append(t)
        return t < 2.0

    r = ode.solve(acc if second else osc, (0.0, 10.0), [1.0, 0.0], method=method,
                  progress=progress, **kw)
    assert r.status == 2 and "stopped by the `progress` callback" in r.message
    assert 2.0 <= r.t_stop < 10.0 and seen[-1] == r.t_stop
    assert seen == sorted(seen) and len(seen) == r.nsteps
