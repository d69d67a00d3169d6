"""Body.particle (ch. 15.5.1, 18, 21): a point mass with a translated frame and no inertia.

Checks: its kinetic energy (1/2) m v^2 of the point, and the equations and motion of the
particle pendulum against the closed forms m L^2 q'' + m g L sin q = 0 and, for a large
amplitude, the exact motion with Jacobi's elliptic functions (rigidmech.testing.problems)."""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.kinetics import Body
from rigidmech.testing import problems


def test_particle_body_attributes():
    x, y = rm.coordinates("x y")
    R0 = rm.Frame("R0")
    P = R0.point("P", x, y, 0)
    b = Body.particle("b", P, mass=2)
    assert b.mass == 2
    assert b.centre == P
    assert b.frame.origin == P
    assert b.frame.name == "R_b"
    assert b.inertia is None
    assert b.frame.dcm(R0) == sp.eye(3)              # the basis of R0, translated
    ke = b.kinetic_energy(R0)
    assert sp.simplify(ke - (x.diff(rm.t) ** 2 + y.diff(rm.t) ** 2)) == 0


def test_particle_in_another_basis_and_frame_name():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    P = R0.origin.moved("P", 2 * R1.i)
    b = Body.particle("bob", P, mass=1, basis=R1, frame_name="Rp")
    assert b.frame.name == "Rp" and b.frame.dcm(R1) == sp.eye(3)
    # the kinetic energy is that of the point only, whatever the basis turns
    assert sp.simplify(b.kinetic_energy(R0) - 2 * q.diff(rm.t) ** 2) == 0


def particle_pendulum():
    q = rm.coordinates("q")
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    P = R0.origin.moved("P", -L * R1.j)               # hangs along -j0 at q = 0
    s = rm.System(galilean=R0)
    s.add(Body.particle("bob", P, mass=m))
    s.act(rm.gravity(-g * R0.j))
    return s.equations_of_motion(), (q, m, L, g)


def test_particle_pendulum_equation_is_the_closed_form():
    # m L^2 q'' = -m g L sin q
    eqs, (q, m, L, g) = particle_pendulum()
    assert sp.simplify(eqs.mass_matrix[0, 0] - m * L**2) == 0
    assert sp.simplify(eqs.forcing[0] + m * g * L * sp.sin(q)) == 0
    assert sp.simplify(eqs.accelerations()[0] + g / L * sp.sin(q)) == 0


def test_particle_pendulum_motion_against_elliptic_exact_solution():
    eqs, _ = particle_pendulum()
    theta0_deg, L, g = 150.0, 0.8, 9.81
    ref = problems.pendulum(theta0_deg, omega0=math.sqrt(g / L), periods=2.0)
    sim = eqs.simulate(t=ref.t_span, q0=[math.radians(theta0_deg)], u0=[0.0], m=1.3, L=L, g=g,
                       rtol=1e-11, atol=1e-12, n_output=201)
    exact = ref.exact(sim.t)
    assert np.max(np.abs(sim.q[0] - exact[0])) < 1e-7
    assert np.max(np.abs(sim.u[0] - exact[1])) < 1e-6


@pytest.mark.parametrize(("kwargs", "error", "match"), [
    (dict(mass=None), ArgumentError, r"`mass` must be given for a particle"),
    (dict(mass=-1.0), ArgumentError, r"`mass`"),
    (dict(at="P"), ArgumentTypeError, r"`at` must be a Point"),
    (dict(basis="R0"), ArgumentTypeError, r"`basis` must be a Frame"),
    (dict(name=""), ArgumentError, r"`name` must be a non-empty string"),
    (dict(name=3), ArgumentError, r"`name` must be a non-empty string"),
])
def test_particle_bad_input(kwargs, error, match):
    R0 = rm.Frame("R0")
    args = dict(name="b", at=R0.point("P", 1, 0, 0), mass=1.0) | kwargs
    with pytest.raises(error, match=match):
        Body.particle(args.pop("name"), args.pop("at"), **args)


def test_zero_mass_particle_accepted():
    R0 = rm.Frame("R0")
    assert Body.particle("b", R0.point("P", 1, 0, 0), mass=0).mass == 0
