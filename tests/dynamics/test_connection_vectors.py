"""Connection unknowns as vectors in any frame, the moment at any point (issue 22): the
pivot's reaction on a pendulum in R0, symbolically and along a simulation, against the
closed form R = -m g (3 cos q - 2 cos q0) e_r (energy and Newton's law, book ch. 18, 22)."""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ArgumentError

VALUES = dict(m=2.0, L=1.5, g=9.81)
Q0 = 1.2


def _pendulum():
    q = rm.coordinates("q")
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    bob = rm.Body("bob", frame=R1, mass=m, centre=R0.origin.moved("G", L * R1.i))
    s = rm.System(galilean=R0)
    s.connect(R0, bob, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.gravity(g * R0.i))          # q from the downward vertical R0.i
    return s, q, R0, bob


def _closed_form(q):
    """The pivot's action on the bob released at rest at Q0: along e_r = (cos q, sin q),
    -m g (3 cos q - 2 cos Q0) (q'^2 = 2 g / L (cos q - cos Q0), q'' = -g / L sin q)."""
    tension = VALUES["m"] * VALUES["g"] * (3 * np.cos(q) - 2 * math.cos(Q0))
    return -tension * np.cos(q), -tension * np.sin(q)


def test_the_pivot_reaction_in_R0_along_a_simulation_is_the_closed_form():
    s, q, R0, bob = _pendulum()
    sim = s.equations_of_motion().simulate(t=(0, 3), q0=[Q0], rtol=1e-11, atol=1e-12,
                                           n_output=301, **VALUES)
    N = sim.connection_action(R0, bob, basis=R0)
    X, Y = _closed_form(sim.q[0])
    scale = VALUES["m"] * VALUES["g"]
    np.testing.assert_allclose(N["X"], X, atol=1e-8 * scale)
    np.testing.assert_allclose(N["Y"], Y, atol=1e-8 * scale)
    np.testing.assert_allclose(N["Z"], 0.0, atol=1e-12 * scale)
    # the same vector from the symbolic torsor, evaluated along the motion
    R = sim.evaluate(s.connection_action(R0, bob).resultant, frame=R0)
    np.testing.assert_allclose(R, np.array([N["X"], N["Y"], N["Z"]]), atol=1e-12 * scale)


def test_the_moment_at_another_point_is_the_transport_of_the_reaction():
    # M(A) = M(O) + R x OA with M(O) = 0 for the pivot on the motion: A = (a, b, c) in R0
    s, q, R0, bob = _pendulum()
    a, b, c = 0.3, -0.7, 0.4
    A = R0.point("A", a, b, c)
    sim = s.equations_of_motion().simulate(t=(0, 2), q0=[Q0], rtol=1e-11, atol=1e-12,
                                           n_output=101, **VALUES)
    N = sim.connection_action(R0, bob, basis=R0, at=A)
    X, Y = _closed_form(sim.q[0])
    expected = np.cross(np.array([X, Y, 0 * X]).T, [a, b, c]).T
    scale = VALUES["m"] * VALUES["g"]
    np.testing.assert_allclose(np.array([N["L"], N["M"], N["N"]]), expected,
                               atol=1e-8 * scale)
    O = sim.connection_action(R0, bob, basis=R0)            # default: the joint's point
    np.testing.assert_allclose([O["L"], O["M"], O["N"]], 0.0, atol=1e-8 * scale)


def test_the_same_vectors_in_a_frame_that_turns():
    # in the pendulum's own frame R1 the reaction is along R1.i only: -m g (3 cos q - 2 cos q0)
    s, q, R0, bob = _pendulum()
    sim = s.equations_of_motion().simulate(t=(0, 2), q0=[Q0], rtol=1e-11, atol=1e-12,
                                           n_output=51, **VALUES)
    N = sim.connection_action(R0, bob, basis=bob.frame)
    tension = VALUES["m"] * VALUES["g"] * (3 * np.cos(sim.q[0]) - 2 * math.cos(Q0))
    np.testing.assert_allclose(N["X"], -tension, rtol=1e-8)
    np.testing.assert_allclose(N["Y"], 0.0, atol=1e-8 * VALUES["m"] * VALUES["g"])


def test_at_without_a_basis_is_refused():
    s, q, R0, bob = _pendulum()
    sim = s.equations_of_motion().simulate(t=(0, 1), q0=[Q0], n_output=3, **VALUES)
    with pytest.raises(ArgumentError, match="`at` needs `basis`"):
        sim.connection_action(R0, bob, at=R0.point("A", 1, 0, 0))


def test_symbolic_reaction_in_R0_on_the_motion():
    s, q, R0, bob = _pendulum()
    m, L, g = sp.symbols("m L g", positive=True)
    R = s.connection_action(R0, bob).resultant.components(R0)
    qd, qdd = q.diff(rm.t), q.diff(rm.t, 2)
    on_motion = R.subs(qdd, -g / L * sp.sin(q)).subs(
        qd**2, 2 * g / L * (sp.cos(q) - sp.cos(sp.Symbol("q0"))))
    q0 = sp.Symbol("q0")
    expected = -m * g * (3 * sp.cos(q) - 2 * sp.cos(q0)) * sp.Matrix([sp.cos(q), sp.sin(q), 0])
    assert sp.simplify(on_motion - expected) == sp.zeros(3, 1)
