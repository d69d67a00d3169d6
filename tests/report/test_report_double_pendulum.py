"""The step-by-step report of the double pendulum holds the book's intermediate results
(ch. 25.4.3): the kinematic torsors at the joints O and A, the partial kinematic torsors, the
power coefficients and the entries of the mass matrix, each checked against a computation
that does not go through rigidmech (sympy.physics.mechanics, or a closed form written here),
and each printed in the report's text.

Conventions (rigidmech.models.double_pendulum): two uniform rods of mass m and length L, on
pivots about k at O and at the tip A of the first rod; theta1, theta2 the absolute angles of
the rods from the downward vertical i (gravity g i).
"""

import pytest
import sympy as sp
import sympy.physics.mechanics as me

from rigidmech import report

pytestmark = pytest.mark.filterwarnings("error")


@pytest.fixture(scope="module")
def pendulum(double_pendulum):
    return double_pendulum


@pytest.fixture(scope="module")
def principle(double_pendulum_report):
    return double_pendulum_report


@pytest.fixture(scope="module")
def lagrange(pendulum):
    return report.derivation(pendulum, route="lagrange")


@pytest.fixture(scope="module")
def plain(pendulum):
    """rigidmech's q(t), q'(t), q''(t) -> plain symbols, and the plain symbols."""
    q, u, a, rule = pendulum.system.symbols()
    return rule, q, u, a


@pytest.fixture(scope="module")
def mechanics(plain):
    """The same pendulum in sympy.physics.mechanics, and its rule to the same plain symbols."""
    _, (q1, q2), (u1, u2), (a1, a2) = plain
    m, L, g = sp.symbols("m L g", positive=True)
    th1, th2 = me.dynamicsymbols("theta1 theta2")
    t = me.dynamicsymbols._t
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [th1, N.z])
    B = N.orientnew("B", "Axis", [th2, N.z])
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", L * A.x)              # the joint A
    G1 = O.locatenew("G1", L / 2 * A.x)
    G2 = P.locatenew("G2", L / 2 * B.x)
    for point in (P, G1, G2):
        point.set_vel(N, point.pos_from(O).dt(N))
    Izz = m * L**2 / 12
    bar1 = me.RigidBody("bar1", G1, A, m, (me.inertia(A, 0, Izz, Izz), G1))
    bar2 = me.RigidBody("bar2", G2, B, m, (me.inertia(B, 0, Izz, Izz), G2))
    for body in (bar1, bar2):
        body.potential_energy = -m * g * body.masscenter.pos_from(O).dot(N.x)
    lm = me.LagrangesMethod(me.Lagrangian(N, bar1, bar2), [th1, th2])
    lm.form_lagranges_equations()
    rule = {th1.diff(t, 2): a1, th2.diff(t, 2): a2, th1.diff(t): u1, th2.diff(t): u2,
            th1: q1, th2: q2}
    return dict(N=N, A=A, B=B, P=P, bar1=bar1, bar2=bar2, lm=lm, rule=rule, m=m, L=L, g=g,
                T=bar1.kinetic_energy(N) + bar2.kinetic_energy(N))


def components(vector, frame, rule):
    """rigidmech Vector -> its components in ``frame``, with the plain symbols."""
    return sp.Matrix(vector.components(frame)).xreplace(rule)


def me_components(vector, frame, rule):
    return sp.Matrix(vector.to_matrix(frame)).xreplace(rule)


def vanishes(matrix):
    return all(sp.simplify(x) == 0 for x in matrix)


def test_kinematic_torsors_at_the_joints_equal_sympy_mechanics(principle, pendulum, plain,
                                                               mechanics):
    rule = plain[0]
    R0 = pendulum.frame("R0")
    me_rule, N = mechanics["rule"], mechanics["N"]
    V1, V2 = principle.kinematic_torsor("bar1"), principle.kinematic_torsor("bar2")
    assert (V1.point.name, V2.point.name) == ("O_R0", "A")   # the joints, by default
    # bar1 at O: {theta1' k ; 0}; bar2 at A: {theta2' k ; v(A) = L theta1' j1}
    assert vanishes(components(V1.rotation, R0, rule)
                    - me_components(mechanics["A"].ang_vel_in(N), N, me_rule))
    assert V1.velocity.is_zero
    assert vanishes(components(V2.rotation, R0, rule)
                    - me_components(mechanics["B"].ang_vel_in(N), N, me_rule))
    assert vanishes(components(V2.velocity, R0, rule)
                    - me_components(mechanics["P"].vel(N), N, me_rule))


def test_the_text_prints_the_kinematic_torsors_at_the_joints(principle):
    text = principle.to_text()
    assert "{V(bar1/R0)} = {theta1_dot k_R1 ; 0}_O_R0" in text
    assert "{V(bar2/R0)} = {theta2_dot k_R2 ; L*theta1_dot j_R1}_A" in text


def test_mass_matrix_entries_equal_sympy_mechanics_and_the_closed_form(principle, plain,
                                                                        mechanics):
    rule, (q1, q2), _, _ = plain
    M = principle.equations.mass_matrix.xreplace(rule)
    M_me = mechanics["lm"].mass_matrix.xreplace(mechanics["rule"])
    m, L = sp.symbols("m L", positive=True)
    closed = m * L**2 * sp.Matrix([[sp.Rational(4, 3), sp.cos(q2 - q1) / 2],
                                   [sp.cos(q2 - q1) / 2, sp.Rational(1, 3)]])
    assert vanishes(M - M_me)
    assert vanishes(M - closed)


def test_the_text_prints_the_mass_matrix_entries(principle, plain):
    _, (q1, q2), _, _ = plain
    m, L = sp.symbols("m L", positive=True)
    text = principle.to_text()
    for entry in (4 * m * L**2 / 3, m * L**2 * sp.cos(q2 - q1) / 2, m * L**2 / 3):
        assert sp.sstr(entry) in text, sp.sstr(entry)


def test_partial_kinematic_torsors_and_power_coefficients(principle, pendulum, plain):
    rule, (q1, q2), _, _ = plain
    R0, R1 = pendulum.frame("R0"), pendulum.frame("R1")
    m, L, g = sp.symbols("m L g", positive=True)
    # {V_theta1(bar2)} at A = {0 ; L j1} (ch. 25.1.2: dv(A)/dtheta1'), {V_theta2(bar2)} = {k ; 0}
    V21, V22 = principle.partial_kinematic_torsors("bar2")
    assert V21.resultant.is_zero
    assert vanishes(components(V21.moment - L * R1.j, R0, rule))
    assert vanishes(components(V22.resultant - R0.k, R0, rule)) and V22.moment.is_zero
    # power of gravity: Q = -dV/dq with V = -m g L (3/2 cos theta1 + 1/2 cos theta2)
    expected = sp.Matrix([-3 * m * g * L * sp.sin(q1) / 2, -m * g * L * sp.sin(q2) / 2])
    assert vanishes(principle.power_coefficients.xreplace(rule) - expected)
    assert "Q_theta1(connection 2) = 0" in principle.to_text()


def test_lagrange_route_momenta_equal_sympy_mechanics(lagrange, plain, mechanics):
    rule = plain[0]
    th = me.dynamicsymbols("theta1 theta2")
    t = me.dynamicsymbols._t
    for p, q in zip(lagrange.results["momenta"], th, strict=True):
        p_me = sp.diff(mechanics["T"], q.diff(t))
        assert sp.simplify(p.xreplace(rule) - p_me.xreplace(mechanics["rule"])) == 0
    assert sp.simplify(lagrange.kinetic_energy.xreplace(rule)
                       - mechanics["T"].xreplace(mechanics["rule"])) == 0


def test_both_routes_give_the_same_equations(principle, lagrange):
    a, b = principle.equations, lagrange.equations
    assert vanishes(a.mass_matrix - b.mass_matrix)
    assert vanishes(a.forcing - b.forcing)


def test_the_steps_follow_the_book(principle, lagrange):
    assert [s.title for s in principle.steps] == [
        "Parameters of situation", "Kinematic torsors", "Kinetic and dynamic torsors",
        "Action torsors", "Partial kinematic torsors", "Power coefficients",
        "Fundamental principle", "Equations of motion"]
    assert [s.title for s in lagrange.steps][-2:] == ["Lagrange's equations",
                                                       "Equations of motion"]
    text = principle.to_text()
    # the connection unknowns with the library's names (Joint.action_torsor)
    assert "{A(R0 -> bar1)} = {X_1 i_R0 + Y_1 j_R0 + Z_1 k_R0 ; L_1 i_R0 + M_1 j_R0}_O_R0" \
        in text
    assert "{D(bar1/R0)} = {A(Gravity -> bar1)} + {A(R0 -> bar1)} + {A(bar2 -> bar1)}" in text
