"""The compiled first-order right-hand side on one state (the integrators' calls) gives the
numbers of the general (batched) path, whatever the form of its arguments."""

import numpy as np
import pytest

from rigidmech import models


@pytest.fixture(scope="module")
def fun():
    eqs = models.n_link_pendulum(3).system.equations_of_motion()
    return eqs.rhs(g=9.81, m1=1.0, m2=2.0, m3=0.5, l1=1.0, l2=0.7, l3=1.3)


def test_one_float64_state_equals_the_batch_column(fun):
    rng = np.random.default_rng(5)
    Y = rng.uniform(-2.0, 2.0, (6, 4))
    batch = fun(0.3, Y)
    for j in range(4):
        one = fun(0.3, Y[:, j].copy())
        assert one.shape == (6,) and one.dtype == np.float64
        np.testing.assert_allclose(one, batch[:, j], rtol=1e-13, atol=1e-13)
        np.testing.assert_array_equal(one[:3], Y[3:, j])
    # other forms of the same state take the general path: same numbers
    y = Y[:, 0]
    np.testing.assert_allclose(fun(np.float64(0.3), y), fun(0.3, y), rtol=1e-13)
    np.testing.assert_allclose(fun(0.3, y[:, None])[:, 0], fun(0.3, y), rtol=1e-13)
    np.testing.assert_allclose(fun(0, list(y)), fun(0.0, y), rtol=1e-13)


def test_a_float64_batch_equals_the_general_path(fun):
    # a batch of float64 (the integrators' calls) against the same batch as nested lists (the
    # general path, with its argument checks), one time and a time per column
    rng = np.random.default_rng(6)
    Y = rng.uniform(-2.0, 2.0, (6, 5))
    np.testing.assert_allclose(fun(0.3, Y), fun(0.3, Y.tolist()), rtol=1e-13, atol=1e-13)
    t = np.linspace(0.0, 1.0, 5)
    np.testing.assert_allclose(fun(t, Y), fun(t.tolist(), Y.tolist()), rtol=1e-13, atol=1e-13)
    assert fun(0.3, Y).shape == (6, 5)


def test_a_fresh_array_each_call(fun):
    y = np.linspace(0.1, 0.6, 6)
    a, b = fun(0.0, y), fun(0.0, y)
    assert a is not b and a is not y


def test_an_error_with_a_time_per_column_is_kept_with_the_earliest(fun):
    # in a simulation the rhs keeps its first error and returns nan; with one time per column
    # (per-trajectory steps) the earliest time is kept (t of 3 columns for 2 states: refused)
    fun.trouble = []
    try:
        out = fun(np.array([0.5, 0.2, 0.9]), np.zeros((6, 2)))
        assert out.shape == (6, 2) and np.isnan(out).all()
        assert fun.trouble[0][1] == 0.2
    finally:
        fun.trouble = None


def test_a_float64_batch_equals_the_symbolic_accelerations(fun):
    # the integrators' batch path (the generated batched code writing the accelerations into
    # the rows of the output) against M^-1 f evaluated by sympy at 30 digits, random states
    from rigidmech.dynamics import _compiled

    eqs = models.n_link_pendulum(3).system.equations_of_motion()
    q_s, u_s, _, _, M, f = _compiled.symbolic(eqs)
    values = dict(g=9.81, m1=1.0, m2=2.0, m3=0.5, l1=1.0, l2=0.7, l3=1.3)
    params = {p: values[p.name] for p in eqs._params}
    rng = np.random.default_rng(7)
    Y = rng.uniform(-2.0, 2.0, (6, 7))
    out = fun(0.3, Y)
    assert out.shape == (6, 7) and not np.shares_memory(out, Y)
    np.testing.assert_array_equal(out[:3], Y[3:])
    for j in range(7):
        point = {**params, **dict(zip(q_s + u_s, Y[:, j].tolist(), strict=True))}
        acc = M.subs(point).evalf(30).LUsolve(f.subs(point).evalf(30))
        expected = np.array([float(v) for v in acc])
        np.testing.assert_allclose(out[3:, j], expected, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(fun(0.3, Y[:, j].copy())[3:], expected, rtol=1e-12,
                                   atol=1e-12)
    again = fun(0.3, Y)
    assert again is not out and not np.shares_memory(again, out)
