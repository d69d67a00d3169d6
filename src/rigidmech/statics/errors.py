"""The error of statics: no equilibrium (book, ch. 14)."""

from __future__ import annotations

from .._core.errors import RigidmechError

__all__ = ["EquilibriumError"]


class EquilibriumError(RigidmechError, ValueError):
    """The equations of statics have no solution: the given actions cannot be balanced.

    Examples
    --------
    >>> issubclass(EquilibriumError, ValueError)
    True
    """
