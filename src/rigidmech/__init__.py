"""rigidmech: mechanics of rigid bodies, the way J.-M. Berthelot's textbook teaches it.

The public surface mirrors the book's parts: frames and vectors (Part I), torsors (ch. 5),
kinematics (Part II), actions and connections (Part III), inertia and kinetics (Part IV),
dynamics and Lagrange's equations (Part V), numerical solvers (Part VI).
"""

import importlib as _importlib

from . import actions, errors, inertia, ode
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

__all__ += ["models"]
__all__ += ["drawing"]

from ._core.deprecation import deprecated_aliases  # noqa: E402

# ``rm.Contact`` was ContactLaws (rigidmech.kinematics.Contact another class): renamed
_deprecated = deprecated_aliases(__name__, {"Contact": ("rigidmech.ContactLaws", ContactLaws)})

# lazy: import cost (see docs/performance). These subpackages (and the names taken from them)
# are imported on first access, by this module ``__getattr__`` (PEP 562): ``rm.statics``,
# ``rm.Statics``, ``from rigidmech import *`` and ``dir(rm)`` are as if imported eagerly.
_LAZY_SUBPACKAGES = ("drawing", "lagrange", "models", "regimes", "scenes", "statics", "testing",
                     "vibrations")
_LAZY_NAMES = {"Catenary": "statics", "Statics": "statics", "lagrange_equations": "lagrange"}


def __getattr__(name):
    if name in _LAZY_SUBPACKAGES:
        value = _importlib.import_module(f"{__name__}.{name}")
    elif name in _LAZY_NAMES:
        value = getattr(_importlib.import_module(f"{__name__}.{_LAZY_NAMES[name]}"), name)
    else:
        return _deprecated(name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__) | set(_LAZY_SUBPACKAGES) | set(_LAZY_NAMES))
