"""
The double pendulum derived step by step (ch. 9, 16, 18, 25)
=============================================================

How do the equations of motion of the double pendulum come out of the fundamental principle?
:func:`rigidmech.report.derivation` lays the derivation out the way the book writes it: the
parameters of situation, each rod's kinematic torsor at its pivot, the kinetic and dynamic
torsors at the mass centres, the action torsors (the weights, and the pivots' unknowns
X_1, Y_1, ...), the partial kinematic torsors and the power coefficients, the fundamental
principle for each rod projected on the partial kinematic torsors, and the equations.

Every value in the report is the library's own (the ones the equations were assembled from),
shown with plain symbols (theta1_dot for theta1') and simplified. The report prints as plain
text, as LaTeX (a document to compile with pdflatex, or a fragment), renders in Jupyter, and
writes a ``.tex`` file.
"""

# %%
# The report
# ----------
# Two uniform rods of mass m and length L, absolute angles theta1 and theta2 from the
# downward vertical i (:func:`rigidmech.models.double_pendulum`).
import sympy as sp

import rigidmech as rm
from rigidmech import models, report

pendulum = models.double_pendulum()
derivation = report.derivation(pendulum)
print(derivation)

# %%
# One intermediate against a closed form
# --------------------------------------
# The second rod turns about the pivot A, the tip of the first rod: its kinematic torsor at A
# is {theta2' k ; v(A) = L theta1' j1} (ch. 9.2.4), and the coupling entry of the mass matrix
# is m L^2 cos(theta2 - theta1) / 2 (ch. 25.4.3).
theta1, theta2 = pendulum.coordinates
m, L, g = pendulum.constants
R0, R1 = pendulum.frame("R0"), pendulum.frame("R1")

V2 = derivation.kinematic_torsor("bar2")
print(V2)
difference = (V2.velocity - L * theta1.diff(rm.t) * R1.j).components(R0)
assert sp.simplify(difference) == sp.zeros(3, 1)

M = derivation.equations.mass_matrix
assert sp.simplify(M[0, 1] - m * L**2 * sp.cos(theta2 - theta1) / 2) == 0
print("M_12 =", sp.simplify(M[0, 1]))

# %%
# Lagrange's route
# ----------------
# The same system by Lagrange's equations (ch. 25.3.2): the kinetic energy T, dT/dq_i', its
# derivative, dT/dq_i and the power coefficients Q_i give the same equations.
by_lagrange = report.derivation(pendulum, route="lagrange")
print(by_lagrange.steps[-2].to_text())
assert sp.simplify(by_lagrange.equations.mass_matrix - M) == sp.zeros(2, 2)

# %%
# LaTeX
# -----
# ``to_latex()`` is a complete document (amsmath and geometry only), ``to_latex(standalone=
# False)`` a fragment for a document of one's own, ``write("derivation.tex")`` the file, and
# Jupyter shows the report through ``_repr_latex_``. The kinematic torsors, in LaTeX:
print(derivation.steps[1].to_latex())
