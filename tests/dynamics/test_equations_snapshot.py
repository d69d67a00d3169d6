"""Equations are a snapshot; coordinates come in a documented order; q0/u0 by name; parameters
that dropped out of the equations are accepted with a note.

Reference values: a free body (mass m, inertia operator diag(A, B, C) about its centre of
mass, book ch. 15) in uniform gravity -g R0.k, positioned by the coordinates (x, y, z) of its
centre and oriented by Euler angles (psi, theta, phi), z-x-z (ch. 9.1.2). Its centre falls
freely: z(t) = z0 + w0 t - g t^2 / 2, x(t) = x0 + u0 t; with no initial rotation rate the
orientation stays constant (no torque about G).
"""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech._core.errors import ArgumentError


def free_body():
    x, y, z, psi, theta, phi = rm.coordinates("x y z psi theta phi")
    m, g, A, B, C = rm.constants("m g A B C", positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, z)
    R = R0.euler("R", psi, theta, phi, origin=G)
    body = rm.Body("b", frame=R, mass=m, centre=G,
                   inertia=rm.InertiaOperator.from_products(A, B, C, frame=R, at=G))
    system = rm.System(galilean=R0)
    system.add(body)
    system.act(rm.gravity(-g * R0.k))
    return system, (x, y, z, psi, theta, phi)


def pendulum():
    q = rm.coordinates("q")
    m, L, g = rm.constants("m L g", positive=True)
    A, B, C = rm.constants("A B C", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", L * R1.i)
    # a planar motion: only C, the moment about the axis of rotation, enters the equations
    bar = rm.Body("bar", frame=R1, mass=m, centre=G,
                  inertia=rm.InertiaOperator.from_products(A, B, C, frame=R1, at=G))
    system = rm.System(galilean=R0)
    system.connect(R0, bar, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    system.act(rm.gravity(g * R0.i))
    return system, bar, R0, q


# -- 3. snapshot --
def test_equations_are_a_snapshot_of_the_system():
    system, bar, R0, q = pendulum()
    eqs = system.equations_of_motion()
    energy, forcing = eqs.energy, eqs.forcing
    system.act(rm.Couple(on=bar, moment=sp.Symbol("c") * rm.t * R0.k))  # no potential energy
    assert system.mechanical_energy() is None
    assert eqs.energy == energy and energy is not None
    assert eqs.forcing == forcing
    assert system.equations_of_motion() is not eqs


def test_energy_of_equations_is_taken_when_they_are_derived():
    system, bar, R0, q = pendulum()
    eqs = system.equations_of_motion()
    system.act(rm.Couple(on=bar, moment=sp.Symbol("c") * rm.t * R0.k))
    # the energy was not asked before the change: it is still that of the old system
    m, L, g, C = rm.constants("m L g C", positive=True)
    qd = q.diff(rm.t)
    expected = (C + m * L**2) * qd**2 / 2 - m * g * L * sp.cos(q)
    assert sp.simplify(eqs.energy - expected) == 0


# -- 4. order of the coordinates --
def test_free_body_coordinates_position_then_orientation():
    system, coords = free_body()
    assert system.coordinates == coords
    assert system.equations_of_motion().coordinates == coords


def test_given_coordinates_override_the_order():
    system, (x, y, z, psi, theta, phi) = free_body()
    s2 = rm.System(galilean=system.galilean, coordinates=(psi, theta, phi, x, y, z))
    s2.add(system.bodies[0])
    assert s2.coordinates == (psi, theta, phi, x, y, z)


def test_chain_coordinates_in_the_order_of_the_bodies():
    q1, q2 = rm.coordinates("q2 q1")  # names that sort the other way
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.k, angle=q2)
    A = R0.origin.moved("A", R1.i)
    b1 = rm.Body("b1", frame=R1, mass=1, centre=R0.origin)
    b2 = rm.Body("b2", frame=R2, mass=1, centre=A)
    s = rm.System(galilean=R0)
    s.connect(R0, b1, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(b1, b2, rm.joints.Pivot(at=A, axis=R0.k))
    assert s.coordinates == (q1, q2)


def test_declared_order_wins_over_the_structure():
    theta, x = rm.coordinates("theta x")  # the pendulum's angle declared first
    R0 = rm.Frame("R0")
    P = R0.point("P", x, 0, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=theta, origin=P)
    cart = rm.Body("cart", frame=R0.translated("Rc", P), mass=1, centre=P)
    rod = rm.Body("rod", frame=R1, mass=1, centre=P.moved("G", R1.i))
    s = rm.System(galilean=R0)
    s.add(cart)
    s.connect(cart, rod, rm.joints.Pivot(at=P, axis=R0.k))
    assert s.coordinates == (theta, x)


def test_dynamicsymbols_free_body_position_then_orientation():
    from sympy.physics.mechanics import dynamicsymbols

    x, y, z, psi, theta, phi = dynamicsymbols("x y z psi theta phi")
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, z)
    s = rm.System(galilean=R0)
    s.add(rm.Body("b", frame=R0.euler("R", psi, theta, phi, origin=G), mass=1, centre=G))
    assert s.coordinates == (x, y, z, psi, theta, phi)


# -- 4. q0 and u0 by name --
def test_initial_state_by_name_falls_freely():
    system, (x, y, z, psi, theta, phi) = free_body()
    eqs = system.equations_of_motion()
    values = {"m": 2.0, "g": 9.81, "A": 1.0, "B": 2.0, "C": 3.0}
    sim = eqs.simulate(t=(0.0, 1.0), q0={"z": 1.0, "psi": 0.2, theta: 0.7},
                       u0={"x": 0.5, "z": 2.0}, n_output=5, rtol=1e-11, atol=1e-12,
                       **values)
    tt = sim.t
    assert_allclose(sim.q[0], 0.5 * tt, atol=1e-9)                     # x
    assert_allclose(sim.q[1], 0.0, atol=1e-12)                          # y
    assert_allclose(sim.q[2], 1.0 + 2.0 * tt - 9.81 * tt**2 / 2, atol=1e-9)  # z
    assert_allclose(sim.q[3:], np.array([[0.2], [0.7], [0.0]]) * np.ones_like(tt),
                    atol=1e-9)


def test_initial_state_names_must_be_coordinates():
    eqs = free_body()[0].equations_of_motion()
    values = {"m": 2.0, "g": 9.81, "A": 1.0, "B": 2.0, "C": 3.0}
    with pytest.raises(ArgumentError, match=r"`q0` .*'w'.*x, y, z, psi, theta, phi"):
        eqs.simulate(t=(0, 1), q0={"w": 1.0, "theta": 0.7}, **values)
    with pytest.raises(ArgumentError, match=r"`u0` .*'xdot'"):
        eqs.simulate(t=(0, 1), q0={"theta": 0.7}, u0={"xdot": 1.0}, **values)


# -- 4. parameters that dropped out --
def test_parameters_that_dropped_out_are_accepted_with_a_note():
    system, *_ = pendulum()
    eqs = system.equations_of_motion()
    assert [p.name for p in eqs.parameters] == ["C", "L", "g", "m"]
    values = {"A": 1.0, "B": 2.0, "C": 0.5, "L": 1.0, "g": 9.81, "m": 2.0}
    fun = eqs.rhs(**values)
    assert_allclose(fun(0.0, np.array([0.3, 0.0]))[1],
                    -2.0 * 9.81 * 1.0 * np.sin(0.3) / (0.5 + 2.0 * 1.0**2), rtol=1e-14)
    assert any("A, B" in note for note in fun.notes)
    sim = eqs.simulate(t=(0.0, 0.1), q0={"q": 0.3}, n_output=3, **values)
    assert any("A, B" in note and "ignored" in note for note in sim.notes)


def test_unknown_parameters_are_still_refused():
    eqs = pendulum()[0].equations_of_motion()
    values = {"C": 0.5, "L": 1.0, "g": 9.81, "m": 2.0}
    with pytest.raises(ArgumentError, match=r"unknown parameters \['mass'\]"):
        eqs.rhs(mass=3.0, **values)


def test_a_scene_parameter_that_dropped_out_is_noted_not_refused():
    """The pipeline behind the command line's --param: the scene passes all its parameters,
    one of which (A, a moment of inertia about an axis the bar never turns about) drops out."""
    from rigidmech import scenes

    def builder():
        system, bar, _, _ = pendulum()
        return scenes.Built(system=system, bodies=(bar,))

    scene = scenes.Scene("bar", "bar on a pivot", "ch. 22", coordinates=("q",),
                         parameters=[(p, 1.0, p) for p in ("A", "B", "C", "L", "g", "m")],
                         q0=(0.3,), builder=builder, t_end=0.1)
    report = scenes.run(scene, params={"A": 2.0})
    assert any("A, B" in note for note in report.simulation.notes)
    assert "note: parameters A, B do not enter the equations" in report.summary()
