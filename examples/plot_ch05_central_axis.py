"""
Central axis of a system of forces (ch. 5.1.7, 5.2.3)
=====================================================

Four forces act on a body at the corners of a unit cube. Their torsor {R ; M(O)} (ch. 5.3.1)
is reduced to its **simplest form** (ch. 5.2.3-5.2.4): a slider of resultant R on the central
axis plus a couple parallel to R, whose moment is the least moment of the field. We draw the
forces, the central axis, and on it the resultant and the minimal moment.

Book conventions: M(B) = M(A) + BA ^ R; the automoment R . M is the same at every point; the
central axis is the line of direction R through I, with OI = R ^ M(O) / R^2; the least moment
is (R . M / R^2) R.
"""

# %%
# The forces and their torsor
# ---------------------------
# Each force is a slider (point of application, force); the torsor of the set is reduced at
# the origin O of R0.
import matplotlib.pyplot as plt
import numpy as np

import rigidmech as rm
from rigidmech.torsors import torsor_of_sliders

R0 = rm.Frame("R0")
forces = [
    (R0.point("A", 1, 0, 0), 2 * R0.j),
    (R0.point("B", 0, 1, 1), R0.i - R0.k),
    (R0.point("C", 1, 1, 0), R0.k),
    (R0.point("D", 0, 0, 1), R0.i + R0.j),
]
T = torsor_of_sliders(forces, at=R0.origin)
print(T)
print("kind:", T.kind, "| automoment:", T.automoment, "| pitch:", T.pitch)

# %%
# Central axis and simplest form
# ------------------------------
# The simplest form is the slider on the central axis plus the couple of least moment; its sum
# is the torsor again, at every point.
axis = T.central_axis()
form = T.simplest_form()
print("central point I:", list(axis.point.coordinates(R0)))
print(form)
assert form.torsor.equals(T)

# %%
# Check: the moment is least on the axis
# --------------------------------------
# ``|M(P)|^2 = |M(I)|^2 + |IP ^ R|^2``: the norm of the moment grows with the distance to
# the axis.
for P in (R0.origin, R0.point("E", 2, -1, 3), axis.point):
    print(P.name, float(T.moment_at(P).magnitude()))


# %%
# Drawing
# -------
def xyz(point):
    return np.array(point.coordinates(R0), dtype=float).ravel()


def comps(vector):
    return np.array(vector.components(R0), dtype=float).ravel()


fig = plt.figure(figsize=(6.5, 6))
ax = fig.add_subplot(projection="3d")
for P, F in forces:
    p, f = xyz(P), comps(F)
    ax.quiver(*p, *f, color="tab:blue", arrow_length_ratio=0.15)
    ax.text(*p, P.name, color="tab:blue")
I, r = xyz(axis.point), comps(axis.direction)
line = I + np.outer(np.linspace(-1.2, 1.2, 2), r / np.linalg.norm(r) * 2.5)
ax.plot(*line.T, "k--", label="central axis")
ax.quiver(*I, *r, color="tab:red", arrow_length_ratio=0.1, label="resultant R")
m = comps(form.couple.moment)  # small here (pitch 1/13): drawn 4 times longer
ax.quiver(*I, *(4 * m), color="tab:green", linewidth=2.5, arrow_length_ratio=0.3,
          label="least moment M(I), x4")
ax.scatter(*I, color="k")
ax.text(*I, " I", color="k")
ax.set(xlabel="x", ylabel="y", zlabel="z", title="Forces reduced to their central axis")
ax.legend(loc="upper left")
plt.show()
