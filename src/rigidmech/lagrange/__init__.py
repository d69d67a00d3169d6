"""Lagrange's equations (book, ch. 25): the equations of motion from the kinetic energy and
the power coefficients of the actions."""

from .equations import lagrange_equations

__all__ = ["lagrange_equations"]
