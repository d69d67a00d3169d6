"""Linear stability and observed order of the Runge-Kutta methods (book, ch. 26.1.3, 26.2.2).

Applied to the test equation ``y' = lambda y`` with a step ``h``, a Runge-Kutta method of
tableau ``(A, b, c)`` multiplies the solution by its **stability function** at every step,
``y_{n+1} = R(z) y_n`` with ``z = h lambda`` and

.. math::

    R(z) = 1 + z\\, b^T (I - zA)^{-1} \\mathbb{1}.

The numerical solution stays bounded when ``|R(z)| <= 1``. On the negative real axis (a
damped, non-oscillating mode of decay rate ``-lambda``) this holds on an interval
``[x_min, 0]``, the **real stability interval**: a fixed step must keep
``h |lambda| <= |x_min|`` (Euler: 2; classical Runge-Kutta: 2.785; Dormand-Prince 5: 3.307;
Hairer and Wanner, *Solving Ordinary Differential Equations* II, Sec. IV.2).

:func:`observed_order` measures the other property of a method, its order, on a problem whose
exact solution is known: the slope of the error against the step in log-log axes.

Examples
--------
>>> from rigidmech.ode import tableaux
>>> from rigidmech.ode.stability import real_stability_interval, stability_function
>>> complex(stability_function(tableaux.EULER, -0.5))
(0.5+0j)
>>> real_stability_interval(tableaux.EULER)
(-2.0, 0.0)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from rigidmech._core.errors import ArgumentError, ArgumentTypeError, NumericalError

from .api import solve
from .tableaux import ALL, ButcherTableau

__all__ = [
    "stability_function",
    "stability_polynomial",
    "is_stable",
    "real_stability_interval",
    "observed_order",
    "Convergence",
]

#: Spacing of the scan of the negative real axis in :func:`real_stability_interval`, before the
#: bisection: an unstable gap narrower than this inside the interval would be missed.
SCAN_STEP = 1e-3


def _tableau(tableau) -> ButcherTableau:
    if isinstance(tableau, ButcherTableau):
        return tableau
    if isinstance(tableau, str):
        try:
            return ALL[tableau]
        except KeyError:
            raise ArgumentError(
                f"`tableau` must be a ButcherTableau or one of {sorted(ALL)}; got {tableau!r}."
            ) from None
    raise ArgumentTypeError(
        f"`tableau` must be a ButcherTableau or the name of one; got "
        f"{type(tableau).__name__}. Pass e.g. rigidmech.ode.tableaux.RK4."
    )


def _complex(z, name="z") -> np.ndarray:
    try:
        out = np.asarray(z, dtype=complex)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"`{name}` must be a complex number or an array of them; got {type(z).__name__}."
        ) from None
    if not np.all(np.isfinite(out)):
        raise ArgumentError(f"`{name}` must be finite; got {z!r}.")
    return out


def stability_function(tableau, z):
    """The stability function ``R(z) = 1 + z b^T (I - zA)^{-1} 1`` of a Runge-Kutta method.

    Book, ch. 26.2.2: one step of the method on ``y' = lambda y`` is the multiplication of
    ``y`` by ``R(h lambda)``.

    Parameters
    ----------
    tableau : ButcherTableau or str
        The method (a name of :data:`rigidmech.ode.tableaux.ALL`, e.g. ``"rk4"``, is accepted).
    z : complex or array_like of complex
        Points ``z = h lambda`` of the complex plane, any shape.

    Returns
    -------
    ndarray of complex
        ``R(z)``, of the shape of `z` (0-d for a scalar).

    Raises
    ------
    ArgumentTypeError
        If `tableau` is not a tableau or `z` not numbers.
    ArgumentError
        If `z` holds a nan or an infinity, or `tableau` names no tableau.

    Notes
    -----
    The stage system ``(I - zA) g = 1`` is solved by forward substitution for all the points
    at once: ``A`` is strictly lower triangular (an explicit method), so ``I - zA`` is never
    singular and ``R`` is the polynomial of :func:`stability_polynomial`. The value at a point
    does not depend on the shape of `z` (element-wise operations only).

    Examples
    --------
    >>> from rigidmech.ode import tableaux
    >>> R = stability_function(tableaux.RK4, [-1.0, 1j])
    >>> bool(np.allclose(R, [1 - 1 + 1/2 - 1/6 + 1/24, 1 + 1j - 1/2 - 1j/6 + 1/24]))
    True
    """
    tab = _tableau(tableau)
    z = _complex(z)
    # (I - zA) g = 1 by forward substitution (A is strictly lower triangular): element-wise
    # operations only, so R(z) at a point does not depend on the shape of the array it is in
    # (a batched LAPACK solve rounds differently, and is_stable must give one verdict).
    g = []
    for i in range(tab.stages):
        gi = np.ones_like(z)
        for j in range(i):
            if tab.A[i, j] != 0.0:
                gi = gi + z * (tab.A[i, j] * g[j])
        g.append(gi)
    total = np.zeros_like(z)
    for bi, gi in zip(tab.b, g, strict=True):
        if bi != 0.0:
            total = total + bi * gi
    return 1 + z * total


def stability_polynomial(tableau) -> np.ndarray:
    """The coefficients of ``R(z)`` for an explicit method, lowest degree first.

    ``R(z) = sum_k gamma_k z^k`` with ``gamma_0 = 1`` and ``gamma_k = b^T A^(k-1) 1``; a method
    of order ``p`` has ``gamma_k = 1/k!`` for ``k <= p`` (book, ch. 26.2.2).

    Parameters
    ----------
    tableau : ButcherTableau or str

    Returns
    -------
    ndarray, shape (stages + 1,)
        ``gamma_0 .. gamma_s`` (trailing zeros kept).

    Examples
    --------
    >>> from rigidmech.ode import tableaux
    >>> stability_polynomial(tableaux.HEUN).tolist()
    [1.0, 1.0, 0.5]
    >>> float(stability_polynomial(tableaux.DOPRI5)[6]) * 600     # HW II, Sec. IV.2: z^6/600
    1.0000000000000...
    """
    tab = _tableau(tableau)
    out = [1.0]
    v = np.ones(tab.stages)
    for _ in range(tab.stages):
        out.append(float(tab.b @ v))
        v = tab.A @ v
    return np.array(out)


def is_stable(tableau, z):
    """Whether ``|R(z)| <= 1``: the point ``z = h lambda`` lies in the region of absolute
    stability (book, ch. 26.1.3).

    The boundary ``|R(z)| = 1`` counts as stable; the comparison is made on the computed
    ``|R(z)|`` without slack (the one rule of this module, used by
    :func:`real_stability_interval`).

    Parameters
    ----------
    tableau : ButcherTableau or str
    z : complex or array_like of complex

    Returns
    -------
    bool or ndarray of bool
        Of the shape of `z`.

    Examples
    --------
    >>> from rigidmech.ode import tableaux
    >>> is_stable(tableaux.EULER, [-2.0, -2.001, -1 + 1j]).tolist()
    [True, False, True]
    """
    stable = np.abs(stability_function(tableau, z)) <= 1.0
    return bool(stable) if stable.ndim == 0 else stable


def real_stability_interval(tableau) -> tuple[float, float]:
    """The interval ``[x_min, 0]`` of the negative real axis where ``|R(x)| <= 1``.

    A fixed step ``h`` integrates a decay ``y' = lambda y`` (``lambda < 0``) without blowing up
    when ``h |lambda| <= |x_min|`` (book, ch. 26.1.3).

    Parameters
    ----------
    tableau : ButcherTableau or str
        An explicit method (every :class:`~rigidmech.ode.tableaux.ButcherTableau` is).

    Returns
    -------
    (float, float)
        ``(x_min, 0.0)``; ``x_min`` is within rounding of 0 (``|R(x)| = 1`` in floating
        point only) if the method is unstable just left of 0 (an inconsistent tableau), and
        ``-inf`` if ``R`` is the constant 1.

    Notes
    -----
    The axis is scanned leftwards with the spacing :data:`SCAN_STEP` up to the first point
    where :func:`is_stable` fails, then bisected between that point and the last stable one
    down to adjacent floats: ``x_min`` is the last float where :func:`is_stable` holds. The
    scan ends at Cauchy's bound on the roots of ``R(x) -+ 1``, beyond which ``|R| > 1`` for
    good. Known values
    (Hairer-Wanner II, Sec. IV.2): Euler -2, Heun and midpoint -2, RK4 -2.7853, DOPRI5
    -3.3066.

    Examples
    --------
    >>> from rigidmech.ode import tableaux
    >>> x_min, _ = real_stability_interval(tableaux.RK4)
    >>> round(x_min, 6)
    -2.785294
    """
    tab = _tableau(tableau)
    gamma = stability_polynomial(tab)
    nonzero = np.flatnonzero(gamma[1:]) + 1
    if nonzero.size == 0:
        return (-math.inf, 0.0)
    degree = int(nonzero[-1])
    # Cauchy's bound on the roots of R(x) - 1 and R(x) + 1 (they share the leading coefficient)
    lower = gamma[:degree]
    bound = 1.0 + max(np.max(np.abs(lower - 1.0)), np.max(np.abs(lower + 1.0))) / abs(
        gamma[degree])
    n = math.ceil(bound / SCAN_STEP) + 1
    chunk = 4096
    x_good = 0.0
    for start in range(1, n + 1, chunk):
        x = -SCAN_STEP * np.arange(start, min(start + chunk, n + 1))
        bad = np.flatnonzero(~is_stable(tab, x))
        if bad.size:
            x_bad = float(x[bad[0]])
            if bad[0] > 0:
                x_good = float(x[bad[0] - 1])
            break
        x_good = float(x[-1])
    else:  # pragma: no cover - beyond Cauchy's bound |R| > 1, so the scan always stops
        raise NumericalError(f"no end to the stability interval of {tab.name!r} found.")
    # Hand-rolled bisection on the predicate of is_stable rather than scipy's brentq on
    # |R| - 1: it ends on the last stable float, so the returned x_min is itself stable
    # (exactly -2.0 for Euler), which a root finder's tolerance does not guarantee.
    while True:
        mid = 0.5 * (x_good + x_bad)
        if mid in (x_good, x_bad):
            break
        if is_stable(tab, mid):
            x_good = mid
        else:
            x_bad = mid
    return (x_good, 0.0)


@dataclass(frozen=True)
class Convergence:
    """Errors of a method at several steps and the order they show (book, ch. 26.2).

    Attributes
    ----------
    steps : tuple of float
        The steps actually taken (each reduced, if needed, so that equal steps span
        ``t_span``), as given.
    errors : tuple of float
        Max-norm error of the final state at each step.
    order : float
        Least-squares slope of ``log(error)`` against ``log(step)``.
    slopes : tuple of float
        The slopes between consecutive steps (to see where the asymptotic regime starts).

    Examples
    --------
    >>> c = Convergence(steps=(0.1, 0.05), errors=(1e-4, 0.25e-4), order=2.0, slopes=(2.0,))
    >>> c.order
    2.0
    """

    steps: tuple
    errors: tuple
    order: float
    slopes: tuple


def observed_order(method, fun: Callable, t_span, y0, exact, steps) -> Convergence:
    """The order a fixed-step method shows on a problem with an exact solution.

    The method is run with each step of `steps`; the error of the final state falls as
    ``C h^p`` in the asymptotic regime, and ``p`` is the slope of ``log(error)`` against
    ``log(h)`` (book, ch. 26.2: Euler's method has order 1, the classical Runge-Kutta method
    order 4).

    Parameters
    ----------
    method : str or ButcherTableau
        A fixed-step method of :func:`rigidmech.ode.solve` (``methods("fixed")``).
    fun : callable
        ``fun(t, y)``, as for :func:`~rigidmech.ode.solve`.
    t_span : (float, float)
    y0 : array_like, shape (n,)
    exact : array_like, shape (n,), or callable
        The exact final state, or ``exact(t)`` giving the state at ``t``.
    steps : sequence of float
        At least two distinct positive steps, in the asymptotic regime (errors well above
        rounding, well below 1).

    Returns
    -------
    Convergence

    Raises
    ------
    ArgumentError
        On fewer than two steps, a non-positive or repeated step, a wrong shape of `exact`, or
        a zero error (the method is exact on this problem: the order cannot be read).
    NumericalError
        If a run fails (a step too large for stability, say).

    Examples
    --------
    >>> import numpy as np
    >>> c = observed_order("rk4", lambda t, y: -y, (0.0, 1.0), [1.0],
    ...                    lambda t: np.exp(-np.array([t])), [0.1, 0.05, 0.025])
    >>> round(c.order, 1)
    4.0
    """
    try:
        hs = [float(h) for h in steps]
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"`steps` must be a sequence of numbers; got {steps!r}.") from None
    if len(hs) < 2:
        raise ArgumentError(
            f"`steps` must hold at least two steps to measure a slope; got {len(hs)}.")
    if not all(h > 0 and math.isfinite(h) for h in hs):
        raise ArgumentError(f"`steps` must be finite and > 0; got {hs}.")
    if len(set(hs)) != len(hs):
        raise ArgumentError(f"`steps` must be distinct; got {hs}.")
    try:
        t0, t1 = (float(x) for x in t_span)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"`t_span` must be a pair of numbers (t0, t1); got {t_span!r}.") from None
    y_exact = np.asarray(exact(t1) if callable(exact) else exact, dtype=float)
    y0 = np.asarray(y0, dtype=float)
    if y_exact.shape != y0.shape:
        raise ArgumentError(
            f"`exact` must give a state of the shape of `y0` {y0.shape}; got {y_exact.shape}.")
    taken, errors = [], []
    for h in hs:
        r = solve(fun, t_span, y0, method=method, step=h)
        if not r.success:
            raise NumericalError(
                f"the run with `step` = {h:g} failed: {r.message} Use smaller steps.")
        err = float(np.max(np.abs(np.asarray(r.y)[..., -1] - y_exact)))
        if err == 0.0:
            raise ArgumentError(
                f"the error is exactly 0 at `step` = {h:g}: the method is exact on this "
                "problem and shows no order; choose a problem it does not solve exactly.")
        taken.append(abs(t1 - t0) / r.nsteps)
        errors.append(err)
    logh, loge = np.log(taken), np.log(errors)
    order = float(np.polyfit(logh, loge, 1)[0])
    slopes = tuple(float(s) for s in np.diff(loge) / np.diff(logh))
    return Convergence(steps=tuple(taken), errors=tuple(errors), order=order, slopes=slopes)
