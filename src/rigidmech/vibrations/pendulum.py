"""The period of the simple pendulum at any amplitude (book, ch. 27.1.3; ch. 21.2 for the
small oscillations).

The pendulum :math:`\\ddot\\theta + \\omega_0^2\\sin\\theta = 0` released at rest from the
amplitude :math:`\\theta_0 < \\pi` swings with the period

.. math::

    T = \\frac{4}{\\omega_0} K(k), \\qquad k = \\sin\\frac{\\theta_0}{2},

:math:`K` the complete elliptic integral of the first kind (of modulus k, parameter
:math:`m = k^2`). It grows from the small-amplitude period :math:`T_0 = 2\\pi/\\omega_0` to
infinity as :math:`\\theta_0 \\to \\pi` (the separatrix). Expanding Legendre's series
:math:`K = \\frac{\\pi}{2}\\sum_n \\big(\\binom{2n}{n}/4^n\\big)^2 k^{2n}` in powers of
:math:`\\theta_0` gives the small-amplitude corrections, Borda's :math:`\\theta_0^2/16` first:

.. math::

    T = T_0\\Big(1 + \\frac{\\theta_0^2}{16} + \\frac{11\\,\\theta_0^4}{3072}
        + \\frac{173\\,\\theta_0^6}{737280} + \\frac{22931\\,\\theta_0^8}{1321205760}
        + O(\\theta_0^{10})\\Big).

:func:`pendulum_period` is numeric (scipy); :func:`pendulum_period_series` works on numbers or
on sympy expressions.
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError
from .._core.lazy import lazy_functions
from ._scalars import _as, _lib, _positive

# lazy: import cost (scipy takes as long as sympy to import; see docs/performance)
(ellipkm1,) = lazy_functions(globals(), "scipy.special", "ellipkm1")

__all__ = ["pendulum_period", "pendulum_period_series", "PERIOD_SERIES"]

#: Coefficients of theta0^0, theta0^2, ..., theta0^8 in T / T0 (exact rationals).
PERIOD_SERIES = (sp.Integer(1), sp.Rational(1, 16), sp.Rational(11, 3072),
                 sp.Rational(173, 737280), sp.Rational(22931, 1321205760))


def _amplitude(theta0):
    try:
        a = np.asarray(theta0, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentError(
            f"`amplitude` must be a number or an array of numbers (radians); got "
            f"{theta0!r}.") from None
    bad = ~((a >= 0) & (a < math.pi))
    if np.any(bad):
        raise ArgumentError(
            f"`amplitude` must lie in [0, pi) radians for an oscillating pendulum; got "
            f"{a[bad].ravel()[0] if a.ndim else float(a)!r}. At pi the pendulum stands on the "
            "unstable equilibrium (infinite period); beyond it, it revolves.")
    return a


def pendulum_period(amplitude, omega0):
    """The exact period :math:`4 K(\\sin(\\theta_0/2)) / \\omega_0` of the simple pendulum
    (book, ch. 27.1.3).

    Parameters
    ----------
    amplitude : float or array_like
        :math:`\\theta_0` in radians, in ``[0, pi)``; arrays broadcast.
    omega0 : float or array_like
        :math:`\\omega_0 = \\sqrt{g/\\ell} > 0`, rad/s.

    Returns
    -------
    float or ndarray

    Raises
    ------
    ArgumentError
        If `amplitude` is outside ``[0, pi)`` or `omega0` is not positive and finite.

    Notes
    -----
    ``K`` is evaluated by :func:`scipy.special.ellipkm1` at the complementary parameter
    :math:`1 - k^2 = \\cos^2(\\theta_0/2)`, which keeps full relative accuracy near the
    separatrix, where :math:`k^2` rounds to 1.

    Examples
    --------
    >>> import math
    >>> pendulum_period(0.0, 1.0) == 2 * math.pi
    True
    >>> round(pendulum_period(math.radians(170), 1.0), 6)    # 2.44 times 2 pi
    15.326968
    """
    a = _amplitude(amplitude)
    _positive(omega0, "omega0")
    w = np.asarray(omega0, dtype=float)
    out = 4.0 * ellipkm1(np.cos(a / 2) ** 2) / w
    return float(out) if out.ndim == 0 else out


def pendulum_period_series(amplitude, omega0, order: int = 2):
    """The small-amplitude expansion of the pendulum's period, to :math:`\\theta_0^{order}`
    (book, ch. 21.2.2 and 27.1.3).

    ``order = 0`` is the linear period :math:`2\\pi/\\omega_0`, ``2`` Borda's correction
    :math:`T_0(1 + \\theta_0^2/16)`, then the terms of :data:`PERIOD_SERIES` up to ``8``.

    Parameters
    ----------
    amplitude : float, array_like or sympy expression
        :math:`\\theta_0` in radians (numbers: in ``[0, pi)``).
    omega0 : float, array_like or sympy expression
        :math:`\\omega_0 > 0`.
    order : int
        Highest power of :math:`\\theta_0` kept: 0, 2, 4, 6 or 8. The error is
        :math:`O(\\theta_0^{order + 2})`.

    Returns
    -------
    float, ndarray or sympy expression

    Raises
    ------
    ArgumentError
        If `order` is not one of 0, 2, 4, 6, 8, a numeric `amplitude` is outside ``[0, pi)``
        or `omega0` not positive.

    Examples
    --------
    >>> import sympy as sp
    >>> th, w = sp.symbols("theta0 omega0", positive=True)
    >>> sp.expand(pendulum_period_series(th, w, order=4) * w / (2 * sp.pi))
    11*theta0**4/3072 + theta0**2/16 + 1
    >>> round(pendulum_period_series(0.5, 1.0), 9)      # exact: 6.3828 (pendulum_period)
    6.381360078
    """
    if isinstance(order, bool) or order not in (0, 2, 4, 6, 8):
        raise ArgumentError(f"`order` must be one of 0, 2, 4, 6, 8; got {order!r}.")
    _positive(omega0, "omega0")
    lib = _lib(amplitude, omega0)
    if lib is np:
        th = _amplitude(amplitude)
        coefficients = [float(c) for c in PERIOD_SERIES]
    else:
        th = sp.sympify(amplitude)
        coefficients = PERIOD_SERIES
    factor = sum(c * th ** (2 * n) for n, c in enumerate(coefficients[: order // 2 + 1]))
    out = 2 * lib.pi / _as(omega0, lib) * factor
    if lib is np:
        out = np.asarray(out, dtype=float)
        return float(out) if out.ndim == 0 else out
    return out
