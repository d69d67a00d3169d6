"""Book ch. 17 (change of reference system) and its classic applications on the Earth
(ch. 12.2.1, 19): closed forms derived by hand, checked with rigidmech's composition of
accelerations and inertial action torsors.

Conventions: R0 = (O; i0, j0, k0) Galilean; R1 the moving reference; omega = omega(R1/R0).
a(M/R0) = a_r + a_e + a_c with a_c = 2 omega ^ v(M/R1) (ch. 17.1.3); the inertial forces are
-m a_e and -m a_c (ch. 17.2, 19.1.1). On the Earth: local frame (east, north, up) at the
latitude lambda, Omega = 7.292115e-5 rad/s, Omega = Omega (cos(lambda) north + sin(lambda) up).
"""

import math

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

import rigidmech as rm
from rigidmech._core.errors import ArgumentError
from rigidmech.actions import surface_gravity
from rigidmech.kinematics import acceleration_composition, velocity_composition
from rigidmech.kinetics import (
    EARTH_ROTATION_RATE,
    coriolis_inertial_torsor,
    earth_reference,
    entrainment_inertial_torsor,
)

t = rm.t


def test_bead_on_a_rotating_rod_accelerations():
    """A bead M at r(t) on a rod turning at theta(t) about k0 in a horizontal plane (ch. 17.1):
    a_r = r'' e_r, a_e = -r theta'^2 e_r + r theta'' e_theta, a_c = 2 r' theta' e_theta;
    their sum is the polar acceleration (r'' - r theta'^2) e_r + (r theta'' + 2 r' theta')
    e_theta; v_r = r' e_r, v_e = r theta' e_theta."""
    r, th = rm.coordinates("r theta")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    M = R0.origin.moved("M", r * R1.i)
    acc = acceleration_composition(M, relative_to=R1, absolute=R0)
    rd, rdd, thd, thdd = r.diff(t), r.diff(t, 2), th.diff(t), th.diff(t, 2)
    assert acc.relative.equals(rdd * R1.i)
    assert acc.entrainment.equals(-r * thd**2 * R1.i + r * thdd * R1.j)
    assert acc.coriolis.equals(2 * rd * thd * R1.j)
    assert acc.absolute.equals((rdd - r * thd**2) * R1.i + (r * thdd + 2 * rd * thd) * R1.j)
    vel = velocity_composition(M, relative_to=R1, absolute=R0)
    assert vel.relative.equals(rd * R1.i) and vel.entrainment.equals(r * thd * R1.j)


def test_bead_on_a_rod_turning_uniformly_the_rods_action():
    """Rod turning at the constant rate w, no friction, no gravity in the plane: in R1 the
    fundamental principle with the inertial forces reads m r'' e_r = N e_theta + m w^2 r e_r
    - 2 m w r' e_theta (ch. 19.1.1), so r'' = w^2 r and N = 2 m w r'. From r(0) = r0 at rest
    on the rod, r = r0 cosh(w t) and N = 2 m w^2 r0 sinh(w t)."""
    r = rm.coordinates("r")
    m, w, r0 = sp.symbols("m w r0", positive=True)
    N = sp.Symbol("N")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=w * t)
    bead = rm.Body("bead", frame=R1.translated("Rb", R1.point("B", r, 0, 0)), mass=m)
    kw = {"relative_to": R1, "absolute": R0}
    F = (entrainment_inertial_torsor(bead, **kw) + coriolis_inertial_torsor(bead, **kw)
         ).resultant + N * R1.j
    balance = (m * bead.centre.acceleration(R1) - F).components(R1)
    sol = sp.solve([balance[0], balance[1]], [r.diff(t, 2), N], dict=True)[0]
    assert sp.simplify(sol[r.diff(t, 2)] - w**2 * r) == 0
    assert sp.simplify(sol[N] - 2 * m * w * r.diff(t)) == 0
    motion = {r: r0 * sp.cosh(w * t)}
    assert sp.simplify(sol[N].subs(motion).doit() - 2 * m * w**2 * r0 * sp.sinh(w * t)) == 0
    # the Galilean route gives the same N: m a(M/R0) . e_theta = N
    galilean = (m * bead.centre.acceleration(R0)).components(R1)[1]
    assert sp.simplify(galilean - sol[N]) == 0


def test_disc_spinning_on_a_turntable():
    """A disc (mass m, axial moment C, axis k) spinning at phi' with its centre at distance d
    on a turntable turning at theta' about k0 (ch. 17.2): the inertial torsor of entrainment
    at G is {m d theta'^2 i1 - m d theta'' j1 ; -C theta'' k}; that of Coriolis is zero (G is
    fixed in R1 and omega(S/R1) is parallel to omega(R1/R0))."""
    th, ph = rm.coordinates("theta phi")
    m, d, A, C = sp.symbols("m d A C", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    RS = R1.rotated("RS", about=R1.k, angle=ph, origin=R1.point("G", d, 0, 0))
    disc = rm.Body("disc", frame=RS, mass=m,
                   inertia=rm.InertiaOperator.from_products(A, A, C, frame=RS))
    kw = {"relative_to": R1, "absolute": R0}
    Fe = entrainment_inertial_torsor(disc, **kw)
    assert Fe.resultant.equals(m * d * th.diff() ** 2 * R1.i - m * d * th.diff(t, 2) * R1.j)
    assert Fe.moment.equals(-C * th.diff(t, 2) * R1.k)
    Fc = coriolis_inertial_torsor(disc, **kw)
    assert Fc.resultant.is_zero and Fc.moment.simplify(R1).is_zero


@pytest.mark.parametrize("latitude_deg, V, m", [
    pytest.param(48.85, 80.0, 4.0e5, id="train-north-paris"),
    pytest.param(-33.9, 30.0, 1.0e5, id="train-north-southern-hemisphere"),
])
def test_train_running_north_coriolis_force_on_the_rails(latitude_deg, V, m):
    """A train of mass m running north at speed V (ch. 19): a_c = 2 Omega ^ V n =
    -2 Omega V sin(lambda) e, so the rails must push the train with m a_c, i.e. westwards in
    the northern hemisphere, and the train pushes the rails eastwards with
    2 m Omega V sin(lambda) (Paris, 400 t at 80 m/s: 3.5 kN)."""
    lam = math.radians(latitude_deg)
    E = earth_reference(latitude=lam)
    x = rm.coordinates("x")
    M = E.frame.origin.moved("M", x * E.north)
    a_c = acceleration_composition(M, relative_to=E.frame, absolute=E.geocentric).coriolis
    on_rails = (-m * a_c).subs(x.diff(t), V).components(E.frame)
    expected = 2 * m * EARTH_ROTATION_RATE * V * math.sin(lam)
    assert_allclose([float(c) for c in on_rails], [expected, 0, 0], rtol=1e-13, atol=1e-12)
    if latitude_deg == 48.85:
        assert round(expected / 1e3, 1) == 3.5


@pytest.mark.parametrize("latitude_deg", [0.0, 30.0, 45.0, 60.0, 90.0, -45.0])
def test_apparent_gravity_and_plumb_line_deviation(latitude_deg):
    """g_a = sqrt((g0 - W^2 R cos^2 l)^2 + (W^2 R sin l cos l)^2), tan(alpha) =
    W^2 R sin l cos l / (g0 - W^2 R cos^2 l) (ch. 12.2.1), with g0 = G M / R^2 of the
    homogeneous Earth (ch. 12.1.3): g_a = g0 - W^2 R at the equator, g0 at the poles, and a
    deviation of about 0.1 degree at 45 degrees."""
    lam = math.radians(latitude_deg)
    Rn, W = 6.371e6, EARTH_ROTATION_RATE
    g0 = float(surface_gravity(5.972e24, Rn))
    E = earth_reference(latitude=lam, radius=Rn)
    ga = [float(c) for c in E.apparent_gravity(g0).components(E.frame)]
    c2 = W**2 * Rn
    expected = [0.0, -c2 * math.sin(lam) * math.cos(lam), -(g0 - c2 * math.cos(lam) ** 2)]
    assert_allclose(ga, expected, rtol=1e-13, atol=1e-15)
    alpha = float(E.plumb_line_deviation(g0))
    assert_allclose(math.tan(alpha), c2 * math.sin(lam) * math.cos(lam)
                    / (g0 - c2 * math.cos(lam) ** 2), rtol=1e-12, atol=1e-18)
    if latitude_deg == 0.0:
        assert_allclose(np.linalg.norm(ga), g0 - c2, rtol=1e-14)
    if latitude_deg == 90.0:
        assert_allclose(np.linalg.norm(ga), g0, rtol=1e-14)
    if latitude_deg == 45.0:
        assert round(math.degrees(alpha), 3) == 0.099


def test_eastward_deflection_of_a_falling_body():
    """A body dropped from rest at height h at latitude lambda (ch. 19): to first order in
    Omega it lands east of the plumb line by d = (1/3) Omega g t^3 cos(lambda), t =
    sqrt(2 h / g). The equations of relative motion are written in the local frame with the
    inertial torsors of entrainment and of Coriolis, the attraction being the constant field
    that makes the apparent gravity at O exactly -g u; integrated by DOP853 (rtol 1e-12).
    The neglected terms are of relative order Omega t (about 3e-4 here): rtol 2e-3."""
    lam, g, h = math.radians(45.0), 9.81, 100.0
    E = earth_reference(latitude=lam)
    x, y, z = rm.coordinates("x y z")
    body = rm.Body("ball", frame=E.frame.translated("Rm", E.frame.point("M", x, y, z)),
                   mass=1)
    kw = {"relative_to": E.frame, "absolute": E.geocentric}
    attraction = -g * E.up + E.entrainment_acceleration()
    force = (attraction + entrainment_inertial_torsor(body, **kw).resultant
             + coriolis_inertial_torsor(body, **kw).resultant)
    acc = [sp.N(c) for c in force.components(E.frame)]  # relative acceleration, m = 1
    q = (x, y, z)
    qd = tuple(c.diff(t) for c in q)
    X = sp.symbols("X0:6")
    rule = dict(zip(qd + q, X[3:] + X[:3], strict=True))
    f = sp.lambdify(X, [a.xreplace(rule) for a in acc], "math")

    def rhs(_, s):
        return [s[3], s[4], s[5], *f(*s)]

    fall = math.sqrt(2 * h / g)
    ground = lambda _, s: s[2]  # noqa: E731
    ground.terminal, ground.direction = True, -1
    sol = solve_ivp(rhs, (0, 2 * fall), [0, 0, h, 0, 0, 0], method="DOP853", rtol=1e-12,
                    atol=1e-14, events=ground)
    t_hit, east = sol.t_events[0][0], sol.y_events[0][0][0]
    assert_allclose(t_hit, fall, rtol=1e-6)
    assert_allclose(east, EARTH_ROTATION_RATE * g * fall**3 * math.cos(lam) / 3, rtol=2e-3)
    assert east > 0


def test_latitude_out_of_range():
    with pytest.raises(ArgumentError, match="`latitude` must be in radians within"):
        earth_reference(latitude=2.0)
    with pytest.raises(ArgumentError, match="`latitude` must be in radians within"):
        earth_reference(latitude=-math.pi)
    with pytest.raises(ArgumentError, match="`radius` must be > 0"):
        earth_reference(latitude=0.5, radius=-1)


def test_pendulum_in_an_accelerating_wagon():
    """A rod pendulum (mass m, length L, pivot O1 at one end, axis j1) in a wagon R1 moving
    with the constant acceleration A i0 relative to R0 (ch. 19.1.1): in R1 the moment about
    the pivot axis of {D(S/R1)} equals that of the weight and of the inertial actions
    (entrainment -m A i0; Coriolis zero for a translating R1). Relative equilibrium:
    tan(theta_e) = A / g; small oscillations about it at w^2 = 3 sqrt(g^2 + A^2) / (2 L)."""
    th = rm.coordinates("theta")
    m, L, g, A = sp.symbols("m L g A", positive=True)
    R0 = rm.Frame("R0")  # k0 upwards
    R1 = R0.translated("R1", R0.point("W", A * t**2 / 2, 0, 0))
    R2 = R1.rotated("R2", about=R1.j, angle=th)
    G = R1.origin.moved("G", -L / 2 * R2.k)
    rod = rm.Body("rod", frame=R2, mass=m, centre=G,
                  inertia=rm.inertia.rod(m, L, axis=R2.k, centre=G))
    O1 = R1.origin
    kw = {"relative_to": R1, "absolute": R0}
    Fe = entrainment_inertial_torsor(rod, **kw)
    Fc = coriolis_inertial_torsor(rod, **kw)
    assert Fe.resultant.equals(-m * A * R0.i) and Fc.resultant.is_zero
    actions = rm.slider(-m * g * R0.k, G) + Fe + Fc
    eq = (rod.dynamic_torsor(R1).moment_at(O1) - actions.moment_at(O1)).dot(R1.j)
    thdd = sp.solve(eq, th.diff(t, 2))[0]
    x = sp.Symbol("x")
    f = sp.simplify(thdd.subs(th.diff(t), 0).subs(th, x))
    th_e = sp.atan(A / g)
    assert sp.simplify(f.subs(x, th_e)) == 0
    w2 = sp.simplify(-sp.diff(f, x).subs(x, th_e))
    assert sp.simplify(w2 - 3 * sp.sqrt(g**2 + A**2) / (2 * L)) == 0


def test_foucault_pendulum_precession_rate():
    """A pendulum of small amplitude (natural rate w0) at latitude lambda: the horizontal
    equations of relative motion, x'' = -w0^2 x + (Coriolis)_x, y'' = -w0^2 y +
    (Coriolis)_y, with the Coriolis inertial force of rigidmech (the centrifugal part is in
    the apparent gravity), integrated by DOP853 (rtol 1e-12): the plane of oscillation turns
    clockwise at Omega sin(lambda) (ch. 19). An exaggerated Omega = 0.02 rad/s makes the
    turn visible in 40 s; the rate is exact for this linear model (z = x + i y =
    exp(-i Omega sin(lambda) t) w with w oscillating in a fixed plane): rtol 1e-6."""
    lam, W, w0 = math.radians(48.85), 0.02, 3.0
    E = earth_reference(latitude=lam, rate=W)
    x, y = rm.coordinates("x y")
    bob = rm.Body("bob", frame=E.frame.translated("Rb", E.frame.point("B", x, y, 0)), mass=1)
    Fc = coriolis_inertial_torsor(bob, relative_to=E.frame, absolute=E.geocentric).resultant
    cx, cy, _ = (sp.N(c) for c in Fc.components(E.frame))
    X = sp.symbols("X0:4")
    rule = {x.diff(t): X[2], y.diff(t): X[3], x: X[0], y: X[1]}
    fx = sp.lambdify(X, cx.xreplace(rule), "math")
    fy = sp.lambdify(X, cy.xreplace(rule), "math")

    def rhs(_, s):
        return [s[2], s[3], -w0**2 * s[0] + fx(*s), -w0**2 * s[1] + fy(*s)]

    turning = lambda _, s: s[0] * s[2] + s[1] * s[3]  # noqa: E731  d|z|^2/dt = 0
    turning.direction = -1  # maxima of |z|
    sol = solve_ivp(rhs, (0, 40), [1.0, 0, 0, 0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=turning)
    t_max = sol.t_events[0]
    angles = np.unwrap(2 * np.arctan2(sol.y_events[0][:, 1], sol.y_events[0][:, 0])) / 2
    rate = np.polyfit(t_max, angles, 1)[0]
    assert_allclose(rate, -W * math.sin(lam), rtol=1e-6)
