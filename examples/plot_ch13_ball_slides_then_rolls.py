"""
A ball that slides, then rolls (ch. 13.1, 23)
=============================================

A solid ball of radius r is launched on a rough horizontal plane with the velocity v0 and the
spin omega0. The contact with the plane is a :class:`~rigidmech.actions.FrictionContact`
with Coulomb's law: the System knows the bodies and the contact, and
:func:`rigidmech.regimes.contact_motion` derives each regime itself. While the ball slides,
the friction ``-mu N v_s/|v_s|`` opposes the **sliding velocity** v_s = v(I in ball/R0), not the
velocity of the centre; it slows the sliding down until v_s = 0 at ``t* = 2 |v_s(0)| / (7 mu g)``,
and then the ball rolls without slipping (the contact sticks). Launched without spin, it
rolls on at 5/7 of v0.
"""

# %%
# The ball and its contact
# ------------------------
import math

import matplotlib.pyplot as plt
import numpy as np

from rigidmech import models
from rigidmech.regimes import contact_motion

# the catalogue's ball (rigidmech.models.sliding_ball): centre C = (x, y, z), orientation by
# the rotations a (about i), b (about the new j), c (about the new k); a FrictionContact with
# Coulomb's law at I = (x, y, z - r), normal k, and gravity -g k
mu = 0.3
model = models.sliding_ball(mu)
system = model.system

# %%
# Launched without spin, then with a spin across the velocity
# -----------------------------------------------------------
values = dict(m=1.0, r=0.5, g=9.81)
plain = contact_motion(system, 0.4, {"z": 0.5}, {"x": 1.0}, rtol=1e-12, **values)
spun = contact_motion(system, 0.4, {"z": 0.5}, {"x": 1.0, "a": 3.0}, rtol=1e-12, **values)
print(plain)
print("t* =", plain.switch_times[0], " closed form 2 v0 / (7 mu g) =", 2 / (7 * mu * 9.81))
print("rolling speed =", plain.phases[-1].y_end[6], " closed form 5/7 v0 =", 5 / 7)
print(spun)

# %%
# The path of the centre: straight without spin, a parabola while the spun ball slides
# (the friction keeps its direction, across the velocity), straight again once it rolls.
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.5))
for motion, label in ((plain, "no spin"), (spun, "spin about i")):
    ts = np.linspace(0, 0.4, 200)
    states = motion(ts)
    ax1.plot(states[0], states[1], label=label)
    speed = np.hypot(states[6], states[7])
    ax2.plot(ts, speed, label=label)
    for s in motion.switch_times:
        ax2.axvline(s, color="0.6", linestyle=":")
ax1.set_xlabel("x"), ax1.set_ylabel("y"), ax1.set_aspect("equal"), ax1.legend()
ax2.set_xlabel("t"), ax2.set_ylabel("speed of the centre"), ax2.legend()
ax1.set_title("centre's path"), ax2.set_title("slides, then rolls")
fig.tight_layout()
plt.show()

assert math.isclose(plain.phases[-1].y_end[6], 5 / 7, abs_tol=1e-9)
