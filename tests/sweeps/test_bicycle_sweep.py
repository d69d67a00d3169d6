"""The benchmark bicycle's eigenvalues swept over speed and trail (issue: sweeps over a
linearised system's two parameters): the sweep equals single calls bit for bit, in process and
on Dask, and on the row of the paper's trail (c = 0.08 m, Meijaard et al. 2007) the
self-stable speeds are exactly those between the paper's weave and capsize speeds, 4.292382
and 6.024262 m/s (book, ch. 25.4)."""

import numpy as np
import pytest
import sympy as sp

from rigidmech import models
from rigidmech.sweeps import WORKER_CONFIG, grid, sweep
from rigidmech.vibrations import growth, linearize

pytestmark = pytest.mark.slow

SPEEDS = np.linspace(0.0, 10.0, 51)
TRAILS = np.array([0.0, 0.04, 0.08, 0.12])


@pytest.fixture(scope="module")
def lin():
    c = sp.Symbol("c", positive=True)
    eqs = models.whipple_bicycle(c=c).system.equations_of_motion()
    v = sp.Symbol("v")
    return linearize(eqs, velocities={"theta_R": v / models.BENCHMARK_BICYCLE["rR"]},
                     parameters={"g": 9.81}, independent=["phi", "delta", "theta_R"],
                     simplify=False)


def test_bicycle_sweep_over_speed_and_trail_equals_single_calls(lin):
    r = sweep(lin, grid(v=SPEEDS, c=TRAILS), quantity="eigenvalues", labels="numpy",
              chunk_size=37)
    assert r.complete and r.values.dims == ("v", "c", "eigenvalue")
    values = r.values.values
    for i in range(0, SPEEDS.size, 5):
        for j in range(TRAILS.size):
            single = np.sort_complex(lin.eigenvalues(v=SPEEDS[i], c=TRAILS[j]))
            np.testing.assert_array_equal(values[i, j], single)
    # the paper's trail: stable exactly strictly between weave and capsize
    stable = np.array([growth(s) < 0 for s in values[:, 2]])
    inside = (SPEEDS > 4.292382) & (SPEEDS < 6.024262)
    np.testing.assert_array_equal(stable, inside)


def test_bicycle_sweep_on_dask_equals_in_process_bit_for_bit(lin):
    distributed = pytest.importorskip("distributed")
    import dask
    over = grid(v=SPEEDS[::5], c=TRAILS)
    local = sweep(lin, over, quantity="eigenvalues", labels="numpy", chunk_size=7)
    with dask.config.set(WORKER_CONFIG), \
            distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                     dashboard_address=":0") as cluster, \
            distributed.Client(cluster, set_as_default=False) as client:
        remote = sweep(lin, over, quantity="eigenvalues", labels="numpy", chunk_size=7,
                       backend="dask", client=client)
    np.testing.assert_array_equal(remote.values.values, local.values.values)
