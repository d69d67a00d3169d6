"""Exact decisions and argument checks shared by the torsors layer (private)."""

from __future__ import annotations

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import zero_decision
from ..vectors import Point, Vector
from ..vectors.geometry import Line
from ..vectors.points import check_point


def _check_vector(v, argument):
    if isinstance(v, Point):
        raise ArgumentTypeError(
            f"`{argument}` must be a Vector; got the Point {v.name}. Use a bipoint B - A."
        )
    if not isinstance(v, Vector):
        raise ArgumentTypeError(f"`{argument}` must be a Vector; got {type(v).__name__}.")


def _vector_is_zero(v: Vector) -> bool | None:
    """Exact decision on a vector: True/False, or None if undecidable.

    Decided component by component in one basis: one component decidedly non-zero is enough
    to say False, which decides cases such as ``a*R0.i + R0.j`` that |v|^2 leaves open.
    """
    if v.is_zero:
        return True
    decisions = [zero_decision(c) for c in v.components(v.frames[0])]
    if any(d is False for d in decisions):
        return False
    if all(d is True for d in decisions):
        return True
    return None


def _undecided(quantity: str, value) -> ArgumentError:
    return ArgumentError(
        f"cannot decide whether {quantity} is zero for symbolic values: got {value}; "
        "substitute values (subs) or declare assumptions on the symbols."
    )


def _is_line(obj) -> bool:
    return isinstance(obj, Line)


def _make_line(point: Point, direction: Vector) -> Line:
    return Line(point, direction)


def _axis_elements(axis, direction):
    """(point, direction vector) of an axis given as a Line or as a Point + direction."""
    if _is_line(axis):
        if direction is not None:
            raise ArgumentError(
                "`direction` must be omitted when `axis` is a Line (the line has its own); "
                f"got {direction!r}."
            )
        return axis.point, axis.direction
    if isinstance(axis, Vector):
        raise ArgumentTypeError(
            "`axis` must be a Line or a Point (a Vector is not a Point: give a point of the "
            "axis and pass the vector as `direction`); got Vector."
        )
    check_point(axis, "axis")
    if direction is None:
        raise ArgumentError(
            f"`direction` is needed when `axis` is the Point {axis.name}; got None."
        )
    _check_vector(direction, "direction")
    if _vector_is_zero(direction) is True:
        raise ArgumentError("`direction` must be a non-zero Vector; got the zero vector.")
    return axis, direction
