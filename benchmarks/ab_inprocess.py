"""A/B of one ``rigidmech.ode`` module against its version at a git commit, in ONE process.

On a shared machine two processes run minutes apart see different loads; here the old module
is loaded beside the new one (its source from ``git show COMMIT:path``, its registered method
names suffixed with ``_old``) and both run the same cases alternately; the best CPU time
(``time.process_time``) of ``--rounds`` runs each is compared, and the evaluations and final
states checked identical. Run from the repository root::

    PYTHONPATH=src python benchmarks/ab_inprocess.py adams --commit 77077cc --rounds 30
    PYTHONPATH=src python benchmarks/ab_inprocess.py runge_kutta --commit c9b9399
    PYTHONPATH=src python benchmarks/ab_inprocess.py rkn --commit 77077cc
    PYTHONPATH=src python benchmarks/ab_inprocess.py adaptive --commit 77077cc

Modules: adams, runge_kutta (fixed-step tableaux), rkn (constant step), adaptive (dopri5,
dop853 numpy and batch paths, plus a control cell whose code is shared by both).
"""

from __future__ import annotations

import argparse
import importlib.util
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

from rigidmech import ode
from rigidmech.testing import problems as P


def load_old(module, commit):
    src = subprocess.run(["git", "show", f"{commit}:src/rigidmech/ode/{module}.py"],
                         check=True, capture_output=True, text=True).stdout
    src = re.sub(r'register\("(\w+)"', r'register("\1_old"', src)  # adaptive, adams, rkn
    src = src.replace('_registry.register(_t.name,', '_registry.register(_t.name + "_old",')
    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as fh:
        fh.write(src)
    spec = importlib.util.spec_from_file_location(f"rigidmech.ode._old_{module}", fh.name)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def _osc(t, y):
    return np.array([y[1], -y[0]])


def _solve_case(fun, span, y0, method, **kw):
    """(new, old): the same solve call with `method` and with ``method + "_old"``."""
    return (lambda: ode.solve(fun, span, y0, method=method, **kw),
            lambda: ode.solve(fun, span, y0, method=method + "_old", **kw))


def _direct_case(new, old, *args, **kw):
    return lambda: new(*args, **kw), lambda: old(*args, **kw)


def cases(module, old):
    """``[(label, new_run, old_run)]`` for `module`."""
    if module == "runge_kutta":
        return [(m, *_solve_case(_osc, (0.0, 200.0), [1.0, 0.0], m, step=0.01))
                for m in ("euler", "rk4", "rk38", "midpoint")]
    if module == "rkn":
        from rigidmech.ode import rkn
        k = P.kepler(0.6, orbits=10)
        return [(f"{m} constant step, {n} steps",
                 *_direct_case(getattr(rkn, m), getattr(old, m), k.acceleration, k.t_span,
                               k.y0, step=(k.t_span[1] - k.t_span[0]) / n))
                for m, n in (("rkn64", 4000), ("rkn1210", 1000))]
    if module == "adams":
        d, k = P.damped_oscillator(10.0, 0.05), P.kepler(0.6, orbits=10)
        y20 = np.stack([np.linspace(0.5, 1.5, 20), np.zeros(20)])
        runs = [("oscillator", d.fun, d.t_span, d.y0, {}),
                ("oscillator dense", d.fun, d.t_span, d.y0, {"dense_output": True}),
                ("Kepler", k.fun, k.t_span, k.y0, {}),
                ("Kepler dense", k.fun, k.t_span, k.y0, {"dense_output": True}),
                ("batch of 20", lambda t, y: np.stack([y[1], -y[0]]), (0, 50), y20, {})]
        return [(f"adams {c}", *_solve_case(f, s, y, "adams", rtol=1e-10, atol=1e-13, **kw))
                for c, f, s, y, kw in runs]
    n = 40
    lap = np.diag(-2.0 * np.ones(n)) + np.diag(np.ones(n - 1), 1) + np.diag(np.ones(n - 1), -1)
    y0 = np.concatenate([np.sin(np.linspace(0, np.pi, n)), np.zeros(n)])
    ecc = np.linspace(0.1, 0.7, 200)
    yb = np.stack([1 - ecc, np.zeros(200), np.zeros(200), np.sqrt((1 + ecc) / (1 - ecc))])

    def chain(t, y):
        return np.concatenate([y[n:], lap @ y[:n]])

    def kb(t, y):
        r3 = (y[0] ** 2 + y[1] ** 2) ** 1.5
        return np.stack([y[2], y[3], -y[0] / r3, -y[1] / r3])

    runs = [("dop853 chain n=80", "dop853", chain, (0, 20.0), y0),
            ("dopri5 chain n=80", "dopri5", chain, (0, 20.0), y0),
            ("dop853 batch 200", "dop853", kb, (0, 4 * np.pi), yb),
            ("dop853 oscillator (control)", "dop853", _osc, (0, 100.0), np.array([1.0, 0.0]))]
    return [(c, *_solve_case(f, s, y, m, rtol=1e-8, atol=1e-10)) for c, m, f, s, y in runs]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("module", choices=("adams", "runge_kutta", "rkn", "adaptive"))
    ap.add_argument("--commit", required=True)
    ap.add_argument("--rounds", type=int, default=15)
    args = ap.parse_args(argv)
    old = load_old(args.module, args.commit)
    print(f"{'cell':<30} {'nfev':>7} same  {'old ms':>8} {'new ms':>8}  ratio")
    for label, new_f, old_f in cases(args.module, old):
        best, res = {}, {}
        for i in range(args.rounds):
            for tag, f in ((("old", old_f), ("new", new_f)) if i % 2 else
                           (("new", new_f), ("old", old_f))):
                t = time.process_time()
                r = f()
                best[tag] = min(best.get(tag, 1e9), time.process_time() - t)
                res[tag] = (r.nfev, r.y[..., -1].tobytes())
        print(f"{label:<30} {res['new'][0]:>7} {str(res['new'] == res['old']):<5} "
              f"{best['old'] * 1e3:8.2f} {best['new'] * 1e3:8.2f}  {best['new'] / best['old']:.3f}")


if __name__ == "__main__":
    main()
