"""Per-trajectory step sizes over a batch (``stepping="each"``) against single runs, a tight
reference and one step for all; bad input."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from rigidmech import ode
from rigidmech._core.errors import ArgumentError

PAIRS = ["dopri5", "dop853", "bs32"]


def pendulum(t, y):
    return np.stack([y[1], -np.sin(y[0])])


def double_pendulum(t, y):
    """Two point masses m = 1 on massless rods l = 1, g = 9.81 (absolute angles); any batch."""
    q1, q2, u1, u2 = y
    d = q1 - q2
    c, s = np.cos(d), np.sin(d)
    den = 2.0 - c * c
    a1 = (-s * (u2 * u2 + c * u1 * u1) - 9.81 * (2.0 * np.sin(q1) - c * np.sin(q2))) / den
    a2 = (s * (2.0 * u1 * u1 + c * u2 * u2) + 9.81 * (2.0 * np.sin(q1) * c - 2.0 * np.sin(q2))
          ) / den
    return np.stack([u1, u2, a1, a2])


def ensemble(amplitude, size, seed=3):
    rng = np.random.default_rng(seed)
    q = rng.uniform(-amplitude, amplitude, (2, size))
    return np.concatenate([q, np.zeros((2, size))])


ANGLES = np.array([0.1, 1.0, 2.0, 3.0])
Y0 = np.stack([ANGLES, np.zeros_like(ANGLES)])
T_EVAL = np.linspace(0.0, 8.0, 9)


@pytest.mark.parametrize("method", PAIRS)
def test_each_equals_the_same_controller_on_one_column(method):
    # a batch of one with one step for all IS the single-trajectory controller on the array
    # path: every column of "each" takes exactly its steps (equal to rounding)
    rb = ode.solve(pendulum, (0.0, 8.0), Y0, method=method, t_eval=T_EVAL, rtol=1e-8,
                   atol=1e-11, stepping="each")
    assert rb.stats["stepping"] == "each" and rb.y.shape == (2, 9, 4)
    for j in range(Y0.shape[1]):
        rj = ode.solve(pendulum, (0.0, 8.0), Y0[:, j:j + 1], method=method, t_eval=T_EVAL,
                       rtol=1e-8, atol=1e-11, stepping="shared")
        assert rb.stats["nsteps_each"][j] == rj.nsteps
        assert rb.stats["nrejected_each"][j] == rj.nrejected
        assert_allclose(rb.y[:, :, j], rj.y[:, :, 0], rtol=1e-12, atol=1e-13)


@pytest.mark.parametrize("method", PAIRS)
@pytest.mark.parametrize("rtol", [1e-6, 1e-9])
def test_each_trajectory_meets_its_own_tolerance(method, rtol):
    # against single runs of the same method and a tight reference: every member's error is
    # that of its single run (within a factor 10 + 10 rtol of slack for the different order
    # of the floating-point sums), and of the order of rtol
    atol = rtol * 1e-3
    rb = ode.solve(pendulum, (0.0, 8.0), Y0, method=method, t_eval=T_EVAL, rtol=rtol,
                   atol=atol)
    assert rb.stats["stepping"] == "each"  # the default with t_eval
    for j in range(Y0.shape[1]):
        ref = ode.solve(pendulum, (0.0, 8.0), Y0[:, j], method="dop853", t_eval=T_EVAL,
                        rtol=1e-13, atol=1e-15).y
        single = ode.solve(pendulum, (0.0, 8.0), Y0[:, j], method=method, t_eval=T_EVAL,
                           rtol=rtol, atol=atol).y
        err_b, err_s = np.abs(rb.y[:, :, j] - ref).max(), np.abs(single - ref).max()
        assert err_b <= 10 * err_s + 10 * rtol
        assert err_b <= 1e3 * rtol


def test_chaotic_ensemble_one_step_for_all_costs_more_than_each():
    # double pendulum released within +-2.5 rad: the hardest member sets the shared step,
    # so one step for all evaluates every column far more often than each column needs
    y0 = ensemble(2.5, 24)
    kw = dict(method="dop853", t_eval=[0.0, 2.5, 5.0], rtol=1e-8, atol=1e-10)
    each = ode.solve(double_pendulum, (0.0, 5.0), y0, stepping="each", **kw)
    shared = ode.solve(double_pendulum, (0.0, 5.0), y0, stepping="shared", **kw)
    assert each.status == 0 and shared.status == 0
    steps = each.stats["nsteps_each"]
    assert steps.max() >= 1.5 * steps.min()  # the members need very different work
    assert shared.nsteps > steps.max()  # the shared step is below every member's own
    # column evaluations: shared pays every step for every member
    assert shared.nfev * y0.shape[1] >= 1.5 * each.stats["nfev_columns"]
    # and every member is correct to its tolerance (tight reference, chaos amplifies: 1e-5)
    for j in range(0, y0.shape[1], 6):
        ref = ode.solve(double_pendulum, (0.0, 5.0), y0[:, j], method="dop853",
                        t_eval=[0.0, 2.5, 5.0], rtol=1e-13, atol=1e-14).y
        assert_allclose(each.y[:, :, j], ref, atol=1e-5)


def test_members_finish_at_different_step_counts():
    # member 0 rests at the bottom (f = 0: 9 steps), members 1 and 2 swing (330 and 390
    # steps): the active set shrinks as members finish and the others go on unchanged
    y0 = np.array([[0.0, 0.5, 3.1], [0.0, 0.0, 0.0]])
    rb = ode.solve(pendulum, (0.0, 20.0), y0, method="dopri5", t_eval=[20.0], rtol=1e-9,
                   atol=1e-12)
    steps = rb.stats["nsteps_each"]
    assert steps[0] < 20 < 300 < min(steps[1], steps[2]) and steps[1] != steps[2]
    assert rb.stats["nfev_columns"] < rb.nfev * 3  # the finished columns were not evaluated
    for j in range(3):
        rj = ode.solve(pendulum, (0.0, 20.0), y0[:, j:j + 1], method="dopri5",
                       t_eval=[20.0], rtol=1e-9, atol=1e-12, stepping="shared")
        assert_allclose(rb.y[:, -1, j], rj.y[:, -1, 0], rtol=1e-12, atol=1e-13)
    assert np.all(rb.stats["t_stop_each"] == 20.0) and rb.t_stop == 20.0


def test_time_is_given_per_column_to_a_non_autonomous_fun():
    seen = []

    def forced(t, y):
        seen.append(np.shape(t))
        return np.stack([y[1], -y[0] + np.cos(2.0 * t)])

    y0 = np.array([[1.0, 0.0, -1.0], [0.0, 1.0, 0.5]])
    rb = ode.solve(forced, (0.0, 6.0), y0, t_eval=[3.0, 6.0], rtol=1e-10, atol=1e-12)
    assert (3,) in seen
    for j in range(3):
        rj = ode.solve(forced, (0.0, 6.0), y0[:, j], t_eval=[3.0, 6.0], rtol=1e-12,
                       atol=1e-14)
        assert_allclose(rb.y[:, :, j], rj.y, atol=1e-8)


def test_backwards_and_pi_control():
    y0 = Y0[:, :3]
    for kw in ({"step_control": "pi"}, {}):
        rb = ode.solve(pendulum, (5.0, 0.0), y0, t_eval=[5.0, 2.0, 0.0], rtol=1e-9,
                       atol=1e-12, stepping="each", **kw)
        for j in range(3):
            rj = ode.solve(pendulum, (5.0, 0.0), y0[:, j], t_eval=[5.0, 2.0, 0.0],
                           rtol=1e-12, atol=1e-14)
            assert_allclose(rb.y[:, :, j], rj.y, atol=1e-7)


def test_without_t_eval_each_returns_both_ends_and_auto_keeps_the_steps():
    rb = ode.solve(pendulum, (0.0, 2.0), Y0, stepping="each")
    assert rb.t.tolist() == [0.0, 2.0] and rb.y.shape == (2, 2, 4)
    assert_allclose(rb.y[:, 0, :], Y0)
    shared = ode.solve(pendulum, (0.0, 2.0), Y0)  # auto without t_eval: the shared steps
    assert "stepping" not in shared.stats and len(shared.t) > 2


def test_dense_output_keeps_one_step_for_all():
    r = ode.solve(pendulum, (0.0, 1.0), Y0, t_eval=[0.5, 1.0], dense_output=True)
    assert "stepping" not in r.stats and r.sol(0.25).shape == (2, 4)


def test_one_failing_member_leaves_the_others_complete():
    def blows_up(t, y):  # y' = y^2 from y0 = 1 reaches infinity at t = 1
        return y * y

    y0 = np.array([[0.1, 1.0, 0.2]])
    r = ode.solve(blows_up, (0.0, 2.0), y0, t_eval=[0.5, 2.0], stepping="each")
    assert r.status == -1 and r.stats["failed_members"] == [1]
    assert "Batch member 1" in r.message and "1 of 3" in r.message
    assert np.isnan(r.y[0, 1, 1]) and r.y[0, 0, 1] == pytest.approx(2.0, rel=1e-5)
    for j, y in ((0, 0.1), (2, 0.2)):
        assert r.y[0, -1, j] == pytest.approx(y / (1 - 2.0 * y), rel=1e-5)


def test_progress_stops_each_run():
    calls = []
    r = ode.solve(pendulum, (0.0, 5.0), Y0, t_eval=[5.0], stepping="each",
                  progress=lambda t: calls.append(t) or len(calls) < 3)
    assert r.status == 2 and len(calls) == 3 and "unfinished" in r.message


def test_max_steps_per_member():
    r = ode.solve(pendulum, (0.0, 50.0), Y0, t_eval=[50.0], stepping="each",
                  max_steps=40, rtol=1e-10)
    assert r.status == -1 and "max_steps" in r.message
    assert r.stats["nsteps_each"].max() == 40


def test_bad_stepping():
    with pytest.raises(ArgumentError, match=r"`stepping` must be one of .*got 'per'"):
        ode.solve(pendulum, (0.0, 1.0), Y0, stepping="per")
    with pytest.raises(ArgumentError, match=r"`stepping`=\"each\".*dense_output=True"):
        ode.solve(pendulum, (0.0, 1.0), Y0, stepping="each", dense_output=True)
    with pytest.raises(ArgumentError, match=r"`stepping`=\"each\".*project"):
        ode.solve(pendulum, (0.0, 1.0), Y0, stepping="each", project=lambda t, y: y)
    with pytest.raises(ArgumentError, match="`stepping` is not an option of method 'rk4'"):
        ode.solve(pendulum, (0.0, 1.0), Y0, method="rk4", step=0.1, stepping="each")


def test_a_fun_bound_to_the_columns_is_told_to_share_the_step():
    k = np.array([1.0, 4.0, 9.0, 16.0])  # one stiffness per member: breaks on compaction

    def spring(t, y):
        return np.stack([y[1], -k * y[0]])

    with pytest.raises(ArgumentError, match=r"stepping=\"shared\""):
        ode.solve(spring, (0.0, 20.0), Y0, t_eval=[20.0], stepping="each")
    r = ode.solve(spring, (0.0, 20.0), Y0, t_eval=[20.0], stepping="shared")
    assert r.status == 0
