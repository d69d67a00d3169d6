"""
Foucault pendulum (ch. 19, 24)
==============================

A bob of mass m on a rod of length L hangs at a point O of the Earth, at the latitude
lambda. The reference R0 = (O; east, north, up) at t = 0 is taken as Galilean and the Earth
turns relative to it at the rate Omega about the polar axis; the pendulum's two angles are
measured relative to the Earth. Released at rest relative to the Earth, the bob swings in a
plane that turns relative to the ground at -Omega sin(lambda): clockwise seen from above in
the northern hemisphere. The Earth's rate (7.3e-5 rad/s) is exaggerated here to
Omega = 0.05 rad/s, so that the plane turns by a visible angle in 60 s.

The scene is ``foucault-pendulum`` of the catalogue (``python -m rigidmech run
foucault-pendulum``).
"""

# %%
# The motion
# ----------
import math

import matplotlib.pyplot as plt
import numpy as np

from rigidmech import scenes

scene = scenes.get("foucault-pendulum")
params = scene.defaults
print(scene.notes)
eqs = scene.build().system.equations_of_motion()
sim = eqs.simulate(t=(0.0, 60.0), q0=scene.q0, u0=scene.u0, params=params, rtol=1e-10,
                   atol=1e-12, n_output=12001)
alpha, beta = sim.q
east, north = -np.sin(beta), np.sin(alpha) * np.cos(beta)      # in units of L

# %%
# The rate of the swing plane, measured
# -------------------------------------
# At each turning point (largest distance from the vertical) the azimuth of the bob, taken
# modulo pi, is fitted by a straight line in time.
r2 = east**2 + north**2
i = np.where((r2[1:-1] > r2[:-2]) & (r2[1:-1] >= r2[2:]))[0] + 1
phi = np.unwrap(2 * np.arctan2(north[i], east[i])) / 2
rate = np.polyfit(sim.t[i], phi, 1)[0]
expected = -params["Omega"] * math.sin(params["lat"])
print(f"measured {rate:.6f} rad/s, -Omega sin(lat) = {expected:.6f} rad/s")

# %%
# The trace of the bob seen from above
# ------------------------------------
fig, ax = plt.subplots(figsize=(5.5, 5.5))
ax.plot(east, north, lw=0.5, color="tab:blue")
ax.plot(east[i], north[i], ".", ms=3, color="tab:red", label="turning points")
ax.set_aspect("equal")
ax.set_xlabel("east / L")
ax.set_ylabel("north / L")
ax.set_title(f"Foucault pendulum, latitude {math.degrees(params['lat']):.0f} N, "
             f"Omega = {params['Omega']} rad/s, 60 s")
ax.legend(loc="lower right")
plt.show()
