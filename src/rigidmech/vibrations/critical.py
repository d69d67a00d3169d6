"""The critical value of a parameter where a linearised motion changes stability (book,
ch. 25.4): the critical speeds of a bicycle (weave and capsize), the critical spin of a
sleeping top, the speed where a rolling disc stands up.

The stability of a linearised system M δq'' + C δq' + K δq = 0 is decided by its exponents s
(the eigenvalues of the first-order matrix, :meth:`LinearSystem.eigenvalues
<rigidmech.vibrations.LinearSystem.eigenvalues>`) with the rule of
:func:`~rigidmech.vibrations.stability`: unstable when ``max Re s > tol max |s|``. The
*growth* ``max Re s - tol max |s|`` is then positive exactly where the system is unstable; a
critical value is a zero of the growth as a function of one parameter, found by Brent's
method (:func:`scipy.optimize.brentq`) in a bracket where it changes sign. The margin
``tol max |s|`` keeps a conservative system's exponents, on the imaginary axis up to the
rounding of the eigenvalue solver, on the stable side.

Examples
--------
>>> import sympy as sp
>>> from rigidmech.vibrations import LinearSystem
>>> c = sp.Symbol("c")                        # x'' + c x' + 4 x = 0: unstable for c < 0
>>> lin = LinearSystem([sp.Symbol("x")], {}, {}, [[1]], [[c]], [[4]], sp.zeros(1, 0), ())
>>> abs(critical_value(lin, "c", (-1, 1))) < 1e-8
True
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError

__all__ = ["StabilityChange", "critical_value", "growth", "stability_changes",
           "STABILITY_TOL"]

#: Relative margin of the stability decision on the exponents: unstable when
#: ``max Re s > STABILITY_TOL max |s|`` (the default ``tol`` of :func:`stability`).
STABILITY_TOL = 1e-9


def growth(exponents, tol=STABILITY_TOL) -> float:
    """``max Re s - tol max |s|`` over the exponents ``s``: positive exactly when the rule of
    :func:`~rigidmech.vibrations.stability` says unstable.

    Examples
    --------
    >>> growth([-1 + 2j, -1 - 2j]) < 0, growth([1e-12j, 0.5]) > 0
    (True, True)
    """
    s = np.asarray(exponents, dtype=complex)
    if s.size == 0:
        return -math.inf
    return float(np.max(s.real) - tol * np.max(np.abs(s)))


def _growth_of(system, parameter, values, tol):
    """g(p): the growth of ``system`` at ``parameter = p`` (the other values fixed)."""
    if callable(system) and not hasattr(system, "eigenvalues"):
        def exponents(p):
            return system(p)
    elif hasattr(system, "eigenvalues") and hasattr(system, "parameters"):
        name = parameter if isinstance(parameter, str) else getattr(parameter, "name", None)
        names = [s.name for s in system.parameters]
        if name not in names:
            raise ArgumentError(
                f"`parameter` must name a parameter of the linear system ({', '.join(names)}"
                f"); got {parameter!r}.")

        def exponents(p):
            return system.eigenvalues(**{**values, name: float(p)})
    else:
        raise ArgumentTypeError(
            f"`system` must be a LinearSystem or a callable giving the exponents at a value "
            f"of the parameter; got {type(system).__name__}.")
    if not (isinstance(tol, int | float) and math.isfinite(tol) and tol >= 0):
        raise ArgumentError(f"`tol` must be a finite number >= 0; got {tol!r}.")

    def g(p):
        return growth(exponents(p), tol)

    return g


def _two_numbers(bracket):
    try:
        a, b = (float(x) for x in bracket)
    except (TypeError, ValueError):
        raise ArgumentError(f"`bracket` must be two numbers (a, b); got {bracket!r}.") from None
    if not (math.isfinite(a) and math.isfinite(b) and a != b):
        raise ArgumentError(f"`bracket` must be two different finite numbers; got {bracket!r}.")
    return a, b


def critical_value(system, parameter, bracket, *, tol=STABILITY_TOL, xtol=1e-12,
                   **values) -> float:
    """The value of ``parameter`` in ``bracket`` where the linearised ``system`` changes
    stability (ch. 25.4): a zero of the growth ``max Re s - tol max |s|`` of its exponents s,
    found by :func:`scipy.optimize.brentq`.

    Parameters
    ----------
    system : LinearSystem or callable
        A :class:`~rigidmech.vibrations.LinearSystem` (its compiled
        :meth:`~rigidmech.vibrations.LinearSystem.eigenvalues`), or a callable giving the
        exponents at a value of the parameter (for matrices built by hand).
    parameter : str or sympy.Symbol
        The parameter that varies (a speed, a spin rate); ignored for a callable.
    bracket : (float, float)
        Two values where the system is stable at one and unstable at the other (the growth
        changes sign); a growth exactly 0 at an end returns that end.
    tol : float
        Relative margin of the decision, as :func:`~rigidmech.vibrations.stability`. It
        moves a transversal crossing (a real part that passes through 0 with a nonzero
        slope, as the bicycle's) by about ``tol max|s| / slope``; ``tol=0`` locates the zero
        of ``max Re s`` itself, which suits such a crossing but not exponents that stay on
        the imaginary axis (a conservative or gyroscopic system: their rounding decides).
    xtol : float
        Absolute tolerance on the value (Brent's method).
    **values
        The values of the other parameters.

    Returns
    -------
    float

    Raises
    ------
    ArgumentError
        If the system is stable at both ends of the bracket, or unstable at both (the
        message gives the growth at each end): narrow or move the bracket, or scan with
        :func:`stability_changes`.

    Examples
    --------
    The sleeping top (ch. 20): stable when C^2 w^2 > 4 A m g l (A about the fixed point),
    written here as its linear equations on the two small tilts.

    >>> import math, sympy as sp
    >>> from rigidmech.vibrations import LinearSystem
    >>> w = sp.Symbol("w"); A, C, mgl = 0.02, 0.03, 0.5
    >>> lin = LinearSystem(sp.symbols("a b"), {}, {}, [[A, 0], [0, A]],
    ...                    [[0, C * w], [-C * w, 0]], [[-mgl, 0], [0, -mgl]],
    ...                    sp.zeros(2, 0), ())
    >>> w_c = critical_value(lin, "w", (1, 100))
    >>> round(w_c, 9) == round(2 * math.sqrt(A * mgl) / C, 9)
    True
    """
    from scipy.optimize import brentq  # imported on use

    g = _growth_of(system, parameter, values, tol)
    a, b = _two_numbers(bracket)
    ga, gb = g(a), g(b)
    if ga == 0.0:
        return a
    if gb == 0.0:
        return b
    if (ga > 0) == (gb > 0):
        state = "unstable" if ga > 0 else "stable"
        raise ArgumentError(
            f"`bracket` must hold a change of stability, but the system is {state} at both "
            f"ends: growth max Re s - tol max|s| = {ga:.3g} at {a:g} and {gb:.3g} at {b:g}. "
            "Move or widen the bracket, or scan a range with stability_changes().")
    return float(brentq(g, a, b, xtol=xtol, rtol=4 * np.finfo(float).eps))


class StabilityChange(NamedTuple):
    """A change of stability found by :func:`stability_changes`: the critical ``value`` and
    what the system ``becomes`` as the parameter increases through it (``"stable"`` or
    ``"unstable"``).

    Examples
    --------
    >>> StabilityChange(4.29, "stable").becomes
    'stable'
    """

    value: float
    becomes: str


def stability_changes(system, parameter, grid, *, tol=STABILITY_TOL, xtol=1e-12,
                      **values) -> tuple:
    """Every change of stability of ``system`` as ``parameter`` runs over ``grid`` (ch.
    25.4): the growth of :func:`critical_value` is evaluated on the grid, and each interval
    where it changes sign refined by Brent's method. A change between two grid points and
    back again within the same interval is not seen: make the grid fine enough.

    Parameters
    ----------
    system, parameter, tol, xtol, **values
        As :func:`critical_value`.
    grid : sequence of float
        Increasing values of the parameter (at least two).

    Returns
    -------
    tuple of StabilityChange
        In increasing order of the value.

    Examples
    --------
    The benchmark bicycle (Meijaard et al. 2007) from its published matrices,
    M q'' + v C1 q' + (g K0 + v^2 K2) q = 0: stable between the weave and capsize speeds.

    >>> import numpy as np, sympy as sp
    >>> from rigidmech.vibrations import LinearSystem
    >>> M = [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]]
    >>> C1 = sp.Matrix([[0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
    >>> K0 = sp.Matrix([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
    >>> K2 = sp.Matrix([[0, 76.59734589573222], [0, 2.65431523794604]])
    >>> v = sp.Symbol("v")
    >>> bike = LinearSystem(sp.symbols("phi delta"), {}, {}, M, v * C1,
    ...                     9.81 * K0 + v**2 * K2, sp.zeros(2, 0), ())
    >>> [(round(c.value, 5), c.becomes) for c in stability_changes(bike, "v",
    ...                                                            np.arange(0.5, 10, 0.5))]
    [(4.29238, 'stable'), (6.02426, 'unstable')]
    """
    grid = np.asarray(grid, dtype=float)
    if grid.ndim != 1 or grid.size < 2 or not np.all(np.isfinite(grid)) \
            or not np.all(np.diff(grid) > 0):
        raise ArgumentError(
            f"`grid` must be at least two increasing finite values of the parameter; got "
            f"{grid!r}.")
    g = _growth_of(system, parameter, values, tol)
    found = [g(p) for p in grid]
    out = []
    for k in range(grid.size - 1):
        a, b, ga, gb = grid[k], grid[k + 1], found[k], found[k + 1]
        if ga > 0 >= gb or ga <= 0 < gb:
            value = critical_value(system, parameter, (a, b), tol=tol, xtol=xtol, **values)
            out.append(StabilityChange(value, "unstable" if gb > 0 else "stable"))
    return tuple(out)
