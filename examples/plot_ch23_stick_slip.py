"""
Dry friction: a stick-slip oscillator, phase by phase (ch. 21.4)
================================================================

A mass m on a spring k slides on a rough floor (Coulomb, f_s >= f_k, normal force N). While it
slides the friction :math:`\\mp f_k N` opposes the velocity, so each half-cycle is a half
oscillation of period :math:`\\pi/\\omega` about :math:`x = \\pm f_k N/k`, and the amplitude
decreases **linearly**, by :math:`4 f_k N / k` per cycle. When the velocity vanishes the mass
sticks if the spring cannot overcome static friction, :math:`|k x| \\le f_s N`.

:func:`rigidmech.regimes.coulomb_oscillator` integrates the motion regime by regime
(``slide+``, ``slide-``, ``stick``), the events of :func:`rigidmech.ode.solve` locating the
instants where the velocity vanishes; the phases are printed and plotted.
"""

# %%
# The phases
# ----------
import math

import matplotlib.pyplot as plt
import numpy as np

from rigidmech.actions import Coulomb
from rigidmech.regimes import coulomb_oscillator

m, k, N = 1.0, 4.0, 2.0
law = Coulomb(static=0.12, kinetic=0.1)
motion = coulomb_oscillator(mass=m, stiffness=k, friction=law, normal_force=N, x0=1.0,
                            t_end=20.0)
print(motion)
omega = math.sqrt(k / m)
print("switches at multiples of pi/omega:",
      np.round(np.array(motion.switch_times) / (math.pi / omega), 12))

# %%
# Position and the linear envelope
# --------------------------------
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
motion.plot(ax1, component=0, label="x")
t = np.linspace(0, motion.phases[-1].start, 200)
envelope = 1.0 - 4 * float(law.kinetic) * N / k * t / (2 * math.pi / omega)
ax1.plot(t, envelope, "k--", linewidth=0.8)
ax1.plot(t, -envelope, "k--", linewidth=0.8, label="1 - 4 f_k N t / (k T)")
band = float(law.static) * N / k
ax1.axhspan(-band, band, color="0.9", zorder=0)
motion.plot(ax2, component=1, label="x'")
plt.tight_layout()
plt.show()
