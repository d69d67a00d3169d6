"""Part I of the book: the vector space, the geometric space, vector functions, curves
(ch. 1-4).

Frames (reference systems) forming a tree, vectors that may mix bases, points, parameters of
situation as functions of time; bases that need not be orthonormal, lines and planes, changes
of reference system, derivatives of vector functions, curves and the Frenet trihedron.
"""

from .basis import Basis, double_cross, linear_dependence, linearly_independent
from .curves import Curve, FrenetSamples, FrenetTrihedron, frenet_numeric
from .euler_parameters import euler_parameter_matrix, euler_parameter_rates, euler_parameters_of
from .frames import Frame
from .functions import derivation_formula, derivative, jacobian, partial
from .geometry import (
    Line,
    Plane,
    angle,
    common_perpendicular,
    distance,
    intersection,
    is_orthogonal,
    is_parallel,
)
from .orientation import axis_angle, euler_angle_rates, rotation_between
from .points import Point
from .reference_change import (
    affine_map,
    change_of_coordinates,
    common_axis_map,
    common_origin_map,
)
from .singularities import OrientationSingularity, orientation_singularity
from .symbols import (
    constants,
    coordinates,
    declared_order,
    is_coordinate,
    partial_derivative,
    t,
    time_derivative,
)
from .vector import Vector, cross, dot, mixed, partial_rotation_vector, rotation_vector

__all__ = [
    "Frame", "Point", "Vector", "t", "coordinates", "constants", "is_coordinate",
    "time_derivative", "partial_derivative", "dot", "cross", "mixed", "rotation_vector",
    "partial_rotation_vector",
    "Basis", "double_cross", "linear_dependence", "linearly_independent",
    "Line", "Plane", "angle", "common_perpendicular", "distance", "intersection",
    "is_orthogonal", "is_parallel",
    "affine_map", "change_of_coordinates", "common_axis_map", "common_origin_map",
    "derivation_formula", "derivative", "jacobian", "partial",
    "Curve", "FrenetSamples", "FrenetTrihedron", "frenet_numeric",
    "declared_order",
    "OrientationSingularity", "orientation_singularity",
    "euler_angle_rates", "rotation_between", "axis_angle",
    "euler_parameter_matrix", "euler_parameter_rates", "euler_parameters_of",
]
