"""Connection actions along a motion of a system with a closed loop (issue 19, item 14):
``Simulation.connection_action`` evaluates the Lagrange multipliers along the motion from the
stored states, and takes ``label=`` for two connections between the same solids.

Reference values (independent route): the fundamental principle for the rocker of a four-bar,
by hand with numpy from the simulated states and accelerations. The rocker (rod D C of length
L3, mass m, turning by q3 about the pivot D, G3 its mid-point) under gravity -g j0, the pivot
D (R0 -> rocker) and the pivot C (coupler -> rocker):

    R_D + R_C - m g j0 = m a_G3,   a_G3 = (L3/2) (q3'' e3perp - q3'^2 e3),
    (m L3^2 / 3) q3'' = [DC x R_C + DG3 x (-m g j0)] . k0      (no moment about D's axis).
"""

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ConnectionError_, HyperstaticWarning

m, g = 1.0, 9.81
L0, L1, L2, L3 = 2.0, 0.6, 2.1, 1.0


def rod_body(name, frame, length, origin):
    G = origin.moved(f"G_{name}", length / 2 * frame.i)
    return rm.Body(name, frame=frame, mass=m, centre=G,
                   inertia=rm.inertia.rod(m, length, axis=frame.i, centre=G))


def four_bar():
    q1, q2, q3 = rm.coordinates("q1 q2 q3")
    R0 = rm.Frame("R0")
    k = R0.k
    R1 = R0.rotated("R1", about=k, angle=q1)
    B = R0.origin.moved("B", L1 * R1.i)
    R2 = R1.rotated("R2", about=k, angle=q2, origin=B)
    D = R0.point("D", L0, 0, 0)
    R3 = R0.rotated("R3", about=k, angle=q3, origin=D)
    crank = rod_body("crank", R1, L1, R0.origin)
    coupler = rod_body("coupler", R2, L2, B)
    rocker = rod_body("rocker", R3, L3, D)
    s = rm.System(galilean=R0)
    s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=k), label="A")
    s.connect(crank, coupler, rm.joints.Pivot(at=B, axis=k), label="B")
    s.connect(R0, rocker, rm.joints.Pivot(at=D, axis=k), label="D")
    s.connect(coupler, rocker, rm.joints.Pivot(at=B.moved("C", L2 * R2.i), axis=k),
              meets=D.moved("C3", L3 * R3.i), label="C")
    s.act(rm.gravity(-g * R0.j))
    return s, (crank, coupler, rocker), R0


@pytest.fixture(scope="module")
def motion():
    s, bodies, R0 = four_bar()
    q0, u0 = s.assemble({"q1": 1.0, "q2": -0.6, "q3": 1.4}, independent=["q1"],
                        rates={"q1": 2.0})
    eqs = s.equations_of_motion()
    sim = eqs.simulate(t=(0.0, 0.5), q0=q0, u0=u0, rtol=1e-10, atol=1e-12, n_output=5)
    return s, bodies, R0, eqs, sim


def state_rule(s, q, u, acc, lam):
    rule = {}
    for c, uu, aa in zip(s.coordinates, u, acc, strict=True):
        rule[c.diff(rm.t, 2)] = aa
        rule[c.diff(rm.t)] = uu
    rule.update(dict(zip(s.coordinates, q, strict=True)))
    rule.update(dict(zip(s.multiplier_symbols(), lam, strict=True)))
    return rule


def components(T, R0, rule):
    moment = T.moment_at(T.point)
    return np.array([float(sp.sympify(v.dot(e)).xreplace(rule))
                     for v in (T.resultant, moment) for e in R0.basis])


@pytest.mark.parametrize("pair", [("R0", "rocker"), ("coupler", "rocker"), ("R0", "crank"),
                                  ("crank", "coupler")])
def test_pivot_actions_along_the_motion_match_the_system_at_each_state(motion, pair):
    s, (crank, coupler, rocker), R0, eqs, sim = motion
    solids = {"R0": R0, "crank": crank, "coupler": coupler, "rocker": rocker}
    parent, child = (solids[p] for p in pair)
    # the out-of-plane components C.Z, C.L, C.M are hyperstatic (pivots in space): taken
    # zero, and said so
    with pytest.warns(HyperstaticWarning, match=r"C\.Z, C\.L, C\.M"):
        along = sim.connection_action(parent, child, basis=R0)
    with pytest.warns(HyperstaticWarning, match=r"C\.Z, C\.L, C\.M"):
        T = s.connection_action(parent, child)
    for n in range(sim.t.size):
        q, u = sim.q[:, n], sim.u[:, n]
        acc = eqs.rhs()(sim.t[n], np.concatenate([q, u]))[3:]
        rule = state_rule(s, q, u, acc, s.multipliers(q, u, sim.t[n]))
        expected = components(T, R0, rule)
        got = np.array([along[k][n] for k in ("X", "Y", "Z", "L", "M", "N")])
        assert got == pytest.approx(expected, abs=1e-9)


def test_the_rocker_balance_by_hand(motion):
    s, (crank, coupler, rocker), R0, eqs, sim = motion
    with pytest.warns(HyperstaticWarning, match=r"C\.Z, C\.L, C\.M"):
        R_D = sim.connection_action(R0, rocker, basis=R0)
        R_C = sim.connection_action(coupler, rocker, basis=R0)
    for n in range(sim.t.size):
        q, u = sim.q[:, n], sim.u[:, n]
        acc = eqs.rhs()(sim.t[n], np.concatenate([q, u]))[3:]
        q3, w3, a3 = q[2], u[2], acc[2]
        e3 = np.array([np.cos(q3), np.sin(q3), 0.0])
        p3 = np.array([-np.sin(q3), np.cos(q3), 0.0])
        a_G = L3 / 2 * (a3 * p3 - w3**2 * e3)
        weight = np.array([0.0, -m * g, 0.0])
        FD = np.array([R_D[k][n] for k in "XYZ"])
        FC = np.array([R_C[k][n] for k in "XYZ"])
        assert FD + FC + weight == pytest.approx(m * a_G, abs=1e-8)
        # moment about D along k0: the pivot D transmits none
        torque = np.cross(L3 * e3, FC)[2] + np.cross(L3 / 2 * e3, weight)[2]
        assert m * L3**2 / 3 * a3 == pytest.approx(torque, abs=1e-8)
        assert R_D["N"][n] == pytest.approx(0.0, abs=1e-8)


def test_two_connections_between_the_same_solids_take_a_label():
    th = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    Rr = R0.rotated("Rr", about=R0.i, angle=th)
    G = R0.point("G", 0.2, 0, 0)
    rotor = rm.Body("rotor", frame=Rr, mass=1.0, centre=G,
                    inertia=rm.inertia.disk(1.0, 0.1, axis=Rr.i, centre=G))
    s = rm.System(galilean=R0)
    s.connect(R0, rotor, rm.joints.Spherical(at=R0.origin), label="A")
    s.connect(R0, rotor, rm.joints.LinearAnnular(at=R0.point("B", 0.6, 0, 0), axis=R0.i),
              label="B")
    s.act(rm.gravity(-10.0 * R0.k))
    sim = s.equations_of_motion().simulate(t=(0.0, 1.0), q0=[0.0], u0=[5.0], n_output=3)
    with pytest.raises(ConnectionError_, match=r"give `label`"):
        sim.connection_action(R0, rotor)
    A = sim.connection_action(R0, rotor, basis=R0, label="A")
    B = sim.connection_action(R0, rotor, basis=R0, label="B")
    assert A["Z"] == pytest.approx(np.full(3, 20.0 / 3.0), abs=1e-9)
    assert B["Z"] == pytest.approx(np.full(3, 10.0 / 3.0), abs=1e-9)
    assert B["X"] == pytest.approx(np.zeros(3), abs=1e-12)


def test_a_connection_asked_the_wrong_way_round_names_the_connections(motion):
    s, (crank, coupler, rocker), R0, eqs, sim = motion
    with pytest.raises(ConnectionError_, match=r"no connection from rocker to coupler: give "
                       r"the parent .* connections of coupler are: .*coupler -> rocker "
                       r"\(label 'C'\)"):
        sim.connection_action(rocker, coupler)
