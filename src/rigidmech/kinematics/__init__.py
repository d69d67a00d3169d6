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
