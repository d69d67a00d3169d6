"""A/B timing of the compiled linear solve q'' = M^-1 f of the planar n-link pendulum between two
checkouts of rigidmech, in one process: calls interleaved, minimum over repeats (on a shared
machine the minimum is the least disturbed figure).

Run::

    python benchmarks/ab_linear_solve.py OLD_SRC NEW_SRC   # e.g. ../main/src src

Prints, for n = 2, 5, 8, the single-state call and the per-state cost in a batch of 1000.
"""
import importlib.util
import pathlib
import sys
import timeit

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).parent))

def load(name, root):
    """rigidmech._core.compile of the checkout whose source root is ``root``."""
    spec = importlib.util.spec_from_file_location(
        name, f"{root}/rigidmech/_core/__init__.py",
        submodule_search_locations=[f"{root}/rigidmech/_core"])
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod
    spec.loader.exec_module(mod)
    return importlib.import_module(f"{name}.compile")

old = load("core_old", sys.argv[1])
new = load("core_new", sys.argv[2])
from compile_rhs import pendulum_kane  # noqa: E402

rng = np.random.default_rng(0)
for n in (2, 5, 8):
    M, f, q, u, params = pendulum_kane(n)[:5]
    args = [list(q), list(u), *params]
    fo = old.compile_linear_solve(M, f, args, symmetric=True)
    fn = new.compile_linear_solve(M, f, args, symmetric=True)
    q0, u0 = rng.uniform(-1, 1, n), rng.uniform(-1, 1, n)
    pv = [1.0] * len(params)
    Q, U = rng.uniform(-1, 1, (n, 1000)), rng.uniform(-1, 1, (n, 1000))
    assert np.allclose(fo(q0, u0, *pv), fn(q0, u0, *pv), rtol=1e-12)
    res = {"old": [[], []], "new": [[], []]}
    for _ in range(15):
        for key, fun in (("old", fo), ("new", fn)):
            one = (fun, q0, u0, pv)
            many = (fun, Q, U, pv)
            single = timeit.repeat(lambda a=one: a[0](a[1], a[2], *a[3]), number=300, repeat=3)
            batch = timeit.repeat(lambda a=many: a[0](a[1], a[2], *a[3]), number=10, repeat=3)
            res[key][0].append(min(single) / 300 * 1e6)
            res[key][1].append(min(batch) / 10 / 1000 * 1e6)
    o1, o2 = min(res["old"][0]), min(res["old"][1])
    n1, n2 = min(res["new"][0]), min(res["new"][1])
    print(f"n={n}: single old {o1:6.2f} us new {n1:6.2f} us ({100*(n1/o1-1):+.1f} %); "
          f"batch per state old {o2:.3f} us new {n2:.3f} us ({100*(n2/o2-1):+.1f} %)")
