"""Time to the first right-hand side call: derive, compile, first call, for growing chains.

Two families, each size in a fresh process (sympy's cache cold):

* planar n-link pendulum (``derive.py``'s ``n_link_pendulum``: rods on pivots, relative angles);
* 3D chain on spherical joints: n axisymmetric links (mass m_i, length l_i, moments A_i about a
  transverse axis and C_i about their own axis, at the centre), each oriented relative to its
  parent by Euler angles z-x-z (precession, nutation, spin), a ball joint at the tip of the
  previous link, gravity -g z. 3n degrees of freedom.

Times (CPU seconds of the case's process; ``--wall`` for wall-clock seconds), per size:
derive (build the System, ``equations_of_motion``), compile (the first
``EquationsOfMotion.rhs(**params)``: cse, code generation, Python's compile), the first call
f(t, y) (it imports scipy.linalg, which solves M q'' = f for n > 6) and the best later call;
the ratios to "Kane-8" (KanesMethod deriving the planar 8-link pendulum, ``derive.py``,
measured in the same run and with the same clock); the operation counts of the generated code
(``n_ops``: operators and calls of the generated single-state code) and of M, f written out as
trees (:func:`tree_operations`: what a tree walk such as sympy's ``cse`` or ``count_ops`` has
to visit); the growth exponents of each over n (log-log least squares).
Correctness: the compiled q'' against M^-1 f evaluated from the symbolic M and f (one pass over
the DAG, numpy) at 3 random states, relative to 1e-12.

Run::

    python benchmarks/first_rhs.py                       # planar 5..30, 3D 2..6 (~10 min)
    python benchmarks/first_rhs.py --planar 5 10 --chain 2 3 4
    python benchmarks/first_rhs.py --profile-chain 4     # cProfile of one compile, top 25
    python benchmarks/first_rhs.py --wall                # wall-clock instead of CPU seconds
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from derive import (  # noqa: E402
    _best,
    _emit,
    _evaluate,
    _preimport,
    fit_exponent,
    header,
    kane_pendulum,
    n_link_pendulum,
    run_case,
)

PLANAR = (5, 10, 20, 30)

#: The clock of derive, compile, first call and Kane-8: CPU seconds of the case's process by
#: default (steady on a shared machine; every timed step is single-threaded sympy/Python), wall
#: seconds with ``--wall`` (passed to the case processes through the environment).
_WALL = "FIRST_RHS_WALL"


def _clock():
    return time.perf_counter() if os.environ.get(_WALL) else time.process_time()


CHAIN = (2, 3, 4, 5, 6)
N_CHECK = 3


def spherical_chain(n):
    """The 3D chain on ball joints, Euler angles z-x-z relative to the parent link (the
    catalogue's :func:`rigidmech.models.spherical_chain`)."""
    from rigidmech import models

    return models.spherical_chain(n).system

def _params(system, rng):
    out = {}
    for s in sorted(system.equations_of_motion().parameters, key=lambda s: s.name):
        if s.name == "g":
            out["g"] = 9.81
        elif s.name.startswith("C"):
            out[s.name] = float(rng.uniform(0.05, 0.2))
        elif s.name.startswith("A"):
            out[s.name] = float(rng.uniform(0.3, 0.6))   # A >= C / 2: a physical body
        else:
            out[s.name] = float(rng.uniform(0.5, 2.0))
    return out


def tree_operations(exprs):
    """Operations of ``exprs`` written out as trees (every shared subexpression counted once
    per use, as ``sympy.count_ops`` counts them: a sum or product of k terms is k - 1
    operations, a power or a function 1), computed over the DAG with a memo: count_ops
    itself walks the trees and takes minutes from a 3D chain of 7 links on."""
    memo = {}

    def count(e):
        hit = memo.get(e)
        if hit is not None:
            return hit
        if not e.args:
            out = 0
        else:
            own = len(e.args) - 1 if (e.is_Add or e.is_Mul) else 1
            out = own + sum(count(a) for a in e.args)
        memo[e] = out
        return out

    return sum(count(e) for e in exprs)


def case(kind, n):
    import numpy as np

    from rigidmech._core.symbolic import xreplace_shared

    _preimport()
    start = _clock()
    system = n_link_pendulum(n) if kind == "planar" else spherical_chain(n)
    eqs = system.equations_of_motion()
    derive = _clock() - start
    _emit(derive=derive)
    rng = np.random.default_rng(n)
    params = _params(system, rng)
    start = _clock()
    fun = eqs.rhs(**params)
    compile_time = _clock() - start
    k = len(eqs.coordinates)
    q = rng.uniform(0.3, 1.2, size=(k, N_CHECK))       # nutations away from 0 and pi
    u = rng.uniform(-1.0, 1.0, size=(k, N_CHECK))
    y = np.concatenate((q[:, 0], u[:, 0]))
    start = _clock()
    fun(0.0, y)
    first_call = _clock() - start
    solver = eqs._cache["solver"]
    _emit(compile=compile_time, first_call=first_call, n_ops=solver.n_ops,
          call=_best(lambda: fun(0.0, y)))
    q_s, u_s, _, rule = system.symbols()
    exprs = xreplace_shared(list(eqs.mass_matrix) + list(eqs.forcing), rule)
    _emit(tree_ops=tree_operations(exprs))
    by_name = {s.name: s for s in eqs.parameters}
    leaves = {by_name[k_]: v for k_, v in params.items() if k_ in by_name}
    leaves |= dict(zip(q_s, q, strict=True)) | dict(zip(u_s, u, strict=True))
    values = [np.broadcast_to(np.asarray(v, dtype=float), (N_CHECK,))
              for v in _evaluate(exprs, leaves)]
    Mn = np.stack(values[: k * k]).reshape(k, k, N_CHECK).transpose(2, 0, 1)
    fn = np.stack(values[k * k:]).reshape(k, N_CHECK).T
    want = np.linalg.solve(Mn, fn[..., None])[..., 0]
    got = np.stack([fun(0.0, np.concatenate((q[:, j], u[:, j])))[k:] for j in range(N_CHECK)])
    _emit(rel_diff=float(np.max(np.abs(got - want)) / np.max(np.abs(want))))


def case_kane8():
    _preimport()
    start = _clock()
    kane_pendulum(8)
    _emit(derive=_clock() - start)


def profile_chain(n, top=25):
    import cProfile
    import pstats

    import numpy as np

    system = spherical_chain(n)
    eqs = system.equations_of_motion()
    params = _params(system, np.random.default_rng(n))
    profiler = cProfile.Profile()
    profiler.enable()
    eqs.rhs(**params)
    profiler.disable()
    pstats.Stats(profiler).sort_stats("cumulative").print_stats(top)
    pstats.Stats(profiler).sort_stats("tottime").print_stats(top)


def _fmt(x, unit="s"):
    if not isinstance(x, float):
        return str(x)
    return f"{x * 1e3:.0f} ms" if x < 1 and unit == "s" else f"{x:.2f} s"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--planar", nargs="*", type=int, default=list(PLANAR))
    parser.add_argument("--chain", nargs="*", type=int, default=list(CHAIN))
    parser.add_argument("--timeout", type=float, default=400.0, help="seconds per case")
    parser.add_argument("--wall", action="store_true",
                        help="time with the wall clock instead of the process's CPU time")
    parser.add_argument("--profile-chain", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--case", nargs=2, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.wall:
        os.environ[_WALL] = "1"
    if args.case:
        kind, n = args.case[0], int(args.case[1])
        case_kane8() if kind == "kane8" else case(kind, n)
        return 0
    if args.profile_chain:
        profile_chain(args.profile_chain)
        return 0
    print(header().replace("Planar n-link pendulum: deriving M(q) q'' = f with rigidmech vs "
                           "sympy KanesMethod", "Time to the first rhs: derive, compile, call"),
          flush=True)
    k8 = run_case(8, "kane8", args.timeout, script=__file__).get("derive", float("nan"))
    clock = "wall-clock" if args.wall else "CPU"
    print(f"Kane-8 (KanesMethod, planar 8-link pendulum, derive): {k8:.2f} s; all times in "
          f"{clock} seconds\n", flush=True)
    cols = ("family", "n", "dof", "derive", "compile", "1st call", "call [us]", "first rhs",
            "/Kane-8", "compile/derive", "ops tree", "ops code", "rel diff")
    widths = (7, 3, 4, 9, 9, 9, 10, 10, 8, 15, 10, 9, 9)
    line = "  ".join(c.rjust(w) for c, w in zip(cols, widths, strict=True))
    print(line + "\n" + "-" * len(line), flush=True)
    results = {"planar": {}, "chain": {}}
    for kind, sizes in (("planar", args.planar), ("chain", args.chain)):
        for n in sizes:
            r = run_case(n, kind, args.timeout, script=__file__)
            results[kind][n] = r
            total = (r["derive"] + r["compile"] + r["first_call"]
                     if all(k in r for k in ("derive", "compile", "first_call")) else None)
            dof = n if kind == "planar" else 3 * n
            row = (kind, str(n), str(dof), _fmt(r.get("derive", r.get("status", "?"))),
                   _fmt(r.get("compile", "--")), _fmt(r.get("first_call", "--")),
                   f"{r['call'] * 1e6:.1f}" if "call" in r else "--",
                   _fmt(total) if total else "--",
                   f"{total / k8:.2f}" if total else "--",
                   f"{r['compile'] / r['derive']:.2f}" if "compile" in r else "--",
                   str(r.get("tree_ops", "--")), str(r.get("n_ops", "--")),
                   f"{r['rel_diff']:.1e}" if "rel_diff" in r else "--")
            print("  ".join(c.rjust(w) for c, w in zip(row, widths, strict=True)), flush=True)
            if r.get("status"):
                print(f"    {r['status']}: {r.get('stderr', '')}", flush=True)
    print("\ngrowth over n (log-log least squares):")
    for kind in ("planar", "chain"):
        done = {n: r for n, r in results[kind].items() if "compile" in r}
        if len(done) < 2:
            continue
        ns = sorted(done)
        parts = []
        for key in ("derive", "compile", "tree_ops", "n_ops"):
            if all(key in done[n] for n in ns):
                parts.append(f"{key} ~ n^{fit_exponent(ns, [done[n][key] for n in ns]):.2f}")
        print(f"  {kind} (n = {', '.join(map(str, ns))}): " + ", ".join(parts))
    print("\ntargets: planar n = 20 first rhs <= 0.5 Kane-8; 3D chain n = 6 first rhs <= 2 "
          "Kane-8; compile <= derive")
    for kind, n, limit in (("planar", 20, 0.5), ("chain", 6, 2.0)):
        r = results[kind].get(n, {})
        if "compile" in r:
            total = r["derive"] + r["compile"] + r["first_call"]
            verdict = "PASS" if total <= limit * k8 else "FAIL"
            print(f"  [{verdict}] {kind} n = {n}: {total:.2f} s = {total / k8:.2f} Kane-8 "
                  f"(<= {limit}); compile/derive {r['compile'] / r['derive']:.2f}")
    load = os.getloadavg()
    print(f"\nload average at end: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    if not math.isfinite(k8):
        print("Kane-8 missing: ratios are nan")
    return 0


if __name__ == "__main__":
    sys.exit(main())
