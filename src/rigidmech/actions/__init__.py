"""Part III of the book, mechanical actions (ch. 11-14): action torsors, power, gravity,
connections."""

from .actions import Action, Couple, Force, Gravity, Spring, gravity, power
from .joints import Cylindrical, Joint, Pivot, Prismatic, Spherical

__all__ = ["Action", "Couple", "Force", "Gravity", "Spring", "gravity", "power", "Joint",
           "Pivot", "Prismatic", "Cylindrical", "Spherical"]
from .connections import (  # noqa: E402  (the rest of the catalogue, ch. 13.2.2)
    BallJoint,
    CylinderPlane,
    Embedding,
    Fixed,
    Helical,
    LinearAnnular,
    LinearRectilinear,
    LineContact,
    Planar,
    PlanarSupport,
    PointContact,
    Revolute,
    Screw,
    Slide,
    SphereCylinder,
    SpherePlane,
    SphericalWithFinger,
)

__all__ += ["Helical", "SphericalWithFinger", "PlanarSupport", "LinearAnnular",
            "LinearRectilinear", "PointContact", "Embedding", "Screw", "Planar",
            "SphereCylinder", "LineContact", "CylinderPlane", "SpherePlane", "Fixed",
            "Revolute", "Slide", "BallJoint"]
from .contacts import GearMesh, RollingContact  # noqa: E402  (ch. 10.1.3, 10.2)

__all__ += ["RollingContact", "GearMesh"]
