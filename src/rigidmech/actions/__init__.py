"""Part III of the book, mechanical actions (ch. 11-14): action torsors, power, gravity,
connections."""

from .actions import Action, Couple, Force, Gravity, Spring, gravity, power
from .contact_laws import ContactLaws, Coulomb, PivotingResistance, RollingResistance
from .dampers import Damper, TorsionalDamper, TorsionSpring, wire_torsional_stiffness
from .gravitation import (
    GRAVITATIONAL_CONSTANT,
    Attractor,
    NewtonAttraction,
    SphericalBodyAttraction,
    homogeneous_sphere_attractor,
    point_mass_attractor,
    spherical_shell_attractor,
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
__all__ += ["GRAVITATIONAL_CONSTANT", "Attractor", "point_mass_attractor",
            "homogeneous_sphere_attractor", "spherical_shell_attractor", "NewtonAttraction",
            "SphericalBodyAttraction", "surface_gravity"]
__all__ += ["work_along_path", "power_of", "work_along_motion", "curl", "is_conservative",
            "potential_energy_of"]
__all__ += ["Coulomb", "RollingResistance", "PivotingResistance", "ContactLaws"]
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
from .knife_edge import KnifeEdge  # noqa: E402

__all__ += ["KnifeEdge"]
__all__ += ["Damper", "TorsionalDamper", "TorsionSpring", "wire_torsional_stiffness"]

from .._core.deprecation import deprecated_aliases  # noqa: E402
from . import gravitation as _gravitation  # noqa: E402

# former names: ``Contact`` (also the name of rigidmech.kinematics.ContactKinematics) and the
# attractors ``point_mass``, ``spherical_shell`` (also inertia operators of rigidmech.inertia)
__getattr__ = deprecated_aliases(__name__, {
    "Contact": ("rigidmech.actions.ContactLaws", ContactLaws),
    **{old: (f"rigidmech.actions.{old}_attractor", getattr(_gravitation, f"{old}_attractor"))
       for old in ("point_mass", "homogeneous_sphere", "spherical_shell")}})
