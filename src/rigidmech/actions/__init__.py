"""Part III of the book, mechanical actions (ch. 11-14): action torsors, power, gravity,
connections."""

from .actions import Action, Couple, Force, Gravity, Spring, gravity, power
from .dampers import Damper, TorsionalDamper, TorsionSpring, wire_torsional_stiffness
from .joints import Cylindrical, Joint, Pivot, Prismatic, Spherical

__all__ = ["Action", "Couple", "Force", "Gravity", "Spring", "gravity", "power", "Joint",
           "Pivot", "Prismatic", "Cylindrical", "Spherical",
           "Damper", "TorsionalDamper", "TorsionSpring", "wire_torsional_stiffness"]
