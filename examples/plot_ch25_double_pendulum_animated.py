"""
Double pendulum: the drawing and the motion (ch. 25.4.3, 27.5)
==============================================================

The catalogue's double pendulum -- two uniform rods on pivots, gravity down -- drawn the way a
kinematic sketch shows it: each rod as a bar, the pivot at O on the hatched ground, the pivot
at A between the rods, the frames of the rods as small trihedra. Then the same drawing along a
simulated motion, as an animation.
"""

# %%
# The system at one state
# -----------------------
# :func:`rigidmech.drawing.draw` takes the system, the parameters of situation and the values
# of the constants the drawing needs (here the length L). A planar system is drawn in its
# plane, gravity down the page.
import matplotlib.pyplot as plt
import numpy as np

from rigidmech import drawing, models

model = models.double_pendulum()
d = drawing.draw(model, [0.6, 1.2], {"L": 1.0}, frames=True, figsize=(4.5, 4))
print([(c.kind, c.point) for c in d.connections])

# %%
# Along a motion
# --------------
# Integrate the equations of motion, then animate the bodies: 20 images at evenly spaced
# times. Each image is a :class:`~rigidmech.drawing.Placement` of the system: the rods keep
# their length L in every one of them.
eqs = model.system.equations_of_motion()
sim = eqs.simulate(t=(0, 3), q0=[2.0, -0.2], m=1.0, L=1.0, g=9.81, rtol=1e-9, atol=1e-9)
anim = drawing.animate(sim, n_frames=20, figsize=(4, 4))
O = np.zeros(3)
for p in anim.placements:
    A, tip = p.point("A"), p.point("G2") * 2 - p.point("A")
    assert abs(np.linalg.norm(A - O) - 1.0) < 1e-9 and abs(np.linalg.norm(tip - A) - 1.0) < 1e-9
print(f"{len(anim.placements)} images, energy drift {sim.energy_drift():.1e}")
plt.show()
