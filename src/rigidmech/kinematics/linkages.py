"""The planar four-bar linkage from its four lengths: Grashof's classification, the
transmission angle and the dead points (book, ch. 9.4 and 25.3.3), in numbers.

Conventions (those of :func:`rigidmech.models.four_bar`): the ground O-D of length ``ground``
along the x axis, the crank O-B (``crank``) turning by the crank angle theta from OD, the
coupler B-C (``coupler``) and the rocker D-C (``rocker``). The diagonal BD has

.. math:: BD^2 = g^2 + a^2 - 2\\,g\\,a\\cos\\theta

(g the ground, a the crank), and the **transmission angle** mu = angle BCD between the coupler
and the rocker at C follows from the triangle BCD (b the coupler, c the rocker):

.. math:: \\cos\\mu = \\frac{b^2 + c^2 - BD^2}{2\\,b\\,c}.

It is the same on both assembly branches (the triangle is mirrored). The crank drives the
rocker worst where mu is near 0 or pi; at mu = 0 or pi (coupler and rocker aligned) the
linkage is at a **dead point** (toggle position).

**Grashof's law**: with s the shortest length, l the longest, p and q the two others, some
link turns fully relative to the others when s + l < p + q; the kind then depends on which
link is the shortest. When s + l = p + q (a *change point*) the links can all fall into line
and the linkage may change branch there; when s + l > p + q no link turns fully.
"""

from __future__ import annotations

import math
import numbers
from fractions import Fraction

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError

__all__ = ["grashof_type", "is_grashof", "transmission_angle", "dead_points",
           "GRASHOF_TYPES", "UNIT_TOL"]

#: The values :func:`grashof_type` returns, and when.
GRASHOF_TYPES = {
    "crank-rocker": "s + l < p + q, the crank shortest: the crank turns fully, the rocker rocks",
    "rocker-crank": "s + l < p + q, the rocker shortest: the rocker turns fully, the crank "
                    "rocks",
    "double-crank": "s + l < p + q, the ground shortest: both side links turn fully",
    "double-rocker": "s + l < p + q, the coupler shortest: the coupler turns fully, both side "
                     "links rock",
    "change-point": "s + l = p + q: all the links can fall into line",
    "triple-rocker": "s + l > p + q (not Grashof): no link turns fully",
}

_NAMES = ("ground", "crank", "coupler", "rocker")

#: Slack on abs(cosine) <= 1 when deciding whether a position can be assembled: the cosines of
#: the dead points, computed back from their crank angles, round to about 1e-15 beyond 1.
UNIT_TOL = 1e-12


def _within_unit(x):
    """The one rule for "this cosine is one of a real angle" (reachable position, dead
    point): abs(x) <= 1 + UNIT_TOL."""
    return np.abs(x) <= 1.0 + UNIT_TOL


def _lengths(ground, crank, coupler, rocker):
    out = []
    for name, x in zip(_NAMES, (ground, crank, coupler, rocker), strict=True):
        if isinstance(x, bool) or not isinstance(x, numbers.Real):
            raise ArgumentTypeError(f"`{name}` must be a positive number (a length); got "
                                    f"{type(x).__name__}.")
        if not (math.isfinite(x) and x > 0):
            raise ArgumentError(f"`{name}` must be a positive finite length; got {x!r}.")
        out.append(x)
    # exact rationals of the given numbers: the Grashof sums are compared without rounding
    exact = [Fraction(x) for x in out]
    longest = max(exact)
    if longest >= sum(exact) - longest:
        k = exact.index(longest)
        raise ArgumentError(
            f"the four lengths cannot close a loop: `{_NAMES[k]}` = {out[k]!r} must be shorter "
            f"than the sum of the three others ({float(sum(exact) - longest)!r}).")
    return out, exact


def is_grashof(ground, crank, coupler, rocker) -> bool:
    """Whether s + l <= p + q (Grashof's condition, ch. 9.4): some link can turn fully
    relative to the others (change points included).

    The sums are compared exactly, on the rationals equal to the given floats.

    Examples
    --------
    >>> is_grashof(2.0, 1.0, 2.0, 1.5), is_grashof(2.0, 3.0, 3.5, 1.8)
    (True, False)
    """
    return grashof_type(ground, crank, coupler, rocker) != "triple-rocker"


def grashof_type(ground, crank, coupler, rocker) -> str:
    """The kind of four-bar linkage by Grashof's law (book, ch. 9.4).

    Parameters
    ----------
    ground, crank, coupler, rocker : float
        The four lengths, positive and finite, the longest shorter than the sum of the others.

    Returns
    -------
    str
        One of :data:`GRASHOF_TYPES`: ``"crank-rocker"``, ``"rocker-crank"``,
        ``"double-crank"``, ``"double-rocker"``, ``"change-point"`` or ``"triple-rocker"``.

    Raises
    ------
    ArgumentError
        A length not positive and finite, or lengths that cannot close a loop.
    ArgumentTypeError
        A length that is not a number.

    Notes
    -----
    The decision s + l versus p + q is made on the exact rationals of the given numbers, so
    that the change point s + l = p + q is recognised exactly, with no tolerance: the floats
    0.1, 0.4, 0.2, 0.3 are not a change point (their exact values do not balance); pass
    integers, :class:`fractions.Fraction` or dyadic floats (0.5, 1.25, ...) to pose one.

    Examples
    --------
    >>> grashof_type(2.0, 1.0, 2.0, 1.5)          # the default of rigidmech.models.four_bar
    'crank-rocker'
    >>> grashof_type(1, 3, 2, 2)                  # 1 + 3 = 2 + 2
    'change-point'
    """
    _, exact = _lengths(ground, crank, coupler, rocker)
    order = sorted(range(4), key=lambda k: exact[k])
    s, p, q, l = (exact[k] for k in order)
    if s + l > p + q:
        return "triple-rocker"
    if s + l == p + q:
        return "change-point"
    return {0: "double-crank", 1: "crank-rocker", 2: "double-rocker",
            3: "rocker-crank"}[order[0]]


def transmission_angle(ground, crank, coupler, rocker, crank_angle):
    """The transmission angle mu (between coupler and rocker) at the crank angle theta
    (book, ch. 9.4).

    Parameters
    ----------
    ground, crank, coupler, rocker : float
        The four lengths (see :func:`grashof_type`).
    crank_angle : float or array_like
        theta, radians, from the ground line OD.

    Returns
    -------
    float or ndarray
        mu in [0, pi]; nan where the linkage cannot be assembled at that crank angle
        (``abs(cos mu) > 1 + UNIT_TOL``: the crank does not reach it; within the slack
        :data:`UNIT_TOL`, for rounding at the dead points, cos mu is clipped to +-1).

    Examples
    --------
    >>> import math
    >>> round(math.degrees(transmission_angle(2.0, 1.0, 2.0, 1.5, math.pi / 2)), 6)
    77.975301
    """
    (g, a, b, c), _ = _lengths(ground, crank, coupler, rocker)
    try:
        theta = np.asarray(crank_angle, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"`crank_angle` must be a number or an array of numbers (radians); got "
            f"{crank_angle!r}.") from None
    if not np.all(np.isfinite(theta)):
        raise ArgumentError(f"`crank_angle` must be finite; got {crank_angle!r}.")
    bd2 = g * g + a * a - 2 * g * a * np.cos(theta)
    cos_mu = (b * b + c * c - bd2) / (2 * b * c)
    reachable = _within_unit(cos_mu)
    out = np.where(reachable, np.arccos(np.clip(cos_mu, -1.0, 1.0)), np.nan)
    return float(out) if out.ndim == 0 else out


def dead_points(ground, crank, coupler, rocker):
    """The crank angles at which the transmission angle is 0 or pi (coupler and rocker in
    line): the dead points, or toggle positions, of the four-bar (book, ch. 9.4).

    Parameters
    ----------
    ground, crank, coupler, rocker : float
        The four lengths (see :func:`grashof_type`).

    Returns
    -------
    tuple of (float, float)
        ``(theta, mu)`` pairs, theta in [0, 2 pi) increasing, mu 0 or pi; empty when there is
        none (a crank-rocker driven by its crank, a double-crank).

    Notes
    -----
    mu = 0 where BD = abs(coupler - rocker), mu = pi where BD = coupler + rocker; each gives
    cos theta = (g^2 + a^2 - BD^2) / (2 g a), two crank angles +-theta (one if
    cos theta = +-1). A dead point exists when abs(cos theta) <= 1 + :data:`UNIT_TOL`, the
    same rule as the reachability in :func:`transmission_angle`.

    Examples
    --------
    A triple rocker: the crank swings between two toggle positions, through theta = pi.

    >>> [(round(t, 6), m) for t, m in dead_points(2.0, 3.0, 3.5, 1.8)]
    [(0.568889, 0.0), (5.714296, 0.0)]
    """
    (g, a, b, c), _ = _lengths(ground, crank, coupler, rocker)
    found = []
    for bd, mu in ((abs(b - c), 0.0), (b + c, math.pi)):
        cos_t = (g * g + a * a - bd * bd) / (2 * g * a)
        if _within_unit(cos_t):
            t = math.acos(max(-1.0, min(1.0, cos_t)))
            found.append((t, mu))
            if 0.0 < t < math.pi:
                found.append((2 * math.pi - t, mu))
    return tuple(sorted(found))
