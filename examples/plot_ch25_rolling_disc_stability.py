"""
Stability of a coin rolling upright (ch. 10.1.3, 25.3, 25.4)
============================================================

A thin uniform disc of radius r rolls without slipping, upright, in a straight line at speed
v: a steady motion. Its rolling constraints are not holonomic, so before linearising we
eliminate the multipliers and the speeds of the contact point, keeping the heading psi, the
lean theta and the spin phi as independent parameters (the reduced form M_r u' = f_r,
ch. 25.3). The linearised equations about the steady motion have a gyroscopic damping matrix
C proportional to the spin rate; the upright motion is stable when

.. math:: v^2 > \\frac{A\\, m g r^3}{C\\,(C + m r^2)} = \\frac{g r}{3}

(A = m r²/4 about a diameter, C = m r²/2 about the axis).
"""

# %%
# The disc, reduced and linearised
# --------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

from rigidmech import models
from rigidmech.vibrations import linearize

# the catalogue's disc (rigidmech.models.rolling_disc): heading psi, lean theta (pi/2 is
# upright), spin phi; the contact point (x, y, 0) and the normal of the table given
model = models.rolling_disc(contact="given")
system = model.system
x, y, psi, theta, phi = model.coordinates
m, g, r = model.constants
eqs = system.equations_of_motion()

Omega = sp.Symbol("Omega")                             # spin rate: v = -r Omega along x
lin = linearize(eqs, about={"theta": sp.pi / 2}, velocities={"phi": Omega},
                independent=["psi", "theta", "phi"])
print("M =", lin.M)
print("C =", lin.C)
print("K =", lin.K)
print("rates of the steady motion:", lin.velocities)

# %%
# Eigenvalues against the speed
# -----------------------------
# Below the critical speed a pair of eigenvalues is real, one positive: the coin falls.
# Above it the pair is purely imaginary: the lean oscillates (the other eigenvalues are zero:
# heading, spin and the cyclic coordinates).
values = {"m": 0.01, "g": 9.81, "r": 0.02}
speeds = np.linspace(0.05, 0.6, 120)
eig = np.array([lin.eigenvalues(Omega=-v / values["r"], **values) for v in speeds])
v_crit = np.sqrt(values["g"] * values["r"] / 3)
fig, ax = plt.subplots(figsize=(7, 4))
ax.plot(speeds, eig.real.max(axis=1), label="largest real part")
ax.plot(speeds, np.abs(eig.imag).max(axis=1), label="largest imaginary part")
ax.axvline(v_crit, color="k", ls="--", label=r"$v = \sqrt{g r / 3}$")
ax.set_xlabel("speed v [m/s]")
ax.set_ylabel("eigenvalue [1/s]")
ax.legend()
ax.set_title("Coin rolling upright: stability vs speed")
plt.show()

# %%
# The nonlinear motion on both sides
# ----------------------------------
# Started upright with a small lean rate (0.05 rad/s), at 0.8 and 1.25 times the critical
# speed, the multiplier form integrated: below, the lean grows at the rate the positive
# eigenvalue gives until the motion is no longer small (the coin swerves, rights itself and
# leans again); above, it stays within a few milliradians.
fig, ax = plt.subplots(figsize=(7, 4))
for factor in (0.8, 1.25):
    v = factor * v_crit
    q0 = [0.0, 0.0, 0.0, np.pi / 2, 0.0]
    u0 = [v, 0.0, 0.0, 0.05, -v / values["r"]]
    sim = eqs.simulate(t=(0, 1.5), q0=q0, u0=u0, n_output=601, rtol=1e-10, atol=1e-12,
                       **values)
    ax.plot(sim.t, sim.q[3] - np.pi / 2, label=f"v = {factor} v_crit")
ax.set_xlabel("t [s]")
ax.set_ylabel("lean from upright [rad]")
ax.legend()
plt.show()
