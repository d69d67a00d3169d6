"""Tables of the adaptive Adams method (:mod:`rigidmech.ode.adams`, book 26.3): its constants,
the Adams coefficients, the backward-difference matrices, the re-sampling and re-interpolation
of the differences at a new step size, and the dense-output polynomial of a step.

Private: :mod:`rigidmech.ode.adams` re-exports :func:`resample_matrix` and :data:`MAX_ORDER`
(documented there) and the other names it uses.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from .multistep import adams_gamma

#: Highest order of the Adams formulas used (as in DE/STEP: beyond it the stability region of
#: the PECE pair becomes too small to gain anything).
MAX_ORDER = 12

#: Up to this order the step may be doubled before the known values of f reach back over 2k
#: steps (the interpolation polynomial is then extrapolated backwards); above it, the doubling
#: waits for them.
RESAMPLE_DOUBLING_MAX_ORDER = 4

#: Number of past values of f (with their times) kept for changes of the step size.
HISTORY = 4 * MAX_ORDER + 1

#: Stiffness test (see :func:`adams`): only steps of order <= STIFF_MAX_ORDER are examined
#: (stiffness drives an Adams code to low orders, as Shampine and Gordon's DE uses), against
#: 0.8 times the real stability interval of the PECE pair of order k (k = 1 .. 4), the roots
#: of its step on y' = lambda y (recomputed in the tests).
STIFF_MAX_ORDER = 4
#: ... and only steps whose error estimate is at least this fraction of the tolerance: below,
#: the difference of the two evaluations is mostly rounding and h rho means nothing.
STIFF_MIN_ESTIMATE = 1e-3
_PECE_REAL_INTERVAL = {1: 2.0, 2: 2.4, 3: 1.935, 4: 1.411}
_STIFF_BORDER = {k: 0.8 * v for k, v in _PECE_REAL_INTERVAL.items()}

#: gamma_j of Adams-Bashforth and |gamma*_j| of Adams-Moulton, j = 0 .. MAX_ORDER + 1
_G = [float(adams_gamma(j)) for j in range(MAX_ORDER + 2)]
_GS = [abs(float(adams_gamma(j, implicit=True))) for j in range(MAX_ORDER + 2)]


def _backward_difference_matrix(m):
    """``Delta`` with ``Delta @ [v_0, v_1, ..., v_m] = [nabla^0 v_0, ..., nabla^m v_0]``."""
    D = np.zeros((m + 1, m + 1))
    for j in range(m + 1):
        for i in range(j + 1):
            D[j, i] = (-1) ** i * math.comb(j, i)
    return D


_DELTA = [_backward_difference_matrix(m) for m in range(MAX_ORDER + 2)]


def resample_matrix(m: int, ratio: float) -> np.ndarray:
    r"""Map the backward differences at spacing :math:`h` to those at spacing ``ratio * h``.

    The differences :math:`\nabla^j f_n` (:math:`j = 0, \dots, m`) define Newton's backward
    interpolation polynomial (book, 26.3.2)

    .. math:: P(t_n + s h) = \sum_{j=0}^{m}\binom{s + j - 1}{j}\nabla^j f_n ;

    sampled at :math:`t_n - i\,r h` (:math:`i = 0, \dots, m`) it gives new values whose backward
    differences are the new :math:`\nabla^j f_n`. The map is linear; this is its matrix.

    Parameters
    ----------
    m : int
        Highest difference, ``0 <= m <= MAX_ORDER + 1``.
    ratio : float
        New step over old step, ``> 0``.

    Returns
    -------
    ndarray, shape (m + 1, m + 1)

    Examples
    --------
    >>> import numpy as np
    >>> f = lambda t: 1.0 + 2.0 * t + 3.0 * t**2          # degree 2: resampling is exact
    >>> def diffs(h):
    ...     v = np.array([f(-i * h) for i in range(3)])
    ...     return np.array([v[0], v[0] - v[1], v[0] - 2 * v[1] + v[2]])
    >>> bool(np.allclose(resample_matrix(2, 0.5) @ diffs(0.2), diffs(0.1)))
    True
    """
    s = -ratio * np.arange(m + 1, dtype=float)
    B = np.ones((m + 1, m + 1))
    for j in range(1, m + 1):  # binom(s + j - 1, j) = binom(s + j - 2, j - 1) (s + j - 1) / j
        B[:, j] = B[:, j - 1] * (s + (j - 1)) / j
    return _DELTA[m] @ B


_REINTERP = {}
_REINTERP_MAX = 4096  # cached matrices (the patterns of past times repeat: ratios are few)


def _reinterpolation_matrix(T, k, h_new):
    """Differences on the grid ``T[-1] - i h_new`` (i = 0..k) from values at past times.

    `T` holds the times of the known values of f, oldest first (the last is the current
    point; at least k + 1 of them). Chosen: the last k + 1 when they reach back over the new
    span (a reduction), else, walking back, for each grid node the nearest older time (a
    doubling). Returns ``(M, idx)``: the backward differences on the grid are ``M @ f[idx]``
    (negative indices into `T`), ``M = Delta_k L`` with ``L`` Lagrange's interpolation matrix
    from the chosen times to the grid (exact on polynomials of degree k; its first row is
    ``e_0``: the current value is kept). Matrices are cached by the chosen times relative to
    the grid, which repeat along an integration.
    """
    m = len(T)
    tn = T[-1]
    span = k * abs(h_new)
    if m >= k + 1 and abs(tn - T[-k - 1]) >= span * (1.0 - 1e-12):
        idx = list(range(-1, -k - 2, -1))
    else:  # walk back: for each node the nearest older time, leaving enough for the rest
        idx = [-1]
        j = -1
        for i in range(1, k + 1):
            node = tn - i * h_new
            j -= 1
            lowest = -m + (k - i)
            while j > lowest and abs(T[j - 1] - node) <= abs(T[j] - node):
                j -= 1
            idx.append(j)
    u = [(T[j] - tn) / h_new for j in idx]  # chosen times, in new steps from the current one
    key = (k, *(round(x, 12) for x in u))
    M = _REINTERP.get(key)
    if M is None:
        n1 = k + 1
        ua = np.array(key[1:])  # from the key: the matrix depends on it alone
        du = ua[:, None] - ua[None, :]
        du.flat[:: n1 + 1] = 1.0
        w = 1.0 / du.prod(axis=1)  # barycentric weights
        # L[i, j] = w_j prod_{m != j} (v_i - u_m) at v_i = -i, by prefix and suffix products
        # (no division: exact where a grid node falls on a known time)
        dv = -np.arange(n1, dtype=float)[:, None] - ua[None, :]
        pre = np.ones((n1, n1 + 1))
        suf = np.ones((n1, n1 + 1))
        np.cumprod(dv, axis=1, out=pre[:, 1:])
        np.cumprod(dv[:, ::-1], axis=1, out=suf[:, 1:])
        L = pre[:, :-1] * suf[:, -2::-1] * w
        L[0] = 0.0  # the grid starts at the current point: its value is kept, bit for bit
        L[0, 0] = 1.0
        M = _DELTA[k] @ L
        if len(_REINTERP) >= _REINTERP_MAX:
            _REINTERP.clear()
        _REINTERP[key] = M
    return M, idx


def _dense_table():
    """``C[j]``: power coefficients in x (x**1 .. x**(j+1)) of ``c_j(x - 1) - c_j(-1)``.

    ``c_j(theta) = int_0^theta binom(s + j - 1, j) ds``, so that over the step ending at
    ``t_{n+1}``, ``y(t_{n+1} + theta h) = y_{n+1} + h sum_j c_j(theta) nabla^j f_{n+1}``
    (``theta`` in [-1, 0], ``x = theta + 1``).
    """
    table = []
    for j in range(MAX_ORDER + 2):
        p = [Fraction(1)]  # binom(s + j - 1, j) as a polynomial in s, ascending
        for i in range(j):
            q = [Fraction(0)] * (len(p) + 1)
            for d, a in enumerate(p):
                q[d] += a * i
                q[d + 1] += a
            p = q
        p = [a / math.factorial(j) for a in p]
        c = [Fraction(0)] + [a / (d + 1) for d, a in enumerate(p)]  # integral from 0
        # substitute theta = x - 1: sum_d c_d (x - 1)^d
        out = [Fraction(0)] * len(c)
        for d, a in enumerate(c):
            for e in range(d + 1):
                out[e] += a * math.comb(d, e) * (-1) ** (d - e)
        table.append(np.array([float(a) for a in out[1:]]))  # drop the constant term
    return table


_DENSE = _dense_table()


def _dense_coefficients(y_old, y_new, D, k, h):
    """Power-form coefficients ``Q`` (``y(x) = y_old + sum_m Q[m] x**(m+1)``) of one step."""
    Q = np.zeros((MAX_ORDER + 1, y_old.size))  # one shape for every step, whatever k
    for j in range(k + 1):
        Q[: j + 1] += np.multiply.outer(_DENSE[j], h * D[j])
    # the integrated polynomial anchored at y_new, moved to pass through y_old at x = 0:
    # y(x) = y_old + x (y_new - y_old - sum(Q)) + sum_m Q[m] x^(m+1)
    Q[0] += (y_new - y_old) - Q.sum(axis=0)
    return Q


def _lazy_dense(y_old, y_new, D, k, h):
    """A zero-argument callable computing :func:`_dense_coefficients` when needed."""
    return lambda: _dense_coefficients(y_old, y_new, D, k, h)


#: cache of re-sampling matrices for the usual ratios: 0.25, 0.5 ... 0.9, 2 (the ratios of a
#: reduction are rounded down to tenths for that); other ratios (the last step) are not kept
_RESAMPLE = {}
_USUAL_RATIOS = frozenset([0.25, 0.5, 0.6, 0.7, 0.8, 0.9, 2.0])


def _resample_cached(k, ratio):
    if ratio not in _USUAL_RATIOS:
        return resample_matrix(k, ratio)
    T = _RESAMPLE.get((k, ratio))
    if T is None:
        T = _RESAMPLE[(k, ratio)] = resample_matrix(k, ratio)
    return T
