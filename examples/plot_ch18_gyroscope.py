"""
The gyroscope: precession of a fast top (ch. 18, 20)
====================================================

A symmetric top of mass m spins fast about its axis on a ball joint at O (no friction), its
mass centre G on the axis at OG = l, its moments of inertia A about the transverse axes
through G and C about its axis, gravity :math:`-g\\,\\mathbf{k}_0`. Euler angles (ch. 9.4.4):
:math:`\\psi` precession about the vertical, :math:`\\theta` nutation (the axis from the upward
vertical), :math:`\\varphi` spin; :math:`A_O = A + m l^2` about the transverse axes through O.

The moment equation at O (the fundamental principle, ch. 18) admits **steady precessions**:
:math:`\\theta` constant, :math:`\\dot\\psi = \\Omega` and :math:`\\dot\\varphi` constant, when

.. math:: (A_O - C)\\cos\\theta\\,\\Omega^2 - C\\dot\\varphi\\,\\Omega + m g l = 0,

whose slow root is, for a fast spin, the gyroscope's precession rate
:math:`\\Omega \\approx m g l / (C \\omega)` (:math:`\\omega = \\dot\\varphi + \\dot\\psi
\\cos\\theta`, the spin about the axis; ch. 20): the weight's moment turns the angular
momentum :math:`C\\omega` about the vertical instead of tipping the axis. Released with
:math:`\\dot\\psi = 0` the axis dips a little and nods (the nutation) while it precesses at
that rate on average: the pseudo-regular precession.

The system is the ``gyroscope`` scene's: the catalogue's :func:`rigidmech.models.heavy_top`
with m = 1 kg, g = 9.81 m/s², l = 0.1 m, A = 0.006 kg m², C = 0.01 kg m², spin 200 rad/s,
the axis at 1.5 rad from the vertical.
"""

# %%
# The steady precession: library and closed form
# ----------------------------------------------
import math

import matplotlib.pyplot as plt
import numpy as np

from rigidmech import scenes
from rigidmech.vibrations import steady_motions

scene = scenes.get("gyroscope")
values = scene.defaults
m, g, l, A, C = (values[k] for k in ("m", "g", "l", "A", "C"))
theta0, spin = scene.q0[1], scene.u0[2]
eqs = scene.build().system.equations_of_motion()

found = steady_motions(eqs, fixed={"theta": theta0}, cyclic={"psi": None, "phi": spin},
                       within={"psi": (0.01, 2.0)}, **values)
Omega = found[0].rates["psi"]
A_O = A + m * l**2
a2, a1, a0 = (A_O - C) * math.cos(theta0), -C * spin, m * g * l
Omega_closed = (-a1 - math.sqrt(a1**2 - 4 * a2 * a0)) / (2 * a2)       # the slow root
omega = spin + Omega * math.cos(theta0)
Omega_fast_top = m * g * l / (C * omega)
print(f"steady_motions: Omega = {Omega:.12f} rad/s")
print(f"closed form:    Omega = {Omega_closed:.12f} rad/s")
print(f"fast top m g l / (C omega) = {Omega_fast_top:.12f} rad/s")
assert len(found) == 1 and abs(Omega - Omega_closed) < 1e-10
assert abs(Omega_fast_top - Omega) < 1e-3 * Omega

# %%
# Simulated: started on the steady precession, and released
# ---------------------------------------------------------
# Started with :math:`\dot\psi = \Omega`, the axis keeps its angle and precesses uniformly;
# released with :math:`\dot\psi = 0` (the scene's state), its axis dips and nods, and it
# precesses at the same rate on average.
t_end = scene.t_end
steady = eqs.simulate(t=(0, t_end), q0=scene.q0, u0=(Omega, 0.0, spin), rtol=1e-11,
                      atol=1e-12, n_output=2001, **values)
released = eqs.simulate(t=(0, t_end), q0=scene.q0, u0=scene.u0, rtol=1e-11, atol=1e-12,
                        n_output=2001, **values)
psi_s, theta_s = steady.q[0], steady.q[1]
assert np.abs(theta_s - theta0).max() < 1e-8
assert np.abs(psi_s - Omega * steady.t).max() < 1e-8
mean_rate = released.q[0, -1] / t_end
dip = released.q[1] - theta0                 # > 0: the axis dips below its start
print(f"released: mean precession rate {mean_rate:.6f} rad/s "
      f"({(mean_rate / Omega - 1) * 100:+.3f} % of Omega); theta - theta0 between "
      f"{dip.min():.2e} and {dip.max():.2e} rad")
# the nutation period 2 pi A_O / (C omega) = 0.05 s is short against 5 s: the mean rate is
# the steady one to the nutation's share of a period (and its small dip)
assert abs(mean_rate - Omega) < 0.01 * Omega
# the nutation's amplitude for a fast top: 2 A_O m g l sin(theta) / (C omega)^2
amplitude = 2 * A_O * m * g * l * math.sin(theta0) / (C * omega) ** 2
print(f"nutation amplitude {np.ptp(released.q[1]):.3e} rad, fast-top estimate {amplitude:.3e}")
assert abs(np.ptp(released.q[1]) - amplitude) < 0.01 * amplitude
print("energy drift:", released.energy_drift())

# %%
# The precession and the nutation
# -------------------------------
# Over the first 0.25 s (five nutation periods): the released axis precesses in steps (cusps
# where it stops, at its highest) about the steady precession, and dips by the nutation.
w = released.t <= 0.25
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True, layout="constrained")
ax1.plot(released.t[w], 1e3 * released.q[0][w], label=r"released, $\dot\psi(0) = 0$")
ax1.plot(steady.t[w], 1e3 * steady.q[0][w], "--", label=r"steady, $\dot\psi = \Omega$")
ax1.plot(steady.t[w], 1e3 * Omega_fast_top * steady.t[w], ":", color="k",
         label=r"$m g l\,t / (C\omega)$")
ax1.set_ylabel(r"precession $\psi$ [mrad]")
ax1.legend(loc="upper left", fontsize=8)
ax2.plot(released.t[w], np.degrees(released.q[1][w] - theta0), label="released")
ax2.plot(steady.t[w], np.degrees(steady.q[1][w] - theta0), "--", label="steady")
ax2.set_xlabel("t [s]")
ax2.set_ylabel(r"nutation $\theta - \theta_0$ [deg]")
ax2.set_ylim(-0.02, 0.6)
ax2.legend(loc="upper right", ncol=2, fontsize=8)
plt.show()
