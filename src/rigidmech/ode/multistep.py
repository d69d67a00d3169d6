r"""Adams multistep methods built on Newton's backward-difference interpolation (book, 26.3).

A multiple-step method (26.3.1) advances :math:`y' = f(t, y)` with the values
:math:`f_n, f_{n-1}, \dots` already computed at the previous points instead of new evaluations
inside the step. The book (26.3.2) interpolates :math:`f` through the last points with Newton's
backward-difference polynomial and integrates it over the next step; the coefficients of this
module are derived that way, exactly in rational arithmetic, when it is imported.

Methods (registered in :func:`rigidmech.ode.solve` with kind ``"fixed"``):

``"ab1"`` ... ``"ab5"``
    Adams-Bashforth with :math:`k = 1, \dots, 5` steps, order :math:`k`, one evaluation per
    step (``"ab1"`` is Euler's method, 26.1.3).
``"abm2"`` ... ``"abm5"``
    Adams-Bashforth-Moulton predictor-corrector in PECE mode, order :math:`k`: the
    :math:`k`-step Adams-Bashforth predictor, the :math:`(k-1)`-step Adams-Moulton corrector
    (the same order), two evaluations per step.

The first :math:`k - 1` steps are made by the classical Runge-Kutta method of order 4 with the
same step (26.2.2), which keeps the global order up to 5.
"""

from __future__ import annotations

from fractions import Fraction
from math import comb, factorial

import numpy as np

from rigidmech._core.errors import ArgumentError

from . import tableaux
from ._fixed import FixedRecorder, check_fixed, fixed_loop
from ._loop import check_progress
from ._registry import register
from .runge_kutta import integrate_fixed

__all__ = [
    "adams_gamma",
    "adams_bashforth_coefficients",
    "adams_moulton_coefficients",
    "adams_bashforth",
    "adams_bashforth_moulton",
]


def _poly_mul_linear(p, c):
    """Coefficients (ascending) of p(s) * (s + c)."""
    out = [Fraction(0)] * (len(p) + 1)
    for i, a in enumerate(p):
        out[i] += a * c
        out[i + 1] += a
    return out


def _integrate(p, lo, hi):
    """Exact integral of the polynomial p (ascending coefficients) over [lo, hi]."""
    return sum(a * (Fraction(hi) ** (i + 1) - Fraction(lo) ** (i + 1)) / (i + 1)
               for i, a in enumerate(p))


def adams_gamma(j: int, *, implicit: bool = False) -> Fraction:
    r"""Coefficient :math:`\gamma_j` (or :math:`\gamma_j^*`) of the `j`-th backward difference.

    Parameters
    ----------
    j : int
        Order of the backward difference, ``j >= 0``.
    implicit : bool
        False: Adams-Bashforth :math:`\gamma_j = \int_0^1 \binom{s+j-1}{j} ds`;
        True: Adams-Moulton :math:`\gamma_j^* = \int_{-1}^0 \binom{s+j-1}{j} ds`.

    Returns
    -------
    fractions.Fraction

    Examples
    --------
    >>> [str(adams_gamma(j)) for j in range(5)]
    ['1', '1/2', '5/12', '3/8', '251/720']
    >>> [str(adams_gamma(j, implicit=True)) for j in range(5)]
    ['1', '-1/2', '-1/12', '-1/24', '-19/720']
    """
    p = [Fraction(1)]
    for i in range(j):  # (s)(s+1)...(s+j-1) / j!  =  binom(s+j-1, j)
        p = _poly_mul_linear(p, Fraction(i))
    p = [a / factorial(j) for a in p]
    return _integrate(p, -1, 0) if implicit else _integrate(p, 0, 1)


def _to_ordinates(gammas):
    """Coefficients on f_{m}, f_{m-1}, ... of sum_j gamma_j nabla^j f_m."""
    k = len(gammas)
    return tuple(
        sum(gammas[j] * (-1) ** i * comb(j, i) for j in range(i, k)) for i in range(k)
    )


def adams_bashforth_coefficients(k: int) -> tuple[Fraction, ...]:
    r"""Weights :math:`\beta_i` of :math:`y_{n+1} = y_n + h\sum_{i=0}^{k-1}\beta_i f_{n-i}`.

    Parameters
    ----------
    k : int
        Number of steps (= order), ``k >= 1``.

    Returns
    -------
    tuple of Fraction

    Notes
    -----
    Newton's backward interpolation polynomial of :math:`f` through
    :math:`t_n, t_{n-1}, \dots, t_{n-k+1}`, with :math:`t = t_n + s h`, is (book, 26.3.2)

    .. math::

        P(t_n + s h) = \sum_{j=0}^{k-1} (-1)^j \binom{-s}{j} \nabla^j f_n
                     = \sum_{j=0}^{k-1} \binom{s+j-1}{j} \nabla^j f_n ;

    integrating it over the step, :math:`y_{n+1} - y_n = h\int_0^1 P\,ds`, gives
    :math:`y_{n+1} = y_n + h\sum_j \gamma_j \nabla^j f_n` with :math:`\gamma_j` of
    :func:`adams_gamma`. Expanding :math:`\nabla^j f_n = \sum_i (-1)^i \binom{j}{i} f_{n-i}`
    gives :math:`\beta_i = (-1)^i \sum_{j=i}^{k-1}\binom{j}{i}\gamma_j`.

    Examples
    --------
    >>> [str(b) for b in adams_bashforth_coefficients(4)]
    ['55/24', '-59/24', '37/24', '-3/8']
    """
    return _to_ordinates([adams_gamma(j) for j in range(k)])


def adams_moulton_coefficients(k: int) -> tuple[Fraction, ...]:
    r"""Weights :math:`\beta^*_i` of :math:`y_{n+1} = y_n + h\sum_{i=0}^{k-1}\beta^*_i f_{n+1-i}`.

    The Adams-Moulton formula of order `k` (``k - 1`` steps back from :math:`t_{n+1}`).

    Parameters
    ----------
    k : int
        Order, ``k >= 1``.

    Returns
    -------
    tuple of Fraction

    Notes
    -----
    The polynomial now interpolates :math:`f` through :math:`t_{n+1}, t_n, \dots,
    t_{n-k+2}`; with :math:`t = t_{n+1} + s h` the step is :math:`s \in [-1, 0]`:

    .. math::

        y_{n+1} = y_n + h\sum_{j=0}^{k-1}\gamma_j^*\nabla^j f_{n+1}, \qquad
        \gamma_j^* = \int_{-1}^{0}\binom{s+j-1}{j}\,ds .

    Examples
    --------
    >>> [str(b) for b in adams_moulton_coefficients(4)]
    ['3/8', '19/24', '-5/24', '1/24']
    """
    return _to_ordinates([adams_gamma(j, implicit=True) for j in range(k)])


_MAX_ORDER = 5
_AB = {k: tuple(float(b) for b in adams_bashforth_coefficients(k))
       for k in range(1, _MAX_ORDER + 1)}
_AM = {k: tuple(float(b) for b in adams_moulton_coefficients(k))
       for k in range(1, _MAX_ORDER + 1)}


def _rk4_start(fun, t0, y, h, k):
    """States at ``t0 + h, ..., t0 + (k - 1) h`` by Runge-Kutta 4 (26.2.2), newest last."""
    r = integrate_fixed(tableaux.RK4, fun, (t0, t0 + (k - 1) * h), y, step=h)
    return [np.array(r.y[:, j], dtype=float) for j in range(1, k)], r.nfev


def _combine(coeffs, fs, h):
    """h * sum_i coeffs[i] * fs[i] (fs newest first)."""
    acc = coeffs[0] * fs[0]
    for c, f in zip(coeffs[1:], fs[1:], strict=False):
        acc = acc + c * f
    return h * acc


def _run(fun, t_span, y0, step, order, corrector, max_steps, save_every, dense_output, name,
         progress=None):
    if isinstance(order, bool) or order not in _AB:
        raise ArgumentError(f"`order` must be an integer in 1..{_MAX_ORDER}; got {order!r}.")
    progress = check_progress(progress)
    t0, h, nsteps, y, save_every = check_fixed(t_span, y0, step, max_steps, save_every)
    beta = _AB[order]
    beta_c = _AM[order] if corrector else None
    f = np.array(fun(t0, y), dtype=float)
    rec = FixedRecorder(t0, y, f, save_every, dense_output)
    # state: the last y, the derivatives newest first, the RK4 starting states, nfev
    box = {"y": y, "history": [f], "starts": [], "i": 0, "nfev": 1}

    def advance(t, h):
        i = box["i"] = box["i"] + 1
        y, history = box["y"], box["history"]
        t_new = t + h
        if i < order:  # starting steps (26.3.1): Runge-Kutta 4
            if i == 1:
                box["starts"], n_start = _rk4_start(fun, t, y, h, min(order, nsteps + 1))
                box["nfev"] += n_start
            y = box["starts"][i - 1]
        else:
            y_pred = y + _combine(beta, history, h)
            if corrector:
                f_pred = np.array(fun(t_new, y_pred), dtype=float)
                box["nfev"] += 1
                y = y + h * beta_c[0] * f_pred + _combine(beta_c[1:], history, h)
            else:
                y = y_pred
        f = np.array(fun(t_new, y), dtype=float)
        box["nfev"] += 1
        history.insert(0, f)
        if len(history) > order:
            history.pop()
        box["y"] = y
        return y, f

    # overflow to inf/nan is reported in the result (status -1), not raised as a warning
    with np.errstate(over="ignore", invalid="ignore"):
        done = fixed_loop(advance, rec, t0, h, nsteps, progress=progress, fun=fun)
    return rec.result(name, box["nfev"], done, stats={"step": abs(h), "order": order})


def adams_bashforth(fun, t_span, y0, *, step, order=4, max_steps=None, save_every=1,
                    dense_output=False, progress=None):
    r"""Adams-Bashforth method with `order` steps, started by Runge-Kutta 4 (book, 26.3.2).

    Parameters
    ----------
    fun : callable
        ``fun(t, y)``, ``y`` of shape ``(n,)`` or ``(n, batch)``.
    t_span : tuple of float
        ``(t0, t1)``.
    y0 : array_like, shape (n,) or (n, batch)
        Initial state; a trailing batch axis integrates many initial states at once.
    step : float
        Requested step, rounded down so that a whole number of steps spans `t_span`.
    order : int
        Number of steps and order, 1 to 5.
    max_steps : int, optional
        Refuse to start if more steps would be needed.
    save_every : int
        Keep the state only every `save_every` steps (and at the end).
    dense_output : bool
        Attach a cubic Hermite interpolant ``sol(t)``.
    progress : callable, optional
        ``progress(t)`` after every step; returning False stops the run (status 2, as
        Ctrl-C does), with everything computed so far kept.

    Returns
    -------
    OdeResult
        ``nfev`` is ``nsteps + 1`` plus 4 per starting step.

    Raises
    ------
    ArgumentError
        On a bad `order`, `t_span`, `y0`, `step`, `max_steps` or `save_every`.

    Notes
    -----
    .. math::

        y_{n+1} = y_n + h\sum_{j=0}^{k-1}\gamma_j\nabla^j f_n
                = y_n + h\sum_{i=0}^{k-1}\beta_i f_{n-i},

    see :func:`adams_bashforth_coefficients` for the derivation. Local error
    :math:`\gamma_k h^{k+1} y^{(k+1)}`, global error :math:`O(h^k)`.

    Examples
    --------
    >>> import numpy as np
    >>> r = adams_bashforth(lambda t, y: -y, (0.0, 1.0), [1.0], step=0.01, order=4)
    >>> bool(abs(r.y[0, -1] - np.exp(-1.0)) < 2e-9), r.nfev
    (True, 113)
    """
    return _run(fun, t_span, y0, step, order, False, max_steps, save_every, dense_output,
                f"ab{order}", progress)


def adams_bashforth_moulton(fun, t_span, y0, *, step, order=4, max_steps=None, save_every=1,
                            dense_output=False, progress=None):
    r"""Adams-Bashforth-Moulton predictor-corrector of order `order` in PECE mode (26.3.2-4).

    Parameters are those of :func:`adams_bashforth`; `order` is 2 to 5.

    Returns
    -------
    OdeResult
        Two evaluations of ``fun`` per step after the start.

    Raises
    ------
    ArgumentError
        On a bad `order`, `t_span`, `y0`, `step`, `max_steps` or `save_every`.

    Notes
    -----
    Predict with Adams-Bashforth (P), evaluate (E), correct with Adams-Moulton of the same
    order (C), evaluate again (E):

    .. math::

        y^{P}_{n+1} = y_n + h\sum_{i=0}^{k-1}\beta_i f_{n-i}, \qquad
        y_{n+1} = y_n + h\Big(\beta^*_0 f(t_{n+1}, y^P_{n+1})
                  + \sum_{i=1}^{k-1}\beta^*_i f_{n+1-i}\Big).

    For ``order=4`` this is the classical pair
    :math:`\tfrac{h}{24}(55, -59, 37, -9)` / :math:`\tfrac{h}{24}(9, 19, -5, 1)`. The error
    constant of the corrector (:math:`\gamma^*_k`) is about ten times smaller than the
    predictor's (:math:`\gamma_k`).

    Examples
    --------
    >>> import numpy as np
    >>> r = adams_bashforth_moulton(lambda t, y: -y, (0.0, 1.0), [1.0], step=0.01, order=4)
    >>> bool(abs(r.y[0, -1] - np.exp(-1.0)) < 1e-10)
    True
    """
    if isinstance(order, bool) or order not in range(2, _MAX_ORDER + 1):
        raise ArgumentError(f"`order` must be an integer in 2..{_MAX_ORDER}; got {order!r}.")
    return _run(fun, t_span, y0, step, order, True, max_steps, save_every, dense_output,
                f"abm{order}", progress)


def _make(fn, order):
    def method(fun, t_span, y0, *, step, **options):
        return fn(fun, t_span, y0, step=step, order=order, **options)

    method.__name__ = method.__qualname__ = f"{fn.__name__}_{order}"
    method.__doc__ = f"{fn.__name__} of order {order} (see :func:`{fn.__name__}`)."
    return method


for _k in range(1, _MAX_ORDER + 1):
    register(f"ab{_k}", _make(adams_bashforth, _k), kind="fixed")
for _k in range(2, _MAX_ORDER + 1):
    register(f"abm{_k}", _make(adams_bashforth_moulton, _k), kind="fixed")
del _k
