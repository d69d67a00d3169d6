"""Textbook-style exercises of chapter 4 (elementary concepts on curves), with
rigidmech.vectors.curves.

Conventions (book, ch. 4): a curve is r(s) in R0 = (O; i, j, k); T = dr/dsigma is the unit
tangent (sigma the curvilinear abscissa), dT/dsigma = N / rho defines the principal normal N and
the radius of curvature rho = 1/kappa, B = T ^ N, and the torsion tau is defined by
dB/dsigma = -tau N (positive for a right-handed helix). Expected values are the classical closed
forms written out in each case's comment.
"""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

from rigidmech.vectors import Frame
from rigidmech.vectors.curves import Curve, frenet_numeric

R0 = Frame("R0")
s = sp.Symbol("s", real=True)
a, b, c, R = sp.symbols("a b c R", positive=True)


def curve(x, y, z):
    return Curve(R0.vector(x, y, z), s, R0)


HELIX = curve(a * sp.cos(s), a * sp.sin(s), b * s)
CIRCLE = curve(R * sp.cos(s), R * sp.sin(s), 0)
ELLIPSE = curve(3 * sp.cos(s), 2 * sp.sin(s), 0)
CYCLOID = curve(s - sp.sin(s), 1 - sp.cos(s), 0)  # rolling circle of radius 1
CATENARY = curve(s, c * sp.cosh(s / c), 0)
CUBIC = curve(s, s**2, s**3)

CASES = [
    # 4.3-4.4: circular helix r = a cos s i + a sin s j + b s k: kappa = a/(a^2 + b^2),
    # tau = b/(a^2 + b^2), one turn has length 2 pi sqrt(a^2 + b^2).
    pytest.param(lambda: HELIX.curvature(), a / (a**2 + b**2), id="4.3-helix-curvature"),
    pytest.param(lambda: HELIX.torsion(), b / (a**2 + b**2), id="4.4-helix-torsion"),
    pytest.param(lambda: HELIX.arc_length(0, 2 * sp.pi), 2 * sp.pi * sp.sqrt(a**2 + b**2),
                 id="4.2-helix-turn-length"),
    # 4.3: circle of radius R: rho = R, plane curve: tau = 0; N points to the centre.
    pytest.param(lambda: CIRCLE.radius_of_curvature(), R, id="4.3-circle-radius"),
    pytest.param(lambda: CIRCLE.torsion(), 0, id="4.4-plane-curve-torsion"),
    pytest.param(lambda: tuple(CIRCLE.normal().components(R0)), (-sp.cos(s), -sp.sin(s), 0),
                 id="4.3-circle-normal-to-centre"),
    # 4.3: parabola y = x^2 (x = s): kappa = |y''| / (1 + y'^2)^(3/2) = 2 / (1 + 4 s^2)^(3/2).
    pytest.param(lambda: curve(s, s**2, 0).curvature(), 2 / (1 + 4 * s**2) ** sp.Rational(3, 2),
                 id="4.3-parabola-curvature"),
    # 4.3: ellipse x = 3 cos s, y = 2 sin s: kappa = a/b^2 = 3/4 at the end of the major axis,
    # b/a^2 = 2/9 at the end of the minor axis.
    pytest.param(lambda: ELLIPSE.curvature(at=0), sp.Rational(3, 4), id="4.3-ellipse-vertex-a"),
    pytest.param(lambda: ELLIPSE.curvature(at=sp.pi / 2), sp.Rational(2, 9),
                 id="4.3-ellipse-vertex-b"),
    # 4.2-4.3: cycloid of a unit circle: an arch has length 8, and rho = 4 |sin(s/2)| = 4 at
    # the top (s = pi).
    pytest.param(lambda: CYCLOID.arc_length(0, 2 * sp.pi, method="numeric"), 8,
                 id="4.2-cycloid-arch-length"),
    pytest.param(lambda: CYCLOID.radius_of_curvature(at=sp.pi), 4, id="4.3-cycloid-top-radius"),
    # 4.2-4.3: catenary y = c cosh(x/c): arc length from the vertex c sinh(x/c), radius of
    # curvature c cosh^2(x/c).
    pytest.param(lambda: CATENARY.curvilinear_abscissa(), c * sp.sinh(s / c),
                 id="4.2-catenary-abscissa"),
    pytest.param(lambda: CATENARY.radius_of_curvature(), c * sp.cosh(s / c) ** 2,
                 id="4.3-catenary-radius"),
    # 4.4: twisted cubic (s, s^2, s^3): r' ^ r'' = (6s^2, -6s, 2), (r', r'', r''') = 12:
    # tau = 12 / (36 s^4 + 36 s^2 + 4) = 3 / (9 s^4 + 9 s^2 + 1); kappa(0) = 2.
    pytest.param(lambda: CUBIC.torsion(), 3 / (9 * s**4 + 9 * s**2 + 1),
                 id="4.4-twisted-cubic-torsion"),
    pytest.param(lambda: CUBIC.curvature(at=0), 2, id="4.3-twisted-cubic-curvature-at-0"),
]


def same(got, expected):
    if isinstance(expected, tuple):
        return len(got) == len(expected) and all(map(same, got, expected))
    got = sp.sympify(got)
    if isinstance(got, sp.Float):  # numeric quadrature: asked for rtol 1e-12
        return abs(float(got) - float(expected)) <= 1e-11 * abs(float(expected))
    return sp.simplify(got - expected) == 0


@pytest.mark.parametrize(("compute", "expected"), CASES)
def test_chapter_4(compute, expected):
    assert same(compute(), expected)


def test_4_4_sampled_helix_against_closed_form():
    # The helix a = 2, b = 1 sampled at 201 points over one turn: kappa = 2/5, tau = 1/5.
    # The spline estimates are O(h^2) (h = 0.031): rtol 1e-3 holds away from the ends (10 %
    # margins), see frenet_numeric's Notes.
    u = np.linspace(0, 2 * np.pi, 201)
    res = frenet_numeric(np.column_stack([2 * np.cos(u), 2 * np.sin(u), u]), u)
    inner = slice(20, -20)
    assert_allclose(res.curvature[inner], 0.4, rtol=1e-3)
    assert_allclose(res.torsion[inner], 0.2, rtol=1e-3)
    assert_allclose(res.normal[inner], np.column_stack([-np.cos(u), -np.sin(u), 0 * u])[inner],
                    atol=1e-3)
