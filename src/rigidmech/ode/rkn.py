r"""Embedded Runge-Kutta-Nystrom pairs for :math:`\ddot q = a(t, q)` (book, ch. 26-27).

The equations of motion of a conservative system with a constant mass matrix (27.2.1) are
*special* second-order systems: the acceleration does not depend on the velocity. A
Runge-Kutta-Nystrom (RKN) method integrates them directly, without doubling the system into
``y' = (v, a)``; for the same order it needs fewer stages than a Runge-Kutta method (DPRKN6:
6 stages, 5 evaluations per step thanks to FSAL, against 12 for DOP853).

Methods (registered in :func:`rigidmech.ode.solve` with kind ``"adaptive_second_order"``:
``fun`` is the acceleration ``a(t, q)`` and ``y0 = [q0, v0]``; ``solve`` passes ``rtol``,
``atol``, ``first_step``, ``max_step``, dense output and events):

``"rkn64"``
    Dormand and Prince's 6(4) RKN pair with FSAL (DPRKN6): the local error (``rtol``,
    ``atol``) is controlled with the 4th-order embedded formula, Hairer's RMS norm on
    ``(q, v)``; dense output and events. Called directly as :func:`rkn64` with a ``step``, it
    runs the 6th-order formula with a constant step.
``"rkn1210"``
    Dormand, El-Mikkawy and Prince's 12(10) pair (DPRKN12), 17 evaluations per step, for
    tight tolerances; same two ways of calling.

One step of size :math:`h` from :math:`(t, q, v)`:

.. math::

    k_i = a\Big(t + c_i h,\; q + c_i h v + h^2 \sum_{j<i} \bar a_{ij} k_j\Big), \quad
    q_1 = q + h v + h^2 \sum_i \bar b_i k_i, \quad v_1 = v + h \sum_i b_i k_i .
"""

from __future__ import annotations

import dataclasses
import math
from decimal import Decimal, localcontext
from fractions import Fraction as F

import numpy as np

from rigidmech._core.errors import ArgumentError, ArgumentTypeError

from . import _registry
from . import _rkn12_coefficients as _rkn12
from ._driver import Stops
from ._fixed import FixedRecorder, _list_finite, fixed_loop
from ._floatpath import make_rkn_stepper
from ._loop import Capabilities, Run, StepResult, check_progress, integrate
from ._registry import register
from .api import _check_fixed_step, _check_t_span, _check_y0, fixed_events, solve
from .events import EventTracker

__all__ = ["RKNPair", "DPRKN6", "DPRKN12", "rkn64", "rkn1210"]

#: Largest ``d = len(q)`` for which the step is unrolled over the components in plain floats.
FLOAT_PATH_MAX_D = 8


class RKNPair:
    """Coefficients of an embedded RKN pair, exact (``Fraction`` or ``p + q sqrt(r)``).

    Parameters
    ----------
    name : str
    order, order_embedded : int
    c : list
        Nodes :math:`c_i` (``c[0] = 0``).
    abar : list of list
        Strictly lower-triangular :math:`\\bar a_{ij}` (position coupling).
    bbar, b : list
        Position and velocity weights of the propagated formula.
    bbar_hat, b_hat : list
        Position and velocity weights of the embedded formula.
    root : int or None
        ``r`` when entries are pairs ``(p, q)`` meaning ``p + q sqrt(r)``.
    fsal : bool
        Whether the last stage is the acceleration at ``(t + h, q_1)``.

    Examples
    --------
    >>> DPRKN6.stages, DPRKN6.order, DPRKN6.floats()["c"][-1]
    (6, 6, 1.0)
    """

    def __init__(self, name, order, order_embedded, c, abar, bbar, b, bbar_hat, b_hat, *,
                 root=None, fsal=True):
        self.name = name
        self.order = order
        self.order_embedded = order_embedded
        self.c, self.abar, self.bbar, self.b = c, abar, bbar, b
        self.bbar_hat, self.b_hat = bbar_hat, b_hat
        self.root = root
        self.fsal = fsal
        self.stages = len(c)

    def _float(self, x):
        if isinstance(x, tuple):
            with localcontext() as ctx:
                ctx.prec = 50
                p, q = x
                r = Decimal(self.root).sqrt()
                val = Decimal(p.numerator) / Decimal(p.denominator) + (
                    Decimal(q.numerator) / Decimal(q.denominator)) * r
                return float(val)
        return float(x)

    def floats(self):
        """The coefficients as floats (correctly rounded from 50 digits), in a dict."""
        f = self._float
        return {
            "c": [f(x) for x in self.c],
            "abar": [[f(x) for x in row] for row in self.abar],
            "bbar": [f(x) for x in self.bbar],
            "b": [f(x) for x in self.b],
            "bbar_hat": [f(x) for x in self.bbar_hat],
            "b_hat": [f(x) for x in self.b_hat],
        }


def _r(p, q=0):
    """``p + q sqrt(8581)`` for DPRKN6 (p, q given as Fractions or ints)."""
    return (F(p), F(q))


_Z = _r(0)

# DPRKN6: J. R. Dormand and P. J. Prince, "Runge-Kutta-Nystrom triples", Comput. Math. Appl.
# 13 (1987) 937-949, the 6(4) pair with FSAL. Exact values in Q(sqrt(8581)) transcribed from
# the DPRKN6 tableau of SciML/OrdinaryDiffEq.jl (lib/OrdinaryDiffEqRKN/src/rkn_tableaus.jl,
# `DPRKN6ConstantCache(T::Type, T2::Type)`), where R = sqrt(8581); checked by the order
# conditions in tests/ode/test_rkn.py. The embedded weights are b - btilde there.
_c6 = [_Z, _r(F(209, 900), F(-1, 900)), _r(F(209, 450), F(-1, 450)),
       _r(F(209, 450), F(1, 450)), _r(F(9, 10)), _r(1)]
_a41 = _r(F(980403512254, 11694469921875), F(7781688431, 11694469921875))
_a42 = _r(F(-1262884486208, 11694469921875), F(-15385481287, 11694469921875))
_a43 = _r(F(7166233891441, 46777879687500), F(78694563299, 46777879687500))
_a51 = _r(F(-9 * 329260, 27040000), F(-9 * 3181, 27040000))
_a52 = _r(F(27 * 35129, 13520000), F(27 * 3331, 13520000))
_a53 = _r(F(-27 * 554358343, 464060480000), F(-27 * 31040327, 464060480000))
_a54 = _r(F(153 * 8555257, 2745920000), F(-153 * 67973, 2745920000))
_b1 = _r(F(329, 4212))
_b3 = _r(F(84119543, 409622616), F(366727, 409622616))
_b4 = _r(F(84119543, 409622616), F(-366727, 409622616))
_b5 = _r(F(200, 17901))
_bp3 = _r(F(389225579, 1024056540), F(96856, 1024056540))
_bp4 = _r(F(389225579, 1024056540), F(-96856, 1024056540))
_bbar6 = [_b1, _Z, _b3, _b4, _b5, _Z]
_bv6 = [_b1, _Z, _bp3, _bp4, _r(F(2000, 17901)), _r(F(1, 20))]
# OrdinaryDiffEq's btilde / bptilde are b - b_hat:
_bt6 = [_r(F(329, 4212) - F(2701, 4563), F(-23, 4563)), _r(F(9829, 9126), F(131, 9126)),
        _r(F(84119543, 409622616) - F(5 * 1798, 9126), F(366727, 409622616) - F(5 * 17, 9126)),
        _b4, _b5, _Z]
_bpt6 = [_r(F(329, 4212) - F(115, 2106)), _Z,
         _r(F(389225579, 1024056540) - F(84119543, 256014135),
            F(96856, 1024056540) - F(366727, 256014135)),
         _r(F(389225579, 1024056540) - F(84119543, 256014135),
            F(-96856, 1024056540) + F(366727, 256014135)),
         _r(F(2000 - 6950, 17901)), _r(F(1, 20) + F(1, 10))]


def _sub(x, y):
    return (x[0] - y[0], x[1] - y[1])


#: The DPRKN6 6(4) pair (Dormand and Prince 1987), FSAL: 6 stages, 5 new evaluations a step.
DPRKN6 = RKNPair(
    "rkn64", 6, 4, _c6,
    [[_Z] * 6,
     [_r(F(26131, 810000), F(-209, 810000))] + [_Z] * 5,
     [_r(F(26131, 607500), F(-209, 607500)), _r(F(26131, 303750), F(-209, 303750))] + [_Z] * 4,
     [_a41, _a42, _a43] + [_Z] * 3,
     [_a51, _a52, _a53, _a54, _Z, _Z],
     [_b1, _Z, _b3, _b4, _b5, _Z]],
    _bbar6, _bv6,
    [_sub(x, y) for x, y in zip(_bbar6, _bt6, strict=True)],
    [_sub(x, y) for x, y in zip(_bv6, _bpt6, strict=True)],
    root=8581,
)


def _pair_from_table(name, order, order_embedded, tab):
    s = len(tab.C)
    frac = [F(*x) for x in tab.C]
    abar = [[F(*tab.ABAR.get(i, {}).get(j, (0, 1))) for j in range(s)] for i in range(s)]

    def vec(d):
        return [F(*d.get(i, (0, 1))) for i in range(s)]

    return RKNPair(name, order, order_embedded, frac, abar, vec(tab.BBAR), vec(tab.B),
                   vec(tab.BBAR_HAT), vec(tab.B_HAT), fsal=False)


#: The DPRKN12(10) pair (Dormand, El-Mikkawy and Prince 1987): 17 stages, not FSAL, so 17
#: evaluations per step (16 stages and the acceleration at the end point, the next step's
#: first stage); coefficients in :mod:`rigidmech.ode._rkn12_coefficients`.
DPRKN12 = _pair_from_table("rkn1210", 12, 10, _rkn12)


# ---------------------------------------------------------------------------------------------
# generated kernels


#: classical step-size controller: factor safety * err**(-1/(q+1)) clipped to [0.2, facmax]
#: (q the embedded order), no increase right after a rejection
_SAFETY, _FACMAX = 0.9, 5.0
#: per-pair (safety, facmax) where the default is not the best: for the 12(10) pair, whose error
#: varies as h^11, 0.9 and 5 reject 16-29 % of the steps on the benchmark problems
#: (benchmarks/work_precision.py); 0.6 and 3 reject 0-9 % and need 5-25 % fewer evaluations for
#: the same final error (measured on the pendulum and Kepler e = 0.6, 0.9 at errors 1e-6 to 1e-10)
_CONTROL = {"rkn1210": (0.6, 3.0)}


def _kernel(pair, d):
    unrolled = d <= FLOAT_PATH_MAX_D
    return make_rkn_stepper(pair, d, unrolled), unrolled


# ---------------------------------------------------------------------------------------------
# driver


def _check_common(fun, t_span, y0):
    """The checks of :func:`~rigidmech.ode.solve` (one set of rules), plus ``[q0, v0]``."""
    if not callable(fun):
        raise ArgumentTypeError(f"`fun` must be callable a(t, q); got {type(fun).__name__}.")
    t0, t1 = _check_t_span(t_span)
    y = _check_y0(y0)
    if y.ndim != 1 or y.shape[0] % 2:
        raise ArgumentError(
            f"`y0` must be [q0, v0] of even length n (no batch axis); got shape {y.shape}.")
    return t0, t1, y


def _tol_list(name, x, d):
    a = np.broadcast_to(np.asarray(x, dtype=float), (2 * d,)) if np.ndim(x) <= 1 and (
        np.ndim(x) == 0 or np.size(x) == 2 * d) else None
    if a is None or not np.all(np.isfinite(a)) or np.any(a < 0):
        raise ArgumentError(
            f"`{name}` must be a float >= 0 or an array of shape ({2 * d},); got {x!r}.")
    return a


def _dense_coeffs(h, q0, v0, a0, q1, v1, a1):
    """Power-form quintic Hermite coefficients of one step (see :func:`rkn64`, Notes)."""
    D = q1 - q0 - h * v0 - 0.5 * h * h * a0
    E = h * (v1 - v0) - h * h * a0
    G = h * h * (a1 - a0)
    c3 = 10.0 * D - 4.0 * E + 0.5 * G
    c4 = -15.0 * D + 7.0 * E - G
    c5 = 6.0 * D - 3.0 * E + 0.5 * G
    z = np.zeros_like(q0)
    return np.stack([
        np.concatenate([h * v0, h * a0]),
        np.concatenate([0.5 * h * h * a0, 3.0 * c3 / h]),
        np.concatenate([c3, 4.0 * c4 / h]),
        np.concatenate([c4, 5.0 * c5 / h]),
        np.concatenate([c5, z]),
    ])


def _run(pair, fun, t_span, y0, step, rtol, atol, first_step, max_step, max_steps,
         dense_output, events, t_eval=None, progress=None):
    t0, t1, y = _check_common(fun, t_span, y0)
    if t0 == t1:  # nothing to integrate: y0, as solve returns it
        return solve(fun, (t0, t1), y, method=pair.name, max_steps=max_steps)
    d = y.shape[0] // 2
    if isinstance(max_steps, bool) or not isinstance(max_steps, int | np.integer) or (
            max_steps < 1):
        raise ArgumentError(f"`max_steps` must be an int >= 1; got {max_steps!r}.")
    kern, unrolled = _kernel(pair, d)
    q = y[:d].copy()
    v = y[d:].copy()
    a = np.array(fun(t0, q.copy()), dtype=float)
    if a.shape != (d,):
        raise ArgumentError(
            f"`fun` must return the acceleration of shape ({d},); got shape {a.shape}.")
    if unrolled:
        q, v, a = q.tolist(), v.tolist(), a.tolist()
    if step is not None:  # constant step, no error control
        return _run_fixed(pair, fun, (t0, t1), y, step, max_steps, dense_output, events, kern,
                          unrolled, (q, v, a), progress)
    # rtol, atol, max_step and first_step were checked by ode.solve (the only way here)
    rtol, at, max_step = float(rtol), _tol_list("atol", atol, d), float(max_step)
    first_order = _FirstOrder(fun, d)
    if first_step is not None:
        first_step = min(abs(float(first_step)), abs(t1 - t0), max_step)
    run = Run(first_order, (t0, t1), y, rtol, at, first_step, max_step, max_steps,
              bool(dense_output), events, 0, "i", check_progress(progress),
              Stops(t_eval, (t0, t1)) if t_eval is not None else None)
    stepper = _RknStepper(pair, fun, d, kern, unrolled, rtol, at, (q, v, a))
    with np.errstate(over="ignore", invalid="ignore"):
        return integrate(stepper, run, np.concatenate([np.asarray(v, dtype=float),
                                                       np.asarray(a, dtype=float)]))


def _coeffs_of(h, qa, va, aa, qb, vb, ab):
    arr = np.asarray
    return lambda: _dense_coeffs(h, arr(qa), arr(va), arr(aa), arr(qb), arr(vb), arr(ab))


def _run_fixed(pair, fun, t_span, y, step, max_steps, dense_output, events, kern, unrolled,
               qva, progress=None):
    """The constant-step run (direct calls with ``step=h``): the 6th/12th-order formula
    without error control, on the fixed-step loop (:func:`~rigidmech.ode._fixed.fixed_loop`:
    finiteness, ``progress``, Ctrl-C), with the step rules of :func:`~rigidmech.ode.solve`;
    the quintic Hermite dense output; events located on it after the run, as ``solve`` does
    for the fixed-step methods."""
    t0, t1 = t_span
    h = _check_fixed_step(_registry.get(pair.name), step, t0, t1, max_steps)
    n = max(1, round((t1 - t0) / h))
    d, (q, v, a) = y.shape[0] // 2, qva
    dense = bool(dense_output) or events is not None
    rec = FixedRecorder(t0, y, np.concatenate([y[d:], np.asarray(a, dtype=float)]), 1, dense,
                        coefficients=lambda y0, y1, f0, f1, h: _dense_coeffs(
                            h, y0[:d], y0[d:], f0[d:], y1[:d], y1[d:], f1[d:]))

    def advance(t, h):
        nonlocal q, v, a
        q, v, a, _ = kern(fun, t, q, v, a, h, 0.0, None, None, False)
        if unrolled:
            return q + v, (v + a if dense else None)
        return np.concatenate([q, v]), (np.concatenate([v, a]) if dense else None)

    with np.errstate(over="ignore", invalid="ignore"):
        done = fixed_loop(advance, rec, t0, h, n, t1=t1, progress=check_progress(progress),
                          finite=_list_finite if unrolled else None)
    per_step = pair.stages - 1 if pair.fsal else pair.stages  # incl. the end-point call
    nfev = 1 + per_step * (done + (rec.status == -1))  # a non-finite step was made, not kept
    res = rec.result(pair.name, nfev, done, {"step": abs(h), "stages": pair.stages})
    if events is None:
        return res
    if not isinstance(events, EventTracker):
        events = EventTracker(events, t0, y.copy())
    res = fixed_events(res, y.shape, events, res.sol)
    return res if dense_output else dataclasses.replace(res, sol=None)


class _FirstOrder:
    """``y' = (v, a(t, q))``: the first-order form of ``q'' = a(t, q)``, for the starting step
    and the checks of the loop."""

    __slots__ = ("fun", "d")

    def __init__(self, fun, d):
        self.fun, self.d = fun, d

    def __call__(self, t, y):
        d = self.d
        return np.concatenate([y[d:], np.asarray(self.fun(t, y[:d].copy()), dtype=float)])


class _RknStepper:
    """A Runge-Kutta-Nystrom pair on the one loop: the generated step of the pair, its own
    controller (safety factor and growth limit of the pair, error accepted up to 1)."""

    def __init__(self, pair, fun, d, kern, unrolled, rtol, at, qva):
        self.pair, self.fun, self.d, self.kern, self.unrolled = pair, fun, d, kern, unrolled
        self.capabilities = Capabilities(pair.name, error_order=pair.order_embedded,
                                         order=pair.order, dense_order=5)
        self.start_order = pair.order
        self.controller = self
        self.rtol = rtol
        self.aq, self.av = (at[:d].tolist(), at[d:].tolist()) if unrolled else (at[:d], at[d:])
        self.expo = 1.0 / (pair.order_embedded + 1)
        self.safety, self.fmax = _CONTROL.get(pair.name, (_SAFETY, _FACMAX))
        self.per_step = pair.stages - 1 if pair.fsal else pair.stages  # incl. the end call
        self.inv2d = 1.0 / (2 * d)
        self.a = qva[2]
        self.nfev = self.nfev_per_attempt = 0

    def begin(self, prob, t0, y0, f0):
        return (y0.tolist() if self.unrolled else y0.copy()), self.a

    def _split(self, y):
        d = self.d
        return y[:d], y[d:]

    def attempt(self, t, y, a, h):
        q, v = self._split(y)
        q1, v1, a1, err2 = self.kern(self.fun, t, q, v, a, h, self.rtol, self.aq, self.av,
                                     True)
        self.nfev += self.per_step
        y1 = (q1 + v1) if self.unrolled else np.concatenate([q1, v1])
        return StepResult(y1, a1, math.sqrt(err2 * self.inv2d), (h, q, v, q1, v1))

    def next(self, err, h_abs, rejected):
        facmax = 1.0 if rejected else self.fmax
        if err <= 1.0:
            fac = facmax if err == 0.0 else min(facmax, max(0.2, self.safety * err**-self.expo))
            return h_abs * fac, True
        fac = 0.2 if not math.isfinite(err) else max(0.2, self.safety * err**-self.expo)
        return h_abs * fac, False

    def finite(self, step):
        return bool(np.all(np.isfinite(step.y)))

    def accept(self, step):
        self.a = step.f

    def hlamb(self, h_abs, step):
        return None

    def dense(self, t, y, h, step):
        hs, q, v, q1, v1 = step.data
        a0, a1, kern, fun = self.a, step.f, self.kern, self.fun

        def exact(s):
            self.nfev += self.per_step
            q_, v_, _, _ = kern(fun, t, q, v, a0, s - t, 0.0, None, None, False)
            return np.concatenate([np.asarray(q_, dtype=float), np.asarray(v_, dtype=float)])

        return (np.asarray(step.y, dtype=float), _coeffs_of(hs, q, v, a0, q1, v1, a1), exact)

    def stats(self):
        return {"stages": self.pair.stages}


def rkn64(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
          max_step=np.inf, max_steps=100_000, dense_output=False, events=None, t_eval=None,
          progress=None):
    r"""Dormand-Prince 6(4) Runge-Kutta-Nystrom pair for :math:`\ddot q = a(t, q)` (ch. 27).

    Parameters
    ----------
    fun : callable
        Acceleration ``a(t, q) -> ndarray of shape (d,)`` (it may return the same buffer at
        every call: it is copied).
    t_span : (float, float)
        ``(t0, t1)``; ``t1 < t0`` integrates backwards.
    y0 : array_like, shape (2 d,)
        ``[q0, v0]`` (no batch axis).
    step : float, optional
        Constant step (the 6th-order formula without error control). ``None`` (what
        :func:`~rigidmech.ode.solve` passes): adaptive step.
    rtol, atol : float (`atol` also array of shape ``(2 d,)``)
        Local error of the 4th-order embedded formula kept below ``atol + rtol |y|`` in
        Hairer's RMS norm over the ``2 d`` components of ``(q, v)``.
    first_step, max_step : float, optional
        First step (default: Hairer's estimate, one extra evaluation) and largest step.
    max_steps : int
        Largest number of accepted steps (status -1 beyond it); with `step`, refuse if more.
    dense_output : bool
        Fill ``result.sol`` (quintic Hermite, see Notes).
    events : EventTracker, optional
        As built by :func:`~rigidmech.ode.solve` (see :mod:`rigidmech.ode.events`); the event
        times located on the interpolant are refined on the method's own step from the start
        of the step to each trial time, so that they are as accurate as the steps.
    t_eval : array_like, optional
        Times the adaptive steps land on (the result still holds every step;
        :func:`~rigidmech.ode.solve` keeps those at `t_eval`), so that the samples are as
        accurate as the steps.
    progress : callable, optional
        ``progress(t)`` after every step; a returned False stops the run with status 2 and
        the steps made so far (as Ctrl-C does).

    Returns
    -------
    OdeResult
        ``y`` holds ``[q, v]`` at the accepted steps; ``nfev`` counts calls of `fun`.

    Raises
    ------
    ArgumentError, ArgumentTypeError
        On a bad `fun`, `t_span`, `y0`, tolerance, step or output shape of `fun`.

    Notes
    -----
    Six stages with FSAL (the last is :math:`a(t + h, q_1)`), so 5 evaluations per step; the
    propagated solution is of order 6 in ``q`` and ``v`` (local extrapolation), the error
    estimate that of the order-4 embedded formula; the step-size factor is
    :math:`0.9\,\mathrm{err}^{-1/5}` clipped to ``[0.2, 5]`` (no increase right after a
    rejection). Coefficients: Dormand and Prince, *Runge-Kutta-Nystrom triples*, Comput.
    Math. Appl. 13 (1987) 937-949 (exact, in :math:`\mathbb Q(\sqrt{8581})`, :data:`DPRKN6`).

    Dense output: on each step, the quintic Hermite polynomial through
    :math:`q, \dot q = v, \ddot q = a` at both ends (the end accelerations are the FSAL
    stages, so it costs no evaluation); ``q`` is interpolated with local error
    :math:`O(h^6)` and ``v`` (its derivative) with :math:`O(h^5)`.

    For ``d <= 8`` the step is generated once as unrolled plain-float code (no numpy call but
    the one wrapping each ``q`` handed to `fun`), as for the first-order pairs.

    Examples
    --------
    >>> import numpy as np
    >>> r = rkn64(lambda t, q: -q, (0.0, 2 * np.pi), [1.0, 0.0], rtol=1e-10, atol=1e-12)
    >>> bool(np.allclose(r.y[:, -1], [1.0, 0.0], atol=1e-9)), r.status
    (True, 0)
    """
    return _direct(DPRKN6, fun, t_span, y0, step, rtol, atol, first_step, max_step,
                   max_steps, dense_output, events, t_eval, progress)


def rkn1210(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
            max_step=np.inf, max_steps=100_000, dense_output=False, events=None, t_eval=None,
            progress=None):
    r"""Dormand-El-Mikkawy-Prince 12(10) Runge-Kutta-Nystrom pair for :math:`\ddot q = a(t, q)`.

    Parameters, returns and errors are those of :func:`rkn64`.

    Returns
    -------
    OdeResult

    Notes
    -----
    17 stages, 17 evaluations per step (the pair is not FSAL; the acceleration at the end
    point is the next step's first stage and the end value of the dense output). The
    propagated solution is of order 12, the error estimate that of the order-10 embedded
    formula (step factor :math:`0.6\,\mathrm{err}^{-1/11}` clipped to ``[0.2, 3]``: the
    safety factor 0.6 avoids most step rejections of this very high order).
    Coefficients: J. R. Dormand, M. E. A. El-Mikkawy and P. J. Prince, *High-order embedded
    Runge-Kutta-Nystrom formulae*, IMA J. Numer. Anal. 7 (1987) 423-430 (:data:`DPRKN12`).
    Meant for tight tolerances (``rtol`` 1e-8 and below) on smooth problems, where its long
    steps make it the cheapest method here.

    The dense output is the same quintic Hermite interpolant as :func:`rkn64` (``q`` to local
    error :math:`O(h^6)`, ``v`` to :math:`O(h^5)`), much less accurate than the steps
    themselves: locate events and sample ``sol`` with that in mind, or limit `max_step`.

    Examples
    --------
    >>> import numpy as np
    >>> r = rkn1210(lambda t, q: -q, (0.0, 2 * np.pi), [1.0, 0.0], rtol=1e-12, atol=1e-14)
    >>> bool(np.allclose(r.y[:, -1], [1.0, 0.0], atol=1e-12)), r.nsteps < 20
    (True, True)
    """
    return _direct(DPRKN12, fun, t_span, y0, step, rtol, atol, first_step, max_step,
                   max_steps, dense_output, events, t_eval, progress)


def _direct(pair, fun, t_span, y0, step, rtol, atol, first_step, max_step, max_steps,
            dense_output, events, t_eval, progress):
    """A direct call: through :func:`~rigidmech.ode.solve` (its checks, its rules) with error
    control; the constant step (`step`), which ``solve`` does not offer for these pairs, runs
    here after the same checks of ``t_span`` and ``y0``."""
    if step is None:
        if isinstance(events, EventTracker):  # built by the caller: its functions
            events = events.functions
        return solve(fun, t_span, y0, method=pair.name, rtol=rtol, atol=atol,
                     first_step=first_step, max_step=max_step, max_steps=max_steps,
                     dense_output=dense_output, events=events, t_eval=t_eval,
                     progress=progress)
    return _run(pair, fun, t_span, y0, step, rtol, atol, first_step, max_step, max_steps,
                dense_output, events, t_eval, progress)


def _solver(pair):
    def method(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
               max_step=np.inf, max_steps=100_000, dense_output=False, events=None,
               t_eval=None, progress=None):
        return _run(pair, fun, t_span, y0, step, rtol, atol, first_step, max_step, max_steps,
                    dense_output, events, t_eval, progress)

    method.__name__ = method.__qualname__ = pair.name
    method.__doc__ = (f"The {pair.name} pair as called by :func:`~rigidmech.ode.solve` "
                      "(``progress`` as for :func:`~rigidmech.ode.adaptive.dopri5`).")
    return method


register("rkn64", _solver(DPRKN6), kind="adaptive_second_order",
         capabilities=("t_eval_at_steps",))
register("rkn1210", _solver(DPRKN12), kind="adaptive_second_order",
         capabilities=("t_eval_at_steps",))
