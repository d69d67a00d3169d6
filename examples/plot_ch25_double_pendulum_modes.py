"""
Natural modes of the double pendulum (ch. 25.4.3, 27.5.2)
=========================================================

Two uniform rods of mass m and length L, hanging from a pivot and from each other. We
linearise the equations of motion about the hanging equilibrium: M and K come out symbolic,
the natural frequencies and mode shapes follow from det(K - w^2 M) = 0 in closed form, and we
draw each mode as the pendulum swinging in it.
"""

# %%
# Linearisation and modes, symbolically
# -------------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

from rigidmech import models
from rigidmech.vibrations import linearize

# the catalogue's double pendulum (rigidmech.models.double_pendulum): absolute angles theta1,
# theta2 from the downward vertical i0, uniform rods, gravity g i0
model = models.double_pendulum()
system = model.system
theta1, theta2 = model.coordinates
m, L, g = model.constants

lin = linearize(system.equations_of_motion())
print(lin.M)
print(lin.K)
modes = lin.modes()
print([sp.simplify(w**2) for w in modes.frequencies])
print(modes.shapes)

# %%
# The two modes drawn
# -------------------
# L = 1 m, g = 9.81 m/s^2: each panel shows the rods at the extreme positions of a small
# oscillation in one mode (amplitudes exaggerated), the first rod's amplitude set to 0.3 rad.
numeric = lin.modes(m=1.0, L=1.0, g=9.81)
fig, axes = plt.subplots(1, 2, figsize=(8, 4.5), sharey=True)
for r, ax in enumerate(axes):
    shape = numeric.shapes[:, r] / numeric.shapes[0, r] * 0.3
    for sign, style in ((1, "C0-o"), (-1, "C1-o")):
        a1, a2 = sign * shape
        x = [0.0, np.sin(a1), np.sin(a1) + np.sin(a2)]
        y = [0.0, -np.cos(a1), -np.cos(a1) - np.cos(a2)]
        ax.plot(x, y, style, lw=2)
    ax.set_title(f"mode {r + 1}: w = {numeric.frequencies[r]:.3f} rad/s, "
                 f"theta2/theta1 = {shape[1] / shape[0]:+.3f}", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlim(-1.3, 1.3)
    ax.grid(True, alpha=0.3)
fig.tight_layout()
