"""Drawings of systems and free-body diagrams (book, ch. 13-14)."""

from .fbd_actions import Component, Cone, ExternalAction, external_actions, limiting_values

__all__ = ["Component", "Cone", "ExternalAction", "external_actions", "limiting_values"]
