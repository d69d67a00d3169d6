"""Part III of the book, mechanical actions (ch. 11-14): action torsors, power, gravity,
connections."""

from .actions import Action, Couple, Force, Gravity, Spring, gravity, power
from .contact_laws import Contact, Coulomb, PivotingResistance, RollingResistance
from .dampers import Damper, TorsionalDamper, TorsionSpring, wire_torsional_stiffness
from .gravitation import (
    GRAVITATIONAL_CONSTANT,
    Attractor,
    NewtonAttraction,
    SphericalBodyAttraction,
    homogeneous_sphere,
    point_mass,
    spherical_shell,
    surface_gravity,
)
from .joints import Cylindrical, Joint, Pivot, Prismatic, Spherical
from .work import (
    curl,
    is_conservative,
    potential_energy_of,
    power_of,
    work_along_motion,
    work_along_path,
)

__all__ = ["Action", "Couple", "Force", "Gravity", "Spring", "gravity", "power", "Joint",
           "Pivot", "Prismatic", "Cylindrical", "Spherical"]
__all__ += ["GRAVITATIONAL_CONSTANT", "Attractor", "point_mass", "homogeneous_sphere",
            "spherical_shell", "NewtonAttraction", "SphericalBodyAttraction", "surface_gravity"]
__all__ += ["work_along_path", "power_of", "work_along_motion", "curl", "is_conservative",
            "potential_energy_of"]
__all__ += ["Coulomb", "RollingResistance", "PivotingResistance", "Contact"]
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
from .contacts import FrictionContact, GearMesh, RollingContact  # noqa: E402

__all__ += ["RollingContact", "GearMesh", "FrictionContact"]
__all__ += ["Damper", "TorsionalDamper", "TorsionSpring", "wire_torsional_stiffness"]
