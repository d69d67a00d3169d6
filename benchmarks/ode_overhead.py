"""Per-step cost of rigidmech.ode's explicit pairs against scipy.integrate.solve_ivp.

Anchor (TARGETS.md, "Integrating"): solve_ivp spends about 50 us per RK45 step and 100 us per
DOP853 step in its machinery. Our ``dopri5`` and ``dop853`` use the same coefficients, norm,
starting step and step-size rules, so both codes take the SAME steps (checked below): the
difference in time per step is pure machinery.

Run::

    .venv/bin/python benchmarks/ode_overhead.py          # about 30 s

Prints, per problem and method pair: steps, function evaluations, microseconds per step for
each side (best of several runs), the cost of ``fun`` alone per step, and the ratio
scipy / rigidmech (> 1: we are faster). Then the same for a batch of trajectories integrated at
once (``y0`` of shape (n, batch)) against a loop of solve_ivp calls. Absolute times drift
between runs and machines; the ratios, measured side by side in one run, are the claim.
"""

import time

import numpy as np
from scipy.integrate import solve_ivp

from rigidmech import ode

REPEAT = 5


def best_time(fn, repeat=REPEAT):
    """Smallest wall time of `repeat` calls of `fn` (seconds)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def oscillator(t, y):
    return np.array([y[1], -y[0]])


def kepler(t, y):
    r3 = (y[0] ** 2 + y[1] ** 2) ** 1.5
    return np.array([y[2], y[3], -y[0] / r3, -y[1] / r3])


def kepler_batch(t, y):  # y: (4, batch)
    r3 = (y[0] ** 2 + y[1] ** 2) ** 1.5
    return np.stack([y[2], y[3], -y[0] / r3, -y[1] / r3])


N_CHAIN = 40
_L = (np.diag(-2.0 * np.ones(N_CHAIN)) + np.diag(np.ones(N_CHAIN - 1), 1)
      + np.diag(np.ones(N_CHAIN - 1), -1))


def chain(t, y):
    """40 masses and springs in a row (n = 80 equations: the numpy kernel)."""
    q, v = y[:N_CHAIN], y[N_CHAIN:]
    return np.concatenate([v, _L @ q])


def van_der_pol(t, y, mu=1000.0):
    return np.array([y[1], mu * (1 - y[0] ** 2) * y[1] - y[0]])


E = 0.6
KEPLER_Y0 = np.array([1 - E, 0.0, 0.0, np.sqrt((1 + E) / (1 - E))])
CHAIN_Y0 = np.concatenate([np.sin(np.linspace(0, np.pi, N_CHAIN)), np.zeros(N_CHAIN)])

PROBLEMS = [
    ("oscillator n=2", oscillator, np.array([1.0, 0.0]), 100.0, 1e-8),
    ("Kepler e=0.6 n=4", kepler, KEPLER_Y0, 20 * np.pi, 1e-10),
    ("spring chain n=80", chain, CHAIN_Y0, 20.0, 1e-8),
]
PAIRS = [("dopri5", "RK45"), ("dop853", "DOP853")]


def fun_cost(fun, y0, nfev):
    y = y0.copy()
    return best_time(lambda: [fun(0.0, y) for _ in range(nfev)])


def main():
    print(f"{'problem':<20} {'method':<16} {'steps':>6} {'nfev':>6} {'ours us/step':>13} "
          f"{'scipy us/step':>14} {'fun us/step':>12} {'ratio':>6}")
    for label, fun, y0, t_end, rtol in PROBLEMS:
        for ours, theirs in PAIRS:
            kw = dict(rtol=rtol, atol=rtol * 1e-2)
            r = ode.solve(fun, (0.0, t_end), y0, method=ours, **kw)
            s = solve_ivp(fun, (0.0, t_end), y0, method=theirs, **kw)
            same = r.nsteps == len(s.t) - 1 and r.nfev == s.nfev
            t_ours = best_time(lambda: ode.solve(fun, (0.0, t_end), y0, method=ours, **kw))  # noqa: B023
            t_sci = best_time(lambda: solve_ivp(fun, (0.0, t_end), y0, method=theirs, **kw))  # noqa: B023
            t_fun = fun_cost(fun, y0, r.nfev)
            steps = r.nsteps
            print(f"{label:<20} {ours + ' / ' + theirs:<16} {steps:>6} {r.nfev:>6} "
                  f"{t_ours / steps * 1e6:>13.1f} {t_sci / steps * 1e6:>14.1f} "
                  f"{t_fun / steps * 1e6:>12.1f} {t_sci / t_ours:>6.2f}"
                  + ("" if same else "  (step counts differ!)"))

    # Radau IIA on a stiff problem: Newton iterations and linear algebra dominate
    kw = dict(rtol=1e-6, atol=1e-6)
    r = ode.solve(van_der_pol, (0.0, 3000.0), [2.0, 0.0], method="radau", **kw)
    s = solve_ivp(van_der_pol, (0.0, 3000.0), [2.0, 0.0], method="Radau", **kw)
    t_ours = best_time(lambda: ode.solve(van_der_pol, (0.0, 3000.0), [2.0, 0.0],
                                         method="radau", **kw), repeat=3)
    t_sci = best_time(lambda: solve_ivp(van_der_pol, (0.0, 3000.0), [2.0, 0.0], method="Radau",
                                        **kw), repeat=3)
    t_fun = fun_cost(van_der_pol, np.array([2.0, 0.0]), r.nfev)
    print(f"{'Van der Pol mu=1000':<20} {'radau / Radau':<16} {r.nsteps:>6} {r.nfev:>6} "
          f"{t_ours / r.nsteps * 1e6:>13.1f} {t_sci / (len(s.t) - 1) * 1e6:>14.1f} "
          f"{t_fun / r.nsteps * 1e6:>12.1f} {t_sci / t_ours:>6.2f}  (scipy: {len(s.t) - 1} "
          f"steps, {s.nfev} nfev; ratio of total times)")

    print()
    batch = 200
    ecc = np.linspace(0.1, 0.7, batch)
    Y0 = np.stack([1 - ecc, np.zeros(batch), np.zeros(batch), np.sqrt((1 + ecc) / (1 - ecc))])
    kw = dict(rtol=1e-8, atol=1e-10)
    print(f"batch of {batch} Kepler orbits (e = 0.1..0.7), 2 orbits, rtol = 1e-8:")
    for ours, theirs in PAIRS:
        r = ode.solve(kepler_batch, (0.0, 4 * np.pi), Y0, method=ours, **kw)
        t_ours = best_time(lambda: ode.solve(kepler_batch, (0.0, 4 * np.pi), Y0,  # noqa: B023
                                             method=ours, **kw), repeat=3)  # noqa: B023
        t_sci = best_time(lambda: [solve_ivp(kepler, (0.0, 4 * np.pi), Y0[:, j],  # noqa: B023
                                             method=theirs, **kw) for j in range(batch)],  # noqa: B023
                          repeat=1)
        print(f"  {ours:<7} one batched call {t_ours * 1e3:8.1f} ms ({r.nsteps} shared steps); "
              f"solve_ivp {theirs} looped {t_sci * 1e3:8.1f} ms; ratio {t_sci / t_ours:6.1f}")


if __name__ == "__main__":
    main()
