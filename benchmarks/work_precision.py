"""Work-precision of rigidmech.ode against scipy.integrate.solve_ivp, side by side in one run.

Problems (rigidmech.testing.problems, book ch. 27): simple pendulum theta0 = 170 deg over 10
periods, Kepler e = 0.6 and e = 0.9 over 10 orbits, damped forced oscillator (omega0 = 10,
zeta = 0.05). Both libraries get the same ``fun`` (the problem's); the methods for
``q'' = a(t, q)`` (yoshida4/6, the Runge-Kutta-Nystrom pairs rkn64 and rkn1210, on the pendulum
and Kepler only) get the acceleration written in the same plain-float style. Adaptive methods sweep
rtol = 1e-3 ... 1e-14 in half decades (``--quick``: whole decades) with atol = 1e-3 rtol
(TARGETS.md); fixed-step methods sweep the number of steps. For every run: final error (max norm
against the exact solution), wall time (best of --repeats, taken in rounds over the problem's
whole sweep) and nfev. Then, per problem and error
level, the cheapest of ours against the cheapest solve_ivp run ("best against best") and the
ratio of wall times, and a PASS/FAIL line per target of TARGETS.md. The header prints the
machine, the versions and ``uptime`` (the machine may be shared: compare ratios, not times).

Usage::

    python benchmarks/work_precision.py [--out DIR] [--repeats 3] [--quick] [--long]

``--long`` adds the long-time energy figure: Kepler e = 0.6 over 10,000 orbits, Yoshida's
order-6 composition (400 steps per orbit) against DOP853 (rtol 1e-10), with the growth exponent
of the energy error (about 3 minutes).
"""

from __future__ import annotations

import argparse
import math
import os
import time
import warnings

import numpy as np
from scipy.integrate import solve_ivp

from rigidmech import ode
from rigidmech.ode import rkn
from rigidmech.testing import problems as P

LEVELS = (1e-6, 1e-8, 1e-10, 1e-11)
#: our adaptive methods: name shown -> (method, options)
OURS_ADAPTIVE = {
    "dopri5": ("dopri5", {}),
    "dop853": ("dop853", {}),
    "dop853-pi": ("dop853", {"step_control": "pi"}),
    "gbs": ("gbs", {}),
    "adams": ("adams", {}),
    "radau": ("radau", {}),
}
#: our Runge-Kutta-Nystrom pairs (separable problems only: q'' = a(t, q)), called directly
#: (ode.solve runs them adaptively too, at the cost of one more call of fun to check its shape)
OURS_RKN = {"rkn64": rkn.rkn64, "rkn1210": rkn.rkn1210}
SCIPY = ("RK45", "DOP853", "LSODA", "Radau")
SLOW_RUN = 0.5  # seconds: a run slower than this is timed once
GIVE_UP = 3.0  # seconds: a method's tighter tolerances are skipped after a run this slow
RADAU_MIN_RTOL = 1e-9  # implicit methods are far too slow below this on non-stiff problems


def _problems():
    return [
        P.pendulum(170.0, periods=10),
        P.kepler(0.6, orbits=10),
        P.kepler(0.9, orbits=10),
        P.damped_oscillator(10.0, 0.05),
    ]


def _float_acceleration(p):
    """The problem's acceleration written like its ``fun`` (plain floats, a fresh ndarray).

    ``p.acceleration`` works on numpy scalars (about 3.3 us a call for Kepler against 1.7 us
    for ``p.fun``); the methods taking ``a(t, q)`` get this same-cost form instead, checked
    equal to ``p.acceleration``, so that the per-call cost of the user function stays the same
    for every method compared.
    """
    if p.acceleration is None:
        return None
    d = len(p.y0) // 2
    if d == 1:  # pendulum: a = -w2 sin(theta)
        w2 = -float(p.acceleration(0.0, np.array([math.pi / 2]))[0])

        def acc(t, q):
            (th,) = q.tolist()
            return np.array([-w2 * math.sin(th)])
    else:  # Kepler: a = -mu r / |r|^3
        mu = -float(p.acceleration(0.0, np.array([1.0, 0.0]))[0])

        def acc(t, q):
            x1, x2 = q.tolist()
            r2 = x1 * x1 + x2 * x2
            c = -mu / (r2 * math.sqrt(r2))
            return np.array([c * x1, c * x2])
    for q in (np.asarray(p.y0[:d], dtype=float), np.full(d, 0.7)):
        np.testing.assert_allclose(acc(0.0, q), p.acceleration(0.0, q), rtol=1e-14)
    return acc


def _timed(run):
    t0 = time.perf_counter()
    out = run()
    return time.perf_counter() - t0, out


def _retime(rows, pending, repeats):
    """Time every run of `pending` again, ``repeats - 1`` rounds over the whole list; keep the
    best time. Rounds over the whole sweep (instead of repeating each run at once) spread a
    run's samples over minutes, so that a slow spell of the shared machine cannot spoil all
    the samples of one run (and its ratio) while sparing its neighbours."""
    for _ in range(repeats - 1):
        for i, run in pending:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                t, _ = _timed(run)
            r = rows[i]
            rows[i] = r[:3] + (min(r[3], t),) + r[4:]


def _sweep(p, repeats, quick):
    # half decades from 1e-3 to 1e-14 (scipy raises rtol < 2.2e-14 to 2.2e-14 itself)
    rtols = [10.0 ** (-k / 2) for k in range(6, 29)]
    if quick:
        rtols = rtols[::2]
    rows = []
    pending = []  # (row, run) of the runs timed again (_retime)
    for name in tuple(OURS_ADAPTIVE) + tuple("scipy:" + s for s in SCIPY):
        slowest = 0.0
        for rtol in rtols:
            if slowest > GIVE_UP:  # same rule for both libraries: it cannot be the cheapest
                continue
            if name.lower().endswith("radau") and (
                rtol < RADAU_MIN_RTOL or abs(math.log10(rtol) - round(math.log10(rtol))) > 1e-9
            ):  # implicit: whole decades only, not below RADAU_MIN_RTOL (seconds per run)
                continue
            atol = 1e-3 * rtol
            if name.startswith("scipy:"):
                m = name[6:]

                def run(m=m, rtol=rtol, atol=atol):
                    s = solve_ivp(p.fun, p.t_span, p.y0, method=m, rtol=rtol, atol=atol)
                    return s.y[:, -1], s.nfev, s.success
            else:

                method, opts = OURS_ADAPTIVE[name]

                def run(method=method, opts=opts, rtol=rtol, atol=atol):
                    r = ode.solve(p.fun, p.t_span, p.y0, method=method, rtol=rtol, atol=atol,
                                  max_steps=10**7, **opts)
                    return r.y[:, -1], r.nfev, r.success
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                t, (y, nfev, ok) = _timed(run)
            slowest = max(slowest, t)
            rows.append((name, f"rtol={rtol:.1e}", p.final_error(y) if ok else math.nan, t, nfev))
            if t <= SLOW_RUN:  # long runs: their noise is relatively small, time them once
                pending.append((len(rows) - 1, run))
    acc = _float_acceleration(p)
    if acc is not None:  # Runge-Kutta-Nystrom pairs, same tolerances and give-up rule
        for name, method in OURS_RKN.items():
            slowest = 0.0
            for rtol in rtols:
                if slowest > GIVE_UP:
                    continue
                atol = 1e-3 * rtol

                def run(method=method, rtol=rtol, atol=atol):
                    r = method(acc, p.t_span, p.y0, rtol=rtol, atol=atol, max_steps=10**7)
                    return r.y[:, -1], r.nfev, r.success
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    t, (y, nfev, ok) = _timed(run)
                slowest = max(slowest, t)
                err = p.final_error(y) if ok else math.nan
                rows.append((name, f"rtol={rtol:.1e}", err, t, nfev))
                if t <= SLOW_RUN:
                    pending.append((len(rows) - 1, run))
    # fixed-step methods: geometric (separable problems) and Adams PECE
    fixed = [("abm5", p.fun)]
    if acc is not None:
        fixed.insert(0, ("yoshida6", acc))
        fixed.insert(1, ("yoshida4", acc))
    counts = [250 * 2**j for j in range(0, 9, 2 if quick else 1)]
    length = p.t_span[1] - p.t_span[0]
    for name, f in fixed:
        for n in counts:
            if name == "yoshida6" and n > 32000:
                continue

            def run(name=name, f=f, n=n):
                r = ode.solve(f, p.t_span, p.y0, method=name, step=length / n,
                              max_steps=10**7)
                return r.y[:, -1], r.nfev, r.success
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                t, (y, nfev, ok) = _timed(run)
            err = p.final_error(y) if ok and np.all(np.isfinite(y)) else math.nan
            rows.append((name, f"N={n}", err, t, nfev))
            if t <= SLOW_RUN:
                pending.append((len(rows) - 1, run))
    _retime(rows, pending, repeats)
    return rows


def _cheapest(rows, level, scipy):
    ok = [r for r in rows if (r[0].startswith("scipy:") == scipy) and r[2] <= level]
    return min(ok, key=lambda r: r[3]) if ok else None


def _fmt(r):
    return "not reached" if r is None else f"{r[0]} {r[1]} {r[3] * 1e3:.1f} ms (err {r[2]:.1e})"


def _plot(p, rows, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 5))
    for name in dict.fromkeys(r[0] for r in rows):
        pts = [(r[2], r[3]) for r in rows if r[0] == name and np.isfinite(r[2]) and r[2] > 0]
        if pts:
            e, t = zip(*pts, strict=True)
            ax.loglog(e, t, "o--" if name.startswith("scipy:") else "s-", label=name, ms=4)
    ax.set_xlabel("final error (max norm)")
    ax.set_ylabel("wall time [s]")
    ax.set_title(f"work-precision: {p.name}")
    ax.invert_xaxis()
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    path = os.path.join(out, f"wp_{p.name}.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def long_run(out, orbits=10_000, per_orbit=400):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    p = P.kepler(0.6, orbits=orbits)
    E0 = p.energy(p.y0)
    t0 = time.perf_counter()
    from rigidmech.ode.geometric import yoshida6

    r = yoshida6(p.acceleration, p.t_span, p.y0, step=p.period / per_orbit, save_every=7)
    t_sym = time.perf_counter() - t0
    t0 = time.perf_counter()
    s = ode.solve(p.fun, p.t_span, p.y0, method="dop853", rtol=1e-10, atol=1e-13,
                  max_steps=10**8)
    t_dop = time.perf_counter() - t0
    res = {}
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, t, y, el in [(f"yoshida6, T/{per_orbit}", r.t, r.y, t_sym),
                            ("dop853, rtol 1e-10", s.t, s.y, t_dop)]:
        rel = np.abs((p.energy(y) - E0) / E0)
        edges = np.linspace(0, t[-1], 101)
        idx = np.searchsorted(t, edges)
        peaks = np.array([rel[idx[i]: idx[i + 1] + 1].max() for i in range(100)])
        g = np.polyfit(np.log(edges[1:]), np.log(peaks), 1)[0]
        res[label] = (peaks.max(), g, el)
        ax.loglog(edges[1:] / p.period, peaks, label=f"{label}: max {peaks.max():.1e}, g={g:.2f}")
        print(f"{label:24s} max |dE/E| = {peaks.max():.2e}  after 1% {peaks[0]:.2e}  "
              f"growth exponent {g:.3f}  wall {el:.1f} s")
    ax.set_xlabel("orbits")
    ax.set_ylabel("max |dE/E| per window")
    ax.set_title("Kepler e = 0.6, 10,000 orbits")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "long_time_energy.png"), dpi=110)
    plt.close(fig)
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="./out/work_precision")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="every other tolerance / step count")
    ap.add_argument("--long", action="store_true", help="also the 10,000-orbit energy figure")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    import platform
    import subprocess
    import sys

    import scipy

    up = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    print(f"command: python {' '.join(sys.argv)}")
    print(f"machine: {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"numpy {np.__version__}, scipy {scipy.__version__}; uptime: {up}")
    print(f"timing: best of {args.repeats}, in rounds over each problem's whole sweep "
          f"(a run over {SLOW_RUN} s is timed once)")
    summary = []
    verdicts = []
    for p in _problems():
        rows = _sweep(p, args.repeats, args.quick)
        print(f"\n== {p.name}: {p.description}, t_end = {p.t_span[1]:.4g}")
        print(f"{'method':14s} {'setting':11s} {'final err':>10s} {'time ms':>9s} {'nfev':>8s}")
        for r in rows:
            print(f"{r[0]:14s} {r[1]:11s} {r[2]:10.2e} {r[3] * 1e3:9.2f} {r[4]:8d}")
        print(f"plot: {_plot(p, rows, args.out)}")
        for level in LEVELS:
            ours, ref = _cheapest(rows, level, False), _cheapest(rows, level, True)
            ratio = (f"{ours[3] / ref[3]:.2f}" if ours and ref
                     else ("ours only" if ours else "-"))
            summary.append((p.name, level, _fmt(ours), _fmt(ref), ratio))
            if ours and ref and level <= 1e-6:
                verdicts.append(ours[3] / ref[3] <= 1.0 / 3.0)
            elif ref and not ours:
                verdicts.append(False)
        if p.name == "kepler-e0.6":
            best = min((r[2] for r in rows if not r[0].startswith("scipy:")
                        and np.isfinite(r[2])), default=math.nan)
            target2 = (best, best <= 1e-11)
    print("\n== cheapest run reaching the error level (ratio = our time / solve_ivp time)")
    print(f"{'problem':22s} {'err <=':7s} | {'ours':52s} | {'solve_ivp':52s} | ratio")
    for name, level, ours, ref, ratio in summary:
        print(f"{name:22s} {level:7.0e} | {ours:52s} | {ref:52s} | {ratio}")
    print(f"\ntarget 1 (ratio <= 1/3 wherever solve_ivp reaches the level): "
          f"{'PASS' if all(verdicts) else 'FAIL'} ({sum(verdicts)} of {len(verdicts)} cells)")
    print(f"target 2 (final error <= 1e-11 on kepler-e0.6): "
          f"{'PASS' if target2[1] else 'FAIL'} (smallest error of ours {target2[0]:.1e})")
    if args.long:
        print("\n== long-time energy, Kepler e = 0.6, 10,000 orbits")
        res = long_run(args.out)
        peak, g, _ = next(v for k, v in res.items() if k.startswith("yoshida6"))
        print(f"target 3 (energy error <= 1e-8, growth exponent <= 0.1): "
              f"{'PASS' if peak <= 1e-8 and g <= 0.1 else 'FAIL'} "
              f"(max {peak:.1e}, exponent {g:.3f})")


if __name__ == "__main__":
    main()
