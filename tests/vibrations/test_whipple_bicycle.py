"""The Whipple bicycle benchmark (Meijaard, Papadopoulos, Ruina and Schwab 2007, Proc. R. Soc.
A 463): a rear frame, a front frame (fork and handlebar) on a tilted steer axis, two knife-edge
wheels rolling without slipping on a horizontal plane. Linearised about the straight upright
run at speed v, the equations on (roll phi, steer delta) are
M q'' + v C1 q' + (g K0 + v^2 K2) q = 0 with the matrices published in the paper (its
benchmark parameters, g = 9.81 m/s^2). Posed here with a System: eight parameters (rear
contact x, y, yaw psi, roll phi, pitch theta, steer delta, wheel angles theta_R, theta_F),
four rolling conditions and the front contact (a loop closed by a point contact), reduced to
the independent speeds (phi', delta', theta_R') and linearised with the pitch eliminated; the
model is the catalogue's :func:`rigidmech.models.whipple_bicycle`.

Conventions: x forward, y to the left, z up (the paper: y right, z down). The roll angle has
the same sense, the steer angle the opposite one (its axis points up here), so the paper's
matrices compare after S = diag(1, -1): M = S M_paper S.
"""

import numpy as np
import pytest
import scipy.optimize
import sympy as sp

from rigidmech import models
from rigidmech.vibrations import linearize

# Meijaard et al. (2007), benchmark matrices (eq. (A 3)-(A 5) values of the paper)
M_PAPER = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1_PAPER = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0_PAPER = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2_PAPER = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])
S = np.diag([1.0, -1.0])
G = 9.81


def whipple_bicycle():
    """The catalogue's bicycle with the paper's benchmark parameters (their defaults)."""
    model = models.whipple_bicycle()
    return model.system.equations_of_motion(), models.BENCHMARK_BICYCLE["rR"]


def _critical_speeds(M, C1, K0, K2):
    def eig(v):
        Mi = np.linalg.inv(M)
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Mi @ (G * K0 + v**2 * K2), -v * Mi @ C1]])
        return np.linalg.eigvals(A)

    def weave(v):
        ev = eig(v)
        return ev[np.abs(ev.imag) > 1e-6].real.max()

    def capsize(v):
        ev = eig(v)
        return ev[np.abs(ev.imag) < 1e-9].real.max()

    return (scipy.optimize.brentq(weave, 4.0, 4.5, xtol=1e-14),
            scipy.optimize.brentq(capsize, 5.5, 6.5, xtol=1e-14))


@pytest.mark.slow
def test_whipple_bicycle_benchmark_matrices_and_critical_speeds():
    eqs, rR = whipple_bicycle()
    assert len(eqs.constraints) == 5 and not eqs.constraints.holonomic
    v = sp.Symbol("v")
    lin = linearize(eqs, velocities={"theta_R": v / rR}, parameters={"g": G},
                    independent=["phi", "delta", "theta_R"], simplify=False)
    assert lin.velocities["x"] == v and lin.velocities["theta"] == 0
    assert lin.parameters == (v,)
    M1, C1, K1, _ = lin.numeric(v=1.0)      # compiled once (tests/vibrations/test_linear_numeric)
    num = {"M": M1, "C": C1}
    K0 = lin.numeric(v=0.0)[2]
    K2 = K1 - K0
    ours = [num["M"][:2, :2], num["C"][:2, :2], K0[:2, :2] / G, K2[:2, :2]]
    for X, Y in zip(ours, (M_PAPER, C1_PAPER, K0_PAPER, K2_PAPER), strict=True):
        np.testing.assert_allclose(X, S @ Y @ S, rtol=1e-11, atol=1e-11)
    # the rear wheel's speed decouples: its equation is free of roll and steer
    assert num["M"][2, 0] == num["M"][2, 1] == 0 and not np.any(num["C"][2]) and not np.any(K2[2])
    weave, capsize = _critical_speeds(*ours)
    paper_weave, paper_capsize = _critical_speeds(M_PAPER, C1_PAPER, K0_PAPER, K2_PAPER)
    assert weave == pytest.approx(paper_weave, rel=1e-10)
    assert capsize == pytest.approx(paper_capsize, rel=1e-10)
    assert weave == pytest.approx(4.292, abs=5e-4) and capsize == pytest.approx(6.024, abs=5e-4)
    # through the library's own eigenvalues: unstable weave just below, stable just above
    assert lin.eigenvalues(v=weave - 0.01).real.max() > 1e-4
    assert lin.eigenvalues(v=0.5 * (weave + capsize)).real.max() < 1e-9
    assert lin.eigenvalues(v=capsize + 0.01).real.max() > 1e-5
