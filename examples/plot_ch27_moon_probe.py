"""
A probe between the Earth and the Moon: Jacobi's integral (ch. 27, 8.3)
=======================================================================

The restricted three-body problem: a probe P of negligible mass moves in the plane of the
orbit of the Earth E and the Moon M, which turn on circles about their barycentre O. Units:
the Earth-Moon distance D and the constant of gravitation G are 1, the masses
:math:`m_E = 1 - \\mu` and :math:`m_M = \\mu = 0.01215`, so that the pair turns at
:math:`\\Omega = \\sqrt{m_E + m_M} = 1` (Kepler's third law; the time unit is 4.34 days).
The Galilean frame :math:`R_0 = (O; \\mathbf{i}, \\mathbf{j})`; the frame :math:`R_1` of the
pair turns by :math:`\\Omega t` about :math:`\\mathbf{k}`, E at :math:`-\\mu\\,\\mathbf{i}_1`,
M at :math:`(1 - \\mu)\\,\\mathbf{i}_1`.

The Moon moves, so the probe's energy in :math:`R_0` is not conserved. In :math:`R_1` the
inertial actions of entrainment derive from the potential :math:`-\\Omega^2 r^2 / 2` and the
Coriolis action does no work (ch. 17, 19): the energy of the relative motion is conserved,
written as **Jacobi's integral**

.. math:: C_J = \\Omega^2(\\xi^2 + \\eta^2) + \\frac{2 m_E}{r_E} + \\frac{2 m_M}{r_M}
          - (\\dot\\xi^2 + \\dot\\eta^2),

with :math:`(\\xi, \\eta)` the probe's coordinates in :math:`R_1`. The system is the
``moon-probe`` scene's, written in :math:`R_0` with the attractions as forces; the check is
:math:`C_J` along the computed motion, evaluated here from the closed form above.
"""

# %%
# The probe, from the scene
# -------------------------
import math

import matplotlib.pyplot as plt
import numpy as np

from rigidmech import scenes

scene = scenes.get("moon-probe")
values = scene.defaults
mE, mM = values["mE"], values["mM"]
mu, Omega = mM / (mE + mM), math.sqrt(mE + mM)
eqs = scene.build().system.equations_of_motion()
# the scene's launch: 0.1 D from the Earth's centre, 4.2 D per time unit across the line
sim = eqs.simulate(t=(0, scene.t_end), q0=scene.q0, u0=scene.u0, rtol=1e-11, atol=1e-12,
                   n_output=3001, **values)
print(sim.status, f"{len(sim.t)} samples up to t = {sim.t[-1]:g}")

# %%
# Jacobi's integral along the motion
# ----------------------------------
(x, y), (xd, yd), t = sim.q, sim.u, sim.t
c, s = np.cos(Omega * t), np.sin(Omega * t)
xi, eta = c * x + s * y, -s * x + c * y                    # coordinates in R1
vx, vy = xd + Omega * y, yd - Omega * x                    # v(P/R1) = v(P/R0) - Omega k x OP
r_E = np.hypot(x + mu * c, y + mu * s)
r_M = np.hypot(x - (1 - mu) * c, y - (1 - mu) * s)
C_J = Omega**2 * (xi**2 + eta**2) + 2 * mE / r_E + 2 * mM / r_M - (vx**2 + vy**2)
drift = np.abs(C_J - C_J[0]) / abs(C_J[0])
energy_R0 = (xd**2 + yd**2) / 2 - mE / r_E - mM / r_M
print(f"C_J = {C_J[0]:.12f}, largest relative drift {drift.max():.2e}")
print(f"energy in R0 varies by {np.ptp(energy_R0) / abs(energy_R0[0]):.2f} of itself")
assert drift.max() < 1e-8                                  # the integration's tolerance
assert np.ptp(energy_R0) > 1e-3 * abs(energy_R0[0])        # while the energy in R0 is not

# %%
# A satellite's period (the ``satellite`` scene: the Earth alone, km and s)
# ---------------------------------------------------------------------------
# Its energy gives the semi-major axis, :math:`a = -\\mu_E / (2\\varepsilon)`, and Kepler's
# third law the period :math:`T = 2\\pi\\sqrt{a^3/\\mu_E}`: after T the satellite is back
# where it started.
sat = scenes.get("satellite")
mu_E = sat.defaults["mu"]
r0, v0 = np.array(sat.q0), np.array(sat.u0)
a = -mu_E / (2 * (v0 @ v0 / 2 - mu_E / np.linalg.norm(r0)))
T = 2 * math.pi * math.sqrt(a**3 / mu_E)
orbit = sat.build().system.equations_of_motion().simulate(
    t=(0, T), q0=sat.q0, u0=sat.u0, rtol=1e-12, atol=1e-9, n_output=2, **sat.defaults)
back = np.linalg.norm(orbit.q[:, -1] - r0) / np.linalg.norm(r0)
print(f"a = {a:.3f} km, T = {T:.3f} s; |r(T) - r(0)| / r(0) = {back:.1e}")
assert back < 1e-8

# %%
# The path in the rotating frame, and the drift of C_J
# ----------------------------------------------------
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.5), layout="constrained")
ax1.plot(xi, eta, linewidth=0.8, label="probe")
ax1.plot([-mu], [0], "o", color="tab:blue", markersize=8, label="Earth")
ax1.plot([1 - mu], [0], "o", color="0.5", markersize=4, label="Moon")
ax1.set_aspect("equal")
ax1.set_xlabel(r"$\xi$ [D]")
ax1.set_ylabel(r"$\eta$ [D]")
ax1.set_title("path in the Earth-Moon frame $R_1$", fontsize=10)
ax1.legend(loc="lower left", fontsize=8)
ax2.semilogy(t[1:], np.maximum(drift[1:], 1e-17))
ax2.set_xlabel("t [4.34 days]")
ax2.set_ylabel(r"$|C_J(t) - C_J(0)|\ /\ |C_J(0)|$")
ax2.set_title("Jacobi's integral along the motion", fontsize=10)
plt.show()
