"""
The benchmark bicycle: eigenvalues against speed, weave and capsize (ch. 25.3, 25.4)
====================================================================================

The Whipple bicycle of Meijaard, Papadopoulos, Ruina and Schwab (2007, *Proc. R. Soc. A* 463,
1955-1982): a rear frame with the rider, a front frame (fork and handlebar) turning about a
steer axis tilted back by :math:`\\lambda`, two knife-edge wheels rolling without slipping on
a horizontal plane -- four rolling conditions, not holonomic, and the front contact closing a
loop (ch. 10, 25.3.3). Its straight upright run at forward speed :math:`v` is a steady motion;
linearised about it, the roll :math:`\\varphi` and the steer :math:`\\delta` obey

.. math:: \\mathbf{M}\\ddot{\\mathbf{q}} + v\\,\\mathbf{C}_1\\dot{\\mathbf{q}}
          + (g\\,\\mathbf{K}_0 + v^2\\mathbf{K}_2)\\,\\mathbf{q} = \\mathbf{0},
          \\qquad \\mathbf{q} = (\\varphi, \\delta).

The free motions are :math:`e^{s t}`: the bicycle runs itself straight when every exponent
:math:`s` has a negative real part. The paper's Fig. 3 plots them against :math:`v`: below the
**weave speed** :math:`v_w` an oscillatory pair (weave) grows, above the **capsize speed**
:math:`v_c` a real exponent (capsize, a slow fall) turns positive; between them the bicycle is
self-stable. The paper gives :math:`v_w = 4.292382` m/s and :math:`v_c = 6.024262` m/s for
its benchmark parameters.

Conventions: x forward, y to the left, z up (the paper has y right, z down: the same roll, the
opposite steer -- eigenvalues do not depend on it); g = 9.81 m/s²; the benchmark values of the
25 parameters are the defaults of :func:`rigidmech.models.whipple_bicycle`, the model the
``benchmark-bicycle`` scene builds.
"""

# %%
# Derive and linearise once
# -------------------------
# The rear wheel's angle :math:`\\theta_R` rolls at :math:`v / r_R`; the pitch is eliminated
# by the front contact, the rates of the contact and of the front wheel by the rolling
# conditions, leaving the independent rates :math:`(\\dot\\varphi, \\dot\\delta,
# \\dot\\theta_R)`. The rear wheel's equation decouples (:math:`\\theta_R` is cyclic), adding
# a pair of zero exponents to the four of roll and steer.
import time

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

from rigidmech import models
from rigidmech.scenes.bicycle_scene import critical_speeds
from rigidmech.vibrations import critical_value, linearize

start = time.perf_counter()
bike = models.whipple_bicycle()
eqs = bike.system.equations_of_motion()
v = sp.Symbol("v")
g = 9.81
lin = linearize(eqs, velocities={"theta_R": v / models.BENCHMARK_BICYCLE["rR"]},
                parameters={"g": g}, independent=["phi", "delta", "theta_R"], simplify=False)
lin.eigenvalues(v=1.0)                       # compiles the matrices; later calls are floats
print(f"derived, linearised and compiled in {time.perf_counter() - start:.1f} s")

# %%
# The weave and capsize speeds
# ----------------------------
# :func:`rigidmech.vibrations.critical_value` brackets a change of stability and locates it
# by Brent's method on the largest real part of the exponents (its relative margin ``tol``
# keeps the two zero exponents of the rear wheel on the stable side and moves a transversal
# crossing by about 1e-7 m/s here).
weave = critical_value(lin, "v", (3.0, 5.0))
capsize = critical_value(lin, "v", (5.0, 8.0))
print(f"weave speed   v_w = {weave:.9f} m/s   (paper: 4.292382)")
print(f"capsize speed v_c = {capsize:.9f} m/s   (paper: 6.024262)")
assert abs(weave - 4.292382) < 1e-6
assert abs(capsize - 6.024262) < 1e-6

# %%
# An independent route: the paper's 2x2 matrices (roll and steer only, the rear wheel left
# out), their 4x4 state matrix, and the scene's own finder (Brent's method without margin).
M, C, K1, _ = lin.numeric(v=1.0)
K0 = lin.numeric(v=0.0)[2]
block = np.ix_([0, 1], [0, 1])
weave_2, capsize_2 = critical_speeds(M[block], C[block], K0[block] / g, (K1 - K0)[block], g)
print(f"from the 2x2 matrices: v_w = {weave_2:.9f}, v_c = {capsize_2:.9f} m/s")
assert abs(weave_2 - weave) < 2e-7 and abs(capsize_2 - capsize) < 2e-7
# self-stable in between (the rear wheel's zero pair within rounding), unstable either side
mid = lin.eigenvalues(v=0.5 * (weave + capsize))
assert mid.real.max() < 1e-9 * abs(mid).max()
assert lin.eigenvalues(v=weave - 0.05).real.max() > 1e-3
assert lin.eigenvalues(v=capsize + 0.05).real.max() > 1e-3

# %%
# Eigenvalues against speed (the paper's Fig. 3)
# ----------------------------------------------
# Real parts black, imaginary parts blue (each point of an oscillatory pair is drawn once,
# with its positive imaginary part); the two zero exponents of the rear wheel lie on the
# axis. The shaded band is the self-stable range.
speeds = np.linspace(0.0, 10.0, 201)
eig = np.array([np.sort_complex(lin.eigenvalues(v=s)) for s in speeds])
fig, ax = plt.subplots(figsize=(7, 5))
ax.plot(speeds, eig.real, "k.", markersize=2)
imag = np.where(eig.imag > 1e-9, eig.imag, np.nan)
ax.plot(speeds, imag, ".", color="tab:blue", markersize=2)
ax.plot([], [], "k.", label="Re s")
ax.plot([], [], ".", color="tab:blue", label="Im s (> 0)")
ax.axvspan(weave, capsize, color="0.9", zorder=0, label="self-stable")
for speed, name in ((weave, "$v_w$"), (capsize, "$v_c$")):
    ax.axvline(speed, color="k", linestyle="--", linewidth=0.8)
    ax.annotate(f"{name} = {speed:.4f} m/s", (speed, 9.0), rotation=90, ha="right",
                va="top", fontsize=8)
ax.axhline(0.0, color="k", linewidth=0.5)
ax.set_xlim(0.0, 10.0)
ax.set_ylim(-10.0, 10.0)
ax.set_xlabel("forward speed v [m/s]")
ax.set_ylabel("eigenvalue s [1/s]")
ax.set_title("Benchmark bicycle: eigenvalues against speed")
ax.legend(loc="lower right")
fig.tight_layout()
plt.show()
