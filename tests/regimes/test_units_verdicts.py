"""The regimes' decisions in other units (issue 19, one relative rule per decision): the
friction block of friction_block.py (m = 1, N = m g, spring k = 1 of zero free length,
f = 0.15) written in metres and in millimetres (lengths x 1000, g x 1000: every force x 1000)
gets the same regimes, and motions equal up to the factor 1000. The start's "sliding velocity
is zero" was 1e-12 (|q'| + 1) in the units of q': a speed of 1e-13 m/s stuck in metres and
slid in millimetres (1e-10 mm/s)."""

import friction_block
import pytest

from rigidmech.regimes import contact_motion

LIMIT = 0.15


def block(unit):
    return friction_block.block(LIMIT, g=unit)


def _runs(x0, v0):
    out = []
    for unit in (1.0, 1000.0):
        out.append(contact_motion(block(unit), 2.0, {"x": unit * x0, "y": 0.0},
                                  {"x": unit * v0, "y": 0.0}, rtol=1e-12, progress=False))
    return out


@pytest.mark.parametrize("factor", [1.0, 1 - 1e-6, 1 + 1e-6, 2.0])
def test_stick_or_slip_at_the_start_in_m_and_mm(factor):
    m_run, mm_run = _runs(LIMIT * factor, 0.0)
    assert m_run.regimes == mm_run.regimes
    assert mm_run(2.0)[0] == pytest.approx(1000.0 * m_run(2.0)[0], rel=1e-8, abs=1e-9)


@pytest.mark.parametrize("v0", [1e-13, 1e-3])
def test_a_slow_start_is_the_same_regime_in_m_and_mm(v0):
    m_run, mm_run = _runs(0.0, v0)
    assert m_run.regimes[0] == mm_run.regimes[0] == "slip+"
    assert m_run.regimes == mm_run.regimes
