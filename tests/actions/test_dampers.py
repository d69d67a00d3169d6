"""Dampers and torsion springs (ch. 11, 21, 22): the System includes them; Lagrange's
equations with Rayleigh's dissipation function give the same equations as the fundamental
principle with the damper actions."""

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import models
from rigidmech._core.errors import ArgumentError
from rigidmech.actions import Damper, TorsionalDamper, TorsionSpring, wire_torsional_stiffness
from rigidmech.vibrations import linearize


def cart_pendulum_with_dampers():
    """A cart (x) with a pendulum (theta); an oblique damper from a fixed point to the bob,
    a torsional damper and a torsion spring at the pivot, a spring to the wall."""
    model = models.cart_pendulum()
    s, (x, th) = model.system, model.coordinates
    c1, c2, k, kt = rm.constants("c1 c2 k k_t", positive=True)
    R0, Rc, _ = model.frames
    cart, bob = model.bodies
    P = model.point("P")
    s.act(rm.Spring(k, 0, a=R0.origin, b=Rc.origin, on_b=cart))
    dampers = [Damper(c1, a=R0.point("A", -2, -3, 0), b=P, on_b=bob),
               TorsionalDamper(c2, axis=R0.k, on=bob, reaction_on=cart)]
    for d in dampers:
        s.act(d)
    s.act(TorsionSpring(kt, th, axis=R0.k, on=bob, reaction_on=cart))
    return s, dampers, (x, th)


def test_lagrange_with_dissipation_equals_the_fundamental_principle():
    s, dampers, qs = cart_pendulum_with_dampers()
    eqs = s.equations_of_motion()
    q_sym, u_sym, a_sym, rule = s.symbols()
    T = s.kinetic_energy()
    V = sum(a.potential_energy(list(s.bodies), s.galilean) for a in s.actions)
    D = sum(d.dissipation_function() for d in dampers)
    t = rm.t
    lhs = [sp.diff(sp.diff(T, q.diff(t)), t) - sp.diff(T, q) + sp.diff(V, q)
           + sp.diff(D, q.diff(t)) for q in qs]
    lhs = [e.xreplace(rule) for e in sp.Matrix(lhs).xreplace(
        {q.diff(t, 2): a for q, a in zip(qs, a_sym, strict=True)})]
    acc = sp.Matrix(a_sym)
    fp = (eqs.mass_matrix * acc - eqs.forcing).xreplace(rule)  # results are in q(t)
    rng = np.random.default_rng(0)
    for _ in range(3):
        point = {p: rng.uniform(0.5, 2) for p in eqs.parameters}
        point |= {v: rng.uniform(-1, 1) for v in (*q_sym, *u_sym, *a_sym)}
        got = [float(e.xreplace(point)) for e in fp]
        want = [float(e.xreplace(point)) for e in lhs]
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12)


def test_damper_power_is_minus_twice_the_dissipation_function():
    s, dampers, qs = cart_pendulum_with_dampers()
    R0 = s.galilean
    for d in dampers:
        power = sp.S.Zero
        for solid, torsor in d.contributions(s.bodies):
            V = solid.kinematic_torsor(relative_to=R0, at=torsor.point)
            power += rm.power(torsor, V)
        assert sp.simplify(power + 2 * d.dissipation_function()) == 0


def test_dampers_store_no_energy_and_the_energy_decreases():
    s, dampers, qs = cart_pendulum_with_dampers()
    eqs = s.equations_of_motion()
    assert eqs.energy is not None
    sim = eqs.simulate(t=(0, 3), q0=[0.2, 0.5], rtol=1e-10, atol=1e-12, M=2.0, m=1.0, L=1.0,
                       g=9.81, c1=0.3, c2=0.2, k=5.0, k_t=1.0)
    e = sim.energy()
    assert np.all(np.diff(e) <= 1e-9) and e[-1] < 0.9 * e[0]


def test_torsion_pendulum_from_a_wire():
    """A disk on a wire of shear modulus G, diameter d, length L: omega^2 = k / J with
    k = G pi d^4 / (32 L) (ch. 22.2.2)."""
    q = rm.coordinates("q")
    m, R, G, d, L = rm.constants("m R G d L", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    disk = rm.Body("disk", frame=R1, mass=m, inertia=rm.inertia.disk(m, R, axis=R1.k))
    s = rm.System(galilean=R0)
    s.connect(R0, disk, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    k = wire_torsional_stiffness(G, d, L)
    s.act(TorsionSpring(k, q, axis=R0.k, on=disk))
    w = linearize(s.equations_of_motion()).modes().frequencies[0]
    assert sp.simplify(w**2 - (G * sp.pi * d**4 / (32 * L)) / (m * R**2 / 2)) == 0


@pytest.mark.parametrize("make, match", [
    (lambda R0, S: Damper(-2, a=R0.origin, b=R0.origin, on_b=S), "`damping` must be >= 0"),
    (lambda R0, S: TorsionalDamper(-0.1, axis=R0.k, on=S), "`damping` must be >= 0"),
    (lambda R0, S: TorsionSpring(-1, 0, axis=R0.k, on=S), "`stiffness` must be >= 0"),
    (lambda R0, S: Damper(1, a=R0.origin, b=R0.origin), "`on_a` and `on_b` cannot both"),
    (lambda R0, S: wire_torsional_stiffness(-1, 1, 1), "`shear_modulus` must be >= 0"),
    (lambda R0, S: wire_torsional_stiffness(1, 1, 0), "`length` must be > 0"),
])
def test_bad_coefficients_are_refused(make, match):
    R0 = rm.Frame("R0")
    S = rm.Body("S", frame=R0.rotated("R1", about=R0.k, angle=rm.coordinates("q")), mass=1)
    with pytest.raises(ArgumentError, match=match):
        make(R0, S)


def test_torsion_spring_refuses_an_angle_that_is_not_the_rotation():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    S = rm.Body("S", frame=R0.rotated("R1", about=R0.k, angle=q), mass=1)
    with pytest.raises(ArgumentError, match="`angle` must be the angle of S relative to R0"):
        TorsionSpring(1, q, axis=R0.i, on=S)


# -- ends that coincide at all times (found by the differential fuzzer) ----------------------
def _turning_body():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    return R0, R1, rm.Body("S", frame=R1, mass=1)


def _resultants(action, body):
    return [(s.name, T.resultant) for s, T in action.contributions([body])]


def test_a_spring_of_free_length_zero_between_coincident_ends_exerts_no_force():
    """-k AB with AB = 0: no direction is needed (k (l - 0) / l is k, not 0/0)."""
    R0, R1, body = _turning_body()
    spring = rm.Spring(2, 0, a=R0.origin, b=R1.point("B", 0, 0, 0), on_b=body)
    assert all(F.is_zero for _, F in _resultants(spring, body))
    assert spring.potential_energy([body], R0) == 0


def test_a_spring_of_nonzero_free_length_between_coincident_ends_is_refused():
    """k (l - l0) AB / l with l = 0 at all times has no direction: refused, naming the ends."""
    R0, R1, body = _turning_body()
    spring = rm.Spring(2, 1, a=R0.origin, b=R1.point("B", 0, 0, 0), on_b=body)
    with pytest.raises(ArgumentError, match=r"`a` \(O_R0\) and `b` \(B\) coincide at all times"):
        spring.contributions([body])


def test_a_damper_between_coincident_ends_exerts_no_force():
    """-c l' AB / l: the ends coincide at all times, v_B - v_A = 0, l' = 0: zero force and
    zero dissipation."""
    R0, R1, body = _turning_body()
    damper = Damper(3, a=R0.origin, b=R1.point("B", 0, 0, 0), on_b=body)
    assert all(F.is_zero for _, F in _resultants(damper, body))
    assert damper.length_rate() == 0 and damper.dissipation_function() == 0


def test_a_damper_whose_ends_meet_at_an_instant_stops_the_run_there():
    """-c l' AB / l has no direction where the ends meet while moving apart: the run stops
    saying where (t and state), not with a nan carried along."""
    x, y = rm.coordinates("x y")
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("P", x, y, 0))
    body = rm.Body("b", frame=R1, mass=1)
    s = rm.System(galilean=R0)
    s.add(body)
    s.act(Damper(1.0, a=R0.origin, b=R1.origin, on_b=body))
    sim = s.equations_of_motion().simulate((0.0, 1.0), q0=[0.0, 0.0], u0=[1.0, 0.5])
    assert sim.status == "failed"
    assert "not finite at t = 0.0; state y = [0.  0.  1.  0.5]" in sim.message
