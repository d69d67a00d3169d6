"""Rolling contact and gear mesh as connections (book, ch. 10.1.3, 10.2.3, 13.1).

Checked: the constraints they impose (closed forms worked in the comments), whether they are
holonomic, and that the power of their action with every motion they allow is zero (the
comoment computed by Torsor.comoment, independently of how the action was built)."""

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidmech as rm
from rigidmech._core.errors import ConnectionError_
from rigidmech.kinematics import Circle, ContactKinematics, Gear, GearPair, Sphere, kinematic_torsor

r = sp.Symbol("r", positive=True)
t = rm.t
values = st.floats(-10, 10, allow_nan=False, allow_infinity=False)


def _ball():
    x, y, psi, theta, phi = rm.coordinates("x y psi theta phi")
    R0 = rm.Frame("R0")
    ball = R0.euler("B", psi, theta, phi, origin=R0.point("C", x, y, r))
    contact = ContactKinematics.between(ball, Sphere(ball.origin, r), R0, rm.Plane(R0.origin, R0.k))
    return R0, ball, contact, (x, y, psi, theta, phi)


@pytest.mark.parametrize("pivoting", [True, False])
@settings(max_examples=10, deadline=None)
@given(data=st.data())
def test_power_of_the_rolling_contact_action_is_zero(pivoting, data):
    R0, ball, contact, _ = _ball()
    rc = rm.joints.RollingContact(contact, pivoting=pivoting)
    T, unknowns = rc.action_torsor("01")
    V, free = rc.allowed_motion("01")
    assert len(free) == rc.degrees_of_freedom
    rule = {s: data.draw(values) for s in (*unknowns, *free)}
    B = R0.point("B", 1, -2, 3)
    power = T.subs(rule).at(B).comoment(V.subs(rule).at(B))
    assert abs(float(sp.N(power.subs(r, 0.7)))) < 1e-11 * (1 + sum(map(abs, rule.values())))**2


def test_ball_rolling_on_a_plane_is_nonholonomic():
    """v(I in B/R0) = v(C) + omega ^ CI with CI = -r k0: the no-slip equations are
    x' - r omega_y = 0, y' + r omega_x = 0 (omega in R0), not integrable."""
    R0, ball, contact, (x, y, psi, theta, phi) = _ball()
    rc = rm.joints.RollingContact(contact)
    w = ball.rotation_vector(R0)
    wx, wy = w.dot(R0.i), w.dot(R0.j)
    got = [c.expression for c in rc.velocity_constraints()]
    expected = [x.diff(t) - r * wy, y.diff(t) + r * wx]  # along t1 = i0, t2 = k0 ^ i0 = j0
    assert [sp.simplify(g - e) for g, e in zip(got, expected, strict=True)] == [0, 0]
    assert not rc.holonomic
    with pytest.raises(ConnectionError_, match="is not holonomic"):
        rc.position_constraints()
    # without pivoting: omega . k0 = psi' + phi' cos(theta) = 0 as well
    no_pivot = rm.joints.RollingContact(contact, pivoting=False)
    assert sp.simplify(no_pivot.velocity_constraints()[-1].expression
                       - (psi.diff(t) + phi.diff(t) * sp.cos(theta))) == 0


def _gears(internal):
    q1, q2 = rm.coordinates("q1 q2")
    R0 = rm.Frame("R0")
    pair = GearPair(Gear(12, 1), Gear(30, 1), internal=internal)  # r1 = 6, r2 = 15
    O2 = R0.point("O2", pair.centre_distance, 0, 0)
    g1 = R0.rotated("G1", about=R0.k, angle=q1)
    g2 = R0.rotated("G2", about=R0.k, angle=q2, origin=O2)
    return R0, pair, g1, g2, (q1, q2)


@pytest.mark.parametrize("internal", [False, True], ids=["external", "internal"])
def test_gear_mesh_constraint_pitch_point_and_zero_power(internal):
    """Ratio -6/15 (external) or 6/15 (internal): the pitch points of the two gears have the
    same velocity once the constraint holds, so the action through the pitch point does no
    work in the relative motion (ch. 10.2.3)."""
    R0, pair, g1, g2, (q1, q2) = _gears(internal)
    mesh = rm.joints.GearMesh(pair, g1, g2, carrier=R0, axis=R0.k)
    lam = sp.Rational(2, 5) * (1 if internal else -1)
    assert mesh.ratio == lam and mesh.holonomic
    (rel,) = mesh.position_constraints({q1: 0, q2: 0})
    assert sp.simplify(rel - (q2 - lam * q1)) == 0
    I = mesh.pitch_point
    assert list(I.coordinates(R0)) == [-6 if internal else 6, 0, 0]
    T, (F,) = mesh.action_torsor("12")
    V21 = kinematic_torsor(g2, relative_to=g1, at=I)
    on_constraint = {q2.diff(t): lam * q1.diff(t)}
    power = T.comoment(rm.Torsor(V21.rotation, V21.velocity, I)).subs(on_constraint)
    assert sp.simplify(power) == 0
    # the radial part pushes gear 2 away from gear 1 (external) or outwards (internal)
    radial = T.resultant.dot(R0.i).subs(F, 1)
    assert sp.simplify(radial - (-1 if internal else 1) * sp.tan(sp.pi / 9)) == 0


@pytest.mark.parametrize("internal", [False, True], ids=["external", "internal"])
@settings(max_examples=10, deadline=None)
@given(F=values, w=values, alpha=st.floats(0, 0.5))
def test_power_of_the_gear_mesh_action_with_its_allowed_motion_is_zero(internal, F, w, alpha):
    R0, pair, g1, g2, _ = _gears(internal)
    mesh = rm.joints.GearMesh(pair, g1, g2, carrier=R0, axis=R0.k, pressure_angle=alpha)
    T, (F_,) = mesh.action_torsor("12")
    V, (w_,) = mesh.allowed_motion("12")
    assert mesh.degrees_of_freedom == len((w_,))
    B = R0.point("B", 1, 2, 3)
    power = T.subs(F_, F).at(B).comoment(V.subs(w_, w).at(B))
    assert abs(float(power)) < 1e-12 * (1 + abs(F) * abs(w))


def test_planar_wheel_rolling_contact_is_holonomic():
    x, theta = rm.coordinates("x theta")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=theta, origin=R0.point("C", x, r, 0))
    rc = rm.joints.RollingContact(ContactKinematics.between(R1, Circle(R1.origin, r, normal=R0.k),
                                                  R0, rm.Line(R0.origin, R0.i)))
    assert rc.holonomic and rc.solids[0].frame is R1
    (rel,) = rc.position_constraints({x: 0, theta: 0})
    assert sp.simplify(rel - (x + r * theta)) == 0


def test_bad_input_is_refused():
    R0, pair, g1, g2, _ = _gears(False)
    with pytest.raises(ConnectionError_, match="at the pair's centre distance 21; got a "
                                               "distance of 5"):
        rm.joints.GearMesh(pair, g1, g2, carrier=R0, axis=R0.k,
                           centres=(R0.origin, R0.point("P", 3, 4, 0)))
    with pytest.raises(TypeError, match="`pair` must be a GearPair"):
        rm.joints.GearMesh(-0.5, g1, g2, carrier=R0, axis=R0.k)
    with pytest.raises(ValueError, match="`axis` must be fixed in the carrier"):
        rm.joints.GearMesh(pair, g1, g2, carrier=R0, axis=g1.i)
    with pytest.raises(TypeError, match="`contact` must be a ContactKinematics"):
        rm.joints.RollingContact(R0)
