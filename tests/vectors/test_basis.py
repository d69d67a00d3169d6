"""Tests of rigidmech.vectors.basis: linear dependence, arbitrary bases, metric (book, ch. 1)."""

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.vectors import Frame, constants, coordinates
from rigidmech.vectors.basis import Basis, double_cross, linear_dependence, linearly_independent

R0 = Frame("R0")
q = coordinates("q")
R1 = R0.rotated("R1", about=R0.k, angle=q)
# Rotations with rational direction cosines (3-4-5 and 5-12-13 triangles): exact and fast.
Rp = R0.rotated("Rp", about=R0.k, angle=sp.atan(sp.Rational(4, 3)))
Rq = Rp.rotated("Rq", about=Rp.i, angle=sp.atan(sp.Rational(5, 12)))

small = st.integers(min_value=-4, max_value=4)
triple = st.tuples(small, small, small)


def vec(c):
    return R0.vector(*c)


# -- linear dependence ------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("vectors", "expected"),
    [
        pytest.param((R0.i,), True, id="one-nonzero"),
        pytest.param((R0.i * 0,), False, id="one-zero"),
        pytest.param((R0.i, 2 * R0.i), False, id="two-collinear"),
        pytest.param((R0.i, R0.i + R0.j, R0.k), True, id="three-independent"),
        pytest.param((R0.i, R0.j, R0.i - 2 * R0.j), False, id="three-coplanar"),
        pytest.param((R0.i, R0.j, R0.k, R0.i), False, id="four-always-dependent"),
        pytest.param((R1.i, R1.j, R0.k), True, id="mixed-bases-symbolic"),
        pytest.param((R1.i, R0.i, R0.j), False, id="mixed-bases-coplanar"),
    ],
)
def test_linearly_independent(vectors, expected):
    assert linearly_independent(*vectors) is expected


def test_independence_is_generic_for_symbols():
    # det = a**2 - 1 is not identically zero: generically independent (documented answer),
    # dependent once a = 1 is substituted.
    a = sp.Symbol("a")
    u, v = a * R0.i + R0.j, R0.i + a * R0.j
    assert linearly_independent(u, v, R0.k)
    assert not linearly_independent(u.subs(a, 1), v.subs(a, 1), R0.k)


def test_independence_decided_by_simplify():
    # (cos^2 + sin^2 - 1) i is zero only after simplification.
    x = sp.Symbol("x")
    zero = (sp.cos(x) ** 2 + sp.sin(x) ** 2 - 1) * R0.i
    assert not linearly_independent(zero)


def test_linear_dependence_relation():
    vs = (R0.i + R0.j, R0.j - R0.k, R0.i + R0.k)
    lam = linear_dependence(*vs)
    assert lam is not None and any(x != 0 for x in lam)
    assert sum((c * v for c, v in zip(lam, vs, strict=True)), R0.i * 0).equals(R0.i * 0)
    assert linear_dependence(R0.i, R0.j, R0.k) is None


def test_linear_dependence_errors():
    with pytest.raises(ArgumentError, match=r"`vectors` must hold at least one Vector; got none"):
        linearly_independent()
    with pytest.raises(ArgumentTypeError,
                       match=r"`vectors` must be Vectors; got int at position 1"):
        linearly_independent(R0.i, 3)


# -- Basis ------------------------------------------------------------------------------------
def test_metric_components_and_products():
    b = Basis(R0.i, R0.i + R0.j, R0.j + R0.k)
    assert b.metric == sp.Matrix([[1, 1, 0], [1, 2, 1], [0, 1, 2]])
    u = 3 * R0.i - R0.j + 2 * R0.k
    cu = b.components_of(u)
    assert b.vector(*cu).equals(u)
    assert b.covariant_components_of(u) == b.metric * cu
    assert b.mixed_product == 1


def test_reciprocal_basis():
    b = Basis(R0.i, R0.i + R0.j, R0.j + R0.k)
    r = b.reciprocal()
    gram = sp.Matrix(3, 3, lambda m, n: sp.simplify(r[m].dot(b[n])))
    assert gram == sp.eye(3)
    assert sp.simplify(r.metric - b.metric.inv()) == sp.zeros(3, 3)


def nonsingular_bases():
    return st.tuples(triple, triple, triple).filter(
        lambda cs: sp.Matrix(cs).det() != 0)


@settings(max_examples=30, deadline=None)
@given(cs=nonsingular_bases(), cu=triple, cv=triple)
def test_metric_products_agree_with_orthonormal(cs, cu, cv):
    # Property (ch. 1.3.3, 1.4.2): products computed through the metric and the mixed product
    # equal the products of the vectors computed in the orthonormal basis of R0.
    b = Basis(*(vec(c) for c in cs))
    u, v = b.vector(*cu), b.vector(*cv)
    assert b.dot(cu, cv) == sp.expand(u.dot(v))
    assert b.vector(*b.cross(cu, cv)).equals(u.cross(v))
    assert b.components_of(u) == sp.Matrix(cu)


@settings(max_examples=30, deadline=None)
@given(cs=nonsingular_bases(), ds=nonsingular_bases(), cu=triple)
def test_change_of_basis_matrix(cs, ds, cu):
    # u (components in b) = P u (components in c)  (ch. 1.5.2)
    b = Basis(*(vec(c) for c in cs))
    c = Basis(*(vec(d) for d in ds))
    u = c.vector(*cu)
    P = b.change_of_basis_matrix(c)
    assert P * sp.Matrix(cu) == b.components_of(u)
    assert sp.simplify(P * c.change_of_basis_matrix(b)) == sp.eye(3)


def test_change_of_basis_matches_frame_dcm():
    P = Basis.of(R0).change_of_basis_matrix(Basis.of(R1))
    assert sp.simplify(P - R0.dcm(R1)) == sp.zeros(3, 3)


def test_orthonormal_and_direct():
    assert Basis.of(R1).is_orthonormal
    assert Basis(R1.i, R0.k, R1.j).is_orthonormal
    assert not Basis(R1.i, R0.k, R1.j).is_direct
    assert not Basis(2 * R0.i, R0.j, R0.k).is_orthonormal
    a = constants("a", positive=True)
    assert Basis(a * R0.i, R0.j, R0.k).is_direct
    assert not Basis(-a * R0.i, R0.j, R0.k).is_direct


def test_is_direct_undecidable_raises():
    b = sp.Symbol("b", real=True)
    with pytest.raises(ArgumentError, match=r"cannot decide whether the basis is direct: the sign "
                                            r"of its mixed product b is unknown"):
        _ = Basis(b * R0.i, R0.j, R0.k).is_direct


def test_coplanar_vectors_are_not_a_basis():
    with pytest.raises(ArgumentError, match=r"`e1, e2, e3` must be non-coplanar to form a basis; "
                                            r"got R0\.i, R0\.j, R0\.i \+ R0\.j, whose mixed"):
        Basis(R0.i, R0.j, R0.i + R0.j)
    with pytest.raises(ArgumentError, match="must be non-coplanar"):
        Basis(R1.i, R0.i, R0.j)


def test_basis_argument_errors():
    with pytest.raises(ArgumentTypeError, match=r"`e1, e2, e3` must be Vectors; got tuple at "
                                                r"position 2"):
        Basis(R0.i, R0.j, (0, 0, 1))
    b = Basis.of(R0)
    with pytest.raises(ArgumentError, match=r"`c_u` must have 3 components; got 2"):
        b.dot((1, 2), (1, 2, 3))
    with pytest.raises(ArgumentTypeError, match=r"`c_v` must be 3 numbers or sympy expressions"):
        b.cross((1, 2, 3), (1, None, 3))
    with pytest.raises(ArgumentTypeError, match=r"`other` must be a Basis; got Frame"):
        b.change_of_basis_matrix(R0)


def test_value_semantics_and_repr():
    b1 = Basis(R0.i, R0.j, 2 * R0.k)
    b2 = Basis(R0.i, R0.j, 2 * R0.k)
    assert b1 == b2 and hash(b1) == hash(b2)
    assert b1 != Basis.of(R0)
    assert repr(b1) == "Basis(R0.i, R0.j, 2*R0.k)"
    assert list(b1) == [R0.i, R0.j, 2 * R0.k]


@settings(max_examples=40, deadline=None)
@given(cu=triple, cv=triple, cw=triple)
def test_double_cross_property(cu, cv, cw):
    # ch. 1.4.6: u ^ (v ^ w) = (u . w) v - (u . v) w, on vectors mixing two bases.
    u, v, w = vec(cu), Rq.vector(*cv), Rp.vector(*cw)
    assert (double_cross(u, v, w) - u.cross(v.cross(w))).components(R0) == sp.zeros(3, 1)


def test_double_cross_errors():
    with pytest.raises(ArgumentTypeError, match=r"`u, v, w` must be Vectors; got int"):
        double_cross(R0.i, R0.j, 1)
