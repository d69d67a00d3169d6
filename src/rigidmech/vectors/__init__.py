"""Part I of the book: the vector space, the geometric space, vector functions (ch. 1-4).

Frames (reference systems) forming a tree, vectors that may mix bases, points, and
parameters of situation as functions of time.
"""

from .frames import Frame
from .points import Point
from .symbols import constants, coordinates, is_coordinate, t, time_derivative
from .vector import Vector, cross, dot, mixed, partial_rotation_vector, rotation_vector

__all__ = [
    "Frame", "Point", "Vector", "t", "coordinates", "constants", "is_coordinate",
    "time_derivative", "dot", "cross", "mixed", "rotation_vector", "partial_rotation_vector",
]
