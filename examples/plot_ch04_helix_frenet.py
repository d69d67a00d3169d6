"""
Frenet trihedron of a circular helix (ch. 4.3-4.4)
==================================================

The circular helix r(s) = a cos s i + a sin s j + b s k winds on a cylinder of radius a with
the pitch 2 pi b. We compute its **Frenet trihedron** (T, N, B), its curvature and its torsion
symbolically, compare them with the closed forms kappa = a / (a^2 + b^2) and
tau = b / (a^2 + b^2), check the estimates made from samples of the curve, and draw the trihedron
at a few points.

Book conventions: T = dr/dsigma (sigma the curvilinear abscissa), dT/dsigma = kappa N,
B = T ^ N, dB/dsigma = -tau N, so that a right-handed helix (b > 0) has a positive torsion.
"""

# %%
# The curve and its trihedron, symbolically
# -----------------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

from rigidmech.vectors import Frame
from rigidmech.vectors.curves import Curve, frenet_numeric

R0 = Frame("R0")
s = sp.Symbol("s", real=True)
a, b = sp.symbols("a b", positive=True)
helix = Curve(R0.vector(a * sp.cos(s), a * sp.sin(s), b * s), s, R0)

T, N, B, kappa, tau = helix.frenet()
print("T =", T)
print("N =", N)
print("B =", B)
print("curvature:", kappa, "| closed form:", a / (a**2 + b**2))
print("torsion:  ", tau, "| closed form:", b / (a**2 + b**2))
print("length of one turn:", helix.arc_length(0, 2 * sp.pi))

# %%
# Numbers, and the estimate from samples
# --------------------------------------
# With a = 1 and b = 0.3, the spline through 200 samples of one turn gives the curvature and
# the torsion to about 1e-4 away from the ends (see ``frenet_numeric``).
values = {a: 1, b: sp.Rational(3, 10)}
kappa_exact = float(kappa.subs(values))
tau_exact = float(tau.subs(values))
u = np.linspace(0, 2 * np.pi, 200)
points = np.column_stack([np.cos(u), np.sin(u), 0.3 * u])
sampled = frenet_numeric(points, u)
inner = slice(20, -20)
print(f"curvature {kappa_exact:.6f}, from samples {sampled.curvature[inner].mean():.6f} "
      f"(max error {np.abs(sampled.curvature[inner] - kappa_exact).max():.1e})")
print(f"torsion   {tau_exact:.6f}, from samples {sampled.torsion[inner].mean():.6f} "
      f"(max error {np.abs(sampled.torsion[inner] - tau_exact).max():.1e})")

# %%
# Drawing the trihedron at a few points
# -------------------------------------
# T (red) is tangent to the helix, N (green) points horizontally to the axis of the cylinder,
# B (blue) leans against the axis by the helix angle.
helix_1 = Curve(R0.vector(sp.cos(s), sp.sin(s), sp.Rational(3, 10) * s), s, R0)


def xyz(vector):
    return np.array(vector.components(R0).evalf(), dtype=float).ravel()


fig = plt.figure(figsize=(6, 6))
ax = fig.add_subplot(projection="3d")
ax.plot(*points.T, color="0.4", lw=1)
for s0 in np.linspace(0.3, 2 * np.pi - 0.3, 5):
    frame = helix_1.frenet(at=sp.Float(s0))
    origin = xyz(helix_1.position(at=sp.Float(s0)))
    for vector, colour in zip(frame[:3], ("tab:red", "tab:green", "tab:blue"), strict=True):
        ax.quiver(*origin, *(0.4 * xyz(vector)), color=colour, lw=2)
ax.set_xlabel("x")
ax.set_ylabel("y")
ax.set_zlabel("z")
ax.set_title("Helix a = 1, b = 0.3: Frenet trihedra (T red, N green, B blue)")
ax.set_box_aspect((1, 1, 0.9))
plt.show()
