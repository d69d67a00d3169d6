"""The knife edge in System: the Chaplygin sleigh (a nonholonomic velocity constraint).

References (the sleigh: mass m, moment of inertia J = m r^2 / 2 about the vertical through
its mass centre G, blade at P = G - a i1 along its axis i1; v = v(G) . i1 its forward speed,
omega = theta' its rate of turn; the condition v(P) . j1 = 0 gives v(G) . j1 = a omega):

* sympy.physics.mechanics.KanesMethod with u = q', the speed of y dependent and the lateral
  condition as its velocity constraint: the same accelerations at random states to 1e-10;
* the fundamental principle with the lateral force T j1 at P (no forward force, no couple
  about the vertical): m (v' - a omega^2) = 0, m (v omega + a omega') = T, J omega' = -a T,
  hence v' = a omega^2 and (J + m a^2) omega' = -m a v omega. The kinetic energy
  E = m v^2 / 2 + (J + m a^2) omega^2 / 2 is conserved (the blade does no work) and, with
  V = sqrt(2 E / m) and k = m a V / (J + m a^2),

      v(t) = V tanh(k t + phi0),  omega(t) = omega0 cosh(phi0) / cosh(k t + phi0),
      tanh(phi0) = v0 / V

  (the sleigh ends moving straight ahead at the speed V). For a = 0 (blade at G): v and
  omega are constant, G runs on a circle of radius v0 / omega0 at constant speed;
* Newton on the centre: T = m a(G) . j1 (only the blade pushes sideways);
* the sleigh on an incline (gravity works, the plane's normal is not vertical) and on a
  turntable pivoted about the vertical (the support is a body): KanesMethod again; on the
  turntable the angular momentum about the axis and the kinetic energy are conserved.
"""

import numpy as np
import pytest
import sympy as sp
from sleigh_models import (
    sleigh,
    sleigh_kane,
    sleigh_on_incline,
    sleigh_on_incline_kane,
    sleigh_on_turntable,
    sleigh_on_turntable_kane,
)

import rigidmech as rm
from rigidmech.errors import ArgumentError, ArgumentTypeError, ConnectionError_

M, R, G_, A = 1.3, 0.4, 9.81, 0.35


def test_sleigh_constraint_is_nonholonomic():
    s, (x, y, th), (m, r, g, a), knife = sleigh()
    c = s.constraints()
    assert len(c) == 1 and not c.holonomic
    (row,) = s.closure_conditions()
    expected = -sp.sin(th) * x.diff(rm.t) + sp.cos(th) * y.diff(rm.t) - a * th.diff(rm.t)
    assert sp.simplify(row[1] - expected) == 0
    with pytest.raises(ConnectionError_):
        knife.position_constraints()


@pytest.mark.parametrize("a", [A, 0.0, -0.8])
def test_sleigh_matches_kanes_method(a):
    s, _, _, _ = sleigh()
    rhs = s.equations_of_motion().rhs(m=M, r=R, g=G_, a=a)
    red = s.equations_of_motion().reduced(independent=["x", "theta"]).rhs(m=M, r=R, g=G_, a=a)
    kane, q, u, (mk, rk, gk, ak) = sleigh_kane()
    vals = {mk: M, rk: R, gk: G_, ak: a}
    MM = sp.lambdify(list(q) + list(u), kane.mass_matrix_full.subs(vals), "numpy")
    FF = sp.lambdify(list(q) + list(u), kane.forcing_full.subs(vals), "numpy")
    rng = np.random.default_rng(7)
    for _ in range(10):
        qv = rng.uniform(-2, 2, 3)
        qv[2] = rng.uniform(-1.2, 1.2)                  # cos(theta) away from 0
        ux, w = rng.uniform(-3, 3, 2)
        uy = (a * w + np.sin(qv[2]) * ux) / np.cos(qv[2])  # on the constraint
        ours = rhs(0.0, np.array([*qv, ux, uy, w]))[3:]
        theirs = np.linalg.solve(MM(*qv, ux, uy, w), FF(*qv, ux, uy, w)).ravel()[3:]
        # Kane's rows: the independent speeds (ux, utheta), then the dependent one (uy)
        np.testing.assert_allclose(ours, [theirs[0], theirs[2], theirs[1]], rtol=1e-10,
                                   atol=1e-10)
        reduced = red(0.0, np.array([*qv, ux, w]))[3:]
        np.testing.assert_allclose(reduced, theirs[:2], rtol=1e-10, atol=1e-10)


def test_sleigh_on_an_incline_matches_kanes_method():
    # the plane's normal is not the vertical, gravity works, the blade's point is off the
    # axis by b along l: b drops out of the condition (omega ^ b j1 is along the blade)
    beta = 0.4
    s, _, _ = sleigh_on_incline(beta)
    assert [p.name for p in s.equations_of_motion().parameters] == ["a", "g", "m", "r"]
    rhs = s.equations_of_motion().rhs(m=M, r=R, g=G_, a=A)
    kane, q, u, (mk, rk, gk, ak, bk) = sleigh_on_incline_kane(beta)
    sub = {mk: M, rk: R, gk: G_, ak: A, bk: 0.15}
    MM = sp.lambdify(list(q) + list(u), kane.mass_matrix_full.subs(sub), "numpy")
    FF = sp.lambdify(list(q) + list(u), kane.forcing_full.subs(sub), "numpy")
    rng = np.random.default_rng(3)
    for _ in range(10):
        qv = rng.uniform(-2, 2, 3)
        qv[2] = rng.uniform(-1.2, 1.2)
        ux, w = rng.uniform(-3, 3, 2)
        # v(P) . j1 = 0 with v(P) = v(G) + w k ^ (-a i1 + b j1) = v(G) - a w j1 - b w i1
        uy = (A * w + np.sin(qv[2]) * ux) / np.cos(qv[2])
        ours = rhs(0.0, np.array([*qv, ux, uy, w]))[3:]
        theirs = np.linalg.solve(MM(*qv, ux, uy, w), FF(*qv, ux, uy, w)).ravel()[3:]
        np.testing.assert_allclose(ours, [theirs[0], theirs[2], theirs[1]], rtol=1e-10,
                                   atol=1e-10)


def test_sleigh_on_an_incline_conserves_energy():
    s, _, _ = sleigh_on_incline(0.4)
    eqs = s.equations_of_motion()
    th0, ux, w = 0.2, 1.0, 1.5
    uy = (A * w + np.sin(th0) * ux) / np.cos(th0)
    sim = eqs.simulate(t=(0, 4), q0={"x": 0.0, "y": 0.0, "theta": th0},
                       u0={"x": ux, "y": uy, "theta": w}, m=M, r=R, g=G_, a=A,
                       rtol=1e-11, atol=1e-12, n_output=201)
    e = sim.energy()
    assert np.ptp(e) < 1e-8 * np.max(np.abs(e))
    assert np.ptp(sim.q[1]) > 0.5                    # it does slide down the slope


def test_sleigh_on_a_turntable_matches_kanes_method():
    # the support is a body: the condition is on the velocity relative to the table, and the
    # multiplier's force acts on both (T l on the sleigh, -T l on the table)
    s, _, _ = sleigh_on_turntable()
    vals = {"m": M, "r": R, "M": 3.0, "R": 2.0, "a": A}
    eqs = s.equations_of_motion()
    rhs = eqs.rhs(**vals)
    kane, q, u, (mk, rk, Mk, Rk, ak) = sleigh_on_turntable_kane()
    sub = {mk: M, rk: R, Mk: 3.0, Rk: 2.0, ak: A}
    MM = sp.lambdify(list(q) + list(u), kane.mass_matrix_full.subs(sub), "numpy")
    FF = sp.lambdify(list(q) + list(u), kane.forcing_full.subs(sub), "numpy")
    rng = np.random.default_rng(5)
    for _ in range(10):
        qv = rng.uniform(-2, 2, 4)
        qv[3] = rng.uniform(-1.2, 1.2)
        wt, ux, w = rng.uniform(-3, 3, 3)
        uy = (A * w + np.sin(qv[3]) * ux) / np.cos(qv[3])  # relative to the table
        ours = rhs(0.0, np.array([*qv, wt, ux, uy, w]))[4:]
        theirs = np.linalg.solve(MM(*qv, wt, ux, uy, w), FF(*qv, wt, ux, uy, w)).ravel()[4:]
        # Kane's rows: (uphi, ux, utheta) independent, then uy
        np.testing.assert_allclose(ours, [theirs[0], theirs[1], theirs[3], theirs[2]],
                                   rtol=1e-10, atol=1e-10)


def test_turntable_and_sleigh_conserve_angular_momentum():
    # no external moment about the vertical through O: sigma_O . k is constant; the pivot and
    # the blade do no work: the kinetic energy is constant
    s, (phi, x, y, th), _ = sleigh_on_turntable()
    table, body = s.bodies
    R0 = s.galilean
    sigma = sum((b.kinetic_torsor(R0, at=R0.origin).moment.dot(R0.k) for b in (table, body)),
                sp.S(0))
    eqs = s.equations_of_motion()
    th0, ux, w = 0.3, 0.8, -1.2
    uy = (A * w + np.sin(th0) * ux) / np.cos(th0)
    sim = eqs.simulate(t=(0, 5), q0={"phi": 0.0, "x": 0.5, "y": -0.3, "theta": th0},
                       u0={"phi": 0.7, "x": ux, "y": uy, "theta": w}, m=M, r=R, M=3.0,
                       R=2.0, a=A, rtol=1e-11, atol=1e-12, n_output=101)
    h = sim.evaluate(sigma)
    np.testing.assert_allclose(h, h[0], rtol=1e-8)
    e = sim.energy()
    np.testing.assert_allclose(e, e[0], rtol=1e-8)
    assert np.ptp(sim.u[0]) > 1e-2                       # the table's rate does change
    # the action of the table on the sleigh: its lateral component is the multiplier
    lateral = sim.evaluate(s.connection_action(table, body).resultant.dot(body.frame.j))
    lam = [s.multipliers(sim.q[:, i], sim.u[:, i], m=M, r=R, M=3.0, R=2.0, a=A)[0]
           for i in range(0, 101, 20)]
    np.testing.assert_allclose(lam, lateral[::20], rtol=1e-9, atol=1e-12)


def _forward_speed_and_rate(sim):
    x_d, y_d, w = sim.u
    th = sim.q[2]
    return x_d * np.cos(th) + y_d * np.sin(th), w


def _simulate(a, v0, w0, t_end, n_output=401):
    s, _, _, _ = sleigh()
    th0 = 0.3
    q0 = {"x": 0.0, "y": 0.0, "theta": th0}
    # v(G) = v0 i1 + a w0 j1
    u0 = {"x": v0 * np.cos(th0) - a * w0 * np.sin(th0),
          "y": v0 * np.sin(th0) + a * w0 * np.cos(th0), "theta": w0}
    sim = s.equations_of_motion().simulate(t=(0, t_end), q0=q0, u0=u0, m=M, r=R, g=G_, a=a,
                                           rtol=1e-11, atol=1e-12, n_output=n_output)
    return s, sim


def test_chaplygin_sleigh_closed_form():
    v0, w0 = 0.5, 2.0
    s, sim = _simulate(A, v0, w0, t_end=6.0)
    v, w = _forward_speed_and_rate(sim)
    J = M * R**2 / 2
    E = 0.5 * M * v0**2 + 0.5 * (J + M * A**2) * w0**2
    V = np.sqrt(2 * E / M)
    k = M * A * V / (J + M * A**2)
    phi0 = np.arctanh(v0 / V)
    np.testing.assert_allclose(v, V * np.tanh(k * sim.t + phi0), rtol=1e-8, atol=1e-9)
    np.testing.assert_allclose(w, w0 * np.cosh(phi0) / np.cosh(k * sim.t + phi0), rtol=1e-8,
                               atol=1e-9)
    np.testing.assert_allclose(0.5 * M * v**2 + 0.5 * (J + M * A**2) * w**2, E, rtol=1e-9)
    # the lateral condition holds along the motion (enforced at the velocity level)
    th = sim.q[2]
    lateral = -np.sin(th) * sim.u[0] + np.cos(th) * sim.u[1] - A * sim.u[2]
    assert np.max(np.abs(lateral)) < 1e-9


def test_sleigh_with_blade_at_the_mass_centre_runs_on_a_circle():
    v0, w0 = 1.5, 0.8
    s, sim = _simulate(0.0, v0, w0, t_end=10.0)
    v, w = _forward_speed_and_rate(sim)
    np.testing.assert_allclose(v, v0, rtol=1e-9)
    np.testing.assert_allclose(w, w0, rtol=1e-9)
    np.testing.assert_allclose(sim.q[2], 0.3 + w0 * sim.t, rtol=1e-9)
    # centre of the circle: G + (v0 / w0) j1 at t = 0, fixed
    th = sim.q[2]
    cx, cy = sim.q[0] - v0 / w0 * np.sin(th), sim.q[1] + v0 / w0 * np.cos(th)
    np.testing.assert_allclose(cx, cx[0], atol=1e-8)
    np.testing.assert_allclose(cy, cy[0], atol=1e-8)
    np.testing.assert_allclose(np.hypot(sim.q[0] - cx[0], sim.q[1] - cy[0]), v0 / w0,
                               rtol=1e-9)


def test_lateral_action_is_mass_times_lateral_acceleration_of_the_centre():
    s, sim = _simulate(A, 0.5, 2.0, t_end=3.0, n_output=3001)
    (body,) = s.bodies
    R1 = body.frame
    T = s.connection_action(s.galilean, body)
    j1 = R1.j
    lateral_action = sim.evaluate(T.resultant.dot(j1))
    # the multiplier is the lateral force of the ground on the blade
    lam = np.array([s.multipliers(sim.q[:, i], sim.u[:, i], m=M, r=R, g=G_, a=A)[0]
                    for i in range(0, sim.t.size, 100)])
    np.testing.assert_allclose(lam, lateral_action[::100], rtol=1e-9, atol=1e-12)
    # Newton on the centre, a(G) from the simulated velocities (central differences)
    th = sim.q[2]
    ax, ay = (np.gradient(sim.u[i], sim.t, edge_order=2) for i in (0, 1))
    a_lat = -np.sin(th) * ax + np.cos(th) * ay
    np.testing.assert_allclose(lateral_action[5:-5], M * a_lat[5:-5], rtol=1e-5, atol=1e-6)
    assert np.max(np.abs(lateral_action)) > 0.1          # a real sideways force
    # the same along the motion in one call, components in the sleigh's axes
    comps = sim.connection_action(s.galilean, body, basis=R1)
    np.testing.assert_allclose(comps["Y"], lateral_action, rtol=1e-12, atol=1e-12)
    # the blade transmits no couple about the vertical through P, nothing along the blade
    np.testing.assert_allclose(sim.evaluate(T.moment.dot(R1.k)), 0.0, atol=1e-9)
    np.testing.assert_allclose(sim.evaluate(T.resultant.dot(R1.i)), 0.0, atol=1e-9)


def test_knife_edge_action_torsor_does_no_work_with_the_allowed_motion():
    s, _, _, knife = sleigh()
    T, unknowns = knife.action_torsor("1")
    V, free = knife.allowed_motion("1")
    assert [str(u) for u in unknowns] == ["N_1", "T_1"] and len(free) == 4
    assert knife.degrees_of_freedom == 4
    # {N n + T l ; 0}_P . {omega ; s e}_P = (N n + T l) . s e + 0 . omega
    power = T.resultant.dot(V.moment) + T.moment.dot(V.resultant)
    assert sp.simplify(power) == 0


def _frames():
    x, y, th = rm.coordinates("x y theta")
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    return R0, R1, G


def test_knife_edge_bad_input():
    R0, R1, G = _frames()
    with pytest.raises(ArgumentError, match=r"`direction` must be a non-zero Vector"):
        rm.actions.KnifeEdge(R1, R0, at=G, direction=0 * R1.i, normal=R0.k)
    with pytest.raises(ArgumentError, match=r"`normal` must be a non-zero Vector"):
        rm.actions.KnifeEdge(R1, R0, at=G, direction=R1.i, normal=R0.k - R0.k)
    with pytest.raises(ArgumentError, match=r"blade must lie in the plane.*perpendicular"):
        rm.actions.KnifeEdge(R1, R0, at=G, direction=R1.i + R0.k, normal=R0.k)
    with pytest.raises(ArgumentError, match=r"`direction` must be fixed in R1"):
        rm.actions.KnifeEdge(R1, R0, at=G, direction=R0.i, normal=R0.k)
    with pytest.raises(ArgumentError, match=r"`normal` must be fixed in R0"):
        rm.actions.KnifeEdge(R1, R0, at=G, direction=R1.i, normal=R1.j)
    with pytest.raises(ArgumentTypeError, match=r"`direction` must be a Vector; got Point"):
        rm.actions.KnifeEdge(R1, R0, at=G, direction=G, normal=R0.k)
    with pytest.raises(ArgumentTypeError, match=r"`at`"):
        rm.actions.KnifeEdge(R1, R0, at=R1.i, direction=R1.i, normal=R0.k)
    with pytest.raises(ArgumentTypeError, match=r"`blade` must be a Solid, a Body or a Frame"):
        rm.actions.KnifeEdge("sleigh", R0, at=G, direction=R1.i, normal=R0.k)


def test_knife_edge_point_must_stay_in_the_plane():
    z = rm.coordinates("z")
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("G", 0, 0, z))
    with pytest.raises(ConnectionError_, match=r"point G of the blade does not stay in the plane"):
        rm.actions.KnifeEdge(R1, R0, at=R1.origin, direction=R1.i, normal=R0.k)


def test_knife_edge_must_join_the_connected_bodies():
    R0, R1, G = _frames()
    other = R0.rotated("Rx", about=R0.k, angle=rm.coordinates("q"))
    body = rm.Body("sleigh", frame=R1, mass=1, centre=G)
    s = rm.System(galilean=R0)
    with pytest.raises(ConnectionError_, match=r"KnifeEdge joins the frames R0 and Rx"):
        s.connect(R0, body, rm.actions.KnifeEdge(other, R0, at=R0.origin, direction=other.i,
                                                  normal=R0.k))
