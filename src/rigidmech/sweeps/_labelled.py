"""The swept points and the labelled arrays of a sweep (book, ch. 27: many runs of one set of
equations of motion).

:func:`grid` (every combination of the values of each axis) and :func:`points` (a list of
points, one value per name each) say where a sweep goes; :class:`Labelled` is the array it
returns when xarray is not installed (with xarray, an ``xarray.DataArray`` of the same dims and
coords).

Examples
--------
>>> g = grid(mu=[1.0, 2.0], theta=[0.1, 0.2, 0.3])
>>> g.shape, g.columns["mu"].tolist()
((2, 3), [1.0, 1.0, 1.0, 2.0, 2.0, 2.0])
"""

from __future__ import annotations

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError

__all__ = ["Points", "grid", "points", "Labelled"]


def _column(name, values):
    try:
        arr = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"the values of `{name}` must be real numbers; got {values!r}.") from None
    if arr.ndim != 1 or arr.size == 0:
        raise ArgumentError(
            f"the values of `{name}` must be a non-empty 1-D sequence; got shape {arr.shape}. "
            f"Pass e.g. {name}=numpy.linspace(0, 1, 11).")
    if not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)][:3]
        raise ArgumentError(f"the values of `{name}` must be finite; got {bad}.")
    return arr


class Points:
    """The points of a sweep: one column of values per swept name, ``size`` points.

    Made by :func:`grid` (``shape`` the lengths of the axes, points in C order: the last axis
    varies fastest) or :func:`points` (``shape`` ``(size,)``). Immutable.

    Examples
    --------
    >>> p = points(mu=[1.0, 2.0], theta=[0.1, 0.2])
    >>> p.size, p.is_grid, p.names
    (2, False, ('mu', 'theta'))
    """

    __slots__ = ("names", "columns", "shape", "axes", "is_grid")

    def __init__(self, names, columns, shape, axes, is_grid):
        self.names = tuple(names)
        self.columns = {k: v.copy() for k, v in columns.items()}
        for v in self.columns.values():
            v.flags.writeable = False
        self.shape = tuple(shape)
        self.axes = {k: np.array(v) for k, v in axes.items()}
        self.is_grid = bool(is_grid)

    @property
    def size(self) -> int:
        """The number of points."""
        return int(np.prod(self.shape))

    def __repr__(self):
        kind = "grid" if self.is_grid else "points"
        return f"{kind}({', '.join(self.names)}; shape={self.shape})"


def grid(**axes) -> Points:
    """Every combination of the values given for each name (an outer product, C order).

    Examples
    --------
    >>> grid(k=[1.0, 4.0], x=[0.0, 1.0]).columns["x"].tolist()
    [0.0, 1.0, 0.0, 1.0]
    """
    if not axes:
        raise ArgumentError("`grid` needs at least one axis, e.g. grid(mu=[1.0, 2.0]).")
    cols = {k: _column(k, v) for k, v in axes.items()}
    mesh = np.meshgrid(*cols.values(), indexing="ij")
    flat = {k: m.ravel() for k, m in zip(cols, mesh, strict=True)}
    return Points(cols, flat, [len(v) for v in cols.values()], cols, True)


def points(**columns) -> Points:
    """A list of points: one value per point for each name, the sequences of equal length.

    Examples
    --------
    >>> points(k=[1.0, 4.0, 9.0], x=[0.0, 1.0, 2.0]).size
    3
    >>> points(k=[1.0, 4.0], x=[0.0])
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: the sequences given to `points` must have one ...
    """
    if not columns:
        raise ArgumentError("`points` needs at least one name, e.g. points(mu=[1.0, 2.0]).")
    cols = {k: _column(k, v) for k, v in columns.items()}
    lengths = {k: len(v) for k, v in cols.items()}
    if len(set(lengths.values())) != 1:
        raise ArgumentError(
            "the sequences given to `points` must have one length (one value per point); got "
            f"lengths {lengths}. Use `grid` for every combination.")
    return Points(cols, cols, [next(iter(lengths.values()))], {}, False)


class Labelled:
    """A numpy array with named dims and coordinates (what a sweep returns without xarray).

    Attributes
    ----------
    values : numpy.ndarray
    dims : tuple of str
    coords : dict
        name -> (dim, 1-D array) for each labelled dim (and, for a list of points, each
        swept name along ``"point"``).

    Examples
    --------
    >>> a = Labelled(np.arange(6.0).reshape(2, 3), ("k", "x"),
    ...              {"k": ("k", np.array([1.0, 4.0])), "x": ("x", np.array([0.0, 1.0, 2.0]))})
    >>> a.sel(k=4.0).values.tolist()
    [3.0, 4.0, 5.0]
    >>> a.sel(k=4.0, x=1.0).values.item()
    4.0
    """

    __slots__ = ("values", "dims", "coords")

    def __init__(self, values, dims, coords):
        self.values = np.asarray(values)
        self.dims = tuple(dims)
        self.coords = dict(coords)

    @property
    def shape(self):
        return self.values.shape

    def sel(self, **where):
        """The sub-array at the given coordinate values (exact match) of labelled dims."""
        out = self
        for name, value in where.items():
            if name not in out.dims or name not in out.coords:
                raise ArgumentError(f"`{name}` is not a labelled dim; the dims are {out.dims}.")
            axis = out.dims.index(name)
            labels = out.coords[name][1]
            hit = np.flatnonzero(labels == value)
            if hit.size == 0:
                raise ArgumentError(
                    f"no `{name}` equal to {value!r}; the values are {labels.tolist()}.")
            values = np.take(out.values, hit[0], axis=axis)
            dims = out.dims[:axis] + out.dims[axis + 1:]
            coords = {k: c for k, c in out.coords.items() if c[0] != name}
            out = Labelled(values, dims, coords)
        return out

    def __repr__(self):
        return f"Labelled(dims={self.dims}, shape={self.values.shape})"
