"""Part III of the book, mechanical actions (ch. 11-14): action torsors, power, gravity,
connections."""

from .actions import Action, Couple, Force, Gravity, Spring, gravity, power
from .joints import Joint, Pivot, Prismatic

__all__ = ["Action", "Couple", "Force", "Gravity", "Spring", "gravity", "power", "Joint",
           "Pivot", "Prismatic"]
