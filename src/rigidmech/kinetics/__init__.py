"""Part IV of the book, kinetics (ch. 16-17): bodies, kinetic and dynamic torsors, kinetic
energy."""

from .body import Body

__all__ = ["Body"]
