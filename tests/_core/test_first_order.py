"""CompiledLinearSolve.first_order: the single-state path as f(t, y) = (x', x'') for a solve
compiled with the arguments (t, x, x', c...), the c bound once. It runs the same generated
arithmetic as a call (same numbers, bit for bit), hands (A, b) back where a call's unrolled
solve hands over to its checked solve, and exists only where there is an unrolled solve."""

import pickle

import numpy as np
import pytest
import sympy as sp

from rigidmech._core import _saddle
from rigidmech._core.compile import UNROLLED_CHOLESKY_MAX_N, compile_linear_solve


def _oscillators(k):
    """M = m (I + 0.1 * coupling(x)), f = -c x - d x' with M symmetric positive definite."""
    t, m, c, d = sp.symbols("t m c d")
    x = sp.symbols(f"x0:{k}")
    v = sp.symbols(f"v0:{k}")
    M = sp.Matrix(k, k, lambda i, j: m * (2 if i == j else sp.cos(x[i] - x[j]) / (4 * k)))
    f = sp.Matrix([-c * x[i] - d * v[i] * sp.sin(x[i]) for i in range(k)])
    return M, f, [t, list(x), list(v), m, c, d]


def _pendulum_on_a_line():
    """A point (x1, x2) held on the circle x1^2 + x2^2 = 1 (one multiplier), gravity g,
    Baumgarte's terms: the saddle system [[I, A^T], [A, 0]] (x'', lam) = (f, b)."""
    t, g = sp.symbols("t g")
    x1, x2, v1, v2 = sp.symbols("x1 x2 v1 v2")
    A = sp.Matrix([[2 * x1, 2 * x2]])
    b = -2 * (v1**2 + v2**2) - 10 * (2 * x1 * v1 + 2 * x2 * v2) - 25 * (x1**2 + x2**2 - 1)
    K = sp.Matrix([[1, 0, A[0]], [0, 1, A[1]], [A[0], A[1], 0]])
    F = sp.Matrix([0, -g, b])
    return K, F, [t, [x1, x2], [v1, v2], g]


@pytest.mark.parametrize("k", [1, 3, UNROLLED_CHOLESKY_MAX_N])
def test_unrolled_cholesky_first_order_equals_a_call(k):
    M, f, args = _oscillators(k)
    solve = compile_linear_solve(M, f, args, symmetric=True)
    fun = solve.first_order([1.5, 2.0, 0.3])
    rng = np.random.default_rng(k)
    for _ in range(5):
        y = rng.uniform(-2.0, 2.0, 2 * k)
        out = fun(0.7, y)
        assert type(out) is np.ndarray and out.shape == (2 * k,)
        np.testing.assert_array_equal(out, np.concatenate(
            (y[k:], solve(0.7, y[:k], y[k:], 1.5, 2.0, 0.3))))
        # and the numbers of the symbolic equations
        at = dict(zip(args[1] + args[2] + args[3:], [*y, 1.5, 2.0, 0.3], strict=True))
        Mv = np.array(M.subs(at), dtype=float)
        fv = np.array(f.subs(at), dtype=float).ravel()
        np.testing.assert_allclose(out[k:], np.linalg.solve(Mv, fv), rtol=1e-12, atol=1e-12)
        assert not np.shares_memory(out, y)


def test_saddle_first_order_equals_a_call_and_drops_the_multipliers():
    K, F, args = _pendulum_on_a_line()
    solve = compile_linear_solve(K, F, args, saddle=2)
    fun = solve.first_order([9.81])
    rng = np.random.default_rng(3)
    for _ in range(5):
        y = rng.uniform(-2.0, 2.0, 4)
        out = fun(0.0, y)
        assert out.shape == (4,)
        full = solve(0.0, y[:2], y[2:], 9.81)
        np.testing.assert_array_equal(out, np.concatenate((y[2:], full[:2])))
        at = dict(zip(args[1] + args[2] + [args[3]], [*y, 9.81], strict=True))
        x = np.linalg.solve(np.array(K.subs(at), dtype=float),
                            np.array(F.subs(at), dtype=float).ravel())
        np.testing.assert_allclose(out[2:], x[:2], rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("c, fast", [(1.0, False), (1.0 + 2.0**-16, True),
                                     (1.0 - 2.0**-16, False), (2.0, True)])
def test_saddle_first_order_hands_back_where_a_call_leaves_the_unrolled_solve(c, fast):
    """The boundary of SADDLE_PIVOT_FACTOR (tests/_core/test_saddle_solve.py): M = I, rows
    (1, 0) and (100, c) of A, the second pivot of S exactly 1/10001 of its diagonal at c = 1;
    at and below it (A, b) come back, for the caller's checked solve."""
    assert _saddle.SADDLE_PIVOT_FACTOR == 10001.0
    t, cs = sp.symbols("t c")
    x, v = sp.symbols("x0:2"), sp.symbols("v0:2")
    K = sp.ImmutableMatrix([[1, 0, 1, 100], [0, 1, 0, cs], [1, 0, 0, 0], [100, cs, 0, 0]])
    F = sp.Matrix([1, 2, 3, 4])
    solve = compile_linear_solve(K, F, [t, list(x), list(v), cs], saddle=2)
    y = np.array([0.1, 0.2, 0.3, 0.4])
    out = solve.first_order([c])(0.0, y)
    if fast:
        np.testing.assert_array_equal(out, np.concatenate((y[2:], solve(0.0, y[:2], y[2:],
                                                                         c)[:2])))
    else:
        A, b = out
        np.testing.assert_array_equal(A, np.array(K.subs(cs, c), dtype=float))
        np.testing.assert_array_equal(b, [1.0, 2.0, 3.0, 4.0])


def test_no_first_order_without_an_unrolled_solve_or_another_layout():
    M, f, args = _oscillators(UNROLLED_CHOLESKY_MAX_N + 1)  # LAPACK's solve: nothing to gain
    assert compile_linear_solve(M, f, args, symmetric=True).first_order([1.0, 1.0, 1.0]) is None
    M, f, args = _oscillators(2)
    assert compile_linear_solve(M, f, args).first_order([1.0, 1.0, 1.0]) is None  # general
    swapped = [args[1], args[0], args[2], *args[3:]]  # x first: not (t, x, x', ...)
    assert compile_linear_solve(M, f, swapped, symmetric=True).first_order([1.0] * 3) is None


def test_bad_values_are_named():
    M, f, args = _oscillators(2)
    solve = compile_linear_solve(M, f, args, symmetric=True)
    with pytest.raises(ValueError, match=r"`values` must hold 3 numbers, one for each of "
                                         r"\['m', 'c', 'd'\]; got 2"):
        solve.first_order([1.0, 2.0])
    with pytest.raises(TypeError, match="`values` must be real numbers"):
        solve.first_order([1.0, "two", 3.0])


def test_first_order_survives_pickle():
    K, F, args = _pendulum_on_a_line()
    solve = compile_linear_solve(K, F, args, saddle=2)
    y = np.array([0.6, -0.8, 0.5, 0.4])
    before = solve.first_order([9.81])(0.0, y)  # executed once, then pickled
    again = pickle.loads(pickle.dumps(solve))
    np.testing.assert_array_equal(again.first_order([9.81])(0.0, y), before)
