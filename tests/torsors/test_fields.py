"""Torsors of fields of sliders, parametrised domains and measure centres (ch. 5.3)."""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

from rigidmech import Frame, constants
from rigidmech.torsors import (
    Domain,
    barycentre,
    measure_centre,
    slider,
    torsor_of_field,
    torsor_of_sliders,
    total_measure,
)
from rigidmech.vectors import Vector

R0 = Frame("R0")
R, h, L = constants("R h L", positive=True)
u, v, w, r, th, ph, x, y, z = sp.symbols("u v w r theta phi x y z")


def coords(point):
    return point.coordinates(R0)


# -- finite sets of sliders (ch. 5.3.1) ---------------------------------------------------------
def test_concurrent_forces_give_a_slider_through_the_common_point():
    P = R0.point("P", 1, 2, 3)
    T = torsor_of_sliders([(P, R0.i), (P, 2 * R0.j), (P, -R0.k)], at=R0.origin)
    assert T.kind == "slider"
    assert T.central_axis().contains(P)


def test_parallel_forces_give_a_slider_through_their_barycentre():
    # weights m_i g (-k) at P_i: slider through the barycentre of the P_i with weights m_i
    g = sp.Symbol("g", positive=True)
    pts = [R0.point("P1", 0, 0, 0), R0.point("P2", 4, 0, 0), R0.point("P3", 0, 6, 0)]
    masses = [1, 1, 2]
    T = torsor_of_sliders([(P, -m * g * R0.k) for P, m in zip(pts, masses, strict=True)])
    assert T.point == pts[0]
    assert T.kind == "slider"
    G = R0.point("G", 1, 3, 0)  # (0*1 + 4*1 + 0*2)/4, (0 + 0 + 12)/4
    assert T.central_axis().contains(G)
    assert T.resultant == -4 * g * R0.k


def test_torsor_of_sliders_is_the_sum_of_sliders():
    pairs = [(R0.point("A", 1, 0, 2), R0.i - R0.k), (R0.point("B", 0, -1, 1), 3 * R0.j)]
    T = torsor_of_sliders(pairs, at=R0.point("C", 2, 2, 2))
    assert T.equals(slider(pairs[0][1], pairs[0][0]) + slider(pairs[1][1], pairs[1][0]))


def test_torsor_of_sliders_errors():
    P = R0.point("P", 1, 0, 0)
    with pytest.raises(TypeError, match=r"`pairs\[0\]` must be \(Point, Vector\); got "
                                        r"\(Vector, Point\): swap them"):
        torsor_of_sliders([(R0.i, P)])
    with pytest.raises(TypeError, match=r"`pairs\[1\]\[1\]` must be a Vector; got the Point P"):
        torsor_of_sliders([(P, R0.i), (P, P)])
    with pytest.raises(TypeError, match=r"`pairs\[0\]\[0\]` must be a Point"):
        torsor_of_sliders([(R0.i, R0.j)])
    with pytest.raises(TypeError, match=r"`pairs\[0\]` must be a \(Point, Vector\) pair"):
        torsor_of_sliders([P])
    with pytest.raises(ValueError, match="`at` is needed when `pairs` is empty"):
        torsor_of_sliders([])
    assert torsor_of_sliders([], at=P).kind == "zero"


# -- domains and their measure ---------------------------------------------------------------
# the domains are built by the test (a lambda each), not at collection: deriving a measure
# costs about 0.3 s, paid otherwise by every process that collects this module
@pytest.mark.parametrize(
    ("domain", "measure", "total"),
    [
        pytest.param(lambda: Domain(R0, [R * sp.cos(u), R * sp.sin(u), 0], (u, 0, 2 * sp.pi)), R,
                     2 * sp.pi * R, id="circle-length"),
        pytest.param(lambda: Domain(R0, [u, 2 * u, 2 * u], (u, 0, L)), 3, 3 * L,
                     id="segment-length"),
        pytest.param(lambda: Domain(R0, [R * sp.sin(th) * sp.cos(ph), R * sp.sin(th) * sp.sin(ph),
                                         R * sp.cos(th)], (th, 0, sp.pi), (ph, 0, 2 * sp.pi)),
                     R**2 * sp.sin(th), 4 * sp.pi * R**2, id="sphere-area"),
        pytest.param(lambda: Domain(R0, [r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph),
                                         r * sp.cos(th)], (r, 0, R), (th, 0, sp.pi),
                                         (ph, 0, 2 * sp.pi)),
                     r**2 * sp.sin(th), 4 * sp.pi * R**3 / 3, id="ball-volume"),
        pytest.param(lambda: Domain(R0, [u, v, 0], (v, 0, h * (1 - u / L)), (u, 0, L)), 1,
                     L * h / 2, id="triangle-area"),
    ],
)
def test_measure_element_and_total(domain, measure, total):
    domain = domain()
    assert sp.simplify(domain.measure - measure) == 0
    assert sp.simplify(total_measure(1, domain) - total) == 0


def test_domain_properties_and_repr():
    d = Domain(R0, x * R0.i + x**2 * R0.j, (x, 0, 1))
    assert d.kind == "curve" and d.dimension == 1 and d.parameters == (x,)
    assert d.frame is R0 and d.position == x * R0.i + x**2 * R0.j
    assert d.coordinates == (x, x**2, 0)
    assert repr(d) == "Domain(R0, [x, x**2, 0], (x, 0, 1))"
    assert Domain(R0, [u, v, 0], (u, 0, 1), (v, 0, 1)).kind == "surface"
    assert Domain(R0, [u, v, w], (u, 0, 1), (v, 0, 1), (w, 0, 1)).kind == "volume"
    same = Domain(R0, [x, x**2, 0], (x, 0, 1))
    assert d == same and hash(d) == hash(same)
    assert d != Domain(R0, [x, x**2, 0], (x, 0, 2))
    # a given measure element overrides the derived one
    assert Domain(R0, [u, 0, 0], (u, 0, 1), measure=7).measure == 7


def test_domain_errors():
    with pytest.raises(TypeError, match="`frame` must be a Frame; got str"):
        Domain("R0", [u, 0, 0], (u, 0, 1))
    with pytest.raises(TypeError, match="`position` must be the Vector OP .* not the Point A"):
        Domain(R0, R0.point("A", 1, 0, 0), (u, 0, 1))
    with pytest.raises(ValueError, match="`position` must have 3 coordinates; got 2"):
        Domain(R0, [u, 0], (u, 0, 1))
    with pytest.raises(ValueError, match="needs 1 .curve., 2 .surface. or 3 .volume. parameter"):
        Domain(R0, [u, 0, 0])
    with pytest.raises(ValueError, match=r"`ranges\[0\]` must be a tuple \(symbol, low, high\)"):
        Domain(R0, [u, 0, 0], (u, 0))
    with pytest.raises(TypeError, match=r"`ranges\[0\]` must start with a sympy Symbol"):
        Domain(R0, [u, 0, 0], (u**2, 0, 1))
    with pytest.raises(ValueError, match="the parameters must be distinct"):
        Domain(R0, [u, 0, 0], (u, 0, 1), (u, 0, 1))
    with pytest.raises(ValueError, match="the bounds of `u` may depend only on the parameters "
                                         "listed after it"):
        Domain(R0, [u, v, 0], (v, 0, 1), (u, 0, v))


def test_integrate_methods_and_errors():
    d = Domain(R0, [u, v, 0], (v, 0, 1 - u), (u, 0, 1))  # triangle, nested bounds
    assert d.integrate([u * v]) == [sp.Rational(1, 24)]
    # Gauss-Legendre is exact for polynomials of degree < 2*order
    assert_allclose(float(d.integrate([u * v], method="numeric", order=4)[0]), 1 / 24,
                    rtol=1e-14)
    assert_allclose(float(d.integrate([u * v], method="quad")[0]), 1 / 24, rtol=1e-10)
    with pytest.raises(ValueError, match="`method` must be one of"):
        d.integrate([1], method="simpson")
    with pytest.raises(ValueError, match="numeric integration needs numbers for every symbol "
                                         r"but the parameters; got \['L'\]"):
        d.integrate([L * u], method="numeric")
    with pytest.raises(ValueError, match="`order` must be a positive integer"):
        d.integrate([u], method="numeric", order=0)


def test_auto_falls_back_to_numbers_when_sympy_cannot_integrate():
    d = Domain(R0, [u, 0, 0], (u, 0, 1))
    f = sp.sin(sp.sin(u))  # no closed form
    (value,) = d.integrate([f])
    expected = float(sp.Integral(f, (u, 0, 1)).evalf(30))
    assert_allclose(float(value), expected, rtol=1e-13)  # 32-node Gauss on a smooth integrand
    with pytest.raises(ValueError, match="sympy could not integrate"):
        d.integrate([f], method="symbolic")
    with pytest.raises(ValueError, match="substitute values"):
        d.integrate([L * f])


# -- torsors of continuous fields (ch. 5.3.2) -------------------------------------------------
def test_uniform_load_on_a_beam_is_a_slider_through_the_middle():
    p = sp.Symbol("p", positive=True)
    beam = Domain(R0, x * R0.i, (x, 0, L))
    T = torsor_of_field(-p * R0.j, beam)
    assert T.point == R0.origin
    assert T.resultant == -p * L * R0.j
    assert T.kind == "slider"
    assert T.central_axis().contains(R0.point("M", L / 2, 0, 0))
    # at another point: the transport of the same torsor
    B = R0.point("B", L, 0, 0)
    assert torsor_of_field(-p * R0.j, beam, at=B).equals(T.at(B))


def test_field_given_as_a_function_of_the_coordinates():
    # hydrostatic-like load q(x) = x on [0, L] along -j, given as a callable of (x, y, z)
    beam = Domain(R0, [u, 0, 0], (u, 0, L))
    T = torsor_of_field(lambda X, Y, Z: -X * R0.j, beam)
    assert T.resultant == -L**2 / 2 * R0.j
    # slider through x = 2L/3 (centre of the triangle of load)
    assert T.central_axis().contains(R0.point("C", 2 * L / 3, 0, 0))


def test_field_torsor_matches_a_fine_sum_of_sliders():
    # a twisting field on a helix: compare with the midpoint sum of sliders (independent).
    helix = Domain(R0, [sp.cos(u), sp.sin(u), u / 4], (u, 0, 3))
    density = sp.cos(u) * R0.i + R0.j + u * R0.k
    T = torsor_of_field(density, helix)
    n = 1000
    pairs = []
    du = 3 / n
    ds = float(sp.sqrt(1 + sp.Rational(1, 16)))  # |r'(u)| = sqrt(17)/4
    for k in range(n):
        uk = (k + 0.5) * du
        P = R0.point("P", np.cos(uk), np.sin(uk), uk / 4)
        pairs.append((P, float(ds * du) * Vector.from_components(R0, [np.cos(uk), 1, uk])))
    S = torsor_of_sliders(pairs, at=R0.origin)
    # midpoint rule: relative error ~ (3^2/24) max|f"|/|f| / n^2, a few 1e-6 at n = 1000
    assert T.is_close(S, rtol=2e-5, atol=1e-5)
    numeric = torsor_of_field(density, helix, method="numeric")
    assert numeric.is_close(T.applyfunc(sp.N), rtol=1e-12)


def test_field_errors():
    d = Domain(R0, [u, 0, 0], (u, 0, 1))
    with pytest.raises(TypeError, match="`density` must be a Vector .* got the Point P"):
        torsor_of_field(R0.point("P", 1, 1, 1), d)
    with pytest.raises(TypeError, match="`density` must be a Vector; got int"):
        torsor_of_field(3, d)
    with pytest.raises(TypeError, match="`domain` must be a Domain; got tuple"):
        torsor_of_field(R0.i, (u, 0, 1))
    with pytest.raises(TypeError, match="`density` must be a scalar .* got a Vector"):
        measure_centre(R0.i, d)
    with pytest.raises(TypeError, match="`at` must be a Point"):
        torsor_of_field(R0.i, d, at=R0.i)


# -- measure centre (ch. 5.3.3) -----------------------------------------------------------------
def test_measure_centre_nonuniform_rod():
    # rod [0, L] with linear density rho = x: OG = int x^2 / int x = 2L/3
    rod = Domain(R0, [x, 0, 0], (x, 0, L))
    assert coords(measure_centre(x, rod)) == sp.Matrix([2 * L / 3, 0, 0])
    assert measure_centre(lambda X, Y, Z: X, rod).name == "G"


def test_measure_centre_numeric_matches_symbolic():
    cone = Domain(R0, [r * sp.cos(th), r * sp.sin(th), z], (r, 0, 2 * (3 - z) / 3),
                  (th, 0, 2 * sp.pi), (z, 0, 3))
    exact = coords(measure_centre(1, cone))
    assert exact == sp.Matrix([0, 0, sp.Rational(3, 4)])
    for method in ("numeric", "quad"):
        got = np.array(coords(measure_centre(1, cone, method=method, order=12)), dtype=float)
        # order-12 Gauss is exact for these polynomial integrands (degree <= 3 in r and z)
        # up to the trigonometric factors, integrated to ~1e-15 over a full period
        assert_allclose(got.ravel(), [0, 0, 0.75], atol=1e-10)


def test_measure_centre_of_a_gravity_field_is_on_the_central_axis():
    # The torsor of gravity (rho g (-k)) on a half-disk is a slider through G (ch. 5.3.3).
    g = sp.Symbol("g", positive=True)
    half_disk = Domain(R0, [r * sp.cos(th), r * sp.sin(th), 0], (r, 0, R), (th, 0, sp.pi))
    T = torsor_of_field(-g * R0.k, half_disk)
    G = measure_centre(1, half_disk)
    assert T.kind == "slider"
    assert T.central_axis().contains(G)
    assert T.resultant == -g * sp.pi * R**2 / 2 * R0.k


def test_measure_centre_zero_measure():
    d = Domain(R0, [u, 0, 0], (u, 0, 1))
    with pytest.raises(ValueError, match="the total measure of the domain is zero"):
        measure_centre(u - sp.Rational(1, 2), d)


def test_barycentre_of_weighted_points():
    m = sp.Symbol("m", positive=True)
    G = barycentre([(R0.point("A", 0, 0, 0), m), (R0.point("B", L, 0, 0), 2 * m),
                    (R0.point("C", 0, L, 0), m)])
    assert coords(G) == sp.Matrix([L / 2, L / 4, 0])
    assert G.name == "G"
    # the gravity torsor of the weighted points is a slider through their barycentre
    g = sp.Symbol("g", positive=True)
    T = torsor_of_sliders([(R0.point("A", 0, 0, 0), -m * g * R0.k),
                           (R0.point("B", L, 0, 0), -2 * m * g * R0.k),
                           (R0.point("C", 0, L, 0), -m * g * R0.k)])
    assert T.central_axis().contains(G)


def test_barycentre_errors():
    A = R0.point("A", 1, 0, 0)
    with pytest.raises(ValueError, match="`pairs` must hold at least one"):
        barycentre([])
    with pytest.raises(ValueError, match="the weights add up to zero"):
        barycentre([(A, 1), (R0.origin, -1)])
    with pytest.raises(TypeError, match=r"`pairs\[0\]\[1\]` must be a scalar weight; got a Vector"):
        barycentre([(A, R0.i)])
    with pytest.raises(TypeError, match=r"`pairs\[0\]\[0\]` must be a Point"):
        barycentre([(R0.i, 1)])
    with pytest.raises(TypeError, match=r"`pairs\[0\]` must be a \(Point, weight\) pair"):
        barycentre([A])
