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
from test_connection_action_along_loops import L2, L3, four_bar

import rigidmech as rm
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
    s, _, _ = four_bar()
    with pytest.raises(SingularMassMatrixError, match=r"constraint Jacobian A .* rank 1 < 2 "
                                                      r".*C\.u, C\.v"):
        s.multipliers(np.zeros(3), np.zeros(3))


def test_a_regular_state_still_gives_multipliers():
    s, _, _ = four_bar()
    q0, u0 = s.assemble({"q1": 1.0, "q2": -0.6, "q3": 1.4}, independent=["q1"])
    assert np.all(np.isfinite(s.multipliers(list(q0.values()), list(u0.values()))))
