"""
Frequency response of a damped oscillator (ch. 21.3.3)
======================================================

A block of mass m on a spring k, with a viscous damper c to the wall and a harmonic force
F cos(w t). We build it the book's way, linearise the equations of motion (here they are
linear already: the linearisation returns M, C, K and the input column B of the force), and
draw the amplitude and phase lag of the steady response against the frequency for three
damping ratios. The closed forms of ch. 21.3.3 -- resonance peak, half-power frequencies --
are marked on the curves.
"""

# %%
# The system and its linear equations
# -----------------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigidmech as rm
from rigidmech.actions import Damper
from rigidmech.vibrations import (
    damping_ratio,
    half_power_frequencies,
    linearize,
    natural_frequency,
    plot_frequency_response,
    resonance,
)

x = rm.coordinates("x")
m, k, c, F = rm.constants("m k c F", positive=True)
R0 = rm.Frame("R0")
R1 = R0.translated("R1", R0.point("P", x, 0, 0))
block = rm.Body("block", frame=R1, mass=m)
system = rm.System(galilean=R0)
system.connect(R0, block, rm.joints.Prismatic(at=R1.origin, axis=R0.i))
system.act(rm.Spring(k, 0, a=R0.origin, b=R1.origin, on_b=block))
system.act(Damper(c, a=R0.point("A", -1, 0, 0), b=R1.origin, on_b=block))
system.act(rm.Force(on=block, vector=F * R0.i, at=R1.origin))

lin = linearize(system.equations_of_motion(), inputs=["F"])
print(lin.M, lin.C, lin.K, lin.B)

# %%
# Amplitude and phase for three damping ratios
# --------------------------------------------
# m = 1 kg, k = 100 N/m: w0 = 10 rad/s. The amplitude is that of x for a unit force.
omega = np.linspace(0.5, 25, 600)
fig, axes = plt.subplots(2, 1, sharex=True, figsize=(8, 6), layout="constrained")
for c_value in (0.5, 2.0, 6.0):
    values = {"m": 1.0, "k": 100.0, "c": c_value}
    zeta = damping_ratio(c_value, 100.0, 1.0)
    H = lin.frequency_response(omega, input="F", **values)
    plot_frequency_response(omega, H, labels=[f"zeta = {zeta:.3f}"], ax=axes, unit="m/N")
    w0 = natural_frequency(100.0, 1.0)
    wr, Xr = resonance(w0, zeta, static_deflection=1 / 100.0)
    axes[0].plot([wr], [Xr], "k.")
    if zeta < 0.38:
        w1, w2 = half_power_frequencies(w0, zeta)
        axes[0].plot([w1, w2], [Xr / np.sqrt(2)] * 2, "k|-", lw=0.8)
axes[0].set_title("steady response of m x'' + c x' + k x = F cos(w t), per unit force")
