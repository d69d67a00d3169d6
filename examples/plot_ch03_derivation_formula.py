"""
Derivative of a vector function relative to two bases (ch. 3.1)
===============================================================

The derivative of a vector function :math:`\\mathbf{u}(t)` depends on the basis it is taken
relative to (ch. 3.1.2). When the basis :math:`(\\mathbf{i}_1, \\mathbf{j}_1, \\mathbf{k}_1)`
turns relative to :math:`(\\mathbf{i}_0, \\mathbf{j}_0, \\mathbf{k}_0)` by the angle
:math:`\\psi(t)` about :math:`\\mathbf{k}_0`, the derivatives of the basis vectors are
:math:`\\frac{d\\mathbf{i}_1}{dt} = \\dot\\psi\\,\\mathbf{j}_1`,
:math:`\\frac{d\\mathbf{j}_1}{dt} = -\\dot\\psi\\,\\mathbf{i}_1` (ch. 3.1.4), and for any
vector function

.. math:: \\frac{d\\mathbf{u}}{dt}\\Big|_{0} = \\frac{d\\mathbf{u}}{dt}\\Big|_{1}
          + \\dot\\psi\\,\\mathbf{k}_0 \\wedge \\mathbf{u}.
"""

# %%
# A vector function written in the turning basis
# ----------------------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech import vectors

psi = rm.coordinates("psi")
a, b = rm.constants("a b", positive=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=psi)
u = a * rm.t * R1.i + b * R1.k

du_0 = u.dt(R0)                                        # relative to the basis of R0
du_1 = u.dt(R1)                                        # relative to the basis of R1
print("du/dt|0 =", du_0)
print("du/dt|1 =", du_1)

# %%
# Check: the derivation formula, and the components route
# -------------------------------------------------------
via = vectors.derivation_formula(u, R0, R1)
correction = rm.cross(psi.diff(rm.t) * R0.k, u)
assert sp.simplify((du_0 - du_1 - correction).components(R0)) == sp.zeros(3, 1)
assert sp.simplify((via - du_0).components(R0)) == sp.zeros(3, 1)
# independent route: differentiate the components in R0 one by one
by_components = u.components(R0).diff(rm.t)
assert sp.simplify(du_0.components(R0) - by_components) == sp.zeros(3, 1)

# %%
# The two derivatives along a uniform rotation
# --------------------------------------------
# With :math:`\psi = \omega t` the derivative relative to R1 is constant, :math:`a\,\mathbf{i}_1`,
# while the one relative to R0 grows with the term :math:`a\omega t\,\mathbf{j}_1`.
w = 1.5
num = {a: 1.0, b: 0.5}
t_s = sp.Symbol("t_s")
norm0 = sp.lambdify(t_s, du_0.magnitude().subs(psi.diff(rm.t), w).subs(psi, w * rm.t)
                    .subs(num).subs(rm.t, t_s), "numpy")
tt = np.linspace(0, 4, 200)
values = norm0(tt)
assert np.allclose(values, np.sqrt(1 + (w * tt) ** 2))
fig, ax = plt.subplots(figsize=(6.5, 4), constrained_layout=True)
ax.plot(tt, values, label=r"$|d\mathbf{u}/dt|_0|$")
ax.plot(tt, np.ones_like(tt), "--", label=r"$|d\mathbf{u}/dt|_1| = a$")
ax.set(xlabel="time t (s)", ylabel="magnitude (m/s)",
       title=r"$\mathbf{u} = a t\,\mathbf{i}_1 + b\,\mathbf{k}_1$, $\psi = \omega t$, "
       r"$\omega$ = 1.5 rad/s")
ax.legend()
plt.show()
