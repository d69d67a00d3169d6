"""
Lines, planes and the common perpendicular of two lines (ch. 2.2-2.4)
=====================================================================

In the geometric space with the direct orthonormal reference
:math:`(O; \\mathbf{i}, \\mathbf{j}, \\mathbf{k})`, a line is a point and a direction and a plane
a point and a normal (ch. 2.2). The distance of a point :math:`M_0` to the plane
:math:`ax + by + cz + d = 0` (ch. 2.4.1) is :math:`|ax_0 + by_0 + cz_0 + d|/\\sqrt{a^2+b^2+c^2}`,
and two non-parallel lines have one **common perpendicular** (ch. 2.2.4), whose length is
their distance,
:math:`|\\mathbf{A_1A_2}\\cdot(\\mathbf{u}_1\\wedge\\mathbf{u}_2)|/|\\mathbf{u}_1\\wedge\\mathbf{u}_2|`.
"""

# %%
# A plane, a point, and the distance
# ----------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm

R0 = rm.Frame("R0")
P = rm.Plane(R0.point("P0", 1, 0, 0), 2 * R0.i - R0.j + 2 * R0.k)   # 2x - y + 2z - 2 = 0
M0 = R0.point("M0", 3, 1, 4)
d = rm.distance(M0, P)
print("distance of M0 to the plane:", d)
assert sp.simplify(d - sp.Abs(2 * 3 - 1 + 2 * 4 - 2) / 3) == 0

# %%
# Two skew lines and their common perpendicular
# ---------------------------------------------
A1, u1 = R0.point("A1", 0, 0, 0), R0.i + R0.j
A2, u2 = R0.point("A2", 1, 0, 2), R0.j - R0.k
D1, D2 = rm.Line(A1, u1), rm.Line(A2, u2)
H1, H2 = rm.common_perpendicular(D1, D2)
H1H2 = H2.position - H1.position
print("H1 =", list(H1.coordinates(R0)), "| H2 =", list(H2.coordinates(R0)))

# %%
# Check: H1H2 is orthogonal to both lines, its length is the closed-form distance
# -------------------------------------------------------------------------------
n = rm.cross(u1, u2)
assert sp.simplify(rm.dot(H1H2, u1)) == 0 and sp.simplify(rm.dot(H1H2, u2)) == 0
closed = sp.Abs(rm.dot(A2.position - A1.position, n)) / n.magnitude()
assert sp.simplify(H1H2.magnitude() - closed) == 0
assert sp.simplify(rm.distance(D1, D2) - closed) == 0
print("distance between the lines:", sp.nsimplify(closed))

# %%
# Drawing
# -------


def xyz(point):
    return np.array(point.coordinates(R0), dtype=float).ravel()


def comps(vec):
    return np.array(vec.components(R0), dtype=float).ravel()


s = np.linspace(-2, 2, 2)[:, None]
fig = plt.figure(figsize=(6.5, 5.5))
ax = fig.add_subplot(projection="3d")
ax.plot(*(xyz(A1) + s * comps(u1)).T, label="line D1")
ax.plot(*(xyz(A2) + s * comps(u2)).T, label="line D2")
h = np.array([xyz(H1), xyz(H2)])
ax.plot(*h.T, "k-o", label="common perpendicular H1H2")
ax.set(xlabel="x (m)", ylabel="y (m)", zlabel="z (m)", title="Common perpendicular of two lines")
ax.legend(loc="upper left")
fig.tight_layout()
plt.show()
