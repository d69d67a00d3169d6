"""Closed loops of rods: the four-bar linkage, a chain of four-bars and the slider-crank
(book, ch. 13.2, 25.3.3: parameters of situation linked by closure conditions).

Each loop is closed by its last pivot (``System.connect(..., meets=...)``): the system keeps
every parameter and the closure conditions (Lagrange multipliers). The rods are uniform, of
mass m, along their frames' ``i``; gravity is ``-g R0.j``.
"""

from __future__ import annotations

from .. import inertia
from .._core.errors import ArgumentError
from ..actions import Pivot, Prismatic
from ..actions import gravity as _gravity_field
from ..dynamics import System
from ..kinetics import Body
from ..vectors import Frame, constants, coordinates
from ._model import Model

__all__ = ["FOUR_BAR_LENGTHS", "CHAIN_COUPLER", "four_bar", "four_bar_chain", "slider_crank"]

#: Default lengths (ground OD, crank OB, coupler BC, rocker DC) of the four-bar.
FOUR_BAR_LENGTHS = (2.0, 1.0, 2.0, 1.5)
#: Coupler of the loops after the first in :func:`four_bar_chain` (2.0 would make them
#: parallelograms, whose singular branch points are no fair test).
CHAIN_COUPLER = 2.2


def _bar(name, frame, length, origin, m):
    G = origin.moved("G" + name, length / 2 * frame.i)
    return Body(name, frame=frame, mass=m, centre=G,
                inertia=inertia.rod(m, length, axis=frame.i, centre=G))


def four_bar(lengths=FOUR_BAR_LENGTHS, gravity=True, stabilization=(5.0, 5.0)) -> Model:
    """The four-bar linkage: crank O-B (q1), coupler B-C (q2, relative to the crank), rocker
    D-C (q3), ground O-D along i; the loop is closed by the pivot at C.

    Three parameters, two closure conditions, mobility 1 (book, ch. 13.2, 25.3.3).

    Parameters
    ----------
    lengths : tuple of 4 numbers, default (2.0, 1.0, 2.0, 1.5)
        Ground OD, crank OB, coupler BC, rocker DC.
    gravity : bool, default True
        Apply gravity ``-g R0.j`` (without it, g is still among the constants).
    stabilization : (float, float), default (5.0, 5.0)
        Baumgarte's coefficients of the closure, passed to
        :class:`~rigidmech.dynamics.System`.

    Returns
    -------
    Model
        coordinates (q1, q2, q3), constants (m, g), frames (R0, R1, R2, R3), bodies (crank,
        coupler, rocker), points (B, C, C3, D): C the coupler's end, C3 the rocker's,
        which the loop makes meet.

    Examples
    --------
    >>> from rigidmech import models
    >>> bar4 = models.four_bar()
    >>> len(bar4.system.closure_conditions()), bar4.system.mobility().mobility
    (2, 1)
    """
    l0, l1, l2, l3 = lengths
    q1, q2, q3 = coordinates("q1 q2 q3")
    m, g = constants("m g", positive=True)
    R0 = Frame("R0")
    k = R0.k
    R1 = R0.rotated("R1", about=k, angle=q1)
    B = R0.origin.moved("B", l1 * R1.i)
    R2 = R1.rotated("R2", about=k, angle=q2, origin=B)
    D = R0.point("D", l0, 0, 0)
    R3 = R0.rotated("R3", about=k, angle=q3, origin=D)
    crank, coupler, rocker = (_bar("crank", R1, l1, R0.origin, m), _bar("coupler", R2, l2, B, m),
                              _bar("rocker", R3, l3, D, m))
    s = System(galilean=R0, stabilization=stabilization)
    s.connect(R0, crank, Pivot(at=R0.origin, axis=k))
    s.connect(crank, coupler, Pivot(at=B, axis=k))
    s.connect(R0, rocker, Pivot(at=D, axis=k))
    C2, C3 = B.moved("C", l2 * R2.i), D.moved("C3", l3 * R3.i)
    s.connect(coupler, rocker, Pivot(at=C2, axis=k), meets=C3)
    if gravity:
        s.act(_gravity_field(-g * R0.j))
    return Model(s, (q1, q2, q3), (m, g), (R0, R1, R2, R3), (crank, coupler, rocker),
                 (B, C2, C3, D))


def four_bar_chain(n: int, lengths=FOUR_BAR_LENGTHS, coupler=CHAIN_COUPLER,
                   stabilization=(5.0, 5.0)) -> Model:
    """A chain of n four-bars: a crank pivoted at O, then for each loop j a coupler pivoted
    at the tip of the previous driver (the crank, then rocker j - 1) and a rocker pivoted at
    D_j = (j L0, 0), the loop closed where the coupler's tip C_j meets the rocker's E_j.

    2n + 1 parameters (q1 the crank's absolute angle, then per loop the coupler's angle
    relative to its driver and the rocker's absolute angle), 2n closure conditions,
    mobility 1 (book, ch. 25.3.3). n = 1 is the four-bar, its bodies named b1, b2, b3.

    Parameters
    ----------
    n : int
        Number of loops, at least 1.
    lengths : tuple of 4 numbers, default (2.0, 1.0, 2.0, 1.5)
        Ground step L0, crank L1, first coupler L2, rockers L3.
    coupler : float, default 2.2
        Length of the couplers after the first.
    stabilization : (float, float), default (5.0, 5.0)
        Baumgarte's coefficients of the closures, passed to
        :class:`~rigidmech.dynamics.System`.

    Returns
    -------
    Model
        coordinates (q1, ..., q(2n+1)), constants (m, g), frames (R0, ...), bodies
        (b1, ...), points (B1, C1, E1, D1, B2, ...).

    Examples
    --------
    >>> from rigidmech import models
    >>> chain = models.four_bar_chain(2)
    >>> len(chain.coordinates), len(chain.system.closure_conditions())
    (5, 4)
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ArgumentError(f"`n` must be an integer >= 1 (the number of loops); got {n!r}.")
    L0, L1, L2, L3 = lengths
    qs = coordinates(" ".join(f"q{i}" for i in range(1, 2 * n + 2)))
    m, g = constants("m g", positive=True)
    R0 = Frame("R0")
    k = R0.k
    s = System(galilean=R0, stabilization=stabilization)
    R1 = R0.rotated("R1", about=k, angle=qs[0])
    driver, driver_length = _bar("b1", R1, L1, R0.origin, m), L1
    s.connect(R0, driver, Pivot(at=R0.origin, axis=k))
    frames, bodies, points = [R0, R1], [driver], []
    for j in range(1, n + 1):
        a, b = qs[2 * j - 1], qs[2 * j]
        B = driver.frame.origin.moved(f"B{j}", driver_length * driver.frame.i)
        Rc = driver.frame.rotated(f"R{2 * j}", about=k, angle=a, origin=B)
        D = R0.point(f"D{j}", j * L0, 0, 0)
        Rr = R0.rotated(f"R{2 * j + 1}", about=k, angle=b, origin=D)
        lc = L2 if j == 1 else coupler
        bc, rocker = _bar(f"b{2 * j}", Rc, lc, B, m), _bar(f"b{2 * j + 1}", Rr, L3, D, m)
        s.connect(driver, bc, Pivot(at=B, axis=k))
        s.connect(R0, rocker, Pivot(at=D, axis=k))
        C, E = B.moved(f"C{j}", lc * Rc.i), D.moved(f"E{j}", L3 * Rr.i)
        s.connect(bc, rocker, Pivot(at=C, axis=k), meets=E)
        driver, driver_length = rocker, L3
        frames += [Rc, Rr]
        bodies += [bc, rocker]
        points += [B, C, E, D]
    s.act(_gravity_field(-g * R0.j))
    return Model(s, tuple(qs), (m, g), tuple(frames), tuple(bodies), tuple(points))


def slider_crank(r=0.5, ell=1.5) -> Model:
    """The slider-crank: crank O-A (q1), rod A-B (q2 relative to the crank), slider at x on
    the line (O, i); the loop is closed by the pivot at B between the rod and the slider.

    Three parameters, two closure conditions, mobility 1 (book, ch. 13.2, 25.3.3); the
    slider is a point mass m, gravity ``-g R0.j``.

    Parameters
    ----------
    r : float, default 0.5
        Length of the crank.
    ell : float, default 1.5
        Length of the connecting rod.

    Returns
    -------
    Model
        coordinates (q1, q2, x), constants (m, g), frames (R0, R1, R2, R3), bodies (crank,
        rod, slider), points (A, B, P): B the rod's end, P the slider's centre.

    Examples
    --------
    >>> from rigidmech import models
    >>> sc = models.slider_crank()
    >>> [str(q) for q in sc.coordinates], sc.system.mobility().mobility
    (['q1(t)', 'q2(t)', 'x(t)'], 1)
    """
    q1, q2, x = coordinates("q1 q2 x")
    m, g = constants("m g", positive=True)
    R0 = Frame("R0")
    k = R0.k
    R1 = R0.rotated("R1", about=k, angle=q1)
    A = R0.origin.moved("A", r * R1.i)
    R2 = R1.rotated("R2", about=k, angle=q2, origin=A)
    P = R0.point("P", x, 0, 0)
    R3 = R0.translated("R3", P)
    crank, rod = _bar("crank", R1, r, R0.origin, m), _bar("rod", R2, ell, A, m)
    slider = Body("slider", frame=R3, mass=m, centre=P)
    s = System(galilean=R0)
    s.connect(R0, crank, Pivot(at=R0.origin, axis=k))
    s.connect(crank, rod, Pivot(at=A, axis=k))
    s.connect(R0, slider, Prismatic(at=P, axis=R0.i))
    B = A.moved("B", ell * R2.i)
    s.connect(rod, slider, Pivot(at=B, axis=k), meets=P)
    s.act(_gravity_field(-g * R0.j))
    return Model(s, (q1, q2, x), (m, g), (R0, R1, R2, R3), (crank, rod, slider), (A, B, P))
