"""Pictures of a system (book, ch. 13, 20, 25, 27): bodies by their shapes, connections by
their symbols, the ground hatched, frames as trihedra; at a state or along a motion.

* :func:`draw` draws a system at a state (a :class:`Drawing`: figure, axes and what was drawn
  where), :meth:`Drawing.save` writes it as PNG, SVG or PDF;
* :func:`animate` draws it along a simulated motion (a matplotlib ``FuncAnimation``, a GIF
  through pillow);
* the numeric core: :class:`Placer` / :func:`place` evaluate a system at a state into
  positions and rotation matrices (:class:`Placement`); :class:`View` maps them onto a plane
  or into space; :func:`draw_body`, :func:`draw_connection`, :func:`draw_frame` and
  :func:`draw_spring` draw one element on given axes;
* free-body diagrams (ch. 13-14): :func:`free_body_diagram` draws a body or a set of bodies
  isolated with the actions exerted on it (:func:`external_actions` gives them in numbers);
  :func:`free_body_motion` draws them along a simulation.

Examples
--------
>>> import matplotlib
>>> matplotlib.use("Agg")
>>> from rigidmech import drawing, models
>>> d = drawing.draw(models.four_bar(), [1.2, -0.9266, 1.3776])
>>> sorted(c.point for c in d.connections)
['B', 'C', 'D', 'O']
>>> import matplotlib.pyplot as plt; plt.close(d.figure)
"""

from .animation import animate, sample_motion, save_animation
from .bodies import View, draw_body, is_3d, shape_mesh
from .placement import Placement, Placer, connection_point, place
from .symbols import ConnectionSymbol, connection_kind, draw_connection, draw_frame, draw_spring
from .system import FIGURE_FORMATS, Drawing, draw

__all__ = ["Placer", "Placement", "place", "connection_point", "View", "draw_body",
           "shape_mesh", "is_3d", "ConnectionSymbol", "connection_kind", "draw_connection",
           "draw_frame", "draw_spring", "Drawing", "draw", "FIGURE_FORMATS",
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
