"""Work-precision with a costly right-hand side: the planar n-link pendulum, ours against solve_ivp.

The reference problems of ``work_precision.py`` have right-hand sides of about 1 us a call, so
that they measure the integrators' own machinery. The equations of motion of a mechanism cost
far more: here q'' = M(q)^-1 f(q, q') of the planar n-link pendulum (uniform rods, relative
joint angles), derived and compiled by rigidmech itself (``System.equations_of_motion().rhs``,
as in ``derive.py``: tens of microseconds a call). Then the number of evaluations is the cost,
and the methods that need fewest win.

Both libraries get the same ``fun``. The reference solution is our ``dop853`` at rtol 1e-13
(checked against ``adams`` at rtol 1e-13: the difference is printed). Tolerances sweep
rtol = 1e-4 ... 1e-12 (whole decades; ``--half`` for half decades) with atol = 1e-3 rtol; time
is the best of ``--repeats``, taken in rounds over the whole sweep; per error level the cheapest
of ours against the cheapest solve_ivp run.

Run::

    .venv/bin/python benchmarks/costly_rhs.py [--links 4] [--t-end 4] [--repeats 3] [--half]
                                              [--angle 0.6 | --chaotic]

The chain starts at rest, straight, ``--angle`` rad from the downward vertical (a regular
motion), or with every joint at 0.6 rad (``--chaotic``: errors grow fast, the reference is
good to about 1e-9 only).
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import time
import warnings

import numpy as np
import scipy
from scipy.integrate import solve_ivp

from rigidmech import ode

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from derive import n_link_pendulum  # noqa: E402  (the sibling script's system)

OURS = ("adams", "dop853", "dopri5")
SCIPY = ("LSODA", "DOP853", "RK45")
LEVELS = (1e-6, 1e-8, 1e-10)


def n_link_rhs(n):
    """``fun(t, y)`` of the n-link pendulum of ``derive.py``, y = (q, u), derived and compiled
    by rigidmech; m_i = l_i = 1, g = 9.81."""
    params = {"g": 9.81} | {f"{s}{i}": 1.0 for i in range(1, n + 1) for s in "ml"}
    return n_link_pendulum(n).equations_of_motion().rhs(**params)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--links", type=int, default=4)
    ap.add_argument("--t-end", type=float, default=4.0)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--half", action="store_true", help="half decades of rtol")
    ap.add_argument("--angle", type=float, default=0.6,
                    help="release angle of the chain from the downward vertical [rad]")
    ap.add_argument("--chaotic", action="store_true",
                    help="every relative angle 0.6 rad instead (a chaotic motion)")
    args = ap.parse_args(argv)
    up = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    print(f"command: python {' '.join(sys.argv)}")
    print(f"machine: {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"numpy {np.__version__}, scipy {scipy.__version__}; uptime: {up}")
    n = args.links
    t0 = time.perf_counter()
    fun = n_link_rhs(n)
    print(f"{n}-link pendulum: equations derived and compiled in {time.perf_counter() - t0:.1f} s")
    # at rest; the first link args.angle from the downward vertical (the rods lie along their
    # frames' x axes: q1 = -pi/2 hangs down), the others in line with it (relative angles 0);
    # --chaotic: every relative angle 0.6 rad (a release from near the horizontal, chaotic)
    q0 = np.full(n, 0.6) if args.chaotic else np.r_[-np.pi / 2 + args.angle, np.zeros(n - 1)]
    y0 = np.concatenate([q0, np.zeros(n)])
    span = (0.0, args.t_end)
    calls = 2000
    t0 = time.perf_counter()
    for _ in range(calls):
        fun(0.0, y0)
    per_call = (time.perf_counter() - t0) / calls
    print(f"one call of fun: {per_call * 1e6:.1f} us; t in [0, {args.t_end:g}]")
    ref = ode.solve(fun, span, y0, method="dop853", rtol=1e-13, atol=1e-16).y[:, -1]
    check = ode.solve(fun, span, y0, method="adams", rtol=1e-13, atol=1e-16).y[:, -1]
    print(f"reference: dop853 rtol 1e-13; adams rtol 1e-13 differs by "
          f"{np.abs(check - ref).max():.1e}")

    step = 0.5 if args.half else 1.0
    rtols = [10.0 ** -(4 + step * i) for i in range(int(8 / step) + 1)]
    runs = []  # (name, rtol, run)
    for name in OURS + tuple("scipy:" + m for m in SCIPY):
        for rtol in rtols:
            if name.startswith("scipy:"):
                def run(m=name[6:], rtol=rtol):
                    s = solve_ivp(fun, span, y0, method=m, rtol=rtol, atol=1e-3 * rtol)
                    return s.y[:, -1], s.nfev
            else:
                def run(m=name, rtol=rtol):
                    r = ode.solve(fun, span, y0, method=m, rtol=rtol, atol=1e-3 * rtol,
                                  max_steps=10**7)
                    return r.y[:, -1], r.nfev
            runs.append((name, rtol, run))
    rows = {}
    for _ in range(args.repeats):  # rounds over the whole sweep (see work_precision.py)
        for name, rtol, run in runs:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                t0 = time.perf_counter()
                y, nfev = run()
                dt = time.perf_counter() - t0
            err = float(np.abs(y - ref).max())
            old = rows.get((name, rtol))
            rows[(name, rtol)] = (err, min(dt, old[1]) if old else dt, nfev)
    print(f"\n{'method':14s} {'rtol':>8s} {'final err':>10s} {'time ms':>9s} {'nfev':>7s}")
    for (name, rtol), (err, dt, nfev) in rows.items():
        print(f"{name:14s} {rtol:8.1e} {err:10.2e} {dt * 1e3:9.2f} {nfev:7d}")

    def cheapest(level, scipy_side):
        ok = [(k, v) for k, v in rows.items()
              if k[0].startswith("scipy:") == scipy_side and v[0] <= level]
        return min(ok, key=lambda kv: kv[1][1]) if ok else None

    def fmt(c):
        if c is None:
            return "not reached"
        (name, rtol), (err, dt, nfev) = c
        return f"{name} rtol {rtol:.0e}: {dt * 1e3:.1f} ms, {nfev} ev (err {err:.1e})"

    print("\n== cheapest run reaching the error level (ratio = our time / solve_ivp time)")
    for level in LEVELS:
        ours, ref_run = cheapest(level, False), cheapest(level, True)
        ratio = (f"{ours[1][1] / ref_run[1][1]:.2f}" if ours and ref_run else "-")
        print(f"err <= {level:.0e} | {fmt(ours):58s} | {fmt(ref_run):58s} | {ratio}")
    return 0


if __name__ == "__main__":
    main()
