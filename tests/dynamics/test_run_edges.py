"""Trust at the edges of a run (issue 19, the run side): simulate, the constraint
projection, the energy drift, early stops.

Each test names the defect it checks and failed on the code before its fix. Reference values:
the closure conditions of a four-bar (tests/systems/mechanisms.py, ground 2, crank 1, coupler
2, rocker 1.5, bars of mass 1, g = 9.81) evaluated along the motion (0 on an exact motion), or
a tight run (rtol 1e-12) of the same equations.
"""

import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import ode

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "systems"))
from mechanisms import four_bar  # noqa: E402

VALUES = {"m": 1.0, "g": 9.81}


def closure_residual(system, sim, **values):
    phi = sp.Matrix([p for _, _, p in system.closure_conditions()])
    return float(np.abs(sim.evaluate(phi)).max())


@pytest.fixture(scope="module")
def bar4():
    s, qs, *_ = four_bar()
    q0, u0 = s.assemble({"q1": 1.0, "q2": -0.5, "q3": 1.5}, independent=["q1"],
                        rates={"q1": 1.0}, **VALUES)
    return s, s.equations_of_motion(), list(q0.values()), list(u0.values())


# -- item 9: an alias behaves exactly as its method ---------------------------------------
@pytest.mark.parametrize("name", ["rk45", "RK45", "DOPRI5", "Dop853"])
def test_alias_or_other_case_projects_as_its_method(bar4, name):
    """"rk45" (an alias of "dopri5") and "DOPRI5" were not projected by default (residual
    1.7e-7 against 1.6e-15 for "dopri5", rtol 1e-7) and refused project=True."""
    s, eqs, q0, u0 = bar4
    sim = eqs.simulate(t=(0, 2), q0=q0, u0=u0, method=name, rtol=1e-7, atol=1e-9,
                       n_output=51, **VALUES)
    assert closure_residual(s, sim) < 1e-12
    sim = eqs.simulate(t=(0, 0.5), q0=q0, u0=u0, method=name, project=True, n_output=5,
                       **VALUES)
    assert sim.status == "finished"


def test_alias_resolves_to_one_entry():
    from rigidmech.ode import _registry

    assert _registry.get("rk45") is _registry.get("dopri5")
    assert "rk45" in ode.methods("adaptive")


# -- item 7: a constant only in the closure conditions -----------------------------------
def test_constant_only_in_closure_conditions_is_a_parameter():
    """System(stabilization=(0, 0)) with the ground length a symbol L0: simulate raised
    CompilationError (the projection needs L0, the equations did not list it) and a note said
    its value was ignored."""
    L0 = sp.Symbol("L0", positive=True)
    s, qs, *_ = four_bar((L0, 1.0, 2.0, 1.5), stabilization=(0, 0))
    eqs = s.equations_of_motion()
    assert L0 in eqs.parameters
    q0, u0 = s.assemble({"q1": 1.0, "q2": -0.5, "q3": 1.5}, independent=["q1"],
                        rates={"q1": 1.0}, L0=2.0, **VALUES)
    sim = eqs.simulate(t=(0, 1), q0=list(q0.values()), u0=list(u0.values()), L0=2.0,
                       n_output=11, **VALUES)
    assert sim.status == "finished" and sim.notes == ()
    phi = sp.Matrix([p for _, _, p in s.closure_conditions()]).subs(L0, 2.0)
    assert np.abs(sim.evaluate(phi)).max() < 1e-12
    with pytest.raises(rm.errors.ArgumentError, match="L0"):
        eqs.simulate(t=(0, 1), q0=list(q0.values()), **VALUES)


# -- item 2: the initial state on the constraints -------------------------------------------
def test_loop_that_cannot_close_is_refused():
    """crank, coupler, rocker 1, 1, 1 and ground 4: simulate(q0=[0, 0, pi]) ran to
    status 'finished' with q(0) ~ (-3e15, -2e15, 8e15); assemble refuses it, so must
    simulate."""
    s, *_ = four_bar((4.0, 1.0, 1.0, 1.0))
    eqs = s.equations_of_motion()
    with pytest.raises(rm.errors.ConnectionError_, match=r"`q0`.*cannot be closed"):
        eqs.simulate(t=(0, 0.1), q0=[0.0, 0.0, np.pi], **VALUES)


def test_q0_off_the_loop_keeps_the_independent_coordinates(bar4):
    """q0 = (1.0, 0.5, 1.5) off the loop was moved to another branch, the crank angle
    included: (-1.58, 2.39, 0.08). The first coordinate (the crank) is kept by default, the
    dependent ones moved by Newton's method from the values given, as System.assemble does
    with independent=["q1"]; the simulation reports q0 given, q0 used and a note."""
    s, eqs, _, _ = bar4
    sim = eqs.simulate(t=(0, 0.5), q0=[1.0, 0.5, 1.5], u0=[1.0, 0.0, 0.0], n_output=6,
                       **VALUES)
    q_ref, u_ref = s.assemble({"q1": 1.0, "q2": 0.5, "q3": 1.5}, independent=["q1"],
                              rates={"q1": 1.0}, **VALUES)
    assert sim.q[0, 0] == 1.0 and sim.u[0, 0] == 1.0
    np.testing.assert_allclose(sim.q[:, 0], list(q_ref.values()), rtol=0, atol=1e-12)
    np.testing.assert_allclose(sim.u[:, 0], list(u_ref.values()), rtol=0, atol=1e-12)
    assert sim.q0_given.tolist() == [1.0, 0.5, 1.5]
    assert sim.u0_given.tolist() == [1.0, 0.0, 0.0]
    note = " ".join(sim.notes)
    assert "`q0`" in note and "q2" in note and "q3" in note and "kept: q1" in note
    assert closure_residual(s, sim) < 1e-12


def test_q0_off_the_loop_with_independent(bar4):
    s, eqs, _, _ = bar4
    sim = eqs.simulate(t=(0, 0.1), q0=[1.0, 0.5, 1.5], independent=["q3"], n_output=2,
                       **VALUES)
    q_ref, _ = s.assemble({"q1": 1.0, "q2": 0.5, "q3": 1.5}, independent=["q3"], **VALUES)
    assert sim.q[2, 0] == 1.5
    np.testing.assert_allclose(sim.q[:, 0], list(q_ref.values()), rtol=0, atol=1e-12)


def test_q0_dict_keeps_the_coordinates_named(bar4):
    """A dict q0 names the coordinates the user chose: those are kept, the others (a guess
    of 0) are the dependent ones first."""
    s, eqs, _, _ = bar4
    sim = eqs.simulate(t=(0, 0.1), q0={"q2": -0.5, "q3": 1.5}, n_output=2, **VALUES)
    assert sim.q[1, 0] == -0.5
    assert "kept: q2" in " ".join(sim.notes)
    assert closure_residual(s, sim) < 1e-12


def test_q0_on_the_loop_is_used_as_given(bar4):
    s, eqs, q0, u0 = bar4
    sim = eqs.simulate(t=(0, 0.1), q0=q0, u0=u0, n_output=2, **VALUES)
    assert sim.notes == () and sim.q[:, 0].tolist() == q0 and sim.u[:, 0].tolist() == u0


def test_independent_without_constraints_is_refused():
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-x]]))
    with pytest.raises(rm.errors.ArgumentError, match="`independent`.*no constraints"):
        eqs.simulate(t=(0, 1), q0=[1.0], independent=["x"])


def _line():
    """x on the line x = 0 (y free): Φ = x exactly, the boundary testable to the last bit."""
    from rigidmech.dynamics import Constraints

    x, y = rm.coordinates("x y")
    c = Constraints((x, y), [("line", x.diff(rm.t), x)])
    return rm.EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
                                forcing=sp.Matrix([0, -1]), constraints=c)


# The rule (rigidmech._core.rules.on_constraints, issue 19): |Φ| at most 1e-9 of the
# magnitude of its terms. On the line x = 1 (Φ = x - 1, terms |x| + 1), the boundary is
# x0 = 1 + d with d = 1e-9 (2 + d): d* = 2e-9 / (1 - 1e-9); floats resolve 1e-7 of d* there
# (the boundary itself and 1e-12 of it are tested on the rule, tests/dynamics/
# test_relative_rules.py).
D_STAR = 2e-9 / (1 - 1e-9)


def _line_at_one():
    from rigidmech.dynamics import Constraints

    x, y = rm.coordinates("x y")
    c = Constraints((x, y), [("line", x.diff(rm.t), x - 1)])
    return rm.EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
                                forcing=sp.Matrix([0, -1]), constraints=c)


@pytest.mark.parametrize("d, moved", [(D_STAR * (1 - 1e-6), False), (D_STAR * (1 + 1e-6), True),
                                      (-D_STAR * (1 - 1e-6), False),
                                      (-D_STAR * (1 + 1e-6), True)])
def test_on_the_constraints_boundary(d, moved):
    """A state on the constraints (|Φ| <= 1e-9 of its terms, the rule System.assemble
    reaches) is used as given; beyond, moved (with a note)."""
    sim = _line_at_one().simulate(t=(0, 0.1), q0=[1.0 + d, 2.0], n_output=2)
    assert (sim.q[0, 0] == 1.0 and len(sim.notes) == 1) if moved else \
        (sim.notes == () and sim.q0_given[0] == 1.0 + d)
    assert sim.q[1, 0] == 2.0


def test_a_condition_without_a_scale_holds_only_exactly():
    """Φ = x (the line x = 0) has no length in it: x0 = 1e-9 is off it (it passed the
    absolute 1e-9), moved onto it."""
    sim = _line().simulate(t=(0, 0.1), q0=[1e-9, 2.0], n_output=2)
    assert sim.q[0, 0] == 0.0 and len(sim.notes) == 1


@pytest.mark.parametrize("v0, moved", [(3e-9 * (1 - 1e-6), False), (3e-9 * (1 + 1e-6), True)])
def test_rates_on_the_constraints_boundary(v0, moved):
    """A q' + a = x': its terms with every rate at the largest |q'_j| (y' = 3) are 3: the
    boundary is |x'| = 3e-9."""
    sim = _line().simulate(t=(0, 0.1), q0=[0.0, 2.0], u0=[v0, 3.0], n_output=2,
                           project=False)
    assert (sim.u[0, 0] == 0.0 and "`u0`" in sim.notes[0]) if moved else \
        not [n for n in sim.notes if "`u0`" in n]
    assert sim.u[1, 0] == 3.0


# -- item 6: the energy drift of a run released where E = 0 -------------------------------
def _rod():
    from mechanisms import bar

    q = rm.coordinates("q")
    m, g, L = rm.constants("m g L", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    s = rm.System(galilean=R0)
    s.connect(R0, bar("rod", R1, L, R0.origin, m), rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.gravity(-g * R0.j))
    return s.equations_of_motion()


def test_energy_drift_of_a_rod_released_horizontal():
    """A rod (m = 2, L = 1.5) released horizontal, pointing away from the side q = 0
    (q0 = pi: V = m g L/2 sin q0 ~ 1e-15, T0 = 0): the drift of an exact run read 9.4e4, its
    scale T(0) + |V(0)| being 1.8e-15. The scale is now the larger of T(0) + |V(0)| and the
    largest kinetic energy reached, here m g L / 2 = 14.715 (the potential energy released at
    the bottom); the tight run (rtol 1e-12) conserves E to 1.7e-10 absolute."""
    eqs = _rod()
    sim = eqs.simulate(t=(0, 2), q0=[np.pi], rtol=1e-12, atol=1e-12, m=2.0, g=9.81, L=1.5)
    T = 1.5**2 * 2.0 * sim.u[0] ** 2 / 6
    assert sim.energy_scale() == pytest.approx(T.max(), rel=1e-12)
    assert sim.energy_scale() == pytest.approx(2.0 * 9.81 * 1.5 / 2, rel=1e-4)
    assert sim.energy_drift() < 1e-10


# -- item 10: the real cause of a missing energy --------------------------------------------
def test_energy_drift_names_the_action_without_potential():
    """A bar on a pivot driven by a constant motor couple, held by a spring: energy_drift()
    said the actions "have no potential energy" while the spring has one. The couple does
    work: it is named, with the way out (energy_balance)."""
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", R1.i)
    crank = rm.Body("crank", frame=R1, mass=1, centre=G,
                    inertia=rm.inertia.rod(1, 2, axis=R1.i, centre=G))
    s = rm.System(galilean=R0)
    s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.Spring(4, 0, a=R0.point("A", 1, 0, 0), b=G, on_b=crank))
    s.act(rm.actions.Couple(on=crank, moment=0.5 * R0.k))
    sim = s.equations_of_motion().simulate(t=(0, 1), q0=[0.0], n_output=401)
    with pytest.raises(rm.errors.ArgumentError,
                       match=r"Couple\(on=crank.*no potential energy.*energy_balance"):
        sim.energy_drift()
    assert np.abs(sim.energy_balance()).max() < 1e-6


# -- item 12: ReducedEquations.simulate -----------------------------------------------------
def test_reduced_simulate_matches_the_augmented_run(bar4):
    """ReducedEquations had no simulate: the user built the state for ode.solve by hand and
    lost the projection. Its run (same options, same result type) matches the multiplier
    form's to the tolerance of both (rtol 1e-10), keeps the loop closed (projection) and the
    energy (conservative four-bar)."""
    s, eqs, q0, u0 = bar4
    red = eqs.reduced(independent=["q1"])
    ref = eqs.simulate(t=(0, 2), q0=q0, u0=u0, rtol=1e-11, atol=1e-12, n_output=21, **VALUES)
    sim = red.simulate(t=(0, 2), q0=q0, u0=u0, rtol=1e-11, atol=1e-12, n_output=21, **VALUES)
    assert isinstance(sim, rm.dynamics.Simulation) and sim.status == "finished"
    assert sim.q.shape == sim.u.shape == (3, 21) and sim.names == ("q1", "q2", "q3")
    np.testing.assert_allclose(sim.q, ref.q, rtol=0, atol=1e-8)
    np.testing.assert_allclose(sim.u, ref.u, rtol=0, atol=1e-8)
    assert closure_residual(s, sim) < 1e-12
    assert sim.energy_drift() < 1e-9
    phi = sp.Matrix([v for _, v, _ in s.closure_conditions()])
    assert np.abs(sim.evaluate(phi)).max() < 1e-12       # the rates on A q' + a = 0


def test_reduced_simulate_assembles_q0_keeping_its_independent(bar4):
    s, eqs, _, _ = bar4
    red = eqs.reduced(independent=["q1"])
    sim = red.simulate(t=(0, 0.2), q0=[1.0, 0.5, 1.5], u0=[1.0, 0.0, 0.0], n_output=3,
                       **VALUES)
    assert sim.q[0, 0] == 1.0 and sim.u[0, 0] == 1.0 and sim.notes
    assert closure_residual(s, sim) < 1e-12


def test_reduced_simulate_fixed_step_and_refusals(bar4):
    s, eqs, q0, u0 = bar4
    red = eqs.reduced(independent=["q1"])
    sim = red.simulate(t=(0, 0.5), q0=q0, u0=u0, method="rk4", step=1e-3, n_output=6,
                       **VALUES)
    ref = eqs.simulate(t=(0, 0.5), q0=q0, u0=u0, rtol=1e-11, atol=1e-12, n_output=6,
                       **VALUES)
    np.testing.assert_allclose(sim.q, ref.q, rtol=0, atol=1e-7)
    with pytest.raises(rm.errors.ArgumentError, match="`method`.*reduced"):
        red.simulate(t=(0, 0.5), q0=q0, method="verlet", step=1e-3, **VALUES)


# -- item 17: a run that stops early keeps the last state it reached ------------------------
def _oscillator(input_=False):
    x = rm.coordinates("x")
    F = sp.Function("F")(rm.t)
    return rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                                forcing=sp.ImmutableMatrix([[-x + (F if input_ else 0)]]))


def _keeps_the_stop(sim):
    """The last sample is the state reached at t_stop (x = cos t, x' = -sin t)."""
    assert sim.t[-1] == sim.t_stop and sim.t.size >= 2
    assert sim.q[0, -1] == pytest.approx(np.cos(sim.t_stop), abs=1e-7)
    assert sim.u[0, -1] == pytest.approx(-np.sin(sim.t_stop), abs=1e-7)


@pytest.mark.parametrize("method", ["dop853", "gbs", "radau"])
def test_max_steps_keeps_the_state_reached(method):
    """max_steps stopped the run between two samples: the samples kept ended at t = 0 while
    the solver had reached t_stop = 1.3 (dop853, 5 steps)."""
    sim = _oscillator().simulate(t=(0, 10), q0=[1.0], n_output=3, max_steps=5, method=method,
                                 rtol=1e-10, atol=1e-12)
    assert sim.status == "failed" and 0 < sim.t_stop < 5
    _keeps_the_stop(sim)


@pytest.mark.parametrize("method", ["rk4", "ab4"])
def test_fixed_step_interrupt_keeps_the_state_reached(method):
    """(max_steps is refused before a fixed-step run starts: it knows its number of steps.)"""
    def force(t):
        if t > 2.0:
            raise KeyboardInterrupt
        return 0.0

    sim = _oscillator(input_=True).simulate(t=(0, 10), q0=[1.0], n_output=3, F=force,
                                            method=method, step=1e-3)
    assert sim.status == "interrupted" and sim.t_stop > 1.0
    _keeps_the_stop(sim)


def test_progress_interrupt_keeps_the_state_reached(monkeypatch):
    from rigidmech.dynamics import _run

    monkeypatch.setattr(_run, "PROGRESS_EVERY", 0.0)   # the callback at every step

    def progress(t):
        if t > 1.0:
            raise KeyboardInterrupt

    sim = _oscillator().simulate(t=(0, 10), q0=[1.0], n_output=3, progress=progress,
                                 rtol=1e-10, atol=1e-12)
    assert sim.status == "interrupted" and sim.t_stop > 1.0
    _keeps_the_stop(sim)
    assert f"{sim.t_stop!r}" in sim.message


def test_rhs_interrupt_keeps_the_state_reached(tmp_path):
    """Ctrl-C raised while the right-hand side runs (here from an input F(t) = 0), then the
    stopping state saved and loaded back."""
    def force(t):
        if t > 2.0:
            raise KeyboardInterrupt
        return 0.0

    sim = _oscillator(input_=True).simulate(t=(0, 10), q0=[1.0], n_output=3, F=force,
                                            rtol=1e-10, atol=1e-12)
    assert sim.status == "interrupted" and 1.0 < sim.t_stop <= 2.0
    _keeps_the_stop(sim)
    back = rm.dynamics.Simulation.load(sim.save(tmp_path / "stopped.npz"))
    assert back.t[-1] == sim.t_stop and back.q[0, -1] == sim.q[0, -1]


def test_failure_keeps_the_last_finite_state():
    """x'' = -x + F(t) with F = 0 until t = 2, then nan: the run fails (a non-finite
    right-hand side, named); the last state it reached before, x = cos t, is kept as the last
    sample (the samples ended at t = 0)."""
    sim = _oscillator(input_=True).simulate(
        t=(0, 10), q0=[1.0], n_output=3, F=lambda t: 0.0 if t <= 2.0 else np.nan,
        rtol=1e-10, atol=1e-12)
    assert sim.status == "failed" and 1.0 < sim.t_stop <= 2.0
    _keeps_the_stop(sim)
    assert "last state reached" in sim.message and "x'' (acceleration of x)" in sim.message


def test_plain_step_underflow_keeps_the_samples_only():
    """A step size underflow at a blow-up (x'' = 2 x^3, x = 1/(1 - t)): the last accepted
    state jumped the singularity (t = 1 + 5e-10, x = 8e13 > 0): it is not kept as a sample
    (the message gives it)."""
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[2 * x**3]]))
    sim = eqs.simulate(t=(0, 2), q0=[1.0], u0=[1.0], n_output=5)
    assert sim.status == "failed" and sim.t[-1] <= 1.0 < sim.t_stop
    assert "state y = " in sim.message and "last state reached" not in sim.message


# -- item 11: Baumgarte's stabilisation and the time scale of the run ----------------------
@pytest.mark.parametrize("span, note", [(0.2, False), (0.2 * (1 - 1e-6), True),
                                        (0.2 * (1 + 1e-6), False), (0.2 * (1 - 1e-12), True),
                                        (0.01, True)])
def test_baumgarte_that_cannot_act_is_noted(span, note):
    """Baumgarte's (5, 5) acts on the time scale 1/5 s: a run without projection shorter than
    1/alpha (alpha * duration < 1) is not corrected by it (a four-bar driven at 1000 rad/s
    over 10 ms, rk4, 500 steps: closure residual 2.64e-6 without, 2.58e-6 with (5, 5); at
    1 rad/s over 10 s: 7.1e-3 without, 1.9e-5 with): a note says so. alpha * duration = 1 is
    the boundary (no note)."""
    sim = _line().simulate(t=(0, span), q0=[0.0, 2.0], method="rk4", step=span / 10,
                           n_output=3)
    said = [n for n in sim.notes if "Baumgarte" in n]
    assert bool(said) == note
    if note:
        assert "1/alpha = 0.2" in said[0] and "stabilization=" in said[0]


def test_baumgarte_note_not_when_projected():
    sim = _line().simulate(t=(0, 0.01), q0=[0.0, 2.0], n_output=3)
    assert not [n for n in sim.notes if "Baumgarte" in n]


# -- a right-hand side that fails at the first step: its error comes through ----------------
def test_a_failure_at_the_first_step_is_reported_not_hidden_by_project():
    """A four-bar of lengths (2, 1, 2, 1) at q0 = (0, 0, 0) is flat: the loop is closed
    (dead centre) but the closure's Jacobian is singular, so the accelerations are not finite
    at t0. The run reported "`project` is for the methods of the integration loop; method
    'dop853' has its own loop" (the loop had stopped before taking the projection)."""
    model = rm.models.four_bar(lengths=(2.0, 1.0, 2.0, 1.0))
    eqs = model.system.equations_of_motion()
    sim = eqs.simulate((0.0, 1.0), q0=[0.0, 0.0, 0.0], method="dop853", **VALUES)
    assert sim.status == "failed" and "constraint Jacobian A has rank 1 < 2" in sim.message
    assert "`project`" not in sim.message


def test_ode_solve_reports_a_non_finite_start_with_project():
    """The same at the solver's level: ``project`` given, f(t0) not finite."""
    res = ode.solve(lambda t, y: np.full(2, np.nan), (0.0, 1.0), [1.0, 0.0],
                    method="dop853", project=lambda t, y: y)
    assert res.status < 0 and "not finite" in res.message
