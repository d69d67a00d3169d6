"""Inertial action torsors of entrainment and Coriolis (ch. 17.2-17.3), checked by the
composition of dynamic torsors {D(S/R0)} = {D(S/R1)} + {D_e} + {D_c}, each side computed
independently (Body.dynamic_torsor differentiates the angular momentum in each frame)."""

import random

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, ArgumentTypeError, FrameError
from rigidmech.kinetics import (
    InertialActions,
    coriolis_dynamic_torsor,
    coriolis_inertial_torsor,
    entrainment_dynamic_torsor,
    entrainment_inertial_torsor,
)

Q = rm.coordinates("q1 q2 q3 q4 q5 q6 q7")


def _numeric(vec, frame, rule):
    return [float(sp.N(c.subs(rm.t, 0.3))) for c in vec.components(frame).xreplace(rule)]


@pytest.mark.parametrize("seed", range(4))
def test_dynamic_torsors_compose(seed):
    """A general body (full operator of inertia with products, Euler angles, moving centre)
    on a frame R1 that translates and rotates about two axes: the composition holds at random
    values of q, q', q'' (to 1e-11 relative)."""
    rnd = random.Random(seed)
    q1, q2, q3, psi, theta, phi, x = Q
    R0 = rm.Frame("R0")
    Ra = R0.rotated("Ra", about=R0.k, angle=q1, origin=R0.point("O1", q3, 1, 0))
    R1 = Ra.rotated("R1", about=Ra.i, angle=q2)
    RS = R1.euler("RS", psi, theta, phi, origin=R1.point("C", x, 0.5, 0))
    G = RS.origin.moved("G", 0.3 * RS.i - 0.2 * RS.k)
    J = rm.InertiaOperator.from_products(3, 4, 5, 0.2, -0.3, 0.1, frame=RS)
    body = rm.Body("S", frame=RS, mass=2, centre=G, inertia=J)
    total = body.dynamic_torsor(R0)
    parts = (body.dynamic_torsor(R1)
             + entrainment_dynamic_torsor(body, relative_to=R1, absolute=R0)
             + coriolis_dynamic_torsor(body, relative_to=R1, absolute=R0))
    rule = {}
    for q in Q:
        rule[q.diff(rm.t, 2)] = rnd.uniform(-2, 2)
        rule[q.diff(rm.t)] = rnd.uniform(-2, 2)
        rule[q] = rnd.uniform(-2, 2)
    for got, expected in ((parts.resultant, total.resultant),
                          (parts.moment_at(G), total.moment_at(G)),
                          (parts.moment_at(R0.origin), total.moment_at(R0.origin))):
        g, e = _numeric(got, R0, rule), _numeric(expected, R0, rule)
        for a, b in zip(g, e, strict=True):
            assert abs(a - b) <= 1e-11 * max(1.0, abs(b))


def test_gyroscope_on_a_turntable_closed_form():
    """Wheel (axial moment C, transverse A) spinning at phi' about i1, centre at distance d on a
    turntable turning at theta' about k0 (ch. 17.3): entrainment resultant m d (-theta'^2 i1 +
    theta'' j1), moment at G  J(theta'' k) + theta' k ^ J(theta' k) = A theta'' k (J(k) = A k
    since k is a transverse axis for every spin angle); Coriolis resultant 0 (G fixed in R1),
    moment C phi' theta' j1 (the gyroscopic couple)."""
    th, ph = Q[:2]
    m, A, C, d = sp.symbols("m A C d", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    RS = R1.rotated("RS", about=R1.i, angle=ph, origin=R1.point("G", d, 0, 0))
    J = rm.InertiaOperator.from_products(C, A, A, frame=RS)
    wheel = rm.Body("wheel", frame=RS, mass=m, inertia=J)
    kw = {"relative_to": R1, "absolute": R0}
    De = entrainment_dynamic_torsor(wheel, **kw)
    assert De.resultant.equals(m * d * (-th.diff() ** 2 * R1.i + th.diff(rm.t, 2) * R1.j))
    assert De.moment.equals(A * th.diff(rm.t, 2) * R1.k)
    Dc = coriolis_dynamic_torsor(wheel, **kw)
    assert Dc.resultant.is_zero
    assert Dc.moment.equals(C * ph.diff() * th.diff() * R1.j)
    assert entrainment_inertial_torsor(wheel, **kw) == -De
    assert coriolis_inertial_torsor(wheel, **kw) == -Dc
    # reduced elsewhere: transport
    O = R0.origin
    assert entrainment_dynamic_torsor(wheel, at=O, **kw).moment.equals(De.moment_at(O))


def test_inertial_actions_action():
    th = Q[0]
    m, d = sp.symbols("m d", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    b = rm.Body("b", frame=R1, mass=m, centre=R1.point("G", d, 0, 0))
    massless = rm.Body("s", frame=R1)
    act = InertialActions(reference=R1, galilean=R0)
    (body, F), = act.contributions([b, massless])
    assert body is b
    kw = {"relative_to": R1, "absolute": R0}
    assert F.equals(entrainment_inertial_torsor(b, **kw) + coriolis_inertial_torsor(b, **kw))
    assert act.potential_energy([b], R1) is None
    assert act.reference is R1 and act.galilean is R0 and "InertialActions" in repr(act)


def test_bad_input():
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=Q[0])
    with pytest.raises(ArgumentError, match="`body` s has no mass"):
        entrainment_dynamic_torsor(rm.Body("s", frame=R1), relative_to=R1, absolute=R0)
    with pytest.raises(ArgumentTypeError, match="`body` must be a Body"):
        coriolis_dynamic_torsor(R1, relative_to=R1, absolute=R0)
    with pytest.raises(FrameError, match="same frame tree"):
        coriolis_dynamic_torsor(rm.Body("b", frame=R1, mass=1), relative_to=R1,
                                absolute=rm.Frame("X"))
    with pytest.raises(ArgumentTypeError, match="`galilean` must be a Frame"):
        InertialActions(reference=R1, galilean="R0")
    with pytest.raises(ArgumentTypeError, match="`at` must be a Point"):
        coriolis_dynamic_torsor(rm.Body("b", frame=R1, mass=1), relative_to=R1, absolute=R0,
                                at=R0.i)


# one reference and state by default, two more in the slow stage (a derivation of 2 s each)
@pytest.mark.parametrize("seed", [0, *(pytest.param(k, marks=pytest.mark.slow) for k in (1, 2))])
def test_inertial_potential_energy_derives_the_power(seed):
    """In a steady motion of the reference (constant rotation vector, origin with a constant
    acceleration in its basis), the power of the inertial actions in the motion relative to
    R1 is -dE_p/dt: checked at random states for a body with a full operator of inertia."""
    rng = random.Random(seed)
    psi, theta, phi, x, y, z = Q[:6]
    W, lam, d = (sp.Rational(rng.randint(1, 9), 7) for _ in range(3))
    R0 = rm.Frame("R0")
    # an Earth-like reference: turning about an inclined axis, its origin off the axis
    R1 = R0.rotated("R1", about=sp.cos(lam) * R0.j + sp.sin(lam) * R0.k, angle=W * rm.t,
                    origin=R0.point("O1", d, 0, 0))
    G = R1.point("G", x, y, z)
    RS = R1.euler("RS", psi, theta, phi, origin=G)
    J = rm.InertiaOperator.from_products(3, 4, 5, sp.Rational(1, 3), sp.Rational(1, 5),
                                         sp.Rational(-1, 4), frame=RS, at=G)
    body = rm.Body("b", frame=RS, mass=2, centre=G, inertia=J)
    act = InertialActions(reference=R1, galilean=R0)
    V = act.potential_energy([body], R1)
    plain = V.xreplace({q: sp.Symbol(f"s{i}") for i, q in enumerate(Q[:6])})
    assert not plain.has(rm.t)                      # a function of the position only
    (_, F), = act.contributions([body])
    power = F.resultant.dot(G.velocity(R1)) + F.moment_at(G).dot(RS.rotation_vector(R1))
    rule = {}
    for q in Q[:6]:
        rule[q.diff(rm.t)] = rng.uniform(-1, 1)
    for q in Q[:6]:
        rule[q] = rng.uniform(-1, 1)
    value = float(sp.N((power + V.diff(rm.t)).subs(rule).subs(rm.t, 0.3)))
    scale = float(sp.N(power.subs(rule).subs(rm.t, 0.3)))
    assert abs(scale) > 1e-3 and abs(value) < 1e-10 * abs(scale)


def test_inertial_potential_energy_none_or_refused():
    x = rm.coordinates("x")
    a = sp.Symbol("a", positive=True)
    R0 = rm.Frame("R0")
    jerk = R0.translated("R1", R0.point("W", a * rm.t**3, 0, 0))   # a(O) grows with t
    body = rm.Body("b", frame=jerk.translated("Rb", jerk.point("B", x, 0, 0)), mass=1)
    act = InertialActions(reference=jerk, galilean=R0)
    assert act.potential_energy([body], jerk) is None
    with pytest.raises(FrameError, match="relative to their reference R1; got `frame` R0"):
        act.potential_energy([body], R0)
