"""Part III of the book, mechanical actions (ch. 11-14): action torsors, power, gravity,
connections."""

from .actions import Action, Couple, Force, Gravity, Spring, gravity, power
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
