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
from ._driver import Stops
from ._loop import Capabilities, Run, StepResult, check_progress, integrate

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
          max_step=math.inf, max_steps=1_000_000, dense_output=False, events=None, jac=None,
          progress=None, t_eval=None):
    """Radau IIA (order 5) with error control and dense output, for stiff systems.

    Called through :func:`rigidmech.ode.solve` (``method="radau"``), which validates the
    common arguments. `jac` is an optional callable ``jac(t, y)`` returning ``df/dy`` of
    shape ``(n, n)`` (``(batch, n, n)`` for a batch); finite differences are used otherwise.
    ``stats`` reports ``njev`` (Jacobians) and ``nlu`` (factorised iteration matrices).
    `progress` as for :func:`~rigidmech.ode.adaptive.dopri5`. With `t_eval` (passed by
    :func:`~rigidmech.ode.solve`) the steps land on those times and only the states there
    are kept: the samples are as accurate as the steps (the dense output, the order-3
    collocation polynomial, is not used for them) and the memory is proportional to the
    samples, not to the steps.

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
    run = Run(fun, t_span, y0, rtol, atol, first_step, max_step, max_steps, dense_output,
              events, 0, "i", check_progress(progress),
              Stops(t_eval, t_span) if t_eval is not None else None, t_eval)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # failures -> status
        return integrate(_RadauStepper(jac, y0.shape, rtol, atol, max_step), run)


_CAPS = Capabilities("radau", error_order=3, order=5, dense_order=3)


class _RadauStepper:
    """Radau IIA on the one loop: an attempt solves the collocation system by simplified
    Newton iterations and estimates the error; the step is chosen by Gustafsson's predictive
    controller (its own ``controller``), with the Jacobian and the factorisations reused
    while Newton converges fast (HNW II, IV.8)."""

    def __init__(self, jac, shape, rtol, atol, max_step):
        self.capabilities, self.controller = _CAPS, self
        self.jac, self.shape, self.rtol, self.atol, self.max_step = jac, shape, rtol, atol, \
            max_step
        self.start_order = 3
        self.lin = _Linear(shape)
        self.newton_tol = max(10 * _EPS / rtol, min(0.03, rtol**0.5))
        self.njev = self.nlu = self.nfev = self.nfev_per_attempt = 0
        self.h_abs_old = self.err_old = self.h_next = None
        self.Minv_r = self.Minv_c = self.Zprev = self.h_prev = None
        self.rejected = False  # an error rejection in this step (not a Newton failure)

    def _jacobian(self, t, y, f):
        self.njev += 1
        self.current_jac = True
        if self.jac is not None:
            return _user_jac(self.jac, self.lin, t, y, self.shape)
        return _finite_difference_jac(self.prob, self.lin, t, y, f, self.atol)

    def begin(self, prob, t0, y0, f0):
        self.prob, self.f, self.eye = prob, f0, np.eye(self.lin.n)
        self.F = np.empty((3, y0.size))
        self.J = self._jacobian(t0, y0, f0)
        return y0, f0

    def restart(self, prob, t, y, f):
        """After a projection of the state (a move of the order of the tolerance, see
        :func:`rigidmech.ode.solve`'s ``project``): the derivative at the projected state,
        the Jacobian and its factorisations kept (formed again, as after any step, when
        Newton converges slowly or fails)."""
        self.f, self.current_jac = f, False
        return y, f

    def _predictor(self, h, size):
        if self.Zprev is None:
            return np.zeros((3, size))
        x = 1.0 + C * (h / self.h_prev)  # extrapolate the previous collocation polynomial
        Q = P.T @ self.Zprev  # (3, N)
        return (x[:, None] * Q[0] + (x**2)[:, None] * Q[1] + (x**3)[:, None] * Q[2]
                - self.Zprev[-1])

    def _newton(self, t, y, h):
        """Newton on the collocation system, with a fresh Jacobian once if it fails."""
        Z0, scale = self._predictor(h, y.size), self.atol + np.abs(y) * self.rtol
        while True:
            if self.Minv_r is None:
                self.Minv_r = np.linalg.inv(MU_REAL / h * self.eye - self.J)
                self.Minv_c = np.linalg.inv(MU_COMPLEX / h * self.eye - self.J)
                self.nlu += 1
            out = _newton(self.prob, self.lin, t, y, h, Z0, scale, self.newton_tol,
                          self.Minv_r, self.Minv_c, self.F)
            if out[0] or self.current_jac:
                return out
            self.J = self._jacobian(t, y, self.f)
            self.Minv_r = self.Minv_c = None

    def attempt(self, t, y, f, h):
        if self.h_next is not None and self.h_next > self.max_step:  # clamped by max_step
            self.h_abs_old = self.err_old = None
        converged, n_iter, Z, rate = self._newton(t, y, h)
        if not converged:
            self._last_data = "newton"
            return StepResult(None, None, math.nan, "newton")
        lin, prob, N = self.lin, self.prob, y.size
        y_new = y + Z[-1]
        ZE = (E @ Z) / h
        error = lin.solve(self.Minv_r, self.f + ZE).real
        scale = self.atol + np.maximum(np.abs(y), np.abs(y_new)) * self.rtol
        err = prob.norm(error / scale)
        if self.rejected and err > 1:
            error = lin.solve(self.Minv_r, prob(t, y + error, np.empty(N)) + ZE).real
            err = prob.norm(error / scale)
        safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + n_iter)
        self._last_data = (t + h, h, Z, n_iter, rate, safety)
        return StepResult(y_new, None, err, self._last_data)

    def next(self, err, h_abs, rejected):
        step_data = self._last_data
        if step_data == "newton":  # Newton failed: halve the step, new factorisations
            self.Minv_r = self.Minv_c = None
            self.h_next = h_abs * 0.5
            return self.h_next, False
        safety = step_data[5]
        if not err <= 1:
            factor = _predict(h_abs, self.h_abs_old, err, self.err_old) if err == err else 0.0
            self.Minv_r = self.Minv_c = None
            self.rejected = True
            self.h_next = h_abs * max(MIN_FACTOR, safety * factor)
            return self.h_next, False
        n_iter, rate = step_data[3], step_data[4]
        self.recompute_jac = n_iter > 2 and rate > 1e-3
        factor = min(MAX_FACTOR, safety * _predict(h_abs, self.h_abs_old, err, self.err_old))
        if not self.recompute_jac and factor < 1.2:
            factor = 1.0
        else:
            self.Minv_r = self.Minv_c = None
        self.h_abs_old, self.err_old = h_abs, err
        self.h_next = h_abs * factor
        return self.h_next, True

    def finite(self, step):
        return bool(np.isfinite(step.y).all())

    def accept(self, step):
        t_new, h, Z = step.data[0], step.data[1], step.data[2]
        self.f = self.prob(t_new, step.y, np.empty(step.y.size))
        if self.recompute_jac:
            self.J = self._jacobian(t_new, step.y, self.f)
        else:
            self.current_jac = False
        self.Zprev, self.h_prev, self.rejected = Z, h, False

    def hlamb(self, h_abs, step):
        return None

    def dense(self, t, y, h, step):
        return step.y, P.T @ step.data[2], None

    def stats(self):
        return {"njev": self.njev, "nlu": self.nlu}


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


_registry.register("radau", radau, kind="stiff", capabilities=("t_eval", "t_eval_at_steps"))
