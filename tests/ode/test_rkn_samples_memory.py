"""rkn64 and rkn1210 with ``t_eval`` keep only the samples (issue 10: memory proportional to
what was asked for). They land their steps on the sample times; they used to record every
step and drop the others at the end, so memory grew with the steps.

Reference: q'' = -q, q = cos t, v = -sin t.
"""

import tracemalloc

import numpy as np
import pytest

from rigidmech import ode


def accel(t, q):
    return -q


def _peak(method, **kw):
    tracemalloc.start()
    try:
        r = ode.solve(accel, (0.0, 20.0), [1.0, 0.0], method=method, max_step=0.02,
                      max_steps=10**6, **kw)
        return r, tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("method", ["rkn64", pytest.param("rkn1210", marks=pytest.mark.slow)])
def test_rkn_t_eval_memory_follows_the_samples(method):
    ode.solve(accel, (0.0, 1.0), [1.0, 0.0], method=method)  # the kernel, generated once
    te = np.linspace(0.0, 20.0, 100)
    r, samples = _peak(method, t_eval=te, rtol=1e-8)
    assert r.status == 0 and r.nsteps >= 1_000  # max_step = 0.02 over a span of 20
    np.testing.assert_array_equal(r.t, te)
    np.testing.assert_allclose(r.y[0], np.cos(te), atol=1e-7)
    np.testing.assert_allclose(r.y[1], -np.sin(te), atol=1e-7)
    # keeping 10^3 steps costs at least 10^3 x (a state of 2 floats as an ndarray, 112
    # bytes, a float, 24 bytes, and two list slots, 16 bytes): > 150 KB (measured: 216 KB,
    # checked below); 100 samples with the stepper's working memory: measured 42 KB
    _, steps = _peak(method, rtol=1e-8)
    assert steps > 150_000 and samples < 80_000, (samples, steps)
