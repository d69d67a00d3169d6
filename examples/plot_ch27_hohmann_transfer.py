"""
A Hohmann transfer from a low orbit to the geostationary orbit (ch. 8.2, 27.3)
==============================================================================

Two tangential burns move a satellite between coplanar circular orbits: the first puts it on
an ellipse whose perigee is on the low orbit and apogee on the high one, the second
circularises it at the apogee. :func:`rigidmech.kinematics.hohmann_transfer` gives the two
speed changes and the transfer time; :class:`rigidmech.kinematics.Orbit` gives the conic from
the state just after the first burn and the position at any time (Kepler's equation). A
numerical integration of :math:`\\ddot{\\mathbf r} = -\\mu\\,\\mathbf r/r^3` from that state
lands on the same apogee.
"""

# %%
# The transfer and its numbers
# ----------------------------
import matplotlib.pyplot as plt
import numpy as np
from scipy.integrate import solve_ivp

from rigidmech.kinematics import Orbit, circular_speed, hohmann_transfer

mu = 3.986004418e14  # Earth, m^3/s^2
r1, r2 = 6678e3, 42164e3  # 300 km altitude, geostationary radius
h = hohmann_transfer(mu, r1, r2)
print(f"dv1 = {h.delta_v1:.1f} m/s, dv2 = {h.delta_v2:.1f} m/s, "
      f"total = {h.total_delta_v:.1f} m/s, transfer time = {h.time / 3600:.2f} h")

# %%
# The transfer ellipse from the state after the first burn
# --------------------------------------------------------
transfer = Orbit([r1, 0, 0], [0, circular_speed(mu, r1) + h.delta_v1, 0], mu=mu)
print(f"e = {transfer.eccentricity:.4f}, perigee {transfer.periapsis / 1e3:.0f} km, "
      f"apogee {transfer.apoapsis / 1e3:.0f} km")
t = np.linspace(0, h.time, 200)
r, v = transfer.state_at(t)

num = solve_ivp(lambda _, y: np.concatenate([y[3:], -mu * y[:3] / np.linalg.norm(y[:3]) ** 3]),
                (0, h.time), np.concatenate([[r1, 0, 0], [0, circular_speed(mu, r1)
                                                          + h.delta_v1, 0]]),
                method="DOP853", rtol=1e-12, atol=1e-6)
print(f"numerical arrival radius {np.linalg.norm(num.y[:3, -1]) / 1e3:.3f} km "
      f"(Kepler: {np.linalg.norm(r[-1]) / 1e3:.3f} km)")

# %%
# The drawing
# -----------
phi = np.linspace(0, 2 * np.pi, 300)
# constrained layout keeps every label inside the figure; the legend goes below the drawing
fig, ax = plt.subplots(figsize=(6.5, 7.5), layout="constrained")
ax.plot(r1 * np.cos(phi) / 1e3, r1 * np.sin(phi) / 1e3, label="low orbit (300 km)")
ax.plot(r2 * np.cos(phi) / 1e3, r2 * np.sin(phi) / 1e3, label="geostationary orbit")
ax.plot(r[:, 0] / 1e3, r[:, 1] / 1e3, "k--", label="transfer (Kepler)")
ax.plot(num.y[0] / 1e3, num.y[1] / 1e3, ":", color="tab:red", label="transfer (DOP853)")
ax.fill(6371 * np.cos(phi), 6371 * np.sin(phi), color="tab:blue", alpha=0.3)
ax.plot([r1 / 1e3], [0], "o", color="tab:green")
ax.annotate("burn 1", (r1 / 1e3, 0), xytext=(8e3, 4e3))
ax.plot([-r2 / 1e3], [0], "o", color="tab:red")
ax.annotate("burn 2", (-r2 / 1e3, 0), xytext=(-40e3, 4e3))
ax.set_aspect("equal")
ax.set_xlabel("x [km]")
ax.set_ylabel("y [km]")
ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncols=2, fontsize=8)
ax.set_title(f"Hohmann transfer: {h.total_delta_v / 1e3:.2f} km/s in {h.time / 3600:.2f} h")
plt.show()
