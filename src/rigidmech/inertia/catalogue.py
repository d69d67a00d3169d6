"""Operators of inertia of homogeneous bodies at their mass centre (book, ch. 15.5).

Every function returns an :class:`~rigidmech.inertia.InertiaOperator` at the body's mass
centre G, in the basis of the frame that carries the body's axis. G is the keyword ``centre``
and defaults to the origin of that frame: pass ``centre=`` when the body's mass centre is
elsewhere (the matrix at G does not depend on where G is; only the operator's point does).

Bodies of revolution take ``axis``, a basis vector of a frame (``R1.i``, ``R1.j``, ``R1.k`` or
an opposite): the matrix is diagonal in that frame's basis with the axial moment on the axis
and the transverse moment on the two others (ch. 15.4.2). Bodies with three planes of symmetry
(block, plate, ellipsoid) take ``frame`` with their edges or semi-axes along i, j, k
(ch. 15.4.1); a sphere takes ``frame`` (ch. 15.4.3).

The table below gives the moments at G (m the mass; axial about the axis of revolution,
transverse about any line through G normal to it).

====================  =====================  ==================================
body                  axial                  transverse
====================  =====================  ==================================
rod, length L         0                      m L^2 / 12
ring (hoop), R        m R^2                  m R^2 / 2
disk, R               m R^2 / 2              m R^2 / 4
cylinder, R, L        m R^2 / 2              m (3 R^2 + L^2) / 12
tube, r1, r2, L       m (r1^2 + r2^2) / 2    m (3 (r1^2 + r2^2) + L^2) / 12
cylindrical shell     m R^2                  m (6 R^2 + L^2) / 12
cone, R, height h     3 m R^2 / 10           3 m (4 R^2 + h^2) / 80
hemisphere, R         2 m R^2 / 5            83 m R^2 / 320
point mass            0                      0
sphere, R             2 m R^2 / 5            (same)
spherical shell, R    2 m R^2 / 3            (same)
====================  =====================  ==================================
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..vectors import Vector
from ._checks import check_frame, nonnegative
from .operator import UNPLACED, InertiaOperator
from .shapes import Shape

__all__ = [
    "rod", "ring", "disk", "cylinder", "tube", "hollow_cylinder", "cylindrical_shell",
    "cone", "sphere", "spherical_shell", "block", "rectangular_plate", "ellipsoid",
    "hemisphere", "point_mass",
]

_R = sp.Rational


def _axis(axis):
    """(frame, index) of a basis vector of a frame (or its opposite)."""
    if isinstance(axis, Vector) and len(axis.parts) == 1:
        frame, comps = axis.parts[0]
        nonzero = [n for n in range(3) if comps[n] != 0]
        if len(nonzero) == 1 and comps[nonzero[0]] in (1, -1):
            return frame, nonzero[0]
    if not isinstance(axis, Vector):
        raise ArgumentTypeError(
            f"`axis` must be a basis vector of a frame (such as R1.i); "
            f"got {type(axis).__name__}."
        )
    raise ArgumentError(
        f"`axis` must be a basis vector of a frame (such as R1.i or -R1.k); got {axis!r}. "
        "For another direction, make a frame whose basis vector it is (Frame.rotated)."
    )


def _revolution(axis, axial, transverse, centre, shape):
    frame, n = _axis(axis)
    moments = [transverse] * 3
    moments[n] = axial
    return _central(InertiaOperator.from_products(*moments, frame=frame, at=centre), centre,
                    Shape(shape[0], shape[1:], axis=axis))


def _central(op, centre, shape):
    """Mark a catalogue operator as taken at the body's mass centre (see
    :meth:`InertiaOperator.placed_at`): at the given ``centre``, or, without one, at the
    frame's origin until a body places it at its own mass centre; tag it with its
    :class:`~rigidmech.inertia.Shape`."""
    return InertiaOperator._make(op.matrix, op.frame, op.at,
                                 central=True if centre is not None else UNPLACED, shape=shape)


def rod(mass, length, *, axis, centre=None) -> InertiaOperator:
    """Slender homogeneous rod of length ``length`` along ``axis`` (ch. 15.5.1).

    Parameters
    ----------
    mass, length : number or sympy expression, >= 0
    axis : Vector
        Basis vector of the frame carrying the rod (``R1.i``); the matrix is given in that
        frame's basis.
    centre : Point, optional
        Mass centre (mid-point) of the rod; defaults to the origin of the axis's frame.

    Returns
    -------
    InertiaOperator
        At the mid-point: 0 about the rod, m L^2 / 12 about the normal axes.

    Raises
    ------
    ArgumentError
        For a negative mass or length, or an ``axis`` that is not a basis vector.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> m, L = sp.symbols("m L", positive=True)
    >>> R1 = Frame("R1")
    >>> rod(m, L, axis=R1.i).matrix
    Matrix([
    [0,         0,         0],
    [0, L**2*m/12,         0],
    [0,         0, L**2*m/12]])
    >>> rod(-1, L, axis=R1.i)
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `mass` must be >= 0; got -1.
    """
    m, L = nonnegative(mass, "mass"), nonnegative(length, "length")
    return _revolution(axis, sp.S.Zero, m * L**2 / 12, centre, ("rod", L))


def ring(mass, radius, *, axis, centre=None) -> InertiaOperator:
    """Thin circular hoop of radius ``radius`` with its axis along ``axis`` (ch. 15.5.1).

    m R^2 about the axis, m R^2 / 2 about the diameters.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> ring(2, 3, axis=R0.k).matrix.diagonal()
    Matrix([[9, 9, 18]])
    """
    m, R = nonnegative(mass, "mass"), nonnegative(radius, "radius")
    return _revolution(axis, m * R**2, m * R**2 / 2, centre, ("ring", R))


def disk(mass, radius, *, axis, centre=None) -> InertiaOperator:
    """Thin homogeneous disk of radius ``radius``, ``axis`` normal to it (ch. 15.5.2).

    m R^2 / 2 about the axis, m R^2 / 4 about the diameters.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> m, R = sp.symbols("m R", positive=True)
    >>> R0 = Frame("R0")
    >>> disk(m, R, axis=R0.k).matrix.diagonal()
    Matrix([[R**2*m/4, R**2*m/4, R**2*m/2]])
    """
    m, R = nonnegative(mass, "mass"), nonnegative(radius, "radius")
    return _revolution(axis, m * R**2 / 2, m * R**2 / 4, centre, ("disk", R))


def cylinder(mass, radius, length, *, axis, centre=None) -> InertiaOperator:
    """Solid homogeneous circular cylinder, axis along ``axis`` (ch. 15.5.3).

    m R^2 / 2 about the axis, m (3 R^2 + L^2) / 12 about the normal axes through G.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> m, R, L = sp.symbols("m R L", positive=True)
    >>> R0 = Frame("R0")
    >>> cylinder(m, R, L, axis=R0.k).A
    m*(L**2 + 3*R**2)/12
    """
    m, R, L = (nonnegative(x, n) for x, n in ((mass, "mass"), (radius, "radius"),
                                               (length, "length")))
    return _revolution(axis, m * R**2 / 2, m * (3 * R**2 + L**2) / 12, centre,
                       ("cylinder", R, L))


def tube(mass, r_in, r_out, length, *, axis, centre=None) -> InertiaOperator:
    """Thick homogeneous tube (hollow cylinder) of radii ``r_in`` <= ``r_out`` (ch. 15.5.3).

    m (r1^2 + r2^2) / 2 about the axis, m (3 (r1^2 + r2^2) + L^2) / 12 about the normal
    axes through G. ``tube(m, 0, R, L)`` is the solid cylinder.

    Raises
    ------
    ArgumentError
        If ``r_in > r_out`` (when decidable).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> tube(2, 1, 2, 3, axis=R0.k).matrix.diagonal()
    Matrix([[4, 4, 5]])
    """
    m, r1, r2, L = (nonnegative(x, n) for x, n in (
        (mass, "mass"), (r_in, "r_in"), (r_out, "r_out"), (length, "length")))
    if (r2 - r1).is_negative:
        raise ArgumentError(f"`r_in` must be <= `r_out`; got r_in={r_in} and r_out={r_out}.")
    s = r1**2 + r2**2
    return _revolution(axis, m * s / 2, m * (3 * s + L**2) / 12, centre, ("tube", r1, r2, L))


hollow_cylinder = tube


def cylindrical_shell(mass, radius, length, *, axis, centre=None) -> InertiaOperator:
    """Thin cylindrical surface (no ends) of radius ``radius`` and length ``length``
    (ch. 15.5.2).

    m R^2 about the axis, m (6 R^2 + L^2) / 12 about the normal axes through G.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> cylindrical_shell(3, 1, 2, axis=R0.k).matrix.diagonal()
    Matrix([[5/2, 5/2, 3]])
    """
    m, R, L = (nonnegative(x, n) for x, n in ((mass, "mass"), (radius, "radius"),
                                               (length, "length")))
    return _revolution(axis, m * R**2, m * (6 * R**2 + L**2) / 12, centre,
                       ("cylindrical_shell", R, L))


def cone(mass, radius, height, *, axis, centre=None) -> InertiaOperator:
    """Solid homogeneous circular cone of base radius ``radius`` and height ``height``, at
    its mass centre (on the axis, at height/4 from the base) (ch. 15.5.3).

    3 m R^2 / 10 about the axis, 3 m (4 R^2 + h^2) / 80 about the normal axes through G.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> m, R, h = sp.symbols("m R h", positive=True)
    >>> R0 = Frame("R0")
    >>> cone(m, R, h, axis=R0.k).C
    3*R**2*m/10
    """
    m, R, h = (nonnegative(x, n) for x, n in ((mass, "mass"), (radius, "radius"),
                                               (height, "height")))
    return _revolution(axis, _R(3, 10) * m * R**2, _R(3, 80) * m * (4 * R**2 + h**2), centre,
                       ("cone", R, h))


def sphere(mass, radius, *, frame, centre=None) -> InertiaOperator:
    """Solid homogeneous sphere (ball): 2 m R^2 / 5 about every axis through its centre
    (ch. 15.4.3, 15.5.3).

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> m, R = sp.symbols("m R", positive=True)
    >>> sphere(m, R, frame=Frame("R0")).A
    2*R**2*m/5
    """
    check_frame(frame, "frame")
    m, R = nonnegative(mass, "mass"), nonnegative(radius, "radius")
    return _central(_revolution(frame.k, _R(2, 5) * m * R**2, _R(2, 5) * m * R**2, centre,
                                ("disk", R)), centre, Shape("sphere", [R], frame=frame))


def spherical_shell(mass, radius, *, frame, centre=None) -> InertiaOperator:
    """Thin spherical surface: 2 m R^2 / 3 about every axis through its centre (ch. 15.5.2).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> spherical_shell(3, 1, frame=Frame("R0")).B
    2
    """
    check_frame(frame, "frame")
    m, R = nonnegative(mass, "mass"), nonnegative(radius, "radius")
    return _central(_revolution(frame.k, _R(2, 3) * m * R**2, _R(2, 3) * m * R**2, centre,
                                ("disk", R)), centre, Shape("spherical_shell", [R], frame=frame))


def block(mass, a, b, c, *, frame, centre=None) -> InertiaOperator:
    """Homogeneous rectangular parallelepiped with edges ``a``, ``b``, ``c`` along the
    basis vectors i, j, k of ``frame`` (ch. 15.5.3).

    A = m (b^2 + c^2) / 12, B = m (c^2 + a^2) / 12, C = m (a^2 + b^2) / 12 at the centre.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> m, a, b, c = sp.symbols("m a b c", positive=True)
    >>> block(m, a, b, c, frame=Frame("R0")).A
    m*(b**2 + c**2)/12
    """
    check_frame(frame, "frame")
    m, a, b, c = (nonnegative(x, n) for x, n in ((mass, "mass"), (a, "a"), (b, "b"),
                                                  (c, "c")))
    return _central(centre=centre, op=InertiaOperator.from_products(
        m * (b**2 + c**2) / 12, m * (c**2 + a**2) / 12, m * (a**2 + b**2) / 12, frame=frame,
        at=centre), shape=Shape("block", [a, b, c], frame=frame))


def rectangular_plate(mass, a, b, *, frame, centre=None) -> InertiaOperator:
    """Thin homogeneous rectangular plate with edges ``a`` along i and ``b`` along j of
    ``frame``, normal k (ch. 15.5.2): ``block(mass, a, b, 0, frame=frame)``.

    A = m b^2 / 12, B = m a^2 / 12, C = A + B (plane solid, ch. 15.3.3).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> rectangular_plate(12, 1, 2, frame=Frame("R0")).matrix.diagonal()
    Matrix([[4, 1, 5]])
    """
    return block(mass, a, b, 0, frame=frame, centre=centre)


def ellipsoid(mass, a, b, c, *, frame, centre=None) -> InertiaOperator:
    """Solid homogeneous ellipsoid with semi-axes ``a``, ``b``, ``c`` along i, j, k of
    ``frame`` (ch. 15.5.3).

    A = m (b^2 + c^2) / 5, B = m (c^2 + a^2) / 5, C = m (a^2 + b^2) / 5 at the centre.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> ellipsoid(5, 1, 1, 1, frame=Frame("R0")).A
    2
    """
    check_frame(frame, "frame")
    m, a, b, c = (nonnegative(x, n) for x, n in ((mass, "mass"), (a, "a"), (b, "b"),
                                                  (c, "c")))
    return _central(centre=centre, op=InertiaOperator.from_products(
        m * (b**2 + c**2) / 5, m * (c**2 + a**2) / 5, m * (a**2 + b**2) / 5, frame=frame,
        at=centre), shape=Shape("ellipsoid", [a, b, c], frame=frame))


def hemisphere(mass, radius, *, axis, centre=None) -> InertiaOperator:
    """Solid homogeneous hemisphere of radius ``radius``, ``axis`` along its axis of
    symmetry, at its mass centre G (on the axis at 3R/8 from the flat face), ch. 15.5.3.

    2 m R^2 / 5 about the axis; about the normal axes through G, the 2 m R^2 / 5 of the
    centre of the flat face less m (3R/8)^2 (Huygens): 83 m R^2 / 320.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> m, R = sp.symbols("m R", positive=True)
    >>> hemisphere(m, R, axis=Frame("R0").k).matrix.diagonal()
    Matrix([[83*R**2*m/320, 83*R**2*m/320, 2*R**2*m/5]])
    """
    m, R = nonnegative(mass, "mass"), nonnegative(radius, "radius")
    return _revolution(axis, _R(2, 5) * m * R**2, _R(83, 320) * m * R**2, centre,
                       ("hemisphere", R))


def point_mass(mass, *, frame, centre=None) -> InertiaOperator:
    """A point mass (particle): the zero operator at its position (ch. 15.5.1). Its
    operator at any other point comes from Huygens' term alone.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> m, a = sp.symbols("m a", positive=True)
    >>> P = R0.point("P", a, 0, 0)
    >>> point_mass(m, frame=R0, centre=P).moved(R0.origin, mass=m, centre=P).C
    a**2*m
    """
    check_frame(frame, "frame")
    nonnegative(mass, "mass")
    return _central(InertiaOperator.from_products(0, 0, 0, frame=frame, at=centre), centre,
                    Shape("point_mass", frame=frame))
