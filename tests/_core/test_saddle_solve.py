"""compile_linear_solve(..., saddle=n): the augmented system [[M, C^T], [C, 0]] of a
constrained system solved on the single-state path by the unrolled sparse range-space
elimination of rigidmech._core._saddle, the general path (LU of the equilibrated matrix)
taking over when a pivot is at most 1/SADDLE_PIVOT_FACTOR of its diagonal entry."""

import numpy as np
import pytest
import sympy as sp

from rigidmech._core import _saddle
from rigidmech._core import compile as compile_module
from rigidmech._core.compile import compile_linear_solve
from rigidmech.errors import SingularMassMatrixError


def _saddle_system(n, m, seed, density=0.5):
    """A random sparse saddle-point system of symbols: M SPD with zeros, C with zeros;
    returns (K, F, symbols, values)."""
    rng = np.random.default_rng(seed)
    syms, values = [], []

    def value(v):
        s = sp.Symbol(f"p{len(syms)}")
        syms.append(s)
        values.append(float(v))
        return s

    B = rng.normal(size=(n, n)) * (rng.random((n, n)) < density)
    Mv = B @ B.T + n * np.eye(n)
    M = sp.zeros(n, n)
    for i in range(n):
        for j in range(i + 1):
            if Mv[i, j] != 0:
                M[i, j] = M[j, i] = value(Mv[i, j])
    C = sp.zeros(m, n)
    for r in range(m):
        for c in range(n):
            if c == r or rng.random() < density:
                C[r, c] = value(rng.normal())
    F = sp.Matrix([value(rng.normal()) for _ in range(n + m)])
    K = sp.BlockMatrix([[M, C.T], [C, sp.zeros(m, m)]]).as_explicit()
    return sp.ImmutableMatrix(K), F, syms, values


@pytest.mark.parametrize("n, m, seed", [(2, 1, 0), (3, 2, 1), (7, 6, 2), (9, 4, 3), (5, 5, 4)])
def test_saddle_solve_equals_numpy_single_and_batch(n, m, seed):
    K, F, syms, values = _saddle_system(n, m, seed)
    solve = compile_linear_solve(K, F, [syms], saddle=n)
    Kv = np.array(K.subs(dict(zip(syms, values, strict=True))), dtype=float)
    Fv = np.array(F.subs(dict(zip(syms, values, strict=True))), dtype=float).ravel()
    expected = np.linalg.solve(Kv, Fv)
    np.testing.assert_allclose(solve(np.array(values)), expected, rtol=1e-10, atol=1e-12)
    batch = np.stack([np.array(values)] * 3, axis=1)
    np.testing.assert_allclose(solve(batch), np.stack([expected] * 3, axis=1), rtol=1e-10,
                               atol=1e-12)


def _boundary_case():
    """M = I (2 x 2), C rows (1, 0) and (100, c): S = [[1, 100], [100, 10000 + c^2]], whose
    second pivot c^2 is exactly 1/10001 of its diagonal entry at c = 1."""
    c = sp.Symbol("c")
    K = sp.ImmutableMatrix([[1, 0, 1, 100], [0, 1, 0, c], [1, 0, 0, 0], [100, c, 0, 0]])
    F = sp.Matrix([1, 2, 3, 4])
    return compile_linear_solve(K, F, [c], saddle=2), K, F, c


@pytest.mark.parametrize("c, fast", [(1.0, False), (1.0 + 2.0**-16, True),
                                     (1.0 - 2.0**-16, False), (2.0, True)])
def test_fast_path_only_above_the_pivot_ratio(monkeypatch, c, fast):
    assert _saddle.SADDLE_PIVOT_FACTOR == 10001.0
    calls = []
    general = compile_module._checked_solve

    def counted(*args):
        calls.append(1)
        return general(*args)

    monkeypatch.setattr(compile_module, "_checked_solve", counted)
    solve, K, F, sym = _boundary_case()
    x = solve(c)
    expected = np.linalg.solve(np.array(K.subs(sym, c), dtype=float),
                               np.array(F, dtype=float).ravel())
    np.testing.assert_allclose(x, expected, rtol=1e-12)
    assert (not calls) is fast


def test_singular_configuration_refused_by_the_general_path():
    """Two equal constraint rows: S singular, the fast path leaves, the general path
    refuses (the error of a singular augmented matrix)."""
    a = sp.Symbol("a")
    K = sp.ImmutableMatrix([[1, 0, 1, 1], [0, 1, a, a], [1, a, 0, 0], [1, a, 0, 0]])
    solve = compile_linear_solve(K, sp.Matrix([1, 2, 3, 4]), [a], saddle=2)
    with pytest.raises(SingularMassMatrixError, match="singular"):
        solve(0.5)


def test_non_finite_entry_goes_to_the_general_path():
    a = sp.Symbol("a")
    K = sp.ImmutableMatrix([[1, 0, 1], [0, a, 1], [1, 1, 0]])
    solve = compile_linear_solve(K, sp.Matrix([1, 2, 3]), [a], saddle=2)
    with pytest.raises(SingularMassMatrixError, match="not finite"):
        solve(np.inf)


@pytest.mark.parametrize("K, saddle, match", [
    (sp.ImmutableMatrix([[1, 0, 1], [0, 1, 2], [1, 3, 0]]), 2, "not a saddle-point"),
    (sp.ImmutableMatrix([[1, 0, 1], [0, 1, 2], [1, 2, 5]]), 2, "trailing block"),
    (sp.ImmutableMatrix([[1, 0, 1], [0, 1, 2], [1, 2, 0]]), 3, "integer between 1 and 2"),
    (sp.ImmutableMatrix([[1, 0, 1], [0, 1, 2], [1, 2, 0]]), True, "integer between 1 and 2"),
])
def test_bad_saddle_refused(K, saddle, match):
    with pytest.raises(ValueError, match=match):
        compile_linear_solve(K, sp.Matrix([1, 2, 3]), [sp.Symbol("x")], saddle=saddle)


def test_saddle_and_symmetric_exclude_each_other():
    K = sp.ImmutableMatrix([[1, 0, 1], [0, 1, 2], [1, 2, 0]])
    with pytest.raises(ValueError, match="exclude each other"):
        compile_linear_solve(K, sp.Matrix([1, 2, 3]), [sp.Symbol("x")], saddle=2,
                             symmetric=True)


def test_saddle_solve_survives_pickle():
    import pickle

    K, F, syms, values = _saddle_system(4, 2, 5)
    solve = compile_linear_solve(K, F, [syms], saddle=4)
    again = pickle.loads(pickle.dumps(solve))
    np.testing.assert_array_equal(again(np.array(values)), solve(np.array(values)))
