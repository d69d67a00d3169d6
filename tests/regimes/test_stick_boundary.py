"""Sticking holds while |T| <= f_s N (ch. 13.1.2), one rule wherever contact_motion decides it
(issue 19 sweep): at the start, when a sliding velocity vanishes, and for a couple held by a
rolling resistance, to 1e-12 relative (the rounding of the multipliers). Tested at the
boundary and at +-1e-12 and +-1e-6 relative, with the motion continuous across it.

The block (m = 1, g = 1, N = 1, spring k = 1 of zero free length, f = 0.15) released at rest
at x0 sticks while k |x0| <= f N = 0.15.
"""

import friction_block
import pytest

from rigidmech.actions import Coulomb
from rigidmech.regimes import contact_motion

LIMIT = 0.15


def block():
    return friction_block.block(LIMIT)


@pytest.mark.parametrize("factor, regime", [(1.0, "stick"), (1 - 1e-12, "stick"),
                                            (1 + 1e-12, "stick"), (1 - 1e-6, "stick"),
                                            (1 + 1e-6, "slip-")])
def test_start_sticks_while_within_the_cone(factor, regime):
    """At the start, 'slips' was decided by |T| > f_s N exactly while the stop of a slip
    used |T| <= f_s N (1 + 1e-12): x0 = 0.15 (1 + 1e-12) slipped at the start, and would
    have stuck at a stop."""
    x0 = LIMIT * factor
    m = contact_motion(block(), 1.0, {"x": x0, "y": 0.0}, rtol=1e-12, progress=False)
    assert m.regimes[0] == regime
    # the motion is continuous across the boundary: beyond it by 1e-6, the block slides
    # by about (x0 - 0.15) (1 - cos t) ~ 1e-7 over 1 s
    assert abs(m(1.0)[0] - x0) < 1e-6


@pytest.mark.parametrize("factor, regime", [(1.0, "stick"), (1 + 1e-12, "stick"),
                                            (1 - 1e-6, "stick"), (1 + 1e-6, "slide-")])
def test_hand_written_oscillator_uses_the_same_rule(factor, regime):
    """coulomb_oscillator (the hand-written regimes contact_motion is checked against) decided
    |k x| <= f_s N exactly: x0 = 0.15 (1 + 1e-12) slid there and stuck in contact_motion."""
    from rigidmech.regimes import coulomb_oscillator

    m = coulomb_oscillator(mass=1.0, stiffness=1.0, friction=Coulomb(LIMIT), normal_force=1.0,
                           x0=LIMIT * factor, t_end=1.0)
    assert m.regimes[0] == regime
