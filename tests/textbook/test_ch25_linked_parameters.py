"""Linked parameters (book, ch. 25.3): closed loops written as constraints between the
parameters of situation, with Lagrange multipliers.

Independent references:
* positions: the loop closure written by hand (the two routes to the closing point meet)
  and solved with ``scipy.optimize.fsolve`` (four-bar) or in closed form (slider-crank,
  x = r cos q1 + sqrt(l^2 - r^2 sin^2 q1));
* velocities and accelerations: central finite differences of that solution along a
  prescribed motion of the crank q1(t) = 0.9 + 0.7 t + 0.25 t^2;
* dynamics: for a one-degree-of-freedom conservative mechanism, energy conservation and the
  closure conditions determine the motion; the ladder sliding on a smooth floor and wall
  leaves the wall when its top has come down to 2/3 of its initial height (released from
  rest; classical result, e.g. Berthelot ch. 20 exercises, Goldstein): the wall's
  multiplier changes sign there.
"""

import sys
from pathlib import Path

import numpy as np
import pytest
import scipy.optimize
import sympy as sp

import rigidmech as rm
from rigidmech.dynamics import System
from rigidmech.errors import ArgumentError, ConnectionError_, HyperstaticWarning

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "systems"))
from mechanisms import L0, L1, L2, L3, four_bar, slider_crank  # noqa: E402

T0, H = 0.3, 1e-4


def crank(t):
    return 0.9 + 0.7 * t + 0.25 * t**2, 0.7 + 0.5 * t, 0.5


def four_bar_by_hand(q1, guess=(-0.6, 1.4)):
    def closure(x):
        q2, q3 = x
        return [L1 * np.cos(q1) + L2 * np.cos(q1 + q2) - L0 - L3 * np.cos(q3),
                L1 * np.sin(q1) + L2 * np.sin(q1 + q2) - L3 * np.sin(q3)]
    sol = scipy.optimize.fsolve(closure, guess, xtol=1e-14)
    assert np.max(np.abs(closure(sol))) < 1e-13
    return np.array([q1, *sol])


def slider_by_hand(q1, r=0.5, ell=1.5):
    x = r * np.cos(q1) + np.sqrt(ell**2 - (r * np.sin(q1)) ** 2)
    q2 = np.arctan2(-r * np.sin(q1), x - r * np.cos(q1)) - q1
    return np.array([q1, q2, x])


def finite_differences(solve):
    qm, q0, qp = (solve(crank(t)[0]) for t in (T0 - H, T0, T0 + H))
    return q0, (qp - qm) / (2 * H), (qp - 2 * q0 + qm) / H**2


def our_route(system, coords, q_by_hand, params):
    q1, w1, a1 = crank(T0)
    names = [q.func.__name__ for q in coords]
    guess = dict(zip(names, q_by_hand + np.array([0, 0.05, -0.05]), strict=True))
    guess[names[0]] = q1
    q0, u0 = system.assemble(guess, independent=[names[0]], rates={names[0]: w1}, **params)
    q = np.array([q0[n] for n in names])
    u = np.array([u0[n] for n in names])
    c = system.constraints()
    rule = {}
    for qq, uu in zip(coords, u, strict=True):
        rule[qq.diff(rm.t)] = uu
    rule.update(dict(zip(coords, q, strict=True)))
    A = np.array(c.jacobian.subs(rule), dtype=float)
    b = np.array(c.bias.subs(rule), dtype=float).ravel()
    acc = np.empty(3)
    acc[0] = a1
    acc[1:] = np.linalg.solve(A[:, 1:], b - A[:, 0] * a1)
    return q, u, acc


@pytest.mark.parametrize(("build", "by_hand"), [
    pytest.param(lambda: four_bar()[:2], four_bar_by_hand, id="four_bar"),
    pytest.param(lambda: slider_crank()[:2], slider_by_hand, id="slider_crank"),
])
def test_positions_velocities_accelerations_vs_finite_differences(build, by_hand):
    system, coords = build()
    q_ref, u_ref, a_ref = finite_differences(by_hand)
    q, u, a = our_route(system, coords, q_ref, {})
    np.testing.assert_allclose(q, q_ref, atol=1e-11)
    np.testing.assert_allclose(u, u_ref, rtol=1e-6, atol=1e-7)
    np.testing.assert_allclose(a, a_ref, rtol=1e-4, atol=1e-5)


@pytest.mark.parametrize("build", [
    pytest.param(lambda: four_bar()[:2], id="four_bar"),
    pytest.param(lambda: slider_crank()[:2], id="slider_crank"),
])
def test_motion_keeps_the_loop_closed_and_the_energy(build):
    system, coords = build()
    eqs = system.equations_of_motion()
    names = [q.func.__name__ for q in coords]
    start = {"q1": 1.0, "q2": -0.6, "q3": 1.4} if "q3" in names else {
        "q1": 1.0, "q2": -0.3, "x": 1.6}
    q0, u0 = system.assemble(start, independent=["q1"], rates={"q1": 2.0}, m=1.0, g=9.81)
    sim = eqs.simulate(t=(0, 20), q0=q0, u0=u0, m=1.0, g=9.81, n_output=401, rtol=1e-10,
                       atol=1e-10)
    residual = max(np.abs(sim.evaluate(p)).max() for _, _, p in system.closure_conditions())
    assert residual < 1e-8
    assert sim.energy_drift() < 1e-7


def ladder(theta0=0.4, ell=2.0):
    x, y, th = rm.coordinates("x y theta")
    m, g = rm.constants("m g", positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    # the ladder along R1.j, top against the wall x = 0, foot on the floor y = 0
    top, foot = G.moved("T", ell / 2 * R1.j), G.moved("F", -ell / 2 * R1.j)
    body = rm.Body("ladder", frame=R1, mass=m, centre=G,
                   inertia=rm.inertia.rod(m, ell, axis=R1.j, centre=G))
    s = System(galilean=R0)
    s.connect(R0, body, rm.joints.PlanarSupport(at=G, normal=R0.k))
    s.connect(R0, body, rm.joints.PointContact(at=R0.origin, normal=R0.j), meets=foot,
              label="floor")
    s.connect(R0, body, rm.joints.PointContact(at=R0.origin, normal=R0.i), meets=top,
              label="wall")
    s.act(rm.gravity(-g * R0.j))
    # theta is the angle of the ladder from the wall, top at x = 0: G = (l/2 sin th, l/2 cos th)
    q0, u0 = s.assemble({"x": ell / 2 * np.sin(theta0), "y": ell / 2 * np.cos(theta0),
                         "theta": theta0}, independent=["theta"], m=1.0, g=9.81)
    return s, q0, u0


def test_ladder_leaves_the_wall_at_two_thirds_of_its_height():
    theta0 = 0.4
    s, q0, u0 = ladder(theta0)
    assert s.mobility(plane=s.galilean.k).mobility == 1
    eqs = s.equations_of_motion()
    sim = eqs.simulate(t=(0, 1.6), q0=q0, u0=u0, m=1.0, g=9.81, n_output=1601, rtol=1e-11,
                       atol=1e-11)
    wall = s.closure_conditions().index(next(r for r in s.closure_conditions()
                                             if r[0] == "wall.w"))
    lam = np.array([s.multipliers(sim.q[:, i], sim.u[:, i], m=1.0, g=9.81)[wall]
                    for i in range(sim.q.shape[1])])
    assert lam[0] > 0
    i = int(np.argmax(lam < 0))
    assert i > 0
    # linear interpolation of cos(theta) at the sign change
    f = lam[i - 1] / (lam[i - 1] - lam[i])
    th = sim.q[2, i - 1] + f * (sim.q[2, i] - sim.q[2, i - 1])
    assert np.cos(th) == pytest.approx(2 / 3 * np.cos(theta0), rel=2e-4)


def test_points_that_cannot_coincide_are_refused():
    th = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    shaft = rm.Body("shaft", frame=R0.rotated("R1", about=R0.k, angle=th))
    s = System(galilean=R0)
    s.connect(R0, shaft, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    with pytest.raises(ConnectionError_, match=r"the points B and B1 do not coincide"):
        s.connect(R0, shaft, rm.joints.Pivot(at=R0.point("B", 0, 0, 1), axis=R0.k),
                  meets=R0.point("B1", 1, 0, 1))


def test_a_loop_with_no_solution_names_its_conditions():
    s, _, _, _ = four_bar(lengths=(5.0, 1.0, 1.0, 1.0))   # 1 + 1 + 1 < 5: cannot close
    with pytest.raises(ConnectionError_, match=r"the loop cannot be closed .*\['4\.u', '4\.v'\]"
                       r"|the loop cannot be closed .*4\.[uv]"):
        s.assemble({"q1": 0.3, "q2": 0.1, "q3": 2.0}, independent=["q1"])


def test_orientation_closure_is_refused_clearly():
    a, b = rm.coordinates("a b")
    R0 = rm.Frame("R0")
    body = rm.Body("b", frame=R0.rotated("R1", about=R0.i, angle=a))
    s = System(galilean=R0)
    s.connect(R0, body, rm.joints.Pivot(at=R0.origin, axis=R0.i))
    with pytest.raises(ConnectionError_, match=r"blocks the relative rotation about u, which "
                                               r"the frames do not block: give `meets` as a "
                                               r"frame"):
        s.connect(R0, body, rm.joints.Pivot(at=R0.origin, axis=R0.k))


def test_meets_only_for_a_closing_joint():
    s, _, (R0, *_), _ = four_bar()
    b = rm.Body("extra", frame=R0.rotated("RX", about=R0.k, angle=rm.coordinates("qx")))
    with pytest.raises(ArgumentError, match=r"`meets` is the point of `child`"):
        s.connect(R0, b, rm.joints.Pivot(at=R0.origin, axis=R0.k), meets=R0.origin)


def test_assemble_refuses_unknown_coordinates():
    s = four_bar()[0]
    with pytest.raises(ArgumentError, match=r"`independent`: \['z'\] are not coordinates"):
        s.assemble({"q1": 1.0}, independent=["z"])
    with pytest.raises(ArgumentError, match=r"`values`: z is not a coordinate"):
        s.assemble({"z": 1.0})


def test_symbolic_accelerations_of_the_augmented_system():
    # a particle on a circle of radius R in a vertical plane (a pendulum): at the bottom with
    # speed v its acceleration is v^2/R towards the centre; at the side, at rest, it falls
    # freely (the constraint force is zero)
    from rigidmech.dynamics import Constraints, EquationsOfMotion
    x, y = rm.coordinates("x y")
    g, R, v = rm.constants("g R v", positive=True)
    phi = x**2 + y**2 - R**2
    eqs = EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
                            forcing=sp.Matrix([0, -g]),
                            constraints=Constraints((x, y), [("rod", phi.diff(rm.t), phi)]))
    acc = eqs.accelerations()
    bottom = {x.diff(rm.t): v, y.diff(rm.t): 0, x: 0, y: -R}
    side = {x.diff(rm.t): 0, y.diff(rm.t): 0, x: R, y: 0}
    assert sp.simplify(acc.subs(bottom) - sp.Matrix([0, v**2 / R])) == sp.zeros(2, 1)
    assert sp.simplify(acc.subs(side) - sp.Matrix([0, -g])) == sp.zeros(2, 1)
    assert "R" in [p.name for p in eqs.parameters]
    # and numerically, through the compiled augmented solve
    f = eqs.rhs(g=9.81, R=2.0)
    np.testing.assert_allclose(f(0.0, np.array([0.0, -2.0, 3.0, 0.0]))[2:], [0.0, 4.5],
                               atol=1e-12)


def state_rule(system, q, u, acc, lam):
    rule = {}
    for c, uu, aa in zip(system.coordinates, u, acc, strict=True):
        rule[c.diff(rm.t, 2)] = aa
        rule[c.diff(rm.t)] = uu
    for c, qq in zip(system.coordinates, q, strict=True):
        rule[c] = qq
    rule.update(dict(zip(system.multiplier_symbols(), lam, strict=True)))
    return rule


def test_connection_actions_with_multipliers_are_consistent():
    # four-bar at a state of its motion: the pivot at D transmits no moment about its axis
    # (N = 0) once q'' and the multipliers solve the equations; the pivot C's action is the
    # multipliers' force, equal and opposite on coupler and rocker
    s, coords, (R0, *_), _ = four_bar()
    eqs = s.equations_of_motion()
    q0, u0 = s.assemble({"q1": 1.0, "q2": -0.6, "q3": 1.4}, independent=["q1"],
                        rates={"q1": 2.0})
    q = np.array(list(q0.values()))
    u = np.array(list(u0.values()))
    acc = eqs.rhs(m=1.0, g=9.81)(0.0, np.concatenate([q, u]))[3:]
    lam = s.multipliers(q, u, m=1.0, g=9.81)
    rule = state_rule(s, q, u, acc, lam)
    rule.update({sp.Symbol("m", positive=True): 1.0, sp.Symbol("g", positive=True): 9.81})
    crank, coupler, rocker = s.bodies
    for parent, child in [(R0, rocker), (R0, crank), (crank, coupler)]:
        with pytest.warns(HyperstaticWarning, match=r"4\.Z, 4\.L, 4\.M, "):  # out of plane
            N = s.connection_components(parent, child)["N"]
        assert abs(float(N.xreplace(rule))) < 1e-10
    with pytest.warns(HyperstaticWarning, match=r"4\.Z, 4\.L, 4\.M, "):
        C = s.connection_action(coupler, rocker)
    assert C.resultant.dot(R0.i).xreplace(rule) == pytest.approx(lam[0], abs=1e-12)


def test_ladder_planar_support_carries_nothing_in_the_plane():
    s, q0, u0 = ladder(0.4)
    eqs = s.equations_of_motion()
    q, u = np.array(list(q0.values())), np.array(list(u0.values()))
    acc = eqs.rhs(m=1.0, g=9.81)(0.0, np.concatenate([q, u]))[3:]
    lam = s.multipliers(q, u, m=1.0, g=9.81)
    rule = state_rule(s, q, u, acc, lam)
    rule.update({sp.Symbol("m", positive=True): 1.0, sp.Symbol("g", positive=True): 9.81})
    R0 = s.galilean
    T = s.connection_action(R0, s.bodies[0], label="1")
    for comp in (T.resultant.dot(R0.i), T.resultant.dot(R0.j), T.moment.dot(R0.k)):
        assert abs(float(sp.sympify(comp).xreplace(rule))) < 1e-10
    wall = s.connection_action(R0, s.bodies[0], label="wall")
    assert float(wall.resultant.dot(R0.i).xreplace(rule)) > 0      # the wall pushes


def test_ambiguous_connection_needs_a_label():
    s, _, _ = ladder(0.4)
    with pytest.raises(ConnectionError_, match=r"3 connections join R0 to ladder .* give "
                                               r"`label`"):
        s.connection_action(s.galilean, s.bodies[0])


def test_lagrange_equations_carry_the_same_constraints():
    # Lagrange's equations (ch. 25) of the four-bar give the same accelerations as the
    # fundamental principle, with the same multipliers' constraint block
    from rigidmech.lagrange import lagrange_equations
    s = four_bar()[0]
    eqs, lag = s.equations_of_motion(), lagrange_equations(s)
    assert lag.constraints is not None
    y = np.array([1.0, -0.6, 1.4, 0.7, -0.3, 0.2])
    np.testing.assert_allclose(lag.rhs(m=1.3, g=9.81)(0.0, y), eqs.rhs(m=1.3, g=9.81)(0.0, y),
                               rtol=1e-12, atol=1e-12)


def test_a_condition_on_a_stray_coordinate_is_refused():
    from rigidmech.dynamics import Constraints
    x, z = rm.coordinates("x z")
    with pytest.raises(ArgumentError, match=r"constraint c depends on z\(t\), which is not a "
                                            r"coordinate"):
        Constraints((x,), [("c", x.diff(rm.t) + z, None)])
