"""Baumgarte's stabilisation and the time scale of a run: the closure residual of a four-bar
(ground 2, crank 1, coupler 2, rocker 1.5, bars of mass 1, g = 9.81) assembled at q1 = 1 and
integrated without projection (rk4, 500 steps; dop853 with ``project=False``, rtol 1e-6), slow
(crank 1 rad/s over 10 s) and fast (1000 rad/s over 10 ms), for several (alpha, alpha). A
fixed (alpha, beta) acts on the time scale 1/alpha: it helps the slow run, does nothing for the
fast one, and with a fixed step alpha * step >= 1 degrades or destabilises the run. Run::

    PYTHONPATH=src python benchmarks/baumgarte_scale.py
"""

import pathlib
import sys

import numpy as np
import sympy as sp

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "tests" / "systems"))
from mechanisms import four_bar  # noqa: E402

print("command: python benchmarks/baumgarte_scale.py; max |Phi| over the run (status)")
for a in (0.0, 5.0, 50.0, 500.0, 5000.0):
    s, *_ = four_bar(stabilization=(a, a))
    eqs = s.equations_of_motion()
    phi = sp.Matrix([p for _, _, p in s.closure_conditions()])
    row = []
    for w, T in ((1.0, 10.0), (1000.0, 0.01)):
        q0, u0 = s.assemble({"q1": 1.0, "q2": -0.5, "q3": 1.5}, independent=["q1"],
                            rates={"q1": w}, m=1.0, g=9.81)
        for method, options in (("rk4", {"step": T / 500}),
                                ("dop853", {"project": False, "rtol": 1e-6, "atol": 1e-9})):
            sim = eqs.simulate(t=(0, T), q0=list(q0.values()), u0=list(u0.values()), m=1.0,
                               g=9.81, method=method, n_output=201, **options)
            res = np.abs(sim.evaluate(phi)).max()
            row.append(f"{method} {w:g} rad/s: {res:.2e} ({sim.status})")
    print(f"alpha = beta = {a:g}: " + " | ".join(row))
