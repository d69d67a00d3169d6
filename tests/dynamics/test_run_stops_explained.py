"""A run that stops says why, and keeps what it reached (issue 19, the items the first
sweep left): the spring or damper whose ends meet, named with the instant; ``q0_given``
written by ``save`` and read back; a method that keeps no partial result interrupted by
Ctrl-C keeps the last state it reached, not only the initial one."""

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm


def _block_on_a_line(action):
    """A block at (x, 0, 0) tied to the origin by `action(a, b, on_b)`."""
    x = rm.coordinates("x")
    R0 = rm.Frame("R0")
    P = R0.point("P", x, 0, 0)
    block = rm.Body("block", frame=R0.translated("R1", P), mass=1, centre=P)
    s = rm.System(galilean=R0)
    s.add(block)
    s.act(action(R0.origin, P, block))
    return s.equations_of_motion()


def test_a_spring_whose_ends_meet_is_named_with_the_instant():
    """Spring of free length 1 between O and P = (x, 0, 0): its force -k (l - l0) AB / l is
    0/0 where x = 0. Started there, the run fails at t = 0 and says so (it said only "the
    right-hand side is not finite at t = 0.0")."""
    eqs = _block_on_a_line(lambda a, b, on_b: rm.Spring(4, 1, a=a, b=b, on_b=on_b))
    sim = eqs.simulate(t=(0, 1), q0=[0.0], u0=[1.0])
    assert sim.status == "failed"
    assert "Spring" in sim.message and "O_R0" in sim.message and "P" in sim.message
    assert "meet" in sim.message and "t = 0.0" in sim.message


def test_a_damper_whose_ends_meet_is_named_with_the_instant():
    """A damper's force -c (AB . AB') AB / l^2 is 0/0 where its ends meet: a block at
    P = (x, y, 0) in a plane, tied to O, started at x = y = 0 (on a line the factor x x' / x^2
    would cancel)."""
    x, y = rm.coordinates("x y")
    R0 = rm.Frame("R0")
    P = R0.point("P", x, y, 0)
    block = rm.Body("block", frame=R0.translated("R1", P), mass=1, centre=P)
    s = rm.System(galilean=R0)
    s.add(block)
    s.act(rm.actions.Damper(2, a=R0.origin, b=P, on_b=block))
    sim = s.equations_of_motion().simulate(t=(0, 1), q0=[0.0, 0.0], u0=[1.0, 0.5])
    assert sim.status == "failed"
    assert "Damper" in sim.message and "meet" in sim.message and "t = 0.0" in sim.message


def test_a_spring_of_free_length_zero_is_not_blamed():
    """k AB has no 0/0: a spring of free length 0 whose ends meet runs on (x = cos 2t)."""
    eqs = _block_on_a_line(lambda a, b, on_b: rm.Spring(4, 0, a=a, b=b, on_b=on_b))
    sim = eqs.simulate(t=(0, 1), q0=[0.0], u0=[2.0], rtol=1e-10, atol=1e-12)
    assert sim.status == "finished"
    assert sim.q[0, -1] == pytest.approx(np.sin(2.0), abs=1e-8)


def _loop_equations():
    from rigidmech.dynamics import Constraints

    x, y = rm.coordinates("x y")
    phi = x**2 + y**2 - 1
    return rm.EquationsOfMotion(
        coordinates=(x, y), mass_matrix=sp.eye(2), forcing=sp.Matrix([0, -1]),
        constraints=Constraints((x, y), [("circle", phi.diff(rm.t), phi)]))


@pytest.mark.parametrize("suffix", [".npz", ".csv"])
def test_save_writes_the_initial_state_given(tmp_path, suffix):
    """q0 = (0.6, 1.0) is off the circle: y is moved to 0.8; the values given are kept by
    the simulation and, now, by its file."""
    sim = _loop_equations().simulate(t=(0, 0.5), q0=[0.6, 1.0], u0=[0.0, 0.0], n_output=3)
    assert sim.q0_given.tolist() == [0.6, 1.0]
    back = rm.dynamics.Simulation.load(sim.save(tmp_path / f"run{suffix}"))
    assert back.q0_given.tolist() == [0.6, 1.0]
    assert back.u0_given.tolist() == [0.0, 0.0]


def test_a_run_with_nothing_moved_reads_back_the_initial_state_given(tmp_path):
    sim = _loop_equations().simulate(t=(0, 0.5), q0=[0.6, 0.8], n_output=3)
    back = rm.dynamics.Simulation.load(sim.save(tmp_path / "run.npz"))
    assert back.q0_given.tolist() == sim.q0_given.tolist()


def _euler(fun, t_span, y0, *, step, progress=None, **options):
    """Explicit Euler, catching nothing (a user's method: keeps no partial result)."""
    t0, t1 = t_span
    y, t = np.asarray(y0, dtype=float), float(t0)
    ts, ys = [t], [y]
    while t < t1 - 1e-12:
        y = y + step * np.asarray(fun(t, y))
        t = t + step
        ts.append(t)
        ys.append(y)
    return rm.ode.OdeResult(t=np.array(ts), y=np.array(ys).T, nfev=len(ts), nsteps=len(ts),
                            nrejected=0, status=0, message="done", method="euler-user",
                            t_stop=t, y_stop=y)


@pytest.fixture
def user_euler():
    from rigidmech.ode import _registry

    _registry.register("euler-user", _euler, kind="fixed")
    yield "euler-user"
    _registry.unregister("euler-user")


def test_ctrl_c_in_a_method_keeping_nothing_keeps_the_last_state_reached(user_euler):
    """x'' = -x + F(t) with F raising KeyboardInterrupt for t > 2 (as Ctrl-C would); the
    user's Euler method lets it through. The run kept only (t0, y0); it keeps now the last
    state the method evaluated the right-hand side at, which for Euler is its last step:
    t = 2.0 (step 0.25) and the Euler values there (computed independently here)."""
    x = rm.coordinates("x")
    F = sp.Function("F")(rm.t)
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-x + F]]))

    def force(t):
        if t > 2.0:
            raise KeyboardInterrupt
        return 0.0

    sim = eqs.simulate(t=(0, 4), q0=[1.0], method=user_euler, step=0.25, F=force)
    y = np.array([1.0, 0.0])
    for _ in range(8):   # Euler to t = 2
        y = y + 0.25 * np.array([y[1], -y[0]])
    assert sim.status == "interrupted"
    assert sim.t[0] == 0.0 and sim.t[-1] == sim.t_stop == 2.0
    assert sim.q[0, -1] == pytest.approx(y[0], abs=1e-15)
    assert sim.u[0, -1] == pytest.approx(y[1], abs=1e-15)
    assert "t = 2.0" in sim.message
