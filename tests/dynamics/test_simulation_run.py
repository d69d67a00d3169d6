"""A run that never loses work (issue 10): ``simulate`` open to the solver's options and safe
(a status, the partial result kept), Ctrl-C, memory, progress, save and load, honest
diagnostics, connection actions along a motion.

Each test names the defect it checks; each failed on the code before the change (``simulate``
took no solver option, raised and dropped the trajectory on failure, kept every step, divided
the energy drift by max |E|, reported NaN as a step-size underflow, ...).

Reference values: closed forms stated in each test (free fall, harmonic oscillator,
x'' = 2 x^3 with x = 1/(1 - t)), or an independent route (Newton's law for the mass centre,
its acceleration differentiated by sympy from a position written by hand).
"""

import math
import tracemalloc

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, NumericalError
from rigidmech.dynamics import Event, Simulation, load_simulation

t = rm.t


def oscillator():
    """x'' = -k x, E = (x'^2 + k x^2) / 2: with x0 = 1, x0' = 0, x = cos(sqrt(k) t)."""
    x = rm.coordinates("x")
    k = sp.Symbol("k", positive=True)
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-k * x]]),
                               energy=(x.diff(t) ** 2 + k * x**2) / 2)
    return eqs, x, k


def blow_up():
    """x'' = 2 x^3, x(0) = x'(0) = 1: x = 1 / (1 - t), infinite at t = 1."""
    x = rm.coordinates("x")
    return rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                                forcing=sp.ImmutableMatrix([[2 * x**3]])), x


# -- 1. simulate open: the solver's options pass through ---------------------------------
def test_terminal_event_as_an_expression():
    # defect: `events` was refused ("unknown parameters")
    z = rm.coordinates("z")
    g = sp.Symbol("g", positive=True)
    eqs = rm.EquationsOfMotion(coordinates=(z,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-g]]))
    sim = eqs.simulate(t=(0, 10), q0=[20.0], events=Event(z, terminal=True, direction=-1),
                       g=9.81)
    # free fall from h = 20: lands at sqrt(2 h / g), with speed -sqrt(2 g h)
    assert sim.status == "event"
    assert_allclose(sim.t_events[0], [math.sqrt(40 / 9.81)], rtol=1e-12)
    assert sim.t[-1] <= math.sqrt(40 / 9.81) + 1e-12
    assert np.all(sim.q[0] >= -1e-9)


def test_event_as_a_function_of_t_y_and_non_terminal():
    eqs, x, k = oscillator()
    crossing = rm.ode.event(lambda tt, y: y[0])  # x = cos(2 t) = 0 at t = pi/4, 3 pi/4
    sim = eqs.simulate(t=(0, 3), q0=[1.0], events=[crossing], rtol=1e-12, atol=1e-14, k=4.0)
    assert sim.status == "finished"
    assert_allclose(sim.t_events[0], np.pi / 4 + np.arange(2) * np.pi / 2, rtol=1e-10)


def test_event_expression_with_a_parameter_and_a_rate():
    eqs, x, k = oscillator()
    # x' = -2 sin(2 t) crosses -sqrt(k) (= -2) at t = pi/4, downwards... it touches; use -1
    ev = Event(x.diff(t) + k / 4, direction=-1)     # x' = -1 at sin(2t) = 1/2, going down
    sim = eqs.simulate(t=(0, 1.5), q0=[1.0], events=ev, rtol=1e-12, atol=1e-14, k=4.0)
    assert_allclose(sim.t_events[0], [np.pi / 12], rtol=1e-9)


def test_max_steps_keeps_the_samples_so_far():
    # defect: max_steps could not be set, and failing dropped everything
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 100), q0=[1.0], max_steps=50, k=4.0)
    assert sim.status == "failed"
    assert "`max_steps` = 50" in sim.message
    assert 1.0 < sim.t[-1] < 100.0
    assert_allclose(sim.q[0], np.cos(2 * sim.t), atol=1e-6)


def test_first_step_max_step_t_eval_dense_output():
    eqs, x, k = oscillator()
    te = [0.0, 0.5, 1.25, 2.0]
    sim = eqs.simulate(t=(0, 2), q0=[1.0], t_eval=te, max_step=0.01, first_step=1e-3,
                       dense_output=True, rtol=1e-10, atol=1e-12, k=4.0)
    assert sim.t.tolist() == te
    assert sim.result.nsteps >= 200  # max_step = 0.01 over a span of 2
    assert_allclose(sim.q[0], np.cos(2 * np.array(te)), atol=1e-9)
    assert_allclose(sim.result.sol(0.3)[0], np.cos(0.6), atol=1e-9)


def test_a_parameter_named_like_a_solver_option():
    x = rm.coordinates("x")
    mx = sp.Symbol("max_steps")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-mx * x]]))
    sim = eqs.simulate(t=(0, 1), q0=[1.0], params={"max_steps": 4.0}, max_steps=10_000,
                       rtol=1e-10, atol=1e-12)
    assert_allclose(sim.q[0, -1], math.cos(2.0), atol=1e-8)
    assert sim.parameters == {"max_steps": 4.0}


def test_a_value_given_twice_is_refused():
    eqs, x, k = oscillator()
    with pytest.raises(ArgumentError, match=r"values of \['k'\] are given twice"):
        eqs.simulate(t=(0, 1), q0=[1.0], params={"k": 1.0}, k=2.0)


# -- 1. status, partial result, opt-in raise ----------------------------------------------
def test_failure_keeps_the_motion_up_to_it():
    # defect: simulate raised NumericalError and dropped the trajectory computed so far
    eqs, x = blow_up()
    sim = eqs.simulate(t=(0, 2), q0=[1.0], u0=[1.0], n_output=1000)  # no sample at t = 1
    assert sim.status == "failed" and not sim.success
    assert 0.99 < sim.t[-1] < 1.0
    assert "step size underflow" in sim.message and "at t = 1.0" in sim.message
    assert_allclose(sim.q[0], 1 / (1 - sim.t), rtol=1e-5)
    with pytest.raises(NumericalError, match="integration failed") as info:
        sim.check()
    assert info.value.simulation is sim


def test_raise_on_failure():
    eqs, x = blow_up()
    with pytest.raises(NumericalError) as info:
        eqs.simulate(t=(0, 2), q0=[1.0], u0=[1.0], raise_on_failure=True)
    assert info.value.simulation.t[-1] > 0.99


# -- 2. interruption ----------------------------------------------------------------------
def test_keyboard_interrupt_returns_the_partial_result():
    # defect: Ctrl-C gave a traceback and kept nothing. Here an input raises
    # KeyboardInterrupt as Ctrl-C would during an evaluation, at t > 2.
    x = rm.coordinates("x")
    F = sp.Function("F")(t)
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-4 * x + F]]))

    def force(tt):
        if tt > 2.0:
            raise KeyboardInterrupt
        return 0.0

    sim = eqs.simulate(t=(0, 10), q0=[1.0], F=force, rtol=1e-10, atol=1e-12)
    assert sim.status == "interrupted"
    assert "Ctrl-C" in sim.message
    assert 1.9 < sim.t[-1] <= 2.0
    assert_allclose(sim.q[0], np.cos(2 * sim.t), atol=1e-8)


def test_progress_callback_sees_the_time_and_can_stop(monkeypatch):
    from rigidmech.dynamics import _run

    monkeypatch.setattr(_run, "PROGRESS_EVERY", 0.0)
    eqs, x, k = oscillator()
    seen = []

    def progress(tt):
        seen.append(tt)
        return tt < 5.0

    sim = eqs.simulate(t=(0, 50), q0=[1.0], max_step=0.01, progress=progress, k=4.0)
    assert sim.status == "interrupted" and "progress" in sim.message
    assert seen == sorted(seen) and seen[-1] >= 5.0
    assert 4.0 < sim.t[-1] < 6.0


def test_progress_bar_on_request(monkeypatch, capsys):
    from rigidmech.dynamics import _run

    monkeypatch.setattr(_run, "PROGRESS_EVERY", 0.0)
    monkeypatch.setattr(_run, "PROGRESS_DELAY", 0.0)
    eqs, x, k = oscillator()
    eqs.simulate(t=(0, 5), q0=[1.0], max_step=0.01, progress=True, k=4.0)
    assert "rigidmech: integrating" in capsys.readouterr().err
    eqs.simulate(t=(0, 5), q0=[1.0], max_step=0.01, k=4.0)  # default: stderr not a TTY
    assert "integrating" not in capsys.readouterr().err


# -- 3. memory ----------------------------------------------------------------------------
@pytest.mark.slow
def test_memory_follows_the_samples_not_the_steps():
    # defect: about 1 KB per step was kept whatever the samples asked for. 10^5 steps of
    # bs32 (max_step = span / 10^5) asking for 100 samples. Keeping every step would hold at
    # least 10^5 states (an ndarray of 2 floats, 128 bytes, and a float, 24 bytes, each):
    # >= 15 MB, and with the dense coefficients about 50 MB (measured with dense_output=True).
    # Kept samples: 100 x ~150 bytes; the bound, 1 MB, leaves room for the solver's and the
    # compiler's working memory (measured: ~0.15 MB).
    eqs, x, k = oscillator()
    eqs.simulate(t=(0, 1), q0=[1.0], n_output=3, k=1.0)  # compile first
    tracemalloc.start()
    try:
        sim = eqs.simulate(t=(0, 100.0), q0=[1.0], method="bs32", max_step=1e-3,
                           n_output=100, rtol=1e-6, k=1.0)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert sim.result.nsteps >= 100_000
    assert sim.t.size == 100
    assert peak < 1_000_000, peak


# -- 5. save and load ---------------------------------------------------------------------
@pytest.mark.parametrize("ext", ["npz", "csv"])
def test_save_and_load(ext, tmp_path):
    # defect: results could not be saved except by pickling
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 1), q0=[1.0], u0=[0.5], n_output=11, k=4.0)
    path = sim.save(tmp_path / f"run.{ext}")
    back = load_simulation(path)
    assert isinstance(back, Simulation) and back.equations is None and back.result is None
    assert back.names == ("x",) and back.parameters == {"k": 4.0}
    assert back.status == "finished" and back.message == sim.message
    assert_allclose(back.t, sim.t, rtol=0, atol=0)
    assert_allclose(back.q, sim.q, rtol=0, atol=0)
    assert_allclose(back.u, sim.u, rtol=0, atol=0)
    with pytest.raises(ArgumentError, match="loaded from a file"):
        back.energy()


def test_csv_header_names_the_columns(tmp_path):
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 1), q0=[1.0], n_output=3, k=4.0)
    lines = (tmp_path / "r.csv").read_text() if sim.save(tmp_path / "r.csv") else ""
    assert lines.splitlines()[1] == "t [s],x,x_dot"
    assert len(lines.splitlines()) == 2 + 3


def test_save_refuses_an_unknown_extension(tmp_path):
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 1), q0=[1.0], n_output=3, k=4.0)
    with pytest.raises(ArgumentError, match=r"`path` must end in .npz or .csv"):
        sim.save(tmp_path / "r.txt")


# -- 6. honest diagnostics ----------------------------------------------------------------
def test_energy_drift_of_a_motion_at_rest_with_zero_energy():
    # defect: it read 1.000 for an exact run whose energy starts at 0
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 1), q0=[0.0], k=4.0)
    assert sim.energy_drift() == 0.0


def test_energy_drift_scale_is_T0_plus_abs_V0():
    # E = x'^2/2 + k x^2/2; with x0 = 1, x0' = 1, k = 4: T0 = 1/2, V0 = 2 (the equations know
    # no kinetic energy apart: the scale is |E(0)| = 5/2)
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 2), q0=[1.0], u0=[1.0], method="rk4", step=0.1, k=4.0)
    e = (sim.u[0] ** 2 + 4 * sim.q[0] ** 2) / 2
    assert sim.energy_scale() == pytest.approx(2.5, rel=1e-15)
    assert sim.energy_drift() == pytest.approx(np.max(np.abs(e - 2.5)) / 2.5, rel=1e-12)
    assert sim.energy_drift(scale=1.0) == pytest.approx(np.max(np.abs(e - 2.5)), rel=1e-12)
    with pytest.raises(ArgumentError, match=r"`scale` must be a finite number > 0"):
        sim.energy_drift(scale=0.0)


def test_energy_drift_scale_from_the_system():
    # a pendulum derived from a System knows T: scale = T(0) + |V(0)|, with V = E - T
    system, bob, R0, q = planar_pendulum()
    sim = system.equations_of_motion().simulate(t=(0, 1), q0=[0.5], u0=[1.0], **PLANAR)
    m, L, g, C = PLANAR["m"], PLANAR["L"], PLANAR["g"], PLANAR["C"]
    T0 = 0.5 * (m * L**2 + C) * 1.0**2
    V0 = -m * g * L * math.cos(0.5)          # gravity g R0.i, G = L R1.i
    assert sim.energy_scale() == pytest.approx(T0 + abs(V0), rel=1e-12)


def test_gbs_samples_are_as_accurate_as_its_steps():
    # defect: gbs's cubic samples reported an energy drift of 5e-2 for a run accurate to 1e-11
    system, bob, R0, q = planar_pendulum()
    eqs = system.equations_of_motion()
    sim = eqs.simulate(t=(0, 10), q0=[1.0], method="gbs", rtol=1e-12, atol=1e-12, **PLANAR)
    assert sim.energy_drift() < 1e-9


def test_fixed_step_samples_are_grid_points():
    # defect: rk4's drift was inflated 4.7x by a cubic interpolation of its grid
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 10), q0=[1.0], method="rk4", step=0.01, n_output=101, k=4.0)
    grid = rm.ode.solve(eqs.rhs(k=4.0), (0, 10), [1.0, 0.0], method="rk4", step=0.01)
    assert_allclose(sim.t, grid.t[::10], rtol=0, atol=1e-12)
    assert_allclose(sim.q[0], grid.y[0, ::10], rtol=0, atol=0)


@pytest.mark.parametrize("method", ["rk4", "verlet"])
def test_fixed_step_run_in_chunks_gives_the_same_numbers(method, monkeypatch):
    # a one-step method run chunk by chunk (memory ~ samples, Ctrl-C keeps the chunks done)
    # gives the grid of one run, to rounding of the grid times
    from rigidmech.dynamics import _run

    monkeypatch.setattr(_run, "CHUNK", 70)
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 10), q0=[1.0], method=method, step=0.01, n_output=101, k=4.0)
    fun = eqs.rhs(k=4.0) if method == "rk4" else (lambda tt, q: -4.0 * q)
    grid = rm.ode.solve(fun, (0, 10), [1.0, 0.0], method=method, step=0.01)
    assert sim.status == "finished"
    assert_allclose(sim.t, grid.t[::10], rtol=0, atol=1e-12)
    assert_allclose(sim.q[0], grid.y[0, ::10], rtol=0, atol=1e-13)
    assert sim.result.nsteps == 1000


def test_fixed_step_interrupted_keeps_the_chunks_done(monkeypatch):
    from rigidmech.dynamics import _run

    monkeypatch.setattr(_run, "CHUNK", 100)
    x = rm.coordinates("x")
    F = sp.Function("F")(t)
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-4 * x + F]]))

    def force(tt):
        if tt > 2.5:
            raise KeyboardInterrupt
        return 0.0

    sim = eqs.simulate(t=(0, 10), q0=[1.0], method="rk4", step=0.01, F=force)
    assert sim.status == "interrupted"
    # the chunks done and, since the driver keeps them (issue 15), the steps of the
    # interrupted chunk: the last step made ends at 2.5 (the next one calls F(2.505))
    assert sim.t_stop == pytest.approx(2.5) and sim.t[-1] == pytest.approx(2.5)
    assert_allclose(sim.q[0], np.cos(2 * sim.t), atol=1e-8)


def test_nan_in_the_right_hand_side_is_named():
    # defect: NaN in the right-hand side was reported as "step size underflow"
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[sp.sqrt(1 - x)]]))
    sim = eqs.simulate(t=(0, 5), q0=[0.0], u0=[1.0])   # x = t + ... reaches 1 before t = 1
    assert sim.status == "failed"
    assert "not finite (nan)" in sim.message and "x'' (acceleration of x)" in sim.message
    assert 0.5 < sim.t[-1] < 1.0


def test_complex_input_is_a_failure_that_keeps_the_motion():
    # defect: a complex right-hand side was silently truncated, one warning per step (here
    # refused by the compiled code: the error is named in the status, the motion kept)
    x = rm.coordinates("x")
    F = sp.Function("F")(t)
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[F]]))
    sim = eqs.simulate(t=(0, 1), q0=[0.0], F=lambda tt: 1.0 + (1j if tt > 0.5 else 0.0))
    assert sim.status == "failed"
    assert "could not be evaluated (ArgumentTypeError: argument `F`" in sim.message
    assert "got complex" in sim.message
    assert 0.4 < sim.t[-1] <= 0.5 + 1e-9
    assert_allclose(sim.q[0], sim.t**2 / 2, atol=1e-12)


@pytest.mark.parametrize("kind", ["callable", "expression"])
def test_an_event_returning_nan_is_a_failure(kind):
    # defect: an event function returning NaN was ignored
    eqs, x, k = oscillator()
    if kind == "callable":
        ev = rm.ode.event(lambda tt, y: math.nan if tt > 1.0 else y[0] - 2.0)
    else:
        ev = Event(sp.log(x + sp.Rational(1, 2)))       # log of a negative once x < -1/2
    sim = eqs.simulate(t=(0, 3), q0=[1.0], events=ev, k=4.0)
    assert sim.status == "failed"
    assert "The event function events[0] returned nan at t = " in sim.message
    assert "events may be missing" in sim.message
    assert sim.t[-1] == 3.0  # the motion itself is complete


def test_explicit_euler_growth_without_overflow_is_noted():
    # x'' = -k x with h^2 k = 1: explicit Euler multiplies the energy by 1 + h^2 k = 2 at each
    # step; over 200 steps E grows 2^200 (~1e60) times without overflow: finished, but noted
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 100), q0=[1.0], method="euler", step=0.5, k=4.0)
    assert sim.status == "finished"
    assert any("step is probably too large for 'euler'" in note for note in sim.notes)
    good = eqs.simulate(t=(0, 1), q0=[1.0], method="rk4", step=0.01, k=4.0)
    assert good.notes == ()


def test_fixed_step_larger_than_the_span_is_refused():
    # defect: it was shrunk silently to the span and the run called a success
    eqs, x, k = oscillator()
    with pytest.raises(ArgumentError, match=r"`step` = 2.0 exceeds the time span"):
        eqs.simulate(t=(0, 1), q0=[1.0], method="rk4", step=2.0, k=4.0)


def test_explicit_euler_blow_up_is_a_failure():
    # defect: an explicit Euler blow-up reported success. x'' = -k x with h sqrt(k) = 10:
    # each step multiplies the amplitude by sqrt(1 + h^2 k) ~ 10, overflow after ~300 steps
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 1000), q0=[1.0], method="euler", step=1.0, k=100.0)
    assert sim.status == "failed"
    assert "non-finite" in sim.message


# -- 7. reactions along the motion --------------------------------------------------------
PLANAR = {"m": 2.0, "L": 0.7, "g": 9.81, "C": 0.3}


def planar_pendulum():
    q = rm.coordinates("q")
    m, L, g, C = rm.constants("m L g C", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", L * R1.i)
    bob = rm.Body("bob", frame=R1, mass=m, centre=G,
                  inertia=rm.InertiaOperator.from_products(C, C, C, frame=R1, at=G))
    system = rm.System(galilean=R0)
    system.connect(R0, bob, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    system.act(rm.gravity(g * R0.i))
    return system, bob, R0, q


def test_reactions_along_a_planar_pendulum_follow_newton():
    system, bob, R0, q = planar_pendulum()
    m, L, g = (PLANAR[k] for k in ("m", "L", "g"))
    sim = system.equations_of_motion().simulate(t=(0, 3), q0=[2.0], rtol=1e-12, atol=1e-12,
                                                **PLANAR)
    action = sim.connection_action(R0, bob, basis=R0)
    # Newton for the mass centre G = L (cos q, sin q, 0), written here by hand:
    # m a(G) = m g i + R  ->  R = m a(G) - m g i, a(G) differentiated by sympy
    qq = sp.Symbol("qq")
    pos = sp.Matrix([L * sp.cos(q), L * sp.sin(q), 0])
    acc = pos.diff(t, 2)
    a = sim.evaluate(sp.ImmutableMatrix(acc))[:, 0]
    assert_allclose(action["X"], m * a[0] - m * g, atol=1e-8 * m * g)
    assert_allclose(action["Y"], m * a[1], atol=1e-8 * m * g)
    assert_allclose(action["Z"], 0.0, atol=1e-8 * m * g)
    # a perfect pivot about k transmits no moment about k
    assert_allclose(action["N"], 0.0, atol=1e-8 * m * g * L)
    del qq
    # the joint's own basis: same magnitude of the resultant
    own = sim.connection_action(R0, bob)
    assert_allclose(np.hypot(own["X"], own["Y"]), np.hypot(action["X"], action["Y"]),
                    rtol=1e-12)


def test_reactions_along_a_spherical_pendulum_follow_newton():
    # a rod of mass m, inertia diag(A, A, C) about G, hung from a ball joint at O, oriented by
    # Euler angles (z-x-z, ch. 9.1.2); G on the rod's axis at distance L from O: OG = -L R.k
    psi, theta, phi = rm.coordinates("psi theta phi")
    m, L, g, A, C = rm.constants("m L g A C", positive=True)
    R0 = rm.Frame("R0")
    R = R0.euler("R", psi, theta, phi)
    G = R0.origin.moved("G", -L * R.k)
    rod = rm.Body("rod", frame=R, mass=m, centre=G,
                  inertia=rm.InertiaOperator.from_products(A, A, C, frame=R, at=G))
    system = rm.System(galilean=R0)
    system.connect(R0, rod, rm.joints.Spherical(at=R0.origin))
    system.act(rm.gravity(-g * R0.k))
    values = {"m": 1.5, "L": 0.8, "g": 9.81, "A": 0.1, "C": 0.02}
    sim = system.equations_of_motion().simulate(t=(0, 2), q0=[0.0, 0.6, 0.0],
                                                u0=[2.5, 0.3, 4.0], rtol=1e-12, atol=1e-12,
                                                **values)
    action = sim.connection_action(R0, rod, basis=R0)
    # written by hand: R.k = (sin th sin psi, -sin th cos psi, cos th) in R0 (z-x-z)
    pos = -L * sp.Matrix([sp.sin(theta) * sp.sin(psi), -sp.sin(theta) * sp.cos(psi),
                          sp.cos(theta)])
    assert sp.simplify(pos - sp.Matrix(G.position.components(R0))) == sp.zeros(3, 1)
    a = sim.evaluate(sp.ImmutableMatrix(pos.diff(t, 2)))[:, 0]
    mv, gv = values["m"], values["g"]
    scale = mv * gv
    assert np.ptp(a[2]) > 1.0  # a genuinely 3-D motion
    assert_allclose(action["X"], mv * a[0], atol=1e-8 * scale)
    assert_allclose(action["Y"], mv * a[1], atol=1e-8 * scale)
    assert_allclose(action["Z"], mv * a[2] + mv * gv, atol=1e-8 * scale)
    for name in "LMN":  # a perfect ball joint transmits no moment at its centre
        assert_allclose(action[name], 0.0, atol=1e-8 * scale * values["L"])


def test_evaluate_a_point_velocity_along_the_motion():
    # G = L (cos q, sin q, 0) in R0: v(G) = L q' (-sin q, cos q, 0)
    system, bob, R0, q = planar_pendulum()
    sim = system.equations_of_motion().simulate(t=(0, 1), q0=[1.0], n_output=11, **PLANAR)
    v = sim.evaluate(bob.centre.velocity(R0), frame=R0)
    L = PLANAR["L"]
    assert_allclose(v, [-L * sim.u[0] * np.sin(sim.q[0]), L * sim.u[0] * np.cos(sim.q[0]),
                        0 * sim.t], atol=1e-14)
    with pytest.raises(TypeError, match=r"`frame` must be a Frame"):
        sim.evaluate(bob.centre.velocity(R0))


def test_connection_action_refuses_a_changed_system():
    system, bob, R0, q = planar_pendulum()
    sim = system.equations_of_motion().simulate(t=(0, 1), q0=[1.0], n_output=3, **PLANAR)
    system.act(rm.Couple(on=bob, moment=sp.Symbol("c") * R0.k))
    with pytest.raises(ArgumentError, match="`system` has changed"):
        sim.connection_action(R0, bob)


def test_connection_action_needs_a_system():
    eqs, x, k = oscillator()
    sim = eqs.simulate(t=(0, 1), q0=[1.0], n_output=3, k=4.0)
    with pytest.raises(ArgumentError, match="`system` is needed"):
        sim.connection_action(None, None)


# -- 5. CSV header with units -------------------------------------------------------------
def test_csv_header_gives_the_units_of_angles_and_those_the_user_passes(tmp_path):
    # a pendulum's angle q (a rotation of its frame: rad, rad/s) and a slider's x (unknown
    # to the model: the user says m)
    q, x = rm.coordinates("q x")
    m, g = sp.symbols("m g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    P = R0.origin.moved("P", x * R0.i)
    bob = rm.Body("bob", frame=R1, mass=m, centre=P.moved("G", R1.i))  # a point mass
    system = rm.System(galilean=R0)
    system.add(bob)
    system.act(rm.gravity(-g * R0.j))
    eqs = system.equations_of_motion()
    assert eqs.names == ("q", "x")
    sim = eqs.simulate(t=(0, 0.5), q0={"q": 0.1, "x": 0.0}, n_output=3, m=1.0, g=9.81)
    path = sim.save(tmp_path / "run.csv", units={"x": "m"})
    with open(path) as fh:
        header = fh.read().splitlines()[1].split(",")
    assert header == ["t [s]", "q [rad]", "x [m]", "q_dot [rad/s]", "x_dot [m/s]"]
    back = Simulation.load(path)
    assert back.names == sim.names and np.array_equal(back.q, sim.q)
    with pytest.raises(ArgumentError, match=r"`units` names \['y'\], which is not a "
                                            r"coordinate"):
        sim.save(tmp_path / "bad.csv", units={"y": "m"})
