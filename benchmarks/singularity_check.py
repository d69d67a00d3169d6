"""Cost of the orientation-singularity check of a simulation (issue 9).

A simulation looks for its closest approach to the singular set of each orientation
parametrisation (``EquationsOfMotion.singular_sets``, ``SingularityWarning``). This measures,
side by side in one process:

* the whole ``scenes.run("double-pendulum", t_end=10)`` (what ``python -m rigidmech run
  double-pendulum --t-end 10`` does) and the work the check adds to it: finding the singular
  sets of the bodies' frames (none for a planar chain), the Euler-parameter groups, and the
  check on the recorded samples;
* for a heavy top in Euler angles z-x-z: deriving its singular set (once per equations) and
  checking a 10 s motion (once per simulation), against the integration itself.

Run::

    python benchmarks/singularity_check.py
"""

import statistics
import time
import timeit

from rigidmech import models, scenes
from rigidmech.dynamics._euler_parameters import euler_parameter_groups
from rigidmech.dynamics._singularities import orientation_singularities, warn_near_singularities

TOP = dict(m=1.0, g=9.81, l=0.3, A=0.05, C=0.02)


def heavy_top():
    """Symmetric heavy top: fixed point O, mass centre at l on its axis R.k, gravity -g k0,
    moments A (about axes through G normal to the axis) and C (about the axis): the
    catalogue's :func:`rigidmech.models.heavy_top`."""
    return models.heavy_top().system


def double_pendulum(repeats=15):
    scene = scenes.get("double-pendulum")
    runs, added = [], []
    for _ in range(repeats):
        start = time.perf_counter()
        report = scenes.run(scene, t_end=10.0)
        runs.append(time.perf_counter() - start)
        system = scene.build().system
        eqs = system.equations_of_motion()
        start = time.perf_counter()
        sets = orientation_singularities(tuple(system.bodies), system.galilean)
        euler_parameter_groups(system.bodies, system.coordinates)
        warn_near_singularities(sets, eqs.coordinates, report.simulation.result,
                                dict(scene.defaults))
        added.append(time.perf_counter() - start)
    run, extra = statistics.median(runs), statistics.median(added)
    print(f"double-pendulum, t_end = 10: run {1e3 * run:.1f} ms, added by the check "
          f"{1e3 * extra:.2f} ms ({100 * extra / run:.2f} %), medians of {repeats}")


def top(repeats=20):
    eqs = heavy_top().equations_of_motion()
    start = time.perf_counter()
    sets = eqs.singular_sets
    derive = time.perf_counter() - start
    sim = eqs.simulate(t=(0, 10), q0=[0.0, 0.5, 0.0], u0=[0.0, 0.0, 200.0], rtol=1e-10,
                       atol=1e-12, **TOP)
    check = timeit.timeit(
        lambda: warn_near_singularities(sets, eqs.coordinates, sim.result, TOP),
        number=repeats) / repeats
    print(f"heavy top (z-x-z), t_end = 10: singular set derived in {1e3 * derive:.1f} ms "
          f"(once per equations), check {1e3 * check:.3f} ms per simulation, integration "
          f"{1e3 * sim.elapsed:.1f} ms ({sim.result.nfev} evaluations)")


if __name__ == "__main__":
    double_pendulum()
    top()
