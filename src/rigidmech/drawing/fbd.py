"""Free-body diagrams: a body or a set of bodies isolated, with every action the rest of the
world exerts on it drawn as the book draws it (ch. 11.1, 13.1-13.2, 14.2.3).

* a force is an arrow from its point of application (a weight from the mass centre, a spring
  or damper from its end);
* a couple is a curved arrow in the plane, a double arrow in space;
* a connection's action is shown by its unknown components, each an arrow along its axis
  labelled with the book's name (``X_A``, ``Y_A``, ``N_A``, ``T_A``...; a couple for the
  moment components ``L_A, M_A, N_A``), or, once its values are known (a statics solve, a
  state of a motion, a limiting equilibrium), by the arrow of its resultant, labelled with
  the values of its components;
* a contact with friction also shows its friction cone (half-angle arctan f_s) and, when
  the action lies on the cone's edge (limiting equilibrium, sliding), that edge highlighted.

A planar system (every point in the plane z = 0 of the reference, every known force in it and
every known moment along z) is drawn in 2D, in the reference's (x, y) plane, showing only
the components in that plane; otherwise in 3D. Known forces are drawn to one scale (force
per unit of length) shown by the force-scale key.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError
from . import arrows as _arrows
from ._fbd_sources import Source, plan, state_numbers
from .bodies import View, draw_body
from .fbd_actions import _build, _frozen
from .placement import Placer

__all__ = ["FreeBodyDiagram", "DrawnArrow", "free_body_diagram", "draw_actions", "NEGLIGIBLE"]

_PLANE_TOL = 1e-9   # |z| / scale below which a point or a force is in the plane z = 0
#: a force below NEGLIGIBLE * (scale * length), a moment below NEGLIGIBLE * (scale *
#: length^2), is rounding noise (the moment of a pivot's action at its point): not drawn
NEGLIGIBLE = 1e-9


@dataclass(frozen=True)
class DrawnArrow:
    """A straight arrow of a diagram: its name, its artist, its tail and its vector (data
    units: the force divided by the scale)."""

    name: str
    artist: object
    tail: np.ndarray
    vector: np.ndarray


@dataclass
class FreeBodyDiagram:
    """A drawn free-body diagram: the axes, the actions (:class:`ExternalAction`) and the
    artists, by kind.

    Attributes
    ----------
    ax : matplotlib Axes
    actions : tuple of ExternalAction
        The actions, in the reference's basis.
    dim : int
        2 or 3.
    scale : float or None
        Force per unit of length of the arrows of known forces (None: no known force).
    arrows : list of DrawnArrow
        The straight arrows of forces, with their names, tails and vectors in the view's
        coordinates (``view.rows @`` the reference's components).
    couples : list of (str, list of artists)
        The couples (curved or double arrows), with their names.
    labels : list of matplotlib Text
        The labels of the actions (names and values).
    cones : list of (str, list of Line, Line or None)
        The friction cones by contact label, with their highlighted edge.
    key : list of artists
        The force-scale key.
    view : View
        How the reference's coordinates map to the axes (:class:`View`): for a System at a
        state, the view of its placement (gravity down the page); otherwise the reference's
        own axes.
    bodies : list of artists
        The isolated bodies.
    """

    ax: object
    actions: tuple
    dim: int
    scale: float | None
    view: object = None
    arrows: list = field(default_factory=list)
    couples: list = field(default_factory=list)
    labels: list = field(default_factory=list)
    cones: list = field(default_factory=list)
    key: list = field(default_factory=list)
    bodies: list = field(default_factory=list)

    @property
    def figure(self):
        """The figure of :attr:`ax`."""
        return self.ax.figure

    @property
    def label_texts(self) -> list:
        """The texts of :attr:`labels`."""
        return [t.get_text() for t in self.labels]


def _fmt(v):
    s = f"{v:.3g}"
    return "0" if s in ("-0", "0", "-0.0") else s


def rotated(actions, rows):
    """``actions`` with every vector in the coordinates of the basis ``rows`` (a rotation:
    moments turn as vectors)."""
    R = np.asarray(rows, dtype=float)

    def rot(v):
        return None if v is None else _frozen(R @ v)

    out = []
    for a in actions:
        comps = tuple(replace(c, direction=rot(c.direction)) for c in a.components)
        cone = None if a.cone is None else replace(a.cone, normal=rot(a.cone.normal),
                                                   side=rot(a.cone.side))
        out.append(replace(a, point=rot(a.point), force=rot(a.force), moment=rot(a.moment),
                           components=comps, cone=cone))
    return tuple(out)


def planar(actions) -> bool:
    """Whether ``actions`` lie in the plane z = 0: points, known forces, known moments
    along z (relative tolerance 1e-9)."""
    pts = np.array([a.point for a in actions]) if actions else np.zeros((0, 3))
    size = max(float(np.ptp(pts, axis=0).max()) if len(pts) else 0.0, 1.0)
    if len(pts) and np.abs(pts[:, 2]).max() > _PLANE_TOL * size:
        return False
    for a in actions:
        for v, out in ((a.force, slice(2, 3)), (a.moment, slice(0, 2))):
            if v is not None and np.abs(v[out]).max() > _PLANE_TOL * max(
                    float(np.linalg.norm(v)), 1e-300):
                return False
    return True


def _in_view(direction, kind, dim):
    if dim == 3:
        return True
    if kind == "force":
        return float(np.linalg.norm(direction[:2])) > _PLANE_TOL
    return abs(float(direction[2])) > _PLANE_TOL


def _extent(actions, placement=None):
    pts = [a.point for a in actions]
    if placement is not None:
        pts += list(placement.extent())
    if not pts:
        return 1.0
    size = float(np.ptp(np.array(pts), axis=0).max())
    return size if size > 0 else 1.0


def _default_scale(actions_sets, length):
    biggest = 0.0
    for actions in actions_sets:
        for a in actions:
            if a.force is not None and a.kind != "couple":
                biggest = max(biggest, float(np.linalg.norm(a.force)))
    return biggest / (0.45 * length) if biggest > 0 else None


class _Painter:
    """Draws actions on an Axes at one scale and records the artists."""

    def __init__(self, diagram, length, show_values):
        self.d, self.length, self.show = diagram, length, show_values
        self.tips = []

    def text(self, at, s, color):
        if self.d.dim == 2:       # beside the tip, a few points off
            t = self.d.ax.annotate(s, tuple(at[:2]), xytext=(4, 3), textcoords="offset points",
                                   color=color, fontsize=9, ha="left", va="bottom", zorder=5)
        else:
            t = self.d.ax.text(*at, s, color=color, fontsize=9, ha="left", va="bottom",
                               zorder=5)
        self.d.labels.append(t)

    def arrow(self, name, tail, vec, color, label):
        art = _arrows.force_arrow(self.d.ax, tail, vec, dim=self.d.dim, color=color)
        self.d.arrows.append(DrawnArrow(name, art, np.array(tail), np.array(vec)))
        self.tips += [tail, tail + vec]
        if label:
            self.text(tail + vec, label, color)

    def couple(self, name, at, moment, color, label):
        r = 0.12 * self.length
        arts = _arrows.couple_arrow(self.d.ax, at, moment, radius=r, dim=self.d.dim,
                                    color=color)
        self.d.couples.append((name, arts))
        self.tips += [at - r, at + r]
        if label:
            self.text(at + np.array([r, r, 0.0]) * 0.8, label, color)

    def visible(self, v, power=1):
        """Whether ``v`` (a force, or a moment with ``power`` 2) is above rounding noise."""
        ref = (self.d.scale or 0.0) * self.length**power
        return float(np.linalg.norm(v)) > NEGLIGIBLE * ref and np.any(v != 0)

    def vector(self, force):
        n = float(np.linalg.norm(force))
        if self.d.scale is None:
            return force / n * 0.35 * self.length if n else force
        return force / self.d.scale

    def given(self, a):
        colour = _arrows.COLOURS["given"]
        if a.kind == "couple":
            m = a.moment if self.d.dim == 3 else np.array([0.0, 0.0, a.moment[2]])
            if self.visible(m, 2):
                value = np.linalg.norm(m) if self.d.dim == 3 else m[2]
                self.couple(a.label, a.point, m, colour,
                            f"{a.label} = {_fmt(value)}" if self.show else a.label)
            return
        if self.visible(a.force):
            self.arrow(a.label, a.point, self.vector(a.force), colour,
                       f"{a.label} = {_fmt(np.linalg.norm(a.force))}" if self.show
                       else a.label)

    def connection(self, a):
        colour = _arrows.COLOURS["connection"]
        comps = [c for c in a.components if _in_view(c.direction, c.kind, self.d.dim)]
        arrow_length = 0.3 * self.length
        if a.force is not None:
            forces = [c for c in comps if c.kind == "force"]
            moments = [c for c in comps if c.kind == "moment"]
            text = ", ".join(f"{c.name} = {_fmt(c.value)}" for c in forces)
            mtext = ", ".join(f"{c.name} = {_fmt(c.value)}" for c in moments)
            m = a.moment if self.d.dim == 3 else np.array([0.0, 0.0, a.moment[2]])
            couple = bool(moments) and self.visible(m, 2)
            if mtext and not couple:       # a zero moment: its value beside the forces'
                text = ", ".join(x for x in (text, mtext) if x)
            f = a.force if self.d.dim == 3 else np.array([a.force[0], a.force[1], 0.0])
            if self.visible(f):
                vec = self.vector(f)
                arrow_length = float(np.linalg.norm(vec))
                self.arrow(a.label, a.point, vec, colour, text if self.show else a.label)
            elif text:
                self.text(a.point, text if self.show else a.label, colour)
            if couple:
                self.couple(a.label, a.point, m, colour, mtext if self.show else a.label)
        else:
            for c in comps:
                if c.kind == "force":
                    vec = c.direction * (arrow_length if c.value is None
                                         else c.value / self.d.scale if self.d.scale
                                         else np.sign(c.value) * arrow_length)
                    label = c.name if c.value is None or not self.show \
                        else f"{c.name} = {_fmt(c.value)}"
                    self.arrow(c.name, a.point, vec, colour, label)
                else:
                    self.couple(c.name, a.point, c.direction, colour, c.name)
        if a.cone is not None:
            lines, edge = _arrows.cone_lines(
                self.d.ax, a.point, a.cone.normal, a.cone.half_angle,
                1.3 * max(arrow_length, 0.3 * self.length), dim=self.d.dim,
                side=a.cone.side, on_edge=a.cone.status == "edge")
            self.d.cones.append((a.label, lines, edge))


def draw_actions(ax, actions, *, dim=2, scale=None, length=1.0, show_values=True,
                 key=True, unit="N", view=None) -> FreeBodyDiagram:
    """Draw ``actions`` (:class:`ExternalAction`) on ``ax`` at ``scale`` (force per unit of
    length; None: every arrow 0.35 ``length`` long) and return the diagram (no body is
    drawn). ``length`` is the size of the diagram (the spread of the points); ``view`` (a
    :class:`View`) maps the reference's coordinates to the axes (default: the reference's
    own x, y, z).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import rigidmech as rm
    >>> from rigidmech.actions import ContactLaws, Force
    >>> from rigidmech.drawing import external_actions
    >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
    >>> st = rm.statics.Statics(R0)
    >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
    >>> st.act(Force(on=box, vector=-10 * R0.j, at=R0.point("G", 0, 1, 0)))
    >>> fig, ax = plt.subplots()
    >>> d = draw_actions(ax, external_actions(st, box, equilibrium=st.solve()), scale=10.0)
    >>> len(d.arrows), d.label_texts
    (2, ['N_A = 10', 'F = 10'])
    >>> plt.close(fig)
    """
    view = View(np.eye(3), dim) if view is None else view
    diagram = FreeBodyDiagram(ax, tuple(actions), dim, scale, view)
    painter = _Painter(diagram, length, show_values)
    seen = rotated(diagram.actions, view.rows)
    for a in seen:
        if a.kind in ("connection", "contact", "rolling"):
            painter.connection(a)
        else:
            painter.given(a)
    _limits(ax, [a.point for a in seen] + painter.tips, dim, length)
    if key and scale is not None:
        diagram.key, _ = _arrows.scale_key(ax, scale, 0.25 * length, dim=dim, unit=unit)
    return diagram


def _limits(ax, points, dim, length, *, with_data=True):
    """Limits holding ``points`` with a margin of a quarter of ``length`` and, in 2D with
    ``with_data``, everything already drawn (the bodies by their shapes)."""
    pts = np.array(points, dtype=float).reshape(-1, 3)
    lo, hi = pts.min(axis=0) - 0.25 * length, pts.max(axis=0) + 0.25 * length
    if dim == 2 and with_data:
        box = ax.dataLim
        if np.all(np.isfinite([box.x0, box.x1, box.y0, box.y1])):
            lo[:2] = np.minimum(lo[:2], [box.x0 - 0.1 * length, box.y0 - 0.1 * length])
            hi[:2] = np.maximum(hi[:2], [box.x1 + 0.1 * length, box.y1 + 0.1 * length])
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    if dim == 3:
        ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect(hi - lo)
    else:
        ax.set_aspect("equal")
    return lo, hi


def _axes(ax, dim):
    import matplotlib.pyplot as plt

    if ax is None:
        fig = plt.figure()
        return fig.add_subplot(projection="3d" if dim == 3 else None)
    from matplotlib.axes import Axes

    if not isinstance(ax, Axes):
        raise ArgumentTypeError(f"`ax` must be a matplotlib Axes (or None for a new figure); "
                                f"got {type(ax).__name__}.")
    is3d = getattr(ax, "name", "") == "3d"
    if is3d != (dim == 3):
        raise ArgumentError(
            f"`ax` must be a {'3D' if dim == 3 else '2D'} Axes for this {dim}D diagram; got a "
            f"{'3D' if is3d else '2D'} one. Pass ax=None, or dim= to choose.")
    return ax


def _check_dim(dim, actions):
    if dim is None:
        return 2 if planar(actions) else 3
    if dim not in (2, 3):
        raise ArgumentError(f"`dim` must be 2, 3 or None (chosen from the system); got {dim!r}.")
    if dim == 2 and not planar(actions):
        raise ArgumentError(
            "`dim` = 2 needs a planar diagram (points in z = 0, forces in that plane, moments "
            "along z); got out-of-plane actions. Pass dim=3 or None.")
    return dim


def _check_scale(scale):
    if scale is None:
        return None
    try:
        s = float(scale)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`scale` must be a number (force per unit of length); "
                                f"got {scale!r}.") from None
    if not (np.isfinite(s) and s > 0):
        raise ArgumentError(f"`scale` must be a finite number > 0 (force per unit of length); "
                            f"got {scale!r}.")
    return s


def free_body_diagram(system, bodies, *, q=None, u=None, t=0.0, params=None,
                      equilibrium=None, values=None, ax=None, dim=None, scale=None,
                      show_values=True, key=True, unit="N") -> FreeBodyDiagram:
    """Draw the free-body diagram of ``bodies``: the body or set of bodies isolated, with
    every action exerted on it by the rest of ``system`` (ch. 14.2.3).

    Parameters
    ----------
    system : System, Model, Mechanism or Statics
        A :class:`~rigidmech.models.Model` stands for its system.
    bodies : Body or sequence of Body
        The isolated set; actions between its bodies are internal and not drawn.
    q, u, t, params, equilibrium, values
        The state and the values, as for :func:`~rigidmech.drawing.external_actions`.
    ax : matplotlib Axes, optional
        Where to draw (2D, or 3D for a diagram in space); default a new figure.
    dim : {2, 3, None}
        None: 2 for a planar diagram, 3 otherwise.
    scale : float, optional
        Force per unit of length of the arrows of known forces; default the largest known
        force drawn 0.45 times the size of the diagram.
    show_values : bool
        Write the known values beside the names.
    key : bool
        Draw the force-scale key (when some force is known).
    unit : str
        The unit of force written in the key.

    Returns
    -------
    FreeBodyDiagram

    Examples
    --------
    A block on a rough incline (f_s = 0.5, slope 0.3 rad) at rest: its weight and the
    action of the plane, inside the friction cone.

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import rigidmech as rm
    >>> from rigidmech.actions import ContactLaws, Coulomb
    >>> from rigidmech import models
    >>> block = models.block_on_incline()
    >>> R0, Ri, _ = block.frames
    >>> st = rm.statics.Statics(R0)
    >>> st.connect(R0, block.bodies[0], ContactLaws(at=block.points[0], normal=Ri.j,
    ...            tangent=Ri.i, friction=Coulomb(0.5)), label="A")
    >>> st.act(rm.gravity(-rm.constants("g", positive=True) * R0.j))
    >>> numbers = {"m": 2.0, "g": 9.81, "alpha": 0.3}
    >>> d = free_body_diagram(st, block.bodies[0], params=numbers,
    ...                       q={"x": 1.0}, equilibrium=st.solve(values=numbers))
    >>> d.label_texts
    ['N_A = 18.7, T_A = -5.8', 'W = 19.6']
    >>> d.actions[0].cone.status
    'inside'
    >>> plt.close("all")
    """
    source = Source(system, bodies)
    dynamic = source.dynamics is not None and q is not None
    items = plan(source, equilibrium=equilibrium, values=values, dynamic=dynamic)
    numbers = state_numbers(source, items, q=q, u=u, t=t, params=params)
    actions = _build(items, numbers)
    scale = _check_scale(scale)
    placement = None
    if source.dynamics is not None and (q is not None or not source.dynamics.coordinates):
        placement = Placer(source.dynamics, params).at([] if q is None else q, t)
    view, dim = _view(placement, actions, dim)
    ax = _axes(ax, dim)
    length = _extent(actions, placement)
    if scale is None:
        scale = _default_scale([actions], length)
    drawn = _draw_bodies(ax, source.bodies, placement, view, actions, length)
    d = draw_actions(ax, actions, dim=dim, scale=scale, length=length,
                     show_values=show_values, key=key, unit=unit, view=view)
    d.bodies = drawn
    return d


def _view(placement, actions, dim):
    """The View (and dim) of a diagram: that of the placement when there is one (its plane,
    gravity down), the reference's axes otherwise; planar means the actions too lie in the
    view's plane."""
    if dim is not None and dim not in (2, 3):
        raise ArgumentError(f"`dim` must be 2, 3 or None (chosen from the system); got {dim!r}.")
    if placement is None:
        dim = _check_dim(dim, actions)
        return View(np.eye(3), dim), dim
    view = View.of(placement, dim)
    seen = rotated(actions, view.rows)
    if view.dim == 2 and not planar(seen):
        if dim == 2:
            raise ArgumentError(
                "`dim` = 2 needs a planar diagram (points in the plane, forces in it, moments "
                "normal to it); got out-of-plane actions. Pass dim=3 or None.")
        view = View.of(placement, 3)
    return view, view.dim


def _draw_bodies(ax, bodies, placement, view, actions, length):
    if placement is None:
        return _draw_isolated(ax, actions, view.dim, length)
    return [a for b in bodies for a in draw_body(ax, b, placement, view, color="0.75",
                                                 zorder=1)]


def _draw_isolated(ax, actions, dim, length):
    """The isolated set of a Statics or a Mechanism (no placement to draw its bodies by
    their shapes), drawn minimally: a bar through the points where the actions are exerted,
    or a small square around a single point."""
    pts = np.unique(np.round(np.array([a.point for a in actions]), 12), axis=0)
    style = dict(color="0.85", zorder=1)
    if dim == 3:
        return ax.plot(*pts.T, "o-", color="0.6")
    if len(pts) == 1:
        h = 0.1 * length
        x, y = pts[0][:2]
        return ax.fill([x - h, x + h, x + h, x - h], [y - h, y - h, y + h, y + h], **style)
    centred = pts[:, :2] - pts[:, :2].mean(axis=0)
    axis = np.linalg.svd(centred)[2][0]
    order = np.argsort(centred @ axis)
    return ax.plot(*pts[order, :2].T, color="0.7", linewidth=6, solid_capstyle="round",
                   zorder=1)
