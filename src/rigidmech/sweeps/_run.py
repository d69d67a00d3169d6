"""Run the chunks of a sweep in this process or on a Dask cluster, keep what finishes.

Both backends call the same task on the same chunks with the same per-chunk random generator
(``numpy.random.SeedSequence(seed).spawn``), so they return the same numbers bit for bit. A
chunk that raises is recorded (:class:`ChunkFailure`) and the others go on; Ctrl-C or a
``progress`` callback returning False stops the sweep with the chunks finished so far.

Examples
--------
>>> import numpy as np
>>> done = {}
>>> failed = run_chunks(lambda cols, rng: cols["x"] ** 2, [{"x": np.array([1.0, 2.0])}],
...                     np.random.SeedSequence(0).spawn(1), "inprocess", None, False,
...                     lambda i, r: done.setdefault(i, r))
>>> failed, done[0].tolist()
([], [1.0, 4.0])
"""

from __future__ import annotations

import sys

import numpy as np

from .._core.errors import ArgumentError, RigidmechError

__all__ = ["ChunkFailure", "ClusterError", "run_chunks"]


class ClusterError(RigidmechError, ConnectionError):
    """The Dask scheduler of a sweep cannot be reached (nothing was computed).

    Examples
    --------
    >>> issubclass(ClusterError, ConnectionError)
    True
    """


class ChunkFailure:
    """A chunk that did not finish: its index, its points ``start:stop`` (in the order of
    the flattened points) and the error (``None`` for a chunk not run, after a stop).

    Examples
    --------
    >>> ChunkFailure(2, 20, 30, ValueError("bad"))
    ChunkFailure(chunk 2, points 20:30, ValueError: bad)
    """

    __slots__ = ("index", "start", "stop", "error")

    def __init__(self, index, start, stop, error):
        self.index, self.start, self.stop, self.error = int(index), int(start), int(stop), error

    @property
    def message(self) -> str:
        """The error as text (``"not run"`` for a chunk skipped after a stop)."""
        return "not run" if self.error is None else f"{type(self.error).__name__}: {self.error}"

    def __repr__(self):
        return f"ChunkFailure(chunk {self.index}, points {self.start}:{self.stop}, {self.message})"


def run_chunk(task, columns, seed):
    """One chunk: the task on its columns with its own generator (what a worker runs)."""
    return task(columns, np.random.default_rng(seed))


def _bar(progress, total):
    show = progress is True or (progress is None and sys.stderr.isatty())
    if not show:
        return None
    from tqdm.auto import tqdm
    return tqdm(total=total, desc="sweep", unit="chunk", file=sys.stderr)


def run_chunks(task, chunks, seeds, backend, client, progress, done):
    """Run ``task`` on each chunk (on the Dask ``client`` for ``backend="dask"``, see
    :func:`connect`); ``done(i, result)`` for each finished one; return the failures (errors
    and, after a stop, the chunks not run as ``(i, None)``)."""
    if progress is not None and not isinstance(progress, bool) and not callable(progress):
        raise ArgumentError(f"`progress` must be None, True, False or a callable "
                            f"progress(done, total); got {progress!r}.")
    bar = _bar(progress, len(chunks))
    state = {"done": 0, "stop": False}

    def finished():
        state["done"] += 1
        if bar is not None:
            bar.update(1)
        if callable(progress) and not isinstance(progress, bool):
            if progress(state["done"], len(chunks)) is False:
                state["stop"] = True

    try:
        if backend == "inprocess":
            return _inprocess(task, chunks, seeds, done, finished, state)
        return _dask(task, chunks, seeds, client, done, finished, state)
    finally:
        if bar is not None:
            bar.close()


def _inprocess(task, chunks, seeds, done, finished, state):
    failures = []
    for i, (columns, seed) in enumerate(zip(chunks, seeds, strict=True)):
        if state["stop"]:
            failures.append((i, None))
            continue
        try:
            done(i, run_chunk(task, columns, seed))
        except KeyboardInterrupt:
            state["stop"] = True
            failures.append((i, None))
            continue
        except Exception as exc:  # kept, the other chunks go on
            failures.append((i, exc))
        finished()
    return failures


def connect(client, address, timeout):
    """``(client, own)``: the Dask client given, or one connected to ``address`` (``own``
    True: the caller closes it)."""
    try:
        import distributed
    except ImportError:
        raise ArgumentError(
            "backend='dask' needs dask.distributed; install it with "
            "`pip install rigidmech[distributed]`.") from None
    if client is not None:
        if address is not None:
            raise ArgumentError("give one of `client` and `address`, not both.")
        return client, False
    if address is None:
        raise ArgumentError(
            "backend='dask' needs `client` (a distributed.Client) or `address` (the "
            "scheduler's, e.g. 'tcp://10.0.0.1:8786').")
    try:
        return distributed.Client(address, timeout=timeout, set_as_default=False), True
    except (OSError, TimeoutError) as exc:
        raise ClusterError(
            f"cannot reach the Dask scheduler at `address`={address!r} within {timeout} s "
            f"({type(exc).__name__}: {exc}); nothing was computed. Check that the scheduler "
            "runs and the address, or pass `client=`, or use backend='inprocess'.") from exc


def _dask(task, chunks, seeds, client, done, finished, state):
    import distributed

    failures = []
    futures = {}
    shipped = client.scatter(task, broadcast=True, hash=False)
    for i, (columns, seed) in enumerate(zip(chunks, seeds, strict=True)):
        futures[client.submit(run_chunk, shipped, columns, seed, pure=False)] = i
    pending = set(futures.values())
    try:
        for fut in distributed.as_completed(list(futures), loop=client.loop):
            i = futures[fut]
            pending.discard(i)
            try:
                done(i, fut.result())
            except Exception as exc:  # kept, the other chunks go on
                failures.append((i, exc))
            finished()
            if state["stop"]:
                break
    except KeyboardInterrupt:
        pass
    for fut, i in futures.items():
        if i in pending:
            fut.cancel()
            failures.append((i, None))
    return sorted(failures, key=lambda f: f[0])
