"""Tests of rigidmech.vectors.points: bipoints, distances, coordinates, velocity, acceleration.

Independent references: closed forms of circular and polar motion (book, ch. 4 and 7.2:
v = r q' on the tangent, centripetal acceleration r q'^2), and the derivative of the
coordinates in R0 computed directly by sympy.
"""

import pytest
import sympy as sp

from rigidmech._core.errors import ArgumentError, ArgumentTypeError, FrameError
from rigidmech.vectors import Frame, Point, Vector, constants, coordinates, t

q, x = coordinates("q x")
r = constants("r", positive=True)


@pytest.fixture
def arm():
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    return R0, R1


def test_bipoints_and_distance():
    R0 = Frame("R0")
    A = R0.point("A", 1, 0, 0)
    B = R0.point("B", 4, 4, 0)
    assert B - A == 3 * R0.i + 4 * R0.j
    assert A - B == -(B - A)
    assert A.distance(B) == 5 and B.distance(A) == 5
    assert (A - A).is_zero
    C = A.moved("C", 2 * R0.k)
    assert C - A == 2 * R0.k
    assert (A + 2 * R0.k).position == C.position
    assert (C - 2 * R0.k).position == A.position
    # Chasles: AB + BC = AC
    assert (B - A) + (C - B) == C - A


def test_coordinates(arm):
    R0, R1 = arm
    P = R0.origin.moved("P", r * R1.i + 2 * R0.k)
    assert P.coordinates(R0) == sp.Matrix([r * sp.cos(q), r * sp.sin(q), 2])
    assert sp.simplify(P.coordinates(R1) - sp.Matrix([r, 0, 2])) == sp.zeros(3, 1)
    # with a moved origin: coordinates in a translated frame shift by the origin's
    T = R0.translated("T", R0.point("B", 1, 2, 3))
    assert P.coordinates(T) == P.coordinates(R0) - sp.Matrix([1, 2, 3])
    assert R0.point("A", 1, 2, 3).coordinates(R0) == sp.Matrix([1, 2, 3])
    assert R0.origin.coordinates(R0) == sp.zeros(3, 1)


def test_point_on_a_rotating_arm(arm):
    # circular motion of radius r (book, ch. 7.2): v = r q' j1, a = r q'' j1 - r q'^2 i1
    R0, R1 = arm
    A = R0.origin.moved("A", r * R1.i)
    qd, qdd = q.diff(t), q.diff(t, 2)
    assert A.velocity(R0) == r * qd * R1.j
    assert A.acceleration(R0).equals(r * qdd * R1.j - r * qd**2 * R1.i)
    assert A.velocity(R0).dot(A.velocity(R0)) == r**2 * qd**2  # |v| = r |q'|
    # attached to R1: at rest relative to R1
    assert A.velocity(R1).is_zero and A.acceleration(R1).is_zero
    # independent route: differentiate the coordinates in R0
    coords = A.coordinates(R0)
    assert sp.simplify(A.velocity(R0).components(R0) - coords.diff(t)) == sp.zeros(3, 1)
    assert sp.simplify(A.acceleration(R0).components(R0) - coords.diff(t, 2)) == sp.zeros(3, 1)


def test_point_sliding_on_a_rotating_arm(arm):
    # polar coordinates (book, ch. 4): v = x' i1 + x q' j1,
    # a = (x'' - x q'^2) i1 + (2 x' q' + x q'') j1
    R0, R1 = arm
    P = R0.origin.moved("P", x * R1.i)
    xd, qd = x.diff(t), q.diff(t)
    assert P.velocity(R0).equals(xd * R1.i + x * qd * R1.j)
    expected = (x.diff(t, 2) - x * qd**2) * R1.i + (2 * xd * qd + x * q.diff(t, 2)) * R1.j
    assert P.acceleration(R0).equals(expected)
    assert P.velocity(R1) == xd * R1.i


def test_velocity_relative_to_a_frame_with_a_moving_origin():
    R0 = Frame("R0")
    T = R0.translated("T", R0.point("B", x, 0, 0))
    P = R0.point("P", 1, 2, 0)  # at rest in R0
    assert P.velocity(R0).is_zero
    assert P.velocity(T) == -x.diff(t) * R0.i
    assert P.acceleration(T) == -x.diff(t, 2) * R0.i


def test_point_values(arm):
    R0, R1 = arm
    A = R0.point("A", 1, 2, 0)
    assert A.name == "A" and str(A) == "A" and A.root is R0
    assert A.position == R0.i + 2 * R0.j
    assert R0.origin.name == "O_R0" and R0.origin.position.is_zero
    assert repr(A) == "Point('A', position=R0.i + 2*R0.j)"
    assert repr(R0.origin) == "Point('O_R0', position=0)"
    assert repr(R0.origin + R0.i) == "Point('(O_R0 + ...)', position=R0.i)"
    a = sp.Symbol("a")
    B = R0.origin.moved("B", a * R1.i)
    assert B.subs(a, 2) == R0.origin.moved("B", 2 * R1.i)
    assert B.subs(a, 2).name == "B"


def test_point_equality_and_hash():
    A1 = Frame("R0").point("A", 1, 2, 0)
    A2 = Frame("R0").point("A", 1, 2, 0)
    assert A1 is not A2 and A1 == A2 and hash(A1) == hash(A2) and len({A1, A2}) == 1
    R0 = Frame("R0")
    assert R0.point("B", 1, 2, 0) != A1  # name is part of the value
    assert R0.point("A", 1, 2, 1) != A1
    assert Frame("S0").point("A", 1, 2, 0) != A1
    assert A1 != R0.i + 2 * R0.j


def test_points_are_immutable():
    A = Frame("R0").point("A", 1, 2, 0)
    with pytest.raises(AttributeError):
        A.name = "B"
    with pytest.raises(AttributeError):
        A.position = Vector.zero()
    with pytest.raises(AttributeError):
        A.mass = 1


def test_point_errors():
    R0, S0 = Frame("R0"), Frame("S0")
    A = R0.point("A", 1, 0, 0)
    with pytest.raises(TypeError, match=r"build points from a frame: R0.origin, "
                       r"R0.point\(name, x, y, z\)"):
        Point("A")
    with pytest.raises(ArgumentTypeError, match="`displacement` must be a Vector; got the "
                       "Point A. Use A - O_R0 for the bipoint"):
        R0.origin.moved("B", A)
    with pytest.raises(ArgumentTypeError, match="`displacement` must be a Vector; got tuple"):
        A.moved("B", (1, 0, 0))
    with pytest.raises(ArgumentTypeError, match=r"`other` must be a Point \(a Vector is not "
                       r"a Point: use A.moved\(name, vector\)\); got Vector"):
        A.distance(R0.i)
    with pytest.raises(ArgumentTypeError, match="`other` must be a Point; got int"):
        A.distance(3)
    with pytest.raises(ArgumentTypeError, match="points cannot be added; add a Vector to a "
                       "Point, or subtract two Points"):
        A + A
    with pytest.raises(TypeError):
        A + 1
    with pytest.raises(TypeError):
        A - 1
    with pytest.raises(FrameError, match="points O_S0 and A live in different frame trees"):
        A - S0.origin
    with pytest.raises(FrameError, match="the vector uses frame S0 of the tree rooted at S0; "
                       "point A lives in the tree rooted at R0"):
        A.moved("B", S0.i)
    with pytest.raises(FrameError, match="the vector uses frame S0"):
        A + S0.i
    with pytest.raises(ArgumentError, match="`name` must be a non-empty string; got ''"):
        A.moved("", R0.i)
    with pytest.raises(ArgumentTypeError, match="`frame` must be a Frame; got Point"):
        A.coordinates(A)
    with pytest.raises(ArgumentTypeError, match="`frame` must be a Frame; got str"):
        A.velocity("R0")
    with pytest.raises(FrameError, match="points O_S0 and A live in different frame trees"):
        A.coordinates(S0)
