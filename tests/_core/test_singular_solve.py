"""A mass matrix singular to working precision raises SingularMassMatrixError on every path of
the compiled linear solve (issue 9: the unrolled Cholesky tested only ``pivot > 0``, so
M = [[c, c], [c, c]] with c = 0.3 returned q'' = +-1.8e16).

Expected values: the matrices below are exactly singular in real arithmetic (rank one), so any
finite answer is wrong; the valid ones have closed-form solutions.
"""

import numpy as np
import pytest
import sympy
from numpy.testing import assert_allclose

from rigidmech._core.compile import compile_linear_solve
from rigidmech._core.errors import SingularMassMatrixError

c, y, d = sympy.symbols("c y d")
a, b = sympy.symbols("a b")

RANK_ONE_2 = sympy.Matrix([[c, c], [c, c]])


@pytest.mark.parametrize("value", [0.3, 0.7, 1.0, 0.1, 1e-3, 123.4])
@pytest.mark.parametrize("symmetric", [True, False])
def test_rank_one_2x2_single_state(value, symmetric):
    solve = compile_linear_solve(RANK_ONE_2, [y, 1], [c, y], symmetric=symmetric)
    with pytest.raises(SingularMassMatrixError, match=rf"is singular at c={value}, y=2\.0;"):
        solve(value, 2.0)


@pytest.mark.parametrize("symmetric", [True, False])
def test_rank_one_2x2_batch_names_the_member(symmetric):
    solve = compile_linear_solve(RANK_ONE_2 + sympy.diag(d, d), [y, 1], [c, y, d],
                                 symmetric=symmetric)
    cs = np.array([0.3, 0.3, 0.3, 0.3])
    ds = np.array([1.0, 0.5, 0.0, 2.0])  # member 2 is [[0.3, 0.3], [0.3, 0.3]]
    with pytest.raises(SingularMassMatrixError,
                       match=r"is singular at batch index 2, where c=0\.3, y=2\.0, d=0\.0"):
        solve(cs, 2.0, ds)


@pytest.mark.parametrize("value", [0.3, 0.7, 1.0])
def test_rank_one_8x8_lapack_and_batch(value):
    # n = 8 > UNROLLED_CHOLESKY_MAX_N: the single state goes through LAPACK, the batch through
    # the batched unrolled Cholesky and then numpy; c ones(8, 8) + d I is singular for d = 0
    solve = compile_linear_solve(c * sympy.ones(8, 8) + d * sympy.eye(8), [y] + [1] * 7,
                                 [c, y, d], symmetric=True)
    with pytest.raises(SingularMassMatrixError,
                       match=rf"is singular at c={value}, y=2\.0, d=0\.0;"):
        solve(value, 2.0, 0.0)
    with pytest.raises(SingularMassMatrixError, match=r"is singular at batch index 1, where"):
        solve(value, np.array([2.0, 3.0]), np.array([1.0, 0.0]))


@pytest.mark.parametrize("values", [(0.1, 0.3), (0.3, 0.9), (0.7, 0.1), (0.2, 0.6)])
@pytest.mark.parametrize("factor", [3, sympy.Rational(1, 3), 7])
def test_general_matrix_with_proportional_rows(values, factor):
    solve = compile_linear_solve(sympy.Matrix([[a, b], [factor * a, factor * b]]), [1, 2],
                                 [a, b])
    with pytest.raises(SingularMassMatrixError, match=r"is singular at a=.*, b=.*;"):
        solve(*values)
    with pytest.raises(SingularMassMatrixError, match=r"is singular at batch index 0"):
        solve(np.array([values[0]] * 2), np.array([values[1]] * 2))


@pytest.mark.parametrize("symmetric", [True, False])
def test_nearly_singular_but_valid_still_solves(symmetric):
    # [[1, 1], [1, 1 + d]]: condition number ~ 4 / d = 4e8; solution of x1 + x2 = y,
    # x1 + (1 + d) x2 = 1 is x2 = (1 - y) / d, x1 = y - x2. d is taken as the float that
    # 1 + 1e-8 actually stores, so the closed form refers to the matrix really solved; the
    # solve loses about log10(cond) digits: rtol 1e-6.
    d_stored = (1.0 + 1e-8) - 1.0
    solve = compile_linear_solve(sympy.Matrix([[1, 1], [1, 1 + d]]), [y, 1], [y, d],
                                 symmetric=symmetric)
    x2 = (1 - 2.0) / d_stored
    expected = [2.0 - x2, x2]
    assert_allclose(solve(2.0, d_stored), expected, rtol=1e-6)
    batch = solve(np.array([2.0, 2.0]), np.array([d_stored, 1.0]))
    assert_allclose(batch[:, 0], expected, rtol=1e-6)
    assert_allclose(batch[:, 1], [3.0, -1.0], rtol=1e-12)  # d = 1: x2 = -1, x1 = 3


@pytest.mark.parametrize("n", [2, 8])
def test_badly_scaled_but_valid_still_solves(n):
    # A = D M D with M = I + ones/2 (well conditioned) and D spanning 18 orders of magnitude:
    # a heavy and a very light degree of freedom. The pivots are tested relative to their own
    # diagonal entry, so the scaling does not make A "singular". x = D^-1 M^-1 D^-1 b.
    scales = np.logspace(3, -6, n)
    M = np.eye(n) + np.ones((n, n)) / 2
    A = np.diag(scales) @ M @ np.diag(scales)
    rhs = np.arange(1.0, n + 1.0)
    expected = np.linalg.solve(M, rhs / scales) / scales
    args = sympy.symbols(f"s0:{n}")
    A_sym = sympy.Matrix(n, n, lambda i, j: args[i] * args[j] * M[i, j])
    solve = compile_linear_solve(A_sym, list(rhs), [list(args)], symmetric=True)
    assert np.allclose(np.array(A_sym.subs(dict(zip(args, scales, strict=True))), float), A)
    # M has condition number n / 2 + 1; Cholesky on the scaled system: rtol 1e-12
    assert_allclose(solve(scales), expected, rtol=1e-12)
    assert_allclose(solve(np.stack([scales, scales], axis=1))[:, 1], expected, rtol=1e-12)


def test_indefinite_symmetric_singular_is_caught():
    # symmetric, not positive definite (negative semi-definite), singular: [[x, 1], [1, 1/x]]
    # at x = -0.3 has determinant 0; Cholesky fails and the general test must catch it
    x = sympy.Symbol("x")
    solve = compile_linear_solve(sympy.Matrix([[x, 1], [1, 1 / x]]), [1, 2], [x],
                                 symmetric=True)
    with pytest.raises(SingularMassMatrixError, match=r"is singular at x=-0\.3;"):
        solve(-0.3)
