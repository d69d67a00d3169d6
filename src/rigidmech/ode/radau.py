"""Radau IIA of order 5 for stiff systems, with simplified Newton iterations (book, ch. 26).

Stiff equations of motion (stiff springs, strongly damped modes, Van der Pol oscillators with a
large parameter) force an explicit method to steps at the border of its stability domain, far
below what accuracy needs. The three-stage Radau IIA collocation method is L-stable and of
order 5; this implementation follows Hairer and Wanner, *Solving ODEs II*, Sec. IV.8 (code
RADAU5) as also done by scipy's ``Radau``:

* the stage equations are solved by simplified Newton iterations, with the Jacobian
  transformed by the eigen-decomposition of the Radau matrix into one real and one complex
  linear system; the Jacobian is reused across steps while Newton converges fast;
* the error is estimated with the embedded third-order formula (filtered by the iteration
  matrix) and the step predicted with Gustafsson's controller;
* the dense output is the collocation polynomial (order 3 in ``x``).

The Jacobian is ``jac(t, y)`` when given (shape ``(n, n)``, or ``(batch, n, n)`` for a batch)
or finite differences (``n`` evaluations of ``fun``, perturbing one component of every
trajectory of a batch at once). Linear systems use the inverses of the iteration matrices,
batched over trajectories.
"""

from __future__ import annotations

import math

import numpy as np

from rigidmech._core.errors import ArgumentError, ArgumentTypeError

from . import _registry
from ._driver import Problem, Recorder, initial_step

__all__ = ["radau"]

_S6 = 6**0.5
C = np.array([(4 - _S6) / 10, (4 + _S6) / 10, 1.0])
E = np.array([-13 - 7 * _S6, -13 + 7 * _S6, -1.0]) / 3
MU_REAL = 3 + 3 ** (2 / 3) - 3 ** (1 / 3)
MU_COMPLEX = 3 + 0.5 * (3 ** (1 / 3) - 3 ** (2 / 3)) - 0.5j * (3 ** (5 / 6) + 3 ** (7 / 6))
# T and its inverse: A = T diag(mu) T^-1 (values from scipy.integrate._ivp.radau).
T = np.array([
    [0.09443876248897524, -0.14125529502095421, 0.03002919410514742],
    [0.25021312296533332, 0.20412935229379994, -0.38294211275726192],
    [1.0, 1.0, 0.0]])
TI = np.array([
    [4.17871859155190428, 0.32768282076106237, 0.52337644549944951],
    [-4.17871859155190428, -0.32768282076106237, 0.47662355450055044],
    [0.50287263494578682, -2.57192694985560522, 0.59603920482822492]])
TI_REAL = TI[0]
TI_COMPLEX = TI[1] + 1j * TI[2]
# Collocation polynomial: y(x) = y0 + sum_k (P^T Z)[k] x^(k+1).
P = np.array([
    [13 / 3 + 7 * _S6 / 3, -23 / 3 - 22 * _S6 / 3, 10 / 3 + 5 * _S6],
    [13 / 3 - 7 * _S6 / 3, -23 / 3 + 22 * _S6 / 3, 10 / 3 - 5 * _S6],
    [1 / 3, -8 / 3, 10 / 3]])
NEWTON_MAXITER = 6
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
_EPS = np.finfo(float).eps
_SQRT_EPS = _EPS**0.5


class _Linear:
    """Batched linear algebra on flat states: shape (N,) viewed as (batch, n)."""

    def __init__(self, shape):
        self.n = shape[0]
        self.b = shape[1] if len(shape) == 2 else 1
        self.batch = len(shape) == 2

    def stack(self, v):  # flat (N,) -> (b, n, 1)
        return (v.reshape(self.n, self.b).T if self.batch else v[None])[..., None]

    def flat(self, w):  # (b, n, 1) -> flat (N,)
        w = w[..., 0]
        return np.ascontiguousarray(w.T).reshape(-1) if self.batch else w[0]

    def solve(self, Minv, v):
        return self.flat(Minv @ self.stack(v))


def _finite_difference_jac(prob, lin, t, y, f, atol):
    """Forward differences, each component perturbed by ``sqrt(eps) max(|y_j|, atol_j)``.

    The perturbation follows the scale of ``y`` (as scipy's ``num_jac``, with `atol` as the
    threshold below which ``|y_j|`` counts as zero), so that the Jacobian of ``s u(t)`` is that
    of ``u(t)`` for any scale ``s``: neither lost below the resolution of ``y`` (``|y| >=
    1e17``) nor far too large (``|y| ~ 1e-20``).
    """
    n, b = lin.n, lin.b
    J = np.empty((b, n, n))
    Y = y.reshape(n, b) if lin.batch else y[:, None]
    floor = np.broadcast_to(np.asarray(atol, dtype=float).reshape(-1), (y.size,))
    floor = floor.reshape(n, b) if lin.batch else floor[:, None]
    out = np.empty_like(y)
    for j in range(n):
        d = _SQRT_EPS * np.maximum(np.abs(Y[j]), floor[j])
        d[d == 0.0] = _SQRT_EPS
        yp = Y.copy()
        yp[j] += d
        d = yp[j] - Y[j]  # the perturbation actually represented
        prob(t, yp.reshape(-1) if lin.batch else yp[:, 0], out)
        df = (out.reshape(n, b) if lin.batch else out[:, None]) - (
            f.reshape(n, b) if lin.batch else f[:, None])
        J[:, :, j] = (df / d).T
    return J


def _user_jac(jac, lin, t, y, shape):
    J = np.array(jac(t, y.reshape(shape)), dtype=float)
    want = (lin.b, lin.n, lin.n) if lin.batch else (lin.n, lin.n)
    if J.shape != want:
        raise ArgumentError(f"`jac(t, y)` must return an array of shape {want}; got {J.shape}.")
    return J if lin.batch else J[None]


def radau(fun, t_span, y0, *, step=None, rtol=1e-6, atol=1e-9, first_step=None,
          max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None, jac=None):
    """Radau IIA (order 5) with error control and dense output, for stiff systems.

    Called through :func:`rigidmech.ode.solve` (``method="radau"``), which validates the
    common arguments. `jac` is an optional callable ``jac(t, y)`` returning ``df/dy`` of
    shape ``(n, n)`` (``(batch, n, n)`` for a batch); finite differences are used otherwise.
    ``stats`` reports ``njev`` (Jacobians) and ``nlu`` (factorised iteration matrices).

    Returns
    -------
    OdeResult

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> lam = 1000.0      # y' = -lam (y - cos t): y follows cos t after a fast transient
    >>> stiff = lambda t, y: -lam * (y - np.cos(t))
    >>> r = ode.solve(stiff, (0.0, 10.0), [0.0], method="radau", rtol=1e-8, atol=1e-12)
    >>> exact = (lam**2 * np.cos(10.0) + lam * np.sin(10.0)) / (lam**2 + 1)
    >>> bool(abs(r.y[0, -1] - exact) < 1e-8), r.nsteps < 400
    (True, True)
    """
    if jac is not None and not callable(jac):
        raise ArgumentTypeError(f"`jac` must be a callable jac(t, y) or None; got {jac!r}.")
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        return _radau(fun, t_span, y0, rtol=rtol, atol=atol, first_step=first_step,
                      max_step=max_step, max_steps=max_steps, dense_output=dense_output,
                      events=events, jac=jac)


def _radau(fun, t_span, y0, *, rtol, atol, first_step, max_step, max_steps, dense_output,
           events, jac):
    t0, t_end = t_span
    direction = 1.0 if t_end > t0 else -1.0
    shape = y0.shape
    prob = Problem(fun, shape)
    lin = _Linear(shape)
    y = y0.reshape(-1).copy()
    N = y.size
    rec = Recorder(t0, y, shape, dense_output, events, "power")
    f = prob(t0, y, np.empty(N))
    if not np.isfinite(f).all():
        rec.fail("The right-hand side is not finite", t0, y)
        return rec.result("radau", prob.nfev, 0)
    newton_tol = max(10 * _EPS / rtol, min(0.03, rtol**0.5))
    if first_step is None:
        h_abs = initial_step(prob, t0, y, f, direction, 3, rtol, atol, t_end, max_step)
    else:
        h_abs = first_step
    h_abs_old = err_old = None
    njev = nlu = nrej = naccpt = 0

    def jacobian(t, y, f):
        nonlocal njev
        njev += 1
        if jac is not None:
            return _user_jac(jac, lin, t, y, shape)
        return _finite_difference_jac(prob, lin, t, y, f, atol)

    J = jacobian(t0, y, f)
    current_jac = True
    eye = np.eye(lin.n)
    Minv_r = Minv_c = None
    Zprev = None  # collocation values of the previous step, for the predictor
    h_prev = None
    t = t0
    F = np.empty((3, N))
    while direction * (t - t_end) < 0:
        if naccpt >= max_steps:
            rec.fail(f"The maximum number of steps `max_steps` = {max_steps} was reached", t, y)
            break
        min_step = 10 * abs(math.nextafter(t, direction * math.inf) - t)
        if h_abs > max_step:
            h_abs, h_abs_old, err_old = max_step, None, None
        elif h_abs < min_step:
            h_abs, h_abs_old, err_old = min_step, None, None
        rejected = accepted = False
        while h_abs >= min_step:
            h = h_abs * direction
            t_new = t + h
            if direction * (t_new - t_end) > 0:
                t_new = t_end
            h = t_new - t
            h_abs = abs(h)
            if Zprev is None:
                Z0 = np.zeros((3, N))
            else:  # extrapolate the previous collocation polynomial
                x = 1.0 + C * (h / h_prev)
                Q = P.T @ Zprev  # (3, N)
                Z0 = (x[:, None] * Q[0] + (x**2)[:, None] * Q[1] + (x**3)[:, None] * Q[2]
                      - Zprev[-1])
            scale = atol + np.abs(y) * rtol
            converged = False
            while not converged:
                if Minv_r is None:
                    Minv_r = np.linalg.inv(MU_REAL / h * eye - J)
                    Minv_c = np.linalg.inv(MU_COMPLEX / h * eye - J)
                    nlu += 1
                converged, n_iter, Z, rate = _newton(prob, lin, t, y, h, Z0, scale, newton_tol,
                                                     Minv_r, Minv_c, F)
                if not converged:
                    if current_jac:
                        break
                    J = jacobian(t, y, f)
                    current_jac = True
                    Minv_r = Minv_c = None
            if not converged:
                h_abs *= 0.5
                Minv_r = Minv_c = None
                nrej += 1
                continue
            y_new = y + Z[-1]
            ZE = (E @ Z) / h
            error = lin.solve(Minv_r, f + ZE).real
            scale = atol + np.maximum(np.abs(y), np.abs(y_new)) * rtol
            err = prob.norm(error / scale)
            safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + n_iter)
            if rejected and err > 1:
                error = lin.solve(Minv_r, prob(t, y + error, np.empty(N)) + ZE).real
                err = prob.norm(error / scale)
            if not err <= 1:
                factor = _predict(h_abs, h_abs_old, err, err_old) if err == err else 0.0
                h_abs *= max(MIN_FACTOR, safety * factor)
                Minv_r = Minv_c = None
                rejected = True
                nrej += 1
            else:
                accepted = True
                break
        if not accepted:
            rec.fail("The step size fell below the resolution of t (step size underflow)", t, y)
            break
        naccpt += 1
        recompute_jac = n_iter > 2 and rate > 1e-3
        factor = min(MAX_FACTOR, safety * _predict(h_abs, h_abs_old, err, err_old))
        if not recompute_jac and factor < 1.2:
            factor = 1.0
        else:
            Minv_r = Minv_c = None
        f_new = prob(t_new, y_new, np.empty(N))
        if recompute_jac:
            J = jacobian(t_new, y_new, f_new)
            current_jac = True
        else:
            current_jac = False
        h_abs_old, err_old = h_abs, err
        coeffs = (P.T @ Z) if (rec.cs is not None or events is not None) else None
        stop = rec.accept(t_new, y_new, coeffs)
        Zprev, h_prev = Z, h
        h_abs *= factor
        t, y, f = t_new, y_new, f_new
        if not np.isfinite(y).all():  # pragma: no cover - the error test rejects these
            rec.fail("The state became non-finite", t, y)
            break
        if stop:
            break
    return rec.result("radau", prob.nfev, nrej, {"njev": njev, "nlu": nlu})


def _predict(h_abs, h_abs_old, err, err_old):
    """Gustafsson's predictive step-size factor (HNW II, IV.8, eq. (8.25))."""
    if err == 0:  # an exact step (y' = 1, free fall): grow as much as allowed
        return MAX_FACTOR
    if err_old is None or h_abs_old is None:
        mult = 1.0
    else:
        mult = h_abs / h_abs_old * (err_old / err) ** 0.25
    with np.errstate(divide="ignore"):
        return min(1.0, mult) * err**-0.25


def _newton(prob, lin, t, y, h, Z0, scale, tol, Minv_r, Minv_c, F):
    """Simplified Newton iterations for the collocation system (HNW II, IV.8)."""
    M_real = MU_REAL / h
    M_complex = MU_COMPLEX / h
    W = TI @ Z0
    Z = Z0
    ch = h * C
    dW = np.empty_like(W)
    dW_norm_old = None
    rate = None
    converged = False
    k = 0
    for k in range(NEWTON_MAXITER):  # noqa: B007
        for i in range(3):
            prob(t + ch[i], y + Z[i], F[i])
        if not np.isfinite(F).all():
            break
        f_real = TI_REAL @ F - M_real * W[0]
        f_complex = TI_COMPLEX @ F - M_complex * (W[1] + 1j * W[2])
        dW[0] = lin.solve(Minv_r, f_real).real
        dWc = lin.solve(Minv_c, f_complex)
        dW[1] = dWc.real
        dW[2] = dWc.imag
        x = dW / scale
        dW_norm = prob.norm(np.sqrt(np.sum(x * x, axis=0) / 3.0))
        if dW_norm_old is not None:
            rate = dW_norm / dW_norm_old
        if rate is not None and (rate >= 1 or rate ** (NEWTON_MAXITER - k) / (1 - rate)
                                 * dW_norm > tol):
            break
        W += dW
        Z = T @ W
        if dW_norm == 0 or (rate is not None and rate / (1 - rate) * dW_norm < tol):
            converged = True
            break
        dW_norm_old = dW_norm
    return converged, k + 1, Z, rate


_registry.register("radau", radau, kind="stiff")
