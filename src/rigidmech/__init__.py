"""rigidmech: mechanics of rigid bodies, the way J.-M. Berthelot's textbook teaches it."""

from .torsors import Torsor, couple, slider
from .vectors import Frame, Point, Vector, constants, coordinates, cross, dot, mixed, t

__version__ = "0.1.0"

__all__ = ["Frame", "Point", "Vector", "constants", "coordinates", "cross", "dot", "mixed", "t",
           "Torsor", "couple", "slider"]
