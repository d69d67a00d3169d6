"""
Four-bar linkage in motion, with its coupler curve (ch. 13.2, 25.3.3)
=====================================================================

The four-bar of the catalogue -- crank, coupler, rocker, four pivots, one closed loop -- moving
under gravity from an assembled state. The animation draws the three rods and the pivots (the
two on the ground hatched) at each image, and traces the path of a point P of the coupler as
the motion goes: the coupler curve.
"""

# %%
# Assemble and integrate
# ----------------------
import matplotlib.pyplot as plt
import numpy as np

from rigidmech import drawing, models

model = models.four_bar()
system = model.system
R2 = model.frame("R2")
P = model.point("B").moved("P", 1.0 * R2.i + 0.6 * R2.j)    # a point of the coupler
eqs = system.equations_of_motion()
q0, u0 = system.assemble({"q1": 1.0, "q2": -0.6, "q3": 1.4}, independent=["q1"],
                         rates={"q1": 3.0}, m=1.0, g=9.81)
sim = eqs.simulate(t=(0, 2), q0=q0, u0=u0, m=1.0, g=9.81, rtol=1e-10, atol=1e-10)

# %%
# The animation
# -------------
# ``trace=[P]`` draws the path of P up to each image. In every image the loop is closed: the
# coupler's end C and the rocker's end C3 are drawn at the same place.
anim = drawing.animate(sim, n_frames=24, trace=[P], figsize=(4.5, 3.5))
gap = max(np.linalg.norm(p.point(model.point("C")) - p.point(model.point("C3")))
          for p in anim.placements)
assert gap < 1e-6, gap
print(f"largest gap at the closing pivot over the images: {gap:.1e}")
plt.show()
