"""
The benchmark bicycle's self-stable region over speed and trail: a parameter sweep (ch. 25.4)
=============================================================================================

The benchmark bicycle of Meijaard et al. (2007) runs itself straight between its weave speed
and its capsize speed (4.292382 and 6.024262 m/s for the paper's trail :math:`c` = 0.08 m).
The trail -- how far behind the steer axis's meeting with the ground the front wheel touches
it -- moves that band. This example keeps the trail a symbol in the derivation, linearises
once, and sweeps the eigenvalues of the linearised motion over a grid of (speed, trail) with
:func:`rigidmech.sweeps.sweep` (chunked, batched in-process; the same call runs on a Dask
cluster with ``backend="dask"``). A point is self-stable when every exponent has a real part
below the library's stability rule (:func:`rigidmech.vibrations.growth` negative).

Checks: the sweep's eigenvalues equal single calls of
:meth:`~rigidmech.vibrations.LinearSystem.eigenvalues` bit for bit, and on the row of the
paper's trail the stable points are exactly those between the weave and capsize speeds found
by :func:`rigidmech.vibrations.critical_value` (equal to the paper's to 1e-6).
"""

# %%
# Derive and linearise once, the trail a symbol
# ---------------------------------------------
import time

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

from rigidmech import models
from rigidmech.sweeps import grid, sweep
from rigidmech.vibrations import critical_value, growth, linearize

start = time.perf_counter()
c = sp.Symbol("c", positive=True)
bike = models.whipple_bicycle(c=c)
eqs = bike.system.equations_of_motion()
v = sp.Symbol("v")
lin = linearize(eqs, velocities={"theta_R": v / models.BENCHMARK_BICYCLE["rR"]},
                parameters={"g": 9.81}, independent=["phi", "delta", "theta_R"],
                simplify=False)
print(f"derived and linearised in {time.perf_counter() - start:.1f} s")

# %%
# The sweep
# ---------
# 101 speeds by 41 trails: each point the six exponents of the linearised motion (the rear
# wheel's angle is cyclic: a pair of zero exponents at every point).
speeds = np.linspace(0.0, 10.0, 101)
trails = np.linspace(0.0, 0.2, 41)
start = time.perf_counter()
result = sweep(lin, grid(v=speeds, c=trails), quantity="eigenvalues", labels="numpy")
print(f"{speeds.size * trails.size} points in {time.perf_counter() - start:.2f} s")
assert result.complete, result.failed
exponents = result.values.values                 # (speed, trail, exponent)
for i, j in ((0, 0), (43, 16), (60, 16), (100, 40)):
    single = np.sort_complex(lin.eigenvalues(v=speeds[i], c=trails[j]))
    np.testing.assert_array_equal(exponents[i, j], single)
stable = np.array([[growth(s) < 0 for s in row] for row in exponents])

# %%
# The paper's trail: the band between weave and capsize
# -----------------------------------------------------
paper = int(np.argmin(abs(trails - 0.08)))
weave = critical_value(lin, "v", (3.0, 5.0), c=0.08)
capsize = critical_value(lin, "v", (5.0, 8.0), c=0.08)
print(f"c = 0.08 m: weave {weave:.6f} m/s, capsize {capsize:.6f} m/s (paper: 4.292382, 6.024262)")
assert abs(weave - 4.292382) < 1e-6 and abs(capsize - 6.024262) < 1e-6
inside = (speeds > weave) & (speeds < capsize)
assert np.array_equal(stable[:, paper], inside)
print(f"self-stable on the sweep's row c = 0.08: {speeds[stable[:, paper]].min():.1f} to "
      f"{speeds[stable[:, paper]].max():.1f} m/s")

# %%
# The map
# -------
fig, ax = plt.subplots(figsize=(7, 4.5), layout="constrained")
ax.contourf(speeds, trails, stable.T.astype(float), levels=[0.5, 1.5], colors=["0.8"])
ax.contour(speeds, trails, stable.T.astype(float), levels=[0.5], colors="k",
           linewidths=0.8)
ax.plot([weave, capsize], [0.08, 0.08], "o", color="tab:red",
        label="weave and capsize speeds at c = 0.08 m")
ax.set_xlabel("forward speed v [m/s]")
ax.set_ylabel("trail c [m]")
ax.set_title("Benchmark bicycle: self-stable region (grey)")
fig.legend(loc="outside lower center")
plt.show()
