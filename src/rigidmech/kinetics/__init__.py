"""Part IV of the book, kinetics (ch. 16-17): bodies, kinetic and dynamic torsors, kinetic
energy."""

from .body import Body
from .earth import EARTH_RADIUS, EARTH_ROTATION_RATE, EarthReference, earth_reference
from .inertial import (
    InertialActions,
    coriolis_dynamic_torsor,
    coriolis_inertial_torsor,
    entrainment_dynamic_torsor,
    entrainment_inertial_torsor,
)

__all__ = ["Body"]
__all__ += ["entrainment_dynamic_torsor", "coriolis_dynamic_torsor",
            "entrainment_inertial_torsor", "coriolis_inertial_torsor", "InertialActions"]
__all__ += ["EARTH_ROTATION_RATE", "EARTH_RADIUS", "EarthReference", "earth_reference"]
