"""Issue #10, the last gaps of the ODE driver: radau's samples as accurate as its steps and
recorded step by step; adams with ``t_eval`` keeping only the samples."""

import tracemalloc

import numpy as np
import pytest

from rigidmech import ode


def oscillator(t, y):
    """y'' = -y as a first-order system; exact solution (cos t, -sin t) from (1, 0)."""
    return np.array([y[1], -y[0]])


def _exact(t):
    return np.array([np.cos(t), -np.sin(t)])


@pytest.mark.parametrize("rtol", [1e-6, 1e-10])
def test_radau_samples_as_accurate_as_its_steps(rtol):
    # error at its own steps (no t_eval) against the closed form
    t_span, y0, atol = (0.0, 20.0), [1.0, 0.0], rtol * 1e-3
    steps = ode.solve(oscillator, t_span, y0, method="radau", rtol=rtol, atol=atol)
    err_steps = np.max(np.abs(steps.y - _exact(steps.t)))
    te = np.linspace(0.0, 20.0, 137)[1:]  # not the steps' times
    sampled = ode.solve(oscillator, t_span, y0, method="radau", rtol=rtol, atol=atol,
                        t_eval=te)
    assert sampled.status == 0
    np.testing.assert_array_equal(sampled.t, te)
    err_samples = np.max(np.abs(sampled.y - _exact(te)))
    # before: the samples came from the order-3 collocation polynomial, up to 40x worse
    assert err_samples <= 2.0 * err_steps, (err_samples, err_steps)


def test_radau_nfev_unchanged_without_t_eval():
    # without t_eval the steps do not land anywhere: same steps, same evaluations as with
    # dense output (which only adds the polynomial's coefficients, no evaluation of fun)
    a = ode.solve(oscillator, (0.0, 20.0), [1.0, 0.0], method="radau", rtol=1e-8, atol=1e-11)
    b = ode.solve(oscillator, (0.0, 20.0), [1.0, 0.0], method="radau", rtol=1e-8, atol=1e-11,
                  dense_output=True)
    assert (a.nfev, a.nsteps, a.stats) == (b.nfev, b.nsteps, b.stats)
    np.testing.assert_array_equal(a.t, b.t)


@pytest.mark.slow  # minutes under tracemalloc: run by CI's slow stage
def test_radau_memory_bounded_by_samples():
    # 3000 time units at rtol 1e-10: about 10^4 steps; 100 samples asked for.
    te = np.linspace(0.0, 3.0e3, 100)
    run = dict(method="radau", rtol=1e-10, atol=1e-12, t_eval=te, max_steps=10**7)
    ode.solve(oscillator, (0.0, 50.0), [1.0, 0.0], **run | {"t_eval": None})  # warm caches
    tracemalloc.start()
    r = ode.solve(oscillator, (0.0, 3.0e3), [1.0, 0.0], **run)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert r.status == 0 and r.nsteps > 5_000
    # Bound: 100 samples of 2 floats (a few KB with list overhead) plus the stepper's fixed
    # working arrays (Jacobian, inverses, 3 x N stages: under 2 KB for N = 2) plus numpy's
    # temporaries; 64 KB is far below the >= 0.5 MB that keeping every step would need
    # (more than 5000 steps x (time + state + 3 x 2 dense coefficients) x 8 bytes, plus
    # the per-step list entries).
    assert peak < 64 * 1024, peak


def _adams_problems():
    from rigidmech.testing.problems import kepler
    k = kepler(0.5, orbits=3.0)
    return [("oscillator", oscillator, (0.0, 20.0), np.array([1.0, 0.0])),
            ("kepler", k.fun, k.t_span, np.asarray(k.y0, dtype=float))]


@pytest.mark.parametrize("rtol", [1e-5, 1e-8, 1e-11])
@pytest.mark.parametrize("which", [0, 1], ids=["oscillator", "kepler"])
def test_adams_t_eval_samples_step_by_step_same_steps(which, rtol):
    # with t_eval adams made its steps with dense output and kept it all; now it keeps the
    # samples as they pass: the steps (hence nfev) are those of the dense run, and the
    # samples are its dense output at t_eval
    _, fun, t_span, y0 = _adams_problems()[which]
    te = np.linspace(t_span[0], t_span[1], 57)
    dense = ode.solve(fun, t_span, y0, method="adams", rtol=rtol, atol=rtol * 1e-3,
                      dense_output=True)
    r = ode.solve(fun, t_span, y0, method="adams", rtol=rtol, atol=rtol * 1e-3, t_eval=te)
    assert r.status == 0 and r.sol is None
    assert (r.nfev, r.nsteps, r.nrejected, r.stats) == (dense.nfev, dense.nsteps,
                                                        dense.nrejected, dense.stats)
    np.testing.assert_array_equal(r.t, te)
    np.testing.assert_allclose(r.y, dense.sol(te), rtol=0, atol=1e-14 * np.abs(y0).max())


@pytest.mark.slow  # minutes under tracemalloc: run by CI's slow stage
def test_adams_t_eval_memory_bounded_by_samples():
    te = np.linspace(0.0, 2.0e3, 100)
    run = dict(method="adams", rtol=1e-10, atol=1e-12, t_eval=te)
    ode.solve(oscillator, (0.0, 50.0), [1.0, 0.0], **run | {"t_eval": None})  # warm caches
    tracemalloc.start()
    r = ode.solve(oscillator, (0.0, 2.0e3), [1.0, 0.0], **run)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert r.status == 0 and r.nsteps > 5_000
    # Bound: the samples wait in a queue with their step's start state and dense coefficients
    # (at most 100 entries, each under 1 KB: arrays of at most 14 x 2 floats), plus the
    # difference table and the last 2 x 49 step times and derivatives (a few KB) and numpy
    # temporaries: 256 KB. Measured: about 135 KB for the 18822 steps of this run, against
    # 15.4 MB for the same run with dense_output=True (every step's polynomial kept).
    assert peak < 256 * 1024, peak
