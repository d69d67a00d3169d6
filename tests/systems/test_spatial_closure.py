"""Spatial loops: closure of the relative orientation, and helical (screw) joints closing a
loop (book, ch. 13.2, 19, 25.3).

Checked against values computed independently of rigidmech: a rotor on a ball joint whose
axis a pivot holds (the bearing couple of an unbalanced rotor, d sigma_O / dt - M_O(weight),
with numpy), a tilted axis (the closed-form solution of the loop, its finite differences
and the rigid rotation about the fixed axis) and a screw jack (Lagrange's equation of the
one-parameter system, by hand).
"""

import numpy as np
import pytest

import rigidmech as rm
from rigidmech.dynamics import System
from rigidmech.errors import ConnectionError_, HyperstaticWarning
from rigidmech.inertia import InertiaOperator

JG = np.array([[0.5, -0.05, -0.08], [-0.05, 0.7, -0.02], [-0.08, -0.02, 0.9]])
OG = np.array([0.3, 0.0, 0.5])


def rotor_on_ball(alpha=0.0, mass=2.0, g=9.81, centre=OG):
    """A rotor on a ball joint at O (yaw psi, pitch theta, roll phi), its axis k held along
    the axis F.k of a pivot at O, F tilted by alpha about R0.i."""
    psi, th, ph = rm.coordinates("psi theta phi")
    R0 = rm.Frame("R0")
    A = R0.rotated("A", about=R0.k, angle=psi)
    B = A.rotated("B", about=A.j, angle=th)
    R = B.rotated("R", about=B.i, angle=ph)
    F = R0.rotated("F", about=R0.i, angle=alpha)
    G = R0.origin.moved("G", centre[0] * R.i + centre[1] * R.j + centre[2] * R.k)
    rotor = rm.Body("rotor", frame=R, mass=mass, centre=G,
                    inertia=InertiaOperator.from_matrix(JG.tolist(), frame=R, at=G))
    s = System(galilean=R0)
    s.connect(R0, rotor, rm.joints.Spherical(at=R0.origin))
    s.connect(R0, rotor, rm.joints.Pivot(at=R0.origin, axis=F.k), meets=R)
    if g:
        s.act(rm.gravity(-g * R0.k))
    return s


def matrix(psi, th, ph):
    """Rz(psi) Ry(theta) Rx(phi): the rotor's basis in R0 (by hand)."""
    c, s = np.cos, np.sin
    Rz = np.array([[c(psi), -s(psi), 0], [s(psi), c(psi), 0], [0, 0, 1]])
    Ry = np.array([[c(th), 0, s(th)], [0, 1, 0], [-s(th), 0, c(th)]])
    Rx = np.array([[1, 0, 0], [0, c(ph), -s(ph)], [0, s(ph), c(ph)]])
    return Rz @ Ry @ Rx


def closed_loop(psi, alpha):
    """theta, phi with R k = F.k = (0, -sin alpha, cos alpha): Rz(-psi) F.k =
    (sin theta cos phi, -sin phi, cos theta cos phi)."""
    ph = np.arcsin(np.cos(psi) * np.sin(alpha))
    th = np.arctan2(-np.sin(psi) * np.sin(alpha), np.cos(alpha))
    return th, ph


def test_two_orientation_conditions_close_a_pivot_on_a_ball_joint():
    s = rotor_on_ball()
    assert [row[0] for row in s.closure_conditions()] == ["2.ru", "2.rv"]
    q0, u0 = s.assemble({"psi": 0.4, "theta": 0.1, "phi": -0.2}, independent=["psi"],
                        rates={"psi": 3.0})
    assert q0["theta"] == pytest.approx(0.0, abs=1e-12)
    assert q0["phi"] == pytest.approx(0.0, abs=1e-12)
    assert u0["theta"] == pytest.approx(0.0, abs=1e-12)


def test_bearing_couple_of_an_unbalanced_rotor():
    # steady rotation Omega k about a fixed axis: the ball joint carries the force, the pivot
    # the couple C = d sigma_O/dt - M_O(weight) = Omega k ^ (J_O Omega k) - OG ^ (-m g k)
    m, g, Omega = 2.0, 9.81, 3.0
    s = rotor_on_ball(mass=m, g=g)
    q, u = [0.0, 0.0, 0.0], [Omega, 0.0, 0.0]
    eqs = s.equations_of_motion()
    qdd = np.asarray(eqs._solver().full(0.0, np.array(q), np.array(u)))[:3]
    assert np.allclose(qdd, 0.0, atol=1e-12)
    JO = JG + m * (OG @ OG * np.eye(3) - np.outer(OG, OG))
    w = np.array([0.0, 0.0, Omega])
    couple = np.cross(w, JO @ w) - np.cross(OG, [0.0, 0.0, -m * g])
    assert s.multipliers(q, u) == pytest.approx(couple[:2], rel=1e-12)
    with pytest.warns(HyperstaticWarning, match=r"2\.X, 2\.Y, 2\.Z, "):  # the ball joint's
        T = s.connection_action(s.galilean, s.bodies[0], label="2")
    assert T.resultant.is_zero


def test_tilted_axis_positions_and_velocities_match_the_loop_solution():
    alpha, rate = 0.6, 1.3
    s = rotor_on_ball(alpha=alpha, g=0.0)
    for psi in (-2.0, 0.3, 1.1, 2.7):
        th, ph = closed_loop(psi, alpha)
        q0, u0 = s.assemble({"psi": psi, "theta": th + 0.05, "phi": ph - 0.05},
                            independent=["psi"], rates={"psi": rate})
        assert (q0["theta"], q0["phi"]) == pytest.approx((th, ph), abs=1e-11)
        h = 1e-6
        (tp, pp), (tm, pm) = closed_loop(psi + h, alpha), closed_loop(psi - h, alpha)
        fd = rate * np.array([tp - tm, pp - pm]) / (2 * h)
        assert (u0["theta"], u0["phi"]) == pytest.approx(tuple(fd), rel=1e-7, abs=1e-9)
        # the rotor's axis is the pivot's
        Rk = matrix(*q0.values())[:, 2]
        assert Rk == pytest.approx([0.0, -np.sin(alpha), np.cos(alpha)], abs=1e-12)


def test_tilted_axis_motion_is_a_rotation_about_the_fixed_axis():
    # no gravity: the torque-free rotor turns uniformly about the fixed axis F.k, so
    # R(t) = Rot(F.k, Omega t) R(0) with Omega = omega(0) . F.k
    alpha = 0.6
    s = rotor_on_ball(alpha=alpha, g=0.0)
    q0, u0 = s.assemble({"psi": 0.3, "theta": 0.0, "phi": 0.0}, independent=["psi"],
                        rates={"psi": 2.0})
    eqs = s.equations_of_motion()
    sim = eqs.simulate(t=(0.0, 1.0), q0=q0, u0=u0, rtol=1e-11, atol=1e-12, n_output=11)
    axis = np.array([0.0, -np.sin(alpha), np.cos(alpha)])
    R_0 = matrix(*sim.q[:, 0])
    h = 1e-7
    dR = (matrix(*(sim.q[:, 0] + h * sim.u[:, 0])) - matrix(*(sim.q[:, 0] - h * sim.u[:, 0])))
    W = dR / (2 * h) @ R_0.T
    Omega = np.array([W[2, 1], W[0, 2], W[1, 0]]) @ axis
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    for k, tk in enumerate(sim.t):
        rot = np.eye(3) + np.sin(Omega * tk) * K + (1 - np.cos(Omega * tk)) * K @ K
        assert matrix(*sim.q[:, k]) == pytest.approx(rot @ R_0, abs=1e-8)


def test_orientation_closure_needs_the_frame_of_the_second_solid():
    psi, th, ph = rm.coordinates("psi theta phi")
    R0 = rm.Frame("R0")
    A = R0.rotated("A", about=R0.k, angle=psi)
    R = A.rotated("B", about=A.j, angle=th)
    s = System(galilean=R0)
    s.connect(R0, rm.Body("b", frame=R), rm.joints.Spherical(at=R0.origin))
    with pytest.raises(ConnectionError_, match=r"give `meets` as a frame of the second solid"):
        s.connect(R0, s.bodies[0], rm.joints.Pivot(at=R0.origin, axis=R0.k))


def test_orientation_closure_refuses_an_axis_that_turns_with_neither_solid():
    a, b, c = rm.coordinates("a b c")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=a)
    R2 = R0.rotated("R2", about=R0.i, angle=b)
    R2 = R2.rotated("R3", about=R2.j, angle=c)
    s = System(galilean=R0)
    s.connect(R0, rm.Body("one", frame=R1), rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(R0, rm.Body("two", frame=R2), rm.joints.Spherical(at=R0.origin))
    with pytest.raises(ConnectionError_, match=r"the axis of the joint closing a loop must "
                                               r"be fixed in one"):
        s.connect(s.bodies[0], s.bodies[1], rm.joints.Pivot(at=R0.origin, axis=R0.i),
                  meets=R2)


def screw_jack(m=3.0, g=9.81, J=0.02, pitch=0.01):
    """A screw turning about R0.k (theta) drives a nut sliding along R0.k (z); the helical
    joint between them closes the loop."""
    th, z = rm.coordinates("theta z")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    P = R0.point("P", 0, 0, z)
    screw = rm.Body("screw", frame=R1, mass=1.0, inertia=InertiaOperator.from_matrix(
        [[0.1, 0, 0], [0, 0.1, 0], [0, 0, J]], frame=R1))
    nut = rm.Body("nut", frame=R0.translated("R2", P), mass=m, centre=P)
    s = System(galilean=R0)
    s.connect(R0, screw, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(R0, nut, rm.joints.Prismatic(at=P, axis=R0.k))
    s.connect(screw, nut, rm.actions.Helical(at=R0.origin, axis=R1.k, pitch=pitch), meets=P)
    s.act(rm.gravity(-g * R0.k))
    return s


def test_screw_jack_closed_by_a_helical_joint():
    # z' = -h theta' (the nut does not turn: it moves by -h per radian of the screw
    # relative to it); T = (J + m h^2) theta'^2 / 2, V = m g z: (J + m h^2) theta'' = m g h
    m, g, J, pitch = 3.0, 9.81, 0.02, 0.01
    h = pitch / (2 * np.pi)
    s = screw_jack(m, g, J, pitch)
    ((label, c, phi),) = s.closure_conditions()
    assert label == "3.h" and phi is None
    q, u = [0.2, 0.1], [1.0, -h]
    qdd = np.asarray(s.equations_of_motion()._solver().full(0.0, np.array(q), np.array(u)))
    assert qdd[0] == pytest.approx(m * g * h / (J + m * h * h), rel=1e-12)
    assert qdd[1] == pytest.approx(-h * qdd[0], rel=1e-12)
    # the multiplier is the axial force Z on the nut: m z'' = -m g + Z
    assert s.multipliers(q, u)[0] == pytest.approx(m * (qdd[1] + g), rel=1e-12)
    with pytest.warns(HyperstaticWarning, match=r"3\.X, 3\.Y, 3\.L, 3\.M, "):
        T = s.connection_action(s.bodies[0], s.bodies[1], label="3")
    k = s.galilean.k  # the book's N = -h Z
    assert float(T.moment.dot(k) / T.resultant.dot(k)) == pytest.approx(-h, rel=1e-12)


def test_screw_jack_keeps_its_linked_motion_along_a_simulation():
    h = 0.01 / (2 * np.pi)
    s = screw_jack()
    sim = s.equations_of_motion().simulate(t=(0.0, 2.0), q0={"theta": 0.0, "z": 0.0},
                                           u0={"theta": 0.5, "z": -0.5 * h}, rtol=1e-11,
                                           atol=1e-12, n_output=5)
    assert sim.q[1] + h * sim.q[0] == pytest.approx(np.zeros(5), abs=1e-9)
