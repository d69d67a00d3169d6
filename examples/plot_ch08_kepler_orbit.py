"""
Motion with a central acceleration in 1/r^2: Binet's formulas and Kepler's laws (ch. 8)
=======================================================================================

A point :math:`M` moves with an acceleration always directed towards a fixed centre
:math:`O`, :math:`\\mathbf{a}(M,t) = -K\\,\\mathbf{OM}/OM^3` (ch. 8.2). The motion is plane and
obeys the **area law** (ch. 8.1.4): the areal velocity :math:`\\tfrac12 C` with
:math:`C = r^2\\dot\\theta` is constant. With :math:`u = 1/r` as a function of the polar angle,
**Binet's formulas** (ch. 8.1.5) give the velocity and the acceleration,

.. math:: V^2 = C^2\\left(u^2 + u'^2\\right), \\qquad
          a_r = -C^2 u^2 \\left(u + u''\\right),

so that the trajectory is a conic :math:`u = (1 + e\\cos\\theta)/p` with :math:`p = C^2/K`
(ch. 8.2.1). For an ellipse of semi-major axis :math:`a` the period obeys Kepler's third law
:math:`T = 2\\pi\\sqrt{a^3/K}`, and the position at time :math:`t` follows from Kepler's
equation :math:`E - e \\sin E = 2\\pi t / T` (ch. 8.2.4).
"""

# %%
# Binet's formulas along a conic
# ------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

from rigidmech import kinematics

theta = sp.Symbol("theta")
p, e, C = sp.symbols("p e C", positive=True)
u = (1 + e * sp.cos(theta)) / p
a_r = kinematics.binet_acceleration(u, theta, C)
V2 = kinematics.binet_speed_squared(u, theta, C)
K = C**2 / p
print("a_r =", sp.simplify(a_r))
# the acceleration is -K u^2: Newton's law in 1/r^2
assert sp.simplify(a_r + K * u**2) == 0
# the speed: the energy integral V^2 = K (2/r - 1/a), with a = p / (1 - e^2)
assert sp.simplify(V2 - K * (2 * u - (1 - e**2) / p)) == 0

# %%
# An elliptic orbit from an initial state
# ---------------------------------------
# :class:`rigidmech.kinematics.Orbit` gives the conic described from a position and a velocity;
# its :meth:`~rigidmech.kinematics.Orbit.state_at` propagates the state in time.
Kc = 1.0                                    # K = G M, in units where r0 = 1
orbit = kinematics.Orbit([1.0, 0.0, 0.0], [0.0, 1.25, 0.0], mu=Kc)
print(orbit.kind, "e =", round(orbit.eccentricity, 6), "a =", round(orbit.semi_major_axis, 6),
      "T =", round(orbit.period, 6))

# Kepler's third law
assert abs(orbit.period - 2 * np.pi * np.sqrt(orbit.semi_major_axis**3 / Kc)) < 1e-12

# %%
# Check: the area law and Kepler's equation
# -----------------------------------------
# The areal constant :math:`C = |\mathbf{r}\wedge\mathbf{v}|` is the same all along the orbit, and
# the distance :math:`r = a(1 - e\cos E)` with :math:`E` from Kepler's equation
# (:func:`rigidmech.kinematics.kepler_elliptic`) is the distance of the propagated state.
times = np.linspace(0.0, orbit.period, 13)
states = [orbit.state_at(t) for t in times]
r = np.array([s[0] for s in states])
v = np.array([s[1] for s in states])
areal = np.linalg.norm(np.cross(r, v), axis=1)
assert np.allclose(areal, areal[0], rtol=1e-11)
E = kinematics.kepler_elliptic(2 * np.pi * times / orbit.period, orbit.eccentricity)
r_kepler = orbit.semi_major_axis * (1 - orbit.eccentricity * np.cos(E))
assert np.allclose(np.linalg.norm(r, axis=1), r_kepler, rtol=1e-10)
print("areal constant C =", areal[0], "| C^2/K =", areal[0] ** 2 / Kc,
      "= semi-latus rectum", orbit.semi_latus_rectum)
assert abs(areal[0] ** 2 / Kc - orbit.semi_latus_rectum) < 1e-12

# %%
# Equal areas in equal times
# --------------------------
# Twelve sectors swept in twelve equal intervals of time: the narrow ones near the periapsis
# and the wide ones near the apoapsis have the same area :math:`C\,T/24`.
fine = np.array([orbit.state_at(t)[0] for t in np.linspace(0, orbit.period, 600)])
fig, ax = plt.subplots(figsize=(8, 5.5), layout="constrained")
ax.plot(fine[:, 0], fine[:, 1], "k", lw=1)
for n in range(12):
    arc = np.array([orbit.state_at(t)[0] for t in np.linspace(times[n], times[n + 1], 30)])
    poly = np.vstack([[0, 0], arc[:, :2]])
    ax.fill(poly[:, 0], poly[:, 1], alpha=0.35, color=plt.cm.tab20(n))
ax.plot(r[:, 0], r[:, 1], "ko", ms=3)
ax.plot(0, 0, "*", color="orange", ms=14, label="centre O")
ax.set(xlabel="x (units of $r_0$)", ylabel="y (units of $r_0$)", aspect="equal",
       title=f"Kepler orbit, e = {orbit.eccentricity:.3f}: equal areas in equal times")
fig.legend(loc="outside right upper")  # outside the axes: the orbit is not covered
plt.show()
