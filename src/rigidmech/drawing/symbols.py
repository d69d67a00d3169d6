"""Symbols of the connections and of the frames (book, ch. 13.2: the catalogue of connections).

Each connection of a system is drawn at its point with a symbol of the usual kinematic
sketches: a pivot as a small open circle, a slide as a block on its guide, a ball joint as a
ball in its socket, a planar support or a point contact as the tangent plane, a rolling contact
as the tangent plane under the contact point, an embedding as a welded square; a connection to
the ground gets the hatching of the ground (a support under a pivot or a ball joint, the
hatched side of a plane). A frame is drawn as a small trihedron of its basis vectors.

A joint that closes a loop (ch. 25.3) joins its point ``at`` (of the first solid) to the point
``meets`` of the second: at a state that does not close the loop the two are apart, and the
symbol is drawn at ``at`` with ``meets`` as a small open circle, named, joined to it by a
dashed line (the gap the closure conditions remove). The gap counted is what the joint does not
allow: along the normal for a contact or a planar support (its point moves on its plane),
across the axis for a slide, a cylindrical joint or a sphere in a cylinder, the whole distance
otherwise; a gap of at most :data:`MEETS_GAP` times the symbol's size is not drawn (invisible at
that scale).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.patches import Circle, FancyArrowPatch, Polygon, Rectangle, Wedge
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

from ..actions import Cylindrical, Embedding, Pivot, Prismatic, Spherical
from ..actions.connections import (
    Helical,
    LinearAnnular,
    LinearRectilinear,
    PlanarSupport,
    PointContact,
    SphericalWithFinger,
)
from .placement import connection_point

__all__ = ["ConnectionSymbol", "connection_kind", "draw_connection", "draw_frame",
           "draw_spring", "MEETS_GAP", "meets_apart"]

_INK = "0.15"

#: A loop-closing joint's ``meets`` point is drawn apart from its ``at`` point when their
#: distance exceeds this fraction of the symbol's size (smaller gaps are invisible).
MEETS_GAP = 0.1


def meets_apart(at, meets, size) -> bool:
    """True when the point ``meets`` (3 numbers in the reference) is drawn apart from the
    joint's point ``at``: their distance exceeds ``MEETS_GAP * size`` (the one rule).

    Examples
    --------
    >>> meets_apart([0, 0, 0], [0.1, 0, 0], size=1.0), meets_apart([0, 0, 0], [0.2, 0, 0], 1.0)
    (False, True)
    """
    gap = np.asarray(meets, dtype=float) - np.asarray(at, dtype=float)
    return bool(np.linalg.norm(gap) > MEETS_GAP * size)


class ConnectionSymbol(NamedTuple):
    """A connection as drawn: its kind, the label of its link, the name of its point, where
    the symbol is (on the axes: 2 or 3 numbers) and its artists; for a joint closing a loop
    at a state that leaves it open, where its ``meets`` point is drawn (None otherwise)."""

    kind: str
    label: str
    point: str
    at: np.ndarray
    artists: tuple
    meets: np.ndarray | None = None


def connection_kind(connection) -> str:
    """The symbol a connection is drawn with: ``"pivot"``, ``"slide"``, ``"cylindrical"``,
    ``"ball"``, ``"helical"``, ``"planar"``, ``"contact"``, ``"rolling"``, ``"knife"``,
    ``"gear"``, ``"embedding"`` or ``"connection"`` (any other).

    Examples
    --------
    >>> import rigidmech as rm
    >>> R0 = rm.Frame("R0")
    >>> connection_kind(rm.joints.Pivot(at=R0.origin, axis=R0.k))
    'pivot'
    >>> connection_kind(rm.actions.BallJoint(at=R0.origin))
    'ball'
    """
    table = ((Helical, "helical"), (Pivot, "pivot"), (Prismatic, "slide"),
             (Cylindrical, "cylindrical"), (SphericalWithFinger, "ball"), (Spherical, "ball"),
             (PlanarSupport, "planar"), (PointContact, "contact"),
             (LinearRectilinear, "contact"), (LinearAnnular, "contact"),
             (Embedding, "embedding"))
    for cls, kind in table:
        if isinstance(connection, cls):
            return kind
    name = type(connection).__name__
    return {"RollingContact": "rolling", "FrictionContact": "contact", "KnifeEdge": "knife",
            "GearMesh": "gear"}.get(name, "connection")


def _normal_of(connection):
    for owner in (connection, getattr(connection, "contact", None)):
        n = getattr(owner, "normal", None) if owner is not None else None
        if n is not None:
            return n
    return None


def _unit(v):
    n = np.linalg.norm(v)
    return v / n if n > 1e-12 else None


def _hatch_2d(ax, centre, along, away, length, s, zorder):
    """A ground line through ``centre`` along ``along`` with its hatching on the side
    ``away``."""
    base = np.array([centre - along * length / 2, centre + along * length / 2])
    line, = ax.plot(*base.T, color=_INK, lw=1.6, zorder=zorder)
    starts = centre + np.outer(np.linspace(-0.45, 0.5, 8) * length, along)
    strokes = [(p, p + 0.45 * s * (away - along)) for p in starts]
    coll = LineCollection(strokes, colors=_INK, linewidths=1.0, zorder=zorder)
    ax.add_collection(coll)
    return [line, coll]


def _plane_2d(ax, at, normal, towards_body, s, ground, zorder):
    n = _unit(normal)
    if n is None:
        n = np.array([0.0, 1.0])
    if towards_body is not None and n @ towards_body < 0:
        n = -n
    along = np.array([-n[1], n[0]])
    if ground:   # the ground's plane, long enough to read as the ground
        return _hatch_2d(ax, at, along, -n, 14 * s, s, zorder)
    seg = np.array([at - 2 * s * along, at + 2 * s * along])
    return list(ax.plot(*seg.T, color=_INK, lw=1.6, zorder=zorder))


def _draw_2d(ax, kind, at, axis, normal, towards_body, s, ground, zorder):
    arts = []
    down = np.array([0.0, -1.0])
    if kind in ("pivot", "ball", "helical") or (kind == "cylindrical" and axis is None):
        if ground:
            tri = Polygon([at, at + s * np.array([-0.9, -1.5]), at + s * np.array([0.9, -1.5])],
                          closed=True, facecolor="white", edgecolor=_INK, lw=1.4,
                          zorder=zorder)
            ax.add_patch(tri)
            arts += [tri] + _hatch_2d(ax, at + 1.5 * s * down, np.array([1.0, 0.0]), down,
                                      2.6 * s, s, zorder)
        if kind == "ball":
            socket = Wedge(at, 0.62 * s, 200, 340, width=0.12 * s, facecolor=_INK,
                           zorder=zorder + 2)
            ball = Circle(at, 0.42 * s, facecolor="0.85", edgecolor=_INK, lw=1.4,
                          zorder=zorder + 2)
            arts += [socket, ball]
        else:
            arts.append(Circle(at, 0.38 * s, facecolor="white", edgecolor=_INK, lw=1.6,
                               zorder=zorder + 2))
        for a in arts[-2 if kind == "ball" else -1:]:
            ax.add_patch(a)
        return arts
    if kind in ("slide", "cylindrical"):
        e = axis if axis is not None else np.array([1.0, 0.0])
        angle = np.degrees(np.arctan2(e[1], e[0]))
        n = np.array([-e[1], e[0]])
        if n @ down > 0:   # n up the page: the ground is hatched under the guide
            n = -n
        corner = at - 1.1 * s * e - 0.55 * s * n
        block = Rectangle(corner, 2.2 * s, 1.1 * s, angle=angle, facecolor="white",
                          edgecolor=_INK, lw=1.6, zorder=zorder + 2)
        ax.add_patch(block)
        guide = np.array([at - 3.5 * s * e, at + 3.5 * s * e])
        arts += [block] + list(ax.plot(*guide.T, color=_INK, lw=1.0, ls="-.", zorder=zorder))
        if ground:
            arts += _hatch_2d(ax, at - 0.55 * s * n, e, -n, 7 * s, s, zorder)
        if kind == "cylindrical":
            c = Circle(at, 0.3 * s, facecolor="white", edgecolor=_INK, lw=1.2,
                       zorder=zorder + 3)
            ax.add_patch(c)
            arts.append(c)
        return arts
    if kind in ("planar", "contact", "rolling", "knife"):
        arts += _plane_2d(ax, at, normal if normal is not None else -down, towards_body, s,
                          ground, zorder)
        dot = Circle(at, 0.14 * s, facecolor=_INK, edgecolor=_INK, zorder=zorder + 3)
        ax.add_patch(dot)
        return arts + [dot]
    if kind == "embedding":
        square = Rectangle(at - 0.7 * s, 1.4 * s, 1.4 * s, facecolor=_INK,
                           hatch="////" if ground else None,
                           edgecolor="white" if ground else _INK, zorder=zorder + 2)
        ax.add_patch(square)
        return [square]
    return list(ax.plot(*at, marker="D", ms=7, color=_INK, zorder=zorder + 2))


def _draw_3d(ax, kind, at, axis, normal, up, s, ground):
    arts = []
    if kind in ("pivot", "cylindrical", "helical", "slide") and axis is not None:
        half = (3.5 if kind == "slide" else 0.9) * s * axis
        seg = np.array([at - half, at + half])
        arts += ax.plot(*seg.T, color=_INK, lw=4 if kind != "slide" else 1.2)
    marker = {"ball": "o", "slide": "s", "pivot": "o"}.get(kind, "D")
    arts.append(ax.scatter(*at, s=70 if kind == "ball" else 40, marker=marker,
                           facecolor="0.85" if kind == "ball" else "white",
                           edgecolors=_INK, depthshade=False))
    if kind in ("planar", "contact", "rolling", "knife") and normal is not None:
        n = _unit(normal)
        a = _unit(np.cross(n, [1.0, 0, 0]) if abs(n[0]) < 0.9 else np.cross(n, [0, 1.0, 0]))
        b = np.cross(n, a)
        w = 6 * s if ground else 1.5 * s
        corners = [at + w * (x * a + y * b) for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        plate = Poly3DCollection([corners], facecolors=(0.6, 0.6, 0.6, 0.25),
                                 edgecolors=_INK, linewidths=0.8)
        ax.add_collection3d(plate)
        arts.append(plate)
    elif ground and kind in ("pivot", "ball", "helical", "cylindrical", "embedding"):
        base = at - 1.4 * s * up
        a = _unit(np.cross(up, [1.0, 0, 0]) if abs(up[0]) < 0.9 else np.cross(up, [0, 1.0, 0]))
        b = np.cross(up, a)
        corners = [base + 1.2 * s * (x * a + y * b) for x, y in ((-1, -1), (1, -1), (1, 1),
                                                                 (-1, 1))]
        plate = Poly3DCollection([corners], facecolors=(0.5, 0.5, 0.5, 0.5), edgecolors=_INK)
        stem = Line3DCollection([(at, base)], colors=_INK, linewidths=1.5)
        ax.add_collection3d(plate)
        ax.add_collection3d(stem)
        arts += [plate, stem]
    return arts


def draw_connection(ax, link, placement, view, *, size, ground=False, label=True,
                    zorder=4, meets=None) -> ConnectionSymbol | None:
    """Draw the symbol of one connection (a :class:`~rigidmech.systems.Link` of the system's
    mechanism) at its point; None for a connection without a point.

    ``size`` is the symbol's scale in the units of the drawing; ``ground`` adds the hatching
    of the ground (a connection to the reference); ``label`` writes the point's name.
    ``meets`` (a Point or Frame of the placement, for a joint that closes a loop:
    :meth:`System.meets <rigidmech.dynamics.System.meets>`) is drawn too when it is apart
    from the joint's point (:func:`meets_apart`).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from rigidmech import models
    >>> from rigidmech.drawing import View, place
    >>> dp = models.double_pendulum()
    >>> p = place(dp, [0.0, 0.0], {"L": 1.0})
    >>> fig, ax = plt.subplots()
    >>> link = dp.system.mechanism.links[1]
    >>> sym = draw_connection(ax, link, p, View.of(p), size=0.1)
    >>> sym.kind, sym.point, sym.at.round(12).tolist()
    ('pivot', 'A', [0.0, -1.0])
    >>> plt.close(fig)
    """
    conn = link.connection
    point = connection_point(conn)
    if point is None:
        return None
    kind = connection_kind(conn)
    xyz = placement.point(point)
    at = view.project(xyz)
    axis = getattr(conn, "axis", None)
    if kind in ("pivot", "slide", "cylindrical", "helical") and axis is not None:
        axis = _unit(view.project(placement.vector(axis)))
    elif kind == "knife":
        axis = _unit(view.project(placement.vector(conn.direction)))
    else:
        axis = None
    normal = _normal_of(conn)
    normal = view.project(placement.vector(normal)) if normal is not None else None
    body = link.second
    centre = getattr(body, "centre", None)
    towards = view.project(placement.point(centre)) - at if centre is not None else None
    if view.dim == 2:
        arts = _draw_2d(ax, kind, at, axis, normal, towards, size, ground, zorder)
    else:
        arts = _draw_3d(ax, kind, at, axis, normal, np.array([0.0, 0.0, 1.0]), size,
                        ground)
    name = "O" if point.name.startswith("O_") else point.name   # a frame's origin
    if label:
        arts.append(_label(ax, view, at, name, size, zorder))
    where = None
    if meets is not None:
        other = getattr(meets, "origin", meets)          # a frame: its origin
        xyz2 = placement.point(other)
        if meets_apart(xyz, xyz + _blocked(conn, kind, placement, xyz2 - xyz), size):
            where = view.project(xyz2)
            arts += _draw_meets(ax, view, at, where, size, zorder)
            if label:
                arts.append(_label(ax, view, where, other.name, size, zorder))
    return ConnectionSymbol(kind, link.label, name, at, tuple(arts), where)


def _blocked(conn, kind, placement, gap):
    """The part of the gap between a joint's point and its ``meets`` point that the joint
    does not allow: along the normal for a contact or a planar support (its point moves on
    its plane), across the axis for a slide, a cylindrical joint or a sphere in a cylinder,
    the whole gap otherwise."""
    normal = _normal_of(conn)
    if normal is not None:
        n = _unit(placement.vector(normal))
        return gap if n is None else (gap @ n) * n
    if kind in ("slide", "cylindrical") or isinstance(conn, LinearAnnular):
        a = _unit(placement.vector(conn.axis))
        return gap if a is None else gap - (gap @ a) * a
    return gap


def _label(ax, view, at, name, size, zorder):
    if view.dim == 2:
        return ax.annotate(name, at, xytext=(-12, 6), textcoords="offset points",
                           fontsize=10, color=_INK, zorder=zorder + 4, ha="right")
    return ax.text(*(at + 0.8 * size * np.array([0, 0, 1])), name, fontsize=10, color=_INK)


def _draw_meets(ax, view, at, where, s, zorder):
    """The point ``meets`` of a loop left open: a small open circle joined to the joint's
    point by a dashed line."""
    line, = ax.plot(*np.array([at, where]).T, color=_INK, lw=1.0, ls="--", zorder=zorder)
    if view.dim == 2:
        ring = Circle(where, 0.25 * s, facecolor="white", edgecolor=_INK, lw=1.2,
                      zorder=zorder + 1)
        ax.add_patch(ring)
        return [line, ring]
    return [line, ax.scatter(*where, s=30, facecolor="white", edgecolors=_INK,
                             depthshade=False)]


def draw_frame(ax, frame, placement, view, *, size, zorder=5) -> list:
    """Draw a frame as a trihedron of its basis vectors i (red), j (green), k (blue) of
    length ``size`` at its origin, each tip labelled with the frame's name (in a plane only
    the vectors not normal to it). Returns the artists.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from rigidmech import models
    >>> from rigidmech.drawing import View, place
    >>> dp = models.double_pendulum()
    >>> p = place(dp, [0.0, 0.0], {"L": 1.0})
    >>> fig, ax = plt.subplots()
    >>> len(draw_frame(ax, dp.frame("R1"), p, View.of(p), size=0.2))   # i, j and 2 labels
    4
    >>> plt.close(fig)
    """
    R = placement.rotation(frame)
    origin = placement.point(frame.origin)
    at = view.project(origin)
    arts = []
    for n, (letter, color) in enumerate(zip("ijk", ("#c0392b", "#27ae60", "#2e6fd6"),
                                            strict=True)):
        tip = view.project(origin + size * R[:, n])
        if view.dim == 2:
            if np.linalg.norm(tip - at) < 0.3 * size:
                continue
            arrow = FancyArrowPatch(at, tip, arrowstyle="-|>", mutation_scale=9, color=color,
                                    lw=1.3, zorder=zorder)
            ax.add_patch(arrow)
            arts.append(arrow)
            arts.append(ax.annotate(f"${letter}_{{{frame.name}}}$", tip, xytext=(2, 2),
                                    textcoords="offset points", fontsize=8, color=color,
                                    zorder=zorder))
        else:
            arts.append(ax.quiver(*at, *(tip - at), color=color, lw=1.3,
                                  arrow_length_ratio=0.25))
            arts.append(ax.text(*tip, f"${letter}_{{{frame.name}}}$", fontsize=8,
                                color=color))
    return arts


def draw_spring(ax, a, b, *, size, damper=False, ground_a=False, zorder=3) -> list:
    """Draw a spring (a zigzag) or a damper (a dashpot) between the points ``a`` and ``b``
    given on the axes (2 or 3 coordinates); ``ground_a`` hatches the end ``a`` fixed in the
    reference. Returns the artists.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> arts = draw_spring(ax, np.array([0.0, 0.0]), np.array([1.0, 0.0]), size=0.1)
    >>> line = arts[0]
    >>> line.get_xdata()[[0, -1]].tolist(), round(float(np.abs(line.get_ydata()).max()), 6)
    ([0.0, 1.0], 0.05)
    >>> plt.close(fig)
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    d = b - a
    length = float(np.linalg.norm(d))
    if length < 1e-12:
        return []
    e = d / length
    if len(a) == 2:
        n = np.array([-e[1], e[0]])
    else:
        n = np.cross(e, [0.0, 0.0, 1.0] if abs(e[2]) < 0.9 else [1.0, 0.0, 0.0])
        n /= np.linalg.norm(n)
    w = 0.5 * size
    arts = []
    if not damper:
        coils = 8
        s_ = np.linspace(0.15, 0.85, 2 * coils + 1)
        side = np.r_[0, np.tile([1.0, -1.0], coils)][: len(s_)]
        side[-1] = 0
        pts = np.vstack([a, *(a + t * d + sgn * w * n for t, sgn in zip(s_, side, strict=True)),
                         b])
        arts += ax.plot(*pts.T, color=_INK, lw=1.2, zorder=zorder)
    else:
        p1, p2 = a + 0.35 * d, a + 0.55 * d
        cup = np.array([p1 + w * n + 0.3 * d, p1 + w * n, p1 - w * n, p1 - w * n + 0.3 * d])
        arts += ax.plot(*np.array([a, p1]).T, color=_INK, lw=1.2, zorder=zorder)
        arts += ax.plot(*cup.T, color=_INK, lw=1.2, zorder=zorder)
        arts += ax.plot(*np.array([p2, b]).T, color=_INK, lw=1.2, zorder=zorder)
        arts += ax.plot(*np.array([p2 - 0.7 * w * n, p2 + 0.7 * w * n]).T, color=_INK, lw=2,
                        zorder=zorder)
    if ground_a and len(a) == 2:
        arts += _hatch_2d(ax, a, n, -e, 2.5 * size, size, zorder)
    return arts
