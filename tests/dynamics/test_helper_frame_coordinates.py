"""A coordinate that moves a body only through the axes of a helper frame is a parameter of
situation of the system (issue 19, item 1): the position S = r Rp.i, Rp turned by phi about
k0, depends on phi through the basis of Rp, not through a component.

Reference values: a particle in polar coordinates (r, phi) under a force F_r er + F_phi ephi,

    m r'' - m r phi'^2 = F_r,      m r^2 phi'' + 2 m r r' phi' = r F_phi,

and the simple pendulum m L^2 theta'' = -m g L sin(theta) (theta from the downward vertical).
"""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.dynamics._tree import body_coordinates
from rigidmech.errors import FrameError

m, L, g = rm.constants("m L g", positive=True)
F_r, F_phi = rm.constants("F_r F_phi")


def polar_particle(connect_planar=False, force=False):
    r, phi = rm.coordinates("r phi")
    R0 = rm.Frame("R0")
    Rp = R0.rotated("Rp", about=R0.k, angle=phi)
    S = R0.origin.moved("S", r * Rp.i)
    sat = rm.Body("sat", frame=R0.translated("Rs", S), mass=m, centre=S)
    s = rm.System(galilean=R0)
    if connect_planar:
        s.connect(R0, sat, rm.joints.PlanarSupport(at=R0.origin, normal=R0.k))
    else:
        s.add(sat)
    if force:
        s.act(rm.Force(on=sat, vector=F_r * Rp.i + F_phi * Rp.j, at=S))
    return s, r, phi, sat


def check_polar(s, r, phi):
    eqs = s.equations_of_motion()
    assert eqs.coordinates == (r, phi)
    rd, pd = r.diff(rm.t), phi.diff(rm.t)
    assert sp.simplify(eqs.mass_matrix - sp.diag(m, m * r**2)) == sp.zeros(2, 2)
    expected = sp.Matrix([m * r * pd**2 + F_r, -2 * m * r * rd * pd + r * F_phi])
    assert sp.simplify(eqs.forcing - expected) == sp.zeros(2, 1)


def test_body_coordinates_include_the_helper_frame_angle():
    s, r, phi, sat = polar_particle()
    assert body_coordinates(sat) == [r, phi]
    assert s.coordinates == (r, phi)


def test_polar_particle_free_body():
    s, r, phi, _ = polar_particle(force=True)
    check_polar(s, r, phi)


def test_polar_particle_on_a_planar_support():
    s, r, phi, _ = polar_particle(connect_planar=True, force=True)
    check_polar(s, r, phi)


def test_partial_velocities_include_phi():
    s, r, phi, sat = polar_particle()
    from rigidmech.dynamics._derivation import partials
    (W_r, V_r), (W_phi, V_phi) = partials(s, sat, sat.centre)
    R0 = s.galilean
    assert W_r.is_zero and W_phi.is_zero
    assert sp.simplify(V_r.components(R0) - sp.Matrix([sp.cos(phi), sp.sin(phi), 0])) \
        == sp.zeros(3, 1)
    assert sp.simplify(V_phi.components(R0) - sp.Matrix([-r * sp.sin(phi), r * sp.cos(phi), 0])) \
        == sp.zeros(3, 1)


def test_particle_pendulum_on_a_translated_frame():
    th = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    Rt = R0.rotated("Rt", about=R0.k, angle=th)
    P = R0.origin.moved("P", L * Rt.i)
    bob = rm.Body("bob", frame=R0.translated("Rb", P), mass=m, centre=P)
    s = rm.System(galilean=R0)
    s.add(bob)
    s.act(rm.gravity(g * R0.i))            # i0 downward: theta from the downward vertical
    eqs = s.equations_of_motion()
    assert eqs.coordinates == (th,)
    assert sp.simplify(eqs.mass_matrix[0] - m * L**2) == 0
    assert sp.simplify(eqs.forcing[0] + m * g * L * sp.sin(th)) == 0


def test_the_helper_frame_of_a_frame_origin_counts_too():
    # the body's frame origin (not only its centre) placed through a helper frame's axes,
    # two levels deep: Rq turned by psi in Rp turned by phi
    r, phi, psi = rm.coordinates("r phi psi")
    R0 = rm.Frame("R0")
    Rp = R0.rotated("Rp", about=R0.k, angle=phi)
    Rq = Rp.rotated("Rq", about=Rp.k, angle=psi)
    O1 = R0.origin.moved("O1", r * Rq.i)
    body = rm.Body("b", frame=R0.translated("Rb", O1), mass=m, centre=O1)
    assert body_coordinates(body) == [r, phi, psi]


def test_constants_of_a_helper_frame_are_parameters_of_the_model():
    r = rm.coordinates("r")
    alpha = rm.constants("alpha")
    R0 = rm.Frame("R0")
    Ra = R0.rotated("Ra", about=R0.k, angle=alpha)
    S = R0.origin.moved("S", r * Ra.i)
    sat = rm.Body("sat", frame=R0.translated("Rs", S), mass=m, centre=S)
    s = rm.System(galilean=R0)
    s.add(sat)
    s.act(rm.gravity(-g * R0.j))
    assert alpha in s.equations_of_motion().forcing.free_symbols
    assert alpha in s.parameters


def test_constants_of_the_basis_of_an_action_are_parameters_of_the_model():
    x = rm.coordinates("x")
    beta, F = rm.constants("beta F")
    R0 = rm.Frame("R0")
    Rb = R0.rotated("Rb", about=R0.k, angle=beta)
    P = R0.point("P", x, 0, 0)
    cart = rm.Body("cart", frame=R0.translated("Rc", P), mass=m, centre=P)
    s = rm.System(galilean=R0)
    s.add(cart)
    s.act(rm.Force(on=cart, vector=F * Rb.i, at=P))
    assert sp.simplify(s.equations_of_motion().forcing[0] - F * sp.cos(beta)) == 0
    assert beta in s.parameters


def test_a_galilean_frame_placed_on_a_turning_helper_frame_is_refused():
    # its origin r0 Rt.i moves with Rt (turning with time) though no component has t
    R0 = rm.Frame("R0")
    Rt = R0.rotated("Rt", about=R0.k, angle=2 * rm.t)
    Rg = R0.translated("Rg", R0.origin.moved("O1", 3 * Rt.i))
    with pytest.raises(FrameError, match=r"`galilean` frame Rg moves relative to the root"):
        rm.System(galilean=Rg)
