"""Book ch. 22: motion of rotation of a solid about a fixed axis, and the actions on its
bearings (unbalanced rotor, ch. 22.3), derived by rigidmech without hand work.

Conventions (book, ch. 15 and 22): the solid S turns about the fixed axis (O, k0) by the angle
q; its frame R1 = (O; i1, j1, k1 = k0) is attached to it; the operator of inertia at O in R1 is
[[A, -F, -E], [-F, B, -D], [-E, -D, C]]; the mass centre G has coordinates (a, b, c) in R1.
No gravity: the pivot alone acts on S.

Closed forms (ch. 22.1.6, 22.3.1), from {D(S/R0)} = {A(pivot -> S)} at O, in R1:
  resultant  R = m a(G) = m (w' k0 ^ OG + w k0 ^ (w k0 ^ OG)),
  moment     M(O) = delta(O) = J_O(w' k0) + w k0 ^ J_O(w k0)
             = (-E w' + D w^2) i1 + (-D w' - E w^2) j1 + C w' k1,
with w = q'. The equation of motion is C q'' = 0 (the perfect pivot transmits no moment
about k0), so along the motion the bearing moment is (D w^2) i1 - (E w^2) j1: a rotor is
balanced dynamically when D = E = 0 and statically when a = b = 0 (ch. 22.3.3).
"""

import pytest
import sympy as sp

import rigidmech as rm


@pytest.fixture(scope="module")
def rotor():
    q = rm.coordinates("q")
    m, a, b, c = rm.constants("m a b c", real=True)
    A, B, C, D, E, F = rm.constants("A B C D E F", real=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    O = R0.origin
    G = O.moved("G", a * R1.i + b * R1.j + c * R1.k)
    J_O = rm.InertiaOperator.from_products(A, B, C, D, E, F, frame=R1, at=O)
    body = rm.Body("rotor", frame=R1, mass=m, centre=G, inertia=J_O)
    system = rm.System(galilean=R0)
    system.connect(R0, body, rm.joints.Pivot(at=O, axis=R0.k))
    return system, q, (m, a, b, c, A, B, C, D, E, F), R1, O, G, body


def test_ch22_equation_of_motion_is_C_q_ddot_equals_zero(rotor):
    system, q, (m, a, b, c, A, B, C, D, E, F), *_ = rotor
    eqs = system.equations_of_motion()
    assert sp.simplify(eqs.mass_matrix[0, 0] - C) == 0
    assert sp.simplify(eqs.forcing[0]) == 0


@pytest.mark.parametrize("part", ["resultant", "moment"])
def test_ch22_3_bearing_actions_of_an_unbalanced_rotor(rotor, part):
    system, q, (m, a, b, c, A, B, C, D, E, F), R1, O, G, body = rotor
    T = system.connection_action(system.galilean, body)
    w, wd = sp.symbols("w wd", real=True)
    at_speed = {q.diff(rm.t, 2): wd, q.diff(rm.t): w}
    k0 = system.galilean.k
    if part == "resultant":
        OG = G - O
        expected = m * ((wd * k0).cross(OG) + (w * k0).cross((w * k0).cross(OG)))
        got = T.resultant
    else:
        expected = (-E * wd + D * w**2) * R1.i + (-D * wd - E * w**2) * R1.j + C * wd * R1.k
        got = T.moment_at(O)
    diff = (got - expected).components(R1).xreplace(at_speed)
    assert sp.simplify(diff) == sp.zeros(3, 1)


def test_ch22_3_balanced_rotor_loads_its_bearing_with_nothing(rotor):
    """a = b = 0 (static balance) and D = E = 0 (dynamic balance): at constant speed the
    pivot transmits only the zero torsor (no gravity here)."""
    system, q, (m, a, b, c, A, B, C, D, E, F), R1, O, G, body = rotor
    q_sym, u_sym, a_sym, rule = system.symbols()
    comps = {k: v.xreplace(rule)
             for k, v in system.connection_components(system.galilean, body).items()}
    balanced = {a: 0, b: 0, D: 0, E: 0, a_sym[0]: 0}
    for name, value in comps.items():
        assert sp.simplify(value.xreplace(balanced)) == 0, name
