"""The stepper protocol and the one loop (rigidmech.ode._loop): a method is only coefficients
and capabilities (bs32), the loop owns progress and interruption (issues 15 and 10)."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from rigidmech import ode
from rigidmech._core.errors import ArgumentError
from rigidmech.ode import adaptive
from rigidmech.ode._loop import Controller


def osc(t, y):
    return np.array([y[1], -y[0]])


def test_bs32_observed_order_is_three():
    # every step accepted at the same size h (tolerances far too loose to reject, max_step = h):
    # the global error of a 3rd-order method drops 8x when h is halved (closed form cos t)
    errs = []
    for h in (0.1, 0.05, 0.025):
        r = ode.solve(osc, (0.0, 4.0), [1.0, 0.0], method="bs32", rtol=1.0, atol=1.0,
                      first_step=h, max_step=h)
        assert np.allclose(np.diff(r.t)[:-1], h)
        errs.append(abs(r.y[0, -1] - math.cos(4.0)))
    orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert_allclose(orders, 3.0, atol=0.15)


def test_bs32_takes_the_steps_of_scipy_rk23():
    # same pair, norm, starting step and controller as scipy's RK23: the same steps
    kw = dict(rtol=1e-6, atol=1e-9)
    ref = solve_ivp(osc, (0.0, 10.0), [1.0, 0.0], method="RK23", **kw)
    r = ode.solve(osc, (0.0, 10.0), [1.0, 0.0], method="bs32", **kw)
    assert r.nsteps == len(ref.t) - 1
    assert_allclose(r.t, ref.t, rtol=1e-7)
    assert_allclose(r.y, ref.y, rtol=1e-7, atol=1e-10)


@pytest.mark.parametrize("numpy_path", [False, True])
def test_bs32_dense_output_and_batch(numpy_path, monkeypatch):
    if numpy_path:
        monkeypatch.setattr(adaptive, "FLOAT_PATH_MAX_N", 0)
    r = ode.solve(osc, (0.0, 5.0), [1.0, 0.0], method="bs32", rtol=1e-9, atol=1e-12,
                  dense_output=True)
    t = np.linspace(0.0, 5.0, 41)
    assert_allclose(r.sol(t)[0], np.cos(t), atol=1e-6)
    y0 = np.array([[1.0, 2.0], [0.0, 0.0]])
    b = ode.solve(lambda t, y: np.stack([y[1], -y[0]]), (0.0, 5.0), y0, method="bs32",
                  rtol=1e-9, atol=1e-12)
    assert_allclose(b.y[0, -1], y0[0] * math.cos(5.0), rtol=1e-6)


def test_progress_callback_is_called_and_can_stop_the_run():
    seen = []

    def progress(t):
        seen.append(t)
        return t < 3.0  # False once past t = 3: stop

    r = ode.solve(osc, (0.0, 10.0), [1.0, 0.0], method="dop853", rtol=1e-8, progress=progress)
    assert r.status == 2 and not r.success
    assert "stopped by the `progress` callback" in r.message
    assert seen == list(r.t[1:])  # once per accepted step, with its time
    assert 3.0 <= r.t[-1] < 10.0
    assert_allclose(r.y[0], np.cos(r.t), atol=1e-7)  # everything computed so far is kept


def test_keyboard_interrupt_returns_the_partial_result():
    calls = [0]

    def interrupted(t, y):
        calls[0] += 1
        if calls[0] == 200:
            raise KeyboardInterrupt
        return np.array([y[1], -y[0]])

    r = ode.solve(interrupted, (0.0, 100.0), [1.0, 0.0], method="dopri5", rtol=1e-8)
    assert r.status == 2
    assert "interrupted (KeyboardInterrupt)" in r.message
    assert len(r.t) > 10
    assert_allclose(r.y[0], np.cos(r.t), atol=1e-6)


def test_progress_must_be_callable():
    with pytest.raises(ArgumentError, match=r"`progress` must be a callable progress\(t\)"):
        ode.solve(osc, (0.0, 1.0), [1.0, 0.0], method="dopri5", progress=3)


def test_progress_is_refused_by_methods_that_do_not_take_it():
    # every built-in method takes it now (adams and the fixed-step ones too): a user's
    # registered method without the option refuses it
    from rigidmech.ode import _registry

    def euler(fun, t_span, y0, *, step, max_steps=None):
        return ode.solve(fun, t_span, y0, method="euler", step=step)

    _registry.register("plain_euler_test", euler, kind="fixed")
    try:
        with pytest.raises(ArgumentError, match=r"`progress` is not an option of method "
                                                r"'plain_euler_test'"):
            ode.solve(osc, (0.0, 1.0), [1.0, 0.0], method="plain_euler_test", step=0.1,
                      progress=print)
    finally:
        _registry.unregister("plain_euler_test")


def test_controller_never_grows_after_a_rejection_and_shrinks_on_nan():
    c = Controller(error_order=4, pi=False)
    assert c.next(1e-6, 1.0, True) == (1.0, True)
    assert c.next(float("nan"), 1.0, False) == (0.2, False)
    assert c.next(0.0, 1.0, False) == (10.0, True)


@pytest.mark.parametrize("method", ["dopri5", "dop853", "bs32"])
def test_t_eval_samples_equal_the_dense_output_at_those_times(method):
    # the samples are kept step by step (no dense output stored) but are the same numbers
    t_eval = np.linspace(0.0, 10.0, 23)
    dense = ode.solve(osc, (0.0, 10.0), [1.0, 0.0], method=method, rtol=1e-8,
                      dense_output=True)
    r = ode.solve(osc, (0.0, 10.0), [1.0, 0.0], method=method, rtol=1e-8, t_eval=t_eval)
    assert r.sol is None and r.nsteps == dense.nsteps
    np.testing.assert_array_equal(r.t, t_eval)
    np.testing.assert_array_equal(r.y, dense.sol(t_eval))


@pytest.mark.slow  # 20,000 steps under tracemalloc: run by CI's slow stage, like test_issue10_gaps'
def test_t_eval_memory_is_proportional_to_the_samples():
    # 10,000 steps (max_step), 100 samples: the peak stays far below what keeping the steps
    # costs (measured: 2.2 MB for the steps, under 0.1 MB for the samples)
    import tracemalloc

    def peak(**kw):
        tracemalloc.start()
        ode.solve(osc, (0.0, 100.0), [1.0, 0.0], method="dopri5", max_step=0.01, **kw)
        size = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        return size

    ode.solve(osc, (0.0, 1.0), [1.0, 0.0], method="dopri5")  # the kernel, generated once
    samples = peak(t_eval=np.linspace(0.0, 100.0, 100))
    steps = peak()
    assert samples < 200_000 and steps > 1_500_000


@pytest.mark.parametrize("method", ["gbs", "radau", "bs32"])
def test_every_method_on_the_loop_takes_progress(method):
    r = ode.solve(osc, (0.0, 10.0), [1.0, 0.0], method=method, rtol=1e-6,
                  progress=lambda t: t < 2.0)
    assert r.status == 2 and 2.0 <= r.t[-1] < 10.0


@pytest.mark.parametrize("method", ["dopri5", "dop853", "bs32", "gbs"])
def test_a_non_finite_right_hand_side_is_named_not_called_underflow_alone(method):
    # y' = 1 while y < 1.5, nan beyond: the run stops near t = 1.5 and says why
    def f(t, y):
        return np.array([1.0 if y[0] < 1.5 else np.nan])

    r = ode.solve(f, (0.0, 3.0), [0.0], method=method, rtol=1e-6)
    assert r.status == -1
    assert "The right-hand side returned non-finite values (nan or inf)" in r.message
    assert r.t[-1] < 1.5  # the steps kept are those before the first nan
