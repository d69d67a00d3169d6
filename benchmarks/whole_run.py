"""The whole run: build -> equations of motion -> compiled right-hand side -> the cheapest
integration reaching a final error <= 1e-6 over 10 s, rigidmech against sympy.physics.mechanics
``KanesMethod`` + ``sympy.lambdify(cse=True)`` + the cheapest ``scipy.integrate.solve_ivp`` run.

The system: the planar n-link pendulum of ``derive.py`` (uniform rods m_i = 1, l_i = 1, relative
joint angles q_i, gravity g = 9.81), released at rest with the first link 1 rad from hanging
straight down and the others aligned with it (``initial_state``; released near the horizontal
the chain is chaotic and no tolerance reaches 1e-6 over 10 s), n = 4 and 6, over 10 s. Both
sides use the same coordinates and speeds (u = q'), so their states compare directly.

* ours: ``models.n_link_pendulum(n).system`` (build), ``.equations_of_motion()`` (derive),
  ``eqs.rhs(**params)`` (compile: cse, code generation), ``ode.solve`` (integrate);
* anchor: ``KanesMethod`` (build and derive, ``derive.py``'s ``kane_pendulum``), then
  ``lambdify([q, u, p], M, cse=True)`` and the same for f (compile) and
  ``f(t, y) = (u, numpy.linalg.solve(M, f))`` integrated by ``solve_ivp``.

Each side runs in a fresh process (sympy's cache cold; imports not timed), the sides alternated
(ours n=4, anchor n=4, ours n=6, anchor n=6, then again: ``--rounds``), the best of the rounds
kept per phase, in CPU time of the child (``time.process_time``: on a machine shared with other
jobs the wall time measures the sharing). "The cheapest integration": in each child, every
candidate method over rtol = 3e-5, 1e-5, 3e-6 ... 1e-12 (atol = rtol * 1e-2), loosest first,
until the final state is within 1e-6 (max abs over the state) of the reference; the fastest
(best of 3) of those is the one charged. The search itself is not charged (a user tunes once).
The reference: rigidmech dop853 at rtol 1e-13 cross-checked against scipy DOP853 at rtol 1e-13
on the Kane right-hand side (printed).

    python benchmarks/whole_run.py                 # n = 4 and 6, 2 rounds (~5 min loaded)
    python benchmarks/whole_run.py --sizes 4 --rounds 1
    python benchmarks/whole_run.py --profile ours 6      # cProfile of one of our whole runs
    python benchmarks/whole_run.py --per-call            # our f(t, y): fast path vs general

Prints per n and side: build+derive, compile, integrate (method, rtol, steps, evaluations,
per-evaluation cost of f(t, y), of the generated code alone -- ours: the single-state
solution of M q'' = f; Kane: the two lambdified functions M and f -- and evaluations x cost:
the share of the integration spent in f, the rest being the integrator's own), total, and the
ratio anchor / ours (> 1: we are faster), the load.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

T_END = 10.0
GOAL = 1e-6
RTOLS = tuple(m * 10.0 ** -k for k in range(5, 13) for m in (3.0, 1.0))  # 3e-5 ... 1e-12
OURS_METHODS = ("dop853", "dopri5", "adams")  # gbs: measured slower here, left out
SCIPY_METHODS = ("DOP853", "RK45", "LSODA")
TARGET = 5.0


def initial_state(n):
    """Released at rest, the first link 1 rad from hanging straight down (q = 0 is horizontal:
    the rods lie along their frames' x axes, gravity along -y), the others aligned with it."""
    import math

    import numpy as np

    return np.array([-math.pi / 2 + 1.0] + [0.0] * (2 * n - 1))


def params(n):
    p = {"g": 9.81}
    for i in range(1, n + 1):
        p[f"m{i}"] = 1.0
        p[f"l{i}"] = 1.0
    return p


def _best(fn, repeat=3):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.process_time()
        out = fn()
        best = min(best, time.process_time() - t0)
    return best, out


def _cheapest(solve_with, methods, ref):
    """For each method, the loosest rtol reaching GOAL; the fastest of those."""
    import numpy as np

    best = None
    for method in methods:
        for rtol in RTOLS:
            try:
                dt, (y_end, nsteps, nfev) = _best(lambda: solve_with(method, rtol), repeat=1)  # noqa: B023
            except Exception:  # noqa: BLE001 - a candidate that fails is no candidate
                break
            err = float(np.max(np.abs(y_end - ref)))
            if err <= GOAL:
                dt, _ = _best(lambda: solve_with(method, rtol), repeat=3)  # noqa: B023
                cand = dict(method=method, rtol=rtol, time=dt, err=err, nsteps=nsteps,
                            nfev=nfev)
                if best is None or dt < best["time"]:
                    best = cand
                break
            if dt > 20.0:
                break
    return best


def case_ours(n, ref):
    import numpy as np
    from derive import _preimport

    from rigidmech import models, ode

    _preimport()
    t0 = time.process_time()
    system = models.n_link_pendulum(n).system
    eqs = system.equations_of_motion()
    t1 = time.process_time()
    fun = eqs.rhs(**params(n))
    y0 = initial_state(n)
    fun(0.0, y0)  # the first call (code generation finishes lazily, if at all)
    t2 = time.process_time()
    per_call = _best(lambda: [fun(0.0, y0) for _ in range(1000)])[0] / 1000
    # the generated single-state code alone (the rest of per_call is the wrapper's)
    solver = next(c.cell_contents for c in fun.__closure__
                  if type(c.cell_contents).__name__ == "CompiledLinearSolve")
    flat = [0.0, *y0.tolist(), *(float(v) for v in (params(n)[p.name] for p in eqs.parameters))]
    generated = _best(lambda: [solver._single(*flat) for _ in range(1000)])[0] / 1000

    def solve_with(method, rtol):
        r = ode.solve(fun, (0.0, T_END), y0, method=method, rtol=rtol, atol=rtol * 1e-2,
                      t_eval=[T_END])
        if r.status != 0:
            raise RuntimeError(r.message)
        return r.y[:, -1], r.nsteps, r.nfev

    if ref is None:  # the reference run
        r = ode.solve(fun, (0.0, T_END), y0, method="dop853", rtol=1e-13, atol=1e-15,
                      t_eval=[T_END])
        return {"ref": r.y[:, -1].tolist()}
    best = _cheapest(solve_with, OURS_METHODS, np.array(ref))
    return dict(derive=t1 - t0, compile=t2 - t1, per_call=per_call, generated=generated,
                **best)


def case_kane(n, ref):
    import numpy as np
    import sympy as sp
    from derive import _preimport, kane_pendulum
    from scipy.integrate import solve_ivp

    _preimport()
    t0 = time.process_time()
    km, q, u, symbols = kane_pendulum(n)
    M, f = km.mass_matrix, km.forcing
    t1 = time.process_time()
    names = sorted(symbols)
    p_syms = [symbols[k] for k in names]
    M_f = sp.lambdify([q, u, p_syms], M, cse=True)
    f_f = sp.lambdify([q, u, p_syms], f, cse=True)
    pv = [params(n)[k] for k in names]
    solve = np.linalg.solve

    def fun(t, y):
        qv, uv = y[:n], y[n:]
        return np.concatenate([uv, solve(M_f(qv, uv, pv), f_f(qv, uv, pv)).ravel()])

    y0 = initial_state(n)
    fun(0.0, y0)
    t2 = time.process_time()
    per_call = _best(lambda: [fun(0.0, y0) for _ in range(1000)])[0] / 1000
    qv, uv = y0[:n], y0[n:]
    generated = _best(lambda: [(M_f(qv, uv, pv), f_f(qv, uv, pv)) for _ in range(1000)])[0] / 1000

    def solve_with(method, rtol):
        s = solve_ivp(fun, (0.0, T_END), y0, method=method, rtol=rtol, atol=rtol * 1e-2)
        if s.status != 0:
            raise RuntimeError(s.message)
        return s.y[:, -1], len(s.t) - 1, s.nfev

    if ref is None:
        s = solve_ivp(fun, (0.0, T_END), y0, method="DOP853", rtol=1e-13, atol=1e-15,
                      t_eval=[T_END])
        return {"ref": s.y[:, -1].tolist()}
    best = _cheapest(solve_with, SCIPY_METHODS, np.array(ref))
    return dict(derive=t1 - t0, compile=t2 - t1, per_call=per_call, generated=generated,
                **best)


def per_call(n, calls=20000, rounds=3):
    """Our f(t, y) on one float64 state against the general call it short-cuts (the compiled
    solve with its argument checks, then the concatenation), alternated; CPU us per call."""
    import numpy as np

    from rigidmech import models

    eqs = models.n_link_pendulum(n).system.equations_of_motion()
    fun = eqs.rhs(**params(n))
    y0 = initial_state(n)
    solver = next(c.cell_contents for c in fun.__closure__
                  if type(c.cell_contents).__name__ == "CompiledLinearSolve")
    values = [params(n)[p.name] for p in eqs.parameters]

    def general():
        return np.concatenate((y0[n:], solver(0.0, y0[:n], y0[n:], *values)))

    assert np.allclose(general(), fun(0.0, y0), rtol=1e-13, atol=1e-13)
    best = {"f(t, y)": float("inf"), "general call": float("inf")}
    for _ in range(rounds):
        for name, f in (("f(t, y)", lambda: fun(0.0, y0)), ("general call", general)):
            t0 = time.process_time()
            for _ in range(calls):
                f()
            best[name] = min(best[name], (time.process_time() - t0) / calls * 1e6)
    print(f"n = {n}: " + ", ".join(f"{k} {v:.1f} us" for k, v in best.items()))


def run_child(side, n, ref, timeout=900):
    cmd = [sys.executable, __file__, "--case", side, str(n)]
    out = subprocess.run(cmd, input=json.dumps(ref), capture_output=True, text=True,
                         timeout=timeout, check=False)
    if out.returncode != 0:
        raise RuntimeError(f"{side} n={n} failed:\n{out.stderr[-2000:]}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[4, 6])
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--case", nargs=2, default=None, help=argparse.SUPPRESS)
    ap.add_argument("--profile", nargs=2, default=None, metavar=("SIDE", "N"))
    ap.add_argument("--per-call", action="store_true",
                    help="only our f(t, y) against the general call it short-cuts")
    args = ap.parse_args(argv)
    if args.per_call:
        for n in args.sizes:
            per_call(n)
        return
    if args.case is not None:
        side, n = args.case[0], int(args.case[1])
        ref = json.loads(sys.stdin.read())
        out = (case_ours if side == "ours" else case_kane)(n, ref)
        print(json.dumps(out), flush=True)
        return
    if args.profile is not None:
        import cProfile
        import pstats

        side, n = args.profile[0], int(args.profile[1])
        ref = run_child("ours", n, None)["ref"]
        case = case_ours if side == "ours" else case_kane
        cProfile.runctx("case(n, ref)", globals(), {"case": case, "n": n, "ref": ref},
                        "/tmp/whole_run.prof")
        pstats.Stats("/tmp/whole_run.prof").sort_stats("cumulative").print_stats(30)
        return
    import numpy as np

    print(f"load (uptime) at start: {os.getloadavg()}")
    refs = {}
    for n in args.sizes:
        ours_ref = np.array(run_child("ours", n, None)["ref"])
        kane_ref = np.array(run_child("kane", n, None)["ref"])
        refs[n] = ours_ref.tolist()
        print(f"n = {n}: reference (ours, dop853 rtol 1e-13) vs scipy DOP853 rtol 1e-13 on the "
              f"Kane rhs: max diff {np.max(np.abs(ours_ref - kane_ref)):.1e}")
    best = {}
    for _ in range(args.rounds):
        for n in args.sizes:
            for side in ("ours", "kane"):
                r = run_child(side, n, refs[n])
                r["total"] = r["derive"] + r["compile"] + r["time"]
                prev = best.get((side, n))
                if prev is None:
                    best[(side, n)] = r
                else:  # best of the rounds, phase by phase
                    for key in ("derive", "compile", "time", "total", "per_call", "generated"):
                        prev[key] = min(prev[key], r[key])
    print(f"load (uptime) at end: {os.getloadavg()}\n")
    head = (f"{'n':>2} {'side':<6} {'derive':>8} {'compile':>8} {'integrate':>10} {'total':>8}"
            f"  {'method':<7} {'rtol':>6} {'steps':>6} {'nfev':>6} {'us/call':>8} {'us gen':>7} "
            f"{'nfev*call':>9} {'error':>8}")
    print(head)
    for n in args.sizes:
        for side in ("ours", "kane"):
            r = best[(side, n)]
            print(f"{n:>2} {side:<6} {r['derive']:>8.3f} {r['compile']:>8.3f} {r['time']:>10.3f} "
                  f"{r['total']:>8.3f}  {r['method']:<7} {r['rtol']:>6.0e} {r['nsteps']:>6} "
                  f"{r['nfev']:>6} {r['per_call'] * 1e6:>8.1f} {r['generated'] * 1e6:>7.1f} "
                  f"{r['nfev'] * r['per_call']:>9.3f} {r['err']:>8.1e}")
        o, k = best[("ours", n)], best[("kane", n)]
        ratio = k["total"] / o["total"]
        print(f"   ratio kane/ours: derive {k['derive'] / o['derive']:.1f}x, compile "
              f"{k['compile'] / o['compile']:.1f}x, integrate {k['time'] / o['time']:.1f}x, "
              f"whole run {ratio:.1f}x (target >= {TARGET:.0f}x: "
              f"{'met' if ratio >= TARGET else 'NOT met'})")


if __name__ == "__main__":
    main()
