"""Tests of rigidmech.vectors.geometry (lines, planes, distances) and
rigidmech.vectors.reference_change (changes of reference system), book ch. 2."""

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.vectors import Frame, coordinates
from rigidmech.vectors.geometry import (
    Line,
    Plane,
    angle,
    common_perpendicular,
    distance,
    intersection,
    is_orthogonal,
    is_parallel,
)
from rigidmech.vectors.reference_change import (
    affine_map,
    change_of_coordinates,
    common_axis_map,
    common_origin_map,
)

R0 = Frame("R0")
O = R0.origin
# A frame with rational direction cosines (3-4-5, 5-12-13) and a shifted origin: exact numbers.
Ra = R0.rotated("Ra", about=R0.k, angle=sp.atan(sp.Rational(4, 3)),
                origin=R0.point("Oa", 1, -2, 3))
Rb = Ra.rotated("Rb", about=Ra.i, angle=sp.atan(sp.Rational(5, 12)))

small = st.integers(min_value=-5, max_value=5)
triple = st.tuples(small, small, small)
nonzero_triple = triple.filter(lambda c: any(c))


def P(name, x, y, z, frame=R0):
    return frame.point(name, x, y, z)


# -- construction ------------------------------------------------------------------------------
def test_line_and_plane_constructors():
    A, B, C = P("A", 1, 0, 0), P("B", 0, 1, 0), P("C", 0, 0, 1)
    L = Line.through(A, B)
    assert L.point == A and L.direction == B - A
    assert L.contains(L.point_at(sp.Rational(7, 3)))
    plane = Plane.through(A, B, C)
    assert plane.equation(R0) == (1, 1, 1, -1)
    assert all(plane.contains(X) for X in (A, B, C))
    again = Plane.from_equation(R0, *plane.equation(R0))
    assert again.equation(R0) == (1, 1, 1, -1)
    assert again.point.coordinates(R0) == sp.Matrix([1, 1, 1]) / 3


def test_line_from_cartesian_equations():
    # x + y + z = 1 and x - y = 0: direction (1, 1, 1) ^ (1, -1, 0) = (1, 1, -2)
    L = Line.from_equations(R0, (1, 1, 1, -1), (1, -1, 0, 0))
    assert L.direction.equals(R0.vector(1, 1, -2))
    assert Plane.from_equation(R0, 1, 1, 1, -1).contains(L.point)
    assert Plane.from_equation(R0, 1, -1, 0, 0).contains(L.point)


def test_plane_equation_in_another_frame():
    # The plane z0 = 0 expressed in Ra (origin (1, -2, 3), rotated about k0): z_a = -3.
    plane = Plane(O, R0.k)
    a, b, c, d = plane.equation(Ra)
    assert (a, b, c, d) == (0, 0, 1, 3)


def test_value_semantics_and_repr():
    L1, L2 = Line(O, R0.i), Line(O, R0.i)
    assert L1 == L2 and hash(L1) == hash(L2) and L1 != Line(O, R0.j)
    assert repr(L1) == "Line(O_R0, R0.i)"
    assert repr(Plane(O, R0.k)) == "Plane(O_R0, R0.k)"
    assert Plane(O, R0.k) == Plane(O, R0.k)


def test_constructor_errors():
    A = P("A", 1, 2, 3)
    with pytest.raises(ArgumentError, match=r"`direction` must be a non-zero Vector to define "
                                            r"a line; got the zero vector"):
        Line(A, R0.i * 0)
    with pytest.raises(ArgumentError, match=r"`A` and `B` must be distinct points"):
        Line.through(A, P("B", 1, 2, 3))
    with pytest.raises(ArgumentError, match=r"`A`, `B`, `C` must be non-collinear points"):
        Plane.through(O, P("B", 1, 1, 1), P("C", 2, 2, 2))
    with pytest.raises(ArgumentError, match=r"`normal` must be a non-zero Vector"):
        Plane(A, R0.i * 0)
    with pytest.raises(ArgumentError, match=r"`a, b, c` must not all be zero"):
        Plane.from_equation(R0, 0, 0, 0, 1)
    with pytest.raises(ArgumentError, match=r"must hold the 4 coefficients \(a, b, c, d\)"):
        Line.from_equations(R0, (1, 0, 0), (0, 1, 0, 0))
    with pytest.raises(ArgumentTypeError, match=r"`point` must be a Point \(a Vector is not a "
                                                r"Point"):
        Line(R0.i, R0.j)
    with pytest.raises(ArgumentTypeError, match=r"`direction` must be a Vector; got tuple"):
        Line(O, (1, 0, 0))


# -- intersections -----------------------------------------------------------------------------
def test_line_plane_intersection():
    L = Line(P("A", 1, 2, 3), R0.vector(1, 1, 1))
    plane = Plane.from_equation(R0, 1, 0, 0, -4)  # x = 4
    I = intersection(plane, L, name="I")
    assert I.name == "I" and I.coordinates(R0) == sp.Matrix([4, 5, 6])


def test_plane_plane_intersection_is_a_line():
    p1 = Plane.from_equation(R0, 1, 2, -1, 3)
    p2 = Plane.from_equation(R0, 0, 1, 4, -2)
    L = intersection(p1, p2)
    assert p1.contains(L.point) and p2.contains(L.point)
    assert p1.contains(L.point_at(5)) and p2.contains(L.point_at(5))


def test_line_line_cases():
    L = Line(O, R0.i)
    secant = Line(P("A", 2, 3, 0), R0.j)
    assert intersection(L, secant).coordinates(R0) == sp.Matrix([2, 0, 0])
    assert intersection(L, Line(P("B", 0, 3, 0), R0.i)) is None  # strictly parallel
    assert intersection(L, Line(P("C", 0, 3, 1), R0.k)) is None  # skew
    with pytest.raises(ArgumentError, match=r"got two coincident lines"):
        intersection(L, Line(P("D", 5, 0, 0), -2 * R0.i))


def test_intersection_errors():
    with pytest.raises(ArgumentError, match=r"`a` and `b` must be non-parallel planes to intersect "
                                            r"in a line; got distinct parallel planes"):
        intersection(Plane(O, R0.k), Plane(P("A", 0, 0, 1), 2 * R0.k))
    with pytest.raises(ArgumentError, match=r"got the same plane"):
        intersection(Plane(O, R0.k), Plane(P("A", 1, 1, 0), -R0.k))
    with pytest.raises(ArgumentError, match=r"got a line parallel to the plane \(it lies in the "
                                            r"plane\)"):
        intersection(Line(O, R0.i), Plane(O, R0.k))
    with pytest.raises(ArgumentError, match=r"\(it does not meet the plane\)"):
        intersection(Line(P("A", 0, 0, 1), R0.i), Plane(O, R0.k))
    with pytest.raises(ArgumentTypeError, match=r"`b` must be a Line or Plane; got Point"):
        intersection(Line(O, R0.i), O)


def test_parallel_and_orthogonal():
    Lx, Ly = Line(O, R0.i), Line(P("A", 0, 0, 7), R0.j)
    Pz = Plane(O, R0.k)
    assert is_orthogonal(Lx, Ly) and not is_parallel(Lx, Ly)  # orthogonal without meeting
    assert is_parallel(Lx, Line(P("B", 1, 1, 1), -3 * R0.i))
    assert is_parallel(Lx, Pz) and not is_orthogonal(Lx, Pz)
    assert is_orthogonal(Line(O, R0.k), Pz)
    assert is_parallel(Pz, Plane(P("C", 0, 0, 1), R0.k))
    assert is_orthogonal(Pz, Plane(O, R0.i + R0.j))
    q = coordinates("q")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    assert is_orthogonal(Line(O, R1.i), Line(O, R1.j.express(R0)))
    with pytest.raises(ArgumentTypeError, match=r"`a` must be a Line or Plane; got Vector"):
        is_parallel(R0.i, Pz)


# -- distances ---------------------------------------------------------------------------------
def test_distances():
    A = P("A", 3, 4, 12)
    assert distance(A, O) == 13
    assert distance(Line(O, R0.k), A) == 5
    assert distance(A, Plane(O, R0.k)) == 12
    assert distance(Line(P("B", 0, 0, 1), R0.i), Plane(O, R0.k)) == 1  # parallel: constant
    assert distance(Line(O, R0.i + R0.k), Plane(O, R0.k)) == 0  # secant
    assert distance(Plane(O, R0.k), Plane(P("C", 0, 0, -2), R0.k)) == 2
    assert distance(Line(O, R0.i), Line(P("D", 0, 3, 4), R0.i)) == 5  # parallel lines


def test_common_perpendicular_feet_are_orthogonal():
    L1 = Line(P("A", 1, 0, 2), R0.vector(1, 2, 0))
    L2 = Line(P("B", 0, -1, 5), R0.vector(0, 1, 1))
    H1, H2 = common_perpendicular(L1, L2)
    assert L1.contains(H1) and L2.contains(H2)
    h = H2 - H1
    assert h.dot(L1.direction) == 0 and h.dot(L2.direction) == 0
    assert sp.simplify(h.magnitude() - distance(L1, L2)) == 0
    with pytest.raises(ArgumentError, match=r"`line1` and `line2` must not be parallel"):
        common_perpendicular(L1, Line(O, R0.vector(2, 4, 0)))


def test_angle():
    assert angle(R0.i, R0.i + R0.j) == sp.pi / 4
    assert angle(R0.i, -R0.i) == sp.pi
    with pytest.raises(ArgumentError, match=r"`v` must be a non-zero vector to have an angle"):
        angle(R0.i, R0.j * 0)


@settings(max_examples=25, deadline=None)
@given(cp=triple, ca=triple, cn=nonzero_triple)
def test_distance_point_plane_invariant_under_change_of_frame(cp, ca, cn):
    # Property: the distance does not depend on the frame the data are given in; the same
    # point and plane built from coordinates in Rb (rotated and shifted) and converted back.
    point_b, a_b = Rb.point("M", *cp), Rb.point("A", *ca)
    d_b = distance(point_b, Plane(a_b, Rb.vector(*cn)))
    point_0 = R0.point("M", *change_of_coordinates(cp, Rb, R0))
    a_0 = R0.point("A", *change_of_coordinates(ca, Rb, R0))
    n_0 = R0.vector(*Rb.vector(*cn).components(R0))
    assert sp.simplify(distance(point_0, Plane(a_0, n_0)) - d_b) == 0


# -- change of reference system ----------------------------------------------------------------
def test_change_of_coordinates_general():
    M = Rb.point("M", 1, 2, 3)
    x0 = change_of_coordinates((1, 2, 3), Rb, R0)
    assert x0 == M.coordinates(R0)
    assert change_of_coordinates(M, None, Rb) == sp.Matrix([1, 2, 3])
    assert change_of_coordinates(x0, R0, Rb) == sp.Matrix([1, 2, 3])
    with pytest.raises(ArgumentError, match=r"`point_or_coords` must hold 3 coordinates; got 2"):
        change_of_coordinates((1, 2), Rb, R0)
    with pytest.raises(ArgumentTypeError, match=r"`from_frame` must be a Frame; got NoneType"):
        change_of_coordinates((1, 2, 3), None, R0)


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_common_axis_map_matches_general_case(axis):
    th = coordinates("theta")
    a, b, c = sp.symbols("a b c", real=True)
    R1 = R0.rotated("R1", about=R0.basis[axis], angle=th, origin=R0.point("O1", a, b, c))
    M, t = common_axis_map("xyz"[axis], th, (a, b, c))
    Mg, tg = affine_map(R1, R0)
    assert sp.simplify(M - Mg) == sp.zeros(3, 3)
    assert sp.simplify(t - tg) == sp.zeros(3, 1)


def test_common_origin_map_matches_euler_frames():
    psi, theta, phi = coordinates("psi theta phi")
    R1 = R0.euler("R1", psi, theta, phi)
    M, t = common_origin_map(psi, theta, phi)
    Mg, tg = affine_map(R1, R0)
    assert sp.simplify(M - Mg) == sp.zeros(3, 3)
    assert t == tg == sp.zeros(3, 1)


def test_map_argument_errors():
    with pytest.raises(ArgumentError, match=r"`axis` must be 'x', 'y', 'z' or 0, 1, 2; got 'w'"):
        common_axis_map("w", 1)
    with pytest.raises(ArgumentError, match=r"`origin` must hold 3 coordinates; got 2"):
        common_axis_map("z", 1, (0, 0))
