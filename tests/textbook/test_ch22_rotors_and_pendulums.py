"""Book ch. 22 (rotation about a fixed axis): compound pendulum (equivalent length, centre of
percussion, reversibility), torsion pendulum, unbalanced rotor and its balancing by two
masses. The closed forms of rigidmech.vibrations.rotors are checked against systems built with
rm.System (equations of motion, connection actions).

Conventions as in test_ch22_rotation_fixed_axis.py: rotor frame R1 turning by q about (O, k0),
G = (a, b, c) in R1, products of inertia at O: D = int yz dm, E = int zx dm.
"""

import math

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.actions import TorsionSpring, wire_torsional_stiffness
from rigidmech.inertia import Part, composite
from rigidmech.vibrations import (
    balancing_masses,
    bearing_forces,
    centre_of_percussion,
    equivalent_length,
    kater_conjugate,
    linearize,
    rotor_bearing_action,
    torsion_pendulum_period,
)


def compound(d, k_G):
    """Uniform body of mass m, radius of gyration k_G about the axis through G, hung at d."""
    q = rm.coordinates("q")
    m, g = sp.symbols("m g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", d * R1.i)
    J = rm.InertiaOperator.from_products(m * k_G**2, m * k_G**2, m * k_G**2, frame=R1, at=G)
    body = rm.Body("body", frame=R1, mass=m, centre=G, inertia=J)
    s = rm.System(galilean=R0)
    s.connect(R0, body, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.gravity(g * R0.i))
    return s, body, R0, R1, (m, g)


@pytest.mark.parametrize("d, k_G, l_eq", [
    pytest.param(sp.Symbol("L", positive=True) / 2, sp.Symbol("L", positive=True) / sp.sqrt(12),
                 2 * sp.Symbol("L", positive=True) / 3, id="22.2.1-rod-hung-at-one-end-2L/3"),
    pytest.param(sp.Symbol("R", positive=True), sp.Symbol("R", positive=True) / sp.sqrt(2),
                 3 * sp.Symbol("R", positive=True) / 2, id="22.2.1-disk-hung-at-its-rim-3R/2"),
])
def test_ch22_2_1_compound_pendulum_equivalent_length(d, k_G, l_eq):
    """Small oscillations w^2 = g / l_eq with l_eq = d + k_G^2 / d (ch. 22.2.1)."""
    s, *_, (m, g) = compound(d, k_G)
    w = linearize(s.equations_of_motion()).modes().frequencies[0]
    assert sp.simplify(equivalent_length(d, k_G) - l_eq) == 0
    assert sp.simplify(w**2 - g / l_eq) == 0


def test_ch22_2_1_centre_of_percussion_leaves_no_transverse_reaction():
    """A force F normal to OG at distance p from O, body at rest at q = 0, no gravity: the
    transverse action of the pivot vanishes iff p = d + k_G^2/d (ch. 22.2.1)."""
    d, kG, F, p = sp.symbols("d k_G F p", positive=True)
    q = rm.coordinates("q")
    m = sp.Symbol("m", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", d * R1.i)
    body = rm.Body("body", frame=R1, mass=m, centre=G,
                   inertia=rm.InertiaOperator.from_products(m * kG**2, m * kG**2, m * kG**2,
                                                            frame=R1, at=G))
    s = rm.System(galilean=R0)
    s.connect(R0, body, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.Force(on=body, vector=F * R1.j, at=R0.origin.moved("I", p * R1.i)))
    eqs = s.equations_of_motion()
    q_s, u_s, a_s, _ = s.symbols()
    acc = sp.simplify(eqs.forcing[0] / eqs.mass_matrix[0])
    normal = s.connection_action(R0, body).resultant.dot(R1.j)  # transverse to OG
    Y = sp.simplify(normal.xreplace({q.diff(rm.t, 2): acc, q.diff(rm.t): 0}))
    assert sp.solve(sp.Eq(Y, 0), p) == [sp.simplify(centre_of_percussion(d, kG))]


def test_ch22_2_1_kater_reversible_pendulum():
    """A rod with a point mass (not symmetric): hung at O (d from G) or at the conjugate
    point d' = k_G^2/d beyond G, the periods are equal (ch. 22.2.1)."""
    R1 = rm.Frame("B")
    parts = composite([Part(2.0, rm.inertia.rod(2.0, 1.0, axis=R1.i)),
                       Part(0.7, centre=R1.point("E", 0.35, 0, 0))], frame=R1)
    mass = float(parts.mass)
    k_G = math.sqrt(float(parts.inertia.C) / mass)
    d = 0.3
    freqs = []
    for dist in (d, float(kater_conjugate(d, k_G))):
        s, *_ = compound(dist, k_G)
        freqs.append(linearize(s.equations_of_motion()).modes(m=mass, g=9.81).frequencies[0])
    assert freqs[0] == pytest.approx(freqs[1], rel=1e-13)
    assert freqs[0] == pytest.approx(math.sqrt(9.81 / equivalent_length(d, k_G)), rel=1e-13)


def test_ch22_2_2_torsion_pendulum_period():
    """A disk (m = 2 kg, R = 0.1 m) on a steel wire G = 80 GPa, d = 1 mm, L = 0.5 m:
    k = G pi d^4 / (32 L) = 0.015708 N m/rad, J = m R^2 / 2 = 0.01 kg m^2,
    T = 2 pi sqrt(J / k) = 5.0133 s (ch. 22.2.2)."""
    k = float(wire_torsional_stiffness(80e9, 1e-3, 0.5))
    assert k == pytest.approx(80e9 * math.pi * 1e-12 / 16, rel=1e-14)
    T = torsion_pendulum_period(0.01, k)
    assert T == pytest.approx(2 * math.pi * math.sqrt(0.01 / (5e-3 * math.pi)), rel=1e-14)
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    disk = rm.Body("disk", frame=R1, mass=2, inertia=rm.inertia.disk(2, sp.Rational(1, 10),
                                                                      axis=R1.k))
    s = rm.System(galilean=R0)
    s.connect(R0, disk, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(TorsionSpring(k, q, axis=R0.k, on=disk))
    w = linearize(s.equations_of_motion()).modes().frequencies[0]
    assert 2 * math.pi / float(w) == pytest.approx(T, rel=1e-12)


def rotor_system(m, centre, J_O):
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    O = R0.origin
    G = O.moved("G", sum((x * e for x, e in zip(centre, (R1.i, R1.j, R1.k), strict=True)),
                         rm.Vector.zero()))
    body = rm.Body("rotor", frame=R1, mass=m, centre=G, inertia=J_O(R1, O))
    s = rm.System(galilean=R0)
    s.connect(R0, body, rm.joints.Pivot(at=O, axis=R0.k))
    return s, body, R1, O, q


def test_ch22_3_1_bearing_action_closed_form_equals_the_connection_action():
    m, a, b, c, A, B, C, D, E, F = rm.constants("m a b c A B C D E F", real=True)
    s, body, R1, O, q = rotor_system(
        m, (a, b, c), lambda R1, O: rm.InertiaOperator.from_products(A, B, C, D, E, F,
                                                                     frame=R1, at=O))
    w, wd = sp.symbols("w wd", real=True)
    T = s.connection_action(s.galilean, body)
    at_speed = {q.diff(rm.t, 2): wd, q.diff(rm.t): w}
    R, M = rotor_bearing_action(m, (a, b, c), (D, E), w, wd, C=C)
    got_R = T.resultant.components(R1).xreplace(at_speed)
    got_M = T.moment_at(O).components(R1).xreplace(at_speed)
    assert sp.simplify(got_R - sp.Matrix(R)) == sp.zeros(3, 1)
    assert sp.simplify(got_M - sp.Matrix(M)) == sp.zeros(3, 1)


def test_ch22_3_2_two_bearings_share_the_action():
    """Bearings at z = -1 and z = 2: forces add up to R and their moments at O to M."""
    m, a, b, D, E, w = 3.0, 0.01, -0.02, 0.004, -0.006, 100.0
    (XA, YA), (XB, YB) = bearing_forces(m, (a, b, 0.5), (D, E), w, planes=(-1.0, 2.0))
    (X, Y, _), (Mx, My, _) = rotor_bearing_action(m, (a, b, 0.5), (D, E), w)
    assert XA + XB == pytest.approx(X) and YA + YB == pytest.approx(Y)
    # moment at O of forces at (0, 0, z): z k ^ (X, Y, 0) = (-z Y, z X, 0)
    assert -(-1.0 * YA + 2.0 * YB) == pytest.approx(Mx, rel=1e-12)
    assert -1.0 * XA + 2.0 * XB == pytest.approx(My, rel=1e-12)


@pytest.mark.parametrize("centre, products", [
    pytest.param((0.002, -0.001, 0.1), (0.0, 0.0), id="22.3.3-static-unbalance"),
    pytest.param((0.0, 0.0, 0.1), (3e-4, -2e-4), id="22.3.3-dynamic-unbalance"),
    pytest.param((0.001, 0.003, 0.2), (-1e-4, 5e-4), id="22.3.3-both"),
])
def test_ch22_3_3_balancing_by_two_masses_in_two_planes(centre, products):
    """After adding the two masses the rotor is balanced: at constant speed its pivot
    carries nothing (the System's connection action vanishes) (ch. 22.3.3)."""
    m, D, E = 5.0, *products
    added = balancing_masses(m, centre, (D, E), planes=(-0.2, 0.3), radius=0.05)
    R1 = rm.Frame("R1")
    O = R1.origin
    rotor_alone = rm.InertiaOperator.from_products(0.5, 0.5, 0.02, D, E, 0, frame=R1, at=O)
    G0 = R1.point("G0", *centre)
    J_G0 = rotor_alone.moved(G0, mass=m, centre=G0)
    parts = [Part(m, J_G0, centre=G0)] + [Part(mi, centre=R1.point(f"M{n}", *pos))
                                          for n, (mi, _, pos) in enumerate(added)]
    total = composite(parts, frame=R1)
    assert all(x == pytest.approx(0, abs=1e-15) for x in total.centre.coordinates(R1)[:2])
    J_O = total.inertia_at(O)
    assert float(J_O.D) == pytest.approx(0, abs=1e-15)
    assert float(J_O.E) == pytest.approx(0, abs=1e-15)
    for _, angle, (x, y, _) in added:
        assert math.hypot(x, y) == pytest.approx(0.05, rel=1e-14)
        assert math.atan2(y, x) == pytest.approx(angle, abs=1e-14)
    s, body, R1s, Os, q = rotor_system(
        float(total.mass), [float(x) for x in total.centre.coordinates(R1)],
        lambda R, P: rm.InertiaOperator.from_matrix(J_O.matrix, frame=R, at=P))
    comps = s.connection_components(s.galilean, body)
    q_s, u_s, a_s, rule = s.symbols()
    for value in comps.values():
        for angle in (0.0, 0.7, 2.1):  # results are in q(t): to the symbols, then values
            v = value.xreplace(rule).xreplace({a_s[0]: 0, u_s[0]: 300.0, q_s[0]: angle})
            assert abs(float(v)) < 1e-9
