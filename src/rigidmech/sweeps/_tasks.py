"""What one chunk of a sweep computes (book, ch. 25.4 and 27): picklable tasks.

A task is made once in the calling process (the equations compiled there, once) and called on
each chunk, in this process or on a Dask worker after a round trip through cloudpickle: it
holds only the compiled code (kept as its generated source, so it pickles) and numbers. The
same chunk gives the same numbers wherever it runs.

* :class:`OdeTask`: a batch of initial states and parameter values integrated at once by
  :func:`rigidmech.ode.solve` (the batch on the trailing axis, one step for the whole batch),
  the final state or the samples at given times kept.
* :class:`EigenTask`: the eigenvalues of the state matrix of a
  :class:`~rigidmech.vibrations.LinearSystem` at each point, sorted by real then imaginary part.

Examples
--------
>>> import sympy as sp, numpy as np
>>> from rigidmech import EquationsOfMotion, vibrations
>>> x, v, k = sp.symbols("x x_dot k")
>>> eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
...     mass_matrix=sp.ImmutableMatrix([[1]]), forcing=sp.ImmutableMatrix([[-k * x]]))
>>> task = EigenTask(vibrations.linearize(eqs))
>>> task({"k": np.array([4.0])}, None).imag.tolist()
[[-2.0, 2.0]]
"""

from __future__ import annotations

import numpy as np

from .._core.errors import NumericalError
from ..dynamics import _compiled
from ..ode import solve
from ..vibrations._numeric import compiled_matrices, state_matrix

#: The embedded pairs, which take the option ``stepping`` (:mod:`rigidmech.ode._ensemble`).
_PAIRS = ("dopri5", "rk45", "dop853", "bs32")

__all__ = ["OdeTask", "EigenTask", "CallableTask"]

_SCALAR = (float, np.float64)


class OdeTask:
    """Integrate a chunk: ``columns`` (name -> values of the chunk) to an array
    ``(chunk, ...)`` of the final states ``(chunk, 2n)`` or samples ``(chunk, len(t_eval), 2n)``,
    or what ``quantity(t, y, rng)`` makes of the samples ``y`` of shape (2n, len(t), chunk)."""

    def __init__(self, eqs, fixed, t_span, t_eval, quantity, options):
        self.solve = _compiled.solver(eqs)          # compiled here, once
        self.n = len(eqs.coordinates)
        self.q_names = tuple(eqs.names)
        self.arg_names = (tuple(p.name for p in eqs.parameters)
                          + tuple(_compiled.coordinate_name(w) for w in eqs.inputs))
        self.fixed = dict(fixed)
        self.t_span = (float(t_span[0]), float(t_span[1]))
        self.t_eval = np.asarray(t_eval, dtype=float)
        self.quantity = quantity
        self.options = dict(options)

    def __call__(self, columns, rng):
        size = len(next(iter(columns.values())))
        n = self.n
        y0 = np.zeros((2 * n, size))
        for i, name in enumerate(self.q_names):
            if name in columns:
                y0[i] = columns[name]
            elif name in self.fixed:
                y0[i] = self.fixed[name]
            if name + "_dot" in columns:
                y0[n + i] = columns[name + "_dot"]
            elif name + "_dot" in self.fixed:
                y0[n + i] = self.fixed[name + "_dot"]
        values = [columns[a] if a in columns else self.fixed[a] for a in self.arg_names]
        solve_ = self.solve
        # the generated batched code called directly on the chunk's float arrays, without the
        # argument handling of solve_(...) (a tenth of a sweep's CPU on the double pendulum,
        # chunks of 1000): the same function on the same arrays, so the same numbers; A and b
        # handed back (a pivot too small) or anything unexpected takes the checked call
        step = _compiled.batched_first_order(solve_, n)
        arrays = [np.asarray(v, dtype=float) for v in values]

        def fun(t, y):
            if step is not None and y.shape == y0.shape and type(t) in _SCALAR:
                dy = step(t, y, arrays)
                if dy is not None:
                    return dy
            return np.concatenate((y[n:], solve_(t, y[:n], y[n:], *values)), axis=0)

        # the members' parameter values are bound to the batch's columns (`values`), which
        # per-trajectory steps would compact: one step for the whole batch
        shared = {"stepping": "shared"} if self.options["method"] in _PAIRS else {}
        res = solve(fun, self.t_span, y0, self.options["method"], t_eval=self.t_eval,
                    rtol=self.options["rtol"], atol=self.options["atol"],
                    max_steps=self.options["max_steps"], step=self.options["step"], **shared)
        if res.status != 0:
            raise NumericalError(f"the integration of the chunk failed: {res.message}")
        if callable(self.quantity):
            return np.asarray(self.quantity(res.t, res.y, rng))
        if self.quantity == "final":
            return np.ascontiguousarray(res.y[:, -1, :].T)
        return np.ascontiguousarray(np.transpose(res.y, (2, 1, 0)))


class EigenTask:
    """The eigenvalues of A = [[0, I], [-M^-1 K, -M^-1 C]] at each point of a chunk, each
    row sorted (``numpy.sort_complex``): an array ``(chunk, 2n)`` of complex numbers."""

    def __init__(self, linear_system, fixed=None):
        self.matrices = compiled_matrices(linear_system)     # compiled here, once
        self.fixed = dict(fixed or {})

    def __call__(self, columns, rng):
        size = len(next(iter(columns.values())))
        out = None
        for k in range(size):
            params = dict(self.fixed)
            params.update({name: float(v[k]) for name, v in columns.items()})
            M, C, K, _ = self.matrices(params)
            lam = np.sort_complex(np.linalg.eigvals(state_matrix(M, C, K)))
            if out is None:
                out = np.empty((size, lam.size), dtype=complex)
            out[k] = lam
        return out


class CallableTask:
    """``function(columns, rng) -> array (chunk, ...)``: any vectorised computation of the
    swept values (``rng`` the chunk's own :class:`numpy.random.Generator`)."""

    def __init__(self, function, fixed=None):
        self.function = function
        self.fixed = dict(fixed or {})

    def __call__(self, columns, rng):
        size = len(next(iter(columns.values())))
        args = {**self.fixed, **columns}
        out = np.asarray(self.function(args, rng))
        if out.ndim == 0 or out.shape[0] != size:
            raise NumericalError(
                f"the swept function must return an array of shape ({size}, ...) for a chunk "
                f"of {size} points; got shape {out.shape}.")
        return out
