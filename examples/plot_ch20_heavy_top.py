"""
The symmetric heavy top: the general process of analysis (ch. 20, 9.4.4)
========================================================================

The book's general process for a problem of dynamics (ch. 20.1.2): choose the parameters of
situation, carry out the kinematic analysis, the kinetic analysis, list the mechanical
actions, apply the fundamental principle, then solve the equations of motion. We follow it for
the **symmetric heavy top**: a solid of revolution of mass :math:`m` on a ball joint without
friction at the fixed point :math:`O` of its axis, its mass centre :math:`G` at
:math:`OG = l` on the axis, moments of inertia :math:`A` about the axes through :math:`G`
normal to its axis and :math:`C` about its axis, under gravity :math:`-g\\,\\mathbf{k}_0`.

* Parameters of situation: the Euler angles :math:`\\psi` (precession), :math:`\\theta`
  (nutation), :math:`\\varphi` (spin) -- rotation about a fixed point (ch. 9.4.4).
* Actions: gravity and the action of the ball joint (a force through :math:`O`).
* The moment equation at :math:`O` gives three equations of motion; :math:`\\psi` and
  :math:`\\varphi` do not appear, so two **first integrals** follow: the angular momentum about
  the vertical :math:`\\sigma_O\\cdot\\mathbf{k}_0` and the spin
  :math:`\\omega_3 = \\dot\\varphi + \\dot\\psi\\cos\\theta`; the joint does no work, so the
  energy is conserved (ch. 18.3).
"""

# %%
# The system and its equations of motion
# --------------------------------------
# :func:`rigidmech.models.heavy_top` assembles the system the book's way.
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech import models

top = models.heavy_top()
psi, theta, phi = top.coordinates
m, g, l, A, C = top.constants
R0 = top.frame("R0")
eqs = top.system.equations_of_motion()
print("mass matrix:", sp.simplify(eqs.mass_matrix))

# %%
# A fast top released with its axis at 60 degrees
# -----------------------------------------------
values = {"m": 1.0, "g": 9.81, "l": 0.05, "A": 2.0e-3, "C": 1.0e-3}
spin = 600.0                                            # rad/s
sim = eqs.simulate(t=(0, 2.0), q0={"psi": 0.0, "theta": np.pi / 3, "phi": 0.0},
                   u0={"phi": spin}, rtol=1e-11, atol=1e-12, n_output=3001, **values)
print(sim.status, "| energy drift:", sim.energy_drift())

# %%
# Check: the first integrals along the computed motion
# ----------------------------------------------------
dpsi, dtheta, dphi = (q.diff(rm.t) for q in top.coordinates)
omega3 = dphi + dpsi * sp.cos(theta)
body = top.body("top")
sigma_z = body.kinetic_torsor(R0, at=R0.origin).moment.dot(R0.k)
# independent closed form of the angular momentum about the vertical
sigma_z_closed = ((A + m * l**2) * dpsi * sp.sin(theta) ** 2 + C * omega3 * sp.cos(theta))
assert sp.simplify(sigma_z - sigma_z_closed) == 0
numbers = {sp.Symbol(k, positive=True): v for k, v in values.items()}
for name, expr in (("omega_3", omega3), ("sigma_O . k0", sigma_z_closed)):
    series = np.asarray(sim.evaluate(expr), dtype=float)
    print(f"{name}: {series[0]:.10f} .. spread {np.ptp(series):.2e}")
    assert np.ptp(series) < 1e-8 * max(1.0, abs(series[0]))
assert abs(sim.energy_drift()) < 1e-8

# %%
# Check: the gyroscopic approximation of the mean precession
# ----------------------------------------------------------
# For a fast top released without precession the mean precession rate tends to
# :math:`m g l / (C\,\omega_3)` and the axis dips by a small nutation, from :math:`\theta_0` to
# about :math:`\theta_0 + 2 A_O\,m g l\sin\theta_0 / (C\omega_3)^2`, with
# :math:`A_O = A + m l^2` the moment of inertia about the normal axes through O.
psi_t = sim.q[0]
mean_rate = psi_t[-1] / sim.t[-1]
gyro = values["m"] * values["g"] * values["l"] / (values["C"] * spin)
print(f"mean precession rate {mean_rate:.4f} rad/s, gyroscopic approximation {gyro:.4f} rad/s")
assert abs(mean_rate - gyro) < 0.02 * gyro
A_O = values["A"] + values["m"] * values["l"] ** 2
mgl = values["m"] * values["g"] * values["l"]
dip = 2 * A_O * mgl * np.sin(np.pi / 3) / (values["C"] * spin) ** 2
print(f"largest dip of the axis {np.ptp(sim.q[1]):.3e} rad, approximation {dip:.3e} rad")
assert abs(np.ptp(sim.q[1]) - dip) < 0.05 * dip

# %%
# Nutation and the trace of the axis
# ----------------------------------
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.2), constrained_layout=True)
ax1.plot(sim.t, np.degrees(sim.q[1]))
ax1.set(xlabel="time t (s)", ylabel=r"nutation $\theta$ (degrees)",
        xlim=(0, 0.3), title="Nutation of a fast top (first 0.3 s)")
x = np.sin(sim.q[1]) * np.sin(sim.q[0])
y = -np.sin(sim.q[1]) * np.cos(sim.q[0])
ax2.plot(x, y, lw=0.8)
ax2.set(xlabel=r"$\sin\theta\sin\psi$", ylabel=r"$-\sin\theta\cos\psi$", aspect="equal",
        title="Trace of the axis on a horizontal plane")
plt.show()
