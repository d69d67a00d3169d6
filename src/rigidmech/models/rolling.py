"""Bodies rolling without slipping: a disc on a plane, a wheel on an incline and a ball on
a driven turntable (book, ch. 10.1, 13.1, 17.1, 23.4).

The no-slip condition is a :class:`~rigidmech.actions.RollingContact` (velocity
constraints, Lagrange multipliers), its contact point and normal either found from the
geometry (``ContactKinematics.between`` of the rim and the ground) or given.
"""

from __future__ import annotations

from .. import inertia as _inertia
from .._core.errors import ArgumentError
from ..actions import Pivot, RollingContact, gravity
from ..dynamics import System
from ..kinematics import ContactKinematics
from ..kinematics.surfaces import Circle, Plane, Sphere
from ..kinetics import Body
from ..vectors import Frame, Line, constants, coordinates, t
from ._model import Model

__all__ = ["rolling_disc", "wheel_on_incline", "ball_on_turntable"]

_CONTACTS = ("between", "given")
_WHEEL_INERTIAS = ("disk", "ring")


def rolling_disc(contact: str = "between") -> Model:
    """A thin uniform disc (mass m, radius r) rolling without slipping on the plane z = 0.

    Parameters of situation: the contact point (x, y), the heading psi (about R0.k, frame
    A), the lean theta (about A.i, frame B; pi/2 upright) and the spin phi (about B.k,
    frame D, the disc's); the centre is G = I0 + r B.j. Gravity ``-g R0.k``. Five
    parameters, two velocity constraints (book, ch. 10.1, 13.1).

    Parameters
    ----------
    contact : {"between", "given"}, default "between"
        ``"between"``: the contact found by ``ContactKinematics.between`` from the disc's rim
        (a circle) and the plane; ``"given"``: the contact point I0 = (x, y, 0) and the
        normal R0.k given.

    Returns
    -------
    Model
        coordinates (x, y, psi, theta, phi), constants (m, g, r), frames (R0, A, B, D),
        bodies (disc,), points (I0, G), connections (the rolling contact,).

    Examples
    --------
    >>> from rigidmech import models
    >>> disc = models.rolling_disc()
    >>> len(disc.system.constraints()), disc.system.mobility().mobility
    (2, 3)
    """
    if contact not in _CONTACTS:
        raise ArgumentError(f"`contact` must be one of {_CONTACTS}; got {contact!r}.")
    x, y, psi, th, phi = coordinates("x y psi theta phi")
    m, g, r = constants("m g r", positive=True)
    R0 = Frame("R0")
    A = R0.rotated("A", about=R0.k, angle=psi)
    B = A.rotated("B", about=A.i, angle=th)
    I0 = R0.point("I0", x, y, 0)
    G = I0.moved("G", r * B.j)
    D = B.rotated("D", about=B.k, angle=phi, origin=G)
    disc = Body("disc", frame=D, mass=m, centre=G,
                inertia=_inertia.disk(m, r, axis=D.k, centre=G))
    kinematics = (ContactKinematics.between(D, Circle(G, r, normal=D.k), R0,
                                            Plane(R0.origin, R0.k))
                  if contact == "between" else ContactKinematics(D, R0, at=I0, normal=R0.k))
    rolling = RollingContact(kinematics)
    s = System(galilean=R0)
    s.connect(R0, disc, rolling)
    s.act(gravity(-g * R0.k))
    return Model(s, (x, y, psi, th, phi), (m, g, r), (R0, A, B, D), (disc,), (I0, G),
                 (rolling,))


def wheel_on_incline(alpha, inertia: str = "disk") -> Model:
    """A wheel of radius r rolling without slipping on a line inclined by -alpha.

    The line passes through O along Ri.i (Ri = R0 turned by -alpha about k); x is the
    centre's abscissa along the slope (downwards positive for alpha > 0), theta the wheel's
    rotation about k; gravity ``-g R0.j`` (book, ch. 23.4).

    Parameters
    ----------
    alpha : number or sympy expression
        Slope of the line.
    inertia : {"disk", "ring"}, default "disk"
        The wheel's inertia: a uniform disk (m r^2 / 2) or a ring (m r^2).

    Returns
    -------
    Model
        coordinates (x, theta), constants (m, g, r), frames (R0, Ri, R1), bodies (wheel,),
        points (C,), connections (the rolling contact,).

    Examples
    --------
    >>> from rigidmech import models
    >>> wheel = models.wheel_on_incline(0)
    >>> wheel.system.mobility(plane=wheel.frame("R0").k).mobility
    1
    """
    if inertia not in _WHEEL_INERTIAS:
        raise ArgumentError(f"`inertia` must be one of {_WHEEL_INERTIAS}; got {inertia!r}.")
    x, th = coordinates("x theta")
    m, g, r = constants("m g r", positive=True)
    R0 = Frame("R0")
    Ri = R0.rotated("Ri", about=R0.k, angle=-alpha)
    C = R0.origin.moved("C", x * Ri.i + r * Ri.j)
    R1 = Ri.rotated("R1", about=R0.k, angle=th, origin=C)
    J = getattr(_inertia, inertia)(m, r, axis=R1.k, centre=C)
    wheel = Body("wheel", frame=R1, mass=m, centre=C, inertia=J)
    contact = ContactKinematics.between(R1, Circle(C, r, normal=R0.k), R0, Line(R0.origin, Ri.i))
    rolling = RollingContact(contact)
    s = System(galilean=R0)
    s.connect(R0, wheel, rolling)
    s.act(gravity(-g * R0.j))
    return Model(s, (x, th), (m, g, r), (R0, Ri, R1), (wheel,), (C,), (rolling,))


def ball_on_turntable(Omega=None) -> Model:
    """A uniform ball (mass m, radius r) on Euler parameters rolling without slipping on a
    horizontal turntable driven at the constant rate Omega about R0.k.

    The ball's centre is G = (x, y, r) in the Galilean R0 and its frame R is oriented
    relative to R0 by the Euler parameters (e0, e1, e2, e3) (book, ch. 9.1.2); inertia
    2 m r^2 / 5 about G. The table is a body whose frame Rt = R0 turned by Omega t about R0.k,
    pivoted to R0 about R0.k: its motion is prescribed, so it adds no parameter of situation
    and no equation (a driven support; its velocity at the contact, Omega k ^ GI, is the
    velocity of entrainment of ch. 17.1). The ball rolls on the table's plane (a
    :class:`~rigidmech.actions.RollingContact` of ``ContactKinematics.between`` the sphere
    and the plane; the sliding velocity of ch. 10.1 zero, ch. 13.1): two nonholonomic
    conditions, kept with Lagrange multipliers (ch. 25.3.3). Gravity ``-g R0.k``. The
    centre runs on a circle at the rate 2 Omega / 7 in R0.

    Parameters
    ----------
    Omega : number or sympy expression, optional
        The table's rate; a positive symbol ``Omega`` unless given.

    Returns
    -------
    Model
        coordinates (x, y, e0, e1, e2, e3), constants (m, r, g, Omega), frames (R0, Rt, R),
        bodies (table, ball), points (G,), connections (the rolling contact,).

    Examples
    --------
    >>> from rigidmech import models
    >>> ball = models.ball_on_turntable()
    >>> [b.name for b in ball.bodies], len(ball.system.constraints())
    (['table', 'ball'], 2)
    """
    x, y, e0, e1, e2, e3 = coordinates("x y e0 e1 e2 e3")
    m, r, g = constants("m r g", positive=True)
    if Omega is None:
        Omega = constants("Omega", positive=True)
    R0 = Frame("R0")
    Rt = R0.rotated("Rt", about=R0.k, angle=Omega * t)
    # the table's mass never enters: its motion is prescribed
    table = Body("table", frame=Rt, mass=1)
    G = R0.point("G", x, y, r)
    R = R0.euler_parameters("R", e0, e1, e2, e3, origin=G)
    ball = Body("ball", frame=R, mass=m, centre=G,
                inertia=_inertia.sphere(m, r, frame=R, centre=G))
    s = System(galilean=R0)
    s.connect(R0, table, Pivot(at=R0.origin, axis=R0.k))
    rolling = RollingContact(ContactKinematics.between(R, Sphere(G, r), Rt,
                                                       Plane(Rt.origin, Rt.k)))
    s.connect(table, ball, rolling)
    s.act(gravity(-g * R0.k))
    return Model(s, (x, y, e0, e1, e2, e3), (m, r, g, Omega), (R0, Rt, R), (table, ball), (G,),
                 (rolling,))
