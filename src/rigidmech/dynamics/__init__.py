"""Part V of the book, dynamics (ch. 18-24): the fundamental principle for a set of bodies,
equations of motion, connection actions, simulation."""

from .equations import EquationsOfMotion, Simulation
from .simulation import Event, load_simulation
from .system import System

__all__ = ["EquationsOfMotion", "Simulation", "System"]
__all__ += ["Event", "load_simulation"]

from .assembly import assemble  # noqa: E402
from .constraints import Constraints  # noqa: E402

__all__ += ["Constraints", "assemble"]
from .reduced import ReducedEquations, reduce_equations  # noqa: E402

__all__ += ["ReducedEquations", "reduce_equations"]
from .inverse import inverse_dynamics  # noqa: E402

__all__ += ["inverse_dynamics"]
from .interop import from_sympy_mechanics, kane_form  # noqa: E402

__all__ += ["from_sympy_mechanics", "kane_form"]
