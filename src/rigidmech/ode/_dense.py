"""Dense output: the continuous solution ``sol(t)`` built from the accepted steps (ch. 26).

One class, :class:`DenseSolution`, holds the breakpoints and, for every step, the coefficients of
a local polynomial in ``x = (t - t_i) / h_i``, in one of two forms:

``"power"``
    ``y(x) = y_i + sum_k Q[k] x**(k + 1)`` (Dormand-Prince 5(4) after Shampine, cubic Hermite,
    Radau IIA collocation polynomial);
``"nested"``
    DOP853's form ``y(x) = y_i + x (F0 + (1 - x)(F1 + x (F2 + (1 - x)(F3 + ...))))``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["DenseSolution", "hermite_coefficients", "evaluate"]


def hermite_coefficients(y0, y1, f0, f1, h):
    """Power-form coefficients of the cubic Hermite interpolant on one step.

    Parameters
    ----------
    y0, y1, f0, f1 : ndarray, shape (N,)
        States and derivatives at both ends of the step.
    h : float
        Step size.

    Returns
    -------
    ndarray, shape (3, N)
        ``Q`` such that ``y(x) = y0 + Q[0] x + Q[1] x**2 + Q[2] x**3``.

    Examples
    --------
    >>> import numpy as np
    >>> Q = hermite_coefficients(np.zeros(1), np.ones(1), np.ones(1), np.ones(1), 1.0)
    >>> Q.ravel().tolist()
    [1.0, 0.0, 0.0]
    """
    dy = y1 - y0
    hf0, hf1 = h * f0, h * f1
    return np.stack([hf0, 3.0 * dy - 2.0 * hf0 - hf1, hf0 + hf1 - 2.0 * dy])


class DenseSolution:
    """Continuous solution over the integration interval, ``sol(t) -> y``.

    Parameters
    ----------
    t_nodes : ndarray, shape (m + 1,)
        Breakpoints: the start time and the end of every accepted step (monotonic).
    y_nodes : ndarray, shape (m, N)
        State at the start of each step (flattened).
    coeffs : ndarray, shape (m, p, N)
        Per-step coefficients in the given `form`.
    form : {"power", "nested"}
        How `coeffs` are evaluated (see the module docstring).
    shape : tuple of int
        Shape of one state: ``(n,)`` or ``(n, batch)``.

    Notes
    -----
    Outside ``[t_nodes[0], t_nodes[-1]]`` the polynomial of the nearest step is extrapolated.
    A call with a scalar time returns one state of shape `shape`; a call with an array of
    ``k`` times returns shape ``(n, k)`` or ``(n, k, batch)``, like ``OdeResult.y``. The
    returned arrays are always fresh.

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import ode
    >>> r = ode.solve(lambda t, y: -y, (0.0, 1.0), [1.0], method="dopri5", rtol=1e-10,
    ...               dense_output=True)
    >>> float(r.sol(0.5)[0])   # exp(-0.5)
    0.60653065...
    """

    __slots__ = ("_t", "_y", "_c", "_form", "_shape", "_sign")

    def __init__(self, t_nodes, y_nodes, coeffs, form, shape):
        self._t = np.asarray(t_nodes, dtype=float)
        self._y = np.asarray(y_nodes, dtype=float)
        self._c = np.asarray(coeffs, dtype=float)
        self._form = form
        self._shape = tuple(shape)
        self._sign = 1.0 if self._t[-1] >= self._t[0] else -1.0

    @property
    def t_min(self) -> float:
        """Lower end of the interval covered."""
        return float(min(self._t[0], self._t[-1]))

    @property
    def t_max(self) -> float:
        """Upper end of the interval covered."""
        return float(max(self._t[0], self._t[-1]))

    def __repr__(self) -> str:
        return (
            f"DenseSolution(t=[{self._t[0]:g}, {self._t[-1]:g}], steps={len(self._y)}, "
            f"form={self._form!r})"
        )

    def _eval_flat(self, t):
        """States at the times `t` (1-D array), flattened: shape (k, N)."""
        m = len(self._y)
        if m == 0:
            return np.broadcast_to(np.zeros(0), (len(t), 0)).copy()
        s = self._sign
        idx = np.searchsorted(s * self._t, s * t, side="right") - 1
        np.clip(idx, 0, m - 1, out=idx)
        t0 = self._t[idx]
        return evaluate(t, t0, self._t[idx + 1] - t0, self._y[idx], self._c[idx], self._form)

    def __call__(self, t):
        t_arr = np.asarray(t, dtype=float)
        flat = self._eval_flat(np.atleast_1d(t_arr).ravel())
        if t_arr.ndim == 0:
            return flat[0].reshape(self._shape)
        k = flat.shape[0]
        out = flat.reshape((k,) + self._shape)
        return np.ascontiguousarray(np.moveaxis(out, 0, 1))


def evaluate(t, t0, h, y0, c, form):
    """The polynomials of the steps at the times `t` (one step per time: its start `t0`,
    length `h`, state `y0` (k, N) and coefficients `c` (k, p, N)); shape (k, N).

    The one evaluation of the dense output (:class:`DenseSolution` and the recorders of
    samples use it, so that both give the same numbers).

    Examples
    --------
    >>> import numpy as np
    >>> evaluate(np.array([0.5]), np.array([0.0]), np.array([1.0]), np.array([[1.0]]),
    ...          np.array([[[2.0]]]), "power").tolist()  # y = 1 + 2 x
    [[2.0]]
    """
    x = ((t - t0) / h)[:, None]
    p = c.shape[1]
    if form == "power":
        acc = c[:, p - 1] * x
        for j in range(p - 2, -1, -1):
            acc += c[:, j]
            acc *= x
    else:
        acc = np.zeros_like(c[:, 0])
        for j in range(p - 1, -1, -1):
            acc += c[:, j]
            acc *= x if j % 2 == 0 else (1.0 - x)
    acc += y0
    return acc
