"""LinearSystem.numeric / eigenvalues compiled once (issue 20): the compiled matrices equal the
exact entries evaluated with sympy's evalf (30 digits) at random parameters, entries that
vanish come out as exact zeros, a compiled LinearSystem survives pickling (shipped to worker
processes), bad input is named."""

import pickle
import sys
import threading
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentError
from rigidmech.vibrations import linearize
from rigidmech.vibrations.linearize import LinearSystem

sys.path.insert(0, str(Path(__file__).parent))
sys.path.insert(0, str(Path(__file__).parents[1] / "systems"))
from rolling_models import rolling_disc  # noqa: E402
from test_linearize import n_link, spherical_pendulum  # noqa: E402


def evalf_matrices(lin, values):
    """(M, C, K, B) from the exact entries, 30 digits: the reference."""
    rule = {p: sp.Float(values[p.name], 30) for p in lin.parameters}
    return tuple(np.array([[float(e.xreplace(rule).evalf(30)) for e in X.row(i)]
                           for i in range(X.rows)], dtype=float).reshape(X.shape)
                 for X in (lin.M, lin.C, lin.K, lin.B))


def _random_values(lin, rng):
    return {p.name: float(rng.uniform(0.5, 2.0)) for p in lin.parameters}


def _systems():
    a = sp.Symbol("a")
    eqs3 = n_link(3)
    yield "3-link pendulum, hanging", linearize(eqs3, [-sp.pi / 2, 0, 0], simplify=False)
    eqs, (phi, theta) = spherical_pendulum()
    W = sp.Symbol("W")
    yield "spherical pendulum, conical motion (gyroscopic)", linearize(
        eqs, {theta: a}, velocities={phi: W}, check=False, simplify=False)
    s, _, _ = rolling_disc()
    Omega = sp.Symbol("Omega")
    yield "rolling disc upright, spinning (constraints)", linearize(
        s.equations_of_motion(), about={"theta": sp.pi / 2}, velocities={"phi": Omega},
        simplify=False)


_SYSTEMS = list(_systems())


@pytest.mark.parametrize("index", range(len(_SYSTEMS)), ids=[s[0] for s in _SYSTEMS])
def test_compiled_numeric_equals_the_exact_entries_at_random_parameters(index):
    lin = _SYSTEMS[index][1]
    rng = np.random.default_rng(index)
    for _ in range(3):
        values = _random_values(lin, rng)
        for got, want in zip(lin.numeric(**values), evalf_matrices(lin, values), strict=True):
            assert got.shape == want.shape
            scale = max(1.0, np.abs(want).max(initial=0.0))
            np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * scale)
            # exact zeros stay exact
            assert (got[want == 0] == 0.0).all()


def _with_hidden_zeros():
    """K[0, 1] vanishes without being structurally 0 (float arithmetic leaves 1e-16 there),
    C[0, 0] is a constant that vanishes, K[0, 0] a constant that does not."""
    x, y = sp.symbols("x y")
    k = sp.Symbol("k", positive=True)
    r2 = sp.sqrt(2)
    hidden = (r2 + k) ** 2 - k**2 - 2 * r2 * k - 2
    constant_zero = sp.sin(sp.pi / 7) ** 2 + sp.cos(sp.pi / 7) ** 2 - 1
    K = sp.Matrix([[sp.sin(sp.pi / 7) * sp.sqrt(3) * k, hidden], [hidden, k]])
    C = sp.Matrix([[constant_zero, 0], [0, 0]])
    return LinearSystem((x, y), {"x": 0, "y": 0}, {"x": 0, "y": 0}, sp.eye(2), C, K,
                        sp.zeros(2, 0), ()), k


def test_entries_that_vanish_are_exact_zeros():
    lin, k = _with_hidden_zeros()
    for value in (0.3, 0.7, 1.9, 123.0):
        M, C, K, B = lin.numeric(k=value)
        assert K[0, 1] == 0.0 and K[1, 0] == 0.0 and C[0, 0] == 0.0
        assert K[0, 0] == pytest.approx(float(sp.sin(sp.pi / 7) * sp.sqrt(3)) * value,
                                        rel=1e-15)
        assert B.shape == (2, 0)


def test_float_arithmetic_alone_leaves_a_residue_there():
    """Why the entries are folded first: compiled as they are, K[0, 1] is rounding noise."""
    from rigidmech._core.compile import compile_expressions

    lin, k = _with_hidden_zeros()
    f = compile_expressions(lin.K, [k])
    assert any(f(v)[0, 1] != 0.0 for v in (0.3, 0.7, 1.9, 123.0))


def test_missing_parameters_are_named_and_unknown_ones_ignored():
    lin = _SYSTEMS[0][1]
    with pytest.raises(ArgumentError, match=r"missing values for parameters \['g', 'l3'"):
        lin.numeric(l1=1.0, l2=1.0, m1=1.0, m2=1.0, m3=1.0)
    values = {p.name: 1.0 for p in lin.parameters}
    ref = lin.numeric(**values)
    for got, want in zip(lin.numeric(**values, not_a_parameter=3.0), ref, strict=True):
        np.testing.assert_array_equal(got, want)


def test_eigenvalues_modes_and_response_use_the_compiled_matrices():
    lin = _SYSTEMS[0][1]
    values = {p.name: 1.0 + 0.1 * i for i, p in enumerate(lin.parameters)}
    M, C, K, _ = evalf_matrices(lin, values)
    n = lin.n
    A = np.block([[np.zeros((n, n)), np.eye(n)],
                  [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    def by_frequency(ev):
        return np.array(sorted(ev, key=lambda z: (round(z.imag, 6), round(z.real, 6))))

    np.testing.assert_allclose(by_frequency(lin.eigenvalues(**values)),
                               by_frequency(np.linalg.eigvals(A)), rtol=1e-10, atol=1e-12)
    assert lin.modes(**values).frequencies.shape == (n,)


@pytest.mark.parametrize("module", ["pickle", "cloudpickle"])
def test_a_compiled_linear_system_survives_pickling(module):
    dumps, loads = pytest.importorskip(module).dumps, pickle.loads
    lin, _ = _with_hidden_zeros()
    before = lin.numeric(k=0.7)
    copy = loads(dumps(lin))
    assert "compiled" in copy._cache  # shipped compiled: no sympy work on the other side
    for got, want in zip(copy.numeric(k=0.7), before, strict=True):
        np.testing.assert_array_equal(got, want)


def test_threads_asking_at_once_share_one_compilation():
    lin, _ = _with_hidden_zeros()
    seen = []
    threads = [threading.Thread(target=lambda: seen.append(lin.numeric(k=0.5)))
               for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(seen) == 4 and all((s[2] == seen[0][2]).all() for s in seen)


def test_a_system_without_parameters_compiles_to_constants():
    x, v = sp.symbols("x x_dot")
    eqs = rm.EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
                               mass_matrix=sp.ImmutableMatrix([[2]]),
                               forcing=sp.ImmutableMatrix([[-8 * x - v]]))
    lin = linearize(eqs)
    M, C, K, B = lin.numeric()
    assert (M.tolist(), C.tolist(), K.tolist(), B.shape) == ([[2.0]], [[1.0]], [[8.0]], (1, 0))
