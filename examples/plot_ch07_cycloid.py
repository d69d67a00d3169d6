"""
Cycloidal motion: a point of a rolling circle (ch. 7.5)
=======================================================

A circle of radius :math:`R` rolls without slipping on the axis :math:`(O, \\mathbf{i}_0)`;
its centre :math:`C` moves at :math:`x_C = R\\theta` while the circle turns by :math:`-\\theta`
about :math:`\\mathbf{k}_0`. A point :math:`M` of the circle, at :math:`O` for
:math:`\\theta = 0`, describes a **cycloid** (ch. 7.5):

.. math:: x = R(\\theta - \\sin\\theta), \\qquad y = R(1 - \\cos\\theta).

For a uniform rolling, :math:`\\theta = \\omega t`, the speed of :math:`M` is
:math:`V = 2R\\omega|\\sin(\\omega t/2)|` (zero at the cusps, where :math:`M` touches the line),
its acceleration has the constant magnitude :math:`R\\omega^2` and points towards the centre
:math:`C`, and one arch of the cycloid is :math:`8R` long.
"""

# %%
# The rolling circle and its point M
# ----------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm

R, w = rm.constants("R omega", positive=True)
theta = w * rm.t
R0 = rm.Frame("R0")
Cc = R0.point("C", R * theta, R, 0)
R1 = R0.rotated("R1", about=R0.k, angle=-theta, origin=Cc)    # attached to the circle
M = Cc.moved("M", -R * R1.j)
xy = sp.simplify(M.position.components(R0))
print("OM =", xy.T)
assert sp.simplify(xy - sp.Matrix([R * (theta - sp.sin(theta)), R * (1 - sp.cos(theta)), 0])) \
    == sp.zeros(3, 1)

# %%
# Check: speed, acceleration and arc length
# -----------------------------------------
v, a = M.velocity(R0), M.acceleration(R0)
V2 = sp.simplify(v.magnitude() ** 2)
assert sp.simplify(V2 - (2 * R * w * sp.sin(w * rm.t / 2)) ** 2) == 0
assert sp.simplify(a.magnitude() ** 2 - (R * w**2) ** 2) == 0
# the acceleration points from M to the centre C
MC = Cc.position - M.position
assert sp.simplify(rm.cross(a, MC).components(R0)) == sp.zeros(3, 1)
assert sp.simplify(rm.dot(a, MC)) != 0
s = sp.Symbol("s", real=True)
arch = rm.Curve(R0.vector(R * (s - sp.sin(s)), R * (1 - sp.cos(s)), 0), s, R0)
length = arch.arc_length(0, 2 * sp.pi)       # sympy leaves the integral of sqrt(1 - cos s)
per_R = float(length.subs(R, 1).evalf())       # ... so it is evaluated numerically, R = 1
print("length of an arch:", per_R, "R")
assert abs(per_R - 8) < 1e-10

# %%
# The cycloid, with the velocity and the acceleration of M
# --------------------------------------------------------
num = {R: 0.5, w: 2.0}
f_pos = sp.lambdify(rm.t, xy.subs(num), "numpy")
f_v = sp.lambdify(rm.t, v.components(R0).subs(num), "numpy")
f_a = sp.lambdify(rm.t, a.components(R0).subs(num), "numpy")
period = float(2 * sp.pi / num[w])
ts = np.linspace(0, 2 * period, 400)
P = np.array([np.ravel(f_pos(tk))[:2] for tk in ts], dtype=float)
fig, ax = plt.subplots(figsize=(9, 3.6), constrained_layout=True)
ax.plot(P[:, 0], P[:, 1], "k", lw=1, label="cycloid")
for tk in np.linspace(0.1, 2 * period - 0.1, 9):
    p = np.ravel(f_pos(tk))[:2].astype(float)
    vv = np.ravel(f_v(tk))[:2].astype(float)
    aa = np.ravel(f_a(tk))[:2].astype(float)
    ax.quiver(*p, *vv, color="tab:blue", angles="xy", scale_units="xy", scale=4, width=0.004)
    ax.quiver(*p, *aa, color="tab:red", angles="xy", scale_units="xy", scale=8, width=0.004)
ax.plot([], [], color="tab:blue", label="velocity (1 m/s : 0.25 m)")
ax.plot([], [], color="tab:red", label=r"acceleration (1 m/s$^2$ : 0.125 m)")
ax.set(xlabel="x (m)", ylabel="y (m)", aspect="equal", ylim=(-0.3, 1.6),
       title=r"Point of a circle R = 0.5 m rolling at $\omega$ = 2 rad/s")
ax.legend(loc="upper right", fontsize=8)
plt.show()
