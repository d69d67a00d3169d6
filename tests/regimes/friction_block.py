"""The block of the friction tests: m = 1 on a rough floor (normal R0.j, N = m g = 1 with
g = 1), pulled back to O by a spring k = 1 of zero free length; x, y its coordinates."""

import rigidmech as rm
from rigidmech.actions import Coulomb, FrictionContact, Spring
from rigidmech.kinematics import ContactKinematics


def block(mu, g=1):
    """The system of the block with Coulomb's coefficient ``mu`` (static = kinetic), under
    gravity ``g`` (1 by default: N = 1)."""
    x, y = rm.coordinates("x y")
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.translated("R1", G)
    b = rm.Body("block", frame=R1, mass=1, centre=G)
    s = rm.System(galilean=R0)
    s.connect(R0, b, FrictionContact(ContactKinematics(
        R1, R0, at=R0.point("I", x, y, 0), normal=R0.j), friction=Coulomb(mu)))
    s.act(rm.gravity(-g * R0.j))
    s.act(Spring(1, 0, a=R0.origin, b=G, on_b=b))
    return s
