"""Pictures of a system (book, ch. 13, 20, 25): bodies by their shapes, frames, connections.

The numeric core: :class:`Placer` / :func:`place` evaluate a system at a state into
positions and rotation matrices (:class:`Placement`); :class:`View` maps them onto a plane
or into space; :func:`draw_body` draws one body by its shape.
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
