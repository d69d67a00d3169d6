"""
Change of reference system: a bead on a turning rod, inertia torsor of Coriolis (ch. 17)
========================================================================================

A rod turns in the horizontal plane about the vertical axis :math:`(O, \\mathbf{k}_0)` of the
reference :math:`\\mathcal{T}_0` at the constant rate :math:`\\omega`; the reference
:math:`\\mathcal{T}_1` is attached to the rod, :math:`\\mathbf{i}_1` along it. A bead :math:`B`
of mass :math:`m` slides without friction on the rod, :math:`\\mathbf{OB} = r\\,\\mathbf{i}_1`.

The acceleration of :math:`B` relative to :math:`\\mathcal{T}_0` is the sum of the relative
acceleration, the acceleration of entrainment and the acceleration of Coriolis (ch. 17.1.3),

.. math:: \\mathbf{a}(B/\\mathcal{T}_0) = \\mathbf{a}(B/\\mathcal{T}_1) + \\mathbf{a}_e(B)
          + 2\\,\\boldsymbol{\\omega}(\\mathcal{T}_1/\\mathcal{T}_0)
          \\wedge\\mathbf{v}(B/\\mathcal{T}_1),

and the same holds for the dynamic torsors (ch. 17.2.3):
:math:`\\{\\mathcal{D}_{/\\mathcal{T}_0}\\} = \\{\\mathcal{D}_{/\\mathcal{T}_1}\\}
+ \\{\\mathcal{D}_e\\} + \\{\\mathcal{D}_c\\}`. In the rod's reference the bead is driven
outwards by the inertia force of entrainment :math:`m\\omega^2 r\\,\\mathbf{i}_1`, and the rod
must push it sideways to balance the inertia force of Coriolis
:math:`-2m\\omega\\dot r\\,\\mathbf{j}_1`.
"""

# %%
# The references and the bead
# ---------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech import kinetics

r = rm.coordinates("r")
m, w = rm.constants("m omega", positive=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=w * rm.t)            # the rod
bead = rm.Body("bead", frame=R1.translated("Rb", R1.point("B", r, 0, 0)), mass=m)
B = bead.centre

D_abs = bead.dynamic_torsor(R0, at=B)
D_rel = bead.dynamic_torsor(R1, at=B)
D_e = kinetics.entrainment_dynamic_torsor(bead, relative_to=R1, absolute=R0, at=B)
D_c = kinetics.coriolis_dynamic_torsor(bead, relative_to=R1, absolute=R0, at=B)
print("D_e :", D_e.resultant)
print("D_c :", D_c.resultant)

# %%
# Check: composition of the dynamic torsors and the Coriolis term in closed form
# ------------------------------------------------------------------------------
total = D_rel + D_e + D_c
assert sp.simplify((total.resultant - D_abs.resultant).components(R1)) == sp.zeros(3, 1)
rdot = r.diff(rm.t)
coriolis = 2 * m * rm.cross(w * R0.k, rdot * R1.i)
assert sp.simplify((D_c.resultant - coriolis).components(R1)) == sp.zeros(3, 1)
F_ic = kinetics.coriolis_inertial_torsor(bead, relative_to=R1, absolute=R0, at=B)
assert sp.simplify((F_ic.resultant + coriolis).components(R1)) == sp.zeros(3, 1)

# %%
# The motion of the bead along the rod
# ------------------------------------
# Along :math:`\mathbf{i}_1` the rod exerts nothing (no friction): the fundamental principle
# in :math:`\mathcal{T}_0` gives :math:`m\,\ddot r - m\omega^2 r = 0`, hence from rest at
# :math:`r_0`, :math:`r = r_0\cosh\omega t`; along :math:`\mathbf{j}_1` the action of the rod is
# :math:`N = 2 m\omega\dot r`.
along = sp.simplify(D_abs.resultant.dot(R1.i))
across = sp.simplify(D_abs.resultant.dot(R1.j))
print("m a . i1 =", along, "| m a . j1 =", across)
r0, wn, mn = 0.1, 2.0, 0.05
t_s = sp.Symbol("t_s")
r_sol = r0 * sp.cosh(wn * t_s)
eq = along.subs({m: mn, w: wn}).subs(rdot.diff(rm.t), r_sol.diff(t_s, 2)).subs(r, r_sol)
assert abs(float(eq.subs(t_s, 0.7))) < 1e-12
N = across.subs({m: mn, w: wn}).subs(rdot, r_sol.diff(t_s)).subs(t_s, 0.7)
assert abs(float(N) - 2 * mn * wn * r0 * wn * np.sinh(wn * 0.7)) < 1e-12

# %%
# The trajectory in the fixed reference
# -------------------------------------
# In :math:`\mathcal{T}_0` the bead spirals out; the arrows are the action of the rod
# :math:`N\,\mathbf{j}_1`, which balances the inertia force of Coriolis.
tt = np.linspace(0, 1.2, 300)
rr = r0 * np.cosh(wn * tt)
x, y = rr * np.cos(wn * tt), rr * np.sin(wn * tt)
fig, ax = plt.subplots(figsize=(6, 6), constrained_layout=True)
ax.plot(x, y, label="trajectory of B in $\\mathcal{T}_0$")
for tk in np.linspace(0.2, 1.2, 6):
    rk, ang = r0 * np.cosh(wn * tk), wn * tk
    Nk = 2 * mn * wn * r0 * wn * np.sinh(wn * tk)
    ax.plot([0, rk * np.cos(ang)], [0, rk * np.sin(ang)], color="gray", lw=0.8)
    ax.quiver(rk * np.cos(ang), rk * np.sin(ang), -np.sin(ang) * Nk, np.cos(ang) * Nk,
              color="tab:red", angles="xy", scale_units="xy", scale=2.0, width=0.006)
ax.plot([], [], color="gray", lw=0.8, label="rod")
ax.plot([], [], color="tab:red", label=r"action of the rod $2m\omega\dot r\,\mathbf{j}_1$")
ax.set(xlabel="x (m)", ylabel="y (m)", aspect="equal",
       title=r"Bead on a rod turning at $\omega$ = 2 rad/s")
ax.set(xlim=(-0.6, 0.2), ylim=(-0.05, 0.45))  # room for the arrows (quiver does not autoscale)
ax.legend(loc="lower left")
plt.show()
