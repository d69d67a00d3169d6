"""
Pendulum in an accelerating wagon (ch. 19, 24)
==============================================

A bob of mass m on a rod of length L hangs at a point O of a wagon whose acceleration a is
constant. The system is written in the wagon's reference, which is not Galilean:
``System(galilean=R0, reference=Rw)`` adds the inertial action of entrainment, -m a, to the
bob. The bob has a relative equilibrium, leaning backwards at tan(theta*) = -a/g, found from
the equations by :func:`rigidmech.vibrations.equilibria`; released at rest along the vertical
it swings about that position. Relative to the wagon, T + V with the potential of the inertial
action is conserved, and the energy balance of the run stays at the level of the solver's
tolerance.

The scene is ``wagon-pendulum`` of the catalogue (``python -m rigidmech run wagon-pendulum``).
"""

# %%
# The relative equilibrium and the motion
# ---------------------------------------
import math

import matplotlib.pyplot as plt

from rigidmech import scenes
from rigidmech.vibrations import equilibria

scene = scenes.get("wagon-pendulum")
params = scene.defaults
eqs = scene.build().system.equations_of_motion()
theta_star = equilibria(eqs, within=(-1.5, 1.5), **params)[0]["theta"]
print(f"theta* = {theta_star:.10f}, -atan(a/g) = {-math.atan(params['a'] / params['g']):.10f}")
sim = eqs.simulate(t=(0.0, 6.0), q0=scene.q0, u0=scene.u0, params=params, rtol=1e-11,
                   atol=1e-12, n_output=3001)
print(f"energy drift {sim.energy_drift():.2e}")

# %%
# The angle and the energy balance
# --------------------------------
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
ax1.plot(sim.t, sim.q[0], label="theta")
ax1.axhline(theta_star, color="tab:red", ls="--", label="relative equilibrium")
ax1.set_ylabel("theta [rad]")
ax1.legend(loc="lower right")
ax2.plot(sim.t, sim.energy_balance())
ax2.set_ylabel("E - E0 - W [J]")
ax2.set_xlabel("t [s]")
ax1.set_title(f"Pendulum in a wagon accelerating at a = {params['a']} m/s²")
plt.show()
