"""The model of Andrews' squeezer mechanism in ``benchmarks/squeezer.py`` (seven bodies, three
loops closed at one point, a spring, a motor; book, ch. 13.2, 25.3) against the published
problem "andrews" of the Test Set for IVP Solvers (Mazzia, Magherini et al., University of
Bari; Hairer & Wanner, Solving ODE II, sec. VII.7): its consistent initial positions close
our loops, and our accelerations equal the test set's equations (written by hand with numpy
in the same file) and its published accelerations and multipliers.
"""

import importlib.util
from pathlib import Path

import mpmath  # a dependency of sympy
import numpy as np
import pytest
import sympy as sp

_PATH = Path(__file__).resolve().parents[2] / "benchmarks" / "squeezer.py"


@pytest.fixture(scope="module")
def squeezer():
    spec = importlib.util.spec_from_file_location("squeezer_benchmark", _PATH)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def system(squeezer):
    return squeezer.squeezer_system()


def test_published_initial_positions_close_our_loops(squeezer, system):
    at = dict(zip(system.equations_of_motion().coordinates, squeezer.Q0, strict=True))
    conditions = system.closure_conditions()
    assert len(conditions) == 6
    residuals = [float(phi.subs(at)) for _, _, phi in conditions]
    assert np.max(np.abs(residuals)) < 1e-12


def test_hand_written_model_gives_the_published_accelerations_and_multipliers(squeezer):
    acc, lam = squeezer.hand_accelerations(squeezer.Q0, squeezer.U0)
    np.testing.assert_allclose(acc, squeezer.A0, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(lam, squeezer.LAMBDA0, rtol=1e-12, atol=1e-12)


def test_our_accelerations_at_t0_equal_the_hand_written_and_published_ones(squeezer, system):
    rhs = system.equations_of_motion().rhs()
    y0 = np.concatenate((squeezer.Q0, squeezer.U0))
    ours, hand = rhs(0.0, y0)[7:], squeezer.hand_rhs(0.0, y0)[7:]
    scale = np.max(np.abs(squeezer.A0))
    assert np.max(np.abs(ours - hand)) < 1e-10 * scale
    assert np.max(np.abs(ours - squeezer.A0)) < 1e-10 * scale


def test_our_right_hand_side_equals_the_hand_written_one_off_the_start(squeezer, system):
    """At states with large rates (the velocity terms, the acceleration bias) and off the
    constraints (Baumgarte's terms, the same on both sides)."""
    rhs = system.equations_of_motion().rhs()
    rng = np.random.default_rng(7)
    for _ in range(5):
        y = np.concatenate((squeezer.Q0 + 0.3 * rng.normal(size=7), 500 * rng.normal(size=7)))
        ours, hand = rhs(0.0, y), squeezer.hand_rhs(0.0, y)
        assert np.max(np.abs(ours - hand)) < 1e-10 * np.max(np.abs(hand))


def test_the_loops_meet_at_E_with_the_published_conditions(squeezer, system):
    """Our closure conditions are the test set's g(q) = 0, row for row, up to sign."""
    eqs = system.equations_of_motion()
    rng = np.random.default_rng(3)
    q = squeezer.Q0 + rng.normal(size=7)
    at = dict(zip(eqs.coordinates, q, strict=True))
    ours = np.array([float(sp.sympify(phi).subs(at)) for _, _, phi in
                     system.closure_conditions()])
    published = squeezer.hand_parts(q, np.zeros(7))[3]
    np.testing.assert_allclose(np.abs(ours), np.abs(published), rtol=1e-12, atol=1e-15)


def test_right_hand_side_equals_the_symbolic_equations_solved_in_40_digits(squeezer, system):
    """The first-order form of the generated code (one float64 state: y' straight from the
    generated function, the augmented solve unrolled in it) against the public symbolic
    M, f, A and the stabilised bias, the augmented system solved by mpmath at 40 digits,
    at random states off the constraints with large rates."""
    eqs = system.equations_of_motion()
    c = eqs.constraints
    q_s = [sp.Symbol(f"q{i}") for i in range(7)]
    u_s = [sp.Symbol(f"u{i}") for i in range(7)]
    rule = dict(zip(eqs.u, u_s, strict=True))
    K = sp.BlockMatrix([[eqs.mass_matrix, c.jacobian.T],
                        [c.jacobian, sp.zeros(6, 6)]]).as_explicit()
    F = sp.Matrix.vstack(eqs.forcing, c.stabilized_bias())
    KF = [m.xreplace(rule).xreplace(dict(zip(eqs.q, q_s, strict=True))) for m in (K, F)]
    evaluate = sp.lambdify([q_s, u_s], KF, "mpmath")
    rhs = eqs.rhs()
    rng = np.random.default_rng(11)
    with mpmath.workdps(40):
        for _ in range(4):
            y = np.concatenate((squeezer.Q0 + 0.3 * rng.normal(size=7),
                                500 * rng.normal(size=7)))
            Kv, Fv = evaluate(list(y[:7]), list(y[7:]))
            x = mpmath.lu_solve(mpmath.matrix(Kv), mpmath.matrix(Fv))
            exact = np.array([float(x[i]) for i in range(7)])
            ours = rhs(0.0, y)
            np.testing.assert_array_equal(ours[:7], y[7:])
            assert np.max(np.abs(ours[7:] - exact)) < 1e-12 * np.max(np.abs(exact))
