"""
Mass centre of a solid hemisphere (ch. 12.4.1, 12.4.3)
======================================================

The mass centre :math:`G` of a material system is the measure centre of its mass
distribution (ch. 12.3.1): :math:`\\mathbf{OG} = \\frac{1}{m}\\int_D \\rho\\,\\mathbf{OP}\\,dV`.
For a homogeneous solid hemisphere of radius :math:`R` (ch. 12.4.1), the planes of symmetry
containing the axis put :math:`G` on the axis (ch. 12.3.4), and the integral in spherical
coordinates gives :math:`OG = 3R/8` from the centre of the flat face. A non-homogeneous
solid (the subject of ch. 12.4.3) is treated the same way: here the hemisphere with a density
that grows with the height, :math:`\\rho = \\rho_0 (1 + z/R)`.
"""

# %%
# The hemisphere as a domain
# --------------------------
# The volume is parametrised by the spherical coordinates :math:`(r, \varphi, \theta)`; the
# volume element :math:`r^2 \sin\varphi\, dr\, d\varphi\, d\theta` is derived by
# :class:`rigidmech.torsors.Domain` from the Jacobian.
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm

R, rho0 = rm.constants("R rho0", positive=True)
r, phi, th, z = sp.symbols("r phi theta z", nonnegative=True)
R0 = rm.Frame("R0")
ball = rm.torsors.Domain(
    R0,
    [r * sp.sin(phi) * sp.cos(th), r * sp.sin(phi) * sp.sin(th), r * sp.cos(phi)],
    (r, 0, R), (phi, 0, sp.pi / 2), (th, 0, 2 * sp.pi),
)
print("volume element:", ball.measure)
G = rm.measure_centre(rho0, ball)
zG = sp.simplify(G.coordinates(R0)[2])
print("homogeneous: OG =", list(G.coordinates(R0)))

# %%
# Check by slices
# ---------------
# An independent route: the hemisphere is a pile of discs of radius :math:`\sqrt{R^2 - z^2}`,
# so :math:`z_G = \int_0^R z\,\pi(R^2 - z^2)\,dz \big/ \int_0^R \pi(R^2 - z^2)\,dz = 3R/8`.
slice_area = sp.pi * (R**2 - z**2)
by_slices = sp.integrate(z * slice_area, (z, 0, R)) / sp.integrate(slice_area, (z, 0, R))
assert sp.simplify(zG - by_slices) == 0 and sp.simplify(zG - 3 * R / 8) == 0
assert list(G.coordinates(R0))[:2] == [0, 0]

# %%
# A non-homogeneous hemisphere
# ----------------------------
# With :math:`\rho = \rho_0(1 + z/R)` the upper layers weigh more and :math:`G` rises.
z_of = r * sp.cos(phi)
G2 = rm.measure_centre(rho0 * (1 + z_of / R), ball, name="G2")
zG2 = sp.simplify(G2.coordinates(R0)[2])
weight = 1 + z / R
by_slices2 = (sp.integrate(z * weight * slice_area, (z, 0, R))
              / sp.integrate(weight * slice_area, (z, 0, R)))
print("non-homogeneous: z_G =", zG2, "(by slices:", sp.simplify(by_slices2), ")")
assert sp.simplify(zG2 - by_slices2) == 0

# %%
# The two mass centres on a meridian section
# ------------------------------------------
a = np.linspace(0, np.pi, 200)
fig, ax = plt.subplots(figsize=(6, 3.8), constrained_layout=True)
ax.fill(np.cos(a), np.sin(a), color="lightsteelblue", label="meridian section")
for value, label, mark in ((zG, "homogeneous", "o"), (zG2, r"$\rho_0(1 + z/R)$", "s")):
    height = float(value.subs(R, 1))
    ax.plot(0, height, mark, ms=8, label=f"G, {label}: z = {height:.4f} R")
ax.axvline(0, color="k", lw=0.6, ls="--")
ax.set(xlabel="x / R", ylabel="z / R", aspect="equal", ylim=(-0.05, 1.1),
       title="Mass centre of a solid hemisphere")
ax.legend(loc="upper right", fontsize=8)
plt.show()
