"""A block sliding without friction down an inclined plane (book, ch. 23.2.5, 27.4).

The simplest motion of a solid in translation along a fixed direction: the fundamental
principle along the slope gives m x'' = m g sin(alpha), so x(t) = x0 + v0 t + g sin(alpha)
t^2 / 2, and the normal action of the plane is m g cos(alpha).
"""

from __future__ import annotations

from ..actions import Prismatic, gravity
from ..dynamics import System
from ..kinetics import Body
from ..vectors import Frame, constants, coordinates
from ._model import Model

__all__ = ["block_on_incline"]


def block_on_incline() -> Model:
    """A block (mass m) sliding without friction on a plane inclined by alpha, gravity
    ``-g R0.j``.

    The slope is the line through O along Ri.i (Ri = R0 turned by -alpha about k); x is the
    abscissa of the block's centre P along it, downwards positive for alpha > 0 (book,
    ch. 23.2.5: the motion without friction; ch. 27.4).

    Returns
    -------
    Model
        coordinates (x,), constants (m, g, alpha), frames (R0, Ri, Rb), bodies (block,),
        points (P,).

    Examples
    --------
    >>> from rigidmech import models
    >>> eqs = models.block_on_incline().system.equations_of_motion()
    >>> eqs.mass_matrix, eqs.forcing
    (Matrix([[m]]), Matrix([[g*m*sin(alpha)]]))
    """
    x = coordinates("x")
    m, g, alpha = constants("m g alpha", positive=True)
    R0 = Frame("R0")
    Ri = R0.rotated("Ri", about=R0.k, angle=-alpha)
    P = R0.origin.moved("P", x * Ri.i)
    Rb = Ri.translated("Rb", P)
    block = Body("block", frame=Rb, mass=m, centre=P)
    s = System(galilean=R0)
    s.connect(R0, block, Prismatic(at=P, axis=Ri.i))
    s.act(gravity(-g * R0.j))
    return Model(s, (x,), (m, g, alpha), (R0, Ri, Rb), (block,), (P,))
