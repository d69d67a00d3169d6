"""The final state of a double pendulum over 10^4 (mass ratio, release angle) pairs: serial
(in-process) against a Dask LocalCluster of 2 local worker processes, same chunks.

Point masses m1 = 1, m2 = mu on rods of length 1 (g = 9.81), released at rest from
q1 = q2 = theta; mu in [0.1, 3], theta in [0.1, 2.5] rad, 100 x 100; the state at t = 5 s
(dop853, rtol 1e-8, atol 1e-10). Prints the times, the ratio, and whether the two backends
agree bit for bit, and the CPU times: of the serial run, and of the worker processes (summed,
and the busiest). On a machine shared with other jobs the wall times measure the sharing; the
CPU per point of the workers over the serial one ("parity", 1.00 = a worker computes a point
at the cost of the serial path) and serial CPU over the busiest worker's CPU (the ratio on two
idle cores) are the figures that carry over. The run with 2 workers includes neither the
cluster's start nor the compilation (done once before timing, as a user's second sweep would);
the fixed cost of a Dask sweep (a 1-point sweep, scheduling and round trips) is printed too,
with the break-even size it implies on 2 idle cores at the measured cost a point and parity.

The workers are started under ``rigidmech.sweeps.WORKER_CONFIG`` (the nanny leaves glibc's
malloc thresholds alone, the workers' statistical profiler off); ``--dask-defaults`` starts
them with dask's defaults instead, for comparison.

    python benchmarks/sweep_dask.py [n_per_axis] [chunk_size] [--dask-defaults]
"""

import os
import resource
import sys
import time

import dask
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech.sweeps import WORKER_CONFIG, grid, points, sweep


def two_mass_pendulum():
    q1, q2 = rm.coordinates("q1 q2")
    t = sp.Symbol("t")
    m1, m2, l, g = sp.symbols("m1 m2 l g", positive=True)
    c, s = sp.cos(q1 - q2), sp.sin(q1 - q2)
    M = sp.ImmutableMatrix([[(m1 + m2) * l**2, m2 * l**2 * c], [m2 * l**2 * c, m2 * l**2]])
    f = sp.ImmutableMatrix([
        -m2 * l**2 * s * q2.diff(t)**2 - (m1 + m2) * g * l * sp.sin(q1),
        m2 * l**2 * s * q1.diff(t)**2 - m2 * g * l * sp.sin(q2)])
    return rm.EquationsOfMotion(coordinates=(q1, q2), mass_matrix=M, forcing=f)


def cpu_and_faults():
    """(user + system CPU seconds, minor page faults) of this process."""
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime, r.ru_minflt


def main():
    from distributed import Client, LocalCluster

    flags = [a for a in sys.argv[1:] if a.startswith("--")]
    numbers = [a for a in sys.argv[1:] if not a.startswith("--")]
    n = int(numbers[0]) if len(numbers) > 0 else 100
    chunk = int(numbers[1]) if len(numbers) > 1 else 1000
    defaults = "--dask-defaults" in flags
    eqs = two_mass_pendulum()
    mu, theta = np.linspace(0.1, 3.0, n), np.linspace(0.1, 2.5, n)
    # the release state q1 = q2 = theta: sweep points with both columns
    MU, TH = np.meshgrid(mu, theta, indexing="ij")
    over = points(m2=MU.ravel(), q1=TH.ravel(), q2=TH.ravel())
    args = dict(t=(0.0, 5.0), chunk_size=chunk, rtol=1e-8, atol=1e-10, m1=1.0, l=1.0,
                g=9.81, progress=False)
    tiny = {**args, "t": (0.0, 0.01)}
    load0 = os.getloadavg()
    sweep(eqs, grid(m2=[1.0]), **tiny)                                 # compile once
    t0, (c0, f0) = time.perf_counter(), cpu_and_faults()
    serial = sweep(eqs, over, **args)
    t_serial = time.perf_counter() - t0
    c1, f1 = cpu_and_faults()
    c_serial, f_serial = c1 - c0, f1 - f0
    with dask.config.set({} if defaults else WORKER_CONFIG), \
            LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                         dashboard_address=":0") as cluster, Client(cluster) as client:
        sweep(eqs, grid(m2=[1.0]), backend="dask", client=client, **tiny)  # workers warmed
        t0 = time.perf_counter()
        sweep(eqs, grid(m2=[1.0]), backend="dask", client=client, **tiny)
        t_fixed = time.perf_counter() - t0
        t0 = time.perf_counter()
        sweep(eqs, grid(m2=[1.0]), **tiny)
        t_fixed -= time.perf_counter() - t0
        before = client.run(cpu_and_faults)
        t0 = time.perf_counter()
        dask_run = sweep(eqs, over, backend="dask", client=client, **args)
        t_dask = time.perf_counter() - t0
        after = client.run(cpu_and_faults)
    cpu = {w: after[w][0] - before[w][0] for w in before}
    faults = sum(after[w][1] - before[w][1] for w in before)
    summed, busiest = sum(cpu.values()), max(cpu.values())
    same = np.array_equal(np.asarray(serial.values.values), np.asarray(dask_run.values.values),
                          equal_nan=True)
    per_point, parity = c_serial / over.size, summed / c_serial
    # on idle cores: serial N c against N c p / 2 + fixed (p the parity), equal at
    # N = 2 fixed / (c (2 - p))
    even = 2 * max(t_fixed, 0.0) / (per_point * (2 - parity)) if parity < 2 else float("inf")
    print(f"{over.size} points, chunks of {chunk}, workers with "
          f"{'dask defaults' if defaults else 'the sweep settings'}; load average "
          f"{load0[0]:.1f} at the start, {os.getloadavg()[0]:.1f} at the end")
    print(f"  serial:    wall {t_serial:.2f} s, CPU {c_serial:.2f} s "
          f"({1e3 * per_point:.3f} ms a point), {f_serial} page faults")
    print(f"  2 workers: wall {t_dask:.2f} s, CPU {summed:.2f} s summed "
          f"({1e3 * summed / over.size:.3f} ms a point), busiest {busiest:.2f} s, "
          f"{faults} page faults")
    print(f"  wall ratio {t_serial / t_dask:.2f}x; CPU a point, workers / serial "
          f"{summed / c_serial:.2f} (parity 1.00); serial CPU / busiest worker's CPU "
          f"{c_serial / busiest:.2f}x (the ratio on 2 idle cores)")
    print(f"  fixed cost of a Dask sweep {1e3 * t_fixed:.0f} ms: break-even on 2 idle cores "
          f"at about {even:.0f} points of this cost and parity (in 2 chunks or more)")
    print(f"  failed chunks {len(serial.failed)}/{len(dask_run.failed)}; bit for bit: {same}")


if __name__ == "__main__":
    main()
