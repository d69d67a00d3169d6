"""Bodies on a floor with Coulomb friction, which may slide or roll (book, ch. 13.1,
23.4): a ball on a plane and an eccentric disc rocking on a line, built for
:func:`rigidmech.regimes.contact_motion`.
"""

from __future__ import annotations

import sympy as sp

from .. import inertia
from ..actions import Coulomb, FrictionContact, gravity
from ..dynamics import System
from ..kinematics import ContactKinematics
from ..kinetics import Body
from ..vectors import Frame, coordinates
from ._model import Model

__all__ = ["sliding_ball", "eccentric_disc"]


def sliding_ball(mu=0.3) -> Model:
    """A solid ball (mass m, radius r) on the plane z = 0 with Coulomb friction ``mu``.

    Centre C = (x, y, z), oriented by the rotations a (about i), b (about the new j), c
    (about the new k); the contact point I = (x, y, z - r), normal R0.k; gravity
    ``-g R0.k``. Launched without spin it slides, then rolls at 5/7 of its initial speed
    (book, ch. 13.1.2).

    Parameters
    ----------
    mu : float, default 0.3
        Coefficient of friction.

    Returns
    -------
    Model
        coordinates (x, y, z, a, b, c), constants (m, r, g), frames (R0, Ra, Rb, Rc),
        bodies (ball,), points (C, I), connections (the friction contact,).

    Examples
    --------
    >>> from rigidmech import models
    >>> ball = models.sliding_ball()
    >>> ball.body("ball").inertia.matrix[0, 0]
    2*m*r**2/5
    """
    x, y, z, a, b, c = coordinates("x y z a b c")
    m, r, g = sp.symbols("m r g", positive=True)
    R0 = Frame("R0")
    C = R0.point("C", x, y, z)
    Ra = R0.rotated("Ra", about=R0.i, angle=a, origin=C)
    Rb = Ra.rotated("Rb", about=Ra.j, angle=b)
    Rc = Rb.rotated("Rc", about=Rb.k, angle=c)
    ball = Body("ball", frame=Rc, mass=m, centre=C,
                inertia=inertia.sphere(m, r, frame=Rc, centre=C))
    I = R0.point("I", x, y, z - r)
    contact = FrictionContact(ContactKinematics(Rc, R0, at=I, normal=R0.k),
                              friction=Coulomb(mu))
    s = System(galilean=R0)
    s.connect(R0, ball, contact)
    s.act(gravity(-g * R0.k))
    return Model(s, (x, y, z, a, b, c), (m, r, g), (R0, Ra, Rb, Rc), (ball,), (C, I),
                 (contact,))


def eccentric_disc(mu=0.8) -> Model:
    """A disc (radius r, mass m) whose mass centre G is at ``ecc`` from its geometric
    centre C, rocking on the line y = 0 with Coulomb friction ``mu``.

    G = (x, y), rotation theta about k, C = G + ecc j1; the contact point I = (x_C, y_C - r),
    normal R0.j, the gap y_C - r; gravity ``-g R0.j``. Its contact conditions are nonlinear
    in the coordinates, so an integration at the acceleration level drifts off them (the
    model of the contact-drift checks; book, ch. 13.1, 23.4). The disc's inertia about G is
    taken as m r^2 / 2.

    Parameters
    ----------
    mu : float, default 0.8
        Coefficient of friction.

    Returns
    -------
    Model
        coordinates (x, y, theta), constants (m, r, ecc, g), frames (R0, R1), bodies
        (disk,), points (G, C, I), connections (the friction contact,).

    Examples
    --------
    >>> from rigidmech import models
    >>> disc = models.eccentric_disc()
    >>> disc.point("C").coordinates(disc.frame("R0"))[1]
    ecc*cos(theta(t)) + y(t)
    """
    x, y, th = coordinates("x y theta")
    m, r, ecc, g = sp.symbols("m r ecc g", positive=True)
    R0 = Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    C = G.moved("C", ecc * R1.j)
    xc, yc, _ = C.coordinates(R0)
    disk = Body("disk", frame=R1, mass=m, centre=G,
                inertia=inertia.disk(m, r, axis=R1.k, centre=G))
    I = R0.point("I", xc, yc - r, 0)
    contact = FrictionContact(ContactKinematics(R1, R0, at=I, normal=R0.j),
                              friction=Coulomb(mu), gap=yc - r)
    s = System(galilean=R0)
    s.connect(R0, disk, contact)
    s.act(gravity(-g * R0.j))
    return Model(s, (x, y, th), (m, r, ecc, g), (R0, R1), (disk,), (G, C, I), (contact,))
