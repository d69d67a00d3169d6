"""
Slider-crank: kinematic torsor and instantaneous centre of the connecting rod (ch. 9)
=====================================================================================

The crank :math:`OA` (length :math:`r`) turns by the angle :math:`q` about :math:`(O,
\\mathbf{k}_0)`; the connecting rod :math:`AB` (length :math:`L`) has its end :math:`B` guided
on the axis :math:`(O, \\mathbf{i}_0)`. The rod makes the angle :math:`\\beta` with
:math:`\\mathbf{i}_0`, with :math:`L\\sin\\beta = -r\\sin q`. Its motion is a **plane motion**
(ch. 9.4.5): the kinematic torsor :math:`\\{\\boldsymbol{\\omega} ; \\mathbf{v}(A)\\}` (ch. 9.2.4)
gives the velocity of every point of the rod,
:math:`\\mathbf{v}(B) = \\mathbf{v}(A) + \\boldsymbol{\\omega}\\wedge\\mathbf{AB}`, and at each
instant there is one point :math:`I` of zero velocity, the **instantaneous centre of
rotation**. Because :math:`\\mathbf{v}(A)` is normal to :math:`OA` and :math:`\\mathbf{v}(B)` is
along :math:`\\mathbf{i}_0`, :math:`I` is where the line :math:`OA` meets the normal to
:math:`\\mathbf{i}_0` at :math:`B`.
"""

# %%
# The rod as a moving frame
# -------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech import kinematics

q = rm.coordinates("q")
r, L = rm.constants("r L", positive=True)
R0 = rm.Frame("R0")
crank = R0.rotated("R1", about=R0.k, angle=q)
A = R0.origin.moved("A", r * crank.i)
beta = -sp.asin(r * sp.sin(q) / L)
rod = R0.rotated("R2", about=R0.k, angle=beta, origin=A)
B = A.moved("B", L * rod.i)
print("y_B =", sp.simplify(B.position.dot(R0.j)))
assert sp.simplify(B.position.dot(R0.j)) == 0          # B stays on its guide

# %%
# Check: the kinematic torsor gives v(B), along the guide
# -------------------------------------------------------
V_A = rm.kinematic_torsor(rod, relative_to=R0, at=A)
vB = V_A.velocity + rm.cross(V_A.rotation, B.position - A.position)
assert sp.simplify((vB - B.velocity(R0)).components(R0)) == sp.zeros(3, 1)
assert sp.simplify(vB.dot(R0.j)) == 0
x_B = sp.simplify(B.position.dot(R0.i))
assert sp.simplify(vB.dot(R0.i) - x_B.diff(rm.t)) == 0

# %%
# Check: the instantaneous centre
# -------------------------------
# I is at :math:`(x_B, x_B\tan q)`, on OA and on the normal at B.
I = kinematics.instantaneous_centre(rod, relative_to=R0)
I_xy = sp.simplify(I.coordinates(R0))
print("I =", I_xy.T)
values = {r: 0.1, L: 0.35}
for qk in (0.3, 1.0, 2.2, 4.0):
    xI, yI = (float(c.subs(values).subs(q, qk)) for c in I_xy[:2])
    xb = float(x_B.subs(values).subs(q, qk))
    assert abs(xI - xb) < 1e-12 and abs(yI - xb * np.tan(qk)) < 1e-12, qk

# %%
# The mechanism at q = 50 degrees with the instantaneous centre
# -------------------------------------------------------------
qk = np.radians(50)
pts = {n: np.array([float(c.subs(values).subs(q, qk)) for c in P.coordinates(R0)[:2]])
       for n, P in (("O", R0.origin), ("A", A), ("B", B), ("I", I))}
fig, ax = plt.subplots(figsize=(7, 5.5), constrained_layout=True)
ax.plot(*zip(pts["O"], pts["A"], strict=True), "k-o", lw=3, label="crank OA")
ax.plot(*zip(pts["A"], pts["B"], strict=True), "-o", color="tab:blue", lw=3, label="rod AB")
ax.plot([-0.15, 0.5], [0, 0], color="gray", lw=1)
ax.plot(*zip(pts["O"], pts["I"], strict=True), ":", color="k", lw=1)
ax.plot(*zip(pts["B"], pts["I"], strict=True), ":", color="k", lw=1)
ax.plot(*pts["I"], "r*", ms=14, label="instantaneous centre I")
for n, p in pts.items():
    ax.annotate(n, p, textcoords="offset points", xytext=(6, 6))
ax.set(xlabel="x (m)", ylabel="y (m)", aspect="equal",
       title="Slider-crank, r = 0.1 m, L = 0.35 m, q = 50 degrees")
ax.margins(0.12)
ax.legend(loc="upper left")
plt.show()
