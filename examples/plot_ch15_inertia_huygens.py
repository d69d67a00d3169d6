"""
Operator of inertia of a parallelepiped at a corner: relations of Huygens (ch. 15)
==================================================================================

The operator of inertia of a homogeneous rectangular parallelepiped of mass :math:`m` and
edges :math:`a, b, c` is diagonal at its mass centre :math:`G` in the basis of its edges
(ch. 15.5.3). At the corner :math:`O` it follows from the **relations of Huygens**
(ch. 15.2.2),

.. math:: \\mathcal{J}_O(S) = \\mathcal{J}_G(S) + \\mathcal{J}_O(G, m),

where :math:`\\mathcal{J}_O(G, m)` is the operator at :math:`O` of the mass :math:`m`
concentrated at :math:`G`. In the book's layout the matrix is
:math:`\\begin{bmatrix} A & -F & -E \\\\ -F & B & -D \\\\ -E & -D & C\\end{bmatrix}`, with the
products of inertia :math:`D = \\int yz\\,dm`, :math:`E = \\int zx\\,dm`,
:math:`F = \\int xy\\,dm`. The moment of inertia about an axis :math:`(O, \\mathbf{u})` is
:math:`\\mathbf{u}\\cdot\\mathcal{J}_O(\\mathbf{u})` (ch. 15.3.4).
"""

# %%
# At the mass centre, then at the corner
# --------------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm

m, a, b, c = rm.constants("m a b c", positive=True)
R0 = rm.Frame("R0")                      # origin O at a corner, edges along i, j, k
G = R0.point("G", a / 2, b / 2, c / 2)
J_G = rm.inertia.block(m, a, b, c, frame=R0).placed_at(G)
J_O = J_G.moved(R0.origin, mass=m, centre=G)
print("J_G =", J_G.matrix)
print("J_O =", J_O.matrix)

# %%
# Check: direct integration over the volume
# -----------------------------------------
# An independent route: :math:`A = \int (y^2 + z^2)\,dm`, :math:`D = \int yz\,dm`, ... with
# :math:`dm = \frac{m}{abc}\,dx\,dy\,dz` over the box :math:`[0,a]\times[0,b]\times[0,c]`.
x, y, z = sp.symbols("x y z", real=True)


def integral(f):
    return sp.integrate(m / (a * b * c) * f, (x, 0, a), (y, 0, b), (z, 0, c))


A_, B_, C_ = integral(y**2 + z**2), integral(z**2 + x**2), integral(x**2 + y**2)
D_, E_, F_ = integral(y * z), integral(z * x), integral(x * y)
direct = sp.Matrix([[A_, -F_, -E_], [-F_, B_, -D_], [-E_, -D_, C_]])
assert sp.simplify(J_O.matrix - direct) == sp.zeros(3, 3)
print("A =", sp.factor(J_O.A), "| D =", sp.factor(J_O.D))

# %%
# Moment of inertia about the diagonal of the block
# -------------------------------------------------
# By symmetry the diagonal from the corner :math:`O` passes through :math:`G`, and the known
# result is :math:`m (a^2 b^2 + b^2 c^2 + c^2 a^2) / (6 (a^2 + b^2 + c^2))`.
diagonal = a * R0.i + b * R0.j + c * R0.k
I_diag = sp.simplify(J_O.moment_about(diagonal))
print("I about the diagonal:", I_diag)
expected = m * (a**2 * b**2 + b**2 * c**2 + c**2 * a**2) / (6 * (a**2 + b**2 + c**2))
assert sp.simplify(I_diag - expected) == 0
# the same at G (the diagonal passes through G: Huygens adds nothing)
assert sp.simplify(J_G.moment_about(diagonal) - I_diag) == 0

# %%
# Principal axes at the corner, numerically
# -----------------------------------------
values = {m: 6.0, a: 3.0, b: 2.0, c: 1.0}
J_num = J_O.subs(values)
axes = J_num.principal_axes()
print("principal moments at O:", [round(float(v), 4) for v in axes.moments])
eig = np.linalg.eigvalsh(np.array(J_num.matrix, dtype=float))
assert np.allclose(sorted(float(v) for v in axes.moments), eig, rtol=1e-10)

# %%
# Moment of inertia about the axes through O in the plane (O, i, j)
# -----------------------------------------------------------------
# :math:`I(\alpha) = A\cos^2\alpha + B\sin^2\alpha - 2F\sin\alpha\cos\alpha`: its extremes are
# the principal moments of the plane section of the operator.
alpha = np.linspace(0, np.pi, 181)
I_alpha = [float(J_num.moment_about(np.cos(t) * R0.i + np.sin(t) * R0.j)) for t in alpha]
An, Bn, Fn = (float(v) for v in (J_num.A, J_num.B, J_num.F))
assert np.allclose(I_alpha, An * np.cos(alpha) ** 2 + Bn * np.sin(alpha) ** 2
                   - 2 * Fn * np.sin(alpha) * np.cos(alpha))
fig, ax = plt.subplots(figsize=(7, 4), constrained_layout=True)
ax.plot(np.degrees(alpha), I_alpha)
ax.set(xlabel=r"angle $\alpha$ of the axis from $\mathbf{i}$ (degrees)",
       ylabel=r"moment of inertia (kg m$^2$)",
       title="Block 3 x 2 x 1 m, 6 kg:\naxes through the corner O in the plane (O, i, j)")
plt.show()
