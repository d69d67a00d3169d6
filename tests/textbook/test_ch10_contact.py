"""Book ch. 10 (and 9.4.5): kinematics of rigid bodies in contact, transmissions, plane motion.

Each expected value is justified independently of rigidmech's code path:

* wheel on a line: the cycloid x = r(phi - sin phi), y = r(1 - cos phi) (ch. 7.5), the
  contact point at rest and accelerated by r omega^2 towards the centre (v(B) = v(A) +
  omega ^ AB differentiated by hand);
* disc inside a ring: the hypocycloid x = (R - r) cos psi + r cos((R - r) psi / r),
  y = (R - r) sin psi - r sin((R - r) psi / r), a straight line when R = 2 r (La Hire);
* gear trains and a planetary train: ratios by hand and Willis' closed form, and the same
  train rebuilt as solids rolling on each other with rigidmech's contact kinematics;
* belts: closed forms of the length, against a numerical construction of the belt (convex
  hull of the pulleys for the open belt, tangent points by root finding for the crossed one);
* sphere on a plane: v(I) = v(C) + omega ^ CI written by hand in R0;
* ladder on a floor and a wall: the ICR at the corner of the rectangle OAIB; centrodes: a
  circle of radius L about O and a circle of radius L/2 about the ladder's middle (Thales).
"""

import math

import numpy as np
import pytest
import sympy as sp
import sympy.physics.mechanics as me
from numpy.testing import assert_allclose
from scipy.optimize import brentq
from scipy.spatial import ConvexHull

import rigidmech as rm
from rigidmech.kinematics import (
    BeltDrive,
    Circle,
    ContactKinematics,
    EpicyclicTrain,
    Gear,
    GearPair,
    GearTrain,
    Solid,
    Sphere,
    centrodes,
    instantaneous_centre,
)

t = rm.t
r, R, L = sp.symbols("r R L", positive=True)


# -- a wheel rolling on a line ---------------------------------------------------------------
@pytest.fixture(scope="module")
def wheel():
    x, theta = rm.coordinates("x theta")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=theta, origin=R0.point("C", x, r, 0))
    rolling = rm.joints.RollingContact(ContactKinematics.between(
        R1, Circle(R1.origin, r, normal=R0.k), R0, rm.Line(R0.origin, R0.i)))
    (rel,) = rolling.position_constraints({x: 0, theta: 0})
    x_of_theta = sp.solve(rel, x)[0]  # x = -r theta
    return R0, R1, rolling, x, theta, x_of_theta


def test_ch10_wheel_no_slip_gives_x_equal_minus_r_theta(wheel):
    R0, R1, rolling, x, theta, x_of_theta = wheel
    # v(I in wheel/R0) = x' i0 + theta' k0 ^ (-r j0) = (x' + r theta') i0 = 0
    assert sp.simplify(x_of_theta + r * theta) == 0


def test_ch10_wheel_rim_point_traces_a_cycloid(wheel):
    R0, R1, rolling, x, theta, x_of_theta = wheel
    P = R1.origin.moved("P", -r * R1.j)  # the rim point at the contact point when theta = 0
    phi = sp.Symbol("phi", real=True)    # angle rolled: phi = -theta
    xy = P.coordinates(R0).subs(x, x_of_theta).subs(theta, -phi)
    expected = [r * (phi - sp.sin(phi)), r * (1 - sp.cos(phi)), 0]
    assert [sp.simplify(g - e) for g, e in zip(xy, expected, strict=True)] == [0, 0, 0]
    # radius of curvature of the cycloid at its top (phi = pi): 4 r (closed form 4 r sin(phi/2))
    cycloid = rm.Curve(R0.vector(*expected), phi, R0)
    assert sp.simplify(cycloid.radius_of_curvature(at=sp.pi) - 4 * r) == 0


@pytest.mark.parametrize("what", [
    pytest.param("velocity", id="contact_point_velocity_zero"),
    pytest.param("acceleration", id="contact_point_acceleration_r_omega2_to_centre"),
])
def test_ch10_wheel_contact_point(wheel, what):
    R0, R1, rolling, x, theta, x_of_theta = wheel
    I = rolling.contact.point
    S = Solid("wheel", R1)
    on_rolling = {x: x_of_theta}
    if what == "velocity":
        v = S.velocity(I, relative_to=R0).subs(on_rolling).applyfunc(sp.Expr.doit)
        assert v.simplify().is_zero or all(sp.simplify(c) == 0 for c in v.components(R0))
    else:
        a = S.acceleration(I, relative_to=R0).subs(on_rolling).applyfunc(sp.Expr.doit)
        w = theta.diff(t)
        expected = r * w**2 * R0.j  # towards the centre C, magnitude r omega^2
        assert all(sp.simplify(c) == 0 for c in (a - expected).components(R0))


# -- a disc rolling inside a ring ------------------------------------------------------------
@pytest.fixture(scope="module")
def hypocycloid():
    psi, theta = rm.coordinates("psi theta")
    R0 = rm.Frame("R0")
    arm = R0.rotated("Ra", about=R0.k, angle=psi)
    C = R0.origin.moved("C", (R - r) * arm.i)
    disc = R0.rotated("Rd", about=R0.k, angle=theta, origin=C)
    contact = ContactKinematics.between(disc, Circle(C, r, normal=R0.k), R0,
                              Circle(R0.origin, R, normal=R0.k), inner="moving")
    rolling = rm.joints.RollingContact(contact)
    (rel,) = rolling.position_constraints({psi: 0, theta: 0})
    theta_of_psi = sp.solve(rel, theta)[0]
    return R0, disc, C, psi, theta, theta_of_psi


def test_ch10_disc_in_ring_no_slip_relation(hypocycloid):
    R0, disc, C, psi, theta, theta_of_psi = hypocycloid
    # v(I) = ((R - r) psi' + r theta') e_psi_perp = 0  =>  theta = -(R - r) psi / r
    assert sp.simplify(theta_of_psi + (R - r) * psi / r) == 0


@pytest.mark.parametrize("ratio", [pytest.param(None, id="general"),
                                   pytest.param(2, id="la_hire_R_equals_2r")])
def test_ch10_disc_in_ring_rim_point_traces_a_hypocycloid(hypocycloid, ratio):
    R0, disc, C, psi, theta, theta_of_psi = hypocycloid
    P = C.moved("P", r * disc.i)  # on the ring when psi = theta = 0
    xy = P.coordinates(R0).subs(theta, theta_of_psi)
    k = (R - r) / r
    expected = [(R - r) * sp.cos(psi) + r * sp.cos(k * psi),
                (R - r) * sp.sin(psi) - r * sp.sin(k * psi), 0]
    if ratio is not None:  # R = 2 r: the point moves on a diameter, x = 2 r cos(psi), y = 0
        xy = xy.subs(R, ratio * r)
        expected = [2 * r * sp.cos(psi), 0, 0]
    assert [sp.simplify(sp.expand_trig(g - e)) for g, e in
            zip(xy, expected, strict=True)] == [0, 0, 0]


def test_ch10_disc_in_ring_centre_speed(hypocycloid):
    R0, disc, C, psi, theta, theta_of_psi = hypocycloid
    # |v(C)| = (R - r) |psi'| = r |theta'| (the disc turns about I, at distance r from C)
    v2 = C.velocity(R0).dot(C.velocity(R0))
    assert sp.simplify(v2 - ((R - r) * psi.diff(t)) ** 2) == 0
    w = sp.diff(theta_of_psi, t)
    assert sp.simplify(v2 - (r * w) ** 2) == 0


# -- gear trains and an epicyclic train ------------------------------------------------------
@pytest.mark.parametrize("pairs, expected", [
    pytest.param([(20, 60, False)], sp.Rational(-1, 3), id="simple_external_20_60"),
    pytest.param([(20, 60, True)], sp.Rational(1, 3), id="simple_internal_20_60"),
    pytest.param([(15, 45, False), (20, 80, False)], sp.Rational(1, 12),
                 id="compound_two_stages_1_over_12"),
    pytest.param([(10, 30, False), (30, 20, False), (20, 50, False)], sp.Rational(-1, 5),
                 id="idlers_only_sign_changes"),
])
def test_ch10_gear_train_ratios(pairs, expected):
    # by hand: product of -z_driver/z_driven (external) or +z_driver/z_driven (internal)
    train = GearTrain(*(GearPair(Gear(a, 2), Gear(b, 2), internal=i) for a, b, i in pairs))
    assert train.ratio == expected


def test_ch10_epicyclic_train_willis_closed_form():
    """Sun z_s, planets z_p, ring z_r = z_s + 2 z_p held fixed: omega_c / omega_s =
    z_s / (z_s + z_r) (the classic closed form; Willis with lambda = -z_s / z_r)."""
    zs, zp = sp.symbols("z_s z_p", positive=True, integer=True)
    zr = zs + 2 * zp
    ws = sp.Symbol("omega_s")
    train = EpicyclicTrain(GearTrain(GearPair(Gear(zs, 1), Gear(zp, 1)),
                                     GearPair(Gear(zp, 1), Gear(zr, 1), internal=True)))
    assert sp.simplify(train.ratio + zs / zr) == 0
    wc = train.solve(first=ws, last=0)["carrier"]
    assert sp.simplify(wc - ws * zs / (zs + zr)) == 0


def test_ch10_epicyclic_train_from_rolling_solids():
    """The planetary train rebuilt as solids: sun (angle a) about O, carrier (angle c), planet
    (angle p) about the carrier's pin at r_s + r_p, fixed ring of radius r_s + 2 r_p. No
    slipping at the two pitch points gives omega_c / omega_s = r_s / (2 (r_s + r_p)), the
    same as Willis with z proportional to r."""
    a, c, p = rm.coordinates("a c p")
    rs, rp = sp.symbols("r_s r_p", positive=True)
    R0 = rm.Frame("R0")
    sun = R0.rotated("S", about=R0.k, angle=a)
    carrier = R0.rotated("K", about=R0.k, angle=c)
    pin = R0.origin.moved("Pc", (rs + rp) * carrier.i)
    planet = R0.rotated("P", about=R0.k, angle=p, origin=pin)
    sun_planet = ContactKinematics.between(planet, Circle(pin, rp, normal=R0.k),
                                 sun, Circle(R0.origin, rs, normal=R0.k))
    planet_ring = ContactKinematics.between(planet, Circle(pin, rp, normal=R0.k), R0,
                                  Circle(R0.origin, rs + 2 * rp, normal=R0.k), inner="moving")
    eqs = [*sun_planet.without_slipping_equations(), *planet_ring.without_slipping_equations()]
    sol = sp.solve(eqs, [c.diff(t), p.diff(t)], dict=True)[0]
    got = sp.simplify(sol[c.diff(t)] / a.diff(t))
    assert sp.simplify(got - rs / (2 * (rs + rp))) == 0
    willis = EpicyclicTrain(-rs / (rs + 2 * rp)).solve(first=1, last=0)["carrier"]
    assert sp.simplify(got - willis) == 0


# -- belts -----------------------------------------------------------------------------------
def _hull_length(r1, r2, a, n=20000):
    """Perimeter of the convex hull of the two discs: the open belt (polygon error ~ 1e-8)."""
    u = np.linspace(0, 2 * np.pi, n, endpoint=False)
    pts = np.vstack([np.column_stack([r1 * np.cos(u), r1 * np.sin(u)]),
                     np.column_stack([a + r2 * np.cos(u), r2 * np.sin(u)])])
    hull = pts[ConvexHull(pts).vertices]
    return float(np.sum(np.linalg.norm(np.roll(hull, -1, axis=0) - hull, axis=1)))


def _crossed_length(r1, r2, a):
    """Tangent point at angle f on pulley 1 (centre 0), f + pi on pulley 2 (centre a i): the
    segment is orthogonal to the radius; the belt wraps 2 pi - 2 f on each pulley."""
    def tangency(f):
        p1 = r1 * np.array([np.cos(f), np.sin(f)])
        p2 = np.array([a, 0.0]) + r2 * np.array([np.cos(f + np.pi), np.sin(f + np.pi)])
        return float(np.dot(p2 - p1, [np.cos(f), np.sin(f)]))
    f = brentq(tangency, 1e-9, np.pi / 2, xtol=1e-15)
    p1 = r1 * np.array([np.cos(f), np.sin(f)])
    p2 = np.array([a, 0.0]) - r2 * np.array([np.cos(f), np.sin(f)])
    return 2 * float(np.linalg.norm(p2 - p1)) + (2 * np.pi - 2 * f) * (r1 + r2)


@pytest.mark.parametrize("r1, r2, a", [
    pytest.param(1.0, 3.0, 10.0, id="open_1_3_10"),
    pytest.param(2.5, 0.5, 4.0, id="open_2.5_0.5_4"),
])
def test_ch10_open_belt_length(r1, r2, a):
    belt = BeltDrive(r1, r2, a)
    beta = math.asin((r2 - r1) / a)
    closed = 2 * a * math.cos(beta) + math.pi * (r1 + r2) + 2 * beta * (r2 - r1)
    assert_allclose(float(belt.length), closed, rtol=1e-14)
    # rtol 1e-7: a polygon of 20000 vertices per pulley under-estimates arcs by ~ (2pi/n)^2/24
    assert_allclose(float(belt.length), _hull_length(r1, r2, a), rtol=1e-7)
    assert math.isclose(float(belt.ratio), r1 / r2, rel_tol=1e-15)


@pytest.mark.parametrize("r1, r2, a", [
    pytest.param(1.0, 3.0, 10.0, id="crossed_1_3_10"),
    pytest.param(2.0, 2.0, 4.5, id="crossed_2_2_4.5"),
])
def test_ch10_crossed_belt_length(r1, r2, a):
    belt = BeltDrive(r1, r2, a, crossed=True)
    beta = math.asin((r1 + r2) / a)
    closed = 2 * a * math.cos(beta) + (math.pi + 2 * beta) * (r1 + r2)
    assert_allclose(float(belt.length), closed, rtol=1e-14)
    assert_allclose(float(belt.length), _crossed_length(r1, r2, a), rtol=1e-12)
    assert float(belt.ratio) == -r1 / r2


# -- a sphere rolling on a plane -------------------------------------------------------------
def test_ch10_sphere_rolling_on_a_plane_no_slip_conditions():
    """Euler angles (psi, theta, phi) of the ball, centre (x, y, r): in R0,
    omega = psi' k0 + theta' u + phi' k with u = (cos psi, sin psi, 0) and
    k = (sin psi sin theta, -cos psi sin theta, cos theta); no slipping:
    x' = r omega_y, y' = -r omega_x; no pivoting: omega_z = psi' + phi' cos(theta) = 0."""
    x, y, psi, theta, phi = rm.coordinates("x y psi theta phi")
    R0 = rm.Frame("R0")
    ball = R0.euler("B", psi, theta, phi, origin=R0.point("C", x, y, r))
    c = ContactKinematics.between(ball, Sphere(ball.origin, r), R0, rm.Plane(R0.origin, R0.k))
    d = [v.diff(t) for v in (psi, theta, phi)]
    wx = d[1] * sp.cos(psi) + d[2] * sp.sin(psi) * sp.sin(theta)
    wy = d[1] * sp.sin(psi) - d[2] * sp.cos(psi) * sp.sin(theta)
    wz = d[0] + d[2] * sp.cos(theta)
    got = c.without_slipping_equations()
    expected = (x.diff(t) - r * wy, y.diff(t) + r * wx)  # tangents i0, j0
    assert [sp.simplify(g - e) for g, e in zip(got, expected, strict=True)] == [0, 0]
    (spin,) = c.without_pivoting_equations()
    assert sp.simplify(spin - wz) == 0
    assert c.without_slipping().equals(expected[0] * R0.i + expected[1] * R0.j)


# -- the ladder: ICR and centrodes -----------------------------------------------------------
@pytest.fixture(scope="module")
def ladder():
    theta = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    A = R0.point("A", L * sp.cos(theta), 0, 0)  # on the floor
    bar = R0.rotated("R1", about=R0.k, angle=sp.pi - theta, origin=A)  # i1 along AB
    return R0, bar, theta


def test_ch9_ladder_icr_at_the_corner_of_the_rectangle(ladder):
    R0, bar, theta = ladder
    I = instantaneous_centre(bar, relative_to=R0)
    assert [sp.simplify(c) for c in I.coordinates(R0)] == [L * sp.cos(theta),
                                                          L * sp.sin(theta), 0]
    B = bar.origin.moved("B", L * bar.i)
    assert [sp.simplify(c) for c in B.coordinates(R0)] == [0, L * sp.sin(theta), 0]  # on wall
    v = Solid("ladder", bar).velocity(I, relative_to=R0)
    assert all(sp.simplify(c) == 0 for c in v.components(R0))


@pytest.mark.parametrize("curve, centre, radius", [
    pytest.param("base", (0, 0), L, id="base_curve_circle_L_about_corner"),
    pytest.param("rolling", (L / 2, 0), L / 2, id="rolling_curve_circle_L_over_2"),
])
def test_ch9_ladder_centrodes(ladder, curve, centre, radius):
    R0, bar, theta = ladder
    cs = centrodes(bar, relative_to=R0, parameter=theta)
    c = getattr(cs, curve)
    frame = R0 if curve == "base" else bar
    pos = c.position().components(frame)
    d2 = (pos[0] - centre[0]) ** 2 + (pos[1] - centre[1]) ** 2
    assert sp.simplify(d2 - radius**2) == 0 and pos[2] == 0
    assert sp.simplify(c.curvature() - 1 / radius) == 0


# -- a disc (coin) rolling on a plane, in 3D -------------------------------------------------
def test_ch10_rolling_disc_contact_point_and_no_slip_vs_sympy_mechanics():
    """Disc of radius r: heading psi about k0, tilt theta about the line of nodes, spin phi
    about its axis; contact point (x, y, 0), centre C = I + r j_theta (above the plane for
    0 < theta < pi). The contact point is found from the circle and the plane; the sliding
    velocity v(I in D/R0) is compared with sympy.physics.mechanics (an independent
    implementation of frames and angular velocities) at random states to 1e-12."""
    x, y, psi, theta, phi = rm.coordinates("x y psi theta phi")
    R0 = rm.Frame("R0")
    Rp = R0.rotated("Rp", about=R0.k, angle=psi)
    Rt = Rp.rotated("Rt", about=Rp.i, angle=theta)
    C = R0.point("P", x, y, 0).moved("C", r * Rt.j)
    disc = Rt.rotated("D", about=Rt.k, angle=phi, origin=C)
    c = ContactKinematics.between(disc, Circle(C, r, normal=disc.k), R0, rm.Plane(R0.origin, R0.k))
    assert [sp.simplify(v) for v in c.point.coordinates(R0)] == [x, y, 0]
    assert c.normal == R0.k
    assert sp.simplify(c.persistence_equation()) == 0  # the contact persists identically
    eqs = c.without_slipping_equations()
    assert len(eqs) == 2
    assert not any(rm.kinematics.VelocityConstraint(e).holonomic for e in eqs)

    # sympy.physics.mechanics, the same disc
    qs = me.dynamicsymbols("x y psi theta phi")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [qs[2], N.z])
    B = A.orientnew("B", "Axis", [qs[3], A.x])
    Dm = B.orientnew("Dm", "Axis", [qs[4], B.z])
    O = me.Point("O")
    C_m = O.locatenew("C", qs[0] * N.x + qs[1] * N.y + r * B.y)
    v_I = C_m.pos_from(O).dt(N) + Dm.ang_vel_in(N).cross(-r * B.y)
    theirs = [v_I.dot(e) for e in (N.x, N.y, N.z)]
    ours = list(c.sliding_velocity.components(R0))

    rng = np.random.default_rng(11)
    to_state = {}
    for q_ours, q_m in zip((x, y, psi, theta, phi), qs, strict=True):
        to_state[q_ours.diff(t)] = to_state[q_m.diff(me.dynamicsymbols._t)] = sp.Symbol(
            f"d{q_m}")
        to_state[q_ours] = to_state[q_m] = sp.Symbol(f"s{q_m}")
    syms = sorted({*to_state.values()}, key=str) + [r]
    f_ours = sp.lambdify(syms, [e.subs(to_state) for e in ours], "numpy")
    f_theirs = sp.lambdify(syms, [e.subs(to_state) for e in theirs], "numpy")
    for _ in range(20):
        state = rng.uniform(-2, 2, len(syms))
        state[-1] = abs(state[-1]) + 0.1
        assert_allclose(f_ours(*state), f_theirs(*state), rtol=1e-12, atol=1e-12)
