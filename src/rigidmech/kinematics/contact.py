"""Kinematics of two solids in contact at a point: sliding, rolling, spinning (book, ch. 10.1).

Two solids S1 and S2 touch at the point I, with the common normal n (ch. 10.1.1). The motion
of S2 relative to S1 is described at I by the kinematic torsor
{V(S2/S1)} = {omega(S2/S1) ; v(I in S2/S1)}:

.. math::
    \\mathbf{v}(I \\in S_2/S_1) = \\mathbf{v}(I \\in S_2/R) - \\mathbf{v}(I \\in S_1/R)

is the **sliding velocity** (it lies in the tangent plane while the contact persists), and
the rotation vector splits along the normal and the tangent plane (ch. 10.1.2):

.. math::
    \\boldsymbol{\\omega}(S_2/S_1) = \\underbrace{(\\boldsymbol{\\omega}\\cdot\\mathbf{n})
    \\,\\mathbf{n}}_{\\text{spinning (pivoting)}} + \\underbrace{\\mathbf{n} \\wedge
    (\\boldsymbol{\\omega} \\wedge \\mathbf{n})}_{\\text{rolling}} .

S2 rolls **without slipping** on S1 when v(I in S2/S1) = 0 and **without pivoting** when
omega(S2/S1) . n = 0 (ch. 10.1.3). :class:`ContactKinematics` gives these vectors and the scalar
equations (sympy expressions that must vanish) in the parameters of situation and their
derivatives.
"""

from __future__ import annotations

import sympy as sp

from .._core.deprecation import deprecated_aliases
from .._core.errors import ArgumentError
from ..vectors import Point, Vector
from ..vectors.points import check_point
from .solid import Solid
from .solid import as_solid as _solid
from .surfaces import _unit, _vector, contact_geometry

__all__ = ["ContactKinematics"]


def _basis_vectors(solids):
    seen = []
    for s in solids:
        f = s.frame
        for frame in (f, f.root):
            if frame not in seen:
                seen.append(frame)
    return [e for f in seen for e in f.basis]


class ContactKinematics:
    """Two solids in contact at a point: S2 (``moving``) relative to S1 (``other``)
    (ch. 10.1).

    Parameters
    ----------
    moving, other : Solid, Body or Frame
        S2 and S1; the motion described is that of S2 relative to S1.
    at : Point
        The contact point I (a geometric point: it may move on both solids).
    normal : Vector
        The common normal n at I (normalised here if needed).

    See Also
    --------
    ContactKinematics.between : the contact point and normal from the two surfaces.

    Examples
    --------
    A wheel of radius r (frame R1, angle theta) on the line (O, i0), centre C at (x, r):

    >>> import sympy as sp
    >>> from rigidmech import Frame, coordinates
    >>> x, theta = coordinates("x theta"); r = sp.Symbol("r", positive=True)
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.k, angle=theta, origin=R0.point("C", x, r, 0))
    >>> c = ContactKinematics(R1, R0, at=R0.point("I", x, 0, 0), normal=R0.j)
    >>> c.sliding_velocity.components(R0).T
    Matrix([[r*Derivative(theta(t), t) + Derivative(x(t), t), 0, 0]])
    >>> c.without_slipping_equations()
    (r*Derivative(theta(t), t) + Derivative(x(t), t),)
    >>> c.spinning, c.rolling
    (0, Derivative(theta(t), t)*R1.k)
    """

    __slots__ = ("_moving", "_other", "_point", "_normal", "_cache")

    def __init__(self, moving, other, *, at: Point, normal: Vector):
        self._moving = _solid(moving, "moving")
        self._other = _solid(other, "other")
        check_point(at, "at")
        self._point = at
        normal = _vector(normal, "normal")
        if normal.is_zero or sp.simplify(normal.dot(normal)) == 0:
            raise ArgumentError(f"`normal` must be a non-zero vector (the common normal at "
                                f"{at.name}); got {normal!r}.")
        self._normal = _unit(normal)
        self._cache = {}

    @classmethod
    def between(cls, moving, moving_surface, other, other_surface, *, name: str = "I",
                inner: str | None = None) -> ContactKinematics:
        """The contact of two solids from their surfaces (see
        :func:`~rigidmech.kinematics.surfaces.contact_geometry`): S2 = ``moving`` bounded by
        ``moving_surface`` on S1 = ``other`` bounded by ``other_surface``. The normal is
        directed from S1 towards S2. For an internal contact of circles or spheres whose
        radii cannot be compared, ``inner`` says which solid's surface is inside the other
        ("moving" or "other").

        Raises
        ------
        ConnectionError\\_
            If the surfaces are not in contact.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech import Frame, Plane, coordinates
        >>> from rigidmech.kinematics.surfaces import Sphere
        >>> x, y = coordinates("x y"); r = sp.Symbol("r", positive=True)
        >>> R0 = Frame("R0"); R1 = R0.translated("R1", R0.point("C", x, y, r))
        >>> c = ContactKinematics.between(R1, Sphere(R1.origin, r), R0, Plane(R0.origin, R0.k))
        >>> c.point.coordinates(R0).T, c.normal
        (Matrix([[x(t), y(t), 0]]), R0.k)
        """
        if inner not in (None, "moving", "other"):
            raise ArgumentError(f"`inner` must be None, 'moving' or 'other'; got {inner!r}.")
        point, normal = contact_geometry(moving_surface, other_surface, name=name,
                                         inner={None: None, "moving": "first",
                                                "other": "second"}[inner])
        return cls(moving, other, at=point, normal=normal)

    # -- geometry -----------------------------------------------------------------------
    @property
    def moving(self) -> Solid:
        """S2, the solid whose motion relative to S1 is described."""
        return self._moving

    @property
    def other(self) -> Solid:
        """S1, the solid the motion is relative to."""
        return self._other

    @property
    def point(self) -> Point:
        """The contact point I."""
        return self._point

    @property
    def normal(self) -> Vector:
        """The unit common normal n."""
        return self._normal

    # -- kinematic vectors ----------------------------------------------------------------
    @property
    def rotation(self) -> Vector:
        """omega(S2/S1), the rotation vector of the relative motion (ch. 9.2.3)."""
        if "w" not in self._cache:
            self._cache["w"] = self._moving.frame.rotation_vector(self._other.frame)
        return self._cache["w"]

    @property
    def sliding_velocity(self) -> Vector:
        """v(I in S2/S1), the velocity of sliding of S2 on S1 at I (ch. 10.1.1).

        Examples
        --------
        >>> from rigidmech import Frame, coordinates
        >>> x = coordinates("x")
        >>> R0 = Frame("R0"); R1 = R0.translated("R1", R0.point("P", x, 0, 0))
        >>> ContactKinematics(R1, R0, at=R1.origin, normal=R0.j).sliding_velocity
        Derivative(x(t), t)*R0.i
        """
        if "v" not in self._cache:
            V = self._moving.kinematic_torsor(relative_to=self._other.frame, at=self._point)
            self._cache["v"] = V.velocity.compact()
        return self._cache["v"]

    @property
    def spinning(self) -> Vector:
        """The spinning (pivoting) rotation vector (omega(S2/S1) . n) n (ch. 10.1.2)."""
        n = self._normal
        return (self.rotation.dot(n) * n).compact()

    @property
    def rolling(self) -> Vector:
        """The rolling rotation vector, the projection of omega(S2/S1) on the tangent plane
        (ch. 10.1.2).

        Examples
        --------
        >>> from rigidmech import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.i, angle=q)
        >>> ContactKinematics(R1, R0, at=R0.origin, normal=R0.k).rolling
        Derivative(q(t), t)*R0.i
        """
        return (self.rotation - self.spinning).compact()

    # -- conditions ---------------------------------------------------------------------
    def without_slipping(self) -> Vector:
        """The condition of rolling without slipping as a vector that must vanish:
        v(I in S2/S1) = 0 (ch. 10.1.3)."""
        return self.sliding_velocity

    def without_pivoting(self) -> Vector:
        """The condition "without pivoting" as a vector that must vanish: the spinning
        vector (omega(S2/S1) . n) n = 0 (ch. 10.1.3)."""
        return self.spinning

    def tangents(self) -> tuple[Vector, Vector]:
        """Two unit vectors (t1, t2) such that (t1, t2, n) is direct and orthonormal.

        t1 is the first basis vector of the solids' frames (or their roots) orthogonal to n;
        when none is, t1 is the normalised projection of one on the tangent plane.

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> ContactKinematics(R0, R0, at=R0.origin, normal=R0.k).tangents()
        (R0.i, R0.j)
        """
        if "t" not in self._cache:
            n = self._normal
            candidates = _basis_vectors((self._other, self._moving))
            t1 = next((e for e in candidates if sp.simplify(e.dot(n)) == 0), None)
            if t1 is None:
                e = min(candidates, key=lambda e: sp.count_ops(e.dot(n)))
                t1 = _unit((e - e.dot(n) * n).compact())
            self._cache["t"] = (t1, n.cross(t1).compact())
        return self._cache["t"]

    def without_slipping_equations(self) -> tuple:
        """The scalar equations of rolling without slipping: the components of
        v(I in S2/S1) on the tangent plane, (v . t1, v . t2), with the zero ones left out.

        The normal component v . n is the time derivative of the condition that the contact
        persists (see :meth:`persistence_equation`); it is not repeated here.

        Returns
        -------
        tuple of sympy expressions
            Each must vanish; they are linear in the derivatives of the parameters.
        """
        v = self.sliding_velocity
        out = (sp.expand(v.dot(t)) for t in self.tangents())
        return tuple(e for e in out if e != 0 and sp.simplify(e) != 0)

    def without_pivoting_equations(self) -> tuple:
        """The scalar equation "without pivoting", (omega(S2/S1) . n,), or () when the
        relative rotation has no component along the normal.

        Examples
        --------
        >>> from rigidmech import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> ContactKinematics(R1, R0, at=R0.origin, normal=R0.k).without_pivoting_equations()
        (Derivative(q(t), t),)
        """
        e = sp.expand(self.rotation.dot(self._normal))
        return () if e == 0 or sp.simplify(e) == 0 else (e,)

    def persistence_equation(self):
        """v(I in S2/S1) . n, which vanishes while the contact persists (the sliding
        velocity then lies in the tangent plane, ch. 10.1.1).

        Examples
        --------
        >>> from rigidmech import Frame, coordinates
        >>> z = coordinates("z")
        >>> R0 = Frame("R0"); R1 = R0.translated("R1", R0.point("P", 0, 0, z))
        >>> ContactKinematics(R1, R0, at=R1.origin, normal=R0.k).persistence_equation()
        Derivative(z(t), t)
        """
        return sp.simplify(self.sliding_velocity.dot(self._normal))

    def __repr__(self):
        return (f"ContactKinematics({self._moving.name} on {self._other.name}, "
                f"at={self._point.name}, "
                f"normal={self._normal!r})")


__getattr__ = deprecated_aliases(  # the name of rigidmech < 0.x, kept as a deprecated alias
    __name__, {"Contact": ("rigidmech.kinematics.ContactKinematics", ContactKinematics)})
