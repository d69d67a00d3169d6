"""What ``simulate`` adds around the solver: the double pendulum, ``simulate`` against
``ode.solve`` on the same compiled right-hand side (the anchor: the bare solver).

``EquationsOfMotion.simulate`` runs ``ode.solve`` with the same method, tolerances and sample
times; anything it adds per evaluation of the right-hand side (a wrapper that watches every
call) shows up as the ratio simulate / solve above 1. The two are timed alternately (A, B, A,
B, ...) in CPU time (``time.process_time``) and the best of each is kept.

Run::

    python benchmarks/simulate_overhead.py            # about 20 s
    python benchmarks/simulate_overhead.py --repeats 9 --t-end 200

Prints the steps, the evaluations, the best CPU time of each side and the ratio.
"""

import argparse
import os
import sys
import time

import numpy as np

from rigidmech import ode

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from derive import n_link_pendulum  # noqa: E402  (the sibling script's system)

PARAMS = {"g": 9.81, "m1": 1.0, "l1": 1.0, "m2": 1.0, "l2": 1.0}


def cpu(fn):
    t0 = time.process_time()
    out = fn()
    return time.process_time() - t0, out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t-end", type=float, default=100.0)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--method", default="dop853")
    args = ap.parse_args(argv)
    print(f"command: python {' '.join(sys.argv)}")
    eqs = n_link_pendulum(2).equations_of_motion()
    fun = eqs.rhs(**PARAMS)
    y0 = np.array([1.0, 0.5, 0.0, 0.0])
    span, n_out = (0.0, args.t_end), 1001
    t_eval = np.linspace(*span, n_out)

    def bare():
        return ode.solve(fun, span, y0, method=args.method, rtol=1e-8, atol=1e-10,
                         t_eval=t_eval)

    def wrapped():
        return eqs.simulate(t=span, q0=y0[:2], u0=y0[2:], method=args.method, rtol=1e-8,
                            atol=1e-10, n_output=n_out, progress=False, **PARAMS)

    wrapped(), bare()  # compile
    a, b = [], []
    for _ in range(args.repeats):
        ta, r = cpu(bare)
        tb, s = cpu(wrapped)
        a.append(ta)
        b.append(tb)
    assert np.allclose(r.y[:2], s.q, rtol=0, atol=1e-12), "not the same run"
    print(f"double pendulum, {args.method}, rtol 1e-8, t = {span}, {n_out} samples: "
          f"{r.nsteps} steps, {r.nfev} evaluations")
    for name, x in (("ode.solve (bare)", min(a)), ("simulate", min(b))):
        print(f"  {name:<17}: {x * 1e3:8.1f} ms CPU  ({x / r.nfev * 1e6:.2f} us/eval)")
    print(f"  ratio simulate / solve: {min(b) / min(a):.3f}  "
          f"(+{(min(b) - min(a)) / r.nfev * 1e6:.2f} us per evaluation)")


if __name__ == "__main__":
    main()
