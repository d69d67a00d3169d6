"""Shared checks and output recording of the fixed-step methods of :mod:`rigidmech.ode`.

Used by :mod:`~rigidmech.ode.multistep` and :mod:`~rigidmech.ode.geometric`: validation of
``t_span``, ``y0`` and ``step``, the uniform grid, thinning of the output (``save_every``) and the
assembly of the :class:`~rigidmech.ode.OdeResult` with an optional cubic Hermite dense output.
"""

from __future__ import annotations

import math

import numpy as np

from rigidmech._core.errors import ArgumentError, ArgumentTypeError

from ._dense import DenseSolution, hermite_coefficients
from ._result import OdeResult

__all__ = ["check_fixed", "FixedRecorder"]

_CHECK_EVERY = 32  # steps between two finiteness checks of the state


def check_fixed(t_span, y0, step, max_steps, save_every, *, even=False):
    """Validate the arguments of a fixed-step method and build its uniform grid.

    Returns
    -------
    t0 : float
    h : float
        Signed step, ``(t1 - t0) / nsteps``: the size ``|step|`` rounded down so that the grid
        ends exactly at ``t1`` (the sign of `step` is ignored: ``t_span`` gives the direction).
    nsteps : int
    y0 : ndarray, shape (n,) or (n, batch)
        Fresh float copy.
    save_every : int

    Examples
    --------
    >>> check_fixed((0.0, 1.0), [1.0, 0.0], 0.3, None, 1)[:3]
    (0.0, 0.25, 4)
    """
    try:
        t0, t1 = (float(v) for v in t_span)
    except (TypeError, ValueError):
        raise ArgumentError(f"`t_span` must be two numbers (t0, t1); got {t_span!r}.") from None
    if not (math.isfinite(t0) and math.isfinite(t1)) or t0 == t1:
        raise ArgumentError(f"`t_span` must be two distinct finite times; got {t_span!r}.")
    y = np.array(y0, dtype=float)
    if y.ndim not in (1, 2) or y.shape[0] == 0:
        raise ArgumentError(
            f"`y0` must have shape (n,) or (n, batch); got shape {np.shape(y0)}."
        )
    if even and y.shape[0] % 2:
        raise ArgumentError(
            f"`y0` must be [q0, v0] with as many velocities as positions (an even length); "
            f"got {y.shape[0]} components."
        )
    if not np.all(np.isfinite(y)):
        raise ArgumentError("`y0` must be finite; got a NaN or an infinity.")
    if step is None or isinstance(step, bool):
        raise ArgumentTypeError(
            f"`step` must be a number > 0 for a fixed-step method; got {step!r}."
        )
    try:
        h_req = float(step)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`step` must be a number > 0; got {step!r}.") from None
    h_req = abs(h_req)  # rigidmech.ode.solve passes the signed step
    if not (h_req > 0.0 and math.isfinite(h_req)):
        raise ArgumentError(f"`step` must be a finite nonzero number; got {step!r}.")
    length = abs(t1 - t0)
    nsteps = max(1, math.ceil(length / h_req * (1.0 - 1e-12)))
    if max_steps is not None and nsteps > max_steps:
        raise ArgumentError(
            f"`step` = {h_req:g} needs {nsteps} steps over `t_span` {t_span!r}, more than "
            f"`max_steps` = {max_steps}; increase `step` or `max_steps`."
        )
    if isinstance(save_every, bool) or not isinstance(save_every, int | np.integer) or (
        save_every < 1
    ):
        raise ArgumentError(f"`save_every` must be an integer >= 1; got {save_every!r}.")
    return t0, (t1 - t0) / nsteps, nsteps, y, int(save_every)


class FixedRecorder:
    """Collects the states of a fixed-step run and builds the :class:`OdeResult`.

    States are kept every `save_every` steps and at the last step; with `dense` the derivative
    is kept too, and the result carries a cubic Hermite ``sol(t)`` through the kept points.
    """

    __slots__ = ("ts", "ys", "fs", "dense", "save_every", "status", "message", "shape")

    def __init__(self, t0, y0, f0, save_every, dense):
        self.ts = [t0]
        self.ys = [y0.copy()]
        self.dense = bool(dense)
        self.fs = [np.array(f0, dtype=float)] if self.dense else None
        self.save_every = save_every
        self.status = 0
        self.message = "The integration reached the end of `t_span`."
        self.shape = y0.shape

    def wants(self, i, nsteps):
        """Whether step number `i` (1-based) is recorded."""
        return i % self.save_every == 0 or i == nsteps

    def add(self, t, y, f=None):
        """Record the state `y` (copied) at `t`, with its derivative `f` if dense."""
        self.ts.append(t)
        self.ys.append(np.array(y, dtype=float))
        if self.dense:
            self.fs.append(np.array(f, dtype=float))

    def check_finite(self, i, t, y):
        """Every few steps, stop with status -1 if the state is not finite; True to stop."""
        if i % _CHECK_EVERY:
            return False
        if np.all(np.isfinite(y)):
            return False
        state = np.array2string(np.asarray(y), precision=6, threshold=12)
        self.status = -1
        self.message = f"The state became non-finite at t = {t!r}; state y = {state}."
        return True

    def result(self, method, nfev, nsteps, stats=None):
        """Build the result: ``y`` of shape (n, m) or (n, m, batch), fresh arrays."""
        t = np.array(self.ts, dtype=float)
        Y = np.array(self.ys, dtype=float)  # (m, n[, batch])
        y = np.ascontiguousarray(np.moveaxis(Y, 0, 1))
        sol = None
        if self.dense and len(t) > 1:
            flat = Y.reshape(len(t), -1)
            F = np.array(self.fs, dtype=float).reshape(len(t), -1)
            h = np.diff(t)
            coeffs = np.stack(
                [hermite_coefficients(flat[i], flat[i + 1], F[i], F[i + 1], h[i])
                 for i in range(len(h))]
            )
            sol = DenseSolution(t, flat[:-1], coeffs, "power", self.shape)
        return OdeResult(
            t=t, y=y, nfev=int(nfev), nsteps=int(nsteps),
            nrejected=0, status=self.status, message=self.message, method=method, sol=sol,
            stats=dict(stats or {}),
        )
