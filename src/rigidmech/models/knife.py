"""The Chaplygin sleigh: a body on a plane guided by a knife edge, one nonholonomic
constraint (book, ch. 13.1, 25.3.3).

The sleigh is a uniform disc of mass m and radius r lying in the plane (moment of inertia
m r^2 / 2 about the normal through its centre G); its blade is at P = G - a i1 (+ b j1),
i1 the sleigh's axis, and lets P move along i1 only (a
:class:`~rigidmech.actions.KnifeEdge`).
"""

from __future__ import annotations

import sympy as sp

from .. import inertia
from ..actions import KnifeEdge, Pivot
from ..actions import gravity as _gravity_field
from ..dynamics import System
from ..kinetics import Body
from ..vectors import Frame, constants, coordinates
from ._model import Model

__all__ = ["sleigh", "sleigh_on_incline", "sleigh_on_turntable"]


def _disc_body(name, frame, m, r, centre):
    return Body(name, frame=frame, mass=m, centre=centre,
                inertia=inertia.disk(m, r, axis=frame.k, centre=centre))


def sleigh(a=None, *, gravity=True) -> Model:
    """The sleigh on the horizontal plane: G = (x, y, 0), heading theta about R0.k.

    Parameters
    ----------
    a : number or sympy expression, optional
        Distance of the blade behind G; a real symbol ``a`` unless given.
    gravity : bool, default True
        Apply gravity ``-g R0.k`` (it does no work on the horizontal plane).

    Returns
    -------
    Model
        coordinates (x, y, theta), constants (m, r, g, a), frames (R0, R1), bodies
        (sleigh,), points (G, P), connections (the knife edge,).

    Examples
    --------
    >>> from rigidmech import models
    >>> sl = models.sleigh()
    >>> sl.constants[-1], len(sl.system.constraints())
    (a, 1)
    """
    x, y, th = coordinates("x y theta")
    m, r, g = constants("m r g", positive=True)
    if a is None:
        a = sp.Symbol("a", real=True)
    R0 = Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    body = _disc_body("sleigh", R1, m, r, G)
    s = System(galilean=R0)
    P = G.moved("P", -a * R1.i)
    knife = KnifeEdge(body, R0, at=P, direction=R1.i, normal=R0.k)
    s.connect(R0, body, knife)
    if gravity:
        s.act(_gravity_field(-g * R0.k))
    return Model(s, (x, y, th), (m, r, g, a), (R0, R1), (body,), (G, P), (knife,))


def sleigh_on_incline(beta) -> Model:
    """The sleigh on a plane inclined by beta about R0.i (normal Ri.k), gravity ``-g R0.k``.

    G = (x, y) in the plane's axes (Ri.i, Ri.j), heading theta about Ri.k, the blade a
    behind G and b to its left (P = G - a i1 + b j1), a and b real symbols.

    Parameters
    ----------
    beta : number or sympy expression
        Tilt of the plane.

    Returns
    -------
    Model
        coordinates (x, y, theta), constants (m, r, g, a, b), frames (R0, Ri, R1), bodies
        (sleigh,), points (G, P), connections (the knife edge,).

    Examples
    --------
    >>> from rigidmech import models
    >>> [c.name for c in models.sleigh_on_incline(0).constants]
    ['m', 'r', 'g', 'a', 'b']
    """
    x, y, th = coordinates("x y theta")
    m, r, g = constants("m r g", positive=True)
    a, b = sp.symbols("a b", real=True)
    R0 = Frame("R0")
    Ri = R0.rotated("Ri", about=R0.i, angle=beta)
    G = R0.origin.moved("G", x * Ri.i + y * Ri.j)
    R1 = Ri.rotated("R1", about=Ri.k, angle=th, origin=G)
    body = _disc_body("sleigh", R1, m, r, G)
    s = System(galilean=R0)
    P = G.moved("P", -a * R1.i + b * R1.j)
    knife = KnifeEdge(body, R0, at=P, direction=R1.i, normal=Ri.k)
    s.connect(R0, body, knife)
    s.act(_gravity_field(-g * R0.k))
    return Model(s, (x, y, th), (m, r, g, a, b), (R0, Ri, R1), (body,), (G, P), (knife,))


def sleigh_on_turntable() -> Model:
    """The sleigh on a turntable: a uniform disc (mass M, radius R) pivoted about R0.k by
    phi, the sleigh at G = (x, y) in the table's axes, heading theta relative to the table,
    the blade a behind G; the knife edge joins the table (a body) and the sleigh. No
    gravity (it would do no work).

    Returns
    -------
    Model
        coordinates (phi, x, y, theta), constants (m, r, M, R, a), frames (R0, Rt, R1),
        bodies (table, sleigh), points (G, P), connections (the knife edge,).

    Examples
    --------
    >>> from rigidmech import models
    >>> [b.name for b in models.sleigh_on_turntable().bodies]
    ['table', 'sleigh']
    """
    phi, x, y, th = coordinates("phi x y theta")
    m, r, M, R = constants("m r M R", positive=True)
    a = sp.Symbol("a", real=True)
    R0 = Frame("R0")
    Rt = R0.rotated("Rt", about=R0.k, angle=phi)
    table = _disc_body("table", Rt, M, R, Rt.origin)
    G = Rt.origin.moved("G", x * Rt.i + y * Rt.j)
    R1 = Rt.rotated("R1", about=Rt.k, angle=th, origin=G)
    body = _disc_body("sleigh", R1, m, r, G)
    s = System(galilean=R0)
    s.connect(R0, table, Pivot(at=R0.origin, axis=R0.k))
    P = G.moved("P", -a * R1.i)
    knife = KnifeEdge(body, table, at=P, direction=R1.i, normal=Rt.k)
    s.connect(table, body, knife)
    return Model(s, (phi, x, y, th), (m, r, M, R, a), (R0, Rt, R1), (table, body), (G, P),
                 (knife,))
