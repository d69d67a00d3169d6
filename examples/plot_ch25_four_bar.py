"""
Four-bar linkage and its coupler curve (ch. 13.2, 25.3)
=======================================================

Three uniform rods -- the crank OB, the coupler BC and the rocker DC -- joined by four pivots
to each other and to the ground OD: the connections form a **loop**. The first three pivots
make a tree (each with its own angle q1, q2, q3); the fourth, at C, closes the loop and links
the three angles by two conditions (the coupler's C and the rocker's C coincide). We count the
degree of mobility and of hyperstaticity (ch. 13.2), assemble the linkage, let it move under
gravity -- the equations carry Lagrange multipliers for the closing pivot -- and trace the
curve drawn by a point of the coupler.
"""

# %%
# The linkage
# -----------
import matplotlib.pyplot as plt
import numpy as np

from rigidmech import models

# the catalogue's four-bar (rigidmech.models.four_bar): crank R1 (q1), coupler R2 (q2,
# relative to the crank) pivoted at B, rocker R3 (q3) pivoted at D = (L0, 0); the pivot at C
# closes the loop: the coupler's C meets the rocker's C3
L0, L1, L2, L3 = 2.0, 1.0, 2.0, 1.5          # ground, crank, coupler, rocker
model = models.four_bar(lengths=(L0, L1, L2, L3))
system = model.system
q1, q2, q3 = model.coordinates
m, g = model.constants
R0, R1, R2, R3 = model.frames
B = model.point("B")
k = R0.k
for label, _, phi in system.closure_conditions():
    print(label, ":", phi, "= 0")

# %%
# Mobility and hyperstaticity
# ---------------------------
# As a plane mechanism the linkage is isostatic (h = 0); in space its four parallel pivots
# over-constrain it (h = 3: the axial forces and transverse moments are undetermined).
print(system.mobility(plane=k))
print(system.mobility())

# %%
# Motion under gravity
# --------------------
# The crank angle is the independent parameter; ``assemble`` solves the loop for q2, q3 and
# their rates. The closure residual stays at the level of the integration tolerance
# (Baumgarte's stabilisation).
eqs = system.equations_of_motion()
q0, u0 = system.assemble({"q1": 1.0, "q2": -0.6, "q3": 1.4}, independent=["q1"],
                         rates={"q1": 3.0}, m=1.0, g=9.81)
sim = eqs.simulate(t=(0, 10), q0=q0, u0=u0, m=1.0, g=9.81, n_output=2001, rtol=1e-10,
                   atol=1e-10)
residual = max(np.abs(sim.evaluate(phi)).max() for _, _, phi in system.closure_conditions())
print(f"closure residual {residual:.1e}, energy drift {sim.energy_drift():.1e}")

# %%
# Coupler curve
# -------------
# The point P of the coupler, at mid-length and 0.6 off its line, draws the coupler curve.
P = B.moved("P", L2 / 2 * R2.i + 0.6 * R2.j)
xP = sim.evaluate(P.coordinates(R0)[0])
yP = sim.evaluate(P.coordinates(R0)[1])
fig, ax = plt.subplots(figsize=(6, 4.5))
ax.plot(xP, yP, lw=1.2, label="coupler point P")
for i in (0, 300):
    q = sim.q[:, i]
    xb, yb = L1 * np.cos(q[0]), L1 * np.sin(q[0])
    xc, yc = xb + L2 * np.cos(q[0] + q[1]), yb + L2 * np.sin(q[0] + q[1])
    ax.plot([0, xb, xc, L0], [0, yb, yc, 0], "o-", color="0.4" if i else "k", lw=2)
ax.set_aspect("equal")
ax.set_xlabel("x")
ax.set_ylabel("y")
ax.set_title("Four-bar linkage under gravity: coupler curve")
ax.legend(loc="lower right")
plt.show()
