"""
Actions on the bearings of an unbalanced rotor, and its balancing (ch. 22.3)
============================================================================

A disc of mass :math:`m` and radius :math:`R` is keyed on a shaft that turns about the fixed
axis :math:`(O, \\mathbf{k}_0)` in two bearings at :math:`z_A = -L` and :math:`z_B = L`. The disc
is badly mounted: its mass centre :math:`G` is at the distance :math:`e` from the axis, in the
plane :math:`z = c`, and its plane is tilted by the small angle :math:`\\beta` about
:math:`\\mathbf{i}_1`. The reference :math:`\\mathcal{T}_1 = (O; \\mathbf{i}_1, \\mathbf{j}_1,
\\mathbf{k}_0)` is attached to the rotor; :math:`q` is its angle of rotation.

Gravity and the mass of the shaft aside, the fundamental principle says that the action of the
bearings is the dynamic torsor of the rotor (ch. 22.3.1). In :math:`\\mathcal{T}_1`,
with :math:`G = (a, b, c)` and the products of inertia :math:`D = \\int yz\\,dm`,
:math:`E = \\int zx\\,dm` at :math:`O`,

.. math:: \\mathbf{R} = m\\left[(-a\\omega^2 - b\\omega')\\,\\mathbf{i}_1 + (a\\omega' - b\\omega^2)
          \\,\\mathbf{j}_1\\right],\\qquad
          \\mathbf{M}(O) = (D\\omega^2 - E\\omega')\\,\\mathbf{i}_1 - (E\\omega^2 + D\\omega')
          \\,\\mathbf{j}_1 + C\\omega'\\,\\mathbf{k}_0 .

The rotor is **balanced** (ch. 22.3.3) when :math:`G` is on the axis (static balance) and
:math:`D = E = 0` (dynamic balance): two masses added in two planes do it.
"""

# %%
# The rotor as a body
# -------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech import vibrations

q = rm.coordinates("q")
m, Rd, e, c, beta = rm.constants("m R_d e c beta", positive=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=q)                     # the rotor
R2 = R1.rotated("R2", about=R1.i, angle=beta)                  # the tilted disc
G = R1.point("G", e, 0, c)
rotor = rm.Body("rotor", frame=R1, mass=m, centre=G,
                inertia=rm.inertia.disk(m, Rd, axis=R2.k).placed_at(G))

# the operator of inertia at O in the basis of R1 (Huygens, change of basis)
J_O = rotor.inertia.in_basis(R1).moved(R1.origin, mass=m, centre=G)
D, E, C = sp.simplify(J_O.D), sp.simplify(J_O.E), sp.simplify(J_O.C)
print("D =", D, "| E =", E)

# %%
# Check: the dynamic torsor of the rotor is the book's bearing action
# -------------------------------------------------------------------
w, dw = q.diff(rm.t), q.diff(rm.t, 2)
dyn = rotor.dynamic_torsor(R0, at=R1.origin)
res, mom = rm.vibrations.rotor_bearing_action(m, (e, 0, c), (D, E), w, dw, C=C)
assert sp.simplify(dyn.resultant.components(R1) - sp.Matrix(res)) == sp.zeros(3, 1)
assert sp.simplify(dyn.moment.components(R1) - sp.Matrix(mom)) == sp.zeros(3, 1)
print("resultant in R1:", list(res))
print("moment at O in R1:", [sp.simplify(x) for x in mom])

# %%
# The forces on the two bearings at a steady rate
# -----------------------------------------------
values = {m: 5.0, Rd: 0.15, e: 2e-4, c: 0.1, beta: 0.01}
L = 0.3
Dn, En = float(D.subs(values)), float(E.subs(values))
rates = np.linspace(0, 600, 121)                               # rad/s
forces = [vibrations.bearing_forces(5.0, (2e-4, 0, 0.1), (Dn, En), wk, planes=(-L, L))
          for wk in rates]
FA = np.array([np.hypot(*map(float, f[0])) for f in forces])
FB = np.array([np.hypot(*map(float, f[1])) for f in forces])
# both grow as omega^2; together they balance the resultant m e omega^2
sumX = np.array([float(f[0][0] + f[1][0]) for f in forces])
assert np.allclose(sumX, -5.0 * 2e-4 * rates**2)

# %%
# Balancing with two masses at radius 0.1 m in the bearing planes
# ---------------------------------------------------------------
added = vibrations.balancing_masses(5.0, (2e-4, 0, 0.1), (Dn, En), planes=(-L, L), radius=0.1)
for mi, angle, pos in added:
    print(f"add {float(mi) * 1e3:.2f} g at {np.degrees(float(angle)):.1f} deg, z = {pos[2]}")
# the balanced rotor: mass centre on the axis, D = E = 0
M = 5.0 + sum(float(mi) for mi, _, _ in added)
a_tot = 5.0 * 2e-4 + sum(float(mi) * float(p[0]) for mi, _, p in added)
b_tot = sum(float(mi) * float(p[1]) for mi, _, p in added)
E_tot = En + sum(float(mi) * float(p[2]) * float(p[0]) for mi, _, p in added)
D_tot = Dn + sum(float(mi) * float(p[1]) * float(p[2]) for mi, _, p in added)
assert max(abs(a_tot), abs(b_tot), abs(E_tot), abs(D_tot)) < 1e-12
res2, mom2 = vibrations.rotor_bearing_action(M, (a_tot / M, b_tot / M, 0), (D_tot, E_tot), 600.0)
assert max(abs(float(x)) for x in res2 + mom2[:2]) < 1e-6

fig, ax = plt.subplots(figsize=(7, 4), constrained_layout=True)
ax.plot(rates * 60 / (2 * np.pi), FA, label="bearing A (z = -0.3 m)")
ax.plot(rates * 60 / (2 * np.pi), FB, label="bearing B (z = +0.3 m)")
ax.set(xlabel="rotation speed (rev/min)", ylabel="force on the bearing (N)",
       title="Unbalanced disc, 5 kg: e = 0.2 mm, tilt 0.01 rad")
ax.legend()
plt.show()
