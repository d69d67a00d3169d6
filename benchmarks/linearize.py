"""Linearising the planar n-link pendulum about its hanging equilibrium: rigidmech against
``KanesMethod.linearize``.

The model is ``derive.py``'s (uniform rods m_i, l_i, relative joint angles q_i, revolute
joints, gravity -g y), hanging straight down: q1 = -pi/2, q2 = ... = qn = 0. Each (n, side)
runs in a fresh process (this script re-run with ``--case``), so that sympy's cache is cold.

- rigidmech: build the System, derive M and f (``System.equations_of_motion``), then
  ``rigidmech.vibrations.linearize`` (M, C, K symbolic in the parameters, evaluated at the
  point while differentiating).
- sympy: build the same system, ``KanesMethod.kanes_equations``, then
  ``KanesMethod.linearize(op_point=..., A_and_B=False)`` (the linear M, A, B of the
  first-order form, symbolic in the parameters, evaluated at the same point).

Printed per n: the time of each side (derive + linearise) and of the linearisation step alone,
their ratios (> 1: we are faster), and the largest relative difference between our M^-1 K and
Kane's (from the u' rows of its M [q', u'] = A [q, u], whatever its sign convention) at random
positive parameters.

Run::

    python benchmarks/linearize.py                # n = 4, 8, 12 (Kane at 12: minutes)
    python benchmarks/linearize.py --sizes 4 8    # fewer sizes
    python benchmarks/linearize.py --timeout 900  # per-case limit in seconds
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

SIZES = (4, 8, 12)


def _emit(**items):
    print(json.dumps(items), flush=True)


def _params(n, seed=2024):
    import numpy as np

    rng = np.random.default_rng(seed + n)
    params = {"g": float(rng.uniform(5.0, 15.0))}
    for i in range(1, n + 1):
        params[f"m{i}"] = float(rng.uniform(0.5, 2.0))
        params[f"l{i}"] = float(rng.uniform(0.5, 2.0))
    return params


def case_ours(n):
    import numpy as np
    import sympy as sp
    from derive import _preimport, n_link_pendulum

    import rigidmech as rm  # noqa: F401  (import excluded from the timing)
    from rigidmech.vibrations import linearize

    _preimport()
    start = time.perf_counter()
    eqs = n_link_pendulum(n).equations_of_motion()
    mid = time.perf_counter()
    about = [-sp.pi / 2] + [0] * (n - 1)
    lin = linearize(eqs, about, simplify=False)
    end = time.perf_counter()
    _emit(total=end - start, linearize=end - mid)
    M, C, K, _ = lin.numeric(**_params(n))
    _emit(MinvK=np.linalg.solve(M, K).tolist())


def case_kane(n):
    import numpy as np
    import sympy as sp
    from derive import _preimport, kane_pendulum
    from sympy.physics import mechanics  # (import excluded from the timing)

    _preimport()
    start = time.perf_counter()
    km, q, u, symbols = kane_pendulum(n)
    mid = time.perf_counter()
    t = mechanics.dynamicsymbols._t
    op = {q[0]: -sp.pi / 2} | {qi: 0 for qi in q[1:]} | {ui: 0 for ui in u} | {
        ui.diff(t): 0 for ui in u}
    M_lin, A_lin, _, _ = km.linearize(op_point=op, A_and_B=False)
    end = time.perf_counter()
    _emit(total=end - start, linearize=end - mid)
    values = {symbols[k]: v for k, v in _params(n).items()}
    Mn = np.array(M_lin.xreplace(values).evalf().tolist(), dtype=float)
    An = np.array(A_lin.xreplace(values).evalf().tolist(), dtype=float)
    # lower block: Mn22 u' = An21 q + ... (Kane's sign convention), so M^-1 K = -Mn22^-1 An21
    _emit(MinvK=(-np.linalg.solve(Mn[n:, n:], An[n:, :n])).tolist())


def run_case(n, side, timeout):
    """One case in a fresh process (the runner of ``derive.py``)."""
    from derive import run_case as run_in_fresh_process

    return run_in_fresh_process(n, side, timeout, script=__file__)


def _rel(a, b):
    import numpy as np

    a, b = np.asarray(a), np.asarray(b)
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", nargs=2, metavar=("SIDE", "N"), help=argparse.SUPPRESS)
    parser.add_argument("--sizes", nargs="+", type=int, default=list(SIZES))
    parser.add_argument("--timeout", type=float, default=1800.0)
    args = parser.parse_args(argv)
    if args.case:
        side, n = args.case[0], int(args.case[1])
        (case_ours if side == "ours" else case_kane)(n)
        return
    import platform

    import sympy

    print(f"python {platform.python_version()}, sympy {sympy.__version__}, "
          f"load {os.getloadavg()[0]:.2f} ({os.cpu_count()} cpus)")
    print(f"{'n':>3} {'ours total':>11} {'Kane total':>11} {'ratio':>7} "
          f"{'ours lin':>9} {'Kane lin':>9} {'ratio':>7} {'M^-1K diff':>11}")
    for n in args.sizes:
        ours = run_case(n, "ours", args.timeout)
        kane = run_case(n, "kane", args.timeout)

        def fmt(d, key):
            if key in d:
                return f"{d[key]:.3f}s"
            return d.get("status", "?")

        ratio = (f"{kane['total'] / ours['total']:.1f}x" if "total" in kane and "total" in ours
                 else f">{args.timeout / ours['total']:.0f}x" if "total" in ours else "-")
        lin_ratio = (f"{kane['linearize'] / ours['linearize']:.1f}x"
                     if "linearize" in kane and "linearize" in ours else "-")
        diff = (f"{_rel(ours['MinvK'], kane['MinvK']):.1e}" if "MinvK" in ours and "MinvK" in kane
                else "-")
        print(f"{n:>3} {fmt(ours, 'total'):>11} {fmt(kane, 'total'):>11} {ratio:>7} "
              f"{fmt(ours, 'linearize'):>9} {fmt(kane, 'linearize'):>9} {lin_ratio:>7} "
              f"{diff:>11}", flush=True)


if __name__ == "__main__":
    main()
