"""Cost of the compiled right-hand side q'' = M(q)^-1 f(q, q') of the planar n-link pendulum.

Anchor (TARGETS.md, "Numeric right-hand side"): sympy.lambdify with and without cse, and PyDy's
ODEFunctionGenerator, on the mass matrix and forcing of sympy.physics.mechanics.KanesMethod.
rigidmech's side is :func:`time_rhs`, reusable with our own derivation of M and f later.

Run::

    .venv/bin/python benchmarks/compile_rhs.py            # n = 2, 5, 8
    .venv/bin/python benchmarks/compile_rhs.py 2 5 8 12   # n = 12: Kane alone takes ~70 s

Prints, per n: ops after cse, build time, the per-call cost for one state and the per-state
cost in a batch of 1000 states, and the ratio of each anchor to rigidmech (> 1: we are faster).
Absolute times drift between runs; the ratios, measured side by side in one run, are the claim.
"""

import sys
import time
import timeit
import warnings

import numpy as np
import sympy
from sympy.physics import mechanics as me

from rigidmech._core import _cse
from rigidmech._core.compile import compile_linear_solve

BATCH = 1000


def pendulum_kane(n):
    """M, f and the plain symbols q, u, params of the planar n-link pendulum (KanesMethod).

    Uniform rods of masses m_i and lengths l_i, relative joint angles q_i, gravity g along -y.
    Returns ``(M, f, q, u, params, KM, q_t, u_t)``; the last three for PyDy.
    """
    q_t = me.dynamicsymbols(f"q:{n}")
    u_t = me.dynamicsymbols(f"u:{n}")
    m = sympy.symbols(f"m:{n}")
    lengths = sympy.symbols(f"l:{n}")
    g = sympy.Symbol("g")
    N = me.ReferenceFrame("N")
    joint = me.Point("O")
    joint.set_vel(N, 0)
    parent = N
    bodies, loads = [], []
    for i in range(n):
        frame = parent.orientnew(f"A{i}", "Axis", [q_t[i], N.z])
        frame.set_ang_vel(N, sum(u_t[: i + 1]) * N.z)
        centre = joint.locatenew(f"G{i}", -lengths[i] / 2 * frame.y)
        centre.v2pt_theory(joint, N, frame)
        tip = joint.locatenew(f"P{i}", -lengths[i] * frame.y)
        tip.v2pt_theory(joint, N, frame)
        inertia = me.inertia(frame, 0, 0, m[i] * lengths[i] ** 2 / 12)
        bodies.append(me.RigidBody(f"B{i}", centre, frame, m[i], (inertia, centre)))
        loads.append((centre, -m[i] * g * N.y))
        joint, parent = tip, frame
    kd = [q_t[i].diff() - u_t[i] for i in range(n)]
    KM = me.KanesMethod(N, q_ind=q_t, u_ind=u_t, kd_eqs=kd)
    KM.kanes_equations(bodies, loads)
    q = sympy.symbols(f"q:{n}")
    u = sympy.symbols(f"u:{n}")
    plain = dict(zip(q_t, q, strict=True)) | dict(zip(u_t, u, strict=True))
    M = KM.mass_matrix.xreplace(plain)
    f = KM.forcing.xreplace(plain)
    params = [g, *m, *lengths]
    return M, f, q, u, params, KM, q_t, u_t


def _per_call(func, budget=0.4):
    """Best per-call time (s) of `func()` over 5 repeats of a count filling about `budget` s."""
    timer = timeit.Timer(func)
    number, elapsed = 1, timer.timeit(1)
    while elapsed * number < budget / 5 and number < 100_000:
        number *= 2 if elapsed * number * 10 > budget / 5 else 10
    return min(timer.repeat(repeat=5, number=number)) / number


def _states(n, n_params, count, seed=0):
    rng = np.random.default_rng(seed)
    q = rng.uniform(-np.pi, np.pi, (n, count))
    u = rng.uniform(-1.0, 1.0, (n, count))
    p = np.concatenate([[9.81], rng.uniform(0.5, 2.0, n_params - 1)])
    return q, u, p


def time_rhs(M, f, q, u, params):
    """Compile q'' = M^-1 f with rigidmech and time it: one state, and per state in a batch.

    Parameters
    ----------
    M, f : sympy.Matrix
        Mass matrix (n, n, symmetric) and forcing (n, 1) in plain Symbols.
    q, u : sequence of sympy.Symbol
        Coordinates and their rates.
    params : sequence of sympy.Symbol
        Constants, passed as one vector argument.

    Returns
    -------
    dict
        ``build`` (s), ``single`` (s per call), ``batch`` (s per state over BATCH states),
        ``n_ops``, and ``solve`` (the compiled callable, ``solve(q, u, params)``).
    """
    start = time.perf_counter()
    solve = compile_linear_solve(M, f, [list(q), list(u), list(params)], symmetric=True)
    build = time.perf_counter() - start
    qs, us, p = _states(len(q), len(params), BATCH)
    q1, u1 = qs[:, 0].copy(), us[:, 0].copy()
    single = _per_call(lambda: solve(q1, u1, p))
    batch = _per_call(lambda: solve(qs, us, p)) / BATCH
    return {"build": build, "single": single, "batch": batch, "n_ops": solve.n_ops, "solve": solve}


def _lambdify_rhs(M, f, q, u, params, cse):
    args = [*q, *u, *params]
    start = time.perf_counter()
    mass = sympy.lambdify(args, M, modules="numpy", cse=cse)
    forcing = sympy.lambdify(args, f, modules="numpy", cse=cse)
    build = time.perf_counter() - start

    def rhs(qv, uv, p):
        values = (*qv, *uv, *p)
        return np.linalg.solve(mass(*values), forcing(*values).ravel())

    return rhs, build


def _pydy_rhs(KM, q_t, u_t, params):
    try:
        from pydy.codegen.ode_function_generators import generate_ode_function
    except ImportError as exc:  # pragma: no cover - depends on the environment
        return None, f"pydy not importable ({exc})"
    start = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            rhs = generate_ode_function(
                KM.forcing,
                q_t,
                u_t,
                params,
                mass_matrix=KM.mass_matrix,
                coordinate_derivatives=sympy.Matrix(u_t),
                generator="lambdify",
                linear_sys_solver="numpy",
            )
    except Exception as exc:  # pragma: no cover - pydy's backends vary
        return None, f"pydy lambdify backend failed ({type(exc).__name__}: {exc})"
    return (rhs, time.perf_counter() - start), None


def _loop_per_state(rhs, qs, us, p, count):
    """Per-state cost of a right-hand side that only takes one state: a Python loop."""
    columns = [(qs[:, k].copy(), us[:, k].copy()) for k in range(count)]

    def run():
        for qv, uv in columns:
            rhs(qv, uv, p)

    return _per_call(run, budget=1.0) / count


def run(n_values):
    print(f"planar n-link pendulum, q'' = M^-1 f; batch of {BATCH} states; times in microseconds")
    print("ratio = anchor time / rigidmech time (> 1: rigidmech faster)\n")
    header = (
        f"{'n':>3} {'method':<22} {'ops':>7} {'build s':>8} {'single':>9} {'ratio':>6} "
        f"{'per state':>10} {'ratio':>7}"
    )
    print(header)
    print("-" * len(header))
    for n in n_values:
        start = time.perf_counter()
        M, f, q, u, params, KM, q_t, u_t = pendulum_kane(n)
        kane_time = time.perf_counter() - start
        ours = time_rhs(M, f, q, u, params)
        qs, us, p = _states(n, len(params), BATCH)
        q1, u1 = qs[:, 0].copy(), us[:, 0].copy()
        x_ours = ours["solve"](q1, u1, p)
        batch_ours = ours["solve"](qs, us, p)
        kane_ops = sympy.count_ops(M) + sympy.count_ops(f) if n <= 8 else float("nan")
        print(
            f"{n:>3} {'(Kane derivation)':<22} {kane_ops:>7} {kane_time:>8.2f}"
        )
        print(
            f"{n:>3} {'rigidmech':<22} {ours['n_ops']:>7} {ours['build']:>8.2f} "
            f"{ours['single'] * 1e6:>9.1f} {1.0:>6.2f} {ours['batch'] * 1e6:>10.2f} {1.0:>7.2f}"
        )
        anchors = []
        for label, cse in (("lambdify", False), ("lambdify + cse", True)):
            if not cse and n > 8:
                print(f"{n:>3} {label:<22} skipped (build > 200 s at n = 12, TARGETS.md)")
                continue
            rhs, build = _lambdify_rhs(M, f, q, u, params, cse)
            anchors.append((label, rhs, build))
        pydy, why = _pydy_rhs(KM, q_t, u_t, params)
        if pydy is None:
            print(f"{n:>3} {'pydy lambdify':<22} skipped: {why}")
        else:
            rhs_pydy, build = pydy

            def pydy_call(qv, uv, p, rhs_pydy=rhs_pydy, n=n):
                return rhs_pydy(np.concatenate([qv, uv]), 0.0, p)[n:]

            anchors.append(("pydy lambdify", pydy_call, build))
        for label, rhs, build in anchors:
            x = rhs(q1, u1, p)
            np.testing.assert_allclose(x, x_ours, rtol=1e-9, atol=1e-9)
            single = _per_call(lambda rhs=rhs, q1=q1, u1=u1, p=p: rhs(q1, u1, p))
            count = BATCH if single < 1e-3 else max(10, int(0.5 / single))
            per_state = _loop_per_state(rhs, qs, us, p, count)
            check = rhs(qs[:, 7].copy(), us[:, 7].copy(), p)
            np.testing.assert_allclose(check, batch_ours[:, 7], rtol=1e-9, atol=1e-9)
            print(
                f"{n:>3} {label:<22} {'':>7} {build:>8.2f} {single * 1e6:>9.1f} "
                f"{single / ours['single']:>6.2f} {per_state * 1e6:>10.2f} "
                f"{per_state / ours['batch']:>7.2f}"
            )
        print()
    print("anchors take one state per call: their per-state cost is a Python loop over states.")
    print("pydy cython backend: not measured (Cython is not installed in the venv).")


def cse_optimizations(n=5):
    """n_ops and single-state cost with sympy.cse(optimizations=None) vs 'basic'."""
    M, f, q, u, params, *_ = pendulum_kane(n)
    print(f"\nsympy.cse optimizations at n = {n}:")
    saved = _cse._CSE_OPTIMIZATIONS
    try:
        for setting in (None, "basic"):
            _cse._CSE_OPTIMIZATIONS = setting
            result = time_rhs(M, f, q, u, params)
            print(
                f"  optimizations={setting!r:8} n_ops={result['n_ops']:>6} "
                f"build={result['build']:.2f} s single={result['single'] * 1e6:.1f} us "
                f"per state={result['batch'] * 1e6:.2f} us"
            )
    finally:
        _cse._CSE_OPTIMIZATIONS = saved


if __name__ == "__main__":
    ns = [int(a) for a in sys.argv[1:] if a.isdigit()] or [2, 5, 8]
    run(ns)
    if "--no-cse-check" not in sys.argv:
        cse_optimizations()
