"""Pictures of a system (book, ch. 13, 20, 25): bodies by their shapes, frames, connections.

The numeric core: :class:`Placer` / :func:`place` evaluate a system at a state into
positions and rotation matrices (:class:`Placement`); :class:`View` maps them onto a plane
or into space; :func:`draw_body` draws one body by its shape.

Free-body diagrams (ch. 13-14): :func:`free_body_diagram` draws a body or a set of bodies
isolated with the actions exerted on it (:func:`external_actions` gives them in numbers);
:func:`free_body_motion` draws them along a simulation.
"""

from .animation import animate, sample_motion, save_animation
from .bodies import View, draw_body, is_3d, shape_mesh
from .placement import Placement, Placer, connection_point, place
from .symbols import ConnectionSymbol, connection_kind, draw_connection, draw_frame
from .system import FIGURE_FORMATS, Drawing, draw

__all__ = ["Placer", "Placement", "place", "connection_point", "View", "draw_body",
           "shape_mesh", "is_3d", "ConnectionSymbol", "connection_kind", "draw_connection",
           "draw_frame", "Drawing", "draw", "FIGURE_FORMATS",
           "animate", "sample_motion", "save_animation"]

from .fbd import FreeBodyDiagram, draw_actions, free_body_diagram  # noqa: E402
from .fbd_actions import (  # noqa: E402
    Component,
    Cone,
    ExternalAction,
    external_actions,
    limiting_values,
)
from .fbd_motion import FreeBodyMotion, free_body_motion  # noqa: E402

__all__ += ["Component", "Cone", "ExternalAction", "external_actions", "limiting_values",
            "FreeBodyDiagram", "free_body_diagram", "draw_actions", "FreeBodyMotion",
            "free_body_motion"]
