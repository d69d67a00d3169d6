"""
Scalar and vector products in an arbitrary basis (ch. 1)
========================================================

Three vectors :math:`\\mathbf{e}_1, \\mathbf{e}_2, \\mathbf{e}_3` form a basis of the vector
space when they are linearly independent (ch. 1.2.3), that is when their mixed product is not
zero. In an arbitrary (non-orthonormal) basis the scalar product of
:math:`\\mathbf{u} = u^i\\mathbf{e}_i` and :math:`\\mathbf{v} = v^j\\mathbf{e}_j` is
:math:`g_{ij}u^iv^j` with the metric :math:`g_{ij} = \\mathbf{e}_i\\cdot\\mathbf{e}_j`
(ch. 1.3.3), and the vector product is expressed with the products
:math:`\\mathbf{e}_j\\wedge\\mathbf{e}_k` (ch. 1.4.2). We check these expressions against the
components in an orthonormal basis (ch. 1.3.6, 1.4.4), and the property of the double vector
product (ch. 1.4.6), :math:`\\mathbf{u}\\wedge(\\mathbf{v}\\wedge\\mathbf{w}) =
(\\mathbf{u}\\cdot\\mathbf{w})\\,\\mathbf{v} - (\\mathbf{u}\\cdot\\mathbf{v})\\,\\mathbf{w}`.
"""

# %%
# A basis that is neither orthogonal nor normed
# ---------------------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech import vectors

R0 = rm.Frame("R0")                       # the orthonormal direct basis (i, j, k)
e1, e2, e3 = 2 * R0.i, R0.i + R0.j, R0.i + R0.j + 3 * R0.k
print("independent:", rm.linearly_independent(e1, e2, e3),
      "| mixed product (e1, e2, e3) =", rm.mixed(e1, e2, e3))
b = vectors.Basis(e1, e2, e3)
print("metric g_ij =", b.metric.tolist(), "| direct:", b.is_direct)
assert rm.linearly_independent(e1, e2, e3) and rm.mixed(e1, e2, e3) == 6
# three coplanar vectors: a relation of linear dependence
print("e1, e2, e1 + 2 e2 dependent:", vectors.linear_dependence(e1, e2, e1 + 2 * e2))

# %%
# Components and products in the basis
# ------------------------------------
u = 3 * R0.i - R0.j + 2 * R0.k
v = R0.i + 4 * R0.j - R0.k
uc, vc = b.components_of(u), b.components_of(v)
print("u = u^i e_i with (u^i) =", list(uc))
# the components rebuild the vector
assert sp.simplify((uc[0] * e1 + uc[1] * e2 + uc[2] * e3 - u).components(R0)) == sp.zeros(3, 1)

# %%
# Check: g_ij u^i v^j is the scalar product, and the vector product by the formula of ch. 1.4.2
# ---------------------------------------------------------------------------------------------
assert sp.simplify((uc.T * b.metric * vc)[0] - rm.dot(u, v)) == 0
w_formula = ((uc[1] * vc[2] - uc[2] * vc[1]) * rm.cross(e2, e3)
             + (uc[2] * vc[0] - uc[0] * vc[2]) * rm.cross(e3, e1)
             + (uc[0] * vc[1] - uc[1] * vc[0]) * rm.cross(e1, e2))
assert (w_formula - rm.cross(u, v)).components(R0) == sp.zeros(3, 1)
print("u . v =", rm.dot(u, v), "| u ^ v =", rm.cross(u, v))

# %%
# Check: the double vector product
# --------------------------------
a, c = rm.constants("a c")
w = a * R0.i + c * R0.k
lhs = rm.double_cross(u, v, w)
rhs = rm.dot(u, w) * v - rm.dot(u, v) * w
assert sp.expand((lhs - rhs).components(R0)) == sp.zeros(3, 1)

# %%
# The basis and the vectors
# -------------------------


def comps(vec):
    return np.array(vec.components(R0), dtype=float).ravel()


fig = plt.figure(figsize=(6.5, 5.5))
ax = fig.add_subplot(projection="3d")
for vec, name, color in ((e1, "e1", "tab:blue"), (e2, "e2", "tab:blue"), (e3, "e3", "tab:blue"),
                         (u, "u", "tab:red"), (v, "v", "tab:green"),
                         (rm.cross(u, v) / 5, "(u ^ v)/5", "tab:purple")):
    x = comps(vec)
    ax.quiver(0, 0, 0, *x, color=color, arrow_length_ratio=0.1)
    ax.text(*x, name, color=color)
ax.set(xlabel="x", ylabel="y", zlabel="z", xlim=(-2, 3), ylim=(-3, 4), zlim=(-1, 3),
       title="An arbitrary basis (blue) and two vectors")
fig.tight_layout()
plt.show()
