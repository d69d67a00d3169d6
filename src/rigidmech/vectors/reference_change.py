"""Change of reference system: coordinates of a point in two frames (book, ch. 2.5).

The coordinates of a point M in two reference systems R0 = (O0; i0, j0, k0) and
R1 = (O1; i1, j1, k1) are related by O0M = O0O1 + O1M (ch. 2.5.1): an affine map
x0 = M x1 + b whose matrix M holds the direction cosines of the two bases and whose translation
b holds the coordinates of O1 in R0. :func:`affine_map` and :func:`change_of_coordinates` give the
general case for any two frames of a tree; :func:`common_axis_map` (ch. 2.5.2) and
:func:`common_origin_map` (ch. 2.5.3, Euler angles) write out the book's particular formulas,
which :meth:`Frame.rotated <rigidmech.vectors.Frame.rotated>`,
:meth:`Frame.translated <rigidmech.vectors.Frame.translated>` and
:meth:`Frame.euler <rigidmech.vectors.Frame.euler>` build as frames.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ._rotations import elementary
from .points import Point
from .vector import _check_frame

__all__ = ["affine_map", "change_of_coordinates", "common_axis_map", "common_origin_map"]


def affine_map(from_frame, to_frame):
    """The affine map of the change of reference system (ch. 2.5.1).

    Returns
    -------
    (M, b) : (sympy.ImmutableMatrix (3, 3), sympy.ImmutableMatrix (3, 1))
        Coordinates in ``to_frame`` from coordinates in ``from_frame``: x_to = M x_from + b,
        where M is ``to_frame.dcm(from_frame)`` and b the coordinates of the origin of
        ``from_frame`` in ``to_frame`` (from O_to M = O_to O_from + O_from M).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> R1 = R0.translated("R1", R0.point("O1", 1, 2, 3))
    >>> M, b = affine_map(R1, R0)
    >>> b.T
    Matrix([[1, 2, 3]])
    """
    _check_frame(from_frame, "from_frame")
    _check_frame(to_frame, "to_frame")
    return (to_frame.dcm(from_frame), from_frame.origin.coordinates(to_frame))


def change_of_coordinates(point_or_coords, from_frame, to_frame) -> sp.ImmutableMatrix:
    """Coordinates in ``to_frame`` of a point given by coordinates in ``from_frame`` (ch. 2.5.1).

    Parameters
    ----------
    point_or_coords : Point or sequence of 3 scalars
        A Point (then ``from_frame`` is not used and may be None) or its coordinates
        (x, y, z) in ``from_frame``.
    from_frame, to_frame : Frame

    Returns
    -------
    sympy.ImmutableMatrix, shape (3, 1)

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> import sympy as sp
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.k, angle=sp.pi / 2, origin=R0.point("O1", 1, 0, 0))
    >>> change_of_coordinates((1, 0, 0), R1, R0).T
    Matrix([[1, 1, 0]])
    """
    _check_frame(to_frame, "to_frame")
    if isinstance(point_or_coords, Point):
        return point_or_coords.coordinates(to_frame)
    _check_frame(from_frame, "from_frame")
    try:
        x = sp.Matrix([sp.sympify(c) for c in point_or_coords])
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`point_or_coords` must be a Point or 3 coordinates; got {point_or_coords!r}."
        ) from exc
    if x.shape != (3, 1):
        raise ArgumentError(
            f"`point_or_coords` must hold 3 coordinates; got {len(x)}: {point_or_coords!r}."
        )
    M, b = affine_map(from_frame, to_frame)
    return sp.ImmutableMatrix(M * x + b)


_AXIS = {"x": 0, "y": 1, "z": 2, 0: 0, 1: 1, 2: 2}


def common_axis_map(axis, angle, origin=(0, 0, 0)):
    """Coordinate change between reference systems with a common axis (ch. 2.5.2).

    R1 is obtained from R0 by a rotation by ``angle`` about the axis ``axis`` of R0, its origin
    O1 having the coordinates ``origin`` = (a, b, c) in R0. For the axis z the book writes

    .. math:: x_0 = a + x_1\\cos\\theta - y_1\\sin\\theta, \\quad
              y_0 = b + x_1\\sin\\theta + y_1\\cos\\theta, \\quad z_0 = c + z_1 .

    Parameters
    ----------
    axis : {"x", "y", "z"} or {0, 1, 2}
    angle : sympy expression
    origin : sequence of 3 scalars

    Returns
    -------
    (M, b)
        x0 = M x1 + b (the inverse is x1 = M^T (x0 - b)); equal to ``affine_map(R1, R0)``.

    Examples
    --------
    >>> import sympy as sp
    >>> th = sp.Symbol("theta")
    >>> M, b = common_axis_map("z", th, (1, 2, 3))
    >>> M
    Matrix([
    [cos(theta), -sin(theta), 0],
    [sin(theta),  cos(theta), 0],
    [         0,           0, 1]])
    """
    if axis not in _AXIS:
        raise ArgumentError(f"`axis` must be 'x', 'y', 'z' or 0, 1, 2; got {axis!r}.")
    b = sp.ImmutableMatrix([sp.sympify(c) for c in origin])
    if b.shape != (3, 1):
        raise ArgumentError(f"`origin` must hold 3 coordinates; got {len(b)}.")
    return (sp.ImmutableMatrix(elementary(_AXIS[axis], sp.sympify(angle))), b)


def common_origin_map(precession, nutation, spin):
    """Coordinate change between reference systems with a common origin, by the Euler angles
    (ch. 2.5.3, 9.1.2): precession psi about z0, nutation theta about the line of nodes u,
    spin phi about z (z-x-z).

    Returns
    -------
    (M, b)
        x0 = M x1 + b with M = Rz(psi) Rx(theta) Rz(phi) and b = 0; equal to
        ``affine_map(R0.euler("R1", psi, theta, phi), R0)``.

    Examples
    --------
    >>> import sympy as sp
    >>> M, b = common_origin_map(sp.pi / 2, 0, 0)
    >>> M.T * sp.Matrix([1, 0, 0])
    Matrix([
    [ 0],
    [-1],
    [ 0]])
    """
    m = (sp.Matrix(elementary(2, sp.sympify(precession)))
         * sp.Matrix(elementary(0, sp.sympify(nutation)))
         * sp.Matrix(elementary(2, sp.sympify(spin))))
    return (sp.ImmutableMatrix(m), sp.ImmutableMatrix(sp.zeros(3, 1)))
