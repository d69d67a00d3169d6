"""Energy balance of simulated motions (theorem of power and energy, ch. 18.3):
Simulation.energy_balance() = E(t) - E(0) - W(t) stays near 0 for a correct run; energy_drift
refuses an energy that depends on time explicitly."""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentError
from rigidmech.dynamics.energy import time_dependence

t = rm.t
TIGHT = {"rtol": 1e-11, "atol": 1e-12, "n_output": 4001}


def _oscillator(damped=True, driven=False):
    x = rm.coordinates("x")
    m, k, c, F0, w = rm.constants("m k c F0 w", positive=True)
    R0 = rm.Frame("R0")
    P = R0.point("P", x, 0, 0)
    s = rm.System(galilean=R0)
    b = rm.Body("b", frame=R0.translated("R1", P), mass=m, centre=P)
    s.add(b)
    # the spring from a point far on the left: its line of action stays along i
    A = R0.point("A", -10, 0, 0)
    s.act(rm.Spring(k, 10, a=A, b=P, on_b=b))
    if damped:
        s.act(rm.actions.Damper(c, a=A, b=P, on_b=b))
    if driven:
        s.act(rm.Force(on=b, vector=F0 * sp.cos(w * t) * R0.i, at=P))
    return s


def test_damped_oscillator_energy_balance_and_closed_form():
    """m x'' + c x' + k x = 0 from x = 1 at rest: E = (m x'^2 + k x^2)/2 follows the closed
    form of the underdamped motion, and E - E0 equals minus the work dissipated."""
    s = _oscillator()
    sim = s.equations_of_motion().simulate(t=(0, 6), q0=[1.0], m=1.0, k=4.0, c=0.4, **TIGHT)
    m, k, c = 1.0, 4.0, 0.4
    z, wn = c / (2 * math.sqrt(k * m)), math.sqrt(k / m)
    wd = wn * math.sqrt(1 - z * z)
    x = np.exp(-z * wn * sim.t) * (np.cos(wd * sim.t) + z * wn / wd * np.sin(wd * sim.t))
    v = -np.exp(-z * wn * sim.t) * (wn**2 / wd) * np.sin(wd * sim.t)
    assert np.allclose(sim.energy(), (m * v**2 + k * x**2) / 2, rtol=0, atol=1e-9)
    balance = sim.energy_balance()
    assert np.max(np.abs(balance)) < 1e-8 * 2.0        # E0 = k / 2 = 2
    assert sim.energy()[-1] < 0.2 * sim.energy()[0]    # the energy is not conserved


def test_energy_balance_reveals_a_loose_run():
    s = _oscillator()
    eqs = s.equations_of_motion()
    tight = eqs.simulate(t=(0, 6), q0=[1.0], m=1.0, k=4.0, c=0.4, **TIGHT)
    loose = eqs.simulate(t=(0, 6), q0=[1.0], m=1.0, k=4.0, c=0.4, rtol=1e-3, atol=1e-3,
                         n_output=4001)
    assert np.max(np.abs(loose.energy_balance())) > 100 * np.max(np.abs(
        tight.energy_balance()))


def test_driven_oscillator_energy_balance():
    s = _oscillator(driven=True)
    sim = s.equations_of_motion().simulate(t=(0, 8), q0=[0.0], m=1.0, k=4.0, c=0.1,
                                           F0=0.5, w=1.7, **TIGHT)
    assert np.max(np.abs(sim.energy_balance())) < 1e-8


def _bead(route):
    r = rm.coordinates("r")
    m, w, k, l0 = rm.constants("m omega k l0", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=w * t)
    B = R1.point("B", r, 0, 0)
    bead = rm.Body("bead", frame=R1.translated("Rb", B), mass=m, centre=B)
    if route == "galilean":
        s = rm.System(galilean=R0)
        s.add(bead)
    else:
        s = rm.System(galilean=R0, reference=R1)
        s.add(bead)
    s.act(rm.Spring(k, l0, a=R1.point("A", -5, 0, 0), b=B, on_b=bead))
    return s


@pytest.mark.parametrize("route", ["galilean", "reference"])
def test_bead_on_rotating_rod_energy(route):
    """Relative to the rod, T + V with the centrifugal potential -m omega^2 r^2 / 2 is
    conserved (Painlevé's integral of the Galilean route); energy_drift accepts it in the
    reference route and refuses T + V of the Galilean route, which is not conserved."""
    s = _bead(route)
    sim = s.equations_of_motion().simulate(t=(0, 5), q0=[1.0], u0=[0.3], m=1.0, omega=1.2,
                                           k=3.0, l0=5.0, **TIGHT)
    assert np.max(np.abs(sim.energy_balance())) < 1e-8
    if route == "reference":
        assert sim.time_dependence() is None
        assert sim.energy_drift() < 1e-9
    else:
        with pytest.raises(ArgumentError, match=r"energy_drift\(\) would misreport: the "
                                                r"kinetic energy has terms of degree 0 or 1"):
            sim.energy_drift()


@pytest.mark.parametrize("route", ["galilean", "reference"])
def test_pendulum_in_a_wagon_with_varying_acceleration_energy_balance(route):
    """The wagon's acceleration varies: the inertial action has no potential and does
    work; the balance still closes."""
    th = rm.coordinates("theta")
    m, L, g, b, c = rm.constants("m L g b c", positive=True)
    R0 = rm.Frame("R0")
    Rw = R0.translated("Rw", R0.point("W", b * sp.sin(c * t), 0, 0))
    Rp = Rw.rotated("Rp", about=Rw.k, angle=th)
    bob = rm.Body("bob", frame=Rp, mass=m, centre=Rw.origin.moved("G", -L * Rp.j))
    s = rm.System(galilean=R0, reference=Rw if route == "reference" else None)
    if route == "reference":
        s.connect(Rw, bob, rm.joints.Pivot(at=Rw.origin, axis=Rw.k))
    else:
        wagon = rm.Body("wagon", frame=Rw)
        s.connect(R0, wagon, rm.joints.Prismatic(at=Rw.origin, axis=R0.i))
        s.connect(wagon, bob, rm.joints.Pivot(at=Rw.origin, axis=Rw.k))
    s.act(rm.gravity(-g * R0.j))
    eqs = s.equations_of_motion()
    sim = eqs.simulate(t=(0, 6), q0=[0.2], m=1.0, L=1.0, g=9.81, b=0.3, c=2.0, **TIGHT)
    assert np.max(np.abs(sim.energy_balance())) < 1e-8 * 9.81
    if route == "reference":
        assert eqs.energy is None          # the inertial action has no potential here


def test_turning_gravity_energy_drift_refused_and_balance():
    """A gravity field that turns with time (as seen from a frame it is not fixed in): its
    potential depends on time explicitly, T + V is not conserved, energy_drift refuses."""
    th = rm.coordinates("theta")
    m, L, g, W = rm.constants("m L g Omega", positive=True)
    R0 = rm.Frame("R0")
    Rg = R0.rotated("Rg", about=R0.k, angle=W * t)
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    bob = rm.Body("bob", frame=R1, mass=m, centre=R0.origin.moved("G", L * R1.i))
    s = rm.System(galilean=R0)
    s.connect(R0, bob, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.gravity(g * Rg.i))
    sim = s.equations_of_motion().simulate(t=(0, 4), q0=[0.5], m=1.0, L=1.0, g=9.81,
                                           Omega=0.7, **TIGHT)
    with pytest.raises(ArgumentError, match=r"T \+ V depends on time explicitly.*"
                                            r"Use energy_balance\(\)"):
        sim.energy_drift()
    assert np.max(np.abs(sim.energy_balance())) < 1e-8 * 9.81


def test_moving_attractor_energy_drift_refused():
    x, y = rm.coordinates("x y")
    m, mu, W = rm.constants("m mu Omega", positive=True)
    R0 = rm.Frame("R0")
    C = R0.origin.moved("C", 0.5 * (sp.cos(W * t) * R0.i + sp.sin(W * t) * R0.j))
    P = R0.point("P", x, y, 0)
    s = rm.System(galilean=R0)
    s.add(rm.Body("probe", frame=R0.translated("Rp", P), mass=m, centre=P))
    s.act(rm.actions.SphericalBodyAttraction(rm.actions.point_mass_attractor(mu, G=1), centre=C))
    sim = s.equations_of_motion().simulate(t=(0, 3), q0=[3.0, 0.0], u0=[0.0, 0.6], m=1.0,
                                           mu=1.0, Omega=1.0, **TIGHT)
    with pytest.raises(ArgumentError, match="depends on time explicitly"):
        sim.energy_drift()
    assert np.max(np.abs(sim.energy_balance())) < 1e-8


def test_energy_balance_bad_input():
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-x]]))
    sim = eqs.simulate(t=(0, 1), q0=[1.0], n_output=5)
    with pytest.raises(ArgumentError, match=r"energy_balance\(\) needs equations derived by "
                                            r"System.equations_of_motion\(\)"):
        sim.energy_balance()
    s = _oscillator()
    sim = s.equations_of_motion().simulate(t=(0, 1), q0=[1.0], m=1.0, k=4.0, c=0.4)
    s.act(rm.gravity(-s.galilean.j))
    with pytest.raises(ArgumentError, match="the system has changed"):
        sim.energy_balance()


def test_four_bar_with_a_damper_energy_balance():
    """A closed loop: the multipliers of the closing joint do no work (its conditions do
    not depend on time), the torsional damper dissipates."""
    q1, q2, q3 = rm.coordinates("q1 q2 q3")
    m, g, c = rm.constants("m g c", positive=True)
    R0 = rm.Frame("R0")
    k = R0.k
    R1 = R0.rotated("R1", about=k, angle=q1)
    R2 = R1.rotated("R2", about=k, angle=q2, origin=R0.origin.moved("B", R1.i))
    R3 = R0.rotated("R3", about=k, angle=q3, origin=R0.point("D", 2, 0, 0))
    bars = []
    for name, frame, length in (("crank", R1, 1), ("coupler", R2, 2), ("rocker", R3, 1.5)):
        G = frame.origin.moved("G" + name, length / 2 * frame.i)
        bars.append(rm.Body(name, frame=frame, mass=m, centre=G,
                            inertia=rm.inertia.rod(m, length, axis=frame.i, centre=G)))
    crank, coupler, rocker = bars
    s = rm.System(galilean=R0)
    s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=k))
    s.connect(crank, coupler, rm.joints.Pivot(at=R2.origin, axis=k))
    s.connect(R0, rocker, rm.joints.Pivot(at=R3.origin, axis=k))
    s.connect(coupler, rocker, rm.joints.Pivot(at=R2.origin.moved("C", 2 * R2.i), axis=k),
              meets=R3.origin.moved("C3", 1.5 * R3.i))
    s.act(rm.gravity(-g * R0.j))
    s.act(rm.actions.TorsionalDamper(c, axis=k, on=crank))
    q0, u0 = s.assemble({"q1": 1.0, "q2": -0.6, "q3": 1.4}, independent=["q1"],
                        rates={"q1": 2.0}, m=1.0, g=9.81, c=0.3)
    sim = s.equations_of_motion().simulate(t=(0, 5), q0=q0, u0=u0, m=1.0, g=9.81, c=0.3,
                                           **TIGHT)
    E = sim.energy()
    assert E[-1] < E[0] - 1.0                        # the damper took energy away
    assert np.max(np.abs(sim.energy_balance())) < 1e-7 * abs(E[0])


def test_free_body_in_euler_parameters_with_a_torsional_damper():
    """A body oriented by Euler parameters (their normalisation row added to the equations)
    under gravity, its rotation about k0 damped: the balance closes."""
    from rigidmech.vectors import euler_parameter_rates

    x, y, z, e0, e1, e2, e3 = rm.coordinates("x y z e0 e1 e2 e3")
    m, g, A, B, C = rm.constants("m g A B C", positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, z)
    R = R0.euler_parameters("R", e0, e1, e2, e3, origin=G)
    body = rm.Body("body", frame=R, mass=m, centre=G,
                   inertia=rm.InertiaOperator.from_products(A, B, C, frame=R, at=G))
    s = rm.System(galilean=R0)
    s.add(body)
    s.act(rm.gravity(-g * R0.k))
    s.act(rm.actions.TorsionalDamper(0.2, axis=R0.k, on=body))
    eqs = s.equations_of_motion()
    e_start = np.array([np.cos(0.15), np.sin(0.15), 0.0, 0.0])
    start = dict(zip(("e0", "e1", "e2", "e3"), e_start, strict=True))
    rates = dict(zip(("e0", "e1", "e2", "e3"),
                     euler_parameter_rates(e_start, [1.0, 0.5, 2.0]), strict=True)) | {"z": 1.0}
    sim = eqs.simulate(t=(0, 3), q0=start, u0=rates, m=1.3, g=9.81, A=1.0, B=2.0, C=2.5,
                       **TIGHT)
    E = sim.energy()
    assert E[-1] < E[0] - 1.0
    assert np.max(np.abs(sim.energy_balance())) < 1e-9 * abs(E[0])


def test_damped_system_energy_drift_refused_not_reported_as_drift():
    """A damper dissipates: T + V decreases along an exact motion (here to < 20 % of E0), so
    energy_drift would report the dissipation as an integration error; it refuses and names
    the damper, and energy_not_conserved() says why. The undamped system is accepted."""
    sim = _oscillator().equations_of_motion().simulate(t=(0, 6), q0=[1.0], m=1.0, k=4.0,
                                                        c=0.4, **TIGHT)
    assert "Damper" in sim.energy_not_conserved()
    with pytest.raises(ArgumentError, match=r"energy_drift\(\) would misreport: .*Damper.*"
                                            r"dissipate.*Use energy_balance\(\)"):
        sim.energy_drift()
    free = _oscillator(damped=False).equations_of_motion().simulate(
        t=(0, 6), q0=[1.0], m=1.0, k=4.0, **TIGHT)
    assert free.energy_not_conserved() is None
    assert free.energy_drift() < 1e-9


# -- "vanishes identically": the rule of the joints and closures ----------------------------
@pytest.mark.parametrize(("residue", "prescribed"), [(6.9e-18, False), (1e-6, True)])
def test_time_dependence_tolerates_only_float_rounding(residue, prescribed):
    """T0 (the part of T of degree 0 in the rates) at float rounding of the other terms
    (6.9e-18, what 0.0625 sin(0.0625) - 0.0625 sin(0.0625) leaves once sympy has combined the
    floats) is not a prescribed motion; 1e-6 of them is. The decision is
    :func:`rigidmech._core.symbolic.vanishes`, as for Joint.check and the closures (it was a
    bare ``simplify``, which saw the rounding as a term)."""
    r = rm.coordinates("r")
    u, q = sp.symbols("u q")
    rule = {r.diff(rm.t): u, r: q}
    kinetic = 0.5 * r.diff(rm.t) ** 2 + residue * r ** 2
    why = time_dependence(kinetic, None, [u], rule)
    assert (why is not None) == prescribed
