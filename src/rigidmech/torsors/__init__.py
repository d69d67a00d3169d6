"""Torsors (book, ch. 5): one algebra for kinematic, action, kinetic and dynamic torsors."""

from .torsor import Torsor, couple, slider

__all__ = ["Torsor", "couple", "slider"]
