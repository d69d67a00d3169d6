"""Statics of rigid bodies and cables (book, ch. 14)."""

from .cables import (
    Catenary,
    ParabolicCable,
    belt_slip_torque,
    capstan_ratio,
    hoisting_force,
    holding_force,
)

__all__ = ["Catenary", "ParabolicCable", "capstan_ratio", "holding_force", "hoisting_force",
           "belt_slip_torque"]
