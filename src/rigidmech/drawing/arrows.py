"""The marks of a free-body diagram in matplotlib: force arrows, couples (a curved arrow in
the plane, a double arrow in space), friction cones and the force-scale key (book, ch. 11.1,
13.1.2).

Every function draws on a given Axes (a 2D one, or a 3D one for ``dim=3``), in data
coordinates (the reference's x, y, z), and returns the artists it made.

Examples
--------
>>> import matplotlib
>>> matplotlib.use("Agg")
>>> import matplotlib.pyplot as plt
>>> fig, ax = plt.subplots()
>>> art = force_arrow(ax, [0, 0, 0], [1, 1, 0], dim=2)
>>> type(art).__name__
'FancyArrowPatch'
>>> plt.close(fig)
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import FancyArrowPatch
from matplotlib.path import Path

__all__ = ["force_arrow", "couple_arrow", "cone_lines", "scale_key", "nice_length"]

#: colours of the marks (given actions, connection actions, friction cones, cone edge)
COLOURS = {"given": "tab:blue", "connection": "tab:red", "cone": "0.55", "edge": "tab:orange"}


def force_arrow(ax, tail, vector, *, dim=2, color="k", width=1.6):
    """An arrow from ``tail`` along ``vector`` (data units).

    Examples
    --------
    See the module.
    """
    tail, vector = np.asarray(tail, dtype=float), np.asarray(vector, dtype=float)
    if dim == 3:
        return ax.quiver(*tail, *vector, color=color, linewidth=width,
                         arrow_length_ratio=0.15)
    arrow = FancyArrowPatch(tuple(tail[:2]), tuple((tail + vector)[:2]), arrowstyle="-|>",
                            mutation_scale=14, linewidth=width, color=color,
                            shrinkA=0, shrinkB=0, zorder=4)
    ax.add_patch(arrow)
    return arrow


def couple_arrow(ax, centre, moment, *, radius, dim=2, color="k", width=1.6):
    """A couple of moment ``moment`` at ``centre``: in the plane, an arc of 270 degrees of
    ``radius`` turning counterclockwise for a moment along +z (clockwise otherwise); in
    space, a double arrow along ``moment`` of length ``radius`` (the book's notation,
    ch. 11.1.4). Returns a list of artists.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> [type(a).__name__ for a in couple_arrow(ax, [0, 0, 0], [0, 0, -2], radius=0.3)]
    ['FancyArrowPatch']
    >>> plt.close(fig)
    """
    centre, moment = np.asarray(centre, dtype=float), np.asarray(moment, dtype=float)
    if dim == 3:
        n = np.linalg.norm(moment)
        d = moment / n * radius if n else np.array([0.0, 0.0, radius])
        return [ax.quiver(*centre, *d, color=color, linewidth=width, arrow_length_ratio=0.2),
                ax.quiver(*centre, *(0.82 * d), color=color, linewidth=width,
                          arrow_length_ratio=0.24)]
    ccw = moment[2] >= 0
    a0, a1 = (-135.0, 135.0) if ccw else (135.0, -135.0)
    angles = np.radians(np.linspace(a0, a1, 40))
    xy = centre[:2] + radius * np.column_stack([np.cos(angles), np.sin(angles)])
    arrow = FancyArrowPatch(path=Path(xy), arrowstyle="-|>", mutation_scale=12,
                            linewidth=width, color=color, zorder=4)
    ax.add_patch(arrow)
    return [arrow]


def cone_lines(ax, apex, normal, half_angle, length, *, dim=2, side=None, on_edge=False):
    """The friction cone of axis ``normal`` and ``half_angle`` at ``apex`` (ch. 13.1.2):
    in the plane, its two edges; in space, 12 generatrices and the rim. With ``on_edge``,
    the edge (2D) or generatrix (3D) on the ``side`` of the tangential force is drawn thick
    in the edge colour. Returns ``(lines, edge)``, ``edge`` the highlighted line or None.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> lines, edge = cone_lines(ax, [0, 0, 0], [0, 1, 0], 0.3, 1.0, side=[1, 0, 0],
    ...                          on_edge=True)
    >>> len(lines), edge is not None
    (2, True)
    >>> plt.close(fig)
    """
    apex, n = np.asarray(apex, dtype=float), np.asarray(normal, dtype=float)
    n = n / np.linalg.norm(n)
    c, s = math.cos(half_angle), math.sin(half_angle)
    style = dict(color=COLOURS["cone"], linestyle="--", linewidth=1.0, zorder=2)
    if dim == 2:
        t = np.array([-n[1], n[0], 0.0])
        ends = [apex + length * (c * n + s * t), apex + length * (c * n - s * t)]
        lines = [ax.plot(*np.transpose([apex[:2], e[:2]]), **style)[0] for e in ends]
        edge = None
        if on_edge and side is not None:
            k = 0 if float(np.dot(side, t)) > 0 else 1
            lines[k].set(color=COLOURS["edge"], linestyle="-", linewidth=2.2)
            edge = lines[k]
        return lines, edge
    a = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
    a /= np.linalg.norm(a)
    b = np.cross(n, a)
    lines = []
    for phi in np.linspace(0, 2 * np.pi, 12, endpoint=False):
        e = apex + length * (c * n + s * (math.cos(phi) * a + math.sin(phi) * b))
        lines.append(ax.plot(*np.transpose([apex, e]), **style)[0])
    phis = np.linspace(0, 2 * np.pi, 60)
    rim = apex + length * (c * n + s * (np.outer(np.cos(phis), a) + np.outer(np.sin(phis), b)))
    lines.append(ax.plot(*rim.T, **style)[0])
    edge = None
    if on_edge and side is not None:
        e = apex + length * (c * n + s * np.asarray(side, dtype=float))
        edge = ax.plot(*np.transpose([apex, e]), color=COLOURS["edge"], linewidth=2.2)[0]
        lines.append(edge)
    return lines, edge


def nice_length(x: float) -> float:
    """The largest of 1, 2, 5 times a power of ten not above ``x`` (> 0).

    Examples
    --------
    >>> nice_length(37.0), nice_length(0.8), nice_length(5.0)
    (20.0, 0.5, 5.0)
    """
    if not x > 0 or not math.isfinite(x):
        raise ValueError(f"`x` must be a finite number > 0; got {x!r}.")
    e = math.floor(math.log10(x))
    for m in (5.0, 2.0, 1.0):
        if m * 10.0**e <= x * (1 + 1e-12):
            return m * 10.0**e
    return 10.0**e      # pragma: no cover  (m = 1 always fits)


def scale_key(ax, scale, length, *, dim=2, unit="N"):
    """The force-scale key: an arrow of a round force (``nice_length``) drawn at ``scale``
    (force per unit of length), about ``length`` long, in the lower right corner, with its
    value. Returns ``(artists, force)``.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> ax.set_xlim(0, 1); ax.set_ylim(0, 1)
    (0.0, 1.0)
    (0.0, 1.0)
    >>> artists, force = scale_key(ax, 50.0, 0.2)
    >>> force, artists[1].get_text()
    (10.0, 'force scale: 10 N')
    >>> plt.close(fig)
    """
    force = nice_length(scale * length)
    size = force / scale
    label = f"force scale: {force:g} {unit}".rstrip()
    if dim == 3:
        text = ax.text2D(0.98, 0.02, f"{label} = {size:.3g} length units",
                         transform=ax.transAxes, ha="right", va="bottom", fontsize=8)
        return [text], force
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    tail = np.array([x1 - 0.05 * (x1 - x0) - size, y0 + 0.06 * (y1 - y0), 0.0])
    arrow = force_arrow(ax, tail, [size, 0.0, 0.0], color="k", width=1.2)
    text = ax.text(tail[0] + size / 2, tail[1] + 0.02 * (y1 - y0), label, ha="center",
                   va="bottom", fontsize=8)
    return [arrow, text], force
