"""A phased run that stops early keeps what it computed (issue 19, item 17): the finished
phases and the part of the phase under way, when a later phase fails or the run is
interrupted (Ctrl-C, the progress callback); progress shown like ``simulate``.

Reference: the block on a spring (k = m = 1, zero free length) on a rough floor (f = 0.15,
N = m g = 1) released at x = 1: half-cycles of pi, slip- then slip+ then slip- then stick at
3 pi (the doctest of contact_motion), the motion in each half-cycle x = c + a cos t.
"""

import math

import friction_block
import numpy as np
import pytest

from rigidmech._core.errors import NumericalError
from rigidmech.regimes import Guard, Regime, contact_motion, integrate_phases


def block():
    return friction_block.block(0.15)


@pytest.fixture
def every_step(monkeypatch):
    from rigidmech.dynamics import _run

    monkeypatch.setattr(_run, "PROGRESS_EVERY", 0.0)   # the callback at every step


@pytest.mark.parametrize("how", ["returns False", "raises KeyboardInterrupt"])
def test_contact_motion_interrupted_keeps_its_phases(every_step, how):
    """Stopped at t > 4 (in the second half-cycle, pi < t < 2 pi): the first phase, finished,
    and the second up to the time reached are kept, status 'interrupted' (it was a
    NumericalError 'phase 2 failed', every phase lost)."""
    seen = []

    def progress(t):
        seen.append(t)
        if t > 4.0:
            if how == "returns False":
                return False
            raise KeyboardInterrupt
        return True

    m = contact_motion(block(), 20.0, {"x": 1.0, "y": 0.0}, rtol=1e-12, progress=progress)
    assert m.status == "interrupted" and "t = " in m.message
    assert m.regimes == ("slip-", "slip+")
    assert m.phases[0].end == pytest.approx(math.pi, abs=1e-9)
    assert m.phases[1].ended_by == "interrupted" and 4.0 < m.phases[1].end < 2 * math.pi
    # the second half-cycle, sliding towards +x (friction -f N): x'' = -x - 0.15 from
    # x(pi) = -0.7 at rest, so x = -0.15 - 0.55 cos(t - pi)
    t_end = m.phases[1].end
    x_exact = -0.15 - 0.55 * math.cos(t_end - math.pi)
    assert m(t_end)[0] == pytest.approx(x_exact, abs=1e-8)
    assert m.phases[1].y_end[0] == pytest.approx(x_exact, abs=1e-8)
    assert seen[0] < math.pi < seen[-1]            # one progress over the whole span


def test_contact_motion_finished_status():
    m = contact_motion(block(), 12.0, {"x": 1.0, "y": 0.0}, rtol=1e-12, progress=False)
    assert m.status == "finished" and m.regimes == ("slip-", "slip+", "slip-", "stick")


def test_integrate_phases_failure_keeps_the_finished_phases():
    """A fall to the ground, then a regime whose right-hand side becomes nan at t > 1.5: the
    NumericalError carries the motion: the fall (finished, lands at 1) and the rest up to the
    last state reached."""
    fall = Regime("fall", lambda t, y: np.array([y[1], -10.0]),
                  [Guard("lands", lambda t, y: y[0], target="slide", direction=-1,
                         reset=lambda t, y: [0.0, 1.0])])
    slide = Regime("slide", lambda t, y: np.array([y[1], 0.0 if t <= 1.5 else np.nan]))
    with pytest.raises(NumericalError, match=r"phase 2 \(slide\) failed") as info:
        integrate_phases([fall, slide], "fall", (0.0, 3.0), [5.0, 0.0], rtol=1e-12)
    m = info.value.motion
    assert m.status == "failed" and m.regimes == ("fall", "slide")
    assert m.phases[0].end == pytest.approx(1.0, abs=1e-12) and m.phases[0].ended_by == "lands"
    assert m.phases[1].ended_by == "failed" and 1.0 < m.phases[1].end <= 1.5
    assert m.phases[1].y_end[0] == pytest.approx(m.phases[1].end - 1.0, abs=1e-9)
