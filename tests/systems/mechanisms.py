"""Mechanisms shared by the tests of the systems layer and of the linked parameters: the
tuple views the tests unpack, of the catalogue's builders (:mod:`rigidmech.models.loops`)."""

import rigidmech as rm
from rigidmech import models

L0, L1, L2, L3 = models.FOUR_BAR_LENGTHS


def bar(name, frame, length, origin, m):
    """A uniform rod of mass m along ``frame.i`` from ``origin`` (the catalogue's bars)."""
    G = origin.moved("G" + name, length / 2 * frame.i)
    return rm.Body(name, frame=frame, mass=m, centre=G,
                   inertia=rm.inertia.rod(m, length, axis=frame.i, centre=G))


def four_bar(lengths=(L0, L1, L2, L3), gravity=True, stabilization=(5.0, 5.0)):
    """Crank O-B (q1), coupler B-C (q2, relative to the crank), rocker D-C (q3), ground
    O-D along i; the loop is closed by the pivot at C (the coupler's C meets the rocker's).
    A length may be a sympy symbol; `stabilization` is Baumgarte's (alpha, beta).
    Returns ``(system, (q1, q2, q3), (R0, R1, R2, R3), (B, C, C3))``."""
    m = models.four_bar(lengths, gravity=gravity, stabilization=stabilization)
    return m.system, m.coordinates, m.frames, m.points[:3]


def slider_crank(r=0.5, ell=1.5):
    """Crank O-A (q1), rod A-B (q2 relative to the crank), slider at x on the line (O, i); the
    loop is closed by the pivot at B between the rod and the slider. Returns
    ``(system, (q1, q2, x), R0)``."""
    m = models.slider_crank(r, ell)
    return m.system, m.coordinates, m.frames[0]
