"""The graph of bodies, connections and actions shared by statics, dynamics and vibrations
(book, ch. 13.2, 14.2): :class:`Mechanism`, its loops, degree of mobility and degree of
hyperstaticity."""

from .closure import closure_conditions, closure_forces
from .graph import Link, Mechanism
from .mobility import Mobility, analyse

__all__ = ["Mechanism", "Link", "Mobility", "analyse", "closure_conditions", "closure_forces"]
