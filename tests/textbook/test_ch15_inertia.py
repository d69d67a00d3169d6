"""Chapter 15, the operator of inertia: textbook-style exercises.

Each case computes a moment (or a matrix) with the library's route — catalogue at the mass
centre, Huygens (ch. 15.2.2), change of basis (ch. 15.2.4), moment about an axis (ch. 15.3.4),
associativity (ch. 15.4.4) — and compares it with a closed form that is classical and
derived independently in the comment of each case.
"""

import pytest
import sympy as sp

import rigidmech.inertia as inertia
from rigidmech.inertia import InertiaOperator
from rigidmech.vectors import Frame, coordinates

m, m1, m2, L, R, a, b, c, h = sp.symbols("m m1 m2 L R a b c h", positive=True)
R0 = Frame("R0")
O = R0.origin


def rod_about_its_end():
    # rod O..L i0: I = int_0^L x^2 (m/L) dx = m L^2 / 3
    G = R0.point("G", L / 2, 0, 0)
    J = inertia.rod(m, L, axis=R0.i, centre=G).moved(O, mass=m, centre=G)
    return J.moment_about(R0.k), m * L**2 / 3


def pendulum_rod_plus_disk():
    # rod (m1, L) pivoting at O plus a disk (m2, R) in the plane of motion centred at the rod's
    # end: I_O = m1 L^2 / 3 + (m2 R^2 / 2 + m2 L^2) about the pivot axis k0
    G1, G2 = R0.point("G1", L / 2, 0, 0), R0.point("G2", L, 0, 0)
    J_rod = inertia.rod(m1, L, axis=R0.i, centre=G1).moved(O, mass=m1, centre=G1)
    J_disk = inertia.disk(m2, R, axis=R0.k, centre=G2).moved(O, mass=m2, centre=G2)
    return (J_rod + J_disk).moment_about(R0.k), m1 * L**2 / 3 + m2 * (R**2 / 2 + L**2)


def block_about_an_edge():
    # edge along k0 through O, block in x, y, z > 0: C = int (x^2 + y^2) dm = m (a^2 + b^2) / 3
    G = R0.point("G", a / 2, b / 2, c / 2)
    J = inertia.block(m, a, b, c, frame=R0, centre=G).moved(O, mass=m, centre=G)
    return J.moment_about(R0.k), m * (a**2 + b**2) / 3


def block_at_a_corner_products():
    # products at the corner: F = int xy dm = m (a/2)(b/2) = m a b / 4, and so on
    G = R0.point("G", a / 2, b / 2, c / 2)
    J = inertia.block(m, a, b, c, frame=R0, centre=G).moved(O, mass=m, centre=G)
    return sp.Matrix([J.D, J.E, J.F]), sp.Matrix([m * b * c, m * c * a, m * a * b]) / 4


def cube_about_its_diagonal_from_a_corner():
    # the body diagonal passes through G, where the cube's operator is isotropic (m a^2 / 6):
    # the moment about it at the corner is still m a^2 / 6
    G = R0.point("G", a / 2, a / 2, a / 2)
    J = inertia.block(m, a, a, a, frame=R0, centre=G).moved(O, mass=m, centre=G)
    return J.moment_about(R0.i + R0.j + R0.k), m * a**2 / 6


def cylinder_about_a_generatrix():
    # generatrix at distance R from the axis: I = m R^2 / 2 + m R^2 = 3 m R^2 / 2
    G = R0.point("G", R, 0, 0)
    J = inertia.cylinder(m, R, L, axis=R0.k, centre=G).moved(O, mass=m, centre=G)
    return J.moment_about(R0.k), 3 * m * R**2 / 2


def ring_about_a_tangent_in_its_plane():
    # tangent parallel to a diameter at distance R: I = m R^2 / 2 + m R^2 = 3 m R^2 / 2
    G = R0.point("G", R, 0, 0)
    J = inertia.ring(m, R, axis=R0.k, centre=G).moved(O, mass=m, centre=G)
    return J.moment_about(R0.j), 3 * m * R**2 / 2


def sphere_about_a_tangent():
    # I = 2 m R^2 / 5 + m R^2 = 7 m R^2 / 5
    G = R0.point("G", 0, R, 0)
    J = inertia.sphere(m, R, frame=R0, centre=G).moved(O, mass=m, centre=G)
    return J.moment_about(R0.k), 7 * m * R**2 / 5


def cone_about_its_apex():
    # apex O, axis k0, base at z = h: int_0^h (pi rho (R z/h)^2 dz) z^2 = 3 m h^2 / 5 and
    # int (x^2) dm = 3 m R^2 / 20, so the moment about (O, i0) is 3 m (R^2 / 4 + h^2) / 5
    G = R0.point("G", 0, 0, 3 * h / 4)
    J = inertia.cone(m, R, h, axis=R0.k, centre=G).moved(O, mass=m, centre=G)
    return J.moment_about(R0.i), 3 * m * (R**2 / 4 + h**2) / 5


def block_with_a_cylindrical_hole():
    # associativity (ch. 15.4.4) with a part removed: block (m1; a, a, c) minus a coaxial
    # cylinder (m2; R, c) along k0: C = m1 a^2 / 6 - m2 R^2 / 2
    J = inertia.block(m1, a, a, c, frame=R0) - inertia.cylinder(m2, R, c, axis=R0.k)
    return J.C, m1 * a**2 / 6 - m2 * R**2 / 2


def square_plate_diagonal_from_a_corner():
    # principal axes at the corner of a square plate (ch. 15.2.3): by symmetry the diagonal
    # (i + j)/sqrt(2) is principal with moment m a^2 / 12 (the diagonal passes through G), the
    # other in-plane one is (i - j)/sqrt(2) with m a^2 / 3 + m a^2 / 4 = 7 m a^2 / 12
    G = R0.point("G", a / 2, a / 2, 0)
    J = inertia.rectangular_plate(m, a, a, frame=R0, centre=G).moved(O, mass=m, centre=G)
    moments, axes = J.principal_axes()
    got = sp.Matrix([moments[0], moments[1], *axes[1].components(R0)])
    return got, sp.Matrix([7 * m * a**2 / 12, m * a**2 / 12, sp.sqrt(2) / 2, sp.sqrt(2) / 2, 0])


def plane_solid_relation():
    # plane solid in (i, j) (ch. 15.3.3): C = A + B, here for a disk about its centre
    J = inertia.disk(m, R, axis=R0.k)
    return J.C, J.A + J.B


def double_pendulum_bar_about_the_pivot():
    # TOUR.md: bar of the double pendulum, attached to R1 rotating by q1 about k0; its
    # operator at O moved from G1 and expressed in R0 keeps C = m L^2 / 3 exactly
    q1 = coordinates("q1")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    G1 = O.moved("G1", L / 2 * R1.i)
    J = inertia.rod(m, L, axis=R1.i, centre=G1).moved(O, mass=m, centre=G1).in_basis(R0)
    return sp.Matrix([J.C, J.D, J.E]), sp.Matrix([m * L**2 / 3, 0, 0])


def tilted_rod_moment():
    # rod along i1 with i1 at angle theta from i0 in the plane (i0, j0): about (G, k0) the
    # moment is m L^2 / 12 whatever theta, about (G, i0) it is m L^2 sin^2(theta) / 12
    theta = sp.Symbol("theta")
    R1 = R0.rotated("R1", about=R0.k, angle=theta)
    J = inertia.rod(m, L, axis=R1.i).in_basis(R0)
    return sp.Matrix([J.C, J.moment_about(R0.i)]), sp.Matrix(
        [m * L**2 / 12, m * L**2 * sp.sin(theta) ** 2 / 12])


@pytest.mark.parametrize(
    "case",
    [
        pytest.param(rod_about_its_end, id="rod-about-its-end"),
        pytest.param(pendulum_rod_plus_disk, id="pendulum-rod-plus-disk"),
        pytest.param(block_about_an_edge, id="block-about-an-edge"),
        pytest.param(block_at_a_corner_products, id="block-corner-products"),
        pytest.param(cube_about_its_diagonal_from_a_corner, id="cube-diagonal"),
        pytest.param(cylinder_about_a_generatrix, id="cylinder-about-a-generatrix"),
        pytest.param(ring_about_a_tangent_in_its_plane, id="ring-about-a-tangent"),
        pytest.param(sphere_about_a_tangent, id="sphere-about-a-tangent"),
        pytest.param(cone_about_its_apex, id="cone-about-its-apex"),
        pytest.param(block_with_a_cylindrical_hole, id="block-with-a-hole"),
        pytest.param(square_plate_diagonal_from_a_corner, id="square-plate-principal-axes"),
        pytest.param(plane_solid_relation, id="plane-solid-C-equals-A-plus-B"),
        pytest.param(double_pendulum_bar_about_the_pivot, id="double-pendulum-bar"),
        pytest.param(tilted_rod_moment, id="tilted-rod"),
    ],
)
def test_chapter_15(case):
    got, expected = case()
    assert sp.simplify(sp.Matrix([got]) - sp.Matrix([expected])) == sp.zeros(
        *sp.Matrix([expected]).shape)


def test_numeric_pendulum_value():
    # the composite pendulum with numbers: m1 = 2, L = 1.5, m2 = 3, R = 0.2
    # I_O = 2 * 1.5^2 / 3 + 3 * (0.2^2 / 2 + 1.5^2) = 1.5 + 6.81 = 8.31 (to round-off)
    got, _ = pendulum_rod_plus_disk()
    value = float(got.subs({m1: 2, L: 1.5, m2: 3, R: 0.2}))
    assert value == pytest.approx(8.31, rel=1e-12)
    assert isinstance(inertia.rod(2, 1.5, axis=R0.i), InertiaOperator)
