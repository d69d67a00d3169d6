"""The catalogue of homogeneous bodies (ch. 15.5) against direct symbolic integration.

Independent route: for each body, sympy integrates rho * (y^2 + z^2), rho * y z, ... over the
body's volume (or surface, or length) in coordinates that fit it, with the origin at the mass
centre, and divides by the integrated mass. The catalogue's closed forms must agree exactly
(``simplify(difference) == 0``).
"""

import pytest
import sympy as sp

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.inertia import (
    InertiaOperator,
    block,
    cone,
    cylinder,
    cylindrical_shell,
    disk,
    ellipsoid,
    hollow_cylinder,
    rectangular_plate,
    ring,
    rod,
    sphere,
    spherical_shell,
    tube,
)
from rigidmech.vectors import Frame

m, a, b, c, R, L, h, r1, r2 = sp.symbols("m a b c R L h r1 r2", positive=True)
x, y, z, r, phi, theta, u = sp.symbols("x y z r phi theta u", real=True)


def integrated_operator(position, jacobian, limits):
    """Matrix of inertia per unit mass times m, by direct integration (ch. 15.1.3).

    ``position`` gives (x, y, z) relative to the mass centre as functions of the integration
    variables, ``jacobian`` the density of the measure, ``limits`` sympy integration limits
    (innermost first). Uniform density: the matrix is m * (int f dV) / (int dV).
    """
    X, Y, Z = position

    def integral(f):
        return sp.integrate(f * jacobian, *limits)

    volume = integral(sp.S.One)
    moments = [Y**2 + Z**2, Z**2 + X**2, X**2 + Y**2]
    A, B, C = (integral(sp.expand(f)) for f in moments)
    D, E, F = (integral(sp.expand(f)) for f in (Y * Z, Z * X, X * Y))
    rows = [[A, -F, -E], [-F, B, -D], [-E, -D, C]]
    return sp.Matrix(rows) * m / volume


def assert_same(operator, expected):
    diff = (operator.matrix - expected).applyfunc(sp.simplify)
    assert diff == sp.zeros(3, 3), diff


R0 = Frame("R0")

CASES = [
    pytest.param(lambda: rod(m, L, axis=R0.k),
                 ((0, 0, u), 1, [(u, -L / 2, L / 2)]), id="rod"),
    pytest.param(lambda: ring(m, R, axis=R0.k),
                 ((R * sp.cos(phi), R * sp.sin(phi), 0), R, [(phi, 0, 2 * sp.pi)]), id="ring"),
    pytest.param(lambda: disk(m, R, axis=R0.k),
                 ((r * sp.cos(phi), r * sp.sin(phi), 0), r,
                  [(r, 0, R), (phi, 0, 2 * sp.pi)]), id="disk"),
    pytest.param(lambda: cylinder(m, R, L, axis=R0.k),
                 ((r * sp.cos(phi), r * sp.sin(phi), z), r,
                  [(r, 0, R), (phi, 0, 2 * sp.pi), (z, -L / 2, L / 2)]), id="cylinder"),
    pytest.param(lambda: tube(m, r1, r1 + r2, L, axis=R0.k),
                 ((r * sp.cos(phi), r * sp.sin(phi), z), r,
                  [(r, r1, r1 + r2), (phi, 0, 2 * sp.pi), (z, -L / 2, L / 2)]), id="tube"),
    pytest.param(lambda: cylindrical_shell(m, R, L, axis=R0.k),
                 ((R * sp.cos(phi), R * sp.sin(phi), z), R,
                  [(phi, 0, 2 * sp.pi), (z, -L / 2, L / 2)]), id="cylindrical-shell"),
    # apex at height h above the base plane z = 0; the mass centre is at h/4 (checked below)
    pytest.param(lambda: cone(m, R, h, axis=R0.k),
                 ((r * sp.cos(phi), r * sp.sin(phi), z - h / 4), r,
                  [(r, 0, R * (1 - z / h)), (phi, 0, 2 * sp.pi), (z, 0, h)]), id="cone"),
    pytest.param(lambda: sphere(m, R, frame=R0),
                 ((r * sp.sin(theta) * sp.cos(phi), r * sp.sin(theta) * sp.sin(phi),
                   r * sp.cos(theta)), r**2 * sp.sin(theta),
                  [(r, 0, R), (phi, 0, 2 * sp.pi), (theta, 0, sp.pi)]), id="sphere"),
    pytest.param(lambda: spherical_shell(m, R, frame=R0),
                 ((R * sp.sin(theta) * sp.cos(phi), R * sp.sin(theta) * sp.sin(phi),
                   R * sp.cos(theta)), R**2 * sp.sin(theta),
                  [(phi, 0, 2 * sp.pi), (theta, 0, sp.pi)]), id="spherical-shell"),
    pytest.param(lambda: block(m, a, b, c, frame=R0),
                 ((x, y, z), 1, [(x, -a / 2, a / 2), (y, -b / 2, b / 2), (z, -c / 2, c / 2)]),
                 id="block"),
    pytest.param(lambda: rectangular_plate(m, a, b, frame=R0),
                 ((x, y, 0), 1, [(x, -a / 2, a / 2), (y, -b / 2, b / 2)]), id="plate"),
    pytest.param(lambda: ellipsoid(m, a, b, c, frame=R0),
                 ((a * r * sp.sin(theta) * sp.cos(phi), b * r * sp.sin(theta) * sp.sin(phi),
                   c * r * sp.cos(theta)), a * b * c * r**2 * sp.sin(theta),
                  [(r, 0, 1), (phi, 0, 2 * sp.pi), (theta, 0, sp.pi)]), id="ellipsoid"),
]


@pytest.mark.parametrize(("make", "body"), CASES)
def test_catalogue_matches_integration(make, body):
    operator = make()
    assert isinstance(operator, InertiaOperator)
    assert operator.frame == R0 and operator.at == R0.origin
    assert_same(operator, integrated_operator(*body))


def test_cone_mass_centre_is_a_quarter_of_the_height_from_the_base():
    # the cone case above integrates about z = h/4: check that it is the mass centre
    zbar = (sp.integrate(z * r, (r, 0, R * (1 - z / h)), (z, 0, h))
            / sp.integrate(r, (r, 0, R * (1 - z / h)), (z, 0, h)))
    assert sp.simplify(zbar - h / 4) == 0


@pytest.mark.parametrize("n", [0, 1, 2])
def test_axis_puts_the_axial_moment_on_its_basis_vector(n):
    axis = R0.basis[n]
    J = cylinder(m, R, L, axis=-axis)  # the opposite vector gives the same operator
    axial, transverse = m * R**2 / 2, m * (3 * R**2 + L**2) / 12
    expected = [transverse] * 3
    expected[n] = axial
    assert J.matrix == sp.ImmutableMatrix(sp.diag(*expected))
    assert J.moment_about(axis) == axial


def test_centre_keyword_sets_the_point():
    G = R0.point("G", 1, 2, 3)
    J = sphere(m, R, frame=R0, centre=G)
    assert J.at == G
    assert J.matrix == sphere(m, R, frame=R0).matrix


def test_hollow_cylinder_is_tube_and_tube_with_no_hole_is_cylinder():
    assert hollow_cylinder is tube
    assert_same(tube(m, 0, R, L, axis=R0.k), cylinder(m, R, L, axis=R0.k).matrix)


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda: rod(-1, 2, axis=R0.i), ArgumentError, r"^`mass` must be >= 0; got -1\.$"),
        (lambda: disk(1, -0.5, axis=R0.i), ArgumentError, r"`radius` must be >= 0; got -0.5"),
        (lambda: block(1, 1, 2, -3, frame=R0), ArgumentError, r"`c` must be >= 0; got -3"),
        (lambda: cone(1, 1, -sp.Symbol("h", positive=True), axis=R0.k), ArgumentError,
         r"`height` must be >= 0; got -h"),
        (lambda: tube(1, 2, 1, 1, axis=R0.k), ArgumentError,
         r"`r_in` must be <= `r_out`; got r_in=2 and r_out=1"),
        (lambda: rod(1, 1, axis=R0.i + R0.j), ArgumentError,
         r"`axis` must be a basis vector of a frame \(such as R1.i or -R1.k\); got R0.i \+ R0.j"),
        (lambda: rod(1, 1, axis=2 * R0.i), ArgumentError, r"`axis` must be a basis vector"),
        (lambda: rod(1, 1, axis="x"), ArgumentTypeError,
         r"`axis` must be a basis vector of a frame \(such as R1.i\); got str"),
        (lambda: sphere(1, 1, frame=R0.i), ArgumentTypeError, r"`frame` must be a Frame"),
        (lambda: rod("m", 1, axis=R0.i), ArgumentTypeError,
         r"`mass` must be a number or a sympy expression; got str"),
        (lambda: rod(float("nan"), 1, axis=R0.i), ArgumentError,
         r"`mass` must be a finite real number; got nan"),
        (lambda: rod(1, 1, axis=R0.i, centre=R0.i), ArgumentTypeError, r"`at` must be a Point"),
    ],
)
def test_catalogue_errors(call, error, match):
    with pytest.raises(error, match=match):
        call()


def test_symbolic_mass_of_unknown_sign_is_accepted():
    k = sp.Symbol("k")  # real sign unknown: cannot be decided, so no error
    assert rod(k, 1, axis=R0.i).B == k / 12
