"""Tests of rigidmech.vectors.curves: arc length, Frenet trihedron, curvature, torsion
(book, ch. 4)."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.special import ellipeinc

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.vectors import Frame, t
from rigidmech.vectors.curves import Curve, FrenetTrihedron, frenet_numeric

R0 = Frame("R0")
s = sp.Symbol("s", real=True)
a, b = sp.symbols("a b", positive=True)
HELIX = Curve(R0.vector(a * sp.cos(s), a * sp.sin(s), b * s), s, R0)


def components(v):
    return np.array(v.components(R0).evalf(), dtype=float).ravel()


# -- symbolic ----------------------------------------------------------------------------------
def test_helix_closed_forms():
    # r = a cos s i + a sin s j + b s k: |r'| = c = sqrt(a^2 + b^2), T = (-a sin, a cos, b)/c,
    # N = (-cos, -sin, 0), B = (b sin, -b cos, a)/c, kappa = a/c^2, tau = b/c^2.
    c = sp.sqrt(a**2 + b**2)
    T, N, B, kappa, tau = HELIX.frenet()
    assert T.equals(R0.vector(-a * sp.sin(s), a * sp.cos(s), b) / c)
    assert N.equals(R0.vector(-sp.cos(s), -sp.sin(s), 0))
    assert B.equals(R0.vector(b * sp.sin(s), -b * sp.cos(s), a) / c)
    assert sp.simplify(kappa - a / c**2) == 0
    assert sp.simplify(tau - b / c**2) == 0
    assert sp.simplify(HELIX.radius_of_curvature() - c**2 / a) == 0
    assert sp.simplify(HELIX.speed() - c) == 0
    assert sp.simplify(HELIX.curvilinear_abscissa() - c * s) == 0


def test_helix_frenet_formulas_symbolic():
    # dT/ds = kappa |r'| N, dN/ds = -kappa |r'| T + tau |r'| B, dB/ds = -tau |r'| N (ch. 4.4)
    T, N, B, kappa, tau = HELIX.frenet()
    v = HELIX.speed()
    assert T.diff(s).equals(kappa * v * N)
    assert N.diff(s).equals(-kappa * v * T + tau * v * B)
    assert B.diff(s).equals(-tau * v * N)


@st.composite
def polynomial_curves(draw):
    coeffs = st.integers(-3, 3)
    comps = [sum(draw(coeffs) * s**p for p in range(4)) for _ in range(3)]
    return comps, sp.Rational(draw(st.integers(-4, 4)), 2)


@settings(max_examples=20, deadline=None)
@given(data=polynomial_curves())
def test_frenet_formulas_on_random_polynomial_curves(data):
    # Property: the trihedron and the scalars returned at s0 satisfy the Frenet formulas. The
    # derivatives of T = r'/|r'|, B = c/|c| (c = r' ^ r'') and N = B ^ T are computed
    # independently by the derivative of a normalised vector, (w/|w|)' = (w' - (e.w') e)/|w|
    # with e = w/|w|, from the exact derivatives of r at s0 (c' = r' ^ r'''), in floating
    # point. Values are O(1)-O(100): rtol 1e-9 and atol 1e-9 cover the round-off.
    comps, s0 = data
    r = sp.Matrix(comps)
    d1, d2, d3 = (np.array(r.diff(s, n).subs(s, s0), dtype=float).ravel() for n in (1, 2, 3))
    c = np.cross(d1, d2)
    assume(np.linalg.norm(d1) > 1e-2 and np.linalg.norm(c) > 1e-2)
    curve = Curve(R0.vector(*comps), s, R0)
    T, N, B, kappa, tau = curve.frenet(at=s0)
    v = float(curve.speed(at=s0))
    kappa, tau = float(kappa), float(tau)

    def unit_derivative(w, dw):
        e = w / np.linalg.norm(w)
        return (dw - e.dot(dw) * e) / np.linalg.norm(w)

    dT = unit_derivative(d1, d2)
    dB = unit_derivative(c, np.cross(d1, d3))
    Bx, Tx = c / np.linalg.norm(c), d1 / np.linalg.norm(d1)
    dN = np.cross(dB, Tx) + np.cross(Bx, dT)
    T, N, B = components(T), components(N), components(B)
    tol = {"rtol": 1e-9, "atol": 1e-9}
    assert_allclose(dT, kappa * v * N, **tol)
    assert_allclose(dN, -kappa * v * T + tau * v * B, **tol)
    assert_allclose(dB, -tau * v * N, **tol)
    assert_allclose(np.cross(T, N), B, **tol)


def test_curve_of_a_point_in_a_rotating_frame():
    # A point fixed at distance 2 on the axis i1 of R1 turning about k0: a circle in R0
    # (curvature 1/2, torsion 0) and a fixed point, hence singular, in R1.
    w = sp.Symbol("omega", positive=True)
    R1 = R0.rotated("R1", about=R0.k, angle=w * t)
    P = R1.point("P", 2, 0, 0)
    circle = Curve(P, t, R0)
    assert sp.simplify(circle.curvature() - sp.Rational(1, 2)) == 0
    assert circle.torsion() == 0
    assert sp.simplify(circle.speed() - 2 * w) == 0
    with pytest.raises(ArgumentError, match=r"singular point: the velocity dr/dt is zero at every "
                                            r"parameter value"):
        Curve(P, t, R1).tangent()


def test_singular_point_raises():
    cusp = Curve(R0.vector(s**2, s**3, 0), s, R0)
    assert cusp.tangent(at=1).equals(R0.vector(2, 3, 0) / sp.sqrt(13))
    for method in (cusp.tangent, cusp.curvature, cusp.normal, cusp.torsion, cusp.frenet):
        with pytest.raises(ArgumentError, match=r"singular point: the velocity dr/ds is zero at "
                                                r"s = 0, so the curve has no tangent there"):
            method(at=0)


def test_straight_line_and_inflection():
    line = Curve(R0.vector(1 + 2 * s, 3 * s, -s), s, R0)
    assert line.curvature() == 0
    assert line.tangent().equals(R0.vector(2, 3, -1) / sp.sqrt(14))
    message = (r"the principal normal, the binormal and the torsion are undefined where the "
               r"curvature is zero; got zero curvature at every parameter value")
    for method in (line.normal, line.binormal, line.torsion, line.radius_of_curvature,
                   line.frenet):
        with pytest.raises(ArgumentError, match=message):
            method()
    cubic = Curve(R0.vector(s, s**3, 0), s, R0)
    assert cubic.curvature(at=0) == 0
    with pytest.raises(ArgumentError, match=r"got zero curvature at s = 0 \(straight line or "
                                            r"inflection point\)"):
        cubic.normal(at=0)
    assert cubic.normal(at=1).equals(R0.vector(-3, 1, 0) / sp.sqrt(10))


def test_arc_length_closed_forms():
    parabola = Curve(R0.vector(s, s**2, 0), s, R0)
    expected = sp.sqrt(5) / 2 + sp.asinh(2) / 4  # integral of sqrt(1 + 4 s^2) on [0, 1]
    assert sp.simplify(parabola.arc_length(0, 1) - expected) == 0
    assert sp.simplify(HELIX.arc_length(0, 2 * sp.pi) - 2 * sp.pi * sp.sqrt(a**2 + b**2)) == 0
    assert sp.simplify(HELIX.arc_length(1, 0) + sp.sqrt(a**2 + b**2)) == 0  # signed


def test_arc_length_numeric_fallback():
    # sympy leaves the integral of sqrt(1 + cos^2 s) unevaluated: quad takes over. Reference:
    # integral_0^x sqrt(2 - sin^2) = sqrt(2) E(x | 1/2) (incomplete elliptic integral);
    # quad is asked for 1e-12 relative accuracy, checked at 1e-11.
    sine = Curve(R0.vector(s, sp.sin(s), 0), s, R0)
    expected = np.sqrt(2) * ellipeinc(2.0, 0.5)
    got = sine.arc_length(0, 2)
    assert isinstance(got, sp.Float)
    assert_allclose(float(got), expected, rtol=1e-11)
    assert_allclose(float(sine.arc_length(0, 2, method="numeric")), expected, rtol=1e-11)
    assert isinstance(sine.arc_length(0, 2, method="symbolic"), sp.Integral)
    x = sp.Symbol("x")
    assert isinstance(sine.arc_length(0, x), sp.Integral)  # symbolic bound: no fallback
    with pytest.raises(ArgumentError, match=r"`method='numeric'` needs numeric bounds"):
        sine.arc_length(0, x, method="numeric")
    with pytest.raises(ArgumentError, match=r"`method` must be 'auto', 'symbolic' or 'numeric'; "
                                            r"got 'exact'"):
        sine.arc_length(0, 1, method="exact")


def test_value_access_and_repr():
    curve = Curve(R0.vector(s, s**2, 0), s, R0)
    assert curve.parameter == s and curve.frame == R0
    assert curve.position(at=3) == 3 * R0.i + 9 * R0.j
    assert curve.velocity(at=1) == R0.i + 2 * R0.j
    assert repr(curve) == "Curve(s*R0.i + s**2*R0.j, s, R0)"
    tri = HELIX.frenet(at=0)
    assert isinstance(tri, FrenetTrihedron) and tri.curvature == tri[3]


def test_constructor_errors():
    with pytest.raises(ArgumentTypeError, match=r"`position` must be a Point or a Vector; got "
                                                r"tuple"):
        Curve((s, 0, 0), s, R0)
    with pytest.raises(ArgumentTypeError, match=r"`parameter` must be a sympy Symbol; got Add"):
        Curve(s * R0.i, s + 1, R0)
    other = Frame("Other")
    with pytest.raises(ArgumentError, match=r"`position` must be a point of the tree of R0; got "
                                            r"point A of the tree rooted at Other"):
        Curve(other.point("A", s, 0, 0), s, R0)
    with pytest.raises(ArgumentTypeError, match=r"`frame` must be a Frame; got NoneType"):
        Curve(s * R0.i, s, None)


# -- numeric -----------------------------------------------------------------------------------
def helix_samples(n):
    u = np.linspace(0, 2 * np.pi, n)
    return u, np.column_stack([np.cos(u), np.sin(u), 0.5 * u])


@pytest.mark.parametrize("method", ["spline", "finite_differences"])
def test_numeric_accuracy(method):
    # Helix a = 1, b = 1/2: kappa = 0.8, tau = 0.4. Inside (10 % margins) both methods
    # converge as h^2 at least; the error must fall by >= 12 (h^2 gives 16) from n = 101 to
    # 401, and stay below the figures documented in frenet_numeric's Notes.
    errors = []
    for n in (101, 401):
        u, pts = helix_samples(n)
        res = frenet_numeric(pts, u, method=method)
        inner = slice(n // 10, n - n // 10)
        T = np.column_stack([-np.sin(u), np.cos(u), 0.5 + 0 * u]) / np.sqrt(1.25)
        N = np.column_stack([-np.cos(u), -np.sin(u), 0 * u])
        errors.append([np.abs(res.tangent - T)[inner].max(), np.abs(res.normal - N)[inner].max(),
                       np.abs(res.curvature - 0.8)[inner].max(),
                       np.abs(res.torsion - 0.4)[inner].max()])
        assert_allclose(res.speed, np.sqrt(1.25), rtol=1e-2)
    coarse, fine = np.array(errors)
    assert np.all(coarse < 5e-4) and np.all(fine < 3e-5)
    converging = coarse > 1e-10  # differences give N exactly (round-off) on this helix
    assert np.all(coarse[converging] / fine[converging] > 12)


def test_numeric_binormal_is_tangent_cross_normal():
    u, pts = helix_samples(64)
    res = frenet_numeric(pts, u)
    assert_allclose(np.cross(res.tangent, res.normal), res.binormal, atol=1e-12)
    assert_allclose(np.linalg.norm(res.normal, axis=1), 1.0, rtol=1e-12)
    with pytest.raises(ValueError, match="read-only"):
        res.curvature[0] = 1.0


def test_numeric_straight_and_singular():
    u = np.linspace(0, 1, 11)
    line = np.column_stack([u, 2 * u, 3 * u])
    with pytest.raises(ArgumentError, match=r"the principal normal is undefined where the "
                                            r"curvature is zero; got curvature <= .* at samples "
                                            r"\[0, 1, 2, 3, 4\] \.\.\.; pass straight='nan'"):
        frenet_numeric(line, u)
    res = frenet_numeric(line, u, straight="nan")
    assert np.all(np.isnan(res.normal)) and np.all(np.isnan(res.torsion))
    assert_allclose(res.tangent, np.tile([1, 2, 3], (11, 1)) / np.sqrt(14), rtol=1e-12)
    stop = line.copy()
    stop[4:7] = stop[5]  # the point stays at rest over three samples
    with pytest.raises(ArgumentError, match=r"singular point: the velocity dr/ds is zero at "
                                            r"samples \[5\]"):
        frenet_numeric(stop, u, method="finite_differences")
    with pytest.raises(ArgumentError, match=r"singular point: the velocity dr/ds is zero at "
                                            r"samples \[0, 1, 2, 3, 4\]"):
        frenet_numeric(np.ones((5, 3)), np.arange(5.0))


def test_numeric_argument_errors():
    u, pts = helix_samples(10)
    with pytest.raises(ArgumentError, match=r"`points` must have shape \(n, 3\); got \(10, 2\)"):
        frenet_numeric(pts[:, :2], u)
    with pytest.raises(ArgumentError, match=r"`params` must have shape \(n,\) matching `points` "
                                            r"with n >= 4 for method='spline'"):
        frenet_numeric(pts[:3], u[:3])
    with pytest.raises(ArgumentError, match=r"`params` must be strictly increasing"):
        frenet_numeric(pts, u[::-1])
    with pytest.raises(ArgumentError, match=r"`points` and `params` must be finite"):
        frenet_numeric(np.where(pts > 0.5, np.nan, pts), u)
    with pytest.raises(ArgumentError, match=r"`method` must be 'spline' or 'finite_differences'; "
                                            r"got 'fd'"):
        frenet_numeric(pts, u, method="fd")
    with pytest.raises(ArgumentError, match=r"`straight` must be 'raise' or 'nan'; got 'zero'"):
        frenet_numeric(pts, u, straight="zero")
    with pytest.raises(ArgumentTypeError, match=r"`points` and `params` must be numeric arrays"):
        frenet_numeric([["a", "b", "c"]] * 4, u[:4])
