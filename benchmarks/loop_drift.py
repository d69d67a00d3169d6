"""Drift of the loop closure of an integrated four-bar linkage over a long time, with
Baumgarte's stabilisation (rigidmech.dynamics.constraints).

The four-bar of ``derive_loops.py`` (m = 1, g = 9.81) is assembled at q1 = 1 with q1' = 1
and integrated over T with dop853; the closure residual max |Phi| is printed over the whole
run and per tenth of it (a growing residual would show in the tenths), with the energy drift.
Run::

    PYTHONPATH=src python benchmarks/loop_drift.py [alpha] [rtol] [T]     # defaults 5 1e-9 1000
"""

import pathlib
import sys
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from derive_loops import four_bar_system  # noqa: E402

alpha = float(sys.argv[1]) if len(sys.argv) > 1 else 5.0
rtol = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-9
T = float(sys.argv[3]) if len(sys.argv) > 3 else 1000.0
s = four_bar_system(stabilization=(alpha, alpha))
eqs = s.equations_of_motion()
q0, u0 = s.assemble({"q1": 1.0, "q2": -0.5, "q3": 1.5}, independent=["q1"],
                    rates={"q1": 1.0}, m=1.0, g=9.81)
t0 = time.perf_counter()
sim = eqs.simulate(t=(0, T), q0=q0, u0=u0, m=1.0, g=9.81, n_output=int(T * 20) + 1, rtol=rtol)
elapsed = time.perf_counter() - t0
res = np.abs(np.array([sim.evaluate(p) for _, _, p in s.closure_conditions()])).max(axis=0)
w = len(res) // 10
print(f"alpha = beta = {alpha}, rtol = {rtol}, T = {T}: max |Phi| = {res.max():.2e}")
print("per tenth:", " ".join(f"{res[i * w:(i + 1) * w + 1].max():.1e}" for i in range(10)))
print(f"energy drift {sim.energy_drift():.1e}; integration {elapsed:.1f} s")
