"""Open chains of rods on pivots: the compound pendulum, the double pendulum, the planar
n-link pendulum and the pendulum on a cart (book, ch. 21, 22.2.1, 24.3, 25.3, 25.4.3).

Every rod lies along its frame's ``i`` and is pivoted about ``k`` at its first end; it is
uniform (:func:`rigidmech.inertia.rod`) but in the point-mass double pendulum (massless rods).
"""

from __future__ import annotations

import sympy as sp

from .. import inertia
from .._core.errors import ArgumentError
from ..actions import Pivot, Prismatic, Spherical, gravity
from ..dynamics import System
from ..inertia import InertiaOperator
from ..kinetics import Body
from ..vectors import Frame, constants, coordinates
from ._model import Model

__all__ = ["compound_pendulum", "double_pendulum", "point_mass_double_pendulum",
           "n_link_pendulum", "cart_pendulum"]


def _rod(name, frame, at, m, length, centre_name):
    """A uniform rod of mass ``m`` and ``length`` from ``at`` along ``frame.i``."""
    G = at.moved(centre_name, length / 2 * frame.i)
    return Body(name, frame=frame, mass=m, centre=G,
                inertia=inertia.rod(m, length, axis=frame.i, centre=G))


def compound_pendulum() -> Model:
    """A uniform rod (mass m, length L) on a pivot at O, gravity ``g R0.i`` (``i`` down).

    The book's compound pendulum (ch. 22.2.1): theta is the rod's angle from the downward
    vertical about k; its equation is (m L^2 / 3) theta'' = -(m g L / 2) sin(theta).

    Returns
    -------
    Model
        coordinates (theta,), constants (m, L, g), frames (R0, R1), bodies (bar,),
        points (O, G).

    Examples
    --------
    >>> from rigidmech import models
    >>> eqs = models.compound_pendulum().system.equations_of_motion()
    >>> eqs.mass_matrix, eqs.forcing
    (Matrix([[L**2*m/3]]), Matrix([[-L*g*m*sin(theta(t))/2]]))
    """
    theta = coordinates("theta")
    m, L, g = constants("m L g", positive=True)
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=theta)
    O = R0.origin
    bar = _rod("bar", R1, O, m, L, "G")
    system = System(galilean=R0)
    system.connect(R0, bar, Pivot(at=O, axis=R0.k))
    system.act(gravity(g * R0.i))
    return Model(system, (theta,), (m, L, g), (R0, R1), (bar,), (O, bar.centre))


def double_pendulum() -> Model:
    """Two uniform rods (mass m, length L each), absolute angles, gravity ``g R0.i``.

    The book's double pendulum (ch. 25.4.3, 27.5): theta1 and theta2 are the angles of the
    rods from the downward vertical i about k (the book also uses the relative angle
    theta2 - theta1); the second rod hangs from the tip A of the first. Its mass matrix is
    m L^2 [[4/3, cos(theta2 - theta1)/2], [cos(theta2 - theta1)/2, 1/3]].

    Returns
    -------
    Model
        coordinates (theta1, theta2), constants (m, L, g), frames (R0, R1, R2), bodies
        (bar1, bar2), points (O, A, G1, G2).

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import models
    >>> dp = models.double_pendulum()
    >>> M = dp.system.equations_of_motion().mass_matrix
    >>> sp.simplify(M[0, 1] / M[1, 1])
    3*cos(theta1(t) - theta2(t))/2
    """
    theta1, theta2 = coordinates("theta1 theta2")
    m, L, g = constants("m L g", positive=True)
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=theta1)
    R2 = R0.rotated("R2", about=R0.k, angle=theta2)  # absolute angle (relative to R0)
    O = R0.origin
    A = O.moved("A", L * R1.i)
    bar1 = _rod("bar1", R1, O, m, L, "G1")
    bar2 = _rod("bar2", R2, A, m, L, "G2")
    system = System(galilean=R0)
    system.connect(R0, bar1, Pivot(at=O, axis=R0.k))
    system.connect(bar1, bar2, Pivot(at=A, axis=R0.k))
    system.act(gravity(g * R0.i))
    return Model(system, (theta1, theta2), (m, L, g), (R0, R1, R2), (bar1, bar2),
                 (O, A, bar1.centre, bar2.centre))


def point_mass_double_pendulum() -> Model:
    """Two point masses m on massless rods of length l, absolute angles, gravity ``g R0.i``.

    The double pendulum of ch. 25.4.3 and 27.5.2 with the masses concentrated at the rods'
    ends: q1, q2 the angles of the rods from the downward vertical i about k; the bodies b1
    and b2 are points at A = O + l i1 and B = A + l i2. Its natural frequencies about the
    lower equilibrium are w^2 = (g / l)(2 -+ sqrt 2).

    Returns
    -------
    Model
        coordinates (q1, q2), constants (m, l, g), frames (R0, R1, R2), bodies (b1, b2),
        points (O, A, B).

    Examples
    --------
    >>> from rigidmech import models
    >>> models.point_mass_double_pendulum().system.equations_of_motion().mass_matrix[1, 1]
    l**2*m
    """
    q1, q2 = coordinates("q1 q2")
    m, l, g = constants("m l g", positive=True)
    R0 = Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R0.rotated("R2", about=R0.k, angle=q2)
    A = R0.origin.moved("A", l * R1.i)
    B = A.moved("B", l * R2.i)
    s = System(galilean=R0)
    b1 = Body("b1", frame=R1, mass=m, centre=A)
    b2 = Body("b2", frame=R2, mass=m, centre=B)
    s.connect(R0, b1, Pivot(at=R0.origin, axis=R0.k))
    s.connect(b1, b2, Pivot(at=A, axis=R0.k))
    s.act(gravity(g * R0.i))
    return Model(s, (q1, q2), (m, l, g), (R0, R1, R2), (b1, b2), (R0.origin, A, B))


def n_link_pendulum(n: int) -> Model:
    """The planar n-link pendulum: n uniform rods, relative angles, gravity ``-g R0.j``.

    Rod i (mass m_i, length l_i, body ``b<i>``, frame ``R<i>``) is turned by q_i about k
    relative to rod i - 1 (the first relative to R0) and pivoted at the tip ``P<i-1>`` of
    the previous one (O for the first); its centre is ``G<i>``. Each constant is its own
    symbol (m1, l1, m2, ...), g is shared. This is the chain of ch. 25.3 (a set of rigid
    bodies with independent parameters) used by the derivation benchmarks.

    Parameters
    ----------
    n : int
        Number of rods, at least 1.

    Returns
    -------
    Model
        coordinates (q1, ..., qn), constants (g, m1, l1, ..., mn, ln), frames (R0, ...,
        Rn), bodies (b1, ..., bn), points (O, P1, ..., Pn).

    Raises
    ------
    ArgumentError
        If ``n`` is not an integer >= 1.

    Examples
    --------
    >>> from rigidmech import models
    >>> chain = models.n_link_pendulum(1)
    >>> chain.system.equations_of_motion().mass_matrix
    Matrix([[l1**2*m1/3]])
    >>> [b.name for b in models.n_link_pendulum(3).bodies]
    ['b1', 'b2', 'b3']
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ArgumentError(f"`n` must be an integer >= 1 (the number of rods); got {n!r}.")
    qs = coordinates(" ".join(f"q{i}" for i in range(1, n + 1)))
    qs = qs if isinstance(qs, tuple) else (qs,)
    g = sp.Symbol("g", positive=True)
    R0 = Frame("R0")
    frame, P, parent = R0, R0.origin, R0
    system = System(galilean=R0)
    consts, frames, bodies, points = [g], [R0], [], [R0.origin]
    for i, q in enumerate(qs):
        m, l = sp.symbols(f"m{i + 1} l{i + 1}", positive=True)
        frame = frame.rotated(f"R{i + 1}", about=frame.k, angle=q)
        body = _rod(f"b{i + 1}", frame, P, m, l, f"G{i + 1}")
        system.connect(parent, body, Pivot(at=P, axis=R0.k))
        P = P.moved(f"P{i + 1}", l * frame.i)
        parent = body
        consts += [m, l]
        frames.append(frame)
        bodies.append(body)
        points.append(P)
    system.act(gravity(-g * R0.j))
    return Model(system, qs, tuple(consts), tuple(frames), tuple(bodies), tuple(points))


def spherical_chain(n: int) -> Model:
    """The 3D chain of n axisymmetric links on ball joints, hanging under gravity ``-g R0.k``.

    Link i (mass m_i, length l_i, transverse moment A_i and axial moment C_i about its centre
    ``G<i>``, body ``b<i>``) is oriented relative to link i - 1 (the first relative to R0) by
    the Euler angles z-x-z (psi_i, theta_i, phi_i) of the book's ch. 9.4.4, and joined at
    the tip ``P<i-1>`` of the previous link (O for the first) by a spherical joint; its axis is
    ``-R<i>.k``. Three parameters of situation per link: the 3D chain of the derivation and
    compilation benchmarks (ch. 25.3).

    Parameters
    ----------
    n : int
        Number of links, at least 1.

    Returns
    -------
    Model
        coordinates (psi1, theta1, phi1, ..., phin), constants (g, m1, l1, A1, C1, ...),
        frames (R0, ..., Rn), bodies (b1, ..., bn), points (O, P1, ..., Pn).

    Raises
    ------
    ArgumentError
        If ``n`` is not an integer >= 1.

    Examples
    --------
    >>> from rigidmech import models
    >>> top = models.spherical_chain(1)
    >>> [str(q) for q in top.coordinates]
    ['psi1(t)', 'theta1(t)', 'phi1(t)']
    >>> top.system.equations_of_motion().mass_matrix[2, 2]
    C1
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ArgumentError(f"`n` must be an integer >= 1 (the number of links); got {n!r}.")
    angles = coordinates(" ".join(f"psi{i} theta{i} phi{i}" for i in range(1, n + 1)))
    g = sp.Symbol("g", positive=True)
    R0 = Frame("R0")
    system = System(galilean=R0)
    frame, P, parent = R0, R0.origin, R0
    consts, frames, bodies, points = [g], [R0], [], [R0.origin]
    for i in range(n):
        psi, theta, phi = angles[3 * i: 3 * i + 3]
        m, l, A, C = sp.symbols(f"m{i + 1} l{i + 1} A{i + 1} C{i + 1}", positive=True)
        frame = frame.euler(f"R{i + 1}", psi, theta, phi)
        G = P.moved(f"G{i + 1}", -l / 2 * frame.k)
        body = Body(f"b{i + 1}", frame=frame, mass=m, centre=G,
                    inertia=InertiaOperator.from_products(A, A, C, frame=frame, at=G))
        system.connect(parent, body, Spherical(at=P))
        P = P.moved(f"P{i + 1}", -l * frame.k)
        parent = body
        consts += [m, l, A, C]
        frames.append(frame)
        bodies.append(body)
        points.append(P)
    system.act(gravity(-g * R0.k))
    return Model(system, tuple(angles), tuple(consts), tuple(frames), tuple(bodies),
                 tuple(points))


def cart_pendulum() -> Model:
    """A cart of mass M sliding along R0.i (x), carrying a point mass m on a massless rod of
    length L pivoted at the cart's centre C (theta about k, 0 hanging down along -R0.j);
    gravity ``-g R0.j``.

    Coupled motions of two solids (book, ch. 24.3, 21): besides the free translation, the
    small oscillations have w^2 = (M + m) g / (M L).

    Returns
    -------
    Model
        coordinates (x, theta), constants (M, m, L, g), frames (R0, Rc, Rp), bodies (cart,
        bob), points (C, P): P the point mass.

    Examples
    --------
    >>> from rigidmech import models
    >>> models.cart_pendulum().system.equations_of_motion().mass_matrix[0, 0]
    M + m
    """
    x, th = coordinates("x theta")
    M, m, L, g = constants("M m L g", positive=True)
    R0 = Frame("R0")
    Rc = R0.translated("Rc", R0.point("C", x, 0, 0))
    Rp = Rc.rotated("Rp", about=R0.k, angle=th)
    cart = Body("cart", frame=Rc, mass=M)
    P = Rc.origin.moved("P", -L * Rp.j)
    bob = Body("bob", frame=Rp, mass=m, centre=P)
    s = System(galilean=R0)
    s.connect(R0, cart, Prismatic(at=Rc.origin, axis=R0.i))
    s.connect(cart, bob, Pivot(at=Rc.origin, axis=R0.k))
    s.act(gravity(-g * R0.j))
    return Model(s, (x, th), (M, m, L, g), (R0, Rc, Rp), (cart, bob), (Rc.origin, P))
