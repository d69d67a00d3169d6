"""Ensembles: 1,000 double-pendulum initial states in one batched call against a loop of
``scipy.integrate.solve_ivp`` (DOP853) on the same compiled right-hand side.

The system: rigidmech's catalogue double pendulum of rods (``models.double_pendulum``, m = 1,
L = 1, g = 9.81), its compiled ``f(t, y)`` (``EquationsOfMotion.rhs``), which takes one state
``(4,)`` or a batch ``(4, batch)``. Two ensembles of ``--size`` states (default 1,000), both
angles uniform in +-0.5 rad (regular) and +-2.5 rad (chaotic), released at rest, integrated
over ``--t-end`` s (default 10) with dop853 at ``--rtol`` (default 1e-8, atol = rtol / 100),
the final state kept (``t_eval = [t_end]``):

* ours, per-trajectory steps (``stepping="each"``: the default of a batch with t_eval);
* ours, one step for the whole batch (``stepping="shared"``);
* with ``--group k``, ours with static groups of k trajectories each sharing a step (a
  batched call per group; what re-forming groups as trajectories diverge could at best
  approach);
* the anchor: ``solve_ivp(fun, ..., method="DOP853")`` looped over the states, the same
  tolerances and the same compiled ``fun`` (``--anchor-every k`` times every k-th state only
  and scales by k, for quick looks; the default times all of them).

The sides are timed alternately in one process (ours, anchor, ours, ...; the best of
``--repeats`` rounds for each), in CPU time of the process (on a machine shared with other
jobs the wall time measures the sharing). Final error: each side's final states against a
tight reference (ours, per trajectory, rtol 1e-13), the median and the largest over the
ensemble; on the chaotic one the largest errors are those of trajectories that amplify any
error (both sides alike), so the median is the fair figure. Prints ratios anchor / ours
(> 1: we are faster) and the load.

    python benchmarks/ensemble.py                       # ~5-10 min on a loaded 2-core machine
    python benchmarks/ensemble.py --size 200 --anchor-every 4 --repeats 1   # quick look
    python benchmarks/ensemble.py --floor --repeats 5   # ours: machinery vs right-hand side
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from scipy.integrate import solve_ivp

from rigidmech import models, ode

PARAMS = {"g": 9.81, "m": 1.0, "L": 1.0}


def compiled_rhs():
    eqs = models.double_pendulum().system.equations_of_motion()
    return eqs.rhs(**PARAMS)


def initial_states(amplitude, size, seed=2026):
    rng = np.random.default_rng(seed)
    return np.concatenate([rng.uniform(-amplitude, amplitude, (2, size)), np.zeros((2, size))])


def ours(fun, y0, t_end, rtol, stepping, group=None):
    kw = dict(method="dop853", t_eval=[t_end], rtol=rtol, atol=rtol / 100, stepping=stepping)
    if group is None:
        r = ode.solve(fun, (0.0, t_end), y0, **kw)
        assert r.status == 0, r.message
        return r.y[:, -1, :], r
    out = np.empty_like(y0)
    for k in range(0, y0.shape[1], group):
        r = ode.solve(fun, (0.0, t_end), y0[:, k:k + group], **kw)
        assert r.status == 0, r.message
        out[:, k:k + group] = r.y[:, -1, :]
    return out, None


def anchor(fun, y0, t_end, rtol, every):
    cols = range(0, y0.shape[1], every)
    out = np.full(y0.shape, np.nan)
    nfev = 0
    for j in cols:
        s = solve_ivp(fun, (0.0, t_end), y0[:, j], method="DOP853", rtol=rtol, atol=rtol / 100,
                      t_eval=[t_end])
        assert s.status == 0, s.message
        out[:, j] = s.y[:, -1]
        nfev += s.nfev
    return out, nfev


def timed(fn):
    """CPU time of this process (``time.process_time``): on a machine shared with other jobs
    the wall time measures the sharing; both sides run in this one process."""
    t0 = time.process_time()
    out = fn()
    return time.process_time() - t0, out


def errors(final, ref):
    err = np.max(np.abs(final - ref), axis=0)
    err = err[np.isfinite(err)]
    return float(np.median(err)), float(err.max())


def run(label, amplitude, fun, args):
    y0 = initial_states(amplitude, args.size)
    t_end, rtol, every = args.t_end, args.rtol, args.anchor_every
    ref, _ = ours(fun, y0, t_end, 1e-13, "each")
    best = {"each": np.inf, "shared": np.inf, "groups": np.inf, "anchor": np.inf}
    outs = {}
    sides = ("each", "anchor", "shared") + (("groups",) if args.group else ())
    for _ in range(args.repeats):
        for side in sides:
            if side == "anchor":
                dt, (outs[side], nfev) = timed(
                    lambda: anchor(fun, y0, t_end, rtol, every))  # noqa: B023
                dt *= every
            else:
                group = args.group if side == "groups" else None
                stepping = "shared" if side != "each" else "each"
                dt, (outs[side], res) = timed(
                    lambda: ours(fun, y0, t_end, rtol, stepping, group))  # noqa: B023
                if side == "each":
                    r_each = res
                elif side == "shared":
                    r_shared = res
            best[side] = min(best[side], dt)
    steps = r_each.stats["nsteps_each"]
    print(f"\n{label}: {args.size} states, angles in +-{amplitude} rad, t = 0..{t_end} s, "
          f"dop853 rtol {rtol:g} atol {rtol / 100:g}")
    print(f"  steps per trajectory (each): min {steps.min()} median {int(np.median(steps))} "
          f"max {steps.max()}; shared steps {r_shared.nsteps}; column evaluations each "
          f"{r_each.stats['nfev_columns']:,} vs shared {r_shared.nfev * args.size:,} vs "
          f"anchor ~{nfev * every:,}")
    print(f"  {'side':<34} {'CPU [s]':>9} {'anchor/ours':>12} {'median err':>11} "
          f"{'max err':>9}")
    mask = np.zeros(args.size, bool)
    mask[::every] = True
    for side, name in (("each", "ours, a step per trajectory"),
                       ("shared", "ours, one step for all"),
                       ("groups", f"ours, static groups of {args.group}"),
                       ("anchor", "solve_ivp DOP853 loop" + (f" (x{every})" if every > 1 else
                                                             ""))):
        if side not in outs:
            continue
        med, mx = errors(outs[side][:, mask], ref[:, mask])
        ratio = best["anchor"] / best[side]
        print(f"  {name:<34} {best[side]:>9.2f} {ratio:>12.1f} {med:>11.1e} {mx:>9.1e}")
    return best["anchor"] / best["each"], best["anchor"] / best["shared"]


def floor(amplitude, fun, args):
    """Where ours' time goes (``--floor``): the run split into the solver's machinery and the
    right-hand side, each timed alone on the same work, CPU time, best of ``--repeats``.

    * machinery alone: the same run with ``fun`` replaced by a replay of the outputs recorded
      in a first run (the same numbers, hence the same steps; a replayed call costs a copy,
      subtracted);
    * right-hand side alone: ``fun`` called on the recorded inputs, in order;
    * of which the transcendental functions: numpy's sin and cos of the angles the double
      pendulum's right-hand side needs (sin q1, sin q2, sin and cos of q1 - q2) on the same
      inputs, what no rewriting of the arithmetic around them removes.
    """
    y0 = initial_states(amplitude, args.size)
    t_end, rtol = args.t_end, args.rtol
    calls = []

    def record(t, y):
        out = fun(t, y)
        calls.append((np.array(t, copy=True), y.copy(), out.copy()))
        return out

    final, r = ours(record, y0, t_end, rtol, "each")

    def replayed():
        outputs = iter(calls)
        return ours(lambda t, y: next(outputs)[2].copy(), y0, t_end, rtol, "each")

    assert np.array_equal(replayed()[0], final)  # the same steps

    def copies():
        for _, _, out in calls:
            out.copy()

    def rhs_alone():
        for t, y, _ in calls:
            fun(t, y)

    def trig_alone():
        for _, y, _ in calls:
            d = y[0] - y[1]
            np.sin(y[0]), np.sin(y[1]), np.sin(d), np.cos(d)

    def best(fn):
        return min(timed(fn)[0] for _ in range(args.repeats))

    whole = best(lambda: ours(fun, y0, t_end, rtol, "each"))
    machinery = best(replayed) - best(copies)
    rhs, trig = best(rhs_alone), best(trig_alone)
    columns, passes = r.stats["nfev_columns"], r.nfev // 12  # dop853: 12 calls a pass
    print(f"\nfloor, +-{amplitude} rad: {len(calls):,} calls of fun, {columns:,} column "
          f"evaluations (mean width {columns / len(calls):.0f}), {passes} passes")
    print(f"  {'part':<34} {'CPU [s]':>9} {'us/column':>10} {'us/call':>9}")
    for name, sec in (("whole run (each)", whole), ("machinery alone (fun replayed)", machinery),
                      ("right-hand side alone", rhs), ("  of which sin/cos (numpy)", trig)):
        print(f"  {name:<34} {sec:>9.3f} {sec / columns * 1e6:>10.3f} "
              f"{sec / len(calls) * 1e6:>9.1f}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--size", type=int, default=1000)
    ap.add_argument("--t-end", type=float, default=10.0)
    ap.add_argument("--rtol", type=float, default=1e-8)
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--group", type=int, default=0,
                    help="also time static groups of this many trajectories (0: no)")
    ap.add_argument("--anchor-every", type=int, default=1)
    ap.add_argument("--only", choices=("regular", "chaotic"), default=None)
    ap.add_argument("--floor", action="store_true",
                    help="instead of the comparison: ours split into the solver's machinery "
                         "and the right-hand side, each timed alone")
    args = ap.parse_args(argv)
    print(f"load (uptime): {os.getloadavg()}")
    fun = compiled_rhs()
    fun(0.0, initial_states(0.5, 4))  # compiled before timing
    targets = {"regular": (0.5, 60.0), "chaotic": (2.5, 30.0)}
    if args.floor:
        for label, (amp, _) in targets.items():
            if args.only in (None, label):
                floor(amp, fun, args)
        print(f"\nload (uptime): {os.getloadavg()}")
        return
    results = {}
    for label, (amp, _) in targets.items():
        if args.only in (None, label):
            results[label] = run(label, amp, fun, args)
    print(f"\nload (uptime): {os.getloadavg()}")
    for label, (each, shared) in results.items():
        goal = targets[label][1]
        print(f"target {label}: >= {goal:.0f}x the solve_ivp loop: {each:.1f}x with a step per "
              f"trajectory ({'met' if each >= goal else 'NOT met'}); one step for all "
              f"{shared:.1f}x")


if __name__ == "__main__":
    main()
