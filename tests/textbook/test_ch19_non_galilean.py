"""Ch. 19 (dynamics in a non-Galilean reference) and ch. 24: relative equilibria and apparent
weight found from a System written in the moving reference.

Conventions: the reference R moves relative to the Galilean R0 with a prescribed motion;
``System(galilean=R0, reference=R)`` adds the inertial actions of entrainment and Coriolis. A
relative equilibrium is a position where the body can stay at rest in R: f(q*, 0) = 0
(:func:`rigidmech.vibrations.equilibria`).
"""

import math

import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import acceleration_composition
from rigidmech.kinetics import EARTH_RADIUS, EARTH_ROTATION_RATE, earth_reference
from rigidmech.vibrations import equilibria, linearize

t = rm.t


def _at_rest(expr, values):
    """expr with q'' = q' = 0 and q = the given values."""
    rule = {}
    for q in values:
        rule[q.diff(t, 2)] = 0
        rule[q.diff(t)] = 0
    expr = expr.subs(rule)
    return expr.subs(values)


def _wagon_pendulum():
    """A bob of mass m at the end of a massless rod of length L hung at the point O of a
    wagon whose acceleration a along i0 is constant; gravity -g j0; theta about k from the
    vertical (theta > 0 towards +i0)."""
    th = rm.coordinates("theta")
    m, L, g, a = rm.constants("m L g a", positive=True)
    R0 = rm.Frame("R0")
    Rw = R0.translated("Rw", R0.point("W", a * t**2 / 2, 0, 0))
    Rp = Rw.rotated("Rp", about=Rw.k, angle=th)
    bob = rm.Body("bob", frame=Rp, mass=m, centre=Rw.origin.moved("G", -L * Rp.j))
    s = rm.System(galilean=R0, reference=Rw)
    s.connect(Rw, bob, rm.joints.Pivot(at=Rw.origin, axis=Rw.k))
    s.act(rm.gravity(-g * R0.j))
    return s, bob, th, (m, L, g, a)


def test_ch19_pendulum_in_accelerating_wagon_relative_equilibrium_and_period():
    """The bob at rest in the wagon leans backwards: tan(theta*) = -a/g; it oscillates about
    that position with the period 2 pi sqrt(L / sqrt(g^2 + a^2)); the rod pulls with
    m sqrt(g^2 + a^2) (the apparent weight in the wagon)."""
    s, bob, th, (m, L, g, a) = _wagon_pendulum()
    eqs = s.equations_of_motion()
    values = {"m": 2.0, "L": 1.5, "g": 9.81, "a": 3.0}
    found = equilibria(eqs, within=(-1.5, 1.5), **values)
    assert len(found) == 1
    theta_star = found[0]["theta"]
    assert math.isclose(theta_star, -math.atan(3.0 / 9.81), rel_tol=1e-10)
    # symbolic: f(-atan(a/g), 0) = 0
    f0 = _at_rest(eqs.forcing[0], {th: -sp.atan(a / g)})
    assert sp.simplify(f0) == 0
    lin = linearize(eqs, about={th: theta_star}, parameters=values)
    omega2 = float(lin.K[0] / lin.M[0])
    assert math.isclose(omega2, math.hypot(9.81, 3.0) / 1.5, rel_tol=1e-10)
    N = _at_rest(s.connection_action(s.reference, bob).resultant.magnitude(),
                 {th: -sp.atan(a / g)})
    assert sp.simplify(N - m * sp.sqrt(g**2 + a**2)) == 0


def test_ch19_bead_on_rotating_hoop_relative_equilibria():
    """A bead on a circular hoop of radius R turning at the rate Omega about its vertical
    diameter: m R^2 theta'' = m R sin(theta) (R Omega^2 cos(theta) - g); besides the bottom
    and the top, the bead rests at cos(theta*) = g / (R Omega^2) when R Omega^2 > g."""
    th = rm.coordinates("theta")
    m, R, g, W = rm.constants("m R g Omega", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=W * t)
    B = R1.point("B", R * sp.sin(th), 0, -R * sp.cos(th))
    s = rm.System(galilean=R0, reference=R1)
    s.add(rm.Body("bead", frame=R1.translated("Rb", B), mass=m, centre=B))
    s.act(rm.gravity(-g * R0.k))
    eqs = s.equations_of_motion()
    expected = m * R * sp.sin(th) * (R * W**2 * sp.cos(th) - g)
    assert sp.simplify(eqs.forcing[0] - expected) == 0
    assert sp.simplify(eqs.mass_matrix[0] - m * R**2) == 0
    roots = [e["theta"] for e in equilibria(eqs)]
    assert sp.acos(g / (W**2 * R)) in roots
    found = equilibria(eqs, within=(0.01, 3.0), m=1.0, R=0.5, g=9.81, Omega=6.0)
    assert any(math.isclose(e["theta"], math.acos(9.81 / (0.5 * 36.0)), rel_tol=1e-10)
               for e in found)
    # the inertial potential -m Omega^2 (R sin theta)^2 / 2 makes the energy
    # T + V relative to the hoop conserved
    E = eqs.energy
    assert sp.simplify(E - (m * R**2 * th.diff(t)**2 / 2 - m * g * R * sp.cos(th)
                            - m * W**2 * R**2 * sp.sin(th)**2 / 2)) == 0


def test_ch19_apparent_weight_and_plumb_line_on_the_earth():
    """A plumb line (bob of mass m on a rod of length L hung at O) at rest on the Earth at
    the latitude 45 deg: it settles along the apparent gravity g_a, deviated from the
    direction of the centre by alpha, tan(alpha) = Omega^2 R sin(l) cos(l) /
    (g0 - Omega^2 R cos^2(l)), towards the equator; the hook carries -m g_a (ch. 12.2.1, 19)."""
    alpha, beta = rm.coordinates("alpha beta")
    m, L, g0, lam, W, RT = rm.constants("m L g0 lambda Omega R_T", positive=True)
    E = earth_reference(latitude=lam, rate=W, radius=RT)
    R = E.frame
    Rb = R.rotated("Ra", about=R.i, angle=alpha)
    Rc = Rb.rotated("Rc", about=Rb.j, angle=beta)
    P = R.origin.moved("P", -L * Rc.k)
    bob = rm.Body("bob", frame=Rc, mass=m, centre=P)
    s = rm.System(reference=E)
    s.connect(R, bob, rm.joints.Spherical(at=R.origin))
    s.act(rm.actions.Force(on=bob, vector=-m * g0 * E.up, at=P))
    eqs = s.equations_of_motion()
    values = {"m": 2.0, "L": 1.0, "g0": 9.82, "lambda": math.pi / 4,
              "Omega": EARTH_ROTATION_RATE, "R_T": EARTH_RADIUS}
    found = equilibria(eqs, within=[(-0.1, 0.1), (-0.1, 0.1)], **values)
    assert len(found) == 1
    rest = {alpha: found[0]["alpha"], beta: found[0]["beta"]}
    numbers = {sp.Symbol(k, positive=True): v for k, v in values.items()}
    # the line O -> P and the apparent gravity are parallel
    OP = np.array(_at_rest((P - R.origin).components(R), rest).subs(numbers), dtype=float)
    ga = np.array(E.apparent_gravity(g0).components(R).subs(numbers), dtype=float).ravel()
    OP = OP.ravel()
    # The closed forms give g_a at O; the bob is at P, L below, where the entrainment
    # acceleration differs by about Omega^2 L = 5e-9 m/s^2: agreement to ~1e-9 relative.
    assert np.allclose(OP / np.linalg.norm(OP), ga / np.linalg.norm(ga), rtol=0, atol=1e-9)
    deviation = math.acos(-OP[2] / np.linalg.norm(OP))
    expected = float(E.plumb_line_deviation(g0).subs(numbers))
    assert math.isclose(deviation, expected, rel_tol=1e-6)
    assert OP[1] < 0                          # towards the equator (south) in the north
    # the action of the hook on the bob: -m g_a(P) exactly, with g_a(P) = -g0 u - a_e(P)
    N = _at_rest(s.connection_action(R, bob).resultant.components(R), rest).subs(numbers)
    N = np.array(N, dtype=float).ravel()
    a_e = acceleration_composition(P, relative_to=R, absolute=E.geocentric).entrainment
    ga_P = -g0 * E.up - a_e
    ga_P = np.array(_at_rest(ga_P.components(R), rest).subs(numbers), dtype=float).ravel()
    assert np.allclose(N, -2.0 * ga_P, rtol=1e-12, atol=1e-14)
    assert math.isclose(np.linalg.norm(N), 2.0 * np.linalg.norm(ga), rel_tol=1e-9)  # m g_a


def test_ch19_foucault_pendulum_in_the_earth_reference():
    """The Foucault pendulum written in the Earth's reference (System(reference=E)): the swing
    plane turns at -Omega sin(lambda) relative to the ground (first order in Omega; the
    tolerance 1e-2 covers the centrifugal terms and Airy's precession with the exaggerated
    Omega = 0.05 rad/s, see the scene's test). The local vertical, gravity and the ground are
    fixed in E and the Earth turns at a constant rate: T + V relative to the Earth, with the
    potential of the inertial actions, is conserved."""
    alpha, beta = rm.coordinates("alpha beta")
    lat, W = math.pi / 4, 0.05
    E = earth_reference(latitude=lat, rate=W, radius=1.0)
    R = E.frame
    Ra = R.rotated("Ra", about=R.i, angle=alpha)
    Rb = Ra.rotated("Rb", about=Ra.j, angle=beta)
    bob = rm.Body("bob", frame=Rb, mass=1.0, centre=R.origin.moved("P", -1.0 * Rb.k))
    s = rm.System(reference=E)
    s.connect(R, bob, rm.joints.Spherical(at=R.origin))
    s.act(rm.gravity(-9.81 * E.up))
    sim = s.equations_of_motion().simulate(t=(0.0, 40.0), q0=[0.05, 0.0], rtol=1e-10,
                                           atol=1e-12, n_output=8001)
    a, b = sim.q
    X, Y = -np.sin(b), np.sin(a) * np.cos(b)         # east, north
    r2 = X**2 + Y**2
    i = np.where((r2[1:-1] > r2[:-2]) & (r2[1:-1] >= r2[2:]))[0] + 1
    rate = np.polyfit(sim.t[i], np.unwrap(2 * np.arctan2(Y[i], X[i])) / 2, 1)[0]
    assert math.isclose(rate, -W * math.sin(lat), rel_tol=1e-2)
    assert sim.time_dependence() is None and sim.energy_drift() < 1e-9
