"""
Heavy top on a ball joint, in space (ch. 9.4.4, 20)
===================================================

The symmetric heavy top of the catalogue: a body on a ball joint at O, its mass centre G at
distance l on its axis, oriented by the Euler angles (precession psi, nutation theta, spin phi).
Its operator of inertia is given by its moments A and C, not by a shape of the catalogue: the
drawing shows it as its mass centre (the quartered disc) with its principal axes of inertia,
joined to the ball joint. A spatial system is drawn in 3D, the vertical up.
"""

# %%
# A fast top
# ----------
import matplotlib.pyplot as plt
import numpy as np

from rigidmech import drawing, models

model = models.heavy_top()
values = {"m": 1.0, "g": 9.81, "l": 1.0, "A": 1.0, "C": 0.5}
eqs = model.system.equations_of_motion()
sim = eqs.simulate(t=(0, 2), q0=[0.0, 0.5, 0.0], u0=[0.0, 0.0, 20.0], rtol=1e-9, atol=1e-9,
                   **values)

# %%
# The animation
# -------------
# The axis OG precesses about the vertical and nods (nutation); in every image G is at
# distance l from O and at the height l cos(theta).
anim = drawing.animate(sim, n_frames=16, figsize=(4, 4))
times, q = drawing.sample_motion(sim, 16)
for p, theta in zip(anim.placements, q[1], strict=True):
    G = p.point(model.point("G"))
    assert abs(np.linalg.norm(G) - 1.0) < 1e-9 and abs(G[2] - np.cos(theta)) < 1e-9
print(f"nutation between {np.degrees(q[1].min()):.1f} and {np.degrees(q[1].max()):.1f} deg")
plt.show()
