"""Tests of rigidmech.vectors.frames and _rotations: direction cosines and frame values.

Independent references: the book's explicit elementary basis changes (ch. 2.5.2), and
``scipy.spatial.transform.Rotation`` at random numeric angles. Convention: ``a.dcm(b)`` has the
basis vectors of ``b`` as columns expressed in ``a`` (components in a = C @ components in b),
which is scipy's ``Rotation.as_matrix()`` of the rotation taking a's basis to b's. Numeric
matrices have entries bounded by 1 computed from a handful of products of sines and cosines,
so they agree to a few ulps: ``atol=1e-12`` throughout.
"""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from rigidmech._core.errors import ArgumentError, ArgumentTypeError, FrameError
from rigidmech.vectors import Frame, Point, Vector, coordinates, t
from rigidmech.vectors._rotations import rotation_steps

ATOL = 1e-12  # entries of products of a few rotation matrices, each exact to ~1 ulp
q1, q2, q3 = coordinates("q1 q2 q3")
RNG = np.random.default_rng(20090101)


def numeric(matrix, values):
    """Float array of a sympy matrix at {coordinate: value}."""
    return np.array(sp.Matrix(matrix).xreplace(values).evalf(), dtype=float)


def random_angles(n=3):
    return RNG.uniform(-np.pi, np.pi, size=n)


# -- elementary basis changes (book, ch. 2.5.2) ---------------------------------------------
c, s = sp.cos(q1), sp.sin(q1)
ELEMENTARY = {
    "i": sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]]),
    "j": sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
    "k": sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
}


@pytest.mark.parametrize("axis", ["i", "j", "k"])
def test_elementary_rotation_matches_the_book(axis):
    # ch. 2.5.2: for psi about k0, i1 = cos i0 + sin j0, j1 = -sin i0 + cos j0 (columns).
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=getattr(R0, axis), angle=q1)
    assert R0.dcm(R1) == ELEMENTARY[axis]
    assert R1.dcm(R0) == ELEMENTARY[axis].T
    # the rotation axis is shared by both bases
    assert getattr(R1, axis).components(R0) == getattr(R0, axis).components(R0)


@pytest.mark.parametrize("axis", ["x", "y", "z"])
def test_elementary_rotation_against_scipy(axis):
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=getattr(R0, "ijk"["xyz".index(axis)]), angle=q1)
    for a in random_angles(4):
        expected = Rotation.from_euler(axis, a).as_matrix()
        assert_allclose(numeric(R0.dcm(R1), {q1: a}), expected, rtol=0, atol=ATOL)


def test_opposite_axis_is_the_opposite_angle():
    R0 = Frame("R0")
    assert R0.dcm(R0.rotated("R1", about=-R0.k, angle=q1)) == ELEMENTARY["k"].subs(q1, -q1)
    assert R0.dcm(R0.rotated("R1", about=3 * R0.k, angle=q1)) == ELEMENTARY["k"]
    assert R0.rotated("R1", about=-R0.k, angle=q1).angle == -q1


def test_same_axis_chain_is_merged_into_one_rotation():
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.k, angle=q2)
    R3 = R2.rotated("R3", about=R2.k, angle=q3)
    C = R0.dcm(R3)
    assert C[0, 0] == sp.cos(q1 + q2 + q3)
    assert C[1, 0] == sp.sin(q1 + q2 + q3)
    assert not C.has(sp.cos(q1))
    assert rotation_steps(R0, R3) == [(2, q1 + q2 + q3)]
    # and it is the product of the elementary matrices (independent: numpy product)
    for a in (random_angles() for _ in range(3)):
        product = (Rotation.from_euler("z", a[0]).as_matrix()
                   @ Rotation.from_euler("z", a[1]).as_matrix()
                   @ Rotation.from_euler("z", a[2]).as_matrix())
        assert_allclose(numeric(C, dict(zip((q1, q2, q3), a, strict=True))), product,
                        rtol=0, atol=ATOL)


def test_sibling_frames_merge_through_their_parent():
    # R1 and R2 both made from R0 about k: R1 -> R2 is one rotation by q2 - q1.
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R0.rotated("R2", about=R0.k, angle=q2)
    assert R1.dcm(R2)[0, 0] == sp.cos(q1 - q2)
    assert R1.dcm(R2) == ELEMENTARY["k"].subs(q1, q2 - q1)


def test_regression_merge_across_a_translated_frame():
    # A translated frame (zero rotation) between two rotations about i used to stop the
    # merge: the result was a product of factors instead of cos(q1 + q2).
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.i, angle=q1)
    T = R1.translated("T", R0.point("A", 1, 0, 0))
    R2 = T.rotated("R2", about=T.i, angle=q2)
    assert R0.dcm(R2)[1, 1] == sp.cos(q1 + q2)
    assert rotation_steps(R0, R2) == [(0, q1 + q2)]


def test_regression_merge_across_cancelling_angles():
    # k by q1 then k by -q1 cancel; the i rotations on either side must then merge.
    R0 = Frame("R0")
    Ra = R0.rotated("Ra", about=R0.i, angle=q3)
    Rb = Ra.rotated("Rb", about=Ra.k, angle=q1).rotated("Rc", about=Ra.k, angle=-q1)
    Rd = Rb.rotated("Rd", about=Rb.i, angle=q2)
    assert rotation_steps(R0, Rd) == [(0, q3 + q2)]
    assert R0.dcm(Rd) == ELEMENTARY["i"].subs(q1, q2 + q3)


def test_chain_about_different_axes_against_scipy():
    # k by q1, then new i by q2, then new j by q3: intrinsic Z-X-Y.
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.i, angle=q2)
    R3 = R2.rotated("R3", about=R2.j, angle=q3)
    for a in (random_angles() for _ in range(4)):
        values = dict(zip((q1, q2, q3), a, strict=True))
        expected = Rotation.from_euler("ZXY", a).as_matrix()
        assert_allclose(numeric(R0.dcm(R3), values), expected, rtol=0, atol=ATOL)
        assert_allclose(numeric(R3.dcm(R0), values), expected.T, rtol=0, atol=ATOL)
        # through the common ancestor R1: R2 -> R0 -> ... -> R3 via R1
        expected_23 = Rotation.from_euler("y", a[2]).as_matrix()
        assert_allclose(numeric(R2.dcm(R3), values), expected_23, rtol=0, atol=ATOL)


def test_cousin_frames_against_scipy():
    R0 = Frame("R0")
    A = R0.rotated("A", about=R0.k, angle=q1).rotated("A2", about=R0.k, angle=0)
    A = A.rotated("A3", about=A.j, angle=q2)
    B = R0.rotated("B", about=R0.i, angle=q3)
    for a in (random_angles() for _ in range(3)):
        values = dict(zip((q1, q2, q3), a, strict=True))
        rA = Rotation.from_euler("ZY", a[:2])
        rB = Rotation.from_euler("X", a[2])
        assert_allclose(numeric(A.dcm(B), values), (rA.inv() * rB).as_matrix(),
                        rtol=0, atol=ATOL)


@pytest.mark.parametrize(
    "components",
    [
        pytest.param((1, 2, 2), id="unit-1-2-2-over-3"),
        pytest.param((1, 1, 0), id="bisector-ij"),
        pytest.param((-3, 0, 4), id="minus-3-0-4"),
        pytest.param((sp.Rational(1, 2), -1, sp.sqrt(2)), id="irrational-norm"),
        pytest.param((0, 0, -2), id="minus-k-elementary"),
    ],
)
def test_rotation_about_a_fixed_axis_against_scipy(components):
    # Rodrigues' formula vs scipy's rotation vector angle * unit axis.
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.vector(*components), angle=q1)
    unit = np.array([float(x) for x in components])
    unit /= np.linalg.norm(unit)
    C = R0.dcm(R1)
    for a in random_angles(4):
        expected = Rotation.from_rotvec(a * unit).as_matrix()
        assert_allclose(numeric(C, {q1: a}), expected, rtol=0, atol=ATOL)
    # the axis is fixed in both frames (same components)
    axis = R0.vector(*components)
    assert sp.simplify(axis.components(R1) - axis.components(R0)) == sp.zeros(3, 1)


def test_fixed_axis_given_in_another_frame_fixed_relative_to_this_one():
    # the axis R1.i of a frame turned by a constant pi/3 is a fixed axis of R0
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=sp.pi / 3)
    R2 = R0.rotated("R2", about=R1.i, angle=q1)
    unit = np.array([0.5, np.sqrt(3) / 2, 0.0])
    for a in random_angles(3):
        assert_allclose(numeric(R0.dcm(R2), {q1: a}), Rotation.from_rotvec(a * unit).as_matrix(),
                        rtol=0, atol=ATOL)


def test_euler_angles_zxz_against_scipy():
    psi, theta, phi = coordinates("psi theta phi")
    R0 = Frame("R0")
    R = R0.euler("R", psi, theta, phi)
    assert (R.parent.name, R.parent.parent.name, R.parent.parent.parent) == (
        "R_theta", "R_psi", R0)
    C = R0.dcm(R)
    for a in (random_angles() for _ in range(5)):
        values = dict(zip((psi, theta, phi), a, strict=True))
        expected = Rotation.from_euler("ZXZ", a).as_matrix()  # intrinsic z-x-z
        got = numeric(C, values)
        assert_allclose(got, expected, rtol=0, atol=ATOL)
        # direct orthonormal basis: C^T C = I and det C = +1
        assert_allclose(got.T @ got, np.eye(3), rtol=0, atol=ATOL)
        assert_allclose(np.linalg.det(got), 1.0, rtol=0, atol=ATOL)
    # line of nodes u = R_psi.i = R_theta.i; k = (sin th sin psi, -sin th cos psi, cos th)
    assert R.parent.i.components(R0) == R.parent.parent.i.components(R0)
    k = R.k.components(R0)
    expected_k = sp.Matrix([sp.sin(theta) * sp.sin(psi), -sp.sin(theta) * sp.cos(psi),
                            sp.cos(theta)])
    assert sp.simplify(k - expected_k) == sp.zeros(3, 1)


def test_dcm_is_orthogonal_and_direct_symbolically():
    R0 = Frame("R0")
    R2 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R2.rotated("R2", about=R2.i, angle=q2)
    C = R0.dcm(R2)
    assert sp.simplify(C.T * C) == sp.eye(3)
    assert sp.simplify(C.det()) == 1
    assert R2.dcm(R0) == C.T
    assert R0.dcm(R0) == sp.eye(3)
    assert isinstance(C, sp.ImmutableMatrix)


# -- frame values -----------------------------------------------------------------------
def test_frame_structure_and_basis():
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    assert R0.name == "R0" and R0.parent is None and R0.root is R0
    assert R1.parent is R0 and R1.root is R0 and R1.angle == q1
    assert R0.angle == 0
    assert R1.basis == (R1.i, R1.j, R1.k)
    assert R1.i.components(R1) == sp.Matrix([1, 0, 0])
    assert R1.origin is R0.origin
    assert R0.vector(1, 2, 3).components(R0) == sp.Matrix([1, 2, 3])
    assert isinstance(R0.point("A", 1, 2, 3), Point)
    assert str(R1) == "R1"


def test_translated_frame_keeps_the_basis_and_moves_the_origin():
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    A = R0.point("A", 1, 2, 3)
    T = R1.translated("T", A)
    assert T.origin is A
    assert T.dcm(R1) == sp.eye(3)
    assert A.coordinates(T) == sp.zeros(3, 1)
    # O0 seen from T: minus OA in the basis of R1 (= R1.dcm(R0) @ (1, 2, 3), ch. 2.3.3)
    expected = -ELEMENTARY["k"].T * sp.Matrix([1, 2, 3])
    assert sp.simplify(R0.origin.coordinates(T) - expected) == sp.zeros(3, 1)
    R2 = R0.rotated("R2", about=R0.k, angle=q2, origin=A)
    assert R2.origin == A
    assert A.coordinates(R2) == sp.zeros(3, 1)


def test_frame_equality_is_structural_and_consistent_with_hash():
    a = Frame("R0").rotated("R1", about=Frame("R0").k, angle=q1)
    b = Frame("R0").rotated("R1", about=Frame("R0").k, angle=q1)
    assert a is not b and a == b and hash(a) == hash(b)
    assert len({a, b}) == 1
    R0 = Frame("R0")
    assert R0.rotated("R1", about=R0.k, angle=q2) != a
    assert R0.rotated("R1", about=R0.i, angle=q1) != a
    assert R0.rotated("R9", about=R0.k, angle=q1) != a
    assert R0.rotated("R1", about=R0.k, angle=q1, origin=R0.point("A", 1, 0, 0)) != a
    assert Frame("R0") != Frame("S0")
    assert R0 != "R0"


def test_frame_reprs():
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    assert repr(R0) == "Frame('R0')"
    assert repr(R1) == "R0.rotated('R1', about=R0.k, angle=q1(t))"
    assert repr(R0.rotated("R2", about=-R0.j, angle=q2)) == (
        "R0.rotated('R2', about=R0.j, angle=-q2(t))")
    assert repr(R0.rotated("G", about=R0.i + R0.j, angle=q1)) == (
        "<Frame 'G': general rotation from 'R0'>")


def test_regression_frame_repr_shows_a_moved_origin():
    # the origin is part of the value: two unequal frames used to print the same, and a
    # translated frame printed as a rotation by 0
    R0 = Frame("R0")
    A = R0.point("A", 1, 0, 0)
    assert repr(R0.translated("T", A)) == "R0.translated('T', A)"
    assert repr(R0.rotated("R1", about=R0.k, angle=q1, origin=A)) == (
        "R0.rotated('R1', about=R0.k, angle=q1(t), origin=A)")
    assert repr(R0.rotated("G", about=R0.i + R0.j, angle=q1, origin=A)) == (
        "<Frame 'G': general rotation from 'R0', origin=A>")
    T = R0.translated("T", A)
    assert repr(T.rotated("R2", about=T.i, angle=q2)) == "T.rotated('R2', about=T.i, angle=q2(t))"


def test_frames_are_immutable():
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    with pytest.raises(AttributeError):
        R1.name = "other"
    with pytest.raises(AttributeError):
        R1.origin = R0.origin
    with pytest.raises(AttributeError):
        R1.colour = "red"


# -- errors ------------------------------------------------------------------------------
def test_about_must_be_a_vector():
    R0 = Frame("R0")
    with pytest.raises(ArgumentTypeError, match=r"`about` must be a Vector \(for example R0.k\); "
                       r"got tuple"):
        R0.rotated("R1", about=(0, 0, 1), angle=q1)
    with pytest.raises(TypeError):  # also a builtin TypeError
        R0.rotated("R1", about="k", angle=q1)


def test_about_must_be_non_zero():
    R0 = Frame("R0")
    with pytest.raises(FrameError, match="`about` must be a non-zero vector; got the zero"):
        R0.rotated("R1", about=Vector.zero(), angle=q1)
    with pytest.raises(ValueError, match="non-zero"):
        R0.rotated("R1", about=0 * R0.k, angle=q1)


@pytest.mark.parametrize(
    "make_axis",
    [
        pytest.param(lambda R0, R1: R1.i, id="axis-of-a-moving-frame"),
        pytest.param(lambda R0, R1: q2 * R0.k, id="coordinate-length"),
        pytest.param(lambda R0, R1: R0.i + t * R0.k, id="explicit-time"),
    ],
)
def test_about_must_be_fixed(make_axis):
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    with pytest.raises(FrameError, match="`about` must be a fixed axis of R0; got .* which "
                       "moves relative to R0. Chain two rotations instead."):
        R0.rotated("R2", about=make_axis(R0, R1), angle=q2)


def test_frames_from_different_trees():
    R0, S0 = Frame("R0"), Frame("S0")
    S1 = S0.rotated("S1", about=S0.k, angle=q1)
    msg = r"frames R0 and S1 belong to different trees \(roots R0 and S0\)"
    with pytest.raises(FrameError, match=msg):
        R0.dcm(S1)
    with pytest.raises(FrameError, match="belong to different trees"):
        R0.rotated("R1", about=S1.k, angle=q2)
    with pytest.raises(FrameError, match="belong to different trees"):
        S1.rotation_vector(R0)
    with pytest.raises(FrameError, match="`origin` belongs to the tree of S0, not R0"):
        R0.translated("T", S0.point("A", 1, 0, 0))


def test_origin_must_be_a_point():
    R0 = Frame("R0")
    with pytest.raises(ArgumentTypeError, match="`origin` must be a Point; got Vector. For a "
                       r"position vector v use R0.origin.moved\(name, v\)"):
        R0.translated("T", R0.i)
    with pytest.raises(ArgumentTypeError, match="`origin` must be a Point; got tuple"):
        R0.rotated("R1", about=R0.k, angle=q1, origin=(1, 0, 0))


def test_angle_and_name_and_dcm_argument_checks():
    R0 = Frame("R0")
    with pytest.raises(ArgumentTypeError, match="`angle` must be a number or a sympy "
                       "expression; got list"):  # regression: was "unhashable type"
        R0.rotated("R1", about=R0.k, angle=[1, 2])
    with pytest.raises(ArgumentTypeError, match="`angle` must be .*; got object"):
        R0.rotated("R1", about=R0.k, angle=object())
    with pytest.raises(ArgumentTypeError, match="`angle` must be .*; got Vector"):
        R0.euler("R", q1, R0.i, q2)
    with pytest.raises(ArgumentError, match="`name` must be a non-empty string; got ''"):
        Frame("")
    with pytest.raises(ArgumentError, match="`name` must be a non-empty string; got None"):
        R0.rotated(None, about=R0.k, angle=q1)
    with pytest.raises(ArgumentTypeError, match="`other` must be a Frame; got str"):
        R0.dcm("R0")
