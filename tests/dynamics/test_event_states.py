"""The states at the events of a simulation (Simulation.at_events) and events on the
accelerations (an Event holding q''): issue 22, "what users reached for" (book, ch. 27)."""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.dynamics import Event
from rigidmech.errors import ArgumentError, ArgumentTypeError


def _pendulum(gravity_sign=1):
    """A point mass m at distance L from a pivot; q from the downward vertical R0.i (gravity
    g R0.i), or from the upward one when ``gravity_sign`` is -1 (a particle on a sphere)."""
    q = rm.coordinates("q")
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    bob = rm.Body("bob", frame=R1, mass=m, centre=R0.origin.moved("G", L * R1.i))
    s = rm.System(galilean=R0)
    s.connect(R0, bob, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.gravity(gravity_sign * g * R0.i))
    return s, q, R0, R1, bob


VALUES = dict(m=2.0, L=1.5, g=9.81)


def test_pendulum_states_at_its_zero_crossings_follow_the_energy():
    s, q, R0, R1, bob = _pendulum()
    q0 = 1.0
    sim = s.equations_of_motion().simulate(t=(0, 6), q0=[q0], events=[q], rtol=1e-11,
                                           atol=1e-12, **VALUES)
    at = sim.at_events(0)
    assert at.t.tolist() == sim.t_events[0].tolist() and len(at.t) >= 3
    g, L, m = VALUES["g"], VALUES["L"], VALUES["m"]
    speed = math.sqrt(2 * g / L * (1 - math.cos(q0)))       # (1/2) L q'^2 = g (cos q - cos q0)
    np.testing.assert_allclose(at.q[0], 0.0, atol=1e-10)
    np.testing.assert_allclose(np.abs(at.u[0]), speed, rtol=1e-9)
    assert np.all(at.u[0, :-1] * at.u[0, 1:] < 0)            # alternating directions
    # what is computed along a motion works at the events: the pivot's tension there,
    # m g + m L q'^2 = m g (3 - 2 cos q0), and q'' = -(g/L) sin q = 0
    np.testing.assert_allclose(at.evaluate(q.diff(rm.t, 2)), 0.0, atol=1e-9)
    N = at.connection_action(R0, bob, basis=R0)
    np.testing.assert_allclose(N["X"], -m * g * (3 - 2 * math.cos(q0)), rtol=1e-9)


def test_the_state_at_a_terminal_event_is_the_impact_velocity():
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-9.81]]))
    sim = eqs.simulate(t=(0, 10), q0=[20.0], events=[Event(x, terminal=True, direction=-1)])
    at = sim.at_events(0)
    assert sim.status == "event" and at.t.shape == (1,)
    assert at.q[0, 0] == pytest.approx(0.0, abs=1e-9)
    assert at.u[0, 0] == pytest.approx(-math.sqrt(2 * 9.81 * 20.0), rel=1e-10)  # -sqrt(2 g h)


def test_an_event_that_never_occurs_has_no_states_and_evaluates_to_empty():
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-x]]))
    sim = eqs.simulate(t=(0, 1), q0=[1.0], events=[x - 5])
    at = sim.at_events(0)
    assert at.t.shape == (0,) and at.q.shape == (1, 0) and at.u.shape == (1, 0)
    assert at.evaluate(x + 1).shape == (0,)


def test_states_at_events_of_reduced_equations_are_full_states():
    # a point on the line y = x, reduced to x: the states at the events hold y and y' too
    from rigidmech.dynamics import Constraints
    x, y = rm.coordinates("x y")
    eqs = rm.EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
                               forcing=sp.Matrix([-x, -y]), constraints=Constraints(
                                   (x, y), [("line", x.diff(rm.t) - y.diff(rm.t), x - y)]))
    sim = eqs.reduced(["x"]).simulate(t=(0, 3), q0=[1.0, 1.0], events=[x], rtol=1e-10,
                                      atol=1e-12)
    at = sim.at_events(0)
    assert at.t == pytest.approx([math.pi / 2], rel=1e-8)        # x = cos t
    np.testing.assert_allclose(at.q[:, 0], [0.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(at.u[:, 0], [-1.0, -1.0], rtol=1e-8)


def test_states_at_events_survive_npz_but_not_csv(tmp_path):
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-x]]))
    sim = eqs.simulate(t=(0, 4), q0=[1.0], events=[x])
    back = rm.Simulation.load(sim.save(tmp_path / "run.npz"))
    np.testing.assert_array_equal(back.at_events(0).u, sim.at_events(0).u)
    csv = rm.Simulation.load(sim.save(tmp_path / "run.csv"))
    with pytest.raises(ArgumentError, match="not known"):
        csv.at_events(0)


def test_at_events_refuses_an_index_that_names_no_event():
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-x]]))
    sim = eqs.simulate(t=(0, 1.2), q0=[1.0], events=[x, x - 0.5])   # x - 0.5 at pi/3
    assert sim.at_events(1).t.size == 1
    for bad in (2, -1):
        with pytest.raises(ArgumentError, match=r"`which` must be the index .* 0 to 1; got"):
            sim.at_events(bad)
    with pytest.raises(ArgumentTypeError, match="`which` must be the index"):
        sim.at_events("x")
    plain = eqs.simulate(t=(0, 1), q0=[1.0])
    with pytest.raises(ArgumentError, match="given no events"):
        plain.at_events(0)


# -- events on accelerations -----------------------------------------------------------------

def test_a_particle_leaves_a_sphere_where_the_normal_force_vanishes():
    # a point mass on a smooth sphere of radius L (the pivot's radial action is the normal
    # force, written with q''), released at rest at q0 from the top: it leaves where
    # N = 0, cos q = (2/3) cos q0 (energy and the radial equation)
    s, q, R0, R1, bob = _pendulum(gravity_sign=-1)
    torsor = s.connection_action(R0, bob)
    normal = torsor.resultant.dot(R1.i)           # the push of the sphere, along the radius
    assert normal.has(q.diff(rm.t, 2)) or normal.has(q.diff(rm.t))
    q0 = 0.1
    leave = Event(normal, terminal=True, direction=-1)
    sim = s.equations_of_motion().simulate(t=(0, 10), q0=[q0], events=[leave], rtol=1e-11,
                                           atol=1e-12, **VALUES)
    assert sim.status == "event"
    at = sim.at_events(0)
    assert math.cos(at.q[0, 0]) == pytest.approx(2 / 3 * math.cos(q0), rel=1e-9)


def test_an_event_on_an_acceleration_itself():
    # x'' = -k x + F: the acceleration crosses zero where x = F / k; x(t) = F/k (1 - cos 2t)
    x = rm.coordinates("x")
    k, F = sp.symbols("k F")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-k * x + F]]))
    sim = eqs.simulate(t=(0, 1.5), q0=[0.0], events=[x.diff(rm.t, 2)], rtol=1e-11,
                       atol=1e-12, k=4.0, F=2.0)
    assert sim.t_events[0] == pytest.approx([math.pi / 4], rel=1e-9)   # cos 2t = 0
    assert sim.at_events(0).q[0, 0] == pytest.approx(0.5, rel=1e-9)


def test_an_event_with_a_third_derivative_is_refused():
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-x]]))
    with pytest.raises(Exception, match="first two derivatives"):
        eqs.simulate(t=(0, 1), q0=[1.0], events=[x.diff(rm.t, 3)])
