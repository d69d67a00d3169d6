"""Tests of rigidmech.vectors.vector: mixed-basis vectors, their algebra and derivatives.

Independent references: numpy products on components obtained with scipy's rotation
matrices (not with rigidmech's direction cosines), sympy differentiation of components in one
basis, and the vector identities of the book (ch. 1.3-1.4) as hypothesis properties.
Numeric tolerance: components are sums of a few products of integers up to 5 and sines and
cosines, so they are exact to ~1e-14; ``atol=1e-10`` leaves a wide margin.
"""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from rigidmech._core.errors import ArgumentError, ArgumentTypeError, FrameError
from rigidmech.vectors import Frame, Vector, coordinates, cross, dot, mixed, t

ATOL = 1e-10
q1, q2, q3 = coordinates("q1 q2 q3")
RNG = np.random.default_rng(1729)


def tree(a1, a2, a3):
    """R0; R1 = k by a1; R2 = R1.i by a2 (child of R1); R3 = R0.j by a3 (sibling of R1)."""
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=a1)
    R2 = R1.rotated("R2", about=R1.i, angle=a2)
    R3 = R0.rotated("R3", about=R0.j, angle=a3)
    return R0, R1, R2, R3


def scipy_matrices(a1, a2, a3):
    """Basis of each frame (columns) in R0, from scipy only."""
    return [np.eye(3), Rotation.from_euler("z", a1).as_matrix(),
            Rotation.from_euler("ZX", [a1, a2]).as_matrix(),
            Rotation.from_euler("y", a3).as_matrix()]


def as_float(matrix):
    return np.array(sp.Matrix(matrix).evalf(), dtype=float).ravel()


# -- strategies: vectors of numeric components in up to four bases of a numeric tree --------
angles = st.tuples(*[st.floats(-3.1, 3.1, allow_nan=False)] * 3)
part = st.tuples(st.integers(0, 3), st.lists(st.integers(-5, 5), min_size=3, max_size=3))
parts = st.lists(part, min_size=1, max_size=3)


def build(frames, spec):
    out = Vector.zero()
    for n, comps in spec:
        out = out + Vector.from_components(frames[n], comps)
    return out


def numeric_in_r0(mats, spec):
    return sum((mats[n] @ np.array(comps, dtype=float) for n, comps in spec), np.zeros(3))


SETTINGS = settings(max_examples=25, deadline=None)


@SETTINGS
@given(angles, parts, parts, parts)
def test_components_dot_cross_mixed_against_numpy(a, su, sv, sw):
    frames = tree(*(sp.Float(x) for x in a))
    mats = scipy_matrices(*a)
    u, v, w = (build(frames, s) for s in (su, sv, sw))
    nu, nv, nw = (numeric_in_r0(mats, s) for s in (su, sv, sw))
    for f, m in zip(frames, mats, strict=True):
        assert_allclose(as_float(u.components(f)), m.T @ nu, rtol=0, atol=ATOL)
    assert_allclose(float(u.dot(v)), nu @ nv, rtol=0, atol=ATOL)
    assert_allclose(float(dot(u, v)), nu @ nv, rtol=0, atol=ATOL)
    assert_allclose(as_float(u.cross(v).components(frames[0])), np.cross(nu, nv),
                    rtol=0, atol=ATOL)
    assert_allclose(as_float(cross(u, v).components(frames[2])),
                    mats[2].T @ np.cross(nu, nv), rtol=0, atol=ATOL)
    assert_allclose(float(mixed(u, v, w)), np.linalg.det(np.array([nu, nv, nw])),
                    rtol=0, atol=1e-8)  # determinant of entries up to ~15: 1e-8 absolute
    assert_allclose(float(u.magnitude()), np.linalg.norm(nu), rtol=0, atol=ATOL)


@SETTINGS
@given(angles, parts, parts, parts, st.integers(-4, 4), st.integers(-4, 4))
def test_vector_identities(a, su, sv, sw, alpha, beta):
    frames = tree(*(sp.Float(x) for x in a))
    R0 = frames[0]
    u, v, w = (build(frames, s) for s in (su, sv, sw))

    def close(x, y):
        assert (x - y).is_close(Vector.zero(), atol=1e-8, frame=R0) if isinstance(
            x, Vector) else abs(float(x - y)) < 1e-8

    # bilinearity of dot and cross
    close((alpha * u + beta * v).dot(w), alpha * u.dot(w) + beta * v.dot(w))
    close((alpha * u + beta * v).cross(w), alpha * u.cross(w) + beta * v.cross(w))
    # u . (u ^ v) = 0 and anti-symmetry
    close(u.dot(u.cross(v)), 0)
    close(u.cross(v), -v.cross(u))
    # double vector product: u ^ (v ^ w) = (u . w) v - (u . v) w (book, ch. 1.4)
    close(u.cross(v.cross(w)), u.dot(w) * v - u.dot(v) * w)
    # mixed product is invariant by circular permutation
    close(mixed(u, v, w), mixed(v, w, u))
    # components round trip through any two bases
    for fa in frames:
        for fb in frames:
            assert u.express(fa).express(fb).is_close(u, atol=1e-9, frame=fb)


def test_symbolic_components_and_express():
    R0, R1, R2, _ = tree(q1, q2, q3)
    u = 2 * R0.i + 3 * R1.j
    c, s = sp.cos(q1), sp.sin(q1)
    assert u.components(R0) == sp.Matrix([2 - 3 * s, 3 * c, 0])
    assert sp.simplify(u.components(R1) - sp.Matrix([2 * c, 2 * -s + 3, 0])) == sp.zeros(3, 1)
    assert u.express(R0) == Vector.from_components(R0, [2 - 3 * s, 3 * c, 0])
    assert u.express(R0).frames == (R0,)
    assert R1.i.express(R1) is R1.i
    assert (R1.i - R1.i).express(R0).is_zero
    assert set(u.frames) == {R0, R1}
    assert dict(u.parts) == {R0: (2, 0, 0), R1: (0, 3, 0)}
    # R2.k seen from R0: rotation k by q1 then i by q2
    assert R2.k.components(R0) == sp.Matrix([s * sp.sin(q2), -c * sp.sin(q2), sp.cos(q2)])


def test_symbolic_dot_cross_mixed_closed_forms():
    R0, R1, _, _ = tree(q1, q2, q3)
    assert R0.i.dot(R1.i) == sp.cos(q1)
    assert R0.i.dot(R1.j) == -sp.sin(q1)
    assert R0.k.dot(R1.i) == 0
    assert R0.i.cross(R0.j) == R0.k and R0.j.cross(R0.k) == R0.i and R0.k.cross(R0.i) == R0.j
    assert R0.k.cross(R1.i) == R1.j  # k is shared: k ^ i1 = j1
    assert R1.i.cross(R1.i).is_zero
    assert mixed(R0.i, R0.j, R0.k) == 1
    assert mixed(R1.i, R1.j, R0.k) == 1
    assert mixed(R0.i, R1.i, R0.k) == sp.sin(q1)  # i0.(i1 ^ k0) = -i0.j1 = sin q1
    assert (3 * R0.i + 4 * R0.j).magnitude() == 5
    assert (2 * R1.k).normalized() == R1.k
    assert dot(R0.i + R0.j, R0.j) == 1 and cross(R0.j, R0.k) == R0.i


def test_scalar_algebra():
    R0 = Frame("R0")
    a, b = sp.symbols("a b", real=True)
    u = a * R0.i + R0.k
    assert 2 * u == u * 2 == Vector.from_components(R0, [2 * a, 0, 2])
    assert u / 2 == Vector.from_components(R0, [a / 2, 0, sp.Rational(1, 2)])
    assert -u == Vector.from_components(R0, [-a, 0, -1])
    assert u - u == Vector.zero() and (u - u).is_zero
    assert 0 * u == Vector.zero()
    assert 1 * u is u
    assert u + 0 is u and 0 + u is u and u - 0 is u
    assert sum([R0.i, R0.j, R0.k]) == R0.vector(1, 1, 1)
    assert (u + Vector.zero()) is u and (Vector.zero() + u) is u
    assert b * (u + R0.j) == b * u + b * R0.j


# -- derivatives (book, ch. 3 and 9.2.3) ---------------------------------------------------
def test_derivation_formula():
    # d/dt|R0 u = d/dt|R1 u + omega(R1/R0) ^ u, for a vector mixing bases of R1, R2 and R3
    R0, R1, R2, R3 = tree(q1, q2, q3)
    a = coordinates("a")
    L = sp.Symbol("L", positive=True)
    u = a * R2.i + L * R1.j + q1 * R3.k
    for rel, via in [(R0, R1), (R0, R2), (R1, R3), (R3, R0)]:
        lhs = u.dt(rel)
        rhs = u.dt(via) + via.rotation_vector(rel).cross(u)
        assert lhs.equals(rhs, frame=rel), (rel, via)


@pytest.mark.parametrize("frame_index", [0, 1, 2, 3])
def test_dt_is_componentwise_derivative_in_that_frame(frame_index):
    frames = tree(q1, q2, q3)
    R0, R1, R2, R3 = frames
    f = frames[frame_index]
    a = coordinates("a")
    u = a * R2.i + 2 * R1.j + q1 * R3.k
    expected = sp.diff(u.components(f), t)
    assert sp.simplify(u.dt(f).components(f) - expected) == sp.zeros(3, 1)


def test_dt_closed_forms():
    R0, R1, _, _ = tree(q1, q2, q3)
    qd = q1.diff(t)
    assert R1.i.dt(R0) == qd * R1.j
    assert R1.j.dt(R0) == -qd * R1.i
    assert R1.k.dt(R0).is_zero
    assert R1.i.dt(R1).is_zero
    assert (q2 * R0.i).dt(R0) == q2.diff(t) * R0.i
    assert Vector.zero().dt(R0).is_zero


def test_partial_derivatives():
    R0, R1, R2, _ = tree(q1, q2, q3)
    qd = q1.diff(t)
    assert (qd * R1.j).diff(qd) == R1.j  # no basis depends on q1': frame may be omitted
    # the basis of the result is not part of the contract: compare symbolically
    assert R1.i.diff(q1, R0).equals(-sp.sin(q1) * R0.i + sp.cos(q1) * R0.j)
    assert R1.i.diff(q1, R0).equals(R1.j)
    assert (q2 * R1.i).diff(q2, R0) == R1.i  # R1 does not depend on q2: stays in R1
    assert R2.i.diff(q1, R1).is_zero  # R2 moves relative to R1 with q2 only
    for v in (R2.j, R2.k + q1 * R1.i):
        for q in (q1, q2):
            expected = sp.diff(v.components(R0), q)
            assert sp.simplify(v.diff(q, R0).components(R0) - expected) == sp.zeros(3, 1)
    # d/dt|R0 = sum over q of (du/dq|R0) q' (no explicit time): ch. 3.3
    v = R2.j
    total = v.diff(q1, R0) * q1.diff(t) + v.diff(q2, R0) * q2.diff(t)
    assert total.equals(v.dt(R0), frame=R0)


def test_partial_derivative_needs_a_frame_when_a_basis_depends_on_the_variable():
    R0, R1, R2, _ = tree(q1, q2, q3)
    with pytest.raises(FrameError, match=r"the basis of R1 depends on q1\(t\): pass `frame`"):
        R1.i.diff(q1)
    with pytest.raises(FrameError, match=r"the basis of R2 depends on q1\(t\)"):
        (q2 * R2.k).diff(q1)
    assert (q2 * R2.k).diff(q2, R2) == R2.k


# -- comparison, hashing, transforms ---------------------------------------------------------
def test_equality_is_structural_and_consistent_with_hash():
    R0, R1, _, _ = tree(q1, q2, q3)
    u = 2 * R0.i + 3 * R1.j
    v = 3 * R1.j + 2 * R0.i
    assert u == v and hash(u) == hash(v) and len({u, v}) == 1
    assert R0.i == R0.vector(1, 0, 0) and hash(R0.i) == hash(R0.vector(1, 0, 0))
    # same vector in another basis: not structurally equal, but symbolically equal
    assert R1.i != R1.i.express(R0)
    assert R1.i.equals(R1.i.express(R0))
    assert not R1.i.equals(R1.j)
    assert Vector.zero() == 0 and R0.i != 0 and R0.i != "R0.i"
    assert (R0.i * 1.0).is_close(R0.i * (1 + 1e-12))
    assert not R0.i.is_close(R0.j)
    assert Vector.zero().is_close(Vector.zero())


def test_transforms():
    R0 = Frame("R0")
    x = sp.Symbol("x")
    u = (sp.sin(x) ** 2 + sp.cos(x) ** 2) * R0.i + x * R0.j
    assert u.simplify() == R0.i + x * R0.j
    assert u.subs(x, 0) == R0.i
    assert (x * R0.i).xreplace({x: 2}) == 2 * R0.i
    assert (x * R0.i).applyfunc(lambda c: 0 * c).is_zero
    assert (x * R0.i).applyfunc(lambda c: c + 1) == R0.vector(x + 1, 1, 1)


def test_reprs_and_printing():
    R0, R1, _, _ = tree(q1, q2, q3)
    a, b = sp.symbols("a b")
    assert repr(Vector.zero()) == "0"
    assert repr(2 * R0.i - R0.k) == "2*R0.i - R0.k"
    assert repr(-R0.i) == "-R0.i"
    assert repr((a + b) * R0.i) == "(a + b)*R0.i"
    assert repr(2 * R1.i + q1 * R0.j) == "2*R1.i + q1(t)*R0.j"
    assert str(2 * R1.i + q1 * R0.j) == "2 i_R1 + q1(t) j_R0"
    assert str((a + b) * R0.k) == "(a + b) k_R0"
    # regression: _repr_latex_ raised AttributeError (sp.printing.latex is a function)
    latex = (2 * R1.i + (q1 + 1) * R0.j)._repr_latex_()
    assert isinstance(latex, str) and latex.startswith("$") and latex.endswith("$")
    assert r"\vec{i}_{R_{1}}" in latex and r"\left(" in latex
    assert sp.latex(R0.i - R0.k) == r"\vec{i}_{R_{0}} - \vec{k}_{R_{0}}"


def test_vectors_are_immutable():
    R0 = Frame("R0")
    u = 2 * R0.i
    with pytest.raises(AttributeError):
        u.parts = ()
    with pytest.raises(AttributeError):
        u.frames = ()
    with pytest.raises(AttributeError):
        u.x = 1
    assert u == 2 * R0.i


# -- errors ----------------------------------------------------------------------------------
def test_construction_errors():
    R0 = Frame("R0")
    with pytest.raises(TypeError, match=r"build a Vector from basis vectors"):
        Vector(1, 2, 3)
    with pytest.raises(ArgumentError, match=r"`components` must have 3 entries; got 2"):
        Vector.from_components(R0, [1, 2])
    with pytest.raises(ArgumentTypeError, match="`components` must be 3 numbers or sympy "
                       "expressions; got 5"):
        Vector.from_components(R0, 5)
    with pytest.raises(ArgumentTypeError, match="`components` must be scalars; got a matrix"):
        Vector.from_components(R0, [sp.Matrix([1, 2]), 0, 0])
    with pytest.raises(ArgumentTypeError, match="`frame` must be a Frame; got str"):
        Vector.from_components("R0", [1, 2, 3])
    with pytest.raises(ArgumentTypeError, match="`frame` must be a Frame; got NoneType"):
        R0.i.components(None)
    with pytest.raises(ArgumentTypeError, match="`frame` must be a Frame; got int"):
        R0.i.express(0)
    with pytest.raises(ArgumentTypeError, match="`frame` must be a Frame; got Vector"):
        R0.i.dt(R0.i)


def test_algebra_errors():
    R0 = Frame("R0")
    u, v = R0.i, R0.j
    with pytest.raises(ArgumentTypeError, match=r"the product of two vectors is ambiguous: "
                       r"use u.dot\(v\) for the scalar product and u.cross\(v\)"):
        u * v
    # regression: u / v raised a bare SympifyError
    with pytest.raises(ArgumentTypeError, match="`scalar` must be a number or a sympy "
                       r"expression; got a Vector \(a vector cannot be divided by a vector\)"):
        u / v
    with pytest.raises(TypeError):
        u / object()
    with pytest.raises(ArgumentError, match="`scalar` must be non-zero to divide a vector"):
        u / 0
    with pytest.raises(ArgumentError, match="cannot normalise the zero vector: it has no "
                       "direction"):
        Vector.zero().normalized()
    with pytest.raises(TypeError):
        u + 1
    with pytest.raises(TypeError):
        u * object()
    for call, name in [(lambda: u.dot(3), "other"), (lambda: u.cross((0, 0, 1)), "other"),
                       (lambda: dot(3, u), "u"), (lambda: cross(None, u), "u"),
                       (lambda: mixed(u, 1, v), "v"), (lambda: mixed(1, u, v), "u"),
                       (lambda: mixed(u, v, 1), "other"), (lambda: u.equals(1), "other"),
                       (lambda: u.is_close(1), "other")]:
        with pytest.raises(ArgumentTypeError, match=f"`{name}` must be a Vector; got "):
            call()


def test_is_close_needs_numbers():
    R0 = Frame("R0")
    x = sp.Symbol("x")
    with pytest.raises(ArgumentError, match="`is_close` needs numeric components; substitute "
                       "values first or use `equals`"):
        (x * R0.i).is_close(R0.i)


def test_frames_from_different_trees_meet_in_a_vector():
    R0, S0 = Frame("R0"), Frame("S0")
    with pytest.raises(FrameError, match="frames R0 and S0 belong to different trees"):
        (R0.i + S0.j).components(R0)
    with pytest.raises(FrameError, match="belong to different trees"):
        R0.i.dot(S0.i)


def test_float_zero_components_are_dropped():
    """Regression: sympy >= 1.13 has Float(0.0) != 0; float zeros must not survive as parts."""
    from rigidmech import Frame, Vector

    R0 = Frame("R0")
    assert Vector.from_components(R0, [0.0, 1.0, 0.0]) == 1.0 * R0.j
    assert (0.0 * R0.i).is_zero
    assert (1.0 * R0.i - 1.0 * R0.i).is_zero
