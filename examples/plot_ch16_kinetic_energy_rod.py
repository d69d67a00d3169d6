"""
Kinetic torsor, dynamic torsor and kinetic energy of a rod turning about a fixed point (ch. 16)
===============================================================================================

A homogeneous rod :math:`OA` of mass :math:`m` and length :math:`L` is hinged at the fixed
point :math:`O`. Its position relative to the reference :math:`\\mathcal{T}_0 = (O; \\mathbf{i}_0,
\\mathbf{j}_0, \\mathbf{k}_0)` is given by two parameters of situation: the angle of precession
:math:`\\psi` about :math:`\\mathbf{k}_0` and the angle :math:`\\theta` between the rod and
:math:`\\mathbf{k}_0`. We form its kinetic torsor
:math:`\\{\\mathcal{C}\\} = \\{m\\,\\mathbf{v}(G) ; \\boldsymbol{\\sigma}(G)\\}` (ch. 16.1.2), its
dynamic torsor :math:`\\{\\mathcal{D}\\} = \\{m\\,\\mathbf{a}(G) ; \\boldsymbol{\\delta}(G)\\}`
(ch. 16.2.2) and its kinetic energy (ch. 16.3.2), and check them against the book's
relations:

* the kinetic energy of a solid with a fixed point :math:`O` is
  :math:`E_k = \\tfrac12\\, \\boldsymbol{\\omega}\\cdot\\mathcal{J}_O(\\boldsymbol{\\omega})`;
* at a fixed point, :math:`\\boldsymbol{\\delta}(O) = \\frac{d}{dt}\\boldsymbol{\\sigma}(O)`;
* the derivative of the kinetic energy is the product of the dynamic torsor by the kinematic
  torsor (ch. 16.3.4): :math:`\\frac{dE_k}{dt} = \\{\\mathcal{D}\\}\\cdot\\{\\mathcal{V}\\}`.
"""

# %%
# Parameters of situation and the body
# ------------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm

psi, theta = rm.coordinates("psi theta")
m, L = rm.constants("m L", positive=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=psi)          # precession
R2 = R1.rotated("R2", about=R1.j, angle=theta)        # the rod along k2
O = R0.origin
rod = rm.Body("rod", frame=R2, mass=m, centre=O.moved("G", L / 2 * R2.k),
              inertia=rm.inertia.rod(m, L, axis=R2.k))

Ek = sp.simplify(rod.kinetic_energy(R0))
print("E_k =", Ek)

# %%
# Check: the kinetic energy in closed form
# ----------------------------------------
# :math:`\omega = \dot\psi\,\mathbf{k}_0 + \dot\theta\,\mathbf{j}_1`; about O the moment of
# inertia of the rod is :math:`mL^2/3` about any axis normal to it, and zero about it, so
# :math:`E_k = \frac{mL^2}{6}\left(\dot\theta^2 + \dot\psi^2\sin^2\theta\right)`.
dpsi, dtheta = psi.diff(rm.t), theta.diff(rm.t)
closed = m * L**2 / 6 * (dtheta**2 + dpsi**2 * sp.sin(theta) ** 2)
assert sp.simplify(Ek - closed) == 0

# %%
# The kinetic and the dynamic torsors at O
# ----------------------------------------
C_O = rod.kinetic_torsor(R0, at=O)
D_O = rod.dynamic_torsor(R0, at=O)
sigma_O = C_O.moment
delta_O = D_O.moment
print("sigma(O) in R2:", sp.simplify(sigma_O.components(R2)).T)

# at the fixed point O, delta(O) = d sigma(O)/dt relative to R0
assert sp.simplify((delta_O - sigma_O.dt(R0)).components(R0)) == sp.zeros(3, 1)

# %%
# Check: dE_k/dt is the product {D} . {V} (ch. 16.3.4)
# ----------------------------------------------------
V_O = rod.kinematic_torsor(relative_to=R0, at=O)
power = D_O.comoment(V_O)
assert sp.simplify(Ek.diff(rm.t) - power) == 0
print("dE_k/dt = {D}.{V} verified")

# %%
# Kinetic energy over a steady precession
# ---------------------------------------
# For :math:`\dot\psi = \Omega`, :math:`\dot\theta = 0` the energy is
# :math:`\frac{mL^2}{6}\Omega^2\sin^2\theta`: nothing along the axis, most at 90 degrees.
th_s = sp.Symbol("th")
steady = Ek.subs({dpsi: 2.0, dtheta: 0, m: 1.5, L: 0.8}).subs(theta, th_s)
th = np.linspace(0, np.pi, 181)
Ek_steady = sp.lambdify(th_s, steady, "numpy")(th)
assert np.allclose(Ek_steady, 0.8**2 * 1.5 / 6 * 4.0 * np.sin(th) ** 2)
fig, ax = plt.subplots(figsize=(6.5, 4), constrained_layout=True)
ax.plot(np.degrees(th), Ek_steady)
ax.set(xlabel=r"angle $\theta$ of the rod from $\mathbf{k}_0$ (degrees)",
       ylabel="kinetic energy (J)",
       title=r"Rod m = 1.5 kg, L = 0.8 m in steady precession $\dot\psi$ = 2 rad/s")
plt.show()
