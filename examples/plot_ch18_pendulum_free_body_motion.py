"""
The free-body diagram of a swinging pendulum along its motion (ch. 18.2, 20)
============================================================================

A homogeneous bar OA of mass :math:`m` and length :math:`L` turns about a pivot at :math:`O`
under gravity. Isolated, it receives two actions: its weight :math:`m\\mathbf{g}` at its mass
centre :math:`G` and the action of the pivot at :math:`O`, whose components
:math:`(X_1, Y_1)` statics cannot give: along a motion they come from the fundamental principle
(ch. 18.2), :math:`m\\,\\mathbf{a}(G) = \\mathbf{R}_{pivot} + m\\,\\mathbf{g}`.

**Conventions.** Gravity is :math:`g\\,\\mathbf{i}_0` (:math:`\\mathbf{i}_0` points down the
page); :math:`\\theta` is the angle from :math:`\\mathbf{i}_0` to the bar's axis
:math:`\\mathbf{i}_1`. With :math:`OG = \\frac{L}{2}\\,\\mathbf{i}_1` and the equation of motion
:math:`\\ddot\\theta = -\\frac{3g}{2L}\\sin\\theta`,

.. math:: \\mathbf{R}_{pivot} = m\\,\\tfrac{L}{2}\\,(\\ddot\\theta\\,\\mathbf{j}_1 -
   \\dot\\theta^2\\,\\mathbf{i}_1) - m g\\,\\mathbf{i}_0 .

Released from :math:`\\theta_0 = 1.5` rad, at the bottom of the swing (:math:`\\theta = 0`,
:math:`\\dot\\theta^2 = \\frac{3g}{L}(1 - \\cos\\theta_0)`) the pivot pulls up with
:math:`m g\\,(\\frac52 - \\frac32\\cos\\theta_0)`, 2.4 times the weight.

:func:`~rigidmech.drawing.free_body_motion` draws the isolated bar at chosen instants, every
arrow to one force scale for the whole motion (its key in the last panel), with the values of
the pivot's components.
"""

# %%
# The motion
# ----------
import matplotlib.pyplot as plt
import numpy as np

from rigidmech import drawing, models

pendulum = models.compound_pendulum()
bar, R0 = pendulum.body("bar"), pendulum.frame("R0")
values = {"m": 1.0, "L": 1.0, "g": 9.81}
theta0 = 1.5
sim = pendulum.system.equations_of_motion().simulate(
    t=(0, 1.2), q0=[theta0], n_output=241, rtol=1e-11, atol=1e-12, **values)

# %%
# The diagram at four instants, the bottom of the swing among them
# ----------------------------------------------------------------
theta, rate = sim.q[0], sim.u[0]
bottom = int(np.argmin(np.abs(theta[: np.argmax(theta < 0) + 1])))   # first pass at 0
times = [0.0, 0.2, float(sim.t[bottom]), 0.8]
motion = drawing.free_body_motion(sim, bar, times=times, scale=40.0)   # 40 N per metre
fig = motion.plot()
print("instants:", motion.times.round(3).tolist(), "| force scale:",
      f"{motion.scale:.3g} N per unit of length")

# %%
# Check: the drawn arrow is the simulation's connection action, and the closed form
# ----------------------------------------------------------------------------------
# At the bottom of the swing (the third panel) the arrow of the pivot is the action
# :meth:`Simulation.connection_action <rigidmech.dynamics.Simulation.connection_action>`
# gives at that sample, and the closed form above at the sample's state.
k = 2
pivot, weight = motion.actions[k]
N = sim.connection_action(R0, bar, basis=R0)
n = bottom
from_simulation = np.array([N["X"][n], N["Y"][n], N["Z"][n]])
assert np.allclose(pivot.force, from_simulation, rtol=1e-12, atol=1e-12)

m, L, g = values["m"], values["L"], values["g"]
th, w = theta[n], rate[n]
i1, j1 = np.array([np.cos(th), np.sin(th), 0]), np.array([-np.sin(th), np.cos(th), 0])
closed_form = m * L / 2 * (-1.5 * g / L * np.sin(th) * j1 - w**2 * i1) - m * g * np.eye(3)[0]
assert np.allclose(pivot.force, closed_form, rtol=1e-8, atol=1e-8)
assert np.allclose(weight.force, [m * g, 0, 0])

# the arrow drawn on the panel: the force in the view's coordinates, divided by the scale
panel = motion.draw(k, ax=plt.figure().add_subplot())
(arrow,) = [a for a in panel.arrows if a.name == "1"]
expected = motion.view.rows @ pivot.force / motion.scale
assert np.allclose(arrow.vector[:2], expected[:2], rtol=1e-12, atol=1e-12)
plt.close(panel.ax.figure)
lowest = m * g * (2.5 - 1.5 * np.cos(theta0))
print(f"pivot at the bottom: |R| = {np.linalg.norm(pivot.force):.4f} N at theta = {th:.1e} "
      f"(closed form at theta = 0: {lowest:.4f} N)")
plt.show()
