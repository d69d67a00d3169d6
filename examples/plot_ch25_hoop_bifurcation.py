"""
Bead on a rotating hoop: equilibria and their bifurcation (ch. 20, 25)
======================================================================

A bead of mass m slides without friction on a hoop of radius R that turns at the constant
rate Omega about its vertical diameter. The rotation is imposed: the hoop's frame turns by
the given angle Omega t, which is not a parameter of situation, so the System has one degree
of freedom, the angle theta of the bead from the bottom. Its equilibria in the turning hoop
are theta = 0, theta = pi and, once Omega^2 > g/R, the pair cos(theta) = g/(R Omega^2): the
bottom loses its stability exactly there (a pitchfork bifurcation).
"""

# %%
# The system, its equilibria in closed form
# -----------------------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigidmech as rm
from rigidmech.vibrations import bifurcation, equilibria, linearize

theta = rm.coordinates("theta")
m, R, g, Omega = rm.constants("m R g Omega", positive=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=Omega * rm.t)      # the hoop, turning at Omega
R2 = R1.rotated("R2", about=R1.j, angle=theta)             # the bead's radius
system = rm.System(galilean=R0)
system.add(rm.Body("bead", frame=R2, mass=m, centre=R0.origin.moved("P", -R * R2.k)))
system.act(rm.gravity(-g * R0.k))
eqs = system.equations_of_motion()

print([e["theta"] for e in equilibria(eqs)])
print("stiffness about the bottom:", linearize(eqs).K[0])

# %%
# The bifurcation diagram
# -----------------------
# Numerically, for R = 0.5 m: the equilibria in (-pi, pi) and their stability for a range of
# Omega; filled markers are stable.
values = np.linspace(0.3, 2.0, 60) * np.sqrt(9.81 / 0.5)
diagram = bifurcation(eqs, "Omega", values, within=(-3.1, 3.1), m=1.0, R=0.5, g=9.81)
fig, ax = plt.subplots(figsize=(7, 4))
diagram.plot("theta", ax=ax)
ax.axvline(np.sqrt(9.81 / 0.5), color="k", lw=0.8, ls="--")
ax.set_title("equilibria of the bead; dashed: Omega^2 = g/R")
fig.tight_layout()
