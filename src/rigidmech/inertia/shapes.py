"""The shape of a homogeneous body of the catalogue (book, ch. 15.5), kept for drawing it.

Every operator of the catalogue (:func:`~rigidmech.inertia.rod`, :func:`~rigidmech.inertia.disk`,
...) carries a :class:`Shape`: which body it is (``kind``), its dimensions, and how it sits in
the frame it was given. A :class:`~rigidmech.kinetics.Body` built with such an operator knows
its shape (``body.shape``), and :mod:`rigidmech.drawing` draws it as such. An operator built
from its moments (:meth:`InertiaOperator.from_products`) has no shape.

Placement: the shape is centred on the body's **mass centre** G. For the bodies of revolution
``axis`` is the axis of symmetry; a cone's axis points from its base to its apex (G at h/4
from the base), a hemisphere's from its flat face to its pole (G at 3R/8 from the face). The
bodies with three planes of symmetry (block, plate, ellipsoid, sphere, spherical shell, point
mass) have their edges or semi-axes along the basis vectors of ``frame``.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..vectors import Frame, Vector

__all__ = ["Shape", "SHAPE_DIMENSIONS"]

#: The kinds of shapes and the names of their dimensions, in the catalogue's order.
SHAPE_DIMENSIONS = {
    "rod": ("length",),
    "ring": ("radius",),
    "disk": ("radius",),
    "cylinder": ("radius", "length"),
    "tube": ("r_in", "r_out", "length"),
    "cylindrical_shell": ("radius", "length"),
    "cone": ("radius", "height"),
    "hemisphere": ("radius",),
    "sphere": ("radius",),
    "spherical_shell": ("radius",),
    "block": ("a", "b", "c"),
    "ellipsoid": ("a", "b", "c"),
    "point_mass": (),
}
_REVOLUTION = ("rod", "ring", "disk", "cylinder", "tube", "cylindrical_shell", "cone",
               "hemisphere")


def _signed_axis(axis):
    """(frame, index, sign) of a basis vector of a frame or its opposite."""
    if isinstance(axis, Vector) and len(axis.parts) == 1:
        frame, comps = axis.parts[0]
        nonzero = [n for n in range(3) if comps[n] != 0]
        if len(nonzero) == 1 and comps[nonzero[0]] in (1, -1):
            return frame, nonzero[0], int(comps[nonzero[0]])
    raise ArgumentError(
        f"`axis` must be a basis vector of a frame (such as R1.i or -R1.k); got {axis!r}.")


class Shape:
    """The shape of a homogeneous body: its kind, dimensions and orientation (ch. 15.5).

    Parameters
    ----------
    kind : str
        One of the keys of :data:`SHAPE_DIMENSIONS` (``"rod"``, ``"disk"``, ``"block"``...).
    dimensions : sequence of numbers or sympy expressions
        In the order of ``SHAPE_DIMENSIONS[kind]`` (a rod: length; a block: a, b, c).
    axis : Vector, optional
        For a body of revolution (rod, ring, disk, cylinder, tube, cylindrical shell, cone,
        hemisphere): its axis, a basis vector of a frame or its opposite.
    frame : Frame, optional
        For the others (sphere, spherical shell, block, ellipsoid, point mass): the frame
        whose basis carries its edges or semi-axes.

    Raises
    ------
    ArgumentError
        For an unknown ``kind``, the wrong number of dimensions, or ``axis``/``frame`` given
        to the wrong kind of shape.

    Notes
    -----
    A value: immutable, ``==`` structural. It is not part of the equality of the operator
    that carries it (two operators with equal matrices are equal whatever their shapes).

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> L = sp.Symbol("L", positive=True)
    >>> R1 = Frame("R1")
    >>> rod = Shape("rod", [L], axis=R1.i)
    >>> rod
    Shape('rod', length=L, axis=R1.i)
    >>> rod.dimension("length"), rod.frame.name, rod.axis_index
    (L, 'R1', 0)
    >>> from rigidmech.inertia import disk
    >>> disk(2, 0.5, axis=R1.k).shape
    Shape('disk', radius=0.500000000000000, axis=R1.k)
    """

    __slots__ = ("_kind", "_dimensions", "_frame", "_axis")

    def __init__(self, kind: str, dimensions=(), *, axis: Vector | None = None,
                 frame: Frame | None = None):
        if kind not in SHAPE_DIMENSIONS:
            raise ArgumentError(
                f"`kind` must be one of {', '.join(SHAPE_DIMENSIONS)}; got {kind!r}.")
        names = SHAPE_DIMENSIONS[kind]
        dimensions = tuple(sp.sympify(x) for x in dimensions)
        if len(dimensions) != len(names):
            raise ArgumentError(
                f"`dimensions` of a {kind} must be ({', '.join(names)}): {len(names)} values; "
                f"got {len(dimensions)}.")
        if kind in _REVOLUTION:
            if axis is None or frame is not None:
                raise ArgumentError(
                    f"a {kind} is a body of revolution: give its `axis` (such as R1.k), not "
                    "a `frame`.")
            frame, index, sign = _signed_axis(axis)
            axis = (index, sign)
        else:
            if frame is None or axis is not None:
                raise ArgumentError(
                    f"a {kind} is oriented by a `frame` (its basis carries the edges or "
                    "semi-axes), not by an `axis`.")
            if not isinstance(frame, Frame):
                raise ArgumentTypeError(f"`frame` must be a Frame; got {type(frame).__name__}.")
        self._kind, self._dimensions, self._frame, self._axis = kind, dimensions, frame, axis

    @property
    def kind(self) -> str:
        """The kind of body (a key of :data:`SHAPE_DIMENSIONS`)."""
        return self._kind

    @property
    def dimensions(self) -> dict:
        """The dimensions by name (a new dict)."""
        return dict(zip(SHAPE_DIMENSIONS[self._kind], self._dimensions, strict=True))

    def dimension(self, name: str):
        """The dimension called ``name`` (``"length"``, ``"radius"``, ``"a"``...)."""
        dims = self.dimensions
        if name not in dims:
            raise ArgumentError(
                f"`name` must be a dimension of a {self._kind} ({', '.join(dims) or 'none'}); "
                f"got {name!r}.")
        return dims[name]

    @property
    def frame(self) -> Frame:
        """The frame whose basis orients the shape."""
        return self._frame

    @property
    def axis_index(self):
        """For a body of revolution, the index (0, 1, 2 for i, j, k) of its axis in the basis
        of :attr:`frame`; None otherwise."""
        return None if self._axis is None else self._axis[0]

    @property
    def axis_sign(self):
        """+1 or -1: the axis is ``frame``'s basis vector or its opposite (None for shapes
        that are not of revolution)."""
        return None if self._axis is None else self._axis[1]

    @property
    def axis(self):
        """The axis as a Vector (None for shapes that are not of revolution)."""
        if self._axis is None:
            return None
        index, sign = self._axis
        return sign * self._frame.basis[index]

    def subs(self, *args, **kwargs) -> Shape:
        """Substitute values in the dimensions and the frame (sympy's ``subs``).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> L = sp.Symbol("L")
        >>> Shape("rod", [L], axis=Frame("R1").i).subs(L, 2).dimension("length")
        2
        """
        new = object.__new__(Shape)
        new._kind, new._axis = self._kind, self._axis
        new._dimensions = tuple(x.subs(*args, **kwargs) for x in self._dimensions)
        new._frame = self._frame.subs(*args, **kwargs)
        return new

    def __eq__(self, other):
        if not isinstance(other, Shape):
            return NotImplemented
        return (self._kind, self._dimensions, self._frame, self._axis) == (
            other._kind, other._dimensions, other._frame, other._axis)

    def __hash__(self):
        return hash((self._kind, self._dimensions, self._frame.name, self._axis))

    def __repr__(self):
        dims = [f"{n}={sp.sstr(x)}" for n, x in self.dimensions.items()]
        where = (f"axis={self.axis!r}" if self._axis is not None
                 else f"frame={self._frame.name}")
        return f"Shape({self._kind!r}, {', '.join([*dims, where])})"
