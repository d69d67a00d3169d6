"""rigidmech: mechanics of rigid bodies, the way J.-M. Berthelot's textbook teaches it.

The public surface mirrors the book's parts: frames and vectors (Part I), torsors (ch. 5),
kinematics (Part II), actions and connections (Part III), inertia and kinetics (Part IV),
dynamics and Lagrange's equations (Part V), numerical solvers (Part VI).
"""

from . import actions, errors, inertia, ode, regimes, scenes, statics, vibrations
from . import actions as joints
from ._core.version import __version__ as __version__
from .actions import ContactLaws, Coulomb, Couple, Force, FrictionContact, Spring, gravity, power
from .dynamics import EquationsOfMotion, Simulation, System
from .inertia import InertiaOperator
from .kinematics import (
    KinematicTorsor,
    Solid,
    acceleration_composition,
    kinematic_torsor,
    velocity_composition,
)
from .kinetics import Body
from .lagrange import lagrange_equations
from .statics import Catenary, Statics
from .torsors import (
    Domain,
    Resolution,
    Torsor,
    couple,
    measure_centre,
    slider,
    torsor_of_field,
    torsor_of_sliders,
)
from .vectors import (
    Basis,
    Curve,
    Frame,
    Line,
    Plane,
    Point,
    Vector,
    change_of_coordinates,
    common_perpendicular,
    constants,
    coordinates,
    cross,
    distance,
    dot,
    double_cross,
    frenet_numeric,
    intersection,
    linearly_independent,
    mixed,
    t,
)

__all__ = [
    "Frame", "Point", "Vector", "constants", "coordinates", "cross", "dot", "mixed", "t",
    "Basis", "Line", "Plane", "Curve", "frenet_numeric", "intersection", "distance",
    "common_perpendicular", "change_of_coordinates", "linearly_independent", "double_cross",
    "Torsor", "couple", "slider", "Resolution", "Domain", "torsor_of_sliders",
    "torsor_of_field", "measure_centre",
    "Solid", "KinematicTorsor", "kinematic_torsor",
    "Force", "Couple", "Spring", "gravity", "power", "joints", "actions",
    "InertiaOperator", "inertia",
    "Body",
    "System", "EquationsOfMotion", "Simulation", "lagrange_equations",
    "ode", "scenes",
    "errors",
    "vibrations",
]
__all__ += ["velocity_composition", "acceleration_composition"]
__all__ += ["statics", "regimes", "Statics", "Catenary", "Coulomb", "ContactLaws",
            "FrictionContact"]

from . import systems  # noqa: E402
from .systems import Mechanism  # noqa: E402

__all__ += ["systems", "Mechanism"]

from . import models  # noqa: E402

__all__ += ["models"]

from ._core.deprecation import deprecated_aliases  # noqa: E402

# ``rm.Contact`` was ContactLaws (rigidmech.kinematics.Contact another class): renamed
__getattr__ = deprecated_aliases(__name__, {"Contact": ("rigidmech.ContactLaws", ContactLaws)})
