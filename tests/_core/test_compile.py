"""Tests of rigidmech._core.compile: the symbolic -> numeric compiler."""

import pickle

import numpy as np
import pytest
import sympy
from hypothesis import example, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from rigidmech._core.compile import (
    CompiledFunction,
    CompiledLinearSolve,
    compile_expressions,
    compile_linear_solve,
)
from rigidmech._core.errors import (
    ArgumentError,
    ArgumentTypeError,
    CompilationError,
    SingularMassMatrixError,
)

x, y, z, a, b, c = sympy.symbols("x y z a b c")

# Smooth, well-conditioned expressions (no cancellation at the sampled points): both code paths
# and a 30-digit sympy evaluation then agree to a few ulps per operation, so 1e-13 relative
# leaves a margin of ~100x over the rounding of these ~10-30 operation expressions.
SMOOTH = [
    sympy.sin(x) * sympy.cos(y) + sympy.exp(z / 3),
    (x**2 + y**2 + 1) ** sympy.Rational(3, 2) / (2 + sympy.cos(z)),
    sympy.atan2(y, 2 + x) + sympy.log(1 + z**2) - a * b,
    sympy.sqrt(1 + a**2) * sympy.tanh(b) + x**-2 * c,
    sympy.pi * x / 7 + sympy.Rational(2, 3) * y**3 - c,
]
RTOL_SMOOTH = 1e-13


def _reference(expr, values):
    return float(expr.evalf(30, subs=values))


@pytest.fixture(scope="module")
def smooth():
    exprs = (sympy.Matrix(SMOOTH[:4]).reshape(2, 2), SMOOTH[4], [SMOOTH[0], SMOOTH[3]])
    return exprs, compile_expressions(exprs, [[x, y, z], a, [b, c]], name="smooth")


def _random_point(rng):
    return {
        x: rng.uniform(0.5, 2.0),
        y: rng.uniform(-2.0, 2.0),
        z: rng.uniform(-2.0, 2.0),
        a: rng.uniform(-2.0, 2.0),
        b: rng.uniform(-2.0, 2.0),
        c: rng.uniform(-2.0, 2.0),
    }


# ----------------------------------------------------------------------------------- values


def test_single_state_matches_sympy(smooth):
    exprs, f = smooth
    rng = np.random.default_rng(1)
    for _ in range(10):
        v = _random_point(rng)
        matrix, scalar, listed = f(np.array([v[x], v[y], v[z]]), v[a], [v[b], v[c]])
        assert isinstance(scalar, float)
        assert isinstance(listed, list) and len(listed) == 2
        assert matrix.shape == (2, 2)
        expected = np.array([_reference(e, v) for e in SMOOTH[:4]]).reshape(2, 2)
        assert_allclose(matrix, expected, rtol=RTOL_SMOOTH)
        assert_allclose(scalar, _reference(SMOOTH[4], v), rtol=RTOL_SMOOTH)
        assert_allclose(listed, [_reference(SMOOTH[0], v), _reference(SMOOTH[3], v)],
                        rtol=RTOL_SMOOTH)


def test_batch_matches_sympy(smooth):
    exprs, f = smooth
    rng = np.random.default_rng(2)
    points = [_random_point(rng) for _ in range(6)]
    xyz = np.array([[p[s] for p in points] for s in (x, y, z)])
    bc = np.array([[p[s] for p in points] for s in (b, c)])
    av = np.array([p[a] for p in points])
    matrix, scalar, listed = f(xyz, av, bc)
    assert matrix.shape == (2, 2, 6) and scalar.shape == (6,) and listed[1].shape == (6,)
    for k, v in enumerate(points):
        expected = np.array([_reference(e, v) for e in SMOOTH[:4]]).reshape(2, 2)
        assert_allclose(matrix[..., k], expected, rtol=RTOL_SMOOTH)
        assert_allclose(scalar[k], _reference(SMOOTH[4], v), rtol=RTOL_SMOOTH)


# The two paths (math on floats, numpy ufuncs on arrays) evaluate the same operations in the
# same order, but through different libm routines (math.tanh vs numpy.tanh, ...), each within
# a few ulps. A top-level sum t_1 + ... + t_k can cancel (sin x cos y + exp(z / 3) -> 0), so the
# paths agree relative to the magnitude of the terms, M = |t_1| + ... + |t_k|, not to the
# result: with each term within 8 ulps (<= 4 ulps per numpy float64 routine, 0.5 per arithmetic
# operation, <= 6 operations a term) on each path, |single - batched| <= 2 * 8 eps M = 16 eps M.
# Measured: at most 2 eps M over 20,000 random points (where the error relative to the result
# reached 2e-13).
PATH_TOLERANCE_EPS = 16
_TERMS = sympy.lambdify([x, y, z, a, b, c], [list(sympy.Add.make_args(e)) for e in SMOOTH],
                        "math")


def _terms_magnitude(*point):
    return np.array([sum(abs(t) for t in terms) for terms in _TERMS(*point)])


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-3.0, 3.0), min_size=6, max_size=6))
# sqrt(1 + a**2) tanh(b) + c / x**2 = -1.1e-3 while its terms are ~1.4 (M = 2.75): the paths
# differ by 1.9e-13 relative to the result (the former rtol=1e-14 bound failed), 0.36 eps M
@example([0.8753631898647409, 2.107249729292744, 0.7828962656130498, -1.5844817285942123,
          0.9369332660538703, -2.6029672549586547])
def test_single_and_batched_paths_agree(smooth, values):
    exprs, f = smooth
    xv = 0.5 + abs(values[0])  # x kept away from 0 (x**-2)
    single = f([xv, values[1], values[2]], values[3], [values[4], values[5]])
    batched = f(np.array([[xv], [values[1]], [values[2]]]), np.array([values[3]]),
                np.array([[values[4]], [values[5]]]))
    one = np.append(np.ravel(single[0]), single[1])  # SMOOTH[0..3] (row-major), SMOOTH[4]
    many = np.append(np.ravel(batched[0][..., 0]), batched[1][0])
    bound = PATH_TOLERANCE_EPS * np.finfo(float).eps * _terms_magnitude(xv, *values[1:])
    assert np.all(np.abs(one - many) <= bound), (one - many, bound)


def test_scalar_expression_gives_float_and_array():
    f = compile_expressions(x * y, [x, y])
    assert f(2.0, 3.0) == 6.0 and type(f(2.0, 3.0)) is float
    assert f(np.int64(2), 3).__class__ is float
    assert_allclose(f(np.array([1.0, 2.0]), 3.0), [3.0, 6.0], rtol=0)


def test_constant_entries_broadcast_in_batch():
    f = compile_expressions(sympy.Matrix([[1, x], [0, sympy.pi]]), [x])
    out = f(np.arange(3.0))
    assert out.shape == (2, 2, 3)
    assert_allclose(out[:, :, 2], [[1.0, 2.0], [0.0, np.pi]], rtol=0)


# --------------------------------------------------------------------------------- broadcasting


@pytest.mark.parametrize(
    ("vector_shape", "scalar_shape", "batch"),
    [
        ((3,), (), ()),
        ((3, 5), (), (5,)),
        ((3,), (5,), (5,)),
        ((3, 4, 5), (5,), (4, 5)),
        ((3, 4, 1), (1, 6), (4, 6)),
    ],
)
def test_broadcast_shapes(vector_shape, scalar_shape, batch):
    f = compile_expressions(
        (sympy.Matrix([[x + a, y], [z, a], [1, 2]]), x * a), [[x, y, z], a]
    )
    matrix, scalar = f(np.ones(vector_shape), np.full(scalar_shape, 2.0))
    assert matrix.shape == (3, 2) + batch
    assert np.shape(scalar) == batch
    assert_allclose(matrix[0, 0], 3.0, rtol=0)
    assert_allclose(matrix[2, 1], 2.0, rtol=0)


def test_array_output_shape_and_1d_array():
    f = compile_expressions(sympy.Array([x, 2 * x, 3 * x]), [x])
    assert f(1.0).shape == (3,)
    assert f(np.ones((2, 4))).shape == (3, 2, 4)


# ------------------------------------------------------------------------------------- errors


def test_missing_symbols_named():
    with pytest.raises(
        CompilationError,
        match=r"`exprs` depend on b, c which are not in `args`; pass them as arguments or "
        r"substitute values first\.",
    ):
        compile_expressions(a + b * c, [a])


def test_functions_of_time_rejected():
    t = sympy.Symbol("t")
    q = sympy.Function("q")(t)
    with pytest.raises(CompilationError, match=r"contain Derivative\(q\(t\), t\), q\(t\) which"):
        compile_expressions(q.diff(t) + q, [t])


@pytest.mark.parametrize(
    ("exprs", "args", "error", "match"),
    [
        (x, x, ArgumentTypeError, r"`args` must be a sequence .* Wrap a single symbol"),
        (x, [x + 1], ArgumentTypeError, r"`args\[0\]` must be a sympy Symbol"),
        (x, [[x, 2]], ArgumentTypeError, r"`args\[0\]` must contain only sympy Symbols"),
        (x, [[]], ArgumentError, r"`args\[0\]` is an empty sequence"),
        (x, [x, [y, x]], ArgumentError, r"`args` list the symbol x twice"),
        (x > 0, [x], CompilationError, r"`exprs` must be numeric; got the condition x > 0"),
        (sympy.I * x, [x], CompilationError, r"imaginary unit"),
        ({x}, [x], ArgumentTypeError, r"`exprs` must be a sympy expression"),
        (sympy.besselk(x, 1) * sympy.DiracDelta(x), [x], CompilationError,
         r"DiracDelta\(x\) which has no numeric translation"),
    ],
)
def test_compile_errors(exprs, args, error, match):
    with pytest.raises(error, match=match):
        compile_expressions(exprs, args)


def test_bad_name():
    with pytest.raises(ArgumentError, match=r"`name` must be a Python identifier"):
        compile_expressions(x, [x], name="my f")


@pytest.fixture(scope="module")
def two_args():
    return compile_expressions(sympy.Matrix([x * a, y * a]), [[x, y], a], name="g")


@pytest.mark.parametrize(
    ("call_args", "error", "match"),
    [
        (([1.0, 2.0, 3.0], 1.0), ArgumentError,
         r"argument `\[x, y\]` must have shape \(2,\) or \(2, \*batch\); got shape \(3,\)"),
        ((1.0, 1.0), ArgumentError, r"argument `\[x, y\]` must have shape \(2,\)"),
        ((np.ones((2, 3)), np.ones(4)), ArgumentError,
         r"batch shapes of the arguments do not broadcast together "
         r"\(\[x, y\]: \(3,\), a: \(4,\)\)"),
        (([1.0, 2.0],), ArgumentTypeError, r"`g` takes 2 arguments \(\[x, y\], a\); got 1"),
        (([1.0, 2.0], "one"), ArgumentTypeError, r"argument `a` must be a real number"),
        (([1.0, 2.0], 1j), ArgumentTypeError, r"argument `a` must be a real number"),
    ],
)
def test_call_errors(two_args, call_args, error, match):
    with pytest.raises(error, match=match):
        two_args(*call_args)


# ----------------------------------------------------------------------------------- freshness


@pytest.mark.parametrize("batched", [False, True])
def test_fresh_arrays(two_args, batched):
    state = np.array([[1.0, 5.0], [2.0, 6.0]]) if batched else np.array([1.0, 2.0])
    first = two_args(state, 2.0)
    kept = first.copy()
    second = two_args(state, 3.0)
    assert first is not second
    assert not np.shares_memory(first, second)
    two_args(state + 10.0, 7.0)
    assert_allclose(first, kept, rtol=0)
    assert_allclose(second, 1.5 * kept, rtol=0)


def test_fresh_arrays_in_a_real_integration():
    # scipy's RK45 keeps references to earlier right-hand sides (k stages); a reused buffer
    # corrupts them (the PyDy trap, TARGETS.md).  Harmonic oscillator y'' = -w^2 y: exact
    # solution cos(w t); with rtol 1e-10 RK45's global error stays below 1e-7 here.
    q, u, w = sympy.symbols("q u w")
    rhs = compile_expressions(sympy.Array([u, -(w**2) * q]), [[q, u], w], name="oscillator")
    sol = solve_ivp(lambda t, s: rhs(s, 2.0), (0.0, 10.0), [1.0, 0.0], method="RK45",
                    rtol=1e-10, atol=1e-12)
    assert sol.success
    assert_allclose(sol.y[0, -1], np.cos(20.0), atol=1e-7)


# ----------------------------------------------------------------- non-smooth and domain errors


NONSMOOTH = [
    sympy.sign(x) * y,
    sympy.Piecewise((x**2, x > 0), (-y, x < -1), (0, True)),
    sympy.Abs(x) + sympy.Heaviside(x),
    sympy.Min(x, y, 0.5) + sympy.Max(x, 1),
]


@pytest.mark.parametrize("xv", [-2.0, -0.5, 0.0, 0.5, 2.0])
def test_piecewise_sign_both_paths(xv):
    f = compile_expressions(NONSMOOTH, [x, y])
    single = f(xv, 3.0)
    batched = f(np.array([xv, xv]), 3.0)
    expected = [float(e.subs({x: xv, y: 3.0})) for e in NONSMOOTH]
    # exact: comparisons, copies and one product or square of exact binary numbers
    assert_allclose(single, expected, rtol=0)
    assert_allclose([v[1] for v in batched], expected, rtol=0)


def test_domain_errors_give_ieee_values_without_warning():
    # math.sqrt(-1) and 1/0 raise on the single-state path; the call falls back to numpy, whose
    # nan and inf agree with the batched path (no RuntimeWarning: filterwarnings=error).
    f = compile_expressions((sympy.sqrt(x), 1 / y, x ** sympy.Rational(1, 3)), [x, y])
    root, inverse, cube = f(-4.0, 0.0)
    assert np.isnan(root) and np.isinf(inverse) and np.isnan(cube)
    assert isinstance(root, float)
    root_b, inverse_b, cube_b = f(np.array([-4.0, 8.0]), np.array([0.0, 2.0]))
    assert np.isnan(root_b[0]) and np.isinf(inverse_b[0]) and np.isnan(cube_b[0])
    assert_allclose([root_b[1], inverse_b[1], cube_b[1]], [np.sqrt(8.0), 0.5, 2.0], rtol=1e-15)
    assert f(8.0, 2.0)[2] == pytest.approx(2.0, rel=1e-15)


def test_function_missing_from_math_uses_scipy():
    f = compile_expressions(sympy.besselj(0, x) + sympy.erf(x), [x])
    import scipy.special as sc

    expected = sc.j0(0.7) + sc.erf(0.7)
    assert_allclose(f(0.7), expected, rtol=1e-15)
    assert_allclose(f(np.array([0.7, 0.7])), [expected, expected], rtol=1e-15)


# ------------------------------------------------------------------------------- the object


def test_repr_source_ops_immutable_pickle(two_args):
    assert repr(two_args) == "CompiledFunction(g([x, y], a) -> (2, 1), n_ops=2)"
    assert "def g_single(x, y, a):" in two_args.source
    assert "def g_batched(_v0, a, _batch):" in two_args.source
    assert two_args.n_ops == 2
    assert two_args.args == ((x, y), (a,))
    with pytest.raises(AttributeError, match="immutable"):
        two_args.n_ops = 3
    clone = pickle.loads(pickle.dumps(two_args))
    assert isinstance(clone, CompiledFunction)
    assert_allclose(clone([1.0, 2.0], 3.0), two_args([1.0, 2.0], 3.0), rtol=0)


def test_cse_reduces_ops_and_awkward_names():
    weird = sympy.Symbol("theta'")
    lam = sympy.Symbol("lambda")
    expr = (sympy.sin(weird + lam) ** 2 + sympy.sin(weird + lam)) * sympy.Dummy("d")
    d = next(iter(expr.atoms(sympy.Dummy)))
    f = compile_expressions(expr, [weird, lam, d])
    g = compile_expressions(expr, [weird, lam, d], cse=False)
    assert f.n_ops < g.n_ops
    assert_allclose(f(0.1, 0.2, 2.0), 2.0 * (np.sin(0.3) ** 2 + np.sin(0.3)), rtol=1e-15)
    assert_allclose(g(0.1, 0.2, 2.0), f(0.1, 0.2, 2.0), rtol=1e-15)


# ------------------------------------------------------------------------------- linear solve


def _spd_problem(n, seed):
    """A = B(x, y)^T B(x, y) + n I (symmetric positive definite), b(x, y), and a numeric twin.

    B[i, j] = c0 + c1 cos(x) + c2 y with small random integers; the twin evaluates the same
    formulas with numpy (an independent evaluation of A and b).
    """
    rng = np.random.default_rng(seed)
    coeffs = rng.integers(-3, 4, (n, n, 3))
    B = sympy.Matrix(n, n, lambda i, j: coeffs[i, j, 0] + coeffs[i, j, 1] * sympy.cos(x)
                     + coeffs[i, j, 2] * y)
    A = B.T * B + n * sympy.eye(n)
    rhs = sympy.Matrix([sympy.sin(k * x) + y**k for k in range(n)])

    def numeric(xv, yv):
        B_num = coeffs[:, :, 0] + coeffs[:, :, 1] * np.cos(xv) + coeffs[:, :, 2] * yv
        b_num = np.array([np.sin(k * xv) + yv**k for k in range(n)])
        return B_num.T @ B_num + n * np.eye(n), b_num

    return A, rhs, numeric


@pytest.mark.parametrize("n", [1, 3, 8])
@pytest.mark.parametrize("symmetric", [True, False])
def test_linear_solve_matches_numpy(n, symmetric):
    A, rhs, numeric = _spd_problem(n, seed=n)
    solve = compile_linear_solve(A, rhs, [[x, y]], symmetric=symmetric)
    assert isinstance(solve, CompiledLinearSolve)
    assert solve.unrolled == (symmetric and n <= 6)
    states = np.array([[0.3, -1.2, 2.0], [0.7, 0.1, -0.4]])
    batched = solve(states)
    assert batched.shape == (n, 3)
    for k in range(3):
        expected = np.linalg.solve(*numeric(*states[:, k]))
        # A is well conditioned (+ n I): Cholesky vs LU differ by a few ulps * cond(A)
        assert_allclose(solve(states[:, k]), expected, rtol=1e-12, atol=1e-14)
        assert_allclose(batched[:, k], expected, rtol=1e-12, atol=1e-14)


def test_linear_solve_multi_axis_batch_and_fresh():
    A, rhs, _ = _spd_problem(2, seed=5)
    solve = compile_linear_solve(A, rhs, [x, y], symmetric=True)
    xs = np.linspace(0.0, 1.0, 12).reshape(3, 4)
    out = solve(xs, 0.5)
    assert out.shape == (2, 3, 4)
    assert_allclose(out[:, 1, 2], solve(xs[1, 2], 0.5), rtol=1e-13)
    first, second = solve(0.1, 0.2), solve(0.1, 0.2)
    assert first is not second
    assert "symmetric=True" in repr(solve)


def test_linear_solve_upper_triangle_only():
    # symmetric=True reads the upper triangle: a wrong lower triangle is ignored
    A = sympy.Matrix([[2, x], [123, 3]])
    solve = compile_linear_solve(A, [1, 1], [x], symmetric=True)
    assert_allclose(solve(1.0), np.linalg.solve([[2.0, 1.0], [1.0, 3.0]], [1.0, 1.0]),
                    rtol=1e-15)


def test_singular_mass_matrix_single_state():
    A = sympy.Matrix([[1, x], [x, 1]])
    for symmetric in (True, False):
        solve = compile_linear_solve(A, [y, 1], [x, y], symmetric=symmetric)
        with pytest.raises(SingularMassMatrixError, match=r"is singular at x=1\.0, y=2\.0;"):
            solve(1.0, 2.0)


def test_singular_mass_matrix_batch_index():
    A = sympy.Matrix([[1, x], [x, 1]])
    solve = compile_linear_solve(A, [y, 1], [[x, y]], symmetric=True)
    states = np.array([[0.0, 0.5, -1.0, 1.0], [1.0, 2.0, 3.0, 4.0]])
    with pytest.raises(
        SingularMassMatrixError,
        match=r"is singular at batch index 2, where \[x, y\]=\[-1\.0, 3\.0\]",
    ):
        solve(states)


def test_non_finite_mass_matrix():
    A = sympy.Matrix([[1 / x, 0], [0, 1]])
    solve = compile_linear_solve(A, [1, 1], [x], symmetric=True)
    with pytest.raises(SingularMassMatrixError, match=r"is not finite at x=0\.0;"):
        solve(0.0)
    with pytest.raises(SingularMassMatrixError, match=r"is not finite at batch index 1, where x=0"):
        solve(np.array([1.0, 0.0]))


def test_indefinite_symmetric_falls_back_to_lu():
    # not positive definite: the unrolled Cholesky gives up, numpy's LU solves it
    A = sympy.Matrix([[x, 1], [1, 0]])
    solve = compile_linear_solve(A, [1, 2], [x], symmetric=True)
    assert_allclose(solve(1.0), np.linalg.solve([[1.0, 1.0], [1.0, 0.0]], [1.0, 2.0]),
                    rtol=1e-15)


@pytest.mark.parametrize(
    ("A", "b", "match"),
    [
        (sympy.Matrix([[1, 2, 3]]), [1], r"`A` must be a square, non-empty sympy Matrix"),
        (sympy.eye(2), sympy.Matrix([1, 2, 3]), r"`b` must have shape \(2, 1\) or \(1, 2\)"),
        (sympy.eye(2), [1, 2, 3], r"`b` must have 2 entries to match `A`; got 3"),
    ],
)
def test_linear_solve_shape_errors(A, b, match):
    with pytest.raises(ArgumentError, match=match):
        compile_linear_solve(A, b, [x])


def test_linear_solve_pickle():
    A, rhs, _ = _spd_problem(3, seed=7)
    solve = compile_linear_solve(A, rhs, [x, y], symmetric=True)
    clone = pickle.loads(pickle.dumps(solve))
    assert_allclose(clone(0.2, 0.3), solve(0.2, 0.3), rtol=0)


def test_batched_symmetric_solve_matches_numpy_and_falls_back():
    """The batched unrolled Cholesky (symmetric systems) agrees with numpy.linalg.solve on
    SPD systems; an indefinite member sends the batch through numpy's LU instead."""
    n = 8
    a = sympy.symbols(f"a0:{n}")
    L = sympy.Matrix(n, n, lambda i, j: (a[i] + a[j]) / 4 if i >= j else 0) + sympy.diag(*a)
    A = L * L.T
    b = sympy.Matrix([a[i] - 2 * a[(i + 1) % n] for i in range(n)])
    solve = compile_linear_solve(A, b, [list(a)], symmetric=True)
    rng = np.random.default_rng(3)
    values = rng.uniform(0.5, 2.0, size=(n, 50))
    got = solve(values)
    f_A = sympy.lambdify([a], A, "numpy")
    f_b = sympy.lambdify([a], b, "numpy")
    for k in range(50):
        expected = np.linalg.solve(np.array(f_A(values[:, k]), dtype=float),
                                   np.array(f_b(values[:, k]), dtype=float).ravel())
        assert_allclose(got[:, k], expected, rtol=1e-10)
    indefinite = compile_linear_solve(sympy.Matrix([[x, 1], [1, 0]]), [1, 2], [x],
                                      symmetric=True)
    assert_allclose(indefinite(np.array([1.0, 2.0])),
                    [[2.0, 2.0], [-1.0, -3.0]], rtol=1e-14)


def test_batched_symmetric_solve_writes_into_a_given_array():
    """The generated batched code of a symmetric system takes an optional ``_out`` (the rows of
    the compiled right-hand side's output it fills): the solution is written there and
    returned, the numbers of a fresh call, of the single-state path and of sympy at 30 digits;
    a member off the unrolled path (singular here) returns (A, b) for the checked solve."""
    A = sympy.Matrix([[2 + x**2, x * y, 0], [x * y, 3 + y**2, sympy.cos(z)],
                      [0, sympy.cos(z), 2 + sympy.sin(z) ** 2]])
    rhs = sympy.Matrix([sympy.sin(x) + y, x * z - 1, sympy.exp(y / 3)])
    solve = compile_linear_solve(A, rhs, [[x, y, z]], symmetric=True)
    rng = np.random.default_rng(11)
    values = rng.uniform(-2.0, 2.0, (3, 6))
    buffer = np.full((3, 6), np.nan)
    got = solve._batched(values, (6,), _out=buffer)
    assert got is buffer
    fresh = solve._batched(values, (6,))
    assert fresh is not buffer and not np.shares_memory(fresh, buffer)
    assert_allclose(fresh, buffer, rtol=0, atol=0)
    for k in range(6):
        point = dict(zip((x, y, z), values[:, k].tolist(), strict=True))
        exact = A.subs(point).evalf(30).LUsolve(rhs.subs(point).evalf(30))
        expected = np.array([float(v) for v in exact])
        assert_allclose(buffer[:, k], expected, rtol=1e-12, atol=1e-12)
        assert_allclose(solve(values[:, k]), expected, rtol=1e-12, atol=1e-12)
    singular = compile_linear_solve(sympy.Matrix([[x, x], [x, x]]), [1, 2], [x],
                                    symmetric=True)
    with np.errstate(all="ignore"):  # as its callers run it: 1/sqrt(0) on the way
        result = singular._batched(np.array([1.0, 2.0]), (2,), _out=np.empty((2, 2)))
    assert type(result) is tuple
    with pytest.raises(SingularMassMatrixError, match="batch index 0"):
        singular(np.array([1.0, 2.0]))
