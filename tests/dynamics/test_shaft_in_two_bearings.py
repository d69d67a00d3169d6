"""A joint that closes a loop without linking the parameters still carries an action (issue
19, item 13): a rotor on a ball joint at A and a linear annular bearing at B, its spin theta
the only coordinate. The bearing's closure conditions vanish identically (the frames already
keep B on the axis), so no Lagrange multiplier stands for its action; its unknowns Y_B, Z_B
enter the fundamental principle for the rotor with those of the ball joint (book, ch. 14,
18.2, 22.2: bearing actions of a rotor).

Reference values, by hand (moments about A, AB = b i0, AG = a i0 + e j1, j1 = Rr.j):

* at rest, G on the axis (e = 0), gravity -g k0: Z_B b = m g a, Z_A = m g - Z_B; for m = 1,
  g = 10, a = 0.2, b = 0.6: Z_A = 20/3, Z_B = 10/3, and no moment at the ball joint;
* at speed, with an unbalance e: the rotor turns about the fixed axis A i0, so
  delta_A = d/dt (J_A omega), J_A omega = theta' ((C + m e^2) i0 - m a e j1), and
  {D} = {A(R0 -> rotor)} + gravity gives theta'' from the moment about i0 and
  (Y_B, Z_B) from the moments about j0, k0; the ball joint takes m a_G - (weight) - R_B.
"""

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import HyperstaticWarning

g, a, b, R, e = 10.0, 0.2, 0.6, 0.1, 0.02


def rotor_system(unbalance=0.0, m=1.0):
    th = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    Rr = R0.rotated("Rr", about=R0.i, angle=th)
    G = R0.origin.moved("G", a * R0.i + unbalance * Rr.j)
    rotor = rm.Body("rotor", frame=Rr, mass=m, centre=G,
                    inertia=rm.inertia.disk(m, R, axis=Rr.i, centre=G))
    s = rm.System(galilean=R0)
    s.connect(R0, rotor, rm.joints.Spherical(at=R0.origin), label="A")
    s.connect(R0, rotor, rm.joints.LinearAnnular(at=R0.point("B", b, 0, 0), axis=R0.i),
              label="B")
    s.act(rm.gravity(-g * R0.k))
    return s, th, R0, rotor


def numbers(T, R0, rule):
    moment = T.moment_at(T.point)
    return (np.array([float(sp.sympify(T.resultant.dot(v)).xreplace(rule)) for v in R0.basis]),
            np.array([float(sp.sympify(moment.dot(v)).xreplace(rule)) for v in R0.basis]))


def test_the_bearing_adds_no_closure_condition_and_the_loop_is_isostatic():
    s, *_ = rotor_system()
    assert s.closure_conditions() == ()
    assert s.mobility().isostatic


def test_bearing_actions_at_rest():
    s, th, R0, rotor = rotor_system()
    rule = {th.diff(rm.t, 2): 0.0, th.diff(rm.t): 0.0, th: 0.3}
    FA, MA = numbers(s.connection_action(R0, rotor, label="A"), R0, rule)
    FB, MB = numbers(s.connection_action(R0, rotor, label="B"), R0, rule)
    assert FA == pytest.approx([0.0, 0.0, 20.0 / 3.0], abs=1e-12)
    assert MA == pytest.approx([0.0, 0.0, 0.0], abs=1e-12)    # a ball joint: no moment
    assert FB == pytest.approx([0.0, 0.0, 10.0 / 3.0], abs=1e-12)
    comps = s.connection_components(R0, rotor, label="B")
    assert float(sp.sympify(comps["Z"]).xreplace(rule)) == pytest.approx(0.0, abs=1e-12)


def by_hand(theta, rate, m=1.0):
    """theta'', R_A, R_B in R0 for the unbalanced rotor (see the module notes)."""
    i0, j0, k0 = np.eye(3)
    j1 = np.array([0.0, np.cos(theta), np.sin(theta)])
    k1 = np.array([0.0, -np.sin(theta), np.cos(theta)])
    C = m * R**2 / 2                               # the disk's moment about its axis
    AG = a * i0 + e * j1
    weight = -m * g * k0
    # moment about i0: (C + m e^2) theta'' = (AG x weight) . i0
    acc = np.cross(AG, weight)[0] / (C + m * e**2)
    delta_A = acc * ((C + m * e**2) * i0 - m * a * e * j1) - m * a * e * rate**2 * k1
    # delta_A = AB x R_B + AG x weight, R_B = (0, Y, Z): AB x R_B = b (-Z j0 + Y k0)
    rest = delta_A - np.cross(AG, weight)
    Z_B, Y_B = -rest[1] / b, rest[2] / b
    R_B = np.array([0.0, Y_B, Z_B])
    a_G = e * (acc * k1 - rate**2 * j1)
    R_A = m * a_G - weight - R_B
    return acc, R_A, R_B


@pytest.mark.parametrize("theta, rate", [(0.0, 0.0), (0.4, 30.0), (2.5, -12.0)])
def test_bearing_actions_of_an_unbalanced_rotor_at_speed(theta, rate):
    s, th, R0, rotor = rotor_system(unbalance=e)
    acc, R_A, R_B = by_hand(theta, rate)
    eqs = s.equations_of_motion()
    got_acc = float(eqs.rhs()(0.0, np.array([theta, rate]))[1])
    assert got_acc == pytest.approx(acc, rel=1e-12)
    rule = {th.diff(rm.t, 2): acc, th.diff(rm.t): rate, th: theta}
    FA, MA = numbers(s.connection_action(R0, rotor, label="A"), R0, rule)
    FB, _ = numbers(s.connection_action(R0, rotor, label="B"), R0, rule)
    assert FA == pytest.approx(R_A, abs=1e-9)
    assert MA == pytest.approx([0.0, 0.0, 0.0], abs=1e-9)
    assert FB == pytest.approx(R_B, abs=1e-9)


def test_two_coaxial_pivots_are_hyperstatic_and_say_so():
    # a shaft in two pivots: h = 5, the split of the load between them is not determined by
    # the fundamental principle: the system names the undetermined unknowns, taken zero in
    # the closing pivot B (the pivot A, a tree joint, carries the whole load)
    th = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    Rr = R0.rotated("Rr", about=R0.i, angle=th)
    G = R0.point("G", a, 0, 0)
    shaft = rm.Body("shaft", frame=Rr, mass=1.0, centre=G,
                    inertia=rm.inertia.disk(1.0, R, axis=Rr.i, centre=G))
    s = rm.System(galilean=R0)
    s.connect(R0, shaft, rm.joints.Pivot(at=R0.origin, axis=R0.i), label="A")
    s.connect(R0, shaft, rm.joints.Pivot(at=R0.point("B", b, 0, 0), axis=R0.i), label="B")
    s.act(rm.gravity(-g * R0.k))
    assert s.mobility().hyperstaticity == 5
    assert s.hyperstatic_unknowns() == ("B.X", "B.Y", "B.Z", "B.L", "B.M")
    with pytest.warns(HyperstaticWarning, match=r"B\.X, B\.Y, B\.Z, B\.L, B\.M, .*taken "
                      r"zero"):
        assert s.connection_action(R0, shaft, label="B").resultant.is_zero
    with pytest.warns(HyperstaticWarning, match=r"B\.X, B\.Y, B\.Z, B\.L, B\.M, "):
        s.connection_action(R0, shaft, label="A")       # A carries the whole load: said too


def test_an_isostatic_loop_has_no_undetermined_unknown():
    s, *_ = rotor_system(unbalance=e)
    assert s.hyperstatic_unknowns() == ()


def test_the_undetermined_unknowns_count_the_hyperstaticity():
    # the multipliers being determined (independent closure conditions), the unknowns the
    # fundamental principle leaves free are those of the degree of hyperstaticity (ch. 14.2):
    # a planar four-bar of pivots, spatially, has h = 3 (C's Z, L, M)
    from test_connection_action_along_loops import four_bar
    s = four_bar()[0]
    assert s.hyperstatic_unknowns() == ("C.Z", "C.L", "C.M")
    assert len(s.hyperstatic_unknowns()) == s.mobility().hyperstaticity
    s = rotor_system()[0]
    assert len(s.hyperstatic_unknowns()) == s.mobility().hyperstaticity == 0
