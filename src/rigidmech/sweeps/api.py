"""Sweeps: one computation over many parameter values and initial states (book, ch. 25.4, 27).

:func:`sweep` runs equations of motion (the final state, or the samples at given times) or a
linearised system (its eigenvalues) over a :func:`~rigidmech.sweeps.grid` or a list of
:func:`~rigidmech.sweeps.points`, in chunks, in this process or on a Dask cluster, and returns
the results labelled by the swept values together with the chunks that failed.
"""

from __future__ import annotations

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError
from ..dynamics import EquationsOfMotion
from ..dynamics._compiled import coordinate_name
from ..vibrations import LinearSystem
from ._labelled import Labelled, Points, grid  # noqa: F401  (grid: the doctests)
from ._run import ChunkFailure, connect, run_chunks
from ._tasks import CallableTask, EigenTask, OdeTask

__all__ = ["sweep", "SweepResult"]

BACKENDS = ("inprocess", "dask")


class SweepResult:
    """What a sweep returns: the labelled values, the failed chunks, the points.

    Attributes
    ----------
    values : xarray.DataArray or Labelled
        One entry per point (dims: the swept names for a grid, ``"point"`` for a list of
        points, then those of the quantity: ``"state"``, ``"time"``, ``"eigenvalue"``);
        nan at the points of failed chunks; None if no chunk finished.
    failed : tuple of ChunkFailure
        The chunks that raised (or were not run after a stop), in order.
    points : Points
    chunk_size : int
    seed : int
        The entropy of the ``SeedSequence`` whose children seed the chunks.

    Examples
    --------
    >>> r = sweep(lambda v, rng: v["x"] ** 2, grid(x=[1.0, 2.0, 3.0]), labels="numpy")
    >>> r.values.values.tolist(), r.complete
    ([1.0, 4.0, 9.0], True)
    """

    __slots__ = ("values", "failed", "points", "chunk_size", "seed")

    def __init__(self, values, failed, points, chunk_size, seed):
        self.values, self.failed, self.points = values, tuple(failed), points
        self.chunk_size, self.seed = chunk_size, seed

    @property
    def complete(self) -> bool:
        """True if every chunk finished."""
        return not self.failed

    def __repr__(self):
        return (f"SweepResult({self.points!r}, {len(self.failed)} failed chunks of "
                f"{-(-self.points.size // self.chunk_size)})")


def _quantity_labels(target, quantity, times, n):
    if quantity == "eigenvalues":
        return ("eigenvalue",), {"eigenvalue": np.arange(2 * n)}
    names = list(target.names) + [f"{x}_dot" for x in target.names]
    if quantity == "final":
        return ("state",), {"state": np.array(names)}
    return ("time", "state"), {"time": np.asarray(times, float), "state": np.array(names)}


def _check_names(target, over, fixed, quantity):
    if isinstance(target, LinearSystem):
        usable = [p.name for p in target.parameters]
        needed = usable
    else:
        params = [p.name for p in target.parameters]
        inputs = [coordinate_name(w) for w in target.inputs]
        needed = params + inputs
        usable = needed + list(target.names) + [f"{x}_dot" for x in target.names]
    both = sorted(set(over.names) & set(fixed))
    if both:
        raise ArgumentError(f"{both} are both swept and given a fixed value; give each once.")
    for name in list(over.names) + list(fixed):
        if name not in usable:
            raise ArgumentError(
                f"`{name}` is not used by the equations: they take the parameters {needed}"
                + ("" if isinstance(target, LinearSystem) else
                   f" and the initial states {usable[len(needed):]}")
                + f"; got `{name}`. Sweep or fix only those names.")
    missing = [x for x in needed if x not in over.names and x not in fixed]
    if missing:
        raise ArgumentError(
            f"missing values for {missing}: sweep them or give them as keywords, e.g. "
            f"{', '.join(f'{m}=1.0' for m in missing)}.")
    for name, value in fixed.items():
        if callable(value) or not np.isscalar(value) or isinstance(value, (str, bool)):
            raise ArgumentTypeError(
                f"the fixed value of `{name}` must be a real number; got {value!r}.")


def _task(target, over, fixed, quantity, t, times, options):
    if callable(quantity) and not isinstance(target, EquationsOfMotion):
        return CallableTask(quantity, fixed), None, {}
    if isinstance(target, LinearSystem):
        if quantity not in ("eigenvalues", None):
            raise ArgumentError(f"a LinearSystem sweeps quantity='eigenvalues'; got {quantity!r}.")
        _check_names(target, over, fixed, quantity)
        dims, coords = _quantity_labels(target, "eigenvalues", None, len(target.coordinates))
        return EigenTask(target, fixed), dims, coords
    if not isinstance(target, EquationsOfMotion):
        raise ArgumentTypeError(
            "`target` must be EquationsOfMotion, a LinearSystem or a callable "
            f"f(values, rng); got {type(target).__name__}.")
    if target.constraints is not None:
        raise ArgumentError("sweeps of equations with constraints are not supported; use "
                            "eqs.reduced() or simulate each point.")
    _check_names(target, over, fixed, quantity)
    try:
        t0, t1 = (float(x) for x in t)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`t` must be (t0, t1); got {t!r}.") from None
    if quantity == "final":
        t_eval = [t1]
    elif quantity == "samples" or callable(quantity):
        if times is None:
            raise ArgumentError(f"quantity={quantity!r} needs `times` (the sample times).")
        t_eval = np.asarray(times, dtype=float)
    else:
        raise ArgumentError(
            "`quantity` must be 'final', 'samples' (with `times`) or a callable "
            f"f(t, y, rng) for equations of motion; got {quantity!r}.")
    task = OdeTask(target, {k: float(v) for k, v in fixed.items()}, (t0, t1), t_eval,
                   quantity, options)
    if callable(quantity):
        return task, None, {}
    dims, coords = _quantity_labels(target, quantity, times, len(target.coordinates))
    return task, dims, coords


def _labelled(values, over, qdims, qcoords, labels):
    if qdims is None:
        qdims = tuple(f"dim_{k}" for k in range(values.ndim - 1))
    if over.is_grid:
        dims = over.names + tuple(qdims)
        values = values.reshape(over.shape + values.shape[1:])
        coords = {name: (name, over.axes[name]) for name in over.names}
    else:
        dims = ("point",) + tuple(qdims)
        coords = {name: ("point", over.columns[name]) for name in over.names}
    coords.update({k: (k, v) for k, v in qcoords.items()})
    if labels in ("auto", "xarray"):
        try:
            import xarray
        except ImportError:
            if labels == "xarray":
                raise ArgumentError("labels='xarray' needs xarray: "
                                    "`pip install rigidmech[distributed]` or `pip install xarray`."
                                    ) from None
        else:
            return xarray.DataArray(values, dims=dims, coords=coords)
    return Labelled(values, dims, coords)


def sweep(target, over, *, quantity="final", t=(0.0, 10.0), times=None, method="dop853",
          rtol=1e-8, atol=1e-10, step=None, max_steps=1_000_000, chunk_size=1000,
          backend="inprocess", client=None, address=None, timeout=10.0, progress=None,
          seed=None, labels="auto", **fixed) -> SweepResult:
    """Compute one quantity over many parameter values and initial states, in chunks.

    Parameters
    ----------
    target : EquationsOfMotion, LinearSystem or callable
        Equations of motion (integrated; their right-hand side compiled once), a linearised
        system (ch. 25.4: its eigenvalues), or a vectorised ``f(values, rng)`` of a dict of
        arrays (one per swept name) returning an array ``(chunk, ...)``.
    over : Points
        :func:`grid` or :func:`points` of names: parameters of the equations, initial
        coordinates (their :attr:`~EquationsOfMotion.names`) and initial rates (the names
        followed by ``_dot``). Initial values neither swept nor fixed are 0.
    quantity : "final", "samples", "eigenvalues" or callable
        The state at ``t[1]`` (dim ``"state"``: q then q'), the states at ``times``
        (dims ``"time"``, ``"state"``), the eigenvalues of a LinearSystem (sorted by real then
        imaginary part), or ``f(t, y, rng)`` of the samples ``y`` of shape
        ``(2n, len(times), chunk)`` returning an array ``(chunk, ...)``.
    t, times : (t0, t1) and array_like
        The time span, and the sample times (within it) for ``"samples"`` or a callable.
    method, rtol, atol, step, max_steps
        As in :func:`rigidmech.ode.solve`. A chunk is one batch: its members share the steps
        (chosen from the largest error of the batch), so a point's numbers depend on the
        chunk it is in within the tolerance, never on the backend.
    chunk_size : int
        Points per chunk (the last chunk may be smaller). The default, 1000: on the double
        pendulum's 10^4-point sweep a point costs 2.2-2.4x less CPU than in chunks of 256 (each
        batched call of the right-hand side has a fixed cost, shared by the chunk), 1.2-1.3x
        more than in chunks of 2500, and its 10 chunks balance 2 Dask workers better (1.59x
        serial against 1.47x in chunks of 2500, medians of the CPU ratio). Both backends cut
        the same chunks.
    backend : "inprocess" or "dask"
        ``"dask"`` needs ``pip install rigidmech[distributed]`` and ``client`` (a
        ``distributed.Client``) or ``address`` (a scheduler's, reached within ``timeout`` s).
    progress : None, bool or callable
        A bar (tqdm) over the chunks: ``None`` when stderr is a terminal, ``True`` always;
        a callable ``progress(done, total)`` after each chunk, returning False to stop.
    seed : int, optional
        Entropy of the ``numpy.random.SeedSequence`` whose ``spawn`` seeds each chunk's
        generator (given to a callable quantity); drawn if None, kept in the result.
    labels : "auto", "xarray" or "numpy"
        An ``xarray.DataArray`` if xarray is installed (``"auto"``), or a :class:`Labelled`.
    **fixed
        Values of the names not swept.

    Returns
    -------
    SweepResult
        ``values`` labelled by the swept values, ``failed`` the chunks that raised (their
        points nan; the others kept).

    Raises
    ------
    ArgumentError, ArgumentTypeError
        Bad input, before anything is computed: a name the equations do not use, a missing
        value, mismatched shapes (:func:`points`), an unknown backend.
    ClusterError
        The scheduler at ``address`` cannot be reached (nothing computed).

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import EquationsOfMotion
    >>> x, v, k = sp.symbols("x x_dot k")
    >>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
    ...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-k * x]]))
    >>> r = sweep(eqs, grid(k=[1.0, 4.0], x=[0.5, 1.0]), t=(0, np.pi), labels="numpy")
    >>> r.values.dims, r.values.shape
    (('k', 'x', 'state'), (2, 2, 2))
    >>> r.values.sel(k=4.0, x=1.0).values.round(6).tolist()   # cos(2 pi), -2 sin(2 pi)
    [1.0, -0.0]
    """
    if not isinstance(over, Points):
        raise ArgumentTypeError(
            f"`over` must be grid(...) or points(...) of rigidmech.sweeps; got "
            f"{type(over).__name__}. Wrap the values: grid(mu=[1, 2], theta=[0.1, 0.2]).")
    if backend not in BACKENDS:
        raise ArgumentError(f"`backend` must be one of {BACKENDS}; got {backend!r}.")
    if labels not in ("auto", "xarray", "numpy"):
        raise ArgumentError(f"`labels` must be 'auto', 'xarray' or 'numpy'; got {labels!r}.")
    if isinstance(chunk_size, bool) or not isinstance(chunk_size, (int, np.integer)) \
            or chunk_size < 1:
        raise ArgumentError(f"`chunk_size` must be a positive integer; got {chunk_size!r}.")
    options = {"method": method, "rtol": rtol, "atol": atol, "max_steps": max_steps,
               "step": step}
    if callable(target) and not isinstance(target, (EquationsOfMotion, LinearSystem)):
        task, qdims, qcoords = CallableTask(target, fixed), None, {}
    else:
        task, qdims, qcoords = _task(target, over, fixed, quantity, t, times, options)
    own = False
    if backend == "dask":      # reached (or refused) before the chunks run
        client, own = connect(client, address, timeout)
    starts = list(range(0, over.size, int(chunk_size)))
    chunks = [{k: v[s:s + chunk_size] for k, v in over.columns.items()} for s in starts]
    seq = np.random.SeedSequence(seed)
    seeds = seq.spawn(len(chunks))
    results = {}
    try:
        failures = run_chunks(task, chunks, seeds, backend, client, progress,
                              results.__setitem__)
    finally:
        if own:
            client.close()
    failed = [ChunkFailure(i, starts[i], min(starts[i] + chunk_size, over.size), exc)
              for i, exc in failures]
    if results:
        first = next(iter(results.values()))
        values = np.full((over.size,) + first.shape[1:], np.nan, dtype=first.dtype
                         if first.dtype.kind in "fc" else float)
        for i, r in results.items():
            values[starts[i]:starts[i] + len(r)] = r
        labelled = _labelled(values, over, qdims, qcoords, labels)
    else:
        labelled = None
    return SweepResult(labelled, failed, over, int(chunk_size), seq.entropy)
