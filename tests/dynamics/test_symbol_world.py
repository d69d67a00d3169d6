"""One symbol world (ARCHITECTURE principle 6): every result a System returns is written with
the user's q(t), q'(t), q''(t) (rigidmech coordinates or sympy.physics.mechanics
dynamicsymbols) and accepts them in ``subs``, evaluation and compilation, together with
specified inputs (functions of time that are not coordinates).

Reference values are closed forms of the systems used:

* compound pendulum: uniform bar (mass m, length L) pivoting about R0.k at one end, gravity
  g R0.i, angle q from R0.i. Moment of inertia about the pivot m L^2 / 3 (ch. 15), torque of
  gravity -m g (L/2) sin q, kinetic energy (1/2)(m L^2/3) q'^2, potential -m g (L/2) cos q;
* slider: a point mass m on R0.i pushed by a force F(t) R0.i: m x'' = F(t), hence from rest at
  0 with F = cos t, x(t) = (1 - cos t) / m.
"""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from sympy.physics import mechanics as me

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, CompilationError


def pendulum(q, *, torque=None):
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", L / 2 * R1.i)
    bar = rm.Body("bar", frame=R1, mass=m, centre=G,
                  inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G))
    system = rm.System(galilean=R0)
    system.connect(R0, bar, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    system.act(rm.gravity(g * R0.i))
    if torque is not None:
        system.act(rm.Couple(on=bar, moment=torque * R0.k))
    return system, bar, R0, (m, L, g)


def slider(force):
    m = rm.constants("m", positive=True)
    x = rm.coordinates("x")
    R0 = rm.Frame("R0")
    P = R0.point("P", x, 0, 0)
    cart = rm.Body("cart", frame=R0.translated("R1", P), mass=m, centre=P)
    system = rm.System(galilean=R0)
    system.add(cart)
    system.act(rm.Force(on=cart, vector=force * R0.i, at=P))
    return system, x, m


# -- results accept the user's q(t) --
def test_forcing_substitutes_the_users_coordinate():
    q = rm.coordinates("q")
    system, _, _, (m, L, g) = pendulum(q)
    eqs = system.equations_of_motion()
    assert eqs.forcing.subs(q, 0.3) == sp.Matrix([[-m * g * L * sp.sin(0.3) / 2]])
    assert eqs.mass_matrix == sp.Matrix([[m * L**2 / 3]])
    acc = eqs.accelerations().subs(q, 0.3)
    assert sp.simplify(acc[0] + 3 * g * sp.sin(0.3) / (2 * L)) == 0


def test_energy_and_generalized_forces_substitute_the_users_coordinate():
    q = rm.coordinates("q")
    system, _, _, (m, L, g) = pendulum(q)
    qd = q.diff(rm.t)
    expected = m * L**2 * qd**2 / 6 - m * g * L * sp.cos(q) / 2
    eqs = system.equations_of_motion()
    assert sp.simplify(eqs.energy - expected) == 0
    assert sp.simplify(system.mechanical_energy() - expected) == 0
    value = eqs.energy.subs({qd: 2.0, q: 0.3})
    assert sp.simplify(value - expected.subs({qd: 2.0, q: 0.3})) == 0
    assert system.generalized_forces().subs(q, 0.3) == sp.Matrix([[-m * g * L * sp.sin(0.3) / 2]])


def test_lagrange_equations_are_written_with_the_users_coordinate():
    q = rm.coordinates("q")
    system, _, _, (m, L, g) = pendulum(q)
    eqs = rm.lagrange_equations(system)
    assert sp.simplify(eqs.forcing.subs(q, 0.3)[0] + m * g * L * sp.sin(0.3) / 2) == 0
    assert eqs.coordinates == (q,)


def test_connection_components_are_those_of_the_connection_action():
    q = rm.coordinates("q")
    system, bar, R0, _ = pendulum(q)
    comps = system.connection_components(R0, bar)
    _, joint = system.joint(bar)
    direct = joint.components(system.connection_action(R0, bar))
    assert set(comps) == set(direct)
    for name, value in comps.items():
        assert sp.simplify(value - direct[name]) == 0, name
    # the user's q, q', q'' substitute into them: no free symbol named q is left
    t = rm.t
    values = {q.diff(t, 2): 0.5, q.diff(t): 2.0, q: 0.3}
    for value in comps.values():
        assert not value.subs(values).atoms(sp.Symbol) - set(rm.constants("m L g",
                                                                           positive=True))


def test_printing_tells_the_coordinate_from_a_symbol():
    q = rm.coordinates("q")
    eqs = pendulum(q)[0].equations_of_motion()
    assert "q(t)" in str(eqs.forcing)
    # a constant of the user's named like the coordinate stays distinct
    assert not eqs.forcing.has(sp.Symbol("q", real=True))


# -- evaluation along a motion --
def test_simulation_evaluates_expressions_of_the_users_coordinates():
    q = rm.coordinates("q")
    system, _, _, (m, L, g) = pendulum(q)
    eqs = system.equations_of_motion()
    values = {"m": 2.0, "L": 1.5, "g": 9.81}
    sim = eqs.simulate(t=(0.0, 1.0), q0=[0.4], n_output=11, **values)
    T = sim.evaluate(system.kinetic_energy())
    assert_allclose(T, 2.0 * 1.5**2 / 6 * sim.u[0] ** 2, rtol=1e-12)
    # any expression of t, q, q' and the parameters
    e = sim.evaluate(rm.t * sp.cos(q) + L * q.diff(rm.t))
    assert_allclose(e, sim.t * np.cos(sim.q[0]) + 1.5 * sim.u[0], rtol=1e-12)
    # q'' is the solution of the equations of motion: -3 g sin q / (2 L)
    acc = sim.evaluate(q.diff(rm.t, 2))
    assert_allclose(acc, -3 * 9.81 * np.sin(sim.q[0]) / (2 * 1.5), rtol=1e-12)


def test_connection_components_evaluate_along_the_motion():
    """A perfect pivot transmits no moment about its axis (ch. 13.2.2): N, written with q''
    among others, vanishes once q'' solves the equations of motion; the resultant is
    m a(G) - m g (ch. 18.2) with a(G) from the closed form of a point at L/2 on the bar."""
    q = rm.coordinates("q")
    system, bar, R0, (m, L, g) = pendulum(q)
    sim = system.equations_of_motion().simulate(t=(0.0, 2.0), q0=[1.0], n_output=9,
                                                m=2.0, L=1.5, g=9.81)
    comps = system.connection_components(R0, bar)
    assert_allclose(sim.evaluate(comps["N"]), 0.0, atol=1e-12)
    qq, w = sim.q[0], sim.u[0]
    a = -3 * 9.81 * np.sin(qq) / (2 * 1.5)
    # a(G) = (L/2)(q'' j1 - q'^2 i1) with i1 = (cos q, sin q), j1 = (-sin q, cos q)
    ax = 0.75 * (-a * np.sin(qq) - w**2 * np.cos(qq))
    ay = 0.75 * (a * np.cos(qq) - w**2 * np.sin(qq))
    resultant = sim.evaluate(system.connection_action(R0, bar).resultant.components(R0))
    assert_allclose(resultant[:2, 0], [2.0 * ax - 2.0 * 9.81, 2.0 * ay], atol=1e-10)


# -- sympy.physics.mechanics dynamicsymbols --
def test_time_is_sympys_dynamicsymbols_time():
    assert rm.t == me.dynamicsymbols._t


def test_dynamicsymbols_are_coordinates():
    q = me.dynamicsymbols("q")
    system, _, _, (m, L, g) = pendulum(q)
    assert system.coordinates == (q,)
    eqs = system.equations_of_motion()
    assert eqs.forcing.subs(q, 0.3) == sp.Matrix([[-m * g * L * sp.sin(0.3) / 2]])
    values = {"m": 1.0, "L": 1.0, "g": 9.81}
    y = np.array([0.3, 0.0])
    assert_allclose(eqs.rhs(**values)(0.0, y), [0.0, -3 * 9.81 * np.sin(0.3) / 2],
                    rtol=1e-14)


# -- specified inputs --
def test_a_function_of_time_is_an_input():
    F = sp.Function("F")(rm.t)
    system, x, m = slider(F)
    eqs = system.equations_of_motion()
    assert eqs.inputs == (F,)
    assert eqs.forcing == sp.Matrix([[F]])
    assert eqs.parameters == (m,)
    fun = eqs.rhs(m=2.0, F=4.0)
    assert_allclose(fun(0.0, np.array([0.0, 0.0])), [0.0, 2.0], rtol=1e-15)
    fun = eqs.rhs(m=2.0, F=lambda t: 3.0 * t)
    assert_allclose(fun(1.5, np.array([0.0, 0.0])), [0.0, 2.25], rtol=1e-15)
    sim = eqs.simulate(t=(0.0, 3.0), q0=[0.0], rtol=1e-11, atol=1e-13, m=2.0, F=np.cos)
    assert_allclose(sim.q[0], (1 - np.cos(sim.t)) / 2.0, atol=1e-9)
    assert_allclose(sim.evaluate(F * x.diff(rm.t)), np.cos(sim.t) * sim.u[0], rtol=1e-12)


def test_a_missing_input_is_named():
    F = sp.Function("F")(rm.t)
    eqs = slider(F)[0].equations_of_motion()
    with pytest.raises(ArgumentError, match=r"missing values for .*\['F'\]"):
        eqs.rhs(m=2.0)


def test_a_control_torque_is_a_callable_input():
    q = rm.coordinates("q")
    u = sp.Function("u")(rm.t)
    system, _, _, _ = pendulum(q, torque=u)
    eqs = system.equations_of_motion()
    assert eqs.inputs == (u,)
    values = {"m": 3.0, "L": 1.0, "g": 0.0}
    # a constant torque C on a bar of inertia m L^2/3 from rest: q = (3 C / (2 m L^2)) t^2
    sim = eqs.simulate(t=(0.0, 1.0), q0=[0.0], rtol=1e-11, atol=1e-13, u=lambda t: 0.5,
                       **values)
    assert_allclose(sim.q[0], 0.5 * sim.t**2 / 2, atol=1e-10)


def test_an_input_derivative_is_refused_clearly():
    F = sp.Function("F")(rm.t)
    eqs = slider(F.diff(rm.t))[0].equations_of_motion()
    with pytest.raises(CompilationError, match="Derivative"):
        eqs.rhs(m=1.0, F=np.sin)


# -- equations written by hand -----------------------------------------------------------------
def test_equations_given_with_stand_in_symbols_are_rewritten_with_the_coordinates():
    x = rm.coordinates("x")
    xs, vs, k, c = sp.symbols("x_s v_s k c")
    eqs = rm.EquationsOfMotion(coordinates=(x,), q=(xs,), u=(vs,),
                               mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-k * xs - c * vs]]),
                               energy=(vs**2 + k * xs**2) / 2)
    xd = x.diff(rm.t)
    assert eqs.forcing == sp.Matrix([[-k * x - c * xd]])
    assert eqs.energy == (xd**2 + k * x**2) / 2
    assert eqs.q == (x,) and eqs.u == (xd,) and eqs.parameters == (c, k)
    # plain-symbol coordinates stay plain symbols, with their rates named by u
    eqs = rm.EquationsOfMotion(coordinates=(xs,), u=(vs,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-k * xs]]))
    assert eqs.names == ("x_s",)
    assert_allclose(eqs.rhs(k=4.0)(0.0, np.array([1.0, 0.5])), [0.5, -4.0], rtol=1e-15)
    with pytest.raises(ArgumentError, match="`u` must name the rates"):
        rm.EquationsOfMotion(coordinates=(xs,), mass_matrix=sp.ImmutableMatrix([[1]]),
                             forcing=sp.ImmutableMatrix([[-k * xs]]))


def test_evaluate_names_what_it_has_no_value_for():
    q = rm.coordinates("q")
    system, _, _, (m, L, g) = pendulum(q)
    sim = system.equations_of_motion().simulate(t=(0.0, 0.1), q0=[0.4], n_output=3,
                                                m=1.0, L=1.0, g=9.81)
    h = sp.Symbol("h")
    with pytest.raises(ArgumentError, match=r"\['h'\]"):
        sim.evaluate(m * g * h)
    with pytest.raises(CompilationError, match=r"G\(t\)"):
        sim.evaluate(sp.Function("G")(rm.t))


def test_a_value_that_is_not_a_number_is_named():
    F = sp.Function("F")(rm.t)
    eqs = slider(F)[0].equations_of_motion()
    with pytest.raises(TypeError, match="parameter `m` must be a real number"):
        eqs.rhs(m=np.cos, F=1.0)
    with pytest.raises(TypeError, match="input `F` must be a real number or a callable"):
        eqs.rhs(m=1.0, F="strong")


def test_declaring_a_name_again_does_not_reorder_a_built_system():
    """Re-creating ``theta`` (e.g. to write a condition) after the body joined the system
    must not move it: a ``q0`` given by position would be silently misassigned."""
    psi, theta, phi = rm.coordinates("psi theta phi")
    R0 = rm.Frame("R0")
    R = R0.euler("R", psi, theta, phi)
    s = rm.System(galilean=R0)
    s.add(rm.Body("b", frame=R, mass=1,
                  inertia=rm.InertiaOperator.from_products(1, 2, 3, frame=R)))
    rm.coordinates("theta")
    assert s.coordinates == (psi, theta, phi)
    # a system built after the new declaration follows it, as documented
    s2 = rm.System(galilean=R0)
    s2.add(rm.Body("b", frame=R, mass=1,
                   inertia=rm.InertiaOperator.from_products(1, 2, 3, frame=R)))
    assert s2.coordinates == (psi, phi, theta)
