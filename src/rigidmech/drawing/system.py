"""A whole system drawn at a state: :func:`draw` (book, ch. 13.2, 20, 25).

The bodies by their shapes (:func:`~rigidmech.drawing.draw_body`), the connections by their
symbols with the ground hatched (:func:`~rigidmech.drawing.draw_connection`), the frames as
trihedra if asked; a planar system in the plane of its motion, any other in space, gravity
down the page. :class:`Drawing` keeps the figure and what was drawn where.
"""

from __future__ import annotations

import os
from typing import NamedTuple

import matplotlib.pyplot as plt
import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError
from ..actions import Damper, Spring
from ..systems import Link
from ..vectors import Frame
from .bodies import View, draw_body, is_3d, shape_mesh
from .placement import Placement, Placer
from .symbols import draw_connection, draw_frame, draw_spring

__all__ = ["Drawing", "draw", "FIGURE_FORMATS", "limits_of", "outline_points", "azimuth_of"]

#: The file formats :meth:`Drawing.save` writes.
FIGURE_FORMATS = ("png", "svg", "pdf")

#: Body colours, in the order of the system's bodies (matplotlib's "tab10", softened).
PALETTE = ("#4c78a8", "#f58518", "#54a24b", "#b279a2", "#e45756", "#72b7b2", "#eeca3b",
           "#9d755d", "#ff9da6", "#bab0ac")


class Drawing(NamedTuple):
    """A drawn system: the figure and axes, the placement and view it was drawn from, and
    the artists of each body (by name), of each connection
    (:class:`~rigidmech.drawing.ConnectionSymbol`) and of each frame (by name)."""

    figure: object
    ax: object
    placement: Placement
    view: View
    bodies: dict
    connections: tuple
    frames: dict

    def save(self, path, **savefig_kwargs) -> str:
        """Write the figure to ``path`` (``.png``, ``.svg`` or ``.pdf``); returns the path.

        Raises
        ------
        ArgumentError
            For another extension or a folder that does not exist.

        Examples
        --------
        >>> import os, tempfile, matplotlib
        >>> matplotlib.use("Agg")
        >>> from rigidmech import models
        >>> d = draw(models.compound_pendulum(), [0.5], {"L": 1.0})
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     path = d.save(os.path.join(folder, "pendulum.svg"))
        ...     os.path.getsize(path) > 1000
        True
        >>> import matplotlib.pyplot as plt; plt.close(d.figure)
        """
        path = os.fspath(path)
        ext = os.path.splitext(path)[1].lower().lstrip(".")
        if ext not in FIGURE_FORMATS:
            raise ArgumentError(
                f"`path` must end with one of .png, .svg, .pdf; got {path!r}.")
        folder = os.path.dirname(os.path.abspath(path))
        if not os.path.isdir(folder):
            raise ArgumentError(f"`path` is in a folder that does not exist: {folder}.")
        options = {"dpi": 150, "bbox_inches": "tight"}
        options.update(savefig_kwargs)
        self.figure.savefig(path, **options)
        return path


def _symbol_size(placement, view):
    low, high = placement.extent()
    span = float(np.max(high - low))
    dims = [placement.placer.number(d) for b in placement.system.bodies if b.shape is not None
            for d in b.shape.dimensions.values()]
    return 0.07 * max(span, max(dims, default=0.0), 1e-3)


def outline_points(placement, body) -> np.ndarray:
    """Points (N, 3) in the reference that the drawing of a body covers: its shape's mesh
    or a rod's ends, else its mass centre.

    Examples
    --------
    >>> from rigidmech import models
    >>> from rigidmech.drawing import place
    >>> m = models.compound_pendulum()
    >>> outline_points(place(m, [0.0], {"L": 2.0}), m.body("bar")).tolist()
    [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]
    """
    G = placement.point(body.centre)
    shape = body.shape
    if shape is None or shape.kind == "point_mass":
        return G[None, :]
    dims = {n: placement.placer.number(x) for n, x in shape.dimensions.items()}
    R = placement.rotation(shape.frame)
    if shape.kind == "rod":
        e = shape.axis_sign * R[:, shape.axis_index]
        return np.array([G - dims["length"] / 2 * e, G + dims["length"] / 2 * e])
    return shape_mesh(shape, dims)[0] @ R.T + G


def limits_of(placements, view, size):
    """(low, high) in the view's coordinates holding every compiled point and every body's
    outline in the placements, with a margin of 4 ``size`` for the symbols (an animation
    keeps one box for all its frames).

    Examples
    --------
    >>> from rigidmech import models
    >>> from rigidmech.drawing import View, place
    >>> p = place(models.compound_pendulum(), [0.0], {"L": 2.0})   # gravity along R0.i
    >>> low, high = limits_of([p], View.of(p), 0.1)
    >>> low.round(12).tolist(), high.round(12).tolist()
    ([-0.4, -2.4], [0.4, 0.4])
    """
    pts = [view.project(np.array(list(p.points.values()))) for p in placements]
    pts += [view.project(outline_points(p, b)) for p in placements for b in p.system.bodies]
    pts = np.vstack(pts)
    return pts.min(axis=0) - 4 * size, pts.max(axis=0) + 4 * size


def azimuth_of(placements, view) -> float:
    """The azimuth (degrees) of a 3D view that shows the spread of the points across: 60
    degrees off the direction of their largest horizontal spread (-60, matplotlib's
    default, when they have none).

    Examples
    --------
    >>> from rigidmech import models
    >>> from rigidmech.drawing import View, place
    >>> p = place(models.heavy_top(), [0.0, 0.0, 0.0], {"l": 1.0})    # the axis vertical
    >>> azimuth_of([p], View.of(p))
    -60.0
    """
    pts = np.vstack([view.project(np.array(list(p.points.values()))) for p in placements])
    spread = pts[:, :2] - pts[:, :2].mean(axis=0)
    if len(spread) < 2 or np.ptp(spread, axis=0).max() < 1e-9:
        return -60.0
    _, _, vt = np.linalg.svd(spread, full_matrices=False)
    return float(np.degrees(np.arctan2(vt[0, 1], vt[0, 0]))) - 60.0


def _set_limits(ax, view, limits):
    low, high = limits
    if view.dim == 2:
        ax.set_xlim(low[0], high[0])
        ax.set_ylim(low[1], high[1])
        ax.set_aspect("equal")
        return
    centre, half = (low + high) / 2, float(np.max(high - low)) / 2
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1))


def _axes(ax, view, figsize):
    if ax is not None:
        if (view.dim == 3) != is_3d(ax):
            want = "3D axes (projection='3d')" if view.dim == 3 else "2D axes"
            raise ArgumentError(
                f"`ax` must be {want} for a drawing in {view.dim}D; got "
                f"{'3D' if is_3d(ax) else '2D'} axes. Pass dim={5 - view.dim} or other axes.")
        return ax.figure, ax
    fig = plt.figure(figsize=figsize or ((5.5, 5.5) if view.dim == 3 else (5.5, 4.5)))
    ax = fig.add_subplot(projection="3d" if view.dim == 3 else None)
    return fig, ax


def _finish(ax, view, placement, limits, size, azim):
    if limits is None:
        limits = limits_of([placement], view, size)
    _set_limits(ax, view, limits)
    if view.dim == 2:
        ax.set_axis_off()
        return
    ax.view_init(elev=22, azim=azimuth_of([placement], view) if azim is None else azim)
    ax.grid(False)
    for name in ("x", "y", "z"):
        getattr(ax, f"set_{name}ticklabels")([])


def draw(system, q, params=None, *, t=0.0, ax=None, frames=False, labels=True, dim=None,
         figsize=None, title=None, limits=None, azim=None, placer=None) -> Drawing:
    """Draw a system at the state ``q``: bodies, connections, ground, frames (ch. 13.2, 20).

    Parameters
    ----------
    system : System or Model
    q : sequence of numbers, or dict by name
        The parameters of situation, in the order of ``system.coordinates``.
    params : dict, optional
        Values of the constants the positions and the shapes depend on (``{"L": 1.0}``).
    t : float, default 0
        The time (for frames moved with time).
    ax : matplotlib Axes, optional
        Axes to draw on (3D axes for a spatial drawing); default a new figure.
    frames : bool, default False
        Draw the frames of the bodies as trihedra.
    labels : bool, default True
        Write the bodies' names and the connection points' names.
    dim : {None, 2, 3}
        None: 2 for a planar system (:attr:`Placer.plane`), 3 otherwise.
    figsize : (float, float), optional
    title : str, optional
    limits : (array, array), optional
        The box (low, high) in the view's coordinates to show (animations keep one).
    azim : float, optional
        Azimuth of a 3D view, degrees (default: chosen to show the system across).
    placer : Placer, optional
        A compiled :class:`Placer` of this system to reuse (then ``params`` is its own).

    Returns
    -------
    Drawing

    Raises
    ------
    ArgumentError
        For a wrong number of coordinates, a missing constant, 2D axes for a spatial system.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from rigidmech import models
    >>> d = draw(models.double_pendulum(), [0.6, 1.2], {"L": 1.0})
    >>> sorted(d.bodies), [c.kind for c in d.connections], d.view.dim
    (['bar1', 'bar2'], ['pivot', 'pivot'], 2)
    >>> import matplotlib.pyplot as plt; plt.close(d.figure)
    """
    if placer is None:
        placer = Placer(system, params)
    elif not isinstance(placer, Placer):
        raise ArgumentTypeError(f"`placer` must be a Placer; got {type(placer).__name__}.")
    if dim not in (None, 2, 3):
        raise ArgumentError(f"`dim` must be None, 2 or 3; got {dim!r}.")
    placement = placer.at(q, t)
    view = View.of(placement, dim)
    fig, ax = _axes(ax, view, figsize)
    size = _symbol_size(placement, view)
    system = placer.system
    ground = system.mechanism.ground
    symbols = []
    meets = getattr(system, "meets", None)
    for link in system.mechanism.links:
        sym = draw_connection(ax, link, placement, view, size=size,
                              ground=link.first is ground or link.second is ground,
                              label=labels, meets=None if meets is None else meets(link))
        if sym is not None:
            symbols.append(sym)
    for n, (parent, child, contact) in enumerate(system.contacts):
        on_ground = isinstance(parent, Frame)
        link = Link(ground if on_ground else parent, child, contact, f"c{n + 1}")
        sym = draw_connection(ax, link, placement, view, size=size, ground=on_ground,
                              label=labels)
        if sym is not None:
            symbols.append(sym)
    for action in system.actions:
        if isinstance(action, Spring | Damper):
            draw_spring(ax, view.project(placement.point(action.a)),
                        view.project(placement.point(action.b)), size=size,
                        damper=isinstance(action, Damper),
                        ground_a=action.on_a is None)
    bodies = {}
    for n, body in enumerate(system.bodies):
        bodies[body.name] = draw_body(ax, body, placement, view, color=PALETTE[n % 10],
                                      size=1.5 * size, label=labels)
    drawn_frames = {}
    if frames:
        for f in [system.reference] + [b.frame for b in system.bodies]:
            drawn_frames[f.name] = draw_frame(ax, f, placement, view, size=2.5 * size)
    _finish(ax, view, placement, limits, size, azim)
    if title is not None:
        ax.set_title(title)
    return Drawing(fig, ax, placement, view, bodies, tuple(symbols), drawn_frames)
