"""Drift of the loop closure of an integrated four-bar linkage over a long time: Baumgarte's
stabilisation (rigidmech.dynamics.constraints) and the projection after every step
(``simulate(project=...)``), each on or off.

The four-bar of ``derive_loops.py`` (m = 1, g = 9.81) is assembled at q1 = 1 with q1' = 1
and integrated over T with dop853; the closure residual max |Phi| is printed over the whole
run and per tenth of it (a growing residual would show in the tenths), with the energy drift
and the CPU time of the integration, for the four combinations (Baumgarte alpha = beta, or
0; projection on or off). Run::

    PYTHONPATH=src python benchmarks/loop_drift.py [alpha] [rtol] [T]     # defaults 5 1e-8 1000
"""

import pathlib
import sys
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from derive_loops import four_bar_system  # noqa: E402

alpha = float(sys.argv[1]) if len(sys.argv) > 1 else 5.0
rtol = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-8
T = float(sys.argv[3]) if len(sys.argv) > 3 else 1000.0
print(f"command: python {' '.join(sys.argv)}; dop853, rtol = {rtol}, T = {T}")
print(f"{'Baumgarte':>10} {'project':>8} {'max |Phi|':>10} {'energy drift':>13} "
      f"{'steps':>7} {'CPU s':>6}  max |Phi| per tenth")
for a in (alpha, 0.0):
    s = four_bar_system(stabilization=(a, a))
    eqs = s.equations_of_motion()
    q0, u0 = s.assemble({"q1": 1.0, "q2": -0.5, "q3": 1.5}, independent=["q1"],
                        rates={"q1": 1.0}, m=1.0, g=9.81)
    for project in (False, True):
        t0 = time.process_time()
        sim = eqs.simulate(t=(0, T), q0=q0, u0=u0, m=1.0, g=9.81, n_output=int(T * 20) + 1,
                           rtol=rtol, project=project)
        elapsed = time.process_time() - t0
        res = np.abs(np.array([sim.evaluate(p) for _, _, p in s.closure_conditions()])).max(
            axis=0)
        w = len(res) // 10
        tenths = " ".join(f"{res[i * w:(i + 1) * w + 1].max():.0e}" for i in range(10))
        print(f"{a:>10g} {str(project):>8} {res.max():>10.2e} {sim.energy_drift():>13.1e} "
              f"{sim.result.nsteps:>7} {elapsed:>6.1f}  {tenths}")
