"""Orientation singularities along a simulated motion (book, ch. 9.1.2).

Private helper of :mod:`rigidmech.dynamics`. :func:`orientation_singularities` finds, for
each body of a system, the angles that orient its frame relative to the nearest frame it is
built from (another body's frame, the Galilean reference or the root) and their singular
set (:meth:`rigidmech.vectors.Frame.singular_set`). :func:`warn_near_singularities` looks for
the closest approach of a simulated motion to each set and issues a
:class:`~rigidmech._core.errors.SingularityWarning` when it comes nearer than :data:`NEAR`.

The check is cheap: it evaluates the compiled measure of each set on the recorded samples
(one vectorised call), and refines on the dense output (a bounded scalar minimisation between
the neighbouring samples) only a local minimum of the samples that could hide a value below
:data:`NEAR`, so that a fast passage near the set between two samples is not missed. The
right-hand side of the integration is not touched.
"""

from __future__ import annotations

import os
import sys
import warnings

import numpy as np

from .._core.errors import FrameError, SingularityWarning

__all__ = ["NEAR", "orientation_singularities", "warn_near_singularities"]

#: A simulation warns when the measure of a singular set (|sin(theta)| for Euler angles,
#: |cos(theta)| for Cardan angles: the sine of the angular distance to the set) falls below
#: this value. At 1e-2 the mass matrix's condition number grows by about 1e4 over its value
#: far from the set (it scales as the inverse square of the measure).
NEAR = 1e-2

_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep


def orientation_singularities(bodies, galilean) -> tuple:
    """The singular sets of the orientation angles of ``bodies`` (a tuple of
    :class:`~rigidmech.vectors.OrientationSingularity`, one per body frame that has one).

    Each body frame is judged relative to its nearest ancestor that is the Galilean frame,
    another body's frame or the root. A chain with more than three angles up to that frame is
    not one parametrisation of an orientation and is skipped.
    """
    stops = {b.frame for b in bodies} | {galilean}
    out, seen = [], set()
    for body in bodies:
        frame = body.frame
        if frame in seen:
            continue
        seen.add(frame)
        anchor = frame.parent
        if anchor is None:
            continue
        while anchor.parent is not None and anchor not in stops:
            anchor = anchor.parent
        try:
            s = frame.singular_set(anchor)
        except FrameError:
            continue
        if s is not None:
            out.append(s)
    return tuple(out)


def _stacklevel():
    """``stacklevel`` naming the first caller outside rigidmech."""
    frame = sys._getframe(1)
    level = 1
    while frame is not None and frame.f_code.co_filename.startswith(_PACKAGE):
        frame = frame.f_back
        level += 1
    return level


def _capital(text):
    return text[:1].upper() + text[1:]


def _closest(s, rows, t, q, sol, params, near):
    """(time, measure) of the closest approach of the motion to the set ``s``."""
    m = s.measure(q[rows], **params)
    k = int(np.argmin(m))
    best_t, best_m = float(t[k]), float(m[k])
    if sol is None or t.size < 3:
        return best_t, best_m
    # local minima of the samples whose lower bound (the sample minus the larger of the
    # changes to its neighbours: the measure has a V-shaped minimum, like |sin(theta)| through
    # theta = 0, or a rounder one) falls below `near`
    mid = m[1:-1]
    reach = np.maximum(np.abs(m[:-2] - mid), np.abs(m[2:] - mid))
    interior = np.flatnonzero((mid <= m[:-2]) & (mid <= m[2:]) & (mid - reach < near))
    if interior.size:
        from scipy.optimize import minimize_scalar  # imported on use (slow import)

        def measure_at(tt):
            return float(s.measure(np.asarray(sol(tt))[rows], **params))

        for j in interior + 1:
            r = minimize_scalar(measure_at, bounds=(float(t[j - 1]), float(t[j + 1])),
                                method="bounded", options={"xatol": 1e-12})
            if r.fun < best_m:
                best_t, best_m = float(r.x), float(r.fun)
    return best_t, best_m


def warn_near_singularities(singular_sets, coordinates, result, params, near=NEAR):
    """Warn (:class:`SingularityWarning`) for each singular set the motion in ``result``
    (an :class:`~rigidmech.ode.OdeResult` of y = (q, q')) comes nearer than ``near``.

    ``singular_sets`` is a sequence of
    :class:`~rigidmech.vectors.OrientationSingularity` or a callable returning one;
    ``params`` the parameter values by name (a set whose constants are not all there is not
    checked). Returns the list of ``(set, time, measure)`` that warned.
    """
    if callable(singular_sets):
        singular_sets = singular_sets()
    if not singular_sets:
        return []
    index = {q: i for i, q in enumerate(coordinates)}
    t = np.asarray(result.t, dtype=float)
    q = np.asarray(result.y, dtype=float)[:len(coordinates)]
    if q.ndim != 2 or t.size == 0:  # a batch of initial states: not checked
        return []
    sol = getattr(result, "sol", None)
    warned = []
    for s in singular_sets:
        if any(c not in index for c in s.coordinates) or any(
                p.name not in params for p in s.parameters):
            continue
        rows = [index[c] for c in s.coordinates]
        values = {p.name: params[p.name] for p in s.parameters}
        when, m = _closest(s, rows, t, q, sol, values, near)
        if m < near:
            warnings.warn(
                f"{s.describe()}; the motion comes within "
                f"{np.arcsin(min(m, 1.0)):.2g} rad of it at t = {when:.6g} (measure {m:.2g} "
                f"< {near:g}). Near it the mass matrix is nearly singular: the integration "
                f"slows down and loses accuracy. {_capital(s.suggestion())}.",
                SingularityWarning, stacklevel=_stacklevel())
            warned.append((s, when, m))
    return warned
