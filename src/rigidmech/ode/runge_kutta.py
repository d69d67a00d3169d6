"""Fixed-step explicit Runge-Kutta methods: Euler, Heun, midpoint, RK4, any tableau (ch. 26.2).

The book (ch. 26.2) integrates the equations of motion step by step with Euler's method and the
classical fourth-order Runge-Kutta method. Every such method is the same loop driven by a
:class:`~rigidmech.ode.tableaux.ButcherTableau`; :func:`fixed_step_method` makes the integrator
of any tableau, and the methods ``"euler"``, ``"heun"``, ``"midpoint"``, ``"rk4"`` and
``"rk38"`` are registered for :func:`rigidmech.ode.solve`.
"""

from __future__ import annotations

import math

import numpy as np

from rigidmech._core.errors import ArgumentTypeError

from . import _registry, tableaux
from ._driver import Problem, fail_message
from ._floatpath import FLOAT_PATH_MAX_N, cached, make_unrolled_stepper
from ._result import OdeResult

__all__ = ["fixed_step_method", "integrate_fixed"]


def integrate_fixed(tableau, fun, t_span, y0, *, step, max_steps=None) -> OdeResult:
    """Integrate with the explicit tableau `tableau` and the uniform step `step`.

    Parameters
    ----------
    tableau : ButcherTableau
    fun : callable
        ``fun(t, y)`` with ``y`` of the shape of `y0`.
    t_span : (float, float)
    y0 : ndarray, shape (n,) or (n, batch)
    step : float
        Signed step; ``round((t1 - t0) / step)`` steps are taken, the last one landing on t1.
    max_steps : int, optional
        Unused (checked by :func:`~rigidmech.ode.solve`); accepted for the common signature.

    Returns
    -------
    OdeResult
        All grid points; on a non-finite state, status -1 and the points computed so far.

    Examples
    --------
    >>> import numpy as np
    >>> r = integrate_fixed(tableaux.RK4, lambda t, y: -y, (0.0, 1.0), np.array([1.0]),
    ...                     step=0.1)
    >>> float(r.y[0, -1]), r.nfev          # exp(-1) = 0.36787944..., error 3.3e-7
    (0.36787977..., 40)
    """
    t0, t1 = t_span
    shape = y0.shape
    nsteps = max(1, int(round((t1 - t0) / step)))
    h = (t1 - t0) / nsteps
    if len(shape) == 1 and shape[0] <= FLOAT_PATH_MAX_N:
        f0 = fun(t0, y0.copy())
        if type(f0) is np.ndarray and f0.shape == shape and f0.dtype == np.float64:
            return _integrate_fixed_float(tableau, fun, t0, t1, y0, f0, nsteps, h)
    else:
        f0 = None
    prob = Problem(fun, shape)
    A, b, c = tableau.A, tableau.b, tableau.c
    s = tableau.stages
    hA = [h * A[i, :i] for i in range(s)]
    hc = h * c
    hb = h * b
    used = [i for i in range(s) if b[i] != 0]
    N = y0.size
    Y = np.empty((nsteps + 1, N))
    Y[0] = y0.reshape(-1)
    K = np.empty((s, N))
    status, message, last = 0, "The integration reached the end of `t_span`.", nsteps
    for k in range(nsteps):
        t = t0 + k * h
        y = Y[k]
        if k == 0 and f0 is not None:
            prob.nfev += 1
            K[0] = f0
        else:
            prob(t, y, K[0])
        for i in range(1, s):
            prob(t + hc[i], y + hA[i] @ K[:i], K[i])
        y_new = Y[k + 1]
        np.dot(hb[used], K[used], out=y_new)
        y_new += y
        if not np.isfinite(y_new.sum()):
            status, last = -1, k
            message = fail_message("The state became non-finite", t + h, y_new, shape)
            break
    t_grid = t0 + h * np.arange(last + 1)
    t_grid[-1] = t1 if status == 0 else t_grid[-1]
    Yk = Y[: last + 1]
    y_out = np.ascontiguousarray(np.moveaxis(Yk.reshape((last + 1,) + shape), 0, 1))
    return OdeResult(t=t_grid, y=y_out, nfev=prob.nfev, nsteps=last, nrejected=0,
                     status=status, message=message, method=tableau.name)


def _integrate_fixed_float(tableau, fun, t0, t1, y0, f0, nsteps, h):
    """:func:`integrate_fixed` on lists of floats, for one small trajectory."""
    n = y0.shape[0]
    step = cached(("rk-fixed", tableau, n), lambda: make_unrolled_stepper(
        tableau.name, tableau.A, tableau.b, tableau.c, tableau.stages, None, n))
    arr, isfinite = np.array, math.isfinite
    y = y0.tolist()
    ys = [y]
    k0 = f0.tolist()
    status, message, last = 0, "The integration reached the end of `t_span`.", nsteps
    nfev = 1
    for k in range(nsteps):
        t = t0 + k * h
        if k:
            k0 = fun(t, arr(y)).tolist()
            nfev += 1
        y = step(fun, t, y, k0, h)
        nfev += tableau.stages - 1
        if not isfinite(sum(y)):
            status, last = -1, k
            message = fail_message("The state became non-finite", t + h, y, y0.shape)
            break
        ys.append(y)
    t_grid = t0 + h * np.arange(last + 1)
    if status == 0:
        t_grid[-1] = t1
    return OdeResult(t=t_grid, y=np.array(ys).T.copy(), nfev=nfev, nsteps=last, nrejected=0,
                     status=status, message=message, method=tableau.name)


def fixed_step_method(tableau):
    """The fixed-step integrator ``fn(fun, t_span, y0, *, step, **options)`` of `tableau`.

    Parameters
    ----------
    tableau : ButcherTableau

    Returns
    -------
    callable
        Suitable for ``rigidmech.ode._registry.register(name, fn, kind="fixed")``.

    Examples
    --------
    >>> import numpy as np
    >>> ralston = tableaux.ButcherTableau("ralston", [[0, 0], [2 / 3, 0]], [1 / 4, 3 / 4],
    ...                                   [0, 2 / 3], order=2)
    >>> fn = fixed_step_method(ralston)
    >>> r = fn(lambda t, y: np.cos(t) * np.ones_like(y), (0.0, 1.0), np.zeros(1), step=0.01)
    >>> bool(abs(r.y[0, -1] - np.sin(1.0)) < 1e-5)
    True
    """
    if not isinstance(tableau, tableaux.ButcherTableau):
        raise ArgumentTypeError(
            f"`tableau` must be a ButcherTableau; got {type(tableau).__name__}."
        )

    def method(fun, t_span, y0, *, step, max_steps=None):
        with np.errstate(over="ignore", invalid="ignore"):  # a blow-up is reported in status
            return integrate_fixed(tableau, fun, t_span, y0, step=step)

    method.__name__ = method.__qualname__ = f"fixed_step_{tableau.name}"
    method.__doc__ = f"Fixed-step explicit Runge-Kutta method {tableau.name!r}."
    return method


for _t in (tableaux.EULER, tableaux.HEUN, tableaux.MIDPOINT, tableaux.RK4, tableaux.RK38):
    _registry.register(_t.name, fixed_step_method(_t), kind="fixed")
