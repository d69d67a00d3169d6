"""A/B of two checkouts of rigidmech: the compiled right-hand side and ``simulate`` of the
double pendulum, each tree in fresh processes, run alternately (A, B, A, B, ...).

Use it when a change touches the run path in many modules at once (where an in-process A/B of
one module, ``ab_inprocess.py``, does not apply): check out the old commit beside the
repository (``git worktree add ../old COMMIT``) and run from the repository root::

    python benchmarks/ab_trees.py ../old . --pairs 7

Each process prints the best CPU time (``time.process_time``) of one right-hand-side call (best
of 7 rounds of 20,000 calls) and of ``simulate`` (dop853, rtol 1e-10, 100 s, best of 5); the
script prints every pair, then the medians of each tree and their ratios B / A.
"""

import argparse
import os
import statistics
import subprocess
import sys

CHILD = r'''
import sys, time
import numpy as np
import rigidmech as rm
q1, q2 = rm.coordinates("q1 q2")
m1, l1, m2, l2, g = rm.constants("m1 l1 m2 l2 g", positive=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=q1)
R2 = R1.rotated("R2", about=R0.k, angle=q2, origin=R0.origin.moved("P1", l1 * R1.i))
P1 = R2.origin
def rod(name, frame, origin, m, l):
    G = origin.moved("G" + name, l / 2 * frame.i)
    return rm.Body(name, frame=frame, mass=m, centre=G,
                   inertia=rm.inertia.rod(m, l, axis=frame.i, centre=G))
s = rm.System(galilean=R0)
s.connect(R0, rod("b1", R1, R0.origin, m1, l1), rm.joints.Pivot(at=R0.origin, axis=R0.k))
s.connect(s.bodies[0], rod("b2", R2, P1, m2, l2), rm.joints.Pivot(at=P1, axis=R0.k))
s.act(rm.gravity(-g * R0.j))
eqs = s.equations_of_motion()
P = {"g": 9.81, "m1": 1.0, "l1": 1.0, "m2": 1.0, "l2": 1.0}
f = eqs.rhs(**P)
y = np.array([0.3, -0.2, 0.1, 0.4])
for _ in range(2000):
    f(0.0, y)
rhs = 1e9
for _ in range(7):
    t0 = time.process_time()
    for _ in range(20000):
        f(0.0, y)
    rhs = min(rhs, (time.process_time() - t0) / 20000)
sim = 1e9
for _ in range(5):
    t0 = time.process_time()
    eqs.simulate(t=(0, 100), q0=[2.0, -0.2], method="dop853", rtol=1e-10, **P)
    sim = min(sim, time.process_time() - t0)
print(rhs, sim)
'''


def run(tree):
    env = dict(os.environ, PYTHONPATH=os.path.join(os.path.abspath(tree), "src"))
    out = subprocess.run([sys.executable, "-c", CHILD], env=env, check=True,
                         capture_output=True, text=True).stdout.split()
    return float(out[0]), float(out[1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("a", help="the old tree (A)")
    ap.add_argument("b", help="the new tree (B)")
    ap.add_argument("--pairs", type=int, default=7)
    args = ap.parse_args()
    res = {"a": [], "b": []}
    print(f"{'pair':>4}  {'A rhs us':>9} {'B rhs us':>9}  "
          f"{'A simulate s':>12} {'B simulate s':>12}")
    for i in range(args.pairs):
        a, b = run(args.a), run(args.b)
        res["a"].append(a)
        res["b"].append(b)
        print(f"{i + 1:>4}  {a[0] * 1e6:9.3f} {b[0] * 1e6:9.3f}  {a[1]:12.4f} {b[1]:12.4f}")
    for k, name in ((0, "rhs call"), (1, "simulate")):
        ma = statistics.median(x[k] for x in res["a"])
        mb = statistics.median(x[k] for x in res["b"])
        print(f"median {name}: A {ma:.6g}  B {mb:.6g}  B / A = {mb / ma:.3f}")


if __name__ == "__main__":
    main()
