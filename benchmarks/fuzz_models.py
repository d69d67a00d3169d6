"""The differential model fuzzer, long run: N random mechanisms built by rigidmech and by
sympy.physics.mechanics (KanesMethod), q'' compared at random states.

Prints the models tried, the disagreements (status, worst relative difference, the model's
repr to paste into a regression test) and the time per model (rigidmech and sympy sides:
build, derive, compile, evaluate) with the slowest models. Run from the repository root::

    PYTHONPATH=src python benchmarks/fuzz_models.py 50                  # up to 3 bodies
    PYTHONPATH=src python benchmarks/fuzz_models.py 20 --bodies 6 --dof 10 --seed 1
    PYTHONPATH=src python benchmarks/fuzz_models.py 30 --ground --no-polar
    PYTHONPATH=src python benchmarks/fuzz_models.py 10 --bodies 2 --dof 4 --closure
    PYTHONPATH=src python benchmarks/fuzz_models.py 30 --seed 0 --dof 8 --knives --closure

Every joint of the generator is drawn (``polar``, a translated frame of a rotated helper
frame, unless ``--no-polar``; the rolling sphere and disc unless ``--no-rolling``);
``--knives`` adds knife edges, ``--closure [kind]`` closes loops (spherical, or a pivot or a
slider closing a planar loop). Larger 3D models are slow on sympy's side (Kane's method on
many coordinates takes minutes): use ``--dof`` to bound them.
"""

from __future__ import annotations

import argparse
import collections
import time

import numpy as np

from rigidmech.testing.fuzz import compare, random_model
from rigidmech.testing.fuzz.generate import JOINT_ORDER


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("n", type=int, help="number of models")
    parser.add_argument("--bodies", type=int, default=3, help="at most this many bodies")
    parser.add_argument("--dof", type=int, default=None, help="at most this many coordinates")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--states", type=int, default=4, help="states compared per model")
    parser.add_argument("--ground", action="store_true", help="turn and move the ground frame")
    parser.add_argument("--no-polar", action="store_true", help="leave out the polar joint")
    parser.add_argument("--closure", nargs="?", const="any", default=None,
                        choices=("any", "spherical", "pivot", "slider"),
                        help="close a loop where the tree allows it (default kind: any of a "
                             "spherical joint, or a pivot or a slider closing a planar loop)")
    parser.add_argument("--knives", action="store_true",
                        help="give bodies on a planar joint a knife edge (one in two)")
    parser.add_argument("--no-rolling", action="store_true",
                        help="leave out the rolling sphere and disc")
    parser.add_argument("--slowest", type=int, default=5)
    args = parser.parse_args(argv)
    joints = tuple(j for j in JOINT_ORDER if not (args.no_polar and j == "polar")
                   and not (args.no_rolling and j in ("ball", "disc")))
    rng = np.random.default_rng(args.seed)
    counts = collections.Counter()
    times = []
    start = time.perf_counter()
    for k in range(args.n):
        model = random_model(rng, max_bodies=args.bodies, max_dof=args.dof, joints=joints,
                             ground=args.ground, closure=args.closure or False,
                             knives=args.knives)
        t0 = time.perf_counter()
        report = compare(model, seed=k, states=args.states)
        elapsed = time.perf_counter() - t0
        counts[report.status] += 1
        times.append((elapsed, k, report))
        print(f"[{k:4d}] {report.status:15s} {elapsed:7.2f} s  worst {report.worst:8.1e}  "
              f"{model.summary()}", flush=True)
        if not report.ok:
            print(f"       {report.detail[:600]}\n       model = {model!r}", flush=True)
    total = time.perf_counter() - start
    bad = sum(v for s, v in counts.items() if s not in ("agree", "degenerate"))
    print(f"\nmodels tried: {args.n}; disagreements: {bad}; "
          + ", ".join(f"{s}: {v}" for s, v in sorted(counts.items())))
    print(f"total {total:.1f} s, {total / max(args.n, 1):.2f} s per model "
          f"(median {np.median([t for t, _, _ in times]):.2f} s)")
    print(f"slowest {args.slowest} models (rigidmech s, sympy s):")
    for elapsed, k, report in sorted(times, key=lambda x: -x[0])[:args.slowest]:
        print(f"  [{k:4d}] {elapsed:7.2f} s ({report.seconds[0]:.2f}, {report.seconds[1]:.2f})"
              f"  {len(report.model.bodies)} bodies, {report.model.degrees_of_freedom} dof: "
              f"{report.model.summary()}")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
