"""One body drawn by its shape, in a plane or in space (book, ch. 15.5 for the shapes).

A :class:`View` says how the reference's coordinates map to the axes: the plane of a planar
system seen from the side its normal points to, gravity pointing down the page; or space with
the vertical (against gravity) up. :func:`draw_body` draws one body of a
:class:`~rigidmech.drawing.Placement` in a View: a body whose operator of inertia comes from
the catalogue as its shape (rods as bars, discs, cylinders and cones as solids of revolution,
blocks, spheres, ellipsoids), any other as its mass centre (the usual quartered disc) with
its principal axes of inertia, joined to its connection points by thin lines.
"""

from __future__ import annotations

import matplotlib.patheffects as path_effects
import numpy as np
import sympy as sp
from matplotlib.colors import to_rgb
from matplotlib.patches import Circle, FancyArrowPatch, Polygon, Wedge
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from scipy.spatial import ConvexHull

from .._core.errors import ArgumentError
from .placement import connection_point

__all__ = ["View", "draw_body", "shape_mesh", "is_3d"]

#: Number of steps round a solid of revolution (enough for a smooth outline on a slide).
_TURN = 36


def is_3d(ax) -> bool:
    """True for matplotlib's 3D axes (``projection="3d"``)."""
    return getattr(ax, "name", "") == "3d"


class View:
    """How coordinates in the reference map to the axes of a figure.

    Parameters
    ----------
    rows : array-like, shape (3, 3)
        An orthonormal direct basis, in the reference's components: the horizontal and the
        vertical of the page and the normal towards the reader (2D), or the three axes of
        the 3D plot, the third one up.
    dim : {2, 3}

    Examples
    --------
    >>> from rigidmech import models
    >>> from rigidmech.drawing import place
    >>> p = place(models.double_pendulum(), [0.0, 0.0], {"L": 1.0})
    >>> view = View.of(p)             # planar, gravity along +i: i points down the page
    >>> view.dim, view.project([1.0, 0.0, 0.0]).tolist()
    (2, [0.0, -1.0])
    """

    __slots__ = ("_rows", "_dim")

    def __init__(self, rows, dim: int):
        rows = np.array(rows, dtype=float)
        if rows.shape != (3, 3) or not np.allclose(rows @ rows.T, np.eye(3), rtol=0,
                                                   atol=1e-9):
            raise ArgumentError(f"`rows` must be an orthonormal 3 x 3 basis; got {rows!r}.")
        if dim not in (2, 3):
            raise ArgumentError(f"`dim` must be 2 or 3; got {dim!r}.")
        rows.flags.writeable = False
        self._rows, self._dim = rows, dim

    dim = property(lambda self: self._dim, doc="2 (a plane) or 3 (space).")
    rows = property(lambda self: self._rows, doc="The basis of the view (read-only).")

    @classmethod
    def of(cls, placement, dim=None) -> View:
        """The view a placement is best seen in: 2D for a planar system (seen along the
        normal of its plane, gravity down the page), 3D otherwise (gravity down); ``dim``
        forces one.

        Examples
        --------
        >>> from rigidmech import models
        >>> from rigidmech.drawing import place
        >>> p = place(models.heavy_top(), [0.0, 0.5, 0.0], {"l": 1.0})
        >>> View.of(p).dim, View.of(p, 2).dim
        (3, 2)
        """
        plane = placement.placer.plane
        if dim is None:
            dim = 2 if plane is not None else 3
        g = placement.gravity
        if dim == 2:
            normal = np.eye(3)[2 if plane is None else plane]
            up = None
            if g is not None:
                up = -(g - g.dot(normal) * normal)
                up = up / np.linalg.norm(up) if np.linalg.norm(up) > 1e-9 else None
            if up is None:
                up = np.eye(3)[(int(np.argmax(np.abs(normal))) + 2) % 3]
            return cls([np.cross(up, normal), up, normal], 2)
        up = -g if g is not None else np.eye(3)[2]
        first = np.eye(3)[int(np.argmin(np.abs(up)))]
        first = first - first.dot(up) * up
        first /= np.linalg.norm(first)
        return cls([first, np.cross(up, first), up], 3)

    def project(self, xyz) -> np.ndarray:
        """Coordinates on the axes of points (..., 3) given in the reference.

        Examples
        --------
        >>> View([[0, 1, 0], [-1, 0, 0], [0, 0, 1]], 2).project([[1.0, 2.0, 3.0]]).tolist()
        [[2.0, -1.0]]
        """
        return (np.asarray(xyz, dtype=float) @ self._rows.T)[..., :self._dim]


def _profile(kind, d):
    """Profile (r, z) of a solid of revolution, z along its axis from its mass centre."""
    if kind == "ring":
        R = d["radius"]
        a = np.linspace(0, 2 * np.pi, 9)
        return np.c_[R + 0.06 * R * np.cos(a), 0.06 * R * np.sin(a)]
    if kind == "disk":
        R, e = d["radius"], 0.04 * d["radius"]
        return np.array([(0, -e), (R, -e), (R, e), (0, e)])
    if kind in ("cylinder", "cylindrical_shell"):
        R, h = d["radius"], d["length"] / 2
        return np.array([(0, -h), (R, -h), (R, h), (0, h)])
    if kind == "tube":
        r1, r2, h = d["r_in"], d["r_out"], d["length"] / 2
        return np.array([(r1, -h), (r2, -h), (r2, h), (r1, h), (r1, -h)])
    if kind == "cone":   # G at h/4 from the base, the apex at 3h/4
        R, h = d["radius"], d["height"]
        return np.array([(0, -h / 4), (R, -h / 4), (0, 3 * h / 4)])
    if kind == "hemisphere":   # G at 3R/8 from the flat face
        R = d["radius"]
        a = np.linspace(0, np.pi / 2, 10)
        return np.r_[[(0, -3 * R / 8)], np.c_[R * np.cos(a), R * np.sin(a) - 3 * R / 8]]
    R = d.get("radius", 1.0)   # sphere, spherical shell, ellipsoid (scaled afterwards)
    a = np.linspace(0, np.pi, 13)
    return np.c_[R * np.sin(a), -R * np.cos(a)]


def shape_mesh(shape, dimensions):
    """Vertices (N, 3), in the basis of ``shape.frame`` from the mass centre, and faces
    (tuples of vertex indices) of a body of the catalogue; None for a rod or a point mass
    (drawn as a line and a dot).

    Examples
    --------
    >>> from rigidmech.inertia import Shape
    >>> from rigidmech.vectors import Frame
    >>> v, faces = shape_mesh(Shape("block", [2, 1, 1], frame=Frame("R1")),
    ...                       {"a": 2.0, "b": 1.0, "c": 1.0})
    >>> v.max(axis=0).tolist(), len(faces)
    ([1.0, 0.5, 0.5], 6)
    """
    kind, d = shape.kind, dimensions
    if kind in ("rod", "point_mass"):
        return None
    if kind == "block":
        half = np.array([d["a"], d["b"], d["c"]]) / 2
        v = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * half
        faces = [(0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4),
                 (1, 3, 7, 5)]
        return v, faces
    prof = _profile(kind, d)
    a = np.linspace(0, 2 * np.pi, _TURN, endpoint=False)
    local = np.array([(r * np.cos(b), r * np.sin(b), z) for r, z in prof for b in a])
    n, m = len(prof), _TURN
    faces = [(k * m + j, k * m + (j + 1) % m, (k + 1) * m + (j + 1) % m, (k + 1) * m + j)
             for k in range(n - 1) for j in range(m)]
    if kind == "ellipsoid":
        return local * np.array([d["a"], d["b"], d["c"]]), faces
    if shape.axis_index is None:   # sphere, spherical shell: any axis
        return local, faces
    i, s = shape.axis_index, shape.axis_sign
    basis = np.eye(3)
    # local x, y, z -> the frame's e(i+1), e(i+2), s e(i)
    return local @ np.array([basis[(i + 1) % 3], s * basis[(i + 2) % 3], s * basis[i]]), faces


def _dimensions(shape, placement):
    return {name: placement.placer.number(x) for name, x in shape.dimensions.items()}


def _darker(color, f=0.6):
    return tuple(f * c for c in to_rgb(color))


def _shaded(polys, color):
    """Face colours lit from above and in front (a fixed light, cos law, floor 0.45)."""
    light = np.array([-0.4, -0.5, 0.77])
    rgb = np.array(to_rgb(color))
    out = []
    for p in polys:
        n = np.cross(p[2] - p[0], p[3 % len(p)] - p[1])
        norm = np.linalg.norm(n)
        f = 0.45 + 0.55 * abs(n @ light) / norm if norm > 1e-12 else 0.8
        out.append((*(f * rgb), 1.0))
    return out


def _principal_axes(body, placement):
    """Columns: the principal directions of inertia of a body in the reference."""
    J = body.inertia
    M = sp.Matrix(J.matrix).xreplace(placement.placer._values)
    if all(M[r, c] == 0 for r in range(3) for c in range(3) if r != c):
        return placement.rotation(J.frame)
    try:
        _, vectors = np.linalg.eigh(np.array(M.tolist(), dtype=float))
    except TypeError:   # moments left symbolic: the axes of the body's frame
        return placement.rotation(J.frame)
    return placement.rotation(J.frame) @ vectors


def _centre_marker_2d(ax, xy, r, color, zorder):
    """The usual mass-centre symbol: a disc in quarters, two opposite ones filled."""
    arts = [Circle(xy, r, facecolor="white", edgecolor="black", lw=1, zorder=zorder)]
    arts += [Wedge(xy, r, a, a + 90, facecolor="black", edgecolor="black", lw=0,
                   zorder=zorder) for a in (0, 180)]
    for a in arts:
        ax.add_patch(a)
    return arts


def draw_body(ax, body, placement, view=None, *, color="C0", size=None, label=True,
              zorder=2):
    """Draw one body of a placement on matplotlib axes (2D or 3D) and return its artists.

    Parameters
    ----------
    ax : matplotlib Axes or Axes3D
    body : Body
        A body of the placement's system.
    placement : Placement
    view : View, optional
        Default :meth:`View.of` the placement, 2D or 3D as ``ax``.
    color : matplotlib colour
    size : float, optional
        Length of the principal axes and radius scale of the markers (default: a tenth of
        the extent of the system).
    label : bool
        Write the body's name next to its mass centre.
    zorder : float

    Returns
    -------
    list of matplotlib artists

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from rigidmech import models
    >>> from rigidmech.drawing import place
    >>> dp = models.double_pendulum()
    >>> p = place(dp, [0.3, 0.6], {"L": 1.0})
    >>> fig, ax = plt.subplots()
    >>> artists = draw_body(ax, dp.body("bar1"), p)
    >>> [type(a).__name__ for a in artists]
    ['Line2D', 'Annotation']
    >>> plt.close(fig)
    """
    view = View.of(placement, 3 if is_3d(ax) else 2) if view is None else view
    low, high = placement.extent()
    if size is None:
        size = 0.1 * max(float(np.max(high - low)), 1e-3)
    G = placement.point(body.centre)
    shape = body.shape
    arts = []
    edge = _darker(color)
    if shape is not None and shape.kind == "rod":
        L = _dimensions(shape, placement)["length"]
        R = placement.rotation(shape.frame)
        e = shape.axis_sign * R[:, shape.axis_index]
        ends = view.project(np.array([G - L / 2 * e, G + L / 2 * e]))
        effects = [path_effects.Stroke(linewidth=9, foreground=edge), path_effects.Normal()]
        line, = ax.plot(*ends.T, color=color, lw=6.5, solid_capstyle="round", zorder=zorder,
                        path_effects=effects)
        arts.append(line)
    elif shape is not None and shape.kind != "point_mass":
        vertices, faces = shape_mesh(shape, _dimensions(shape, placement))
        world = vertices @ placement.rotation(shape.frame).T + G
        xy = view.project(world)
        if view.dim == 2:
            hull = xy[ConvexHull(xy).vertices] if np.ptp(xy, axis=0).min() > 1e-12 else xy
            patch = Polygon(hull, closed=True, facecolor=color, edgecolor=edge, lw=1.5,
                            alpha=0.9, zorder=zorder)
            ax.add_patch(patch)
            arts.append(patch)
        else:
            polys = [xy[list(f)] for f in faces]
            poly = Poly3DCollection(polys, facecolors=_shaded(polys, color),
                                    edgecolors="none", alpha=0.95)
            ax.add_collection3d(poly)
            arts.append(poly)
    else:
        arts += _unshaped(ax, body, placement, view, G, size, color, zorder)
    if label:
        at = view.project(G)
        if view.dim == 2:
            arts.append(ax.annotate(body.name, at, xytext=(6, 6), textcoords="offset points",
                                    fontsize=10, color=edge, zorder=zorder + 3))
        else:
            arts.append(ax.text(*(at + 0.3 * size * np.array([0, 0, 1])), body.name,
                                fontsize=10, color=edge))
    return arts


def _unshaped(ax, body, placement, view, G, size, color, zorder):
    """A body without a shape: thin lines from its connection points to G, then a bob (a
    particle) or the mass-centre symbol with the principal axes of inertia."""
    arts = []
    mech = placement.system.mechanism
    for link in mech.links:
        if link.first is body or link.second is body:
            p = connection_point(link.connection)
            if p is not None:
                seg = view.project(np.array([placement.point(p), G]))
                arts += ax.plot(*seg.T, color=_darker(color), lw=3.0, zorder=zorder)
    if body.mass is None or body.mass == 0:
        return arts
    if body.inertia is None:     # a particle: a bob
        at = view.project(G)
        if view.dim == 2:
            bob = Circle(at, 0.35 * size, facecolor=color, edgecolor=_darker(color),
                         lw=1.5, zorder=zorder + 1)
            ax.add_patch(bob)
            return arts + [bob]
        return arts + [ax.scatter(*at, s=180, color=color, edgecolors=_darker(color),
                                  depthshade=False)]
    axes = _principal_axes(body, placement)
    at = view.project(G)
    for n in range(3):
        tip = view.project(G + 2 * size * axes[:, n])
        if view.dim == 2:
            if np.linalg.norm(tip - at) < 0.3 * size:
                continue
            arrow = FancyArrowPatch(at, tip, arrowstyle="-|>", mutation_scale=10,
                                    color=_darker(color), lw=1.2, zorder=zorder)
            ax.add_patch(arrow)
            arts.append(arrow)
        else:
            arts.append(ax.quiver(*at, *(tip - at), color=_darker(color), lw=1.2,
                                  arrow_length_ratio=0.2))
    if view.dim == 2:
        arts += _centre_marker_2d(ax, at, 0.18 * size, color, zorder + 2)
    else:
        arts.append(ax.scatter(*at, s=60, facecolor="white", edgecolors="black",
                               depthshade=False))
    return arts
