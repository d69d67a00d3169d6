"""
A free body in a Galilean reference: a thrown symmetric solid (ch. 18.4)
========================================================================

A solid of revolution of mass :math:`m` (moments of inertia :math:`A` about the axes through its
mass centre :math:`G` normal to its axis, :math:`C` about its axis) is thrown in the air and
subjected only to gravity. The fundamental principle of dynamics (ch. 18.1.3) splits into

* the **theorem of the resultant**: :math:`m\\,\\mathbf{a}(G) = m\\,\\mathbf{g}`: the mass centre
  describes a parabola, whatever the rotation;
* the **theorem of the moment** at :math:`G`: :math:`\\boldsymbol{\\delta}(G) =
  \\frac{d}{dt}\\boldsymbol{\\sigma}(G) = \\mathbf{0}`: the angular momentum about :math:`G` is a
  constant vector (ch. 18.4.2, the body under no moment about its mass centre).

For the symmetric body, with :math:`\\mathbf{k}_0` along :math:`\\boldsymbol{\\sigma}(G)`, the
Euler angles then give a **regular precession**: :math:`\\theta` constant,
:math:`\\dot\\psi = \\sigma/A` and :math:`\\dot\\varphi = \\sigma\\cos\\theta\\,(1/C - 1/A)`.
"""

# %%
# Parameters of situation: the position of G and the Euler angles
# ---------------------------------------------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigidmech as rm

x, y, z, psi, theta, phi = rm.coordinates("x y z psi theta phi")
m, g, A, C = rm.constants("m g A C", positive=True)
R0 = rm.Frame("R0")
G = R0.point("G", x, y, z)
R = R0.euler("R", psi, theta, phi, origin=G)
body = rm.Body("body", frame=R, mass=m, centre=G,
               inertia=rm.InertiaOperator.from_products(A, A, C, frame=R, at=G))
system = rm.System(galilean=R0)
system.add(body)
system.act(rm.gravity(-g * R0.k))
eqs = system.equations_of_motion()
print("coordinates:", eqs.coordinates)

# %%
# A throw: G launched at 8 m/s at 60 degrees, the body spinning
# -------------------------------------------------------------
# The initial rates are those of a regular precession about :math:`\mathbf{k}_0` with
# :math:`\theta_0 = 0.4` rad and the spin :math:`\omega_3 = \dot\varphi + \dot\psi\cos\theta`.
values = {"m": 0.4, "g": 9.81, "A": 2.0e-3, "C": 3.0e-3}
th0, sigma = 0.4, 0.06                                   # rad, kg m^2/s
An, Cn = values["A"], values["C"]
dpsi0 = sigma / An
dphi0 = sigma * np.cos(th0) * (1 / Cn - 1 / An)
v0 = 8.0
sim = eqs.simulate(t=(0, 1.4), q0={"theta": th0},
                   u0={"x": v0 * np.cos(np.pi / 3), "z": v0 * np.sin(np.pi / 3),
                       "psi": dpsi0, "phi": dphi0},
                   rtol=1e-11, atol=1e-12, n_output=701, **values)
print(sim.status, "| energy drift", sim.energy_drift())

# %%
# Check: the parabola of G and the regular precession
# ---------------------------------------------------
names = [str(q.func) for q in eqs.coordinates]
qx, qz = sim.q[names.index("x")], sim.q[names.index("z")]
tt = sim.t
assert np.allclose(qx, v0 * np.cos(np.pi / 3) * tt, atol=1e-9)
assert np.allclose(qz, v0 * np.sin(np.pi / 3) * tt - values["g"] * tt**2 / 2, atol=1e-9)
q_theta, q_psi = sim.q[names.index("theta")], sim.q[names.index("psi")]
assert np.ptp(q_theta) < 1e-9
assert np.allclose(q_psi, dpsi0 * tt, atol=1e-8)
# sigma(G) is a constant vector of R0: sigma k0
sigma_G = body.kinetic_torsor(R0, at=G).moment
for k, unit in enumerate((R0.i, R0.j, R0.k)):
    series = np.asarray(sim.evaluate(sigma_G.dot(unit)), dtype=float)
    expected = sigma if k == 2 else 0.0
    assert np.allclose(series, expected, atol=1e-9), k
print(f"sigma(G) = (0, 0, {sigma:.3f}) kg m^2/s all along the flight")

# %%
# The flight
# ----------
# The mass centre on its parabola and the axis of the body (drawn 0.3 m long) every 0.1 s.
fig, ax = plt.subplots(figsize=(8, 4.2), constrained_layout=True)
ax.plot(qx, qz, "k", lw=1, label="trajectory of G")
k_axis = [np.asarray(sim.evaluate(R.k.dot(u)), dtype=float) for u in (R0.i, R0.k)]
for n in range(0, len(tt), 50):
    ax.plot([qx[n], qx[n] + 0.3 * k_axis[0][n]], [qz[n], qz[n] + 0.3 * k_axis[1][n]],
            color="tab:red", lw=2)
ax.plot([], [], color="tab:red", lw=2, label="axis of the body (projection)")
ax.set(xlabel="x (m)", ylabel="z (m)", aspect="equal", title="A spinning solid thrown in the air")
ax.legend(loc="lower center")
plt.show()
