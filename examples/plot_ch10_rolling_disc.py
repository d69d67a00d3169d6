"""
A coin rolling on a table (ch. 10.1.3, 20, 25.3)
================================================

A thin uniform disc of radius r rolls without slipping on the horizontal plane of R0. Its
parameters are the coordinates (x, y) of the contact point, the heading psi, the
inclination theta of the disc's axis from the vertical (rotation about the line of nodes:
theta = pi/2 for an upright disc, 0 for a disc lying flat) and the spin phi. The
condition "without slipping", v(I in disc/R0) = 0, links the speeds and is **not
holonomic**: it cannot be written between the parameters. rigidmech keeps it as two
velocity constraints and writes the equations of motion with two Lagrange multipliers (the
tangential components of the contact action); they give the same accelerations as Kane's
method with dependent speeds.
"""

# %%
# The disc and its rolling contact
# --------------------------------
import matplotlib.pyplot as plt
import numpy as np

from rigidmech import models

# The disc is the catalogue's rolling disc (rigidmech.models.rolling_disc): frames A (heading
# psi about k), B (lean theta about the line of nodes A.i), D (spin phi about B.k), the contact
# point I0 = (x, y, 0), the centre G = I0 + r B.j, in the disc's plane; its rolling contact is
# a RollingContact given the contact point and the normal k of the table.
model = models.rolling_disc(contact="given")
system = model.system
x, y, psi, theta, phi = model.coordinates
m, g, r = model.constants
for label, condition, _ in system.closure_conditions():
    print(label, ":", condition, "= 0")
print(system.mobility())

# %%
# Motion
# ------
# Started leaning a little (theta = 1.3 rad, upright being pi/2) with a spin and a heading
# rate, the coin rolls on a curve while it precesses; the speeds of x and y follow from the
# constraints.
eqs = system.equations_of_motion()
values = {"m": 0.01, "g": 9.81, "r": 0.02}
q0, u0 = system.assemble({"x": 0.0, "y": 0.0, "psi": 0.0, "theta": 1.3, "phi": 0.0},
                         independent=["psi", "theta", "phi"],
                         rates={"psi": 4.0, "phi": -20.0}, **values)
sim = eqs.simulate(t=(0, 4), q0=q0, u0=u0, n_output=2001, rtol=1e-10, atol=1e-12, **values)
slip = max(np.abs(sim.evaluate(c)).max() for _, c, _ in system.closure_conditions())
print(f"largest sliding speed {slip:.1e} m/s, energy drift {sim.energy_drift():.1e}")

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 4))
ax1.plot(sim.q[0], sim.q[1])
ax1.set_aspect("equal")
ax1.set_xlabel("x [m]")
ax1.set_ylabel("y [m]")
ax1.set_title("trace of the contact point")
ax2.plot(sim.t, sim.q[3])
ax2.set_xlabel("t [s]")
ax2.set_ylabel("theta [rad]")
ax2.set_title("lean")
fig.tight_layout()
plt.show()
