"""CPU time of the one loop's cells of ``ode_overhead.py`` (our side only), for A/B runs of
two versions of the code: run this script alternately with each version on ``PYTHONPATH``
and compare the best CPU times cell by cell (the machine is shared: wall time is not used).

Run::

    PYTHONPATH=src python benchmarks/loop_cpu.py [repeats]        # default 15; ~20 s

Prints, per cell: steps, evaluations, best CPU time in ms.
"""

import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ode_overhead import PAIRS, PROBLEMS, van_der_pol  # noqa: E402

from rigidmech import ode  # noqa: E402


def best_cpu(fn, repeat):
    best = np.inf
    for _ in range(repeat):
        t0 = time.process_time()
        out = fn()
        best = min(best, time.process_time() - t0)
    return best, out


def main():
    repeat = int(sys.argv[1]) if len(sys.argv) > 1 else 15
    cells = [(label, method, fun, y0, t_end, rtol) for label, fun, y0, t_end, rtol in PROBLEMS
             for method, _ in PAIRS]
    cells.append(("Van der Pol mu=1000", "radau", van_der_pol, np.array([2.0, 0.0]), 300.0,
                  1e-6))
    for label, method, fun, y0, t_end, rtol in cells:
        def run(method=method, fun=fun, y0=y0, t_end=t_end, rtol=rtol):
            return ode.solve(fun, (0.0, t_end), y0, method=method, rtol=rtol,
                             atol=rtol * 1e-2)
        run()
        t, r = best_cpu(run, repeat)
        print(f"{label:<20} {method:<7} {r.nsteps:>6} {r.nfev:>7} {t * 1e3:9.2f} ms")


if __name__ == "__main__":
    main()
