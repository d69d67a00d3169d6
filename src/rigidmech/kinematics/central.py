"""Motion with central acceleration: areal velocity, areal constant, Binet's formulas
(book, ch. 8).

The acceleration of a point M is central, of centre O fixed in the reference R, when
OM ^ a(M/R) = 0 at every instant (ch. 8.1.1). Then the vector OM ^ v(M/R) is constant: the motion
is plane and obeys the law of areas. In polar coordinates (r, theta) in that plane,

.. math::
    \\frac{dA}{dt} = \\tfrac12\\,r^2\\dot\\theta = \\tfrac12\\,C,\\qquad
    C = r^2\\dot\\theta \\quad\\text{(areal constant, ch. 8.1.3-8.1.4)},

and with u = 1/r written as a function of theta Binet's formulas read (ch. 8.1.5-8.1.6)

.. math::
    v^2 = C^2\\left(u^2 + \\left(\\frac{du}{d\\theta}\\right)^2\\right),\\qquad
    \\mathbf{a} = -C^2u^2\\left(u + \\frac{d^2u}{d\\theta^2}\\right)\\mathbf{e}_r .

The numerical side of orbits (conic from a state, Kepler's equation, transfers) is in
:mod:`rigidmech.kinematics.orbits`.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentTypeError
from ..vectors import Frame, Point, Vector
from ..vectors.points import check_point

__all__ = ["areal_velocity", "areal_constant", "is_central", "binet_speed_squared",
           "binet_acceleration"]


def _check(point, centre, frame):
    check_point(point, "point")
    check_point(centre, "centre")
    if not isinstance(frame, Frame):
        raise ArgumentTypeError(f"`frame` must be a Frame; got {type(frame).__name__}.")


def areal_velocity(point: Point, *, centre: Point, frame: Frame) -> Vector:
    """The vector areal velocity (1/2) OM ^ v(M/R) of M about ``centre`` (ch. 8.1.3).

    Its magnitude is the rate dA/dt at which the radius OM sweeps area.

    Examples
    --------
    >>> import rigidmech as rm
    >>> r, th = rm.coordinates("r theta")
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=th)
    >>> M = R0.origin.moved("M", r * R1.i)
    >>> areal_velocity(M, centre=R0.origin, frame=R0)
    r(t)**2*Derivative(theta(t), t)/2*R1.k
    """
    _check(point, centre, frame)
    return (point - centre).cross(point.velocity(frame)) / 2


def areal_constant(point: Point, *, centre: Point, frame: Frame) -> Vector:
    """The vector C = OM ^ v(M/R) (twice the areal velocity; C = r^2 theta' in the plane
    of the motion), constant when the acceleration is central (ch. 8.1.3).

    Examples
    --------
    >>> import rigidmech as rm
    >>> r, th = rm.coordinates("r theta")
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=th)
    >>> M = R0.origin.moved("M", r * R1.i)
    >>> areal_constant(M, centre=R0.origin, frame=R0).components(R0).T
    Matrix([[0, 0, r(t)**2*Derivative(theta(t), t)]])
    """
    _check(point, centre, frame)
    return (point - centre).cross(point.velocity(frame))


def is_central(point: Point, *, centre: Point, frame: Frame) -> bool:
    """Whether the acceleration of M relative to ``frame`` is central about ``centre``:
    OM ^ a(M/R) simplifies to zero (ch. 8.1.1).

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> w = rm.constants("omega")
    >>> R0 = rm.Frame("R0")
    >>> M = R0.point("M", sp.cos(w * rm.t), 2 * sp.sin(w * rm.t), 0)  # an ellipse, a = -w^2 OM
    >>> is_central(M, centre=R0.origin, frame=R0)
    True
    """
    _check(point, centre, frame)
    m = (point - centre).cross(point.acceleration(frame))
    return all(sp.simplify(c) == 0 for c in m.components(frame))


def _u_theta(u, theta):
    if not isinstance(theta, sp.Symbol):
        raise ArgumentTypeError(
            f"`theta` must be a sympy Symbol (the polar angle); got {type(theta).__name__}.")
    try:
        u = sp.sympify(u)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`u` must be a sympy expression of `theta`; got {type(u).__name__}.") from exc
    return u


def binet_speed_squared(u, theta: sp.Symbol, areal_constant) -> sp.Expr:
    """Binet's first formula v^2 = C^2 (u^2 + (du/dtheta)^2), u = 1/r (ch. 8.1.5).

    Parameters
    ----------
    u : sympy expression
        u = 1/r as a function of the polar angle ``theta`` (an expression or ``u(theta)``).
    theta : sympy.Symbol
    areal_constant : scalar
        C = r^2 dtheta/dt.

    Examples
    --------
    >>> import sympy as sp
    >>> th, p, e, C = sp.symbols("theta p e C", positive=True)
    >>> sp.simplify(binet_speed_squared((1 + e * sp.cos(th)) / p, th, C))
    C**2*(e**2 + 2*e*cos(theta) + 1)/p**2
    """
    u = _u_theta(u, theta)
    C = sp.sympify(areal_constant)
    return C**2 * (u**2 + sp.diff(u, theta) ** 2)


def binet_acceleration(u, theta: sp.Symbol, areal_constant) -> sp.Expr:
    """Binet's second formula: the radial acceleration a_r = -C^2 u^2 (u + d^2u/dtheta^2) of a
    motion with central acceleration (ch. 8.1.5); the orthoradial component is zero.

    Examples
    --------
    A conic u = (1 + e cos theta)/p is described under an acceleration in 1/r^2 (Newton):

    >>> import sympy as sp
    >>> th, p, e, C = sp.symbols("theta p e C", positive=True)
    >>> u = (1 + e * sp.cos(th)) / p
    >>> sp.simplify(binet_acceleration(u, th, C) / u**2)
    -C**2/p
    """
    u = _u_theta(u, theta)
    C = sp.sympify(areal_constant)
    return -(C**2) * u**2 * (u + sp.diff(u, theta, 2))
