"""CPU time of rigidmech.ode's fixed-step methods: the cost of the loop around the step.

The fixed-step methods share one loop (finiteness at every step, ``progress``, Ctrl-C). This
script times them on a problem whose ``fun`` costs almost nothing, so that the loop's share
shows: ``y' = (y1, -y0)`` (or ``q'' = -q`` for the compositions) over ``[0, 200]`` with
``step = 0.01``, plus rk4 on a batch of 50 oscillators. CPU time (``time.process_time``),
best of ``--repeats``; run it for two versions alternately to compare them (the machine may be
shared)::

    PYTHONPATH=src python benchmarks/fixed_overhead.py [--repeats 5] [--only rk4,euler]

Prints, per method: evaluations, steps, best CPU time in ms and us per step.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from rigidmech import ode


def oscillator(t, y):
    return np.array([y[1], -y[0]])


def acceleration(t, q):
    return -q


def batch_oscillator(t, y):
    return np.stack([y[1], -y[0]])


SPAN, STEP = (0.0, 200.0), 0.01
Y0 = np.array([1.0, 0.0])
CASES = {
    "euler": (oscillator, Y0),
    "rk4": (oscillator, Y0),
    "rk38": (oscillator, Y0),
    "ab4": (oscillator, Y0),
    "abm4": (oscillator, Y0),
    "verlet": (acceleration, Y0),
    "yoshida6": (acceleration, Y0),
    "rk4-batch50": (batch_oscillator, np.stack([np.linspace(0.5, 1.5, 50), np.zeros(50)])),
}


def cpu_best(fn, repeats):
    best = float("inf")
    for _ in range(repeats):
        t0 = time.process_time()
        fn()
        best = min(best, time.process_time() - t0)
    return best


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--only", default="", help="comma-separated method names")
    args = ap.parse_args(argv)
    names = [n for n in CASES if not args.only or n in args.only.split(",")]
    print(f"{'method':<12} {'nfev':>7} {'steps':>7} {'CPU ms':>8} {'us/step':>8}")
    for name in names:
        fun, y0 = CASES[name]
        method = name.split("-")[0]

        def run(fun=fun, y0=y0, method=method):
            return ode.solve(fun, SPAN, y0, method=method, step=STEP)

        r = run()
        ms = cpu_best(run, args.repeats) * 1e3
        print(f"{name:<12} {r.nfev:>7} {r.nsteps:>7} {ms:>8.2f} {ms * 1e3 / r.nsteps:>8.3f}")


if __name__ == "__main__":
    main()
