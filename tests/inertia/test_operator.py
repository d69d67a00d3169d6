"""InertiaOperator: construction, validation, change of basis, Huygens, principal axes,
associativity, comparison and printing (book, ch. 15)."""

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from rigidmech._core.errors import ArgumentError, ArgumentTypeError, FrameError
from rigidmech.inertia import InertiaOperator, block, cylinder, disk, principal_axes, rod
from rigidmech.vectors import Frame, coordinates, mixed

m, L, R = sp.symbols("m L R", positive=True)
R0 = Frame("R0")

# Tolerances: every numeric route below is a handful of float operations on O(1)..O(100)
# values, so agreement is to ~1e-13 relative; 1e-9 leaves a wide margin and would still
# catch any wrong term (which is O(1) relative).
RTOL = 1e-9


def numeric(J):
    return np.array(J.matrix.tolist(), dtype=float)


def random_operator(draw_moments, draw_angles, frame=R0, at=None):
    """A valid numeric operator: R diag(principal) R^T with principal moments obeying the
    triangle inequalities (second moments s1, s2, s3 >= 0)."""
    s = draw_moments
    principal = np.array([s[1] + s[2], s[2] + s[0], s[0] + s[1]])
    rot = Rotation.from_euler("ZXZ", draw_angles).as_matrix()
    return InertiaOperator.from_matrix(rot @ np.diag(principal) @ rot.T, frame=frame, at=at)


second_moments = st.lists(st.floats(0.0, 10.0), min_size=3, max_size=3)
angles = st.lists(st.floats(-math.pi, math.pi), min_size=3, max_size=3)
coords = st.lists(st.floats(-5.0, 5.0), min_size=3, max_size=3)


# -- construction and validation --------------------------------------------------------------
def test_layout_and_attributes():
    A, B, C, D, E, F = sp.symbols("A B C D E F")
    J = InertiaOperator.from_products(A, B, C, D, E, F, frame=R0, at=R0.origin)
    assert J.matrix == sp.ImmutableMatrix([[A, -F, -E], [-F, B, -D], [-E, -D, C]])
    assert (J.A, J.B, J.C, J.D, J.E, J.F) == (A, B, C, D, E, F)
    assert J.frame == R0 and J.at == R0.origin
    assert isinstance(J.matrix, sp.ImmutableMatrix)
    assert J == InertiaOperator.from_matrix(J.matrix, frame=R0)


def test_immutable():
    J = InertiaOperator.from_products(1, 1, 1, frame=R0)
    with pytest.raises(AttributeError):
        J.foo = 1
    with pytest.raises(AttributeError):
        J.A = 2


def test_numeric_roundoff_asymmetry_is_averaged():
    J = InertiaOperator.from_matrix([[2, -1 + 1e-14, 0], [-1, 2, 0], [0, 0, 3]], frame=R0)
    assert J.matrix[0, 1] == J.matrix[1, 0]
    assert_allclose(float(J.F), 1.0, rtol=1e-12)


def test_symbolic_symmetry_up_to_expansion():
    a = sp.Symbol("a")
    J = InertiaOperator.from_matrix([[2, -a * (a + 1), 0], [-(a**2 + a), 2, 0], [0, 0, 3]],
                                    frame=R0)
    assert J.matrix.is_symmetric()


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda: InertiaOperator.from_matrix([[2, -2, 0], [-3, 3, 0], [0, 0, 4]], frame=R0),
         ArgumentError, r"^`matrix` must be symmetric; got F=2 above the diagonal and F=3 "
                        r"below\.$"),
        (lambda: InertiaOperator.from_matrix([[2, 0, -1], [0, 3, 0], [0, 0, 4]], frame=R0),
         ArgumentError, r"got E=1 above the diagonal and E=0 below"),
        (lambda: InertiaOperator.from_matrix(
            [[2, 0, 0], [0, 3, -sp.Symbol("a")], [0, -sp.Symbol("b"), 4]], frame=R0),
         ArgumentError, r"got D=a above the diagonal and D=b below"),
        (lambda: InertiaOperator.from_matrix([[1, 0], [0, 1]], frame=R0), ArgumentError,
         r"`matrix` must be 3x3; got shape \(2, 2\)"),
        (lambda: InertiaOperator.from_matrix("abc", frame=R0), ArgumentTypeError,
         r"`matrix` must be a 3x3 array or sympy Matrix; got str"),
        (lambda: InertiaOperator.from_products(-1, 1, 1, frame=R0), ArgumentError,
         r"^`A` must be >= 0; got -1\.$"),
        (lambda: InertiaOperator.from_products(5, 1, 1, frame=R0), ArgumentError,
         r"^`A` must be <= B \+ C \(triangle inequality of the moments of inertia, ch\. "
         r"15\.3\.2\); got A=5, B=1, C=1\.$"),
        (lambda: InertiaOperator.from_products(1, 1, 5, frame=R0), ArgumentError,
         r"`C` must be <= A \+ B"),
        (lambda: InertiaOperator.from_products(2, 2, 1, F=1, frame=R0), ArgumentError,
         r"the products of inertia `D`, `E`, `F` are too large for the moments A, B, C.*"
         r"got principal moments 1, 1, 3\."),
        (lambda: InertiaOperator.from_matrix([[1, 0, 0], [0, -1, 0], [0, 0, 1]], frame=R0),
         ArgumentError, r"`matrix` must have non-negative moments of inertia on its "
                        r"diagonal; got B=-1\."),
        (lambda: InertiaOperator.from_matrix([[1, 0, 0], [0, 1, 0], [0, 0, 3]], frame=R0),
         ArgumentError, r"the moment C of `matrix` must be <= A \+ B"),
        (lambda: InertiaOperator.from_matrix([[1, -5, 0], [-5, 1, 0], [0, 0, 1]], frame=R0),
         ArgumentError, r"`matrix` is not the operator of inertia of any body"),
        (lambda: InertiaOperator.from_products(-m, 1, 1, frame=R0), ArgumentError,
         r"`A` must be >= 0; got -m"),
        (lambda: InertiaOperator.from_products(1, 1, 1, frame="R0"), ArgumentTypeError,
         r"`frame` must be a Frame; got str"),
        (lambda: InertiaOperator.from_products(1, 1, 1, frame=R0, at=R0.i), ArgumentTypeError,
         r"`at` must be a Point"),
        (lambda: InertiaOperator.from_products(1, 1, 1, frame=R0, at=Frame("S0").origin),
         FrameError, r"`at` lives in the frame tree rooted at S0"),
        (lambda: InertiaOperator.from_products([1], 1, 1, frame=R0), ArgumentTypeError,
         r"`A` must be a"),
        (lambda: InertiaOperator(), TypeError, r"build an InertiaOperator with"),
    ],
)
def test_construction_errors(call, error, match):
    with pytest.raises(error, match=match):
        call()


def test_symbolic_checks_use_assumptions_only():
    k = sp.Symbol("k")  # sign unknown: accepted
    assert InertiaOperator.from_products(k, k, k, F=k, frame=R0).F == k


# -- apply, moment about an axis ---------------------------------------------------------------
@settings(max_examples=25, deadline=None)
@given(second_moments, angles, coords)
def test_apply_and_moment_about_match_numpy(s, ang, direction):
    J = random_operator(s, ang)
    u = np.array(direction)
    vec = R0.vector(*direction)
    assert_allclose(np.array(J.apply(vec).components(R0), dtype=float).ravel(),
                    numeric(J) @ u, rtol=RTOL, atol=1e-9)
    if np.linalg.norm(u) > 1e-3:
        assert_allclose(float(J.moment_about(vec)), u @ numeric(J) @ u / (u @ u),
                        rtol=RTOL, atol=1e-9)


def test_moment_about_an_axis_of_another_basis():
    q = sp.Symbol("q")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    J = rod(m, L, axis=R0.i)
    got = J.moment_about(R1.i)  # ch. 15.3.4: I = A a^2 + B b^2 + C c^2 - 2 (D bc + E ca + F ab)
    assert sp.simplify(got - m * L**2 / 12 * sp.sin(q) ** 2) == 0


def test_apply_and_moment_about_errors():
    J = InertiaOperator.from_products(1, 1, 1, frame=R0)
    with pytest.raises(ArgumentError, match=r"`axis` must be a non-zero vector; got the zero"):
        J.moment_about(0 * R0.i)
    with pytest.raises(ArgumentTypeError, match=r"`axis` must be a Vector; got tuple"):
        J.moment_about((1, 0, 0))
    with pytest.raises(ArgumentTypeError, match=r"`vector` must be a Vector; got int"):
        J.apply(1)


# -- change of basis (ch. 15.2.4) ------------------------------------------------------------
ROTATIONS = [
    pytest.param(lambda R: R.rotated("R1", about=R.k, angle=0.7),
                 Rotation.from_euler("Z", 0.7), id="about-k"),
    pytest.param(lambda R: R.rotated("R1", about=R.j, angle=-1.1),
                 Rotation.from_euler("Y", -1.1), id="about-j"),
    pytest.param(lambda R: (lambda R1: R1.rotated("R2", about=R1.i, angle=0.3))(
        R.rotated("R1", about=R.k, angle=0.7)), Rotation.from_euler("ZX", [0.7, 0.3]),
        id="two-steps"),
    pytest.param(lambda R: R.rotated("R1", about=R.k, angle=0.7).rotated(
        "R2", about=R.i, angle=0.3), Rotation.from_euler("zx", [0.7, 0.3]),
        id="two-steps-fixed-axes"),
    pytest.param(lambda R: R.euler("R3", 0.4, 0.5, 0.6),
                 Rotation.from_euler("ZXZ", [0.4, 0.5, 0.6]), id="euler"),
    pytest.param(lambda R: R.rotated("R4", about=R.vector(1, 2, 3), angle=0.4),
                 Rotation.from_rotvec(0.4 * np.array([1, 2, 3]) / math.sqrt(14)),
                 id="general-axis"),
]


@pytest.mark.parametrize(("make_frame", "rotation"), ROTATIONS)
def test_in_basis_matches_numpy(make_frame, rotation):
    J = InertiaOperator.from_products(4, 5, 6, D=0.5, E=-0.25, F=1, frame=R0)
    new = make_frame(R0)
    P = rotation.as_matrix()  # columns: the new basis vectors in R0
    got = np.array(J.in_basis(new).matrix.evalf().tolist(), dtype=float)
    assert_allclose(got, P.T @ numeric(J) @ P, rtol=RTOL, atol=1e-12)
    back = J.in_basis(new).in_basis(R0)
    assert back.is_close(J, rtol=RTOL, atol=1e-12)
    assert J.in_basis(new).at == J.at


def test_in_basis_keeps_an_operator_of_revolution_exactly():
    q = coordinates("q")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    J = cylinder(m, R, L, axis=R0.k)
    assert J.in_basis(R1).matrix == J.matrix
    assert J.in_basis(R1).frame == R1


def test_in_basis_symbolic_round_trip():
    q1, q2 = coordinates("q1 q2")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.i, angle=q2)
    A, B, C, D, E, F = sp.symbols("A B C D E F")
    J = InertiaOperator.from_products(A, B, C, D, E, F, frame=R0)
    assert J.in_basis(R2).in_basis(R0).equals(J)
    assert J.in_basis(R2).matrix.is_symmetric()
    assert J.components(R0) == J.matrix


def test_in_basis_other_tree_is_an_error():
    with pytest.raises(FrameError, match="different trees"):
        InertiaOperator.from_products(1, 1, 1, frame=R0).in_basis(Frame("S0"))


# -- Huygens (ch. 15.2.2) -----------------------------------------------------------------------
@settings(max_examples=25, deadline=None)
@given(second_moments, angles, coords, coords, coords, st.floats(0.1, 10.0))
def test_huygens_through_any_point(s, ang, g, a, b, mass):
    G, A, B = R0.point("G", *g), R0.point("A", *a), R0.point("B", *b)
    JG = random_operator(s, ang, at=G)
    JA = JG.moved(A, mass=mass, centre=G)
    via_A = JA.moved(B, mass=mass, centre=G)
    direct = JG.moved(B, mass=mass, centre=G)
    # round-off is relative to the largest operator met on the way
    scale = max(float(np.max(np.abs(numeric(J)))) for J in (JG, JA, direct))
    assert via_A.is_close(direct, rtol=RTOL, atol=1e-9 * scale)
    assert direct.moved(G, mass=mass, centre=G).is_close(JG, rtol=RTOL, atol=1e-9 * scale)


@settings(max_examples=25, deadline=None)
@given(second_moments, angles, coords, coords, st.floats(0.1, 10.0))
def test_parallel_axis_theorem(s, ang, g, a, mass):
    # I_Delta(A) = I_Delta(G) + m d^2, d the distance between the parallel axes (ch. 15.3.4)
    G, A = R0.point("G", *g), R0.point("A", *a)
    JG = random_operator(s, ang, at=G)
    JA = JG.moved(A, mass=mass, centre=G)
    d2 = (g[0] - a[0]) ** 2 + (g[1] - a[1]) ** 2
    expected = float(JG.C) + mass * d2
    assert_allclose(float(JA.moment_about(R0.k)), expected, rtol=RTOL, atol=1e-9)


def test_huygens_symbolic_rod_about_its_end():
    G = R0.point("G", L / 2, 0, 0)
    J = rod(m, L, axis=R0.i, centre=G).moved(R0.origin, mass=m, centre=G)
    assert J.matrix == sp.ImmutableMatrix(sp.diag(0, m * L**2 / 3, m * L**2 / 3))
    assert J.at == R0.origin


def test_huygens_products_of_inertia():
    # a point mass at (x, y, z): F = m x y, E = m z x, D = m y z (ch. 15.2.2)
    x, y, z = sp.symbols("x y z")
    P = R0.point("P", x, y, z)
    J = InertiaOperator.from_products(0, 0, 0, frame=R0, at=P).moved(R0.origin, mass=m,
                                                                     centre=P)
    assert (J.D, J.E, J.F) == (m * y * z, m * z * x, m * x * y)
    assert sp.expand(J.A - m * (y**2 + z**2)) == 0


def test_moved_errors():
    G = R0.point("G", 1, 0, 0)
    J = InertiaOperator.from_products(0, 1, 1, frame=R0, at=R0.origin)
    with pytest.raises(ArgumentError, match=r"`mass` must be >= 0; got -2\."):
        J.moved(G, mass=-2, centre=G)
    with pytest.raises(ArgumentError, match=r"`mass` and `centre` do not fit this operator at "
                                            r"O_R0.*Check the mass and the mass centre\."):
        J.moved(G, mass=5, centre=G)
    with pytest.raises(ArgumentTypeError, match=r"`to` must be a Point"):
        J.moved(R0.i, mass=1, centre=G)
    with pytest.raises(ArgumentTypeError, match=r"`centre` must be a Point"):
        J.moved(G, mass=1, centre=None)


# -- principal axes (ch. 15.2.3) ----------------------------------------------------------------
@settings(max_examples=25, deadline=None)
@given(second_moments, angles)
def test_principal_axes_match_eigh(s, ang):
    J = random_operator(s, ang)
    moments, axes = J.principal_axes()
    values = numeric(J)
    assert_allclose(moments, np.linalg.eigvalsh(values), rtol=RTOL, atol=1e-9)
    scale = max(1.0, float(np.max(np.abs(values))))
    for lam, ax in zip(moments, axes, strict=True):
        v = np.array(ax.components(R0), dtype=float).ravel()
        assert_allclose(values @ v, lam * v, atol=1e-9 * scale)
    assert_allclose(float(mixed(*axes)), 1.0, rtol=1e-12)  # a direct orthonormal basis


def test_principal_axes_diagonal_is_exact():
    J = cylinder(m, R, L, axis=R0.i)
    assert J.principal_axes() == ((m * R**2 / 2, J.B, J.C), R0.basis)


def test_principal_axes_one_product_symbolic():
    A, B, F = sp.symbols("A B F", positive=True)
    J = InertiaOperator.from_products(A, B, A + B, F=F, frame=R0)
    moments, axes = J.principal_axes()
    assert axes[2] == R0.k and moments[2] == A + B
    for lam, ax in zip(moments[:2], axes[:2], strict=True):
        residual = (J.apply(ax) - lam * ax).express(R0)
        vals = {A: 2.0, B: 3.5, F: 0.7}  # J u - lambda u vanishes: checked at numbers
        num = np.array(residual.components(R0).subs(vals).evalf(), dtype=float)
        assert_allclose(num.ravel(), 0.0, atol=1e-12)
    assert sp.simplify(moments[0] + moments[1] - A - B) == 0


def test_principal_axes_general_symbolic_is_an_error():
    A, D, F = sp.symbols("A D F")
    J = InertiaOperator.from_products(A, A, A, D=D, F=F, frame=R0)
    with pytest.raises(ArgumentError, match=r"more than one non-zero product of inertia and "
                                            r"symbolic entries.*\(`subs`\)"):
        J.principal_axes()
    moments = principal_axes(J.subs({A: 3, D: 1, F: 1}).matrix, R0).moments
    assert_allclose(moments, [3 - math.sqrt(2), 3, 3 + math.sqrt(2)], rtol=1e-12)


# -- associativity (ch. 15.4.4) and scalars -------------------------------------------------------
def test_addition_of_parts_at_a_common_point_in_different_bases():
    q = sp.Symbol("q")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    J0 = InertiaOperator.from_products(1, 2, 3, frame=R0)
    J1 = InertiaOperator.from_products(4, 4, 5, frame=R1)
    total = J0 + J1
    assert total.frame == R0
    assert total.matrix == sp.ImmutableMatrix(sp.diag(5, 6, 8))
    assert sum([J0, J1]) == total
    assert (total - J1).matrix == J0.matrix


def test_addition_at_different_points_is_an_error():
    J0 = InertiaOperator.from_products(1, 1, 1, frame=R0)
    J1 = InertiaOperator.from_products(1, 1, 1, frame=R0, at=R0.point("A", 1, 0, 0))
    with pytest.raises(ArgumentError, match=r"operators of inertia add only at a common point "
                                            r"\(ch\. 15\.4\.4\); got one at O_R0 and one at A"):
        J0 + J1
    with pytest.raises(ArgumentError, match=r"subtract only at a common point"):
        J0 - J1
    # same position, another name: a common point
    same = InertiaOperator.from_products(1, 1, 1, frame=R0, at=R0.point("O", 0, 0, 0))
    assert (J0 + same).A == 2


def test_removing_too_much_is_an_error():
    J0 = InertiaOperator.from_products(1, 1, 1, frame=R0)
    with pytest.raises(ArgumentError, match=r"`other`"):
        J0 - 2 * J0


def test_scalar_multiplication():
    J = InertiaOperator.from_products(1, 2, 3, frame=R0)
    assert (2 * J).matrix == 2 * J.matrix
    assert (J * m).C == 3 * m
    assert (J / 2).A == sp.Rational(1, 2)
    with pytest.raises(ArgumentError, match=r"`scalar` must be >= 0; got -1"):
        J * -1
    with pytest.raises(ArgumentError, match=r"`scalar` must be non-zero"):
        J / 0
    with pytest.raises(TypeError):
        J * R0.i
    with pytest.raises(TypeError):
        J + 1


# -- comparison and printing -----------------------------------------------------------------------
def test_eq_hash_structural():
    J1 = InertiaOperator.from_products(1, 2, 3, frame=R0)
    J2 = InertiaOperator.from_products(1, 2, 3, frame=R0)
    J3 = InertiaOperator.from_products(1, 2, 3, frame=R0, at=R0.point("A", 0, 0, 1))
    assert J1 == J2 and hash(J1) == hash(J2)
    assert J1 != J3
    assert len({J1, J2, J3}) == 2
    assert J1 != "J1"


def test_equals_and_is_close():
    x = sp.Symbol("x")
    J = InertiaOperator.from_products(1, 1, 1, frame=R0)
    K = InertiaOperator.from_products(sp.sin(x) ** 2 + sp.cos(x) ** 2, 1, 1, frame=R0)
    assert J.equals(K) and J != K
    assert K.simplify() == J
    assert not J.equals(J.moved(R0.point("A", 1, 0, 0), mass=0, centre=R0.origin))
    assert J.is_close(J * 1.0)
    assert not J.is_close(J * 1.1)
    with pytest.raises(ArgumentError, match=r"`is_close` needs numeric entries"):
        J.is_close(K.subs(x, sp.Symbol("y")) * m)
    with pytest.raises(ArgumentTypeError, match=r"`other` must be an InertiaOperator"):
        J.is_close(1)
    with pytest.raises(ArgumentTypeError, match=r"`other` must be an InertiaOperator"):
        J.equals(1)


def test_repr_str_latex():
    G = R0.point("G", 1, 0, 0)
    J = InertiaOperator.from_products(m, 2 * m, 3 * m, F=m / 2, frame=R0, at=G)
    assert repr(J) == "InertiaOperator.from_products(m, 2*m, 3*m, F=m/2, frame=R0, at=G)"
    assert str(J) == "J(G) in (R0): [m, -m/2, 0; -m/2, 2*m, 0; 0, 0, 3*m]"
    latex = sp.latex(J)
    assert latex.startswith(r"\mathcal{J}_{G} = \begin{bmatrix} m & - \frac{m}{2} & 0")
    assert latex.endswith(r"_{(\vec{i}_{R_{0}}, \vec{j}_{R_{0}}, \vec{k}_{R_{0}})}")
    assert J._repr_latex_() == f"$\\displaystyle {latex}$"
    assert repr(disk(1, 2, axis=R0.k)) == (
        "InertiaOperator.from_products(1, 1, 2, frame=R0, at=O_R0)")


def test_block_operator_from_repr_round_trip():
    J = block(12, 1, 2, 3, frame=R0)
    assert eval(repr(J), {"InertiaOperator": InertiaOperator, "R0": R0,
                          "O_R0": R0.origin}) == J


@pytest.mark.parametrize(
    ("s", "b"),
    [([0.0, 9.316005037897453e-284, 0.0], [0.0, 0.0, 1.0]),
     ([0.0, 0.0, 0.0], [0.0, 2.5, 6.77513616983262e-199])],
)
def test_moving_back_to_the_centre_tolerates_cancellation(s, b):
    # regression (found by hypothesis): a nearly-zero operator at G, moved to B and back; the
    # round-off tolerance must be relative to the operator at B, not to the near-zero result
    G, B = R0.origin, R0.point("B", *b)
    JG = random_operator(s, [0.0, 0.0, 0.0], at=G)
    back = JG.moved(B, mass=3.0, centre=G).moved(G, mass=3.0, centre=G)
    assert back.is_close(JG, rtol=RTOL, atol=1e-12)


def test_principal_axes_of_a_float_diagonal_matrix_are_sorted():
    # floats always go through eigh (0.0 is not a structural zero in sympy >= 1.13)
    J = InertiaOperator.from_matrix(np.diag([3.0, 1.0, 2.0]), frame=R0)
    moments, axes = J.principal_axes()
    assert moments == (1.0, 2.0, 3.0)
    assert_allclose(np.array(axes[0].components(R0), dtype=float).ravel() ** 2, [0, 1, 0])
    assert_allclose(float(mixed(*axes)), 1.0, rtol=1e-12)
