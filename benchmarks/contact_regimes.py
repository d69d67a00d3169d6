"""CPU time of a motion with dry friction three ways: the regimes derived from a System with
FrictionContact (rigidmech.regimes.contact_motion: derivation and compilation, then
integration), the hand-written regimes of rigidmech.regimes.friction, and scipy's solve_ivp
(DOP853, events) on the same hand-written equations, phase by phase (the anchor).

Run::

    PYTHONPATH=src python benchmarks/contact_regimes.py

Prints, for the cylinder launched slipping on an incline (it slips, then rolls; t = 0..3 s)
and the Coulomb-damped oscillator (t = 0..20 s), at rtol 1e-12, the minimum over 3 runs of
each and the ratios to scipy. "build + derive + compile" builds a fresh System each time;
"run (derived once)" reuses one System, whose equations of motion are cached (compilation of
the regimes included).
"""
import math
import pathlib
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "tests" / "regimes"))
from test_contact_motion import block_on_spring, cylinder_system  # noqa: E402

from rigidmech.actions import Coulomb  # noqa: E402
from rigidmech.regimes import contact_motion, coulomb_oscillator, cylinder_on_incline  # noqa: E402
from rigidmech.regimes.contact_motion import _Model  # noqa: E402

G, RTOL = 9.81, 1e-12


def cpu(fn, repeats=3):
    best = math.inf
    for _ in range(repeats):
        t0 = time.process_time()
        fn()
        best = min(best, time.process_time() - t0)
    return best


def scipy_phases(phases, y0, t_end):
    """phases: [(rhs, event)] run one after the other from each event's state."""
    t, y = 0.0, np.array(y0, float)
    for rhs, event in phases:
        if event is not None:
            event.terminal = True
        sol = solve_ivp(rhs, (t, t_end), y, method="DOP853", rtol=RTOL, atol=1e-12,
                        events=event)
        t, y = sol.t[-1], sol.y[:, -1]
        if t >= t_end:
            break
    return t, y


def cylinder():
    alpha, fk, r, v0 = math.atan(0.3), 0.15, 0.1, 2.0
    s, c = math.sin(alpha), math.cos(alpha)
    law = Coulomb(0.2, fk)
    system = cylinder_system(law)
    params = dict(m=2.0, r=r, g=G, alpha=alpha)

    def slip(_, y):
        return [y[1], G * (s - fk * c), y[3], fk * G * c / (0.5 * r)]

    def stops(_, y):
        return y[1] - r * y[3]

    def roll(_, y):
        a = G * s / 1.5
        return [y[1], a, y[3], a / r]

    rows = {
        "System route, build + derive + compile": lambda: _Model(cylinder_system(law), params),
        "System route, run (derived once)": lambda: contact_motion(
            system, 3.0, {"y": r}, {"x": v0}, rtol=RTOL, **params),
        "hand-written regimes": lambda: cylinder_on_incline(
            radius=r, angle=alpha, friction=law, v0=v0, t_end=3.0, rtol=RTOL),
        "scipy solve_ivp, hand-written": lambda: scipy_phases(
            [(slip, stops), (roll, None)], [0, v0, 0, 0], 3.0),
    }
    return rows


def oscillator():
    law, m, k, x0 = Coulomb(0.2, 0.15), 2.0, 3.0, 1.0
    system = block_on_spring(law)
    N = m * G

    def phase(sign):
        return lambda _, y: [y[1], (-k * y[0] - sign * 0.15 * N) / m]

    def stop(_, y):
        return y[1]

    rows = {
        "System route, build + derive + compile": lambda: _Model(block_on_spring(law),
                                                                 dict(m=m, k=k, g=G)),
        "System route, run (derived once)": lambda: contact_motion(
            system, 20.0, {"x": x0}, rtol=RTOL, m=m, k=k, g=G),
        "hand-written regimes": lambda: coulomb_oscillator(
            mass=m, stiffness=k, friction=law, normal_force=N, x0=x0, t_end=20.0, rtol=RTOL),
        "scipy solve_ivp, hand-written": lambda: scipy_phases(
            [(phase(-1), stop), (phase(1), stop), (phase(-1), stop)], [x0, 0.0], 20.0),
    }
    return rows


for name, rows in (("cylinder slips then rolls", cylinder()),
                   ("Coulomb-damped oscillator", oscillator())):
    times = {label: cpu(fn) for label, fn in rows.items()}
    anchor = times["scipy solve_ivp, hand-written"]
    print(name)
    for label, sec in times.items():
        print(f"  {label:40s} {1e3 * sec:8.1f} ms   x{sec / anchor:6.2f} of scipy")
