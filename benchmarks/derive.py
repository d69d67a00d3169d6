"""Deriving the equations of motion of the planar n-link pendulum: rigidmech against KanesMethod.

Anchor (TARGETS.md, "Deriving equations of motion"): ``sympy.physics.mechanics.KanesMethod`` on
the same system -- uniform rods, independent symbols m_i, l_i, g, relative joint angles q_i,
revolute joints, gravity -g y. Each (n, side) runs in a fresh process (this script re-run with
the internal ``--case`` flag), so that sympy's cache is cold for both sides.

Run::

    .venv/bin/python benchmarks/derive.py                 # n = 2, 3, 5, 8, 12 (Kane n=12: minutes)
    .venv/bin/python benchmarks/derive.py --quick         # n = 2, 3, 5
    .venv/bin/python benchmarks/derive.py --max-kane 8    # skip Kane above n = 8

Prints, per n: the time to build the system and derive M and f (import excluded) for rigidmech
and for Kane, their ratio (> 1: we are faster), sympy.count_ops of M and f for both, the
operations left after ``sympy.cse`` for ours, the time to compile our right-hand side (the
first ``EquationsOfMotion.rhs`` call, not in the derive time), the per-call cost of that
compiled f(t, y) (one state; per state in a batch of 1000), and the largest relative
difference between our q'' = M^-1 f and Kane's at 3 random states with random positive
parameters (infinity norm of the difference over the infinity norm of Kane's q'', per state).
Then the growth exponent of our derive time (log-log least squares over n >= 3) and the
targets with PASS/FAIL. Absolute times drift between runs and with the machine's load (printed
in the header); the ratios, measured side by side in one run, are the claim.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import time
import timeit

SIZES = (2, 3, 5, 8, 12)
QUICK_SIZES = (2, 3, 5)
BATCH = 1000
N_CHECK = 3
CHECK_TOL = 1e-12

TARGET_RATIO_N8 = 20.0
TARGET_DERIVE_N12 = 2.0
TARGET_SINGLE_N12 = 100e-6
TARGET_BATCH_N12 = 10e-6


# -- child side: one derivation in a fresh process ------------------------------------------------
def _emit(**items):
    """Print one JSON line for the parent (flushed: a timed-out child keeps what it said)."""
    print(json.dumps(items), flush=True)


def _check_point(n, seed=12345):
    """Random positive parameters and 3 random states, identical in both children."""
    import numpy as np

    rng = np.random.default_rng(seed + n)
    params = {"g": float(rng.uniform(5.0, 15.0))}
    for i in range(1, n + 1):
        params[f"m{i}"] = float(rng.uniform(0.5, 2.0))
        params[f"l{i}"] = float(rng.uniform(0.5, 2.0))
    q = rng.uniform(-math.pi, math.pi, size=(n, N_CHECK))
    u = rng.uniform(-2.0, 2.0, size=(n, N_CHECK))
    return params, q, u


def _evaluate(exprs, leaves):
    """Evaluate sympy expressions on arrays, one pass over the expression DAG.

    ``leaves`` maps symbols (or applied functions such as q1(t)) to numpy arrays. Shared
    subtrees (same object) are evaluated once; this is independent of any code generation,
    so it judges both derivations the same way.
    """
    import numpy as np
    import sympy as sp
    from sympy.core.function import AppliedUndef

    memo = {}
    results = []
    for root in exprs:
        stack = [root]
        while stack:
            node = stack[-1]
            key = id(node)
            if key in memo:
                stack.pop()
                continue
            if node.is_Symbol or isinstance(node, AppliedUndef):
                if node not in leaves:
                    raise KeyError(f"no value for {node}")
                memo[key] = leaves[node]
                stack.pop()
                continue
            if node.is_Number:
                memo[key] = float(node)
                stack.pop()
                continue
            pending = [a for a in node.args if id(a) not in memo]
            if pending:
                stack.extend(pending)
                continue
            stack.pop()
            args = [memo[id(a)] for a in node.args]
            if node.is_Add:
                value = sum(args[1:], args[0])
            elif node.is_Mul:
                value = args[0]
                for a in args[1:]:
                    value = value * a
            elif node.is_Pow:
                value = np.power(args[0], args[1])
            elif isinstance(node, sp.sin):
                value = np.sin(args[0])
            elif isinstance(node, sp.cos):
                value = np.cos(args[0])
            else:
                raise TypeError(f"cannot evaluate {type(node).__name__}")
            memo[key] = value
        results.append(memo[id(root)])
    return results


def _accelerations(M, f, leaves, n):
    """q'' = M^-1 f at each check state, shape (N_CHECK, n)."""
    import numpy as np

    values = _evaluate(list(M) + list(f), leaves)
    values = [np.broadcast_to(np.asarray(v, dtype=float), (N_CHECK,)) for v in values]
    Mn = np.stack(values[: n * n]).reshape(n, n, N_CHECK).transpose(2, 0, 1)
    fn = np.stack(values[n * n:]).reshape(n, N_CHECK).T
    return np.linalg.solve(Mn, fn[..., None])[..., 0]


def _preimport():
    """Import the modules sympy loads lazily on first use, so that no side times an import.

    ``Add.flatten`` imports sympy.tensor.tensor (with sympy.combinatorics: ~0.3-0.5 s) the
    first time it runs; importing sympy.physics.mechanics loads it already, so without this
    the Kane side would be spared a cost our side pays inside its timing.
    """
    import importlib

    for name in ("sympy.tensor.tensor", "sympy.assumptions.wrapper", "sympy.sets.setexpr",
                 "sympy.calculus.accumulationbounds", "sympy.matrices.expressions"):
        importlib.import_module(name)


def _best(func, budget=0.5, repeat=7):
    """Best per-call time (s) of ``func()`` over ``repeat`` runs of a count filling ``budget``."""
    timer = timeit.Timer(func)
    number, elapsed = 1, timer.timeit(1)
    while elapsed * number < budget / repeat and number < 100_000:
        number *= 2 if elapsed * number * 10 > budget / repeat else 10
    return min(timer.repeat(repeat=repeat, number=number)) / number


def n_link_pendulum(n):
    """The planar n-link pendulum with rigidmech: uniform rods (masses m_i, lengths l_i) along
    their frames' x axes, revolute joints, relative angles q_i, gravity -g y -- the
    catalogue's :func:`rigidmech.models.n_link_pendulum`. Returns the System (also used by
    ``costly_rhs.py``)."""
    from rigidmech import models

    return models.n_link_pendulum(n).system


def case_ours(n):
    import numpy as np
    import sympy as sp

    from rigidmech._core.symbolic import xreplace_shared

    _preimport()
    start = time.perf_counter()
    system = n_link_pendulum(n)
    eqs = system.equations_of_motion()
    M, f = eqs.mass_matrix, eqs.forcing
    _emit(derive=time.perf_counter() - start)

    # operations counted with q, q' as plain symbols (as compiled), like Kane's u(t) leaves
    q_sym, u_sym, _, rule = system.symbols()
    exprs = xreplace_shared(list(M) + list(f), rule)
    M, f = exprs[: n * n], exprs[n * n:]
    _emit(ops=int(sp.count_ops(exprs)))
    replacements, reduced = sp.cse(exprs)
    _emit(ops_cse=int(sp.count_ops([r for _, r in replacements]) + sp.count_ops(reduced)))

    params, q, u = _check_point(n)
    start = time.perf_counter()
    fun = eqs.rhs(**params)
    _emit(compile=time.perf_counter() - start)
    y1 = np.concatenate((q[:, 0], u[:, 0]))
    rng = np.random.default_rng(7)
    yb = np.concatenate((rng.uniform(-math.pi, math.pi, (n, BATCH)),
                         rng.uniform(-2.0, 2.0, (n, BATCH))))
    _emit(rhs_single=_best(lambda: fun(0.0, y1)),
          rhs_batch=_best(lambda: fun(0.0, yb)) / BATCH)

    by_name = {s.name: s for s in eqs.parameters}
    leaves = {by_name[k]: v for k, v in params.items() if k in by_name}
    leaves |= dict(zip(q_sym, q, strict=True)) | dict(zip(u_sym, u, strict=True))
    acc = _accelerations(M, f, leaves, n)
    compiled = np.stack([fun(0.0, np.concatenate((q[:, k], u[:, k])))[n:]
                         for k in range(N_CHECK)])
    _emit(acc=acc.tolist(), acc_compiled=compiled.tolist())


def kane_pendulum(n):
    """KanesMethod on the same system; returns (KM, q(t), u(t), {name: symbol})."""
    import sympy as sp
    from sympy.physics import mechanics as me

    q = me.dynamicsymbols(" ".join(f"q{i}" for i in range(1, n + 1)), seq=True)
    u = me.dynamicsymbols(" ".join(f"u{i}" for i in range(1, n + 1)), seq=True)
    g = sp.Symbol("g", positive=True)
    N = me.ReferenceFrame("N")
    joint = me.Point("O")
    joint.set_vel(N, 0)
    frame = N
    bodies, loads = [], []
    symbols = {"g": g}
    for i in range(n):
        m, l = sp.symbols(f"m{i + 1} l{i + 1}", positive=True)
        symbols[m.name], symbols[l.name] = m, l
        frame = frame.orientnew(f"A{i + 1}", "Axis", [q[i], frame.z])
        centre = joint.locatenew(f"G{i + 1}", l / 2 * frame.x)
        centre.v2pt_theory(joint, N, frame)
        tip = joint.locatenew(f"P{i + 1}", l * frame.x)
        tip.v2pt_theory(joint, N, frame)
        inertia = me.inertia(frame, 0, m * l**2 / 12, m * l**2 / 12)
        bodies.append(me.RigidBody(f"B{i + 1}", centre, frame, m, (inertia, centre)))
        loads.append((centre, -m * g * N.y))
        joint = tip
    kd = [u[i] - q[i].diff(me.dynamicsymbols._t) for i in range(n)]
    km = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    km.kanes_equations(bodies, loads)
    return km, q, u, symbols


def case_kane(n):
    import sympy as sp
    from sympy.physics import mechanics  # noqa: F401  (import excluded from the timing)

    _preimport()

    start = time.perf_counter()
    km, q_t, u_t, symbols = kane_pendulum(n)
    M, f = km.mass_matrix, km.forcing
    _emit(derive=time.perf_counter() - start)
    _emit(ops=int(sp.count_ops(list(M) + list(f))))
    params, q, u = _check_point(n)
    leaves = {symbols[k]: v for k, v in params.items()}
    leaves |= dict(zip(q_t, q, strict=True)) | dict(zip(u_t, u, strict=True))
    _emit(acc=_accelerations(M, f, leaves, n).tolist())


# -- parent side ----------------------------------------------------------------------------------
def run_case(n, side, timeout, script=__file__):
    """Run one case of ``script`` (``script --case SIDE N``) in a fresh process; returns its
    dict (``timeout``/``error`` on failure)."""
    cmd = [sys.executable, os.path.abspath(script), "--case", side, str(n)]
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        out, status = proc.stdout, None if proc.returncode == 0 else "error"
        err = proc.stderr
    except subprocess.TimeoutExpired as exc:
        out = exc.stdout.decode() if isinstance(exc.stdout, bytes) else (exc.stdout or "")
        status, err = "timeout", ""
    result = {}
    for line in out.splitlines():
        if line.startswith("{"):
            result.update(json.loads(line))
    if status:
        result["status"] = status
        if status == "error":
            result["stderr"] = err.strip().splitlines()[-1:] if err else []
    return result


def _rel_diff(a, b):
    import numpy as np

    a, b = np.asarray(a), np.asarray(b)
    return float(max(np.max(np.abs(a[k] - b[k])) / np.max(np.abs(b[k])) for k in range(len(b))))


def _fmt_time(x):
    if isinstance(x, str):
        return x
    return f"{x * 1e3:.0f} ms" if x < 1 else f"{x:.2f} s"


def _fmt_us(x):
    return "--" if x is None else f"{x * 1e6:.1f}"


def fit_exponent(ns, times):
    """Least-squares slope of log(time) against log(n)."""
    import numpy as np

    if len(ns) < 2:
        return float("nan")
    return float(np.polyfit(np.log(ns), np.log(times), 1)[0])


def header():
    import numpy as np
    import sympy as sp

    load = os.getloadavg()
    try:
        rev = subprocess.run(["git", "describe", "--always", "--dirty"], capture_output=True,
                             text=True, cwd=os.path.dirname(os.path.abspath(__file__)),
                             timeout=10).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        rev = ""
    lines = [
        "Planar n-link pendulum: deriving M(q) q'' = f with rigidmech vs sympy KanesMethod",
        f"python {platform.python_version()}, sympy {sp.__version__}, numpy {np.__version__}, "
        f"{os.cpu_count()} cores, {platform.machine()}, rigidmech {rev or '(no git)'}",
        f"load average (1, 5, 15 min) at start: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}"
        + ("  -- machine shared with other jobs: absolute times inflated"
           if load[0] > 0.5 * (os.cpu_count() or 1) else ""),
    ]
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sizes", nargs="*", type=int, help=f"values of n (default {SIZES})")
    parser.add_argument("--quick", action="store_true", help=f"n = {QUICK_SIZES}")
    parser.add_argument("--max-kane", type=int, default=12, help="run Kane only up to this n")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per case")
    parser.add_argument("--json", help="also write the raw results to this file")
    parser.add_argument("--case", nargs=2, metavar=("SIDE", "N"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)

    if args.case:
        side, n = args.case[0], int(args.case[1])
        {"ours": case_ours, "kane": case_kane}[side](n)
        return 0

    sizes = args.sizes or (QUICK_SIZES if args.quick else SIZES)
    print(header(), flush=True)
    print(f"per case: fresh process, timeout {args.timeout:.0f} s; Kane up to n = "
          f"{args.max_kane}; rhs batch of {BATCH} states; check at {N_CHECK} random states\n",
          flush=True)
    cols = ("n", "ours", "Kane", "Kane/ours", "ops ours", "ops Kane", "ops cse ours",
            "compile", "rhs 1 [us]", "rhs batch [us/state]", "max rel diff")
    widths = (3, 9, 9, 9, 9, 10, 12, 9, 10, 20, 12)
    line = "  ".join(c.rjust(w) for c, w in zip(cols, widths, strict=True))
    print(line + "\n" + "-" * len(line), flush=True)
    results = {}
    for n in sizes:
        ours = run_case(n, "ours", args.timeout)
        kane = run_case(n, "kane", args.timeout) if n <= args.max_kane else {"status": "skipped"}
        results[n] = {"ours": ours, "kane": kane}
        t_ours = ours.get("derive", ours.get("status", "?"))
        t_kane = kane.get("derive", kane.get("status", "?"))
        ratio = (f"{t_kane / t_ours:.1f}" if isinstance(t_ours, float)
                 and isinstance(t_kane, float) else "--")
        diff = "--"
        if "acc" in ours and "acc" in kane:
            d = max(_rel_diff(ours["acc"], kane["acc"]),
                    _rel_diff(ours["acc_compiled"], kane["acc"]))
            results[n]["max_rel_diff"] = d
            diff = f"{d:.1e}"
        row = (str(n), _fmt_time(t_ours), _fmt_time(t_kane), ratio,
               str(ours.get("ops", "--")), str(kane.get("ops", "--")),
               str(ours.get("ops_cse", "--")), _fmt_time(ours.get("compile", "--")),
               _fmt_us(ours.get("rhs_single")),
               _fmt_us(ours.get("rhs_batch")), diff)
        print("  ".join(c.rjust(w) for c, w in zip(row, widths, strict=True)), flush=True)
        for side, res in (("ours", ours), ("kane", kane)):
            if res.get("status") == "error":
                print(f"    {side} failed: {res.get('stderr')}", flush=True)

    load = os.getloadavg()
    print(f"\nload average at end: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    fit = [(n, r["ours"]["derive"]) for n, r in results.items()
           if n >= 3 and isinstance(r["ours"].get("derive"), float)]
    if len(fit) >= 2:
        exponent = fit_exponent([n for n, _ in fit], [t for _, t in fit])
        print(f"growth of our derive time: ~ n^{exponent:.2f} (log-log fit over n = "
              f"{', '.join(str(n) for n, _ in fit)})")

    print("\nTargets (TARGETS.md):")
    checks = []

    def target(label, value, ok, shown):
        status = "n/a " if ok is None else ("PASS" if ok else "FAIL")
        checks.append(ok)
        print(f"  [{status}] {label}: {shown}")

    r8 = results.get(8)
    if r8 and isinstance(r8["ours"].get("derive"), float) and isinstance(
            r8["kane"].get("derive"), float):
        ratio = r8["kane"]["derive"] / r8["ours"]["derive"]
        target(f">= {TARGET_RATIO_N8:.0f}x faster than Kane at n = 8", ratio,
               ratio >= TARGET_RATIO_N8, f"{ratio:.1f}x")
    else:
        target(f">= {TARGET_RATIO_N8:.0f}x faster than Kane at n = 8", None, None, "not run")
    r12 = results.get(12, {}).get("ours", {})
    if isinstance(r12.get("derive"), float):
        target(f"n = 12 derived in < {TARGET_DERIVE_N12:.0f} s", r12["derive"],
               r12["derive"] < TARGET_DERIVE_N12, _fmt_time(r12["derive"]))
        target(f"rhs single state at n = 12 <= {TARGET_SINGLE_N12 * 1e6:.0f} us",
               r12["rhs_single"], r12["rhs_single"] <= TARGET_SINGLE_N12,
               f"{r12['rhs_single'] * 1e6:.1f} us")
        target(f"rhs batched at n = 12 <= {TARGET_BATCH_N12 * 1e6:.0f} us per state",
               r12["rhs_batch"], r12["rhs_batch"] <= TARGET_BATCH_N12,
               f"{r12['rhs_batch'] * 1e6:.2f} us/state")
    else:
        for label in ("n = 12 derived in < 2 s", "rhs single state at n = 12 <= 100 us",
                      "rhs batched at n = 12 <= 10 us per state"):
            target(label, None, None, "not run")
    diffs = [r["max_rel_diff"] for r in results.values() if "max_rel_diff" in r]
    if diffs:
        worst = max(diffs)
        target(f"q'' agrees with Kane to {CHECK_TOL:g} relative", worst, worst <= CHECK_TOL,
               f"worst {worst:.1e} over n = "
               f"{', '.join(str(n) for n, r in results.items() if 'max_rel_diff' in r)}")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({str(k): v for k, v in results.items()}, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
