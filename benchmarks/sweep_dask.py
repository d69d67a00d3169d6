"""The final state of a double pendulum over 10^4 (mass ratio, release angle) pairs: serial
(in-process) against a Dask LocalCluster of 2 local worker processes, same chunks.

Point masses m1 = 1, m2 = mu on rods of length 1 (g = 9.81), released at rest from
q1 = q2 = theta; mu in [0.1, 3], theta in [0.1, 2.5] rad, 100 x 100; the state at t = 5 s
(dop853, rtol 1e-8, atol 1e-10). Prints the times, the ratio, and whether the two backends
agree bit for bit, and the CPU times (on a machine shared with other jobs the wall times
measure the sharing; serial CPU over the busiest worker's CPU is the ratio on idle cores). The
run with 2 workers includes neither the cluster's start nor the
compilation (done once before timing, as a user's second sweep would).

    python benchmarks/sweep_dask.py [n_per_axis] [chunk_size]
"""

import sys
import time

import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech.sweeps import grid, sweep


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


def main():
    from distributed import Client, LocalCluster

    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    chunk = int(sys.argv[2]) if len(sys.argv) > 2 else 500
    eqs = two_mass_pendulum()
    mu, theta = np.linspace(0.1, 3.0, n), np.linspace(0.1, 2.5, n)
    # the release state q1 = q2 = theta: sweep points with both columns
    from rigidmech.sweeps import points
    MU, TH = np.meshgrid(mu, theta, indexing="ij")
    over = points(m2=MU.ravel(), q1=TH.ravel(), q2=TH.ravel())
    args = dict(t=(0.0, 5.0), chunk_size=chunk, rtol=1e-8, atol=1e-10, m1=1.0, l=1.0,
                g=9.81, progress=False)
    sweep(eqs, grid(m2=[1.0]), **{**args, "t": (0.0, 0.01)})        # compile once
    t0, c0 = time.perf_counter(), time.process_time()
    serial = sweep(eqs, over, **args)
    t_serial, c_serial = time.perf_counter() - t0, time.process_time() - c0
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        sweep(eqs, grid(m2=[1.0]), backend="dask", client=client,
              **{**args, "t": (0.0, 0.01)})                           # workers warmed
        cpu0 = client.run(time.process_time)
        t0 = time.perf_counter()
        dask = sweep(eqs, over, backend="dask", client=client, **args)
        t_dask = time.perf_counter() - t0
        cpu1 = client.run(time.process_time)
        busiest = max(cpu1[w] - cpu0[w] for w in cpu0)
    same = np.array_equal(np.asarray(serial.values.values), np.asarray(dask.values.values),
                          equal_nan=True)
    # CPU time of the serial run below its wall time: other jobs share the cores
    print(f"{over.size} points, chunks of {chunk}: serial {t_serial:.2f} s "
          f"(CPU {c_serial:.2f} s), "
          f"2 local workers {t_dask:.2f} s (CPU of the busiest {busiest:.2f} s), ratio "
          f"{t_serial / t_dask:.2f}x (of CPU times {c_serial / busiest:.2f}x); "
          f"failed chunks {len(serial.failed)}/{len(dask.failed)}; bit for bit: {same}")


if __name__ == "__main__":
    main()
