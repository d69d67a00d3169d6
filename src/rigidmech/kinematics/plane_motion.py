"""Plane motion: instantaneous centre of rotation and centrodes (book, ch. 9.4.5).

A solid S is in plane motion relative to R when its rotation vector keeps a fixed direction k
of R and the velocities of its points are orthogonal to k. If omega(S/R) = omega k with
omega != 0, the velocity field is that of a rotation about the point I of the plane of A
with (ch. 9.4.5)

.. math::
    \\mathbf{AI} = \\frac{\\mathbf{k} \\wedge \\mathbf{v}(A \\in S/R)}{\\omega},

the **instantaneous centre of rotation** (v(I in S/R) = 0). For a motion depending on one
parameter q, I traces the **base curve** (fixed centrode) in R and the **rolling curve**
(moving centrode) in S; the rolling curve rolls without slipping on the base curve.
"""

from __future__ import annotations

from typing import NamedTuple

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..vectors import Curve, Frame, Point, Vector, t
from ..vectors.symbols import is_coordinate
from .solid import Solid

__all__ = ["instantaneous_centre", "Centrodes", "centrodes"]


def _frame(x, argument):
    if isinstance(x, Solid):
        return x.frame
    if isinstance(x, Frame):
        return x
    raise ArgumentTypeError(
        f"`{argument}` must be a Frame, a Solid or a Body; got {type(x).__name__}.")


def _plane_data(frame, relative_to):
    """(k, omega, A, v(A)) for the plane motion of ``frame`` relative to ``relative_to``."""
    w = frame.rotation_vector(relative_to).compact()
    A = frame.origin
    vA = A.velocity(relative_to)
    if w.is_zero or sp.simplify(w.dot(w)) == 0:
        raise ArgumentError(
            f"the motion of {frame.name} relative to {relative_to.name} is a translation "
            "(omega = 0): it has no instantaneous centre of rotation.")
    k = None
    for f, c in w.parts:
        nz = [n for n in range(3) if c[n] != 0]
        if len(w.parts) == 1 and len(nz) == 1:
            k = f.basis[nz[0]]
    if k is None or not k.dt(relative_to).is_zero or not k.dt(frame).is_zero:
        raise ArgumentError(
            f"`moving` must be in plane motion relative to `relative_to`: omega({frame.name}/"
            f"{relative_to.name}) must keep a fixed direction; got {w!r}.")
    vk = sp.simplify(vA.dot(k))
    if vk != 0:
        raise ArgumentError(
            f"`moving` must be in plane motion relative to `relative_to`: the velocity of "
            f"{A.name} must be orthogonal to the rotation axis {k!r}; got a component {vk}.")
    return k, w.dot(k), A, vA


def instantaneous_centre(moving, *, relative_to, name: str = "I") -> Point:
    """The instantaneous centre of rotation of a plane motion (ch. 9.4.5), in the plane of the
    origin of the moving frame.

    Parameters
    ----------
    moving : Frame, Solid or Body
        The solid S.
    relative_to : Frame
        The reference R.
    name : str
        Name of the returned point.

    Returns
    -------
    Point
        I with v(I in S/R) = 0; its position depends on the parameters and, for a motion
        with several parameters, on their derivatives.

    Raises
    ------
    ArgumentError
        If the motion is a translation or not a plane motion.

    Examples
    --------
    A ladder of length L, end A on the floor (O, i0), end B on the wall (O, j0), at the
    angle theta to the floor: I is the corner of the rectangle built on OA and OB.

    >>> import sympy as sp
    >>> from rigidmech import Frame, coordinates
    >>> theta = coordinates("theta"); L = sp.Symbol("L", positive=True)
    >>> R0 = Frame("R0")
    >>> ladder = R0.rotated("R1", about=R0.k, angle=sp.pi - theta,
    ...                     origin=R0.point("A", L * sp.cos(theta), 0, 0))
    >>> instantaneous_centre(ladder, relative_to=R0).coordinates(R0).T
    Matrix([[L*cos(theta(t)), L*sin(theta(t)), 0]])
    """
    frame = _frame(moving, "moving")
    if not isinstance(relative_to, Frame):
        raise ArgumentTypeError(
            f"`relative_to` must be a Frame; got {type(relative_to).__name__}.")
    k, omega, A, vA = _plane_data(frame, relative_to)
    AI = (k.cross(vA) / omega).applyfunc(sp.simplify)
    return A.moved(name, AI)


class Centrodes(NamedTuple):
    """The base curve (fixed centrode, in the reference) and the rolling curve (moving
    centrode, in the moving solid) of a plane motion (ch. 9.4.5), as
    :class:`~rigidmech.vectors.Curve` of the parameter.

    Examples
    --------
    >>> Centrodes._fields
    ('base', 'rolling')
    """

    base: Curve
    rolling: Curve


def centrodes(moving, *, relative_to, parameter, symbol=None) -> Centrodes:
    """The centrodes of a plane motion depending on one parameter (ch. 9.4.5).

    Parameters
    ----------
    moving : Frame, Solid or Body
        The solid S, whose frame depends on the one parameter q(t) (and constants).
    relative_to : Frame
        The reference R.
    parameter : sympy expression
        The parameter of situation q(t) (from :func:`rigidmech.coordinates`).
    symbol : sympy.Symbol, optional
        The curve parameter standing for q (default: a real symbol named like q).

    Returns
    -------
    Centrodes
        ``base``: I relative to R, components in R's basis; ``rolling``: I relative to the
        moving frame, components in its basis.

    Raises
    ------
    ArgumentError
        If the motion depends on anything else than q (another parameter, the time).

    Examples
    --------
    The ladder of :func:`instantaneous_centre`: the base curve is the circle of radius L
    about the corner O, the rolling curve the circle of diameter AB.

    >>> import sympy as sp
    >>> from rigidmech import Frame, coordinates
    >>> theta = coordinates("theta"); L = sp.Symbol("L", positive=True)
    >>> R0 = Frame("R0")
    >>> ladder = R0.rotated("R1", about=R0.k, angle=sp.pi - theta,
    ...                     origin=R0.point("A", L * sp.cos(theta), 0, 0))
    >>> base, rolling = centrodes(ladder, relative_to=R0, parameter=theta)
    >>> base.curvature(), rolling.curvature()
    (1/L, 2/L)
    """
    frame = _frame(moving, "moving")
    if not is_coordinate(parameter):
        raise ArgumentTypeError(
            f"`parameter` must be a parameter of situation q(t) (rigidmech.coordinates); got "
            f"{parameter!r}.")
    s = symbol if symbol is not None else sp.Symbol(str(parameter.func), real=True)
    if not isinstance(s, sp.Symbol):
        raise ArgumentTypeError(f"`symbol` must be a sympy Symbol; got {type(s).__name__}.")
    I = instantaneous_centre(frame, relative_to=relative_to)
    rule = {parameter.diff(t): sp.S.One}

    def curve_in(f):
        comps = (I - f.origin).components(f).xreplace(rule)
        comps = comps.xreplace({parameter: s}).applyfunc(sp.simplify)
        extra = {a for a in comps.atoms(sp.Function, sp.Derivative) if a.has(t)}
        if extra or comps.has(t):
            raise ArgumentError(
                f"`moving` must depend on the one parameter {parameter} (and constants); the "
                f"instantaneous centre also depends on {sorted(map(str, extra)) or 't'}.")
        return Curve(Vector.from_components(f, comps), s, f)

    return Centrodes(curve_in(relative_to), curve_in(frame))
