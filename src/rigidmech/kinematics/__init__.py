"""Part II of the book, kinematics (ch. 6-10): solids, kinematic torsors, composition."""

from .central import (
    areal_constant,
    areal_velocity,
    binet_acceleration,
    binet_speed_squared,
    is_central,
)
from .composition import Composition, acceleration_composition, velocity_composition
from .orbits import (
    HohmannTransfer,
    Orbit,
    circular_speed,
    escape_speed,
    hohmann_transfer,
    kepler_elliptic,
    kepler_hyperbolic,
)
from .solid import KinematicTorsor, Solid, kinematic_torsor

__all__ = ["KinematicTorsor", "Solid", "kinematic_torsor"]
__all__ += ["Composition", "velocity_composition", "acceleration_composition"]
__all__ += ["areal_velocity", "areal_constant", "is_central", "binet_speed_squared",
            "binet_acceleration"]
__all__ += ["Orbit", "HohmannTransfer", "kepler_elliptic", "kepler_hyperbolic",
            "circular_speed", "escape_speed", "hohmann_transfer"]
from .contact import ContactKinematics  # noqa: E402  (ch. 10)
from .plane_motion import Centrodes, centrodes, instantaneous_centre  # noqa: E402
from .surfaces import Circle, ContactGeometry, Cylinder, Sphere, contact_geometry  # noqa: E402
from .transmissions import (  # noqa: E402
    BeltDrive,
    EpicyclicTrain,
    Gear,
    GearPair,
    GearTrain,
)

__all__ += ["ContactKinematics", "Centrodes", "centrodes", "instantaneous_centre", "Circle",
            "ContactGeometry", "Cylinder", "Sphere", "contact_geometry", "BeltDrive",
            "EpicyclicTrain", "Gear", "GearPair", "GearTrain"]
from .constraints import VelocityConstraint  # noqa: E402  (ch. 10.1.3, 25.3)

__all__ += ["VelocityConstraint"]
from .linkages import dead_points, grashof_type, is_grashof, transmission_angle  # noqa: E402

__all__ += ["grashof_type", "is_grashof", "transmission_angle", "dead_points"]

from .._core.deprecation import deprecated_aliases  # noqa: E402

# ``Contact`` was the name of ContactKinematics; rigidmech.actions.ContactLaws was the other
# ``Contact``: two classes of one name in two namespaces
__getattr__ = deprecated_aliases(
    __name__, {"Contact": ("rigidmech.kinematics.ContactKinematics", ContactKinematics)})
