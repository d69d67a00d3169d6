"""
Work of a force, potential energy, and a force without one (ch. 11.3)
=====================================================================

The work of a force :math:`\\mathbf{F}` whose point of application describes a path from
:math:`M_1` to :math:`M_2` is :math:`W = \\int_{M_1}^{M_2}\\mathbf{F}\\cdot d\\mathbf{M}`
(ch. 11.3.4-11.3.5). When the force field derives from a **potential energy**,
:math:`\\mathbf{F} = -\\mathbf{grad}\\,E_p` (ch. 11.3.3), the work does not depend on the path:
:math:`W = E_p(M_1) - E_p(M_2)`. We take a point attached to the origin by a spring of
stiffness :math:`k` (free length zero) and subjected to gravity, so
:math:`\\mathbf{F} = -k\\,\\mathbf{OM} - mg\\,\\mathbf{k}_0`, and compare two paths from
:math:`M_1 = (a, 0, 0)` to :math:`M_2 = (-a, 0, h)`: a half turn of a helix and a straight
segment. A field with a curl, :math:`\\mathbf{F}' = c\\,(-y\\,\\mathbf{i}_0 + x\\,\\mathbf{j}_0)`
(a "whirl"), gives two different works.
"""

# %%
# The force and its potential energy
# ----------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech import actions

x, y, z = sp.symbols("x y z", real=True)
s = sp.Symbol("s", real=True)
k, m, g, a, h, c = rm.constants("k m g a h c", positive=True)
R0 = rm.Frame("R0")
F = -k * R0.vector(x, y, z) - m * g * R0.k
assert actions.is_conservative(F, R0, (x, y, z))
Ep = sp.simplify(actions.potential_energy_of(F, R0, (x, y, z)))
print("E_p =", Ep)
assert sp.simplify(Ep - (k * (x**2 + y**2 + z**2) / 2 + m * g * z)) == 0

# %%
# Check: two paths, one work, equal to the drop of potential energy
# -----------------------------------------------------------------
helix = rm.Curve(R0.vector(a * sp.cos(s), a * sp.sin(s), h * s / sp.pi), s, R0)
segment = rm.Curve(R0.vector(a * (1 - 2 * s), 0, h * s), s, R0)
W_helix = sp.simplify(actions.work_along_path(F, helix, 0, sp.pi, variables=(x, y, z)))
W_segment = sp.simplify(actions.work_along_path(F, segment, 0, 1, variables=(x, y, z)))
drop = sp.simplify(Ep.subs({x: a, y: 0, z: 0}) - Ep.subs({x: -a, y: 0, z: h}))
print("W(helix) =", W_helix, "| W(segment) =", W_segment, "| E_p(M1) - E_p(M2) =", drop)
assert sp.simplify(W_helix - drop) == 0 and sp.simplify(W_segment - drop) == 0

# %%
# Check: the whirl has no potential energy, its work depends on the path
# ----------------------------------------------------------------------
whirl = c * R0.vector(-y, x, 0)
assert not actions.is_conservative(whirl, R0, (x, y, z))
Wh = sp.simplify(actions.work_along_path(whirl, helix, 0, sp.pi, variables=(x, y, z)))
Ws = sp.simplify(actions.work_along_path(whirl, segment, 0, 1, variables=(x, y, z)))
print("whirl: W(helix) =", Wh, "| W(segment) =", Ws)
assert sp.simplify(Wh - sp.pi * c * a**2) == 0 and Ws == 0   # c r^2 d(theta) along the turn

# %%
# The two paths on the level surfaces of E_p (section y = 0)
# ----------------------------------------------------------
num = {k: 50.0, m: 1.0, g: 9.81, a: 0.5, h: 0.8}
X, Z = np.meshgrid(np.linspace(-0.7, 0.7, 141), np.linspace(-0.4, 1.0, 141))
f_Ep = sp.lambdify((x, y, z), Ep.subs(num), "numpy")
fig, ax = plt.subplots(figsize=(6.5, 5.5), constrained_layout=True)
cs = ax.contour(X, Z, f_Ep(X, 0 * X, Z), levels=15, cmap="viridis", linewidths=0.8)
fig.colorbar(cs, ax=ax, label=r"potential energy $E_p$ (J) in the plane y = 0")
ss = np.linspace(0, np.pi, 100)
ax.plot(0.5 * np.cos(ss), 0.8 * ss / np.pi, "tab:red", label="half turn of helix (projection)")
ax.plot([0.5, -0.5], [0, 0.8], "k--", label="straight segment")
ax.plot([0.5, -0.5], [0, 0.8], "ko")
ax.annotate("$M_1$", (0.5, 0), xytext=(5, -12), textcoords="offset points")
ax.annotate("$M_2$", (-0.5, 0.8), xytext=(5, 5), textcoords="offset points")
ax.set(xlabel="x (m)", ylabel="z (m)", aspect="equal",
       title="Spring k = 50 N/m and gravity, m = 1 kg")
ax.legend(loc="lower left", fontsize=8)
plt.show()
