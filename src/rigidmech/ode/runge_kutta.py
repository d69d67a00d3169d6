"""Fixed-step explicit Runge-Kutta methods: Euler, Heun, midpoint, RK4, any tableau (ch. 26.2).

The book (ch. 26.2) integrates the equations of motion step by step with Euler's method and the
classical fourth-order Runge-Kutta method. Every such method is the same loop driven by a
:class:`~rigidmech.ode.tableaux.ButcherTableau`; :func:`fixed_step_method` makes the integrator
of any tableau, and the methods ``"euler"``, ``"heun"``, ``"midpoint"``, ``"rk4"`` and
``"rk38"`` are registered for :func:`rigidmech.ode.solve`.
"""

from __future__ import annotations

import numpy as np

from rigidmech._core.errors import ArgumentTypeError

from . import _registry, tableaux
from ._driver import Problem
from ._fixed import FixedRecorder, _list_finite, fixed_loop
from ._floatpath import FLOAT_PATH_MAX_N, make_fixed_advance
from ._loop import check_progress
from ._result import OdeResult

__all__ = ["fixed_step_method", "integrate_fixed"]


def integrate_fixed(tableau, fun, t_span, y0, *, step, max_steps=None,
                    progress=None) -> OdeResult:
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
    progress : callable, optional
        ``progress(t)`` after every step; returning False stops the run (status 2, as
        Ctrl-C does), with everything computed so far kept.

    Returns
    -------
    OdeResult
        All grid points; on a non-finite state, status -1 and the finite points computed so
        far; on Ctrl-C, status 2 and the points computed so far.

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
    rec = FixedRecorder(t0, y0.reshape(-1), None, 1, False, shape)
    f0 = None
    if len(shape) == 1 and shape[0] <= FLOAT_PATH_MAX_N:
        f0 = fun(t0, y0.copy())
        if type(f0) is np.ndarray and f0.shape == shape and f0.dtype == np.float64:
            advance, stages = _float_steps(tableau, fun, y0, f0)
            done = fixed_loop(advance, rec, t0, h, nsteps, t1=t1, progress=progress,
                              finite=_list_finite, fun=fun)
            attempted = done + (rec.status == -1)  # a non-finite step was made, not kept
            return rec.result(tableau.name, max(1, attempted * stages), done)
    advance, nfev = _array_steps(tableau, Problem(fun, shape), y0, f0, h)
    done = fixed_loop(advance, rec, t0, h, nsteps, t1=t1, progress=progress, fun=fun)
    return rec.result(tableau.name, nfev(), done)


def _array_steps(tableau, prob, y0, f0, h):
    """The step ``advance(t, h) -> (y, None)`` of `tableau` (of size `h`) on flat arrays,
    and its counter of evaluations."""
    s = tableau.stages
    hA = [h * tableau.A[i, :i] for i in range(s)]
    hc = h * tableau.c
    used = [i for i in range(s) if tableau.b[i] != 0]
    hb = h * tableau.b[used]
    K = np.empty((s, y0.size))
    box = [y0.reshape(-1).copy(), f0]

    def advance(t, h):
        y = box[0]
        if box[1] is not None:  # f(t0, y0), evaluated to choose the path
            prob.nfev += 1
            K[0] = box[1]
            box[1] = None
        else:
            prob(t, y, K[0])
        for i in range(1, s):
            prob(t + hc[i], y + hA[i] @ K[:i], K[i])
        y_new = np.dot(hb, K[used])
        y_new += y
        box[0] = y_new
        return y_new, None

    return advance, lambda: prob.nfev


def _float_steps(tableau, fun, y0, f0):
    """The step ``advance(t, h) -> (y, None)`` of `tableau` on lists of floats, for one small
    trajectory (generated: the whole step, first stage included), and its counter of
    evaluations (``f0`` then every stage of every step: each step after the first one
    evaluates its first stage)."""
    advance = make_fixed_advance(tableau.name, tableau.A, tableau.b, tableau.c,
                                 tableau.stages, y0.shape[0])(fun, y0.tolist(), f0.tolist())
    return advance, tableau.stages


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

    def method(fun, t_span, y0, *, step, max_steps=None, progress=None):
        progress = check_progress(progress)
        with np.errstate(over="ignore", invalid="ignore"):  # a blow-up is reported in status
            return integrate_fixed(tableau, fun, t_span, y0, step=step, progress=progress)

    method.__name__ = method.__qualname__ = f"fixed_step_{tableau.name}"
    method.__doc__ = f"Fixed-step explicit Runge-Kutta method {tableau.name!r}."
    return method


for _t in (tableaux.EULER, tableaux.HEUN, tableaux.MIDPOINT, tableaux.RK4, tableaux.RK38):
    _registry.register(_t.name, fixed_step_method(_t), kind="fixed")
