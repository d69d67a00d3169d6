"""Drawings of systems and free-body diagrams (book, ch. 13-14)."""

from .fbd import FreeBodyDiagram, draw_actions, free_body_diagram
from .fbd_actions import Component, Cone, ExternalAction, external_actions, limiting_values
from .fbd_motion import FreeBodyMotion, free_body_motion

__all__ = ["Component", "Cone", "ExternalAction", "external_actions", "limiting_values",
           "FreeBodyDiagram", "free_body_diagram", "draw_actions", "FreeBodyMotion",
           "free_body_motion"]
