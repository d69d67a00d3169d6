"""Rolling without slipping and gears in System (book, ch. 10.1.3, 10.2, 20, 25.3).

References:
* a uniform disc rolling without slipping down an incline of angle alpha: x'' = (2/3) g sin
  alpha (energy: (1/2)(m + J/r^2) x'^2 = m g x sin alpha with J = m r^2 / 2); a ring
  (J = m r^2): x'' = (1/2) g sin alpha;
* two gears in mesh (ratio lambda) driven by a torque C on gear 1: the reduced inertia
  (J1 + lambda^2 J2) q1'' = C (power theorem);
* a disc rolling on a plane in 3D: sympy.physics.mechanics.KanesMethod with u = q', the
  speeds of x and y dependent and the no-slip conditions as velocity constraints; the
  accelerations agree at random states to 1e-10.
"""

import numpy as np
import pytest
import sympy as sp
from rolling_models import rolling_disc, rolling_disc_kane, wheel_on_incline

import rigidmech as rm
from rigidmech.dynamics import System
from rigidmech.errors import ConnectionError_
from rigidmech.kinematics import Circle, ContactKinematics, Gear, GearPair


@pytest.mark.parametrize(("inertia", "ratio"), [pytest.param("disk", sp.Rational(2, 3), id="disc"),
                                                pytest.param("ring", sp.Rational(1, 2), id="ring")])
def test_wheel_rolling_down_an_incline(inertia, ratio):
    alpha = sp.Symbol("alpha", positive=True)
    s, (x, th), (m, g, r) = wheel_on_incline(alpha, inertia)
    c = s.constraints()
    assert len(c) == 1 and c.labels[0] in ("1.t1", "1.t2")
    # one parameter is linked: the mobility is one
    assert s.mobility(plane=s.galilean.k).mobility == 1
    acc = s.equations_of_motion().accelerations()
    assert sp.simplify(acc[0] - ratio * g * sp.sin(alpha)) == 0
    assert sp.simplify(acc[1] + acc[0] / r) == 0        # rolls: x' + r theta' = 0


def test_wheel_simulation_rolls_without_slipping():
    s, (x, th), _ = wheel_on_incline(sp.pi / 6)
    eqs = s.equations_of_motion()
    sim = eqs.simulate(t=(0, 2), q0={"x": 0.0, "theta": 0.0}, u0={"x": 0.0, "theta": 0.0},
                       m=2.0, g=9.81, r=0.3, n_output=21)
    np.testing.assert_allclose(sim.q[0], 2 / 3 * 9.81 * 0.5 * sim.t**2 / 2, rtol=1e-7)
    # enforced at the velocity level: the position relation drifts by the integration error
    np.testing.assert_allclose(sim.q[0] + 0.3 * sim.q[1], 0.0, atol=1e-7)


def test_gear_pair_reduced_inertia():
    q1, q2 = rm.coordinates("q1 q2")
    J1, J2, C = rm.constants("J1 J2 C", positive=True)
    R0 = rm.Frame("R0")
    G1 = R0.rotated("G1", about=R0.k, angle=q1)
    G2 = R0.rotated("G2", about=R0.k, angle=q2, origin=R0.point("O2", 60, 0, 0))
    b1 = rm.Body("g1", frame=G1, mass=1,
                 inertia=rm.inertia.disk(1, sp.sqrt(2 * J1), axis=G1.k, centre=G1.origin))
    b2 = rm.Body("g2", frame=G2, mass=1,
                 inertia=rm.inertia.disk(1, sp.sqrt(2 * J2), axis=G2.k, centre=G2.origin))
    s = System(galilean=R0)
    s.connect(R0, b1, rm.joints.Pivot(at=G1.origin, axis=R0.k))
    s.connect(R0, b2, rm.joints.Pivot(at=G2.origin, axis=R0.k))
    pair = GearPair(Gear(20, 2), Gear(40, 2))
    s.connect(b1, b2, rm.actions.GearMesh(pair, b1, b2, carrier=R0, axis=R0.k))
    s.act(rm.actions.Couple(on=b1, moment=C * R0.k))
    acc = s.equations_of_motion().accelerations()
    lam = pair.ratio
    assert sp.simplify(acc[0] - C / (J1 + lam**2 * J2)) == 0
    assert sp.simplify(acc[1] - lam * acc[0]) == 0
    r = s.mobility()
    assert (r.mobility, r.hyperstaticity) == (1, 0)


def test_rolling_disc_matches_kanes_method():
    s, coords, (m, g, r) = rolling_disc()
    c = s.constraints()
    assert not c.holonomic and len(c) == 2
    eqs = s.equations_of_motion()
    kane, q, u, (mk, gk, rk) = rolling_disc_kane()
    vals = {mk: 1.3, gk: 9.81, rk: 0.7}
    MM = sp.lambdify(list(q) + list(u), kane.mass_matrix_full.subs(vals), "numpy")
    FF = sp.lambdify(list(q) + list(u), kane.forcing_full.subs(vals), "numpy")
    rhs = eqs.rhs(m=1.3, g=9.81, r=0.7)
    rng = np.random.default_rng(11)
    for _ in range(10):
        qv = rng.uniform(-3, 3, 5)
        qv[3] = rng.uniform(0.2, np.pi - 0.2)          # lean: the disc stands
        w = rng.uniform(-3, 3, 3)                       # psi', theta', phi' (independent)
        xd, yd = -0.7 * np.cos(qv[2]) * w[2], -0.7 * np.sin(qv[2]) * w[2]
        kane_u = np.array([xd, yd, *w])                 # as in dynamicsymbols(...)
        ours = rhs(0.0, np.concatenate([qv, [xd, yd, *w]]))[5:]
        theirs = np.linalg.solve(MM(*qv, *kane_u), FF(*qv, *kane_u)).ravel()[5:]
        # Kane's rows: the independent speeds first, then the dependent ones
        np.testing.assert_allclose(ours, [*theirs[3:], *theirs[:3]], rtol=1e-10, atol=1e-10)


def test_rolling_contact_must_join_the_connected_bodies():
    s, _, _ = wheel_on_incline(sp.pi / 6)
    R0 = s.galilean
    other = R0.rotated("Rx", about=R0.k, angle=rm.coordinates("z"))
    body = rm.Body("other", frame=other)
    contact = ContactKinematics(other, R0, at=R0.origin, normal=R0.j)
    with pytest.raises(ConnectionError_, match=r"RollingContact joins the frames Rx and R0"):
        s.connect(s.bodies[0], body, rm.actions.RollingContact(contact))


def test_surfaces_not_in_contact_are_refused():
    x = rm.coordinates("x")
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("C", x, 2, 0))
    with pytest.raises(ConnectionError_, match=r"not in contact|do not touch|contact"):
        ContactKinematics.between(R1, Circle(R1.origin, 1, normal=R0.k), R0,
                                  rm.Line(R0.origin, R0.i))


def test_contact_action_of_the_rolling_wheel():
    # uniform disc on the incline: friction m g sin(alpha) / 3 up the slope, normal
    # m g cos(alpha) (the fundamental principle with x'' = 2/3 g sin(alpha))
    alpha = sp.Symbol("alpha", positive=True)
    s, (x, th), (m, g, r) = wheel_on_incline(alpha)
    acc = s.equations_of_motion().accelerations()
    T = s.connection_action(s.galilean, s.bodies[0])
    Ri = s.bodies[0].frame.parent
    sub = {x.diff(rm.t, 2): acc[0], th.diff(rm.t, 2): acc[1]}
    assert sp.simplify(T.resultant.dot(Ri.i).subs(sub) + m * g * sp.sin(alpha) / 3) == 0
    assert sp.simplify(T.resultant.dot(Ri.j).subs(sub) - m * g * sp.cos(alpha)) == 0


def test_rolling_contact_has_no_joint_components():
    s, _, _ = wheel_on_incline(sp.pi / 6)
    with pytest.raises(ConnectionError_, match=r"no local components .* use connection_action"):
        s.connection_components(s.galilean, s.bodies[0])


def test_gear_mesh_action_from_its_multiplier():
    # gear pair driven by a torque C on gear 1 at a state of its motion: the pivots transmit
    # no moment about their axes (N = 0) once the mesh force F (from the multiplier) acts at
    # the pitch point; its moment about O2 accelerates gear 2: F r2 = J2 q2''
    q1, q2 = rm.coordinates("q1 q2")
    R0 = rm.Frame("R0")
    G1 = R0.rotated("G1", about=R0.k, angle=q1)
    G2 = R0.rotated("G2", about=R0.k, angle=q2, origin=R0.point("O2", 60, 0, 0))
    b1 = rm.Body("g1", frame=G1, mass=1, inertia=rm.inertia.disk(1, 20, axis=G1.k,
                                                                    centre=G1.origin))
    b2 = rm.Body("g2", frame=G2, mass=1, inertia=rm.inertia.disk(1, 40, axis=G2.k,
                                                                    centre=G2.origin))
    s = System(galilean=R0)
    s.connect(R0, b1, rm.joints.Pivot(at=G1.origin, axis=R0.k))
    s.connect(R0, b2, rm.joints.Pivot(at=G2.origin, axis=R0.k))
    s.connect(b1, b2, rm.actions.GearMesh(GearPair(Gear(20, 2), Gear(40, 2)), b1, b2,
                                          carrier=R0, axis=R0.k))
    s.act(rm.actions.Couple(on=b1, moment=5 * R0.k))
    eqs = s.equations_of_motion()
    q, u = np.array([0.3, -0.15]), np.array([1.0, -0.5])
    acc = eqs.rhs()(0.0, np.concatenate([q, u]))[2:]
    lam = s.multipliers(q, u)
    rule = {q1.diff(rm.t, 2): acc[0], q2.diff(rm.t, 2): acc[1], q1.diff(rm.t): u[0],
            q2.diff(rm.t): u[1], q1: q[0], q2: q[1],
            **dict(zip(s.multiplier_symbols(), lam, strict=True))}
    for b in (b1, b2):
        N = s.connection_components(R0, b)["N"]
        assert abs(float(sp.sympify(N).xreplace(rule))) < 1e-9
    F = s.connection_action(b1, b2)
    moment = (F.moment_at(G2.origin)).dot(R0.k).xreplace(rule)
    assert float(moment) == pytest.approx(800 * acc[1], rel=1e-12)   # J2 = m r^2 / 2 = 800
