"""Chapter 5, torsors: textbook-style exercises.

Conventions (the book's, ch. 5.1): a torsor is {R ; M(A)}; the moment field is
M(B) = M(A) + BA ^ R; the automoment is R . M(A); the comoment of {T1}, {T2} is
R1 . M2(A) + R2 . M1(A); the pitch is R . M / R^2; the central axis is the line of direction R
through I with AI = R ^ M(A) / R^2; the moment about an axis (P, u) is M(P) . u with u unit.
A measure centre G satisfies OG = int rho OP dmu / int rho dmu (ch. 5.3.3).

Each case returns (got, expected); the expected value is a closed form derived in the comment
of the case (by hand, independently of the library) or, for numbers, an independent numpy
computation. Symbolic cases compare by ``simplify(got - expected) == 0``; numeric cases by
``assert_allclose`` with the tolerance stated at the case.
"""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

from rigidmech import Frame, constants
from rigidmech.torsors import (
    Domain,
    Torsor,
    measure_centre,
    slider,
    torsor_of_field,
    torsor_of_sliders,
)
from rigidmech.vectors import Vector

F, a, b, c, d, R, h, L, q0, omega, C, alpha = constants(
    "F a b c d R h L q0 omega C alpha", positive=True)
rho, g, H = constants("rho g H", positive=True)
u, v, r, th, ph, x, z = sp.symbols("u v r theta phi x z")
R0 = Frame("R0")
O = R0.origin


def xyz(point):
    return point.coordinates(R0)


# -- symbolic exercises (ch. 5.1-5.2) ---------------------------------------------------------
def cube_three_forces_pitch():
    # cube of side a: F i at A(0, 0, a), F j at B(a, 0, 0), F k at C(0, a, 0).
    # R = F (i + j + k); M(O) = aF (k^i + i^j + j^k) = aF (i + j + k), parallel to R:
    # O is on the central axis (the body diagonal) and the pitch is 3aF^2 / 3F^2 = a.
    T = torsor_of_sliders([(R0.point("A", 0, 0, a), F * R0.i), (R0.point("B", a, 0, 0), F * R0.j),
                           (R0.point("C", 0, a, 0), F * R0.k)], at=O)
    return sp.Matrix([T.pitch, *xyz(T.central_point())]), sp.Matrix([a, 0, 0, 0])


def two_skew_forces_central_axis():
    # F i at O and F j at D(0, 0, d): R = F (i + j), M(O) = d k ^ F j = -dF i.
    # automoment -dF^2, pitch -d/2, OI = R ^ M / R^2 = -dF^2 (j ^ i) / 2F^2 = (d/2) k.
    T = torsor_of_sliders([(O, F * R0.i), (R0.point("D", 0, 0, d), F * R0.j)], at=O)
    return (sp.Matrix([T.automoment, T.pitch, *xyz(T.central_point())]),
            sp.Matrix([-d * F**2, -d / 2, 0, 0, d / 2]))


def moment_about_box_diagonal():
    # box a x b x c, force F k at P(a, 0, 0); axis: the diagonal from O to (a, b, c).
    # M(O) = a i ^ F k = -aF j; u = (a, b, c)/sqrt(a^2 + b^2 + c^2): M . u = -abF / |OD|.
    T = slider(F * R0.k, R0.point("P", a, 0, 0))
    return T.moment_about(O, direction=R0.vector(a, b, c)), -a * b * F / sp.sqrt(
        a**2 + b**2 + c**2)


def power_as_comoment():
    # body rotating about the z axis at rate omega: kinematic torsor {omega k ; 0} at O;
    # force F j at A(a, 0, 0): power = F . v(A) = F j . (omega k ^ a i) = a F omega (ch. 11.3).
    V = Torsor(resultant=omega * R0.k, moment=Vector.zero(), at=O)
    return slider(F * R0.j, R0.point("A", a, 0, 0)).comoment(V), a * F * omega


def wrench_resolved_at_a_point():
    # torsor {F k ; C k} at O resolved at B(b, 0, 0): the slider F k through B plus the couple
    # M(B) = C k + BO ^ F k = C k - b i ^ F k = C k + bF j.
    T = Torsor(resultant=F * R0.k, moment=C * R0.k, at=O)
    s, cp = T.resolve(R0.point("B", b, 0, 0))
    return cp.moment.components(R0), sp.Matrix([0, b * F, C])


def simplest_form_of_wrench():
    # {F i ; C i + aF k} at O: OI = F i ^ (C i + aF k) / F^2 = -a j; the least moment is
    # (R . M / R^2) R = (C/F) F i = C i.
    T = Torsor(resultant=F * R0.i, moment=C * R0.i + a * F * R0.k, at=O)
    form = T.simplest_form()
    return (sp.Matrix([*xyz(form.slider.point), *form.couple.moment.components(R0)]),
            sp.Matrix([0, -a, 0, C, 0, 0]))


def triangular_load_on_a_beam():
    # load q(x) = q0 x / L per unit length along -j on [0, L]: resultant q0 L / 2, slider
    # through x = int x q / int q = (q0 L^2/3) / (q0 L/2) = 2L/3.
    beam = Domain(R0, [x, 0, 0], (x, 0, L))
    T = torsor_of_field(-q0 * x / L * R0.j, beam)
    I = T.central_point()
    return sp.Matrix([T.resultant.dot(R0.j), *xyz(I)]), sp.Matrix([-q0 * L / 2, 2 * L / 3, 0, 0])


def hydrostatic_gate():
    # vertical gate of width b and depth H in the plane (x, z), water surface at z = H, pressure
    # rho g (H - z) along +j: resultant rho g b H^2 / 2, central axis at z = H/3.
    gate = Domain(R0, [u, 0, z], (u, 0, b), (z, 0, H))
    T = torsor_of_field(rho * g * (H - z) * R0.j, gate)
    I = T.central_point(near=R0.point("M", b / 2, 0, 0))
    return (sp.Matrix([T.resultant.dot(R0.j), *xyz(I)]),
            sp.Matrix([rho * g * b * H**2 / 2, b / 2, 0, H / 3]))


# -- measure centres (ch. 5.3.3, applications of ch. 12.3) ------------------------------------
def semicircular_wire():
    # x = R cos u, y = R sin u, u in [0, pi]: y_G = int R sin u R du / (pi R) = 2R/pi
    wire = Domain(R0, [R * sp.cos(u), R * sp.sin(u), 0], (u, 0, sp.pi))
    return xyz(measure_centre(1, wire)), sp.Matrix([0, 2 * R / sp.pi, 0])


def circular_arc_half_angle():
    # arc of half-angle alpha about i: x_G = int R cos u R du / (2 alpha R) = R sin(alpha)/alpha
    arc = Domain(R0, [R * sp.cos(u), R * sp.sin(u), 0], (u, -alpha, alpha))
    return xyz(measure_centre(1, arc)), sp.Matrix([R * sp.sin(alpha) / alpha, 0, 0])


def half_disk():
    # y_G = int r sin(th) r dr dth / (pi R^2/2) = (2 R^3/3) / (pi R^2/2) = 4R/(3 pi)
    plate = Domain(R0, [r * sp.cos(th), r * sp.sin(th), 0], (r, 0, R), (th, 0, sp.pi))
    return xyz(measure_centre(1, plate)), sp.Matrix([0, 4 * R / (3 * sp.pi), 0])


def circular_sector():
    # sector of half-angle alpha: x_G = (2R^3 sin(alpha)/3) / (alpha R^2) = 2R sin(alpha)/(3 alpha)
    plate = Domain(R0, [r * sp.cos(th), r * sp.sin(th), 0], (r, 0, R), (th, -alpha, alpha))
    return xyz(measure_centre(1, plate)), sp.Matrix([2 * R * sp.sin(alpha) / (3 * alpha), 0, 0])


def triangle_plate():
    # triangle O(0,0), (a, 0), (0, b): the centroid is the mean of the vertices (a/3, b/3)
    plate = Domain(R0, [u, v, 0], (v, 0, b * (1 - u / a)), (u, 0, a))
    return xyz(measure_centre(1, plate)), sp.Matrix([a / 3, b / 3, 0])


def hemispherical_shell():
    # z_G = int R cos(th) R^2 sin(th) / (2 pi R^2) over th in [0, pi/2] = R/2
    shell = Domain(R0, [R * sp.sin(th) * sp.cos(ph), R * sp.sin(th) * sp.sin(ph),
                        R * sp.cos(th)], (th, 0, sp.pi / 2), (ph, 0, 2 * sp.pi))
    return xyz(measure_centre(1, shell)), sp.Matrix([0, 0, R / 2])


def solid_hemisphere():
    # z_G = int r cos(th) r^2 sin(th) / (2 pi R^3/3) = (pi R^4/4) / (2 pi R^3/3) = 3R/8
    ball = Domain(R0, [r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph),
                       r * sp.cos(th)], (r, 0, R), (th, 0, sp.pi / 2), (ph, 0, 2 * sp.pi))
    return xyz(measure_centre(1, ball)), sp.Matrix([0, 0, 3 * R / 8])


def solid_cone():
    # base radius R at z = 0, apex at z = h; section area pi R^2 (1 - z/h)^2:
    # z_G = int z (1 - z/h)^2 dz / int (1 - z/h)^2 dz = (h^2/12) / (h/3) = h/4 from the base
    cone = Domain(R0, [r * sp.cos(th), r * sp.sin(th), z], (r, 0, R * (1 - z / h)),
                  (th, 0, 2 * sp.pi), (z, 0, h))
    return xyz(measure_centre(1, cone)), sp.Matrix([0, 0, h / 4])


def rod_with_linear_density():
    # rho = rho0 (1 + x/L) on [0, L]: x_G = int x(1 + x/L) / int (1 + x/L) = (5L/6) / (3/2) = 5L/9
    rod = Domain(R0, [x, 0, 0], (x, 0, L))
    return xyz(measure_centre(rho * (1 + x / L), rod)), sp.Matrix([5 * L / 9, 0, 0])


SYMBOLIC = [
    pytest.param(cube_three_forces_pitch, id="cube-three-forces-pitch"),
    pytest.param(two_skew_forces_central_axis, id="two-skew-forces-central-axis"),
    pytest.param(moment_about_box_diagonal, id="moment-about-box-diagonal"),
    pytest.param(power_as_comoment, id="power-as-comoment"),
    pytest.param(wrench_resolved_at_a_point, id="wrench-resolved-at-a-point"),
    pytest.param(simplest_form_of_wrench, id="simplest-form-of-wrench"),
    pytest.param(triangular_load_on_a_beam, id="triangular-load-on-a-beam"),
    pytest.param(hydrostatic_gate, id="hydrostatic-gate"),
    pytest.param(semicircular_wire, id="semicircular-wire-2R/pi"),
    pytest.param(circular_arc_half_angle, id="circular-arc-Rsin(a)/a"),
    pytest.param(half_disk, id="half-disk-4R/3pi"),
    pytest.param(circular_sector, id="circular-sector"),
    pytest.param(triangle_plate, id="triangle-plate"),
    pytest.param(hemispherical_shell, id="hemispherical-shell-R/2"),
    pytest.param(solid_hemisphere, id="solid-hemisphere-3R/8"),
    pytest.param(solid_cone, id="solid-cone-h/4"),
    pytest.param(rod_with_linear_density, id="rod-linear-density-5L/9"),
]


@pytest.mark.parametrize("case", SYMBOLIC)
def test_symbolic(case):
    got, expected = (sp.Matrix(e) if isinstance(e, sp.MatrixBase) else sp.Matrix([e])
                     for e in case())
    assert sp.simplify(got - expected) == sp.zeros(*got.shape)


# -- with numbers --------------------------------------------------------------------------------
def force_system_numbers():
    # five forces with float components; independent computation with numpy: R = sum F_i,
    # M(O) = sum OP_i x F_i, pitch R.M/R^2, central point R x M / R^2.
    rng = np.random.default_rng(5)
    P = rng.uniform(-2, 2, (5, 3))
    Fs = rng.uniform(-3, 3, (5, 3))
    T = torsor_of_sliders([(R0.point(f"P{k}", *map(float, P[k])),
                            Vector.from_components(R0, list(map(float, Fs[k]))))
                           for k in range(5)], at=O)
    Rn, Mn = Fs.sum(axis=0), np.cross(P, Fs).sum(axis=0)
    got = [*np.array(T.components(R0)[0], float).ravel(), *np.array(T.components(R0)[1],
           float).ravel(), float(T.pitch), *np.array(xyz(T.central_point()), float).ravel()]
    expected = [*Rn, *Mn, Rn @ Mn / (Rn @ Rn), *(np.cross(Rn, Mn) / (Rn @ Rn))]
    return got, expected, 1e-12  # a handful of float operations


def least_moment_numbers():
    # the central axis minimises |M|: compare |M(I)| with the minimum of |M(P)| over a grid of
    # points P (numpy); |M(I)| = |R.M|/|R| exactly, the grid minimum is not below it.
    T = Torsor(resultant=R0.vector(1.0, 2.0, -1.0), moment=R0.vector(0.5, -1.0, 3.0), at=O)
    Rn, M0 = np.array([1.0, 2.0, -1.0]), np.array([0.5, -1.0, 3.0])
    grid = np.stack(np.meshgrid(*[np.linspace(-3, 3, 41)] * 3), -1).reshape(-1, 3)
    M_grid = M0 + np.cross(-grid, Rn)  # M(P) = M(O) + PO ^ R
    least = np.linalg.norm(M_grid, axis=1).min()
    M_I = np.array(T.simplest_form().couple.moment.components(R0), float).ravel()
    assert least >= np.linalg.norm(M_I) - 1e-12
    return [np.linalg.norm(M_I)], [abs(Rn @ M0) / np.linalg.norm(Rn)], 1e-12


def hemisphere_numbers():
    # R = 2, Gauss-Legendre: z_G = 3R/8 = 0.75; the integrands are polynomials in r and
    # trigonometric in (theta, phi): 16 nodes per parameter give ~1e-15
    ball = Domain(R0, [r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph),
                       r * sp.cos(th)], (r, 0, 2), (th, 0, sp.pi / 2), (ph, 0, 2 * sp.pi))
    G = measure_centre(1, ball, method="numeric", order=16)
    return list(np.array(xyz(G), float).ravel()), [0, 0, 0.75], 1e-12


def half_disk_quad_numbers():
    # R = 1, scipy nquad: y_G = 4/(3 pi); quad's default tolerance 1.5e-8
    plate = Domain(R0, [r * sp.cos(th), r * sp.sin(th), 0], (r, 0, 1), (th, 0, sp.pi))
    G = measure_centre(1, plate, method="quad")
    return list(np.array(xyz(G), float).ravel()), [0, 4 / (3 * np.pi), 0], 1e-8


NUMERIC = [
    pytest.param(force_system_numbers, id="force-system-numpy"),
    pytest.param(least_moment_numbers, id="least-moment-on-central-axis"),
    pytest.param(hemisphere_numbers, id="solid-hemisphere-gauss-legendre"),
    pytest.param(half_disk_quad_numbers, id="half-disk-scipy-nquad"),
]


@pytest.mark.parametrize("case", NUMERIC)
def test_numeric(case):
    got, expected, rtol = case()
    assert_allclose(np.asarray(got, float), np.asarray(expected, float), rtol=rtol, atol=rtol)
