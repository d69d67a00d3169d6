"""Textbook-style exercises of chapter 2 (the geometric space), with rigidmech.vectors.geometry.

Conventions (book, ch. 2): R0 = (O; i, j, k) is a direct orthonormal reference system,
coordinates (x, y, z) are relative to it; a plane is a x + b y + c z + d = 0 (coefficients
compared up to a common factor), a line is a point and a direction. Distances use
|n . AP| / |n| (point-plane), |AP ^ u| / |u| (point-line) and |(A2 - A1) . (u1 ^ u2)| / |u1 ^ u2|
(two skew lines). Expected values are worked out by hand in each case's comment.
"""

import pytest
import sympy as sp

from rigidmech.vectors import Frame
from rigidmech.vectors.geometry import (
    Line,
    Plane,
    angle,
    common_perpendicular,
    distance,
    intersection,
)
from rigidmech.vectors.reference_change import change_of_coordinates

R0 = Frame("R0")
V = R0.vector


def P(name, x, y, z):
    return R0.point(name, x, y, z)


def proportional(a, b):
    return sp.Matrix([a]).rank() == sp.Matrix([a, b]).rank() == 1


def plane_through_axes_intercepts():
    # 2.4.1: intercepts (1, 0, 0), (0, 2, 0), (0, 0, 3): x + y/2 + z/3 = 1 ~ 6x + 3y + 2z - 6.
    eq = Plane.through(P("A", 1, 0, 0), P("B", 0, 2, 0), P("C", 0, 0, 3)).equation(R0)
    return proportional(eq, (6, 3, 2, -6))


def angle_at_A():
    A, B, C = P("A", 1, 0, 0), P("B", 0, 1, 0), P("C", 0, 0, 1)
    return angle(B - A, C - A)


def skew_feet():
    # 2.2.4: L1 = (O, i), L2 = ((0, 1, 2), j + k). n = i ^ (j + k) = -j + k; H1 = O + l1 i,
    # H2 = A2 + l2 (j + k) with H1H2 . i = 0 -> l1 = 0 and H1H2 . (j + k) = 0 -> 3 + 2 l2 = 0.
    H1, H2 = common_perpendicular(Line(R0.origin, R0.i), Line(P("A2", 0, 1, 2), V(0, 1, 1)))
    return (tuple(H1.coordinates(R0)), tuple(H2.coordinates(R0)))


CASES = [
    # 2.1.3: A(1, 2, 3), B(4, 6, 15): sqrt(9 + 16 + 144) = 13.
    pytest.param(lambda: distance(P("A", 1, 2, 3), P("B", 4, 6, 15)), 13, id="2.1.3-distance"),
    # 2.1.4: A(1, 0, 0), B(0, 1, 0), C(0, 0, 1): equilateral triangle, angle (AB, AC) = pi/3.
    pytest.param(angle_at_A, sp.pi / 3, id="2.1.4-angle-of-bipoints"),
    # 2.4.1: plane through three points.
    pytest.param(plane_through_axes_intercepts, True, id="2.4.1-plane-through-three-points"),
    # 2.4.1: P(1, 2, 3) to 2x - y + 2z - 4 = 0: |2 - 2 + 6 - 4| / 3 = 2/3.
    pytest.param(lambda: distance(P("P", 1, 2, 3), Plane.from_equation(R0, 2, -1, 2, -4)),
                 sp.Rational(2, 3), id="2.4.1-distance-point-plane"),
    # 2.2.1: P(1, 1, 1) to the line through O directed by (1, 2, 2): |OP ^ u| / |u| =
    # |(0, -1, 1)| / 3 = sqrt(2)/3.
    pytest.param(lambda: distance(P("P", 1, 1, 1), Line(R0.origin, V(1, 2, 2))),
                 sp.sqrt(2) / 3, id="2.2.1-distance-point-line"),
    # 2.2.4: L1 = ((1, 0, 0), (1, 1, 0)), L2 = ((0, 0, 2), (0, 1, 1)): u1 ^ u2 = (1, -1, 1),
    # A2 - A1 = (-1, 0, 2), |(-1 + 0 + 2)| / sqrt(3) = 1/sqrt(3).
    pytest.param(lambda: distance(Line(P("A1", 1, 0, 0), V(1, 1, 0)),
                                  Line(P("A2", 0, 0, 2), V(0, 1, 1))),
                 1 / sp.sqrt(3), id="2.2.4-distance-skew-lines"),
    pytest.param(skew_feet, ((0, 0, 0), (0, -sp.Rational(1, 2), sp.Rational(1, 2))),
                 id="2.2.4-common-perpendicular"),
    # 2.2: line through (1, 2, 3) directed by (1, 1, 1) meets x = 4 at (4, 5, 6).
    pytest.param(lambda: tuple(intersection(Line(P("A", 1, 2, 3), V(1, 1, 1)),
                                            Plane.from_equation(R0, 1, 0, 0, -4)).coordinates(R0)),
                 (4, 5, 6), id="2.2-line-meets-plane"),
    # 2.4.2: x + y + z = 1 and x - y = 0: direction (1, 1, 1) ^ (1, -1, 0) = (1, 1, -2).
    pytest.param(lambda: proportional(tuple(Line.from_equations(R0, (1, 1, 1, -1), (1, -1, 0, 0))
                                            .direction.components(R0)), (1, 1, -2)),
                 True, id="2.4.2-line-of-two-planes"),
    # 2.5.2: R1 = R0 turned by pi/6 about k, origin O1(1, 2, 0); the point (2, 0, 0) of R1 is
    # (1 + 2 cos 30deg, 2 + 2 sin 30deg, 0) = (1 + sqrt(3), 3, 0) in R0.
    pytest.param(lambda: tuple(change_of_coordinates(
        (2, 0, 0), R0.rotated("R1", about=R0.k, angle=sp.pi / 6, origin=P("O1", 1, 2, 0)), R0)),
        (1 + sp.sqrt(3), 3, 0), id="2.5.2-common-axis"),
]


def same(got, expected):
    if isinstance(expected, tuple):
        return len(got) == len(expected) and all(map(same, got, expected))
    if isinstance(expected, bool):
        return got is expected
    return sp.simplify(sp.sympify(got) - expected) == 0


@pytest.mark.parametrize(("compute", "expected"), CASES)
def test_chapter_2(compute, expected):
    assert same(compute(), expected)
