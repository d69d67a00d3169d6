"""Part II of the book, kinematics (ch. 6-10): solids, kinematic torsors, composition."""

from .solid import KinematicTorsor, Solid, kinematic_torsor

__all__ = ["KinematicTorsor", "Solid", "kinematic_torsor"]
from .contact import Contact  # noqa: E402  (ch. 10)
from .plane_motion import Centrodes, centrodes, instantaneous_centre  # noqa: E402
from .surfaces import Circle, ContactGeometry, Cylinder, Sphere, contact_geometry  # noqa: E402
from .transmissions import (  # noqa: E402
    BeltDrive,
    EpicyclicTrain,
    Gear,
    GearPair,
    GearTrain,
)

__all__ += ["Contact", "Centrodes", "centrodes", "instantaneous_centre", "Circle",
            "ContactGeometry", "Cylinder", "Sphere", "contact_geometry", "BeltDrive",
            "EpicyclicTrain", "Gear", "GearPair", "GearTrain"]
from .constraints import VelocityConstraint  # noqa: E402  (ch. 10.1.3, 25.3)

__all__ += ["VelocityConstraint"]
