"""The operator of inertia (book, ch. 15).

:class:`InertiaOperator` is the operator of inertia of a body at a point, held as its matrix in
the basis of a frame in the book's layout [[A, -F, -E], [-F, B, -D], [-E, -D, C]]. It changes
basis (:meth:`~InertiaOperator.in_basis`, ch. 15.2.4), changes point by the relations of
Huygens (:meth:`~InertiaOperator.moved`, ch. 15.2.2), gives the moment about any axis
(:meth:`~InertiaOperator.moment_about`, ch. 15.3.4) and the principal axes
(:meth:`~InertiaOperator.principal_axes`, ch. 15.2.3), and adds over the parts of a body
(ch. 15.4.4). The catalogue gives the operators of homogeneous bodies at their mass centre
(ch. 15.5).

Examples
--------
>>> import sympy as sp
>>> import rigidmech as rm
>>> m, L = sp.symbols("m L", positive=True)
>>> R0 = rm.Frame("R0")
>>> G = R0.point("G", L / 2, 0, 0)
>>> bar = rm.inertia.rod(m, L, axis=R0.i, centre=G)
>>> bar.moved(R0.origin, mass=m, centre=G).moment_about(R0.k)
L**2*m/3
"""

from .catalogue import (
    block,
    cone,
    cylinder,
    cylindrical_shell,
    disk,
    ellipsoid,
    hemisphere,
    hollow_cylinder,
    point_mass,
    rectangular_plate,
    ring,
    rod,
    sphere,
    spherical_shell,
    tube,
)
from .composite import MassProperties, Part, composite, mass_properties
from .operator import InertiaOperator
from .principal import PrincipalAxes, principal_axes
from .shapes import SHAPE_DIMENSIONS, Shape

__all__ = [
    "InertiaOperator", "PrincipalAxes", "principal_axes",
    "rod", "ring", "disk", "cylinder", "tube", "hollow_cylinder", "cylindrical_shell",
    "cone", "sphere", "spherical_shell", "block", "rectangular_plate", "ellipsoid",
    "hemisphere", "point_mass", "Part", "MassProperties", "composite", "mass_properties",
    "Shape", "SHAPE_DIMENSIONS",
]
