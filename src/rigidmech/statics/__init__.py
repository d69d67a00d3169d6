"""Statics of rigid bodies and of cables (book, ch. 14).

* :mod:`~rigidmech.statics.equilibrium`: :class:`Statics`, the equilibrium of a body or a set
  of bodies at rest (unknown connection actions, hyperstaticity, mechanisms), solved into an
  :class:`Equilibrium` (:mod:`~rigidmech.statics.solution`);
* :mod:`~rigidmech.statics.limits`: limiting equilibrium with friction (where sliding,
  tipping, rolling or lift-off starts, and which comes first);
* :mod:`~rigidmech.statics.cables`: heavy cables (catenary), cables under a load uniform
  along the horizontal (parabola), ropes and belts on rough cylinders (capstan).
"""

from .cables import (
    Catenary,
    ParabolicCable,
    belt_slip_torque,
    capstan_ratio,
    hoisting_force,
    holding_force,
)
from .equilibrium import Statics, StaticsConnection
from .errors import EquilibriumError
from .limits import Limit, largest_margin, limiting_equilibrium
from .solution import Equilibrium

__all__ = ["Catenary", "ParabolicCable", "capstan_ratio", "holding_force", "hoisting_force",
           "belt_slip_torque", "Statics", "StaticsConnection", "Equilibrium", "EquilibriumError",
           "limiting_equilibrium", "Limit", "largest_margin"]
