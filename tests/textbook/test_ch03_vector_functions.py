"""Textbook-style exercises of chapter 3 (vector functions and their derivatives), with
rigidmech.vectors.functions.

Conventions (book, ch. 3): R0 = (O; i, j, k) is fixed; the polar basis (e_r, e_theta, k) is the
basis (i1, j1, k) of the frame R1 obtained by turning R0 by theta(t) about k; derivatives are
taken relative to the frame named in each case, with the derivation formula
d/dt|R0 u = d/dt|R1 u + omega(R1/R0) ^ u. Expected values are the classical closed forms
written out in each case's comment.
"""

import pytest
import sympy as sp

from rigidmech.vectors import Frame, coordinates, t
from rigidmech.vectors.functions import derivation_formula, derivative, jacobian, partial

R0 = Frame("R0")
r, theta, z = coordinates("r theta z")
R1 = R0.rotated("R1", about=R0.k, angle=theta)  # (e_r, e_theta, k)
e_r, e_th = R1.i, R1.j
rd, thd = r.diff(t), theta.diff(t)
a = sp.Symbol("a", positive=True)
x, y = sp.symbols("x y", real=True)
th, ph = sp.symbols("theta_s phi_s", real=True)


def spherical(th_, ph_):
    return R0.vector(sp.sin(th_) * sp.cos(ph_), sp.sin(th_) * sp.sin(ph_), sp.cos(th_))


CASES = [
    # 3.1.4: d e_r/dt|R0 = theta' e_theta, d e_theta/dt|R0 = -theta' e_r.
    pytest.param(lambda: derivative(e_r, t, R0), thd * e_th, R0, id="3.1.4-derivative-of-e_r"),
    pytest.param(lambda: derivative(e_th, t, R0), -thd * e_r, R0,
                 id="3.1.4-derivative-of-e_theta"),
    # 3.1.4: OM = r e_r + z k: velocity r' e_r + r theta' e_theta + z' k.
    pytest.param(lambda: derivative(r * e_r + z * R0.k, t, R0),
                 rd * e_r + r * thd * e_th + z.diff(t) * R0.k, R0, id="3.1.4-cylindrical-velocity"),
    # 3.1.4: acceleration (r'' - r theta'^2) e_r + (2 r' theta' + r theta'') e_theta + z'' k.
    pytest.param(lambda: derivative(r * e_r + z * R0.k, t, R0, order=2),
                 (r.diff(t, 2) - r * thd**2) * e_r + (2 * rd * thd + r * theta.diff(t, 2)) * e_th
                 + z.diff(t, 2) * R0.k, R0, id="3.1.4-cylindrical-acceleration"),
    # 3.1.4: relative to R1 the basis is fixed: d(r e_r)/dt|R1 = r' e_r, and the derivation
    # formula adds omega(R1/R0) ^ r e_r = theta' k ^ r e_r = r theta' e_theta.
    pytest.param(lambda: derivative(r * e_r, t, R1), rd * e_r, R1, id="3.1.4-relative-to-R1"),
    pytest.param(lambda: derivation_formula(r * e_r, R0, R1), rd * e_r + r * thd * e_th, R0,
                 id="3.1.4-derivation-formula"),
    # 3.1.3: d(u ^ v)/dt = u' ^ v + u ^ v' with u = a e_r, v = k: a theta' e_theta ^ k =
    # a theta' e_r (and u ^ v = -a e_theta, whose derivative is indeed a theta' e_r).
    pytest.param(lambda: derivative((a * e_r).cross(R0.k), t, R0), a * thd * e_r, R0,
                 id="3.1.3-derivative-of-a-vector-product"),
    # 3.2.2: u(theta, phi) the unit radial vector of spherical coordinates:
    # du/dtheta = (cos th cos ph, cos th sin ph, -sin th) = e_theta (spherical).
    pytest.param(lambda: partial(spherical(th, ph), th, R0),
                 R0.vector(sp.cos(th) * sp.cos(ph), sp.cos(th) * sp.sin(ph), -sp.sin(th)), R0,
                 id="3.2.2-partial-spherical-theta"),
    # 3.2.2: d2u/dtheta dphi = (-cos th sin ph, cos th cos ph, 0).
    pytest.param(lambda: partial(spherical(th, ph), (th, ph), R0),
                 R0.vector(-sp.cos(th) * sp.sin(ph), sp.cos(th) * sp.cos(ph), 0), R0,
                 id="3.2.2-mixed-partial"),
    # 3.2.3: u = x^2 y i + x y^2 j: d2u/dx dy = 2x i + 2y j.
    pytest.param(lambda: partial(x**2 * y * R0.i + x * y**2 * R0.j, (x, y), R0),
                 2 * x * R0.i + 2 * y * R0.j, R0, id="3.2.3-polynomial-mixed-partial"),
]


@pytest.mark.parametrize(("compute", "expected", "frame"), CASES)
def test_chapter_3(compute, expected, frame):
    assert compute().equals(expected, frame=frame)


def test_3_3_jacobian_of_cylindrical_coordinates():
    # 3.3: OM(rho, phi, h) = rho cos phi i + rho sin phi j + h k; the Jacobian determinant is
    # rho (the volume element rho drho dphi dh).
    rho, phi_, h = sp.symbols("rho phi h", positive=True)
    J = jacobian(R0.vector(rho * sp.cos(phi_), rho * sp.sin(phi_), h), (rho, phi_, h), R0)
    assert sp.simplify(J.det() - rho) == 0
