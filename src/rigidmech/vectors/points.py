"""Points of the geometric space (book, ch. 2.1).

A point is known by its position vector from the origin of the root frame of its tree. The
bipoint AB is the vector ``B - A``; ``A + u`` is the point reached from A by the vector u.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, FrameError
from .vector import Vector, _check_frame

__all__ = ["Point"]


class Point:
    """A point of the geometric space, known by its position from the root origin.

    Build points from a frame (``R0.origin``, ``R0.point("A", x, y, z)``) and by moving
    other points (``A.moved("B", L * R1.i)``).

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> q = coordinates("q")
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> A = R0.origin.moved("A", 2 * R1.i)
    >>> A.velocity(R0)
    2*Derivative(q(t), t)*R1.j
    >>> (A - R0.origin).magnitude()
    2
    """

    __slots__ = ("_name", "_position", "_root", "_hash")

    def __init__(self, *args, **kwargs):
        raise TypeError(
            "build points from a frame: R0.origin, R0.point(name, x, y, z), "
            "or A.moved(name, vector)."
        )

    @classmethod
    def _make(cls, name, position, root):
        if not isinstance(name, str) or not name:
            raise ArgumentError(f"`name` must be a non-empty string; got {name!r}.")
        obj = object.__new__(cls)
        obj._name = name
        obj._position = position
        obj._root = root
        obj._hash = hash((name, position, root._name))
        return obj

    @classmethod
    def _root_origin(cls, frame):
        return cls._make("O_" + frame._name, Vector.zero(), frame)

    @property
    def name(self) -> str:
        """Name of the point."""
        return self._name

    @property
    def position(self) -> Vector:
        """Position vector from the origin of the root frame."""
        return self._position

    @property
    def root(self):
        """Root frame of the tree the point lives in."""
        return self._root

    def moved(self, name: str, displacement: Vector) -> Point:
        """The point reached from this one by ``displacement``.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> B = R0.origin.moved("B", 3 * R0.j)
        >>> B - R0.origin
        3*R0.j
        """
        if isinstance(displacement, Point):
            raise ArgumentTypeError(
                f"`displacement` must be a Vector; got the Point {displacement.name}. "
                f"Use {displacement.name} - {self.name} for the bipoint."
            )
        if not isinstance(displacement, Vector):
            raise ArgumentTypeError(
                f"`displacement` must be a Vector; got {type(displacement).__name__}."
            )
        self._check_tree(displacement)
        return Point._make(name, self._position + displacement, self._root)

    def _check_tree(self, v):
        for f in v.frames:
            if f.root != self._root:
                raise FrameError(
                    f"the vector uses frame {f.name} of the tree rooted at {f.root.name}; "
                    f"point {self._name} lives in the tree rooted at {self._root.name}."
                )

    def __sub__(self, other):
        if isinstance(other, Point):
            if other._root != self._root:
                raise FrameError(
                    f"points {other.name} and {self.name} live in different frame trees."
                )
            return self._position - other._position
        if isinstance(other, Vector):
            return self + (-other)
        return NotImplemented

    def __add__(self, other):
        if isinstance(other, Point):
            raise ArgumentTypeError(
                "points cannot be added; add a Vector to a Point, or subtract two Points "
                "to get their bipoint."
            )
        if not isinstance(other, Vector):
            return NotImplemented
        self._check_tree(other)
        return Point._make(f"({self._name} + ...)", self._position + other, self._root)

    def distance(self, other: Point) -> sp.Expr:
        """Distance between two points (book, ch. 2.1.3).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> R0.point("A", 1, 0, 0).distance(R0.point("B", 4, 4, 0))
        5
        """
        _check_point(other, "other")
        return (other - self).magnitude()

    def coordinates(self, frame) -> sp.ImmutableMatrix:
        """Cartesian coordinates in the reference system ``frame`` (book, ch. 2.3.3).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> R0.point("A", 1, 2, 3).coordinates(R0).T
        Matrix([[1, 2, 3]])
        """
        _check_frame(frame, "frame")
        return (self - frame.origin).components(frame)

    def velocity(self, frame) -> Vector:
        """Velocity of the point relative to ``frame``: d/dt|frame of (O_frame -> P)
        (book, ch. 6.2.2).

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> x = coordinates("x")
        >>> R0 = Frame("R0")
        >>> R0.point("P", x, 0, 0).velocity(R0)
        Derivative(x(t), t)*R0.i
        """
        _check_frame(frame, "frame")
        return (self - frame.origin).dt(frame)

    def acceleration(self, frame) -> Vector:
        """Acceleration of the point relative to ``frame`` (book, ch. 6.2.2).

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> x = coordinates("x")
        >>> R0 = Frame("R0")
        >>> R0.point("P", x, 0, 0).acceleration(R0)
        Derivative(x(t), (t, 2))*R0.i
        """
        return self.velocity(frame).dt(frame)

    def subs(self, *args, **kwargs) -> Point:
        """The point with values substituted in its position, including the angles and
        origins of the frames whose bases the position uses (see :meth:`Frame.subs`).

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> R0.origin.moved("A", 2 * R1.i).subs(q, 0).coordinates(R0).T
        Matrix([[2, 0, 0]])
        """
        return self._subs(args, kwargs, {})

    def _subs(self, args, kwargs, memo):
        position = self._position._subs(args, kwargs, memo)
        if position == self._position:
            return self
        return Point._make(self._name, position, self._root)

    def __eq__(self, other):
        if not isinstance(other, Point):
            return NotImplemented
        return (self._name == other._name and self._root == other._root
                and self._position == other._position)

    def __hash__(self):
        return self._hash

    def __repr__(self):
        return f"Point({self._name!r}, position={self._position!r})"

    def __str__(self):
        return self._name


def _check_point(p, argument):
    if not isinstance(p, Point):
        hint = " (a Vector is not a Point: use A.moved(name, vector))" if isinstance(
            p, Vector) else ""
        raise ArgumentTypeError(
            f"`{argument}` must be a Point{hint}; got {type(p).__name__}."
        )


check_point = _check_point
