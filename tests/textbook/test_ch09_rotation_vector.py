"""Book ch. 9 (kinematics of rigid body): the instantaneous vector of rotation.

Each case is one way to locate a body relative to R0 (ch. 9.1.2): an elementary rotation, a
rotation about a fixed axis, Euler angles z-x-z, a chain about different axes, sibling frames.
For each, omega(R/R0) is checked by two routes independent of rigidmech:

* numerically: along a smooth trajectory q(t), the skew matrix C^T dC/dt of the direction
  cosines C(t) = R0.dcm(R) differentiated by finite differences (ch. 9.2.3: dk/dt = omega ^ k
  for every basis vector k of R);
* symbolically: sympy.physics.vector (``orient_axis``, ``orient_body_fixed`` and
  ``ang_vel_in``); the difference simplifies to zero.

and the algebra of ch. 9.3: inverse motions omega(R0/R) = -omega(R/R0) (9.3.2) and composition
omega(2/0) = omega(2/1) + omega(1/0) (9.3.1).
"""

import itertools

import numpy as np
import pytest
import sympy as sp
import sympy.physics.vector as spv
from numpy.testing import assert_allclose

from rigidmech.vectors import Frame, coordinates, t

q1, q2, q3 = coordinates("q1 q2 q3")
Q = (q1, q2, q3)
T = spv.dynamicsymbols._t
D1, D2, D3 = spv.dynamicsymbols("q1 q2 q3")

# Smooth trajectory: q_n(t) = a + b sin(c t + d), all derivatives of order 1 (scale ~1).
TRAJECTORY = {
    q1: 0.3 + 0.8 * sp.sin(1.3 * t + 0.2),
    q2: -0.5 + 0.6 * sp.sin(0.7 * t + 1.1),
    q3: 1.1 + 0.9 * sp.sin(1.9 * t - 0.4),
}
TIMES = (0.0, 0.37, 1.9, 4.2)
H = 1e-3
# 4th-order central differences: truncation ~ H^4 |C^(5)| / 30 ~ 1e-13 with derivatives of
# order 1-10, rounding ~ eps / H ~ 1e-13; atol=1e-8 is a wide, safe margin.
FD_ATOL = 1e-8


def on_trajectory(expr):
    """A float function of time: expr with q(t) replaced by the trajectory."""
    return sp.lambdify(t, sp.Matrix(expr).subs(TRAJECTORY).doit(), "numpy")


def vee(skew):
    return np.array([skew[2, 1], skew[0, 2], skew[1, 0]])


def to_ours(expr):
    """sympy.physics.vector dynamicsymbols -> rigidmech coordinates."""
    rule = {}
    for d, q in zip((D1, D2, D3), Q, strict=True):
        rule[d.diff(T)] = q.diff(t)
        rule[d] = q
    return expr.xreplace(rule)


# -- the cases: (rigidmech frames, sympy.physics.vector frames) ---------------------------
def elementary():
    R0 = Frame("R0")
    N = spv.ReferenceFrame("N")
    B = N.orientnew("B", "Axis", (D1, N.y))
    return R0, R0.rotated("R", about=R0.j, angle=q1), N, B


def fixed_axis():
    # rotation about the fixed axis (1, 2, 2)/3 of R0 (ch. 9.4.1), Rodrigues in rigidmech
    R0 = Frame("R0")
    N = spv.ReferenceFrame("N")
    B = spv.ReferenceFrame("B")
    B.orient_axis(N, N.x + 2 * N.y + 2 * N.z, D1)
    return R0, R0.rotated("R", about=R0.vector(1, 2, 2), angle=q1), N, B


def euler():
    # precession q1 about k0, nutation q2 about u, spin q3 about k (ch. 9.1.2)
    R0 = Frame("R0")
    N = spv.ReferenceFrame("N")
    B = spv.ReferenceFrame("B")
    B.orient_body_fixed(N, (D1, D2, D3), "ZXZ")
    return R0, R0.euler("R", q1, q2, q3), N, B


def chain_zxy():
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.i, angle=q2)
    N = spv.ReferenceFrame("N")
    B = spv.ReferenceFrame("B")
    B.orient_body_fixed(N, (D1, D2, D3), "ZXY")
    return R0, R2.rotated("R", about=R2.j, angle=q3), N, B


def siblings():
    # omega(B/A) where A and B are both made from a common root: not parent and child
    root = Frame("root")
    A = root.rotated("A", about=root.k, angle=q1)
    B = root.rotated("B", about=root.i, angle=q2).rotated("R", about=root.i, angle=q3)
    N = spv.ReferenceFrame("N")
    NA = N.orientnew("NA", "Axis", (D1, N.z))
    NB = N.orientnew("NB", "Axis", (D2 + D3, N.x))
    return A, B, NA, NB


CASES = [
    pytest.param(elementary, id="elementary-about-j"),
    pytest.param(fixed_axis, id="fixed-axis-rodrigues"),
    pytest.param(euler, id="euler-zxz"),
    pytest.param(chain_zxy, id="chain-z-x-y"),
    pytest.param(siblings, id="sibling-frames"),
]


@pytest.mark.parametrize("case", CASES)
def test_rotation_vector_against_finite_differences(case):
    R0, R, _, _ = case()
    C = on_trajectory(R0.dcm(R))
    w = R.rotation_vector(R0)
    w_in_R = on_trajectory(w.components(R))
    w_in_R0 = on_trajectory(w.components(R0))
    for time in TIMES:
        c = np.asarray(C(time), dtype=float)
        dc = (-np.asarray(C(time + 2 * H), dtype=float) + 8 * np.asarray(C(time + H), dtype=float)
              - 8 * np.asarray(C(time - H), dtype=float)
              + np.asarray(C(time - 2 * H), dtype=float)) / (12 * H)
        # ch. 9.2.3: in the basis of R, skew(omega) = C^T C'; in the basis of R0, C' C^T
        assert_allclose(np.asarray(w_in_R(time), dtype=float).ravel(), vee(c.T @ dc),
                        rtol=0, atol=FD_ATOL)
        assert_allclose(np.asarray(w_in_R0(time), dtype=float).ravel(), vee(dc @ c.T),
                        rtol=0, atol=FD_ATOL)


@pytest.mark.parametrize("case", CASES)
def test_rotation_vector_against_sympy_physics_vector(case):
    R0, R, N, B = case()
    expected = to_ours(B.ang_vel_in(N).to_matrix(B))
    got = R.rotation_vector(R0).components(R)
    assert sp.simplify(got - expected) == sp.zeros(3, 1)


@pytest.mark.parametrize("case", CASES)
def test_inverse_motion(case):
    # ch. 9.3.2: omega(R0/R) = -omega(R/R0)
    R0, R, _, _ = case()
    assert R0.rotation_vector(R).equals(-R.rotation_vector(R0))


def test_euler_angles_in_the_book_form():
    # ch. 9.1.2: omega = psi' k0 + theta' u + phi' k, with u the line of nodes
    psi, theta, phi = Q
    R0 = Frame("R0")
    R = R0.euler("R", psi, theta, phi)
    R_psi, R_theta = R.parent.parent, R.parent
    w = R.rotation_vector(R0)
    assert w == psi.diff(t) * R_psi.k + theta.diff(t) * R_psi.i + phi.diff(t) * R.k
    assert R_psi.k == R_psi.k and R_theta.i.components(R0) == R_psi.i.components(R0)
    # components in the body basis (classical kinematic equations of Euler)
    pd, td, fd = (x.diff(t) for x in Q)
    expected = sp.Matrix([pd * sp.sin(theta) * sp.sin(phi) + td * sp.cos(phi),
                          pd * sp.sin(theta) * sp.cos(phi) - td * sp.sin(phi),
                          pd * sp.cos(theta) + fd])
    assert sp.simplify(w.components(R) - expected) == sp.zeros(3, 1)


def test_composition_of_rotation_vectors():
    # ch. 9.3.1: omega(3/0) = omega(3/2) + omega(2/1) + omega(1/0), along any frames of a tree
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.i, angle=q2)
    R3 = R0.rotated("R3", about=R0.vector(0, 3, 4), angle=q3)  # another branch
    # symbolically along the chain R0 -> R1 -> R2
    assert R2.rotation_vector(R0).equals(R2.rotation_vector(R1) + R1.rotation_vector(R0))
    # every ordered triple of distinct frames (24), up and down the chain and across branches,
    # at random values of (q, q'): components of a few products of sines and cosines with
    # rates of order 1, exact to ~1e-15, hence atol=1e-12
    rng = np.random.default_rng(93)
    for a, b, c in itertools.permutations((R0, R1, R2, R3), 3):
        values = {}
        for q in Q:
            values[q.diff(t)] = sp.Float(rng.uniform(-2, 2))
            values[q] = sp.Float(rng.uniform(-np.pi, np.pi))
        lhs = c.rotation_vector(a).components(a).xreplace(values)
        rhs = (c.rotation_vector(b) + b.rotation_vector(a)).components(a).xreplace(values)
        assert_allclose(np.array(lhs.evalf(), dtype=float), np.array(rhs.evalf(), dtype=float),
                        rtol=0, atol=1e-12, err_msg=f"{a}, {b}, {c}")


def test_elementary_closed_forms():
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.k, angle=q2)
    assert R1.rotation_vector(R0) == q1.diff(t) * R1.k
    assert R0.rotation_vector(R1) == -q1.diff(t) * R0.k
    assert R2.rotation_vector(R0) == (q1.diff(t) + q2.diff(t)) * R2.k
    assert R0.rotation_vector(R0).is_zero
    assert R0.rotated("C", about=R0.k, angle=sp.pi / 3).rotation_vector(R0).is_zero


def test_velocity_of_a_point_of_a_body_rotating_about_a_fixed_axis():
    # ch. 9.4.1: v(M) = omega ^ OM for M attached to the body, O on the axis
    R0 = Frame("R0")
    R = R0.rotated("R", about=R0.vector(1, 2, 2), angle=q1)
    M = R0.origin.moved("M", 2 * R.i - R.k)
    w = R.rotation_vector(R0)
    assert w.equals(q1.diff(t) * R0.vector(1, 2, 2) / 3, frame=R0)
    assert M.velocity(R0).equals(w.cross(M - R0.origin), frame=R0)
