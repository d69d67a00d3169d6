"""A body turning about a fixed point: the symmetric heavy top (book, ch. 9.4.4, 20).
"""

from __future__ import annotations

from ..actions import Spherical, gravity
from ..dynamics import System
from ..inertia import InertiaOperator, Shape
from ..kinetics import Body
from ..vectors import Frame, constants, coordinates
from ._model import Model

__all__ = ["heavy_top"]


def heavy_top() -> Model:
    """The symmetric heavy top: a body on a ball joint at O, its mass centre G at l on its
    axis R.k, gravity ``-g R0.k``.

    Oriented by the Euler angles psi (precession), theta (nutation) and phi (spin) of
    :meth:`~rigidmech.vectors.Frame.euler` (z-x-z); its moments about G are A (about the
    axes normal to its axis) and C (about its axis). The orientation is singular at
    theta = 0 (the axis vertical), where psi and phi turn about the same line (book,
    ch. 9.4.4: rotation about a fixed point).

    For drawing, the top is given the shape of a cone (``top.shape``) with its apex at O and
    its mass centre at G: height 4 l / 3 (a homogeneous cone's mass centre is at 3/4 of its
    height from the apex) and radius l / 2. The shape is for the picture only: the moments
    A and C stay parameters of their own and need not be those of that cone.

    Returns
    -------
    Model
        coordinates (psi, theta, phi), constants (m, g, l, A, C), frames (R0, R), bodies
        (top,), points (O, G).

    Examples
    --------
    >>> from rigidmech import models
    >>> top = models.heavy_top()
    >>> top.system.equations_of_motion().mass_matrix[2, 2]
    C
    >>> top.bodies[0].shape
    Shape('cone', radius=l/2, height=4*l/3, axis=-R.k)
    """
    psi, theta, phi = coordinates("psi theta phi")
    m, g, l, A, C = constants("m g l A C", positive=True)
    R0 = Frame("R0")
    R = R0.euler("R", psi, theta, phi)
    G = R0.origin.moved("G", l * R.k)
    top = Body("top", frame=R, mass=m, centre=G,
               inertia=InertiaOperator.from_products(A, A, C, frame=R, at=G),
               shape=Shape("cone", [l / 2, 4 * l / 3], axis=-R.k))
    system = System(galilean=R0)
    system.connect(R0, top, Spherical(at=R0.origin))
    system.act(gravity(-g * R0.k))
    return Model(system, (psi, theta, phi), (m, g, l, A, C), (R0, R), (top,), (R0.origin, G))
