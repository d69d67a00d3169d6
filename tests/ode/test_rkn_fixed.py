"""The constant step of the Runge-Kutta-Nystrom pairs (direct calls with ``step=h``) on the
fixed-step loop: progress, non-finite states, evaluations, events on the quintic dense output."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from rigidmech.ode import rkn


def test_events_on_the_quintic_dense_output():
    # q'' = -q, q(0) = 1: q = cos t crosses 0 at pi/2 (downwards) and 3 pi/2; with h = 0.01 the
    # step's error is ~h^7 and the quintic interpolant's O(h^6) ~ 1e-12
    def g(t, y):
        return y[0]

    r = rkn.rkn64(lambda t, q: -q, (0.0, 5.0), [1.0, 0.0], step=0.01, events=g)
    assert_allclose(r.t_events[0], [math.pi / 2, 3 * math.pi / 2], atol=1e-10)
    assert r.status == 0 and r.sol is None  # dense output only when asked for
    g.terminal = True
    r = rkn.rkn64(lambda t, q: -q, (0.0, 5.0), [1.0, 0.0], step=0.01, events=g)
    assert r.status == 1 and r.t[-1] == pytest.approx(math.pi / 2, abs=1e-10)
    assert r.t_stop == r.t[-1]


@pytest.mark.parametrize(("method", "per_step"), [(rkn.rkn64, 5), (rkn.rkn1210, 17)])
def test_evaluations_and_progress(method, per_step):
    seen = []
    r = method(lambda t, q: -q, (0.0, 1.0), [1.0, 0.0], step=0.1)
    assert r.nsteps == 10 and r.nfev == 1 + per_step * 10 and r.t[-1] == 1.0
    r = method(lambda t, q: -q, (0.0, 1.0), [1.0, 0.0], step=0.1,
               progress=lambda t: seen.append(t) or len(seen) < 3)
    assert r.status == 2 and len(r.t) == 4 and r.t_stop == pytest.approx(0.3)
    assert_allclose(r.y[:, -1], [math.cos(0.3), -math.sin(0.3)], atol=1e-12)


def test_non_finite_state_ends_with_the_last_finite_one():
    # q'' = 6 q^2, q(0) = 1, q'(0) = 2: q = 1 / (1 - t)^2 (q' = 2 / (1 - t)^3) blows up at
    # t = 1; the steps overflow to inf or nan soon after
    r = rkn.rkn64(lambda t, q: 6.0 * q * q, (0.0, 3.0), [1.0, 2.0], step=0.25)
    assert r.status == -1 and "non-finite" in r.message
    assert np.all(np.isfinite(r.y)) and r.t[-1] < 3.0


def test_step_rules_are_those_of_solve():
    # one validation: a step longer than the span is refused, as by solve for fixed steps
    with pytest.raises(ValueError, match="exceeds the time span"):
        rkn.rkn64(lambda t, q: -q, (0.0, 1.0), [1.0, 0.0], step=2.0)
