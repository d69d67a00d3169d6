"""
A ladder against a wall at its limiting equilibrium, with both friction cones (ch. 14)
======================================================================================

A uniform ladder AB of length :math:`L` and weight :math:`W = m g` leans against a vertical
wall, its foot :math:`A` on the ground (static friction coefficient :math:`f_1`), its top
:math:`B` against the wall (coefficient :math:`f_2`). It makes the angle :math:`\\alpha` with
the ground. How low can :math:`\\alpha` go before the ladder slips?

**Conventions.** :math:`R_0` has :math:`\\mathbf{i}` horizontal, away from the wall (the wall
is the plane :math:`x = 0`), and :math:`\\mathbf{j}` up (the ground is :math:`y = 0`):
:math:`A = (L\\cos\\alpha, 0)`, :math:`B = (0, L\\sin\\alpha)`, :math:`G` the middle of AB.
The ground acts on the ladder at :math:`A` by :math:`N_A\\mathbf{j} + T_A\\mathbf{i}`, the wall
at :math:`B` by :math:`N_B\\mathbf{i} + T_B\\mathbf{j}` (normals into the ladder, ch. 13.1).

With friction at both ends statics alone leaves one unknown free (the ladder is hyperstatic
of degree 1). At the limit both contacts slide at once: the foot away from the wall
(:math:`T_A = -f_1 N_A`) and the top down the wall (:math:`T_B = +f_2 N_B`), each action on the
edge of its **friction cone** of half-angle :math:`\\arctan f` (ch. 13.1.2). The equations of
statics (ch. 14.2) -- horizontal :math:`N_B + T_A = 0`, vertical :math:`N_A + T_B = W`, moments
about :math:`A`: :math:`N_B L\\sin\\alpha + T_B L\\cos\\alpha = W \\frac{L}{2}\\cos\\alpha` -- give
:math:`N_A = W/(1 + f_1 f_2)` and

.. math:: \\tan\\alpha_{min} = \\frac{1 - f_1 f_2}{2 f_1}.
"""

# %%
# The ladder and its two contacts with friction
# ---------------------------------------------
# The catalogue builds it (:func:`rigidmech.models.ladder`): a problem of statics, its two
# contacts labelled ``"A"`` (ground) and ``"B"`` (wall), the angle ``alpha`` a constant.
import math

import matplotlib.pyplot as plt

from rigidmech import models
from rigidmech.drawing import free_body_diagram, limiting_values

f1, f2 = 0.4, 0.3                              # ground, wall
model = models.ladder(f1, f2)
statics, ladder, alpha = model.system, model.body("ladder"), model.constant("alpha")
values = {"m": 10.0, "g": 9.81, "L": 4.0}
print("unknowns:", statics.unknowns,
      "| hyperstaticity at 60 deg:",
      statics.solve(values={**values, "alpha": math.radians(60)}).hyperstaticity)

# %%
# The limiting angle, found by statics and checked against the closed form
# ------------------------------------------------------------------------
# :meth:`~rigidmech.statics.Statics.limit` lowers the angle from 80 degrees until the laws of
# the contacts can no longer all hold.
limit = statics.limit(alpha, (math.radians(80), math.radians(3)), values=values)
closed_form = math.atan((1 - f1 * f2) / (2 * f1))
print(limit)
print(f"alpha_min = {math.degrees(limit.value):.6f} deg, closed form "
      f"{math.degrees(closed_form):.6f} deg")
assert abs(limit.value - closed_form) < 1e-9 * closed_form
assert set(limit.contacts) == {"A", "B"} and limit.kinds == ("sliding",)

# %%
# The actions at the limit
# ------------------------
# At the limit the feasible actions reduce to one: both on the edges of their cones.
actions = limiting_values(statics, limit, values=values)
W = values["m"] * values["g"]
N_A = W / (1 + f1 * f2)
expected = {"N_A": N_A, "T_A": -f1 * N_A, "N_B": f1 * N_A, "T_B": f1 * f2 * N_A}
for unknown, value in actions.items():
    print(f"{unknown} = {value:9.4f}   (closed form {expected[unknown.name]:9.4f})")
    assert abs(value - expected[unknown.name]) < 1e-8 * W

# %%
# The free-body diagram of the ladder
# -----------------------------------
# The ladder isolated: its weight at :math:`G`, the ground's and the wall's actions at
# :math:`A` and :math:`B` drawn to the force scale of the key, each with its friction cone;
# the edge each action lies on is drawn thick.
fig, ax = plt.subplots(figsize=(6, 6))
diagram = free_body_diagram(statics, ladder, params={**values, "alpha": limit.value},
                            values=actions, ax=ax)
ax.set_title(f"limiting equilibrium: alpha = {math.degrees(limit.value):.2f} deg")
print([(a.label, a.cone.status) for a in diagram.actions if a.cone is not None])
assert all(a.cone.status == "edge" for a in diagram.actions if a.cone is not None)

# %%
# Before the solve: the unknowns by their names
# ---------------------------------------------
# Without values, each contact shows its unknown components along their axes, named as
# :mod:`rigidmech.actions` names them.
fig, ax = plt.subplots(figsize=(6, 6))
free_body_diagram(statics, ladder, params={**values, "alpha": math.radians(60)}, ax=ax)
ax.set_title("alpha = 60 deg: the unknowns")
plt.show()
