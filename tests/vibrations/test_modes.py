"""Natural modes of several degrees of freedom (ch. 21, 25.4, 27.5.2)."""

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from rigidmech import ode
from rigidmech._core.errors import ArgumentError
from rigidmech.vibrations import harmonic_response_direct, natural_modes, plot_frequency_response


def _random_system(seed, n):
    rng = np.random.default_rng(seed)
    A = rng.normal(size=(n, n))
    M = A @ A.T + n * np.eye(n)
    B = rng.normal(size=(n, n))
    K = B @ B.T + 0.1 * np.eye(n)
    return M, K


@given(st.integers(0, 10**6), st.integers(1, 6))
def test_modes_are_M_and_K_orthogonal(seed, n):
    M, K = _random_system(seed, n)
    modes = natural_modes(M, K)
    P = modes.shapes
    assert_allclose(P.T @ M @ P, np.eye(n), atol=1e-10)
    assert_allclose(P.T @ K @ P, np.diag(modes.frequencies**2),
                    atol=1e-10 * np.max(modes.frequencies**2))
    assert np.all(np.diff(modes.frequencies) >= 0)
    # each mode solves (K - w^2 M) phi = 0
    for r in range(n):
        residual = (K - modes.frequencies[r] ** 2 * M) @ P[:, r]
        assert np.max(np.abs(residual)) <= 1e-9 * np.max(np.abs(K))


def test_two_masses_three_springs_in_closed_form():
    """m - k - m between two walls, springs k: w^2 = k/m (in phase) and 3k/m (opposed)."""
    k, m = sp.symbols("k m", positive=True)
    modes = natural_modes(sp.Matrix([[m, 0], [0, m]]), sp.Matrix([[2 * k, -k], [-k, 2 * k]]))
    assert [sp.simplify(w**2) for w in modes.frequencies] == [k / m, 3 * k / m]
    assert modes.shapes == sp.Matrix([[1, 1], [1, -1]])
    # symbolic orthogonality
    P = sp.Matrix(modes.shapes)
    assert sp.simplify((P[:, 0].T * modes.mass * P[:, 1])[0]) == 0
    assert sp.simplify((P[:, 0].T * modes.stiffness * P[:, 1])[0]) == 0


def test_modal_superposition_equals_direct_integration():
    M, K = _random_system(7, 3)
    modes = natural_modes(M, K)
    q0, u0 = np.array([0.1, -0.2, 0.05]), np.array([0.0, 0.3, -0.1])
    t = np.linspace(0, 5, 11)
    Minv_K = np.linalg.solve(M, K)

    def rhs(_, y):
        return np.concatenate((y[3:], -Minv_K @ y[:3]))

    sol = ode.solve(rhs, (0.0, 5.0), np.concatenate((q0, u0)), method="dop853", rtol=1e-14,
                    atol=1e-16, t_eval=t)
    assert_allclose(modes.free_response(t, q0, u0), sol.y[:3], rtol=0, atol=1e-10)


def test_forced_response_by_modes_equals_direct_solution():
    M, K = _random_system(3, 4)
    modes = natural_modes(M, K)
    F = np.array([1.0, 0.0, -0.5, 0.2])
    w = np.linspace(0.05, 2.0, 37)
    assert_allclose(modes.harmonic_response(F, w), harmonic_response_direct(M, 0 * M, K, F, w),
                    rtol=1e-9)
    # proportional damping C = a M + b K has modal damping ratios (a/w + b w)/2
    a, b = 0.02, 0.01
    z = (a / modes.frequencies + b * modes.frequencies) / 2
    assert_allclose(modes.harmonic_response(F, w, z),
                    harmonic_response_direct(M, a * M + b * K, K, F, w), rtol=1e-9)


def test_modal_coordinates_invert_the_shapes():
    M, K = _random_system(11, 3)
    modes = natural_modes(M, K)
    q = np.array([0.3, -1.0, 2.0])
    assert_allclose(modes.shapes @ modes.modal_coordinates(q), q, rtol=1e-12)


def test_frequency_response_plot_draws_amplitude_and_phase(tmp_path):
    w = np.linspace(0.1, 3, 40)
    H = harmonic_response_direct([[1.0]], [[0.1]], [[1.0]], [1.0], w)
    ax_amp, ax_phase = plot_frequency_response(w, H, path=tmp_path / "frf.png")
    assert (tmp_path / "frf.png").stat().st_size > 0
    assert_allclose(ax_amp.lines[0].get_ydata(), np.abs(H[0]))
    assert_allclose(ax_phase.lines[0].get_ydata(), -np.unwrap(np.angle(H[0])))


@pytest.mark.parametrize("M, K, match", [
    ([[1.0, 0], [0, 1.0]], [[1.0]], "`stiffness` must be a 2x2 matrix"),
    ([[1.0, 0.5], [0.0, 1.0]], np.eye(2), "`mass` must be symmetric"),
    (np.eye(2), [[-1.0, 0], [0, 1.0]], "`stiffness` must be positive semi-definite"),
    (-np.eye(2), np.eye(2), "`mass` must be positive definite"),
    (sp.eye(3) * sp.Symbol("m"), sp.eye(3), "closed form for 2 degrees of freedom"),
])
def test_bad_matrices_are_refused(M, K, match):
    with pytest.raises(ArgumentError, match=match):
        natural_modes(M, K)


@pytest.mark.parametrize("scale", [1.0, 1e-15, 1e15])
def test_symmetry_is_decided_relative_to_the_size_of_the_matrix(scale):
    """K with an asymmetry of 1e-4 of its size is refused whatever the unit (it was accepted
    below 1e-12 in absolute value, i.e. for small units); a symmetric one is accepted."""
    M = scale * np.eye(2)
    K = scale * np.array([[2.0, -1.0], [-1.0, 2.0]])
    assert_allclose(natural_modes(M, K).frequencies, [1.0, math.sqrt(3.0)], rtol=1e-12)
    bad = K + scale * np.array([[0.0, 1e-4], [0.0, 0.0]])
    with pytest.raises(ArgumentError, match="`stiffness` must be symmetric"):
        natural_modes(M, bad)


def test_direct_response_at_an_undamped_natural_frequency_is_refused_clearly():
    """K - w^2 M singular without damping (w = 2 for k = 4, m = 1; w = 1 for the 2-dof chain):
    the steady amplitude is infinite: a named error, not numpy's 'Singular matrix'."""
    with pytest.raises(ArgumentError, match=r"`omega` = 2.0 is a natural frequency"):
        harmonic_response_direct([[1.0]], [[0.0]], [[4.0]], [1.0], [1.0, 2.0])
    with pytest.raises(ArgumentError, match=r"`omega` = 1.0 is a natural frequency"):
        harmonic_response_direct(np.eye(2), np.zeros((2, 2)), [[2.0, -1.0], [-1.0, 2.0]],
                                  [1.0, 0.0], [1.0])
    # with damping the same frequency has a finite response
    out = harmonic_response_direct([[1.0]], [[0.1]], [[4.0]], [1.0], [2.0])
    assert_allclose(out, [[1 / (0.2j)]], rtol=1e-14)
