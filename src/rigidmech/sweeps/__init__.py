"""Sweeps over parameters and initial states, in this process or on a Dask cluster (ch. 25.4,
27).

:func:`sweep` computes the final state (or samples) of equations of motion, or the eigenvalues
of a linearised system, at every point of a :func:`grid` or a list of :func:`points`, in chunks:
in-process by default, unchanged on a Dask cluster (``backend="dask"``; ``pip install
rigidmech[distributed]``). The results are labelled by the swept values (an
``xarray.DataArray`` when xarray is installed, else :class:`Labelled`); chunks that fail are
returned beside the finished ones. :data:`WORKER_CONFIG` holds the Dask settings for the
workers that run sweeps (to hold while a cluster starts).

Examples
--------
>>> r = sweep(lambda v, rng: v["a"] * v["b"], grid(a=[1.0, 2.0], b=[3.0, 4.0]),
...           labels="numpy")
>>> r.values.values.tolist()
[[3.0, 4.0], [6.0, 8.0]]
>>> WORKER_CONFIG["distributed.worker.profile.enabled"]
False
"""

from types import MappingProxyType

from ._labelled import Labelled, Points, grid, points
from ._run import ChunkFailure, ClusterError
from .api import SweepResult, sweep

#: Dask settings for the workers of sweeps, to hold while they start: the nanny does not set
#: ``MALLOC_TRIM_THRESHOLD_`` (with it, glibc gives the top of the heap back whenever 64 KiB
#: are free and faults the pages in again at the next step's arrays: a worker's task took
#: 1.17-1.30x the serial CPU a point on the double pendulum sweep in chunks of 1000, 0.99-1.13x
#: without), and no statistical profiler samples their stacks every 10 ms.
#: ``with dask.config.set(WORKER_CONFIG): LocalCluster(...)``; a read-only mapping.
WORKER_CONFIG = MappingProxyType({
    "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None,
    "distributed.worker.profile.enabled": False,
})

__all__ = ["sweep", "grid", "points", "Points", "Labelled", "SweepResult", "ChunkFailure",
           "ClusterError", "WORKER_CONFIG"]
