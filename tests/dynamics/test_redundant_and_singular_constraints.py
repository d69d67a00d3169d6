"""Redundant closure conditions and singular configurations of a loop are reported with
where they happen (issue 19, sweep): a connection whose conditions repeat others (a second
pivot at the same place of a four-bar) makes the augmented matrix [[M, A^T], [A, 0]]
singular at every configuration; a four-bar with its three bars aligned loses the rank of
its constraint Jacobian A there. Neither is a singular mass matrix.

Reference: the four-bar's Jacobian rows (C.u, C.v) have the minors 2.1 sin(q1 + q2 - q3)
and 2.1 sin(q1 + q2 - q3) + 0.6 sin(q1 - q3): both vanish at q = (0, 0, 0).
"""

import numpy as np
import pytest
from test_connection_action_along_loops import L0, L1, L2, L3, four_bar

import rigidmech as rm
from rigidmech import models
from rigidmech.errors import ConnectionError_, SingularMassMatrixError


def test_a_repeated_closure_is_refused_naming_its_conditions():
    s, (crank, coupler, rocker), R0 = four_bar()
    B, D = coupler.frame.origin, rocker.frame.origin
    s.connect(coupler, rocker, rm.joints.Pivot(at=B.moved("C2", L2 * coupler.frame.i),
                                                axis=R0.k),
              meets=D.moved("C4", L3 * rocker.frame.i), label="C2")
    with pytest.raises(ConnectionError_, match=r"C2\.u, C2\.v depend on the other closure "
                                               r"conditions .*hyperstatic.*mobility\(\)"):
        s.equations_of_motion()


def test_aligned_bars_name_the_constraint_jacobian():
    # rocker 0.7 instead of 1.0: the aligned state q = 0 is then on the loop (crank + coupler
    # = ground + rocker = 2.7), as multipliers() requires, and the Jacobian's rank drops there
    s = models.four_bar(lengths=(L0, L1, L2, L1 + L2 - L0)).system
    with pytest.raises(SingularMassMatrixError, match=r"constraint Jacobian A .* rank 1 < 2 "
                                                      r".*conditions 4\.u, 4\.v"):
        s.multipliers(np.zeros(3), np.zeros(3), m=1.0, g=9.81)


def test_aligned_bars_off_the_loop_are_refused_as_off_the_constraints():
    s, _, _ = four_bar()                     # q = 0 leaves C 0.3 short of the rocker's end
    with pytest.raises(rm.errors.ArgumentError, match=r"not on the constraints .*C\.u = 0\.3"):
        s.multipliers(np.zeros(3), np.zeros(3))


def test_a_regular_state_still_gives_multipliers():
    s, _, _ = four_bar()
    q0, u0 = s.assemble({"q1": 1.0, "q2": -0.6, "q3": 1.4}, independent=["q1"])
    assert np.all(np.isfinite(s.multipliers(list(q0.values()), list(u0.values()))))
