"""Newton's attraction (ch. 12): fields and potentials of spherical bodies checked against
-dV/dr, Gauss's theorem and a direct numerical integration over the mass; the actions'
forces against minus the gradient of their potential energy."""

import math

import pytest
import sympy as sp
from numpy.testing import assert_allclose
from scipy.integrate import quad

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.actions import (
    GRAVITATIONAL_CONSTANT,
    Attractor,
    NewtonAttraction,
    SphericalBodyAttraction,
    homogeneous_sphere_attractor,
    point_mass_attractor,
    spherical_shell_attractor,
    surface_gravity,
)

M, R, G, r = sp.symbols("M R G r", positive=True)


@pytest.mark.parametrize("make", [homogeneous_sphere_attractor, spherical_shell_attractor])
@pytest.mark.parametrize("branch", [0, 1], ids=["outside", "inside"])
def test_field_is_minus_the_derivative_of_the_potential(make, branch):
    """g(r) = dV/dr on each branch of the piecewise expressions (the field points towards
    the centre, g = -dV/dr along the outward radius)."""
    body = make(M, R, G=G)
    V = body.potential(r)
    g = body.field_magnitude(r)
    assert isinstance(V, sp.Piecewise) and isinstance(g, sp.Piecewise)
    assert sp.simplify(g.args[branch][0] - sp.diff(V.args[branch][0], r)) == 0


@pytest.mark.parametrize("make", [homogeneous_sphere_attractor, spherical_shell_attractor])
def test_potential_continuous_at_the_surface_and_outer_law(make):
    body = make(M, R, G=G)
    assert sp.simplify(body.potential(R) + G * M / R) == 0
    assert sp.simplify(body.potential(3 * R) + G * M / (3 * R)) == 0
    assert sp.simplify(body.field_magnitude(2 * R) - G * M / (4 * R**2)) == 0


@pytest.mark.parametrize("k", [sp.Rational(1, 10), sp.Rational(1, 2), sp.Rational(9, 10)])
def test_solid_sphere_inside_by_gauss(k):
    """Gauss: g(r) = G M(r) / r^2 with M(r) = M r^3 / R^3 inside (ch. 12.1.3); the shell
    encloses no mass: g = 0 inside."""
    rr = k * R
    assert sp.simplify(homogeneous_sphere_attractor(M, R, G=G).field_magnitude(rr)
                       - G * (M * rr**3 / R**3) / rr**2) == 0
    assert spherical_shell_attractor(M, R, G=G).field_magnitude(rr) == 0


@pytest.mark.parametrize("rr", [0.3, 0.7, 1.5, 4.0])
def test_shell_potential_against_numerical_integration(rr):
    """V(r) = -G sum dm / |P - Q| summed over the rings of the shell (angle theta), with
    scipy.integrate.quad at 1e-13."""
    Mn, Rn, Gn = 2.0, 1.0, 1.0

    def f(th):
        return math.sin(th) / math.sqrt(rr**2 + Rn**2 - 2 * rr * Rn * math.cos(th))

    expected = -Gn * Mn / 2 * quad(f, 0, math.pi, epsabs=1e-14, epsrel=1e-13)[0]
    assert_allclose(float(spherical_shell_attractor(Mn, Rn, G=Gn).potential(rr)), expected,
                    rtol=1e-11)


@pytest.mark.parametrize("rr", [0.0, 0.3, 1.0, 2.5])
def test_solid_sphere_potential_from_the_field(rr):
    """V(r) = -integral from r to infinity of G M(s)/s^2 ds, M(s) the mass inside radius s
    (Gauss), integrated by quad at 1e-13."""
    Mn, Rn, Gn = 2.0, 1.0, 1.0

    def g(s):
        return Gn * Mn * min(s, Rn) ** 3 / Rn**3 / s**2

    inner = quad(g, rr, Rn, epsabs=1e-14, epsrel=1e-13)[0] if rr < Rn else 0.0
    outer = quad(g, max(rr, Rn), math.inf, epsabs=1e-14, epsrel=1e-13)[0]
    assert_allclose(float(homogeneous_sphere_attractor(Mn, Rn, G=Gn).potential(rr)),
                    -(inner + outer),
                    rtol=1e-11)


def test_symbolic_piecewise_and_point_mass():
    assert isinstance(homogeneous_sphere_attractor(M, R, G=G).potential(r), sp.Piecewise)
    assert point_mass_attractor(M, G=G).potential(r) == -G * M / r
    assert point_mass_attractor(M, G=G).field_magnitude(r) == G * M / r**2
    assert point_mass_attractor(M).G == GRAVITATIONAL_CONSTANT
    assert point_mass_attractor(M, G=G).mu == G * M
    assert "homogeneous sphere" in repr(homogeneous_sphere_attractor(M, R))


def test_gravity_is_the_local_approximation():
    """m V(R + h) = m V(R) + m (G M / R^2) h + O(h^2) (ch. 12.2): gravity g = G M / R^2;
    for the Earth (M = 5.972e24 kg, R = 6.371e6 m) g = 9.82 m/s^2."""
    h, m = sp.symbols("h m", positive=True)
    V = homogeneous_sphere_attractor(M, R, G=G).potential(R + h)
    series = sp.series(m * V, h, 0, 2).removeO()
    assert sp.simplify(series - (-G * M * m / R + m * G * M / R**2 * h)) == 0
    assert sp.simplify(surface_gravity(M, R, G=G) - G * M / R**2) == 0
    g = float(surface_gravity(5.972e24, 6.371e6))
    assert_allclose(g, 6.67430e-11 * 5.972e24 / 6.371e6**2, rtol=1e-14)
    assert round(g, 2) == 9.82
    R0 = rm.Frame("R0")
    grav = point_mass_attractor(M, G=G).local_gravity(R0.point("P", 0, 0, R), centre=R0.origin)
    assert grav.field.equals(-G * M / R**2 * R0.k)


def _two_bodies():
    x, y, z = rm.coordinates("x y z")
    m1, m2 = sp.symbols("m1 m2", positive=True)
    R0 = rm.Frame("R0")
    a = rm.Body("a", frame=R0.translated("Ra", R0.point("A", 1, 2, 0)), mass=m1)
    b = rm.Body("b", frame=R0.translated("Rb", R0.point("B", x, y, z)), mass=m2)
    return (x, y, z), m1, m2, R0, a, b


def test_newton_attraction_forces_derive_from_the_potential():
    """Force on b = -grad_B E_p, on a the opposite (action and reaction), magnitude
    G m1 m2 / d^2 (ch. 12.1)."""
    (x, y, z), m1, m2, R0, a, b = _two_bodies()
    att = NewtonAttraction(a, b, G=G)
    Ep = att.potential_energy([a, b], R0)
    (sb, Fb), (sa, Fa) = att.contributions([a, b])
    assert sb is b and sa is a
    comps = Fb.resultant.components(R0)
    for c, q in zip(comps, (x, y, z), strict=True):
        assert sp.simplify(c + sp.diff(Ep, q)) == 0
    assert (Fa.resultant + Fb.resultant).is_zero
    assert Fb.point == b.centre and Fa.point == a.centre
    vals = {x: 4, y: 6, z: 0}
    assert sp.simplify(Fb.resultant.magnitude().subs(vals) - G * m1 * m2 / 25) == 0
    assert "NewtonAttraction" in repr(att)


def test_spherical_body_attraction():
    """Force m g(P) derives from m V; below the surface the solid sphere pulls linearly."""
    (x, y, z), m1, m2, R0, a, b = _two_bodies()
    earth = SphericalBodyAttraction(point_mass_attractor(M, G=G), centre=R0.origin)
    Ep = earth.potential_energy([a, b], R0)
    (_, Fa), (_, Fb) = earth.contributions([a, b])
    for c, q in zip(Fb.resultant.components(R0), (x, y, z), strict=True):
        assert sp.simplify(c + sp.diff(Ep, q)) == 0
    assert earth.body.kind == "point mass" and "SphericalBodyAttraction" in repr(earth)
    inner = SphericalBodyAttraction(homogeneous_sphere_attractor(M, 10, G=G), centre=R0.origin)
    (_, F), = inner.contributions([a])  # A at distance sqrt(5) < 10
    assert F.resultant.equals(-G * M * m1 / 1000 * (a.centre - R0.origin))
    assert inner.contributions([rm.Body("s", frame=R0)]) == []


def test_bad_input():
    with pytest.raises(ArgumentError, match="`mass` must be >= 0; got -1"):
        point_mass_attractor(-1)
    with pytest.raises(ArgumentError, match="`mass` must be >= 0"):
        homogeneous_sphere_attractor(-sp.Symbol("m", positive=True), 1)
    with pytest.raises(ArgumentError, match="`radius` must be > 0; got 0"):
        homogeneous_sphere_attractor(1, 0)
    with pytest.raises(ArgumentError, match="`G` must be > 0"):
        point_mass_attractor(1, G=-1)
    with pytest.raises(ArgumentError, match="`mass` must be finite"):
        point_mass_attractor(sp.oo)
    with pytest.raises(ArgumentTypeError, match="`mass` must be a number"):
        point_mass_attractor("a b c (")
    with pytest.raises(ArgumentError, match="`r` must be > 0 for a point mass"):
        point_mass_attractor(1).potential(0)
    with pytest.raises(ArgumentError, match="`r` must be > 0 for a point mass"):
        point_mass_attractor(1).field_magnitude(0)
    assert homogeneous_sphere_attractor(1, 1).field_magnitude(0) == 0
    with pytest.raises(ArgumentError, match="`kind` must be one of"):
        Attractor("cube", 1, 1)
    R0 = rm.Frame("R0")
    a = rm.Body("a", frame=R0, mass=1)
    with pytest.raises(ArgumentError, match="`b` \\(s\\) must have a mass"):
        NewtonAttraction(a, rm.Body("s", frame=R0))
    with pytest.raises(ArgumentError, match="two different bodies"):
        NewtonAttraction(a, a)
    with pytest.raises(ArgumentTypeError, match="`body` must be an Attractor"):
        SphericalBodyAttraction(1, centre=R0.origin)
    with pytest.raises(ArgumentError, match="`mass` must be >= 0"):
        rm.Body("neg", frame=R0, mass=-2)
