"""The knife edge: a blade that slides along its own direction on a plane but not across it
(a skate, the blade of the Chaplygin sleigh; book, ch. 10.1, 13.1, 25.3).

A solid S2 carries a blade at a point P, along a direction e fixed in S2; it rests on a plane
of S1 of normal n (fixed in S1), e lying in that plane. The blade may slide along e and turn
about any axis through P, but the velocity of the point of S2 at P relative to S1 has **no
lateral component**:

.. math:: \\vec v(P \\in S_2/S_1) \\cdot \\vec l = 0, \\qquad \\vec l = \\vec n \\wedge \\vec e

(unit vectors). Unlike the condition of a wheel rolling on a line, this one does not integrate
to a relation between the parameters when the blade can turn (the heading of the sleigh): it is
a **nonholonomic** velocity constraint, kept as such by a
:class:`~rigidmech.dynamics.System`, which writes it with a Lagrange multiplier. The
multiplier is the lateral force of S1 on the blade: the action of S1 on S2 is
{N n + T l ; 0}_P, whose power with every allowed motion (a rotation about P and a sliding
along e) is zero. The blade keeps in contact with the plane through the parameters chosen (the
coordinates of S2 keep P in the plane): the normal component N is carried by them, like the
normal reaction of a :class:`~rigidmech.actions.RollingContact`.

The book has no knife edge: it is the standard example of a nonholonomic connection
(Neimark and Fufaev, *Dynamics of Nonholonomic Systems*, 1972, ch. I).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from .._core.symbolic import vanishes
from ..kinematics.constraints import VelocityConstraint
from ..kinematics.solid import as_solid as _solid
from ..torsors import Torsor
from ..vectors import Point, Vector
from ..vectors.points import check_point
from .actions import _check_perpendicular

__all__ = ["KnifeEdge"]


def _zero(e) -> bool:
    """Identically zero: the library's one rule (:func:`~rigidmech._core.symbolic.vanishes`)."""
    return vanishes(e)


def _unit(vector, argument, solid):
    """``vector`` / |vector|, refused when it is not a non-zero Vector fixed in ``solid``."""
    if isinstance(vector, Point) or not isinstance(vector, Vector):
        raise ArgumentTypeError(
            f"`{argument}` must be a Vector; got {type(vector).__name__}.")
    square = vector.dot(vector) if not vector.is_zero else sp.S.Zero
    if _zero(square):
        raise ArgumentError(f"`{argument}` must be a non-zero Vector; got {vector!r}.")
    if not all(_zero(c) for c in vector.dt(solid.frame).components(solid.frame)):
        raise ArgumentError(
            f"`{argument}` must be fixed in {solid.name} (constant in its frame "
            f"{solid.frame.name}); got {vector!r}.")
    if not sp.sympify(square).atoms(sp.Float) and _zero(square - 1):  # exactly unit already
        return vector
    return vector / sp.sqrt(sp.simplify(square))


class KnifeEdge:
    """A blade of S2 at the point P, along e, on a plane of S1 of normal n: no lateral
    sliding, v(P in S2/S1) . (n ^ e) = 0 (see the module's notes).

    Parameters
    ----------
    blade : Body, Solid or Frame
        S2, the solid that carries the blade (the sleigh, the skate).
    support : Body, Solid or Frame
        S1, the solid whose plane the blade rests on (the ground: the Galilean frame).
    at : Point
        The point P of the blade in contact with the plane.
    direction : Vector
        The direction e of the blade, fixed in S2 and lying in the plane.
    normal : Vector
        The normal n of the plane, fixed in S1.

    Raises
    ------
    ArgumentError
        If ``direction`` or ``normal`` is zero or not fixed in its solid, or if the blade is
        not in the plane (e . n not identically zero).
    ConnectionError\\_
        If the point P does not stay in the plane (v(P in S2/S1) . n not identically zero).

    Examples
    --------
    The Chaplygin sleigh: a body in the plane (x, y, theta) with its blade at a distance a
    behind the mass centre G, along the body's axis.

    >>> import sympy as sp
    >>> from rigidmech import Frame, coordinates
    >>> x, y, th = coordinates("x y theta"); a = sp.Symbol("a", positive=True)
    >>> R0 = Frame("R0"); G = R0.point("G", x, y, 0)
    >>> R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    >>> knife = KnifeEdge(R1, R0, at=G.moved("P", -a * R1.i), direction=R1.i, normal=R0.k)
    >>> knife.lateral
    R1.j
    >>> (c,) = knife.velocity_constraints()
    >>> sp.simplify(c.expression - (-sp.sin(th) * x.diff() + sp.cos(th) * y.diff() - a * th.diff()))
    0
    >>> knife.holonomic
    False
    """

    __slots__ = ("_blade", "_support", "_at", "_e", "_n", "_constraints")

    def __init__(self, blade, support, *, at: Point, direction: Vector, normal: Vector):
        self._blade = _solid(blade, "blade")
        self._support = _solid(support, "support")
        check_point(at, "at")
        self._e = _unit(direction, "direction", self._blade)
        self._n = _unit(normal, "normal", self._support)
        _check_perpendicular(self._e, self._n, "direction", "normal",
                             "the blade must lie in the plane: ")
        self._at = at
        v = self._blade.velocity(at, relative_to=self._support.frame)
        if not _zero(sp.expand(v.dot(self._n))):
            raise ConnectionError_(
                f"the point {at.name} of the blade does not stay in the plane of "
                f"{self._support.name}: its velocity along the normal is "
                f"{sp.simplify(v.dot(self._n))}, not zero. Build the coordinates of "
                f"{self._blade.name} so that {at.name} moves in the plane.")
        self._constraints = None

    @property
    def solids(self) -> tuple:
        """(S1, S2): the support and the solid that carries the blade (the action of S1 on
        S2 goes through the blade)."""
        return self._support, self._blade

    @property
    def at(self) -> Point:
        """The point P of the blade."""
        return self._at

    @property
    def direction(self) -> Vector:
        """The unit vector e of the blade."""
        return self._e

    @property
    def normal(self) -> Vector:
        """The unit normal n of the plane."""
        return self._n

    @property
    def lateral(self) -> Vector:
        """The unit vector l = n ^ e across the blade, in the plane."""
        return self._n.cross(self._e).compact()

    @property
    def degrees_of_freedom(self) -> int:
        """Relative motions left: the three rotations about P and the sliding along e."""
        return 4

    def velocity_constraints(self) -> tuple:
        """(v(P in S2/S1) . l,) as a VelocityConstraint: no lateral sliding."""
        if self._constraints is None:
            v = self._blade.velocity(self._at, relative_to=self._support.frame)
            self._constraints = (VelocityConstraint(sp.expand(v.dot(self.lateral))),)
        return self._constraints

    @property
    def holonomic(self) -> bool:
        """True when the condition integrates to a relation between the parameters (a blade
        that cannot turn); False for the sleigh."""
        return all(c.holonomic for c in self.velocity_constraints())

    def position_constraints(self, initial: dict | None = None) -> tuple:
        """The relation between the parameters, for a blade that cannot turn (see
        :meth:`VelocityConstraint.position_constraint`).

        Raises
        ------
        ConnectionError\\_
            If the condition is not holonomic (a blade that turns).
        """
        return tuple(c.position_constraint(initial) for c in self.velocity_constraints())

    def constraint_torsors(self) -> tuple:
        """For each velocity constraint, the action on S2 that a unit Lagrange multiplier
        stands for ({l ; 0}_P, its opposite on S1): its power with the motion of S2
        relative to S1 is the constraint, so the multiplier is the lateral force T.

        Examples
        --------
        >>> from rigidmech import Frame, coordinates
        >>> x, th = coordinates("x theta")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=th,
        ...                                   origin=R0.point("G", x, 0, 0))
        >>> (T,) = KnifeEdge(R1, R0, at=R1.origin, direction=R1.i,
        ...                  normal=R0.k).constraint_torsors()
        >>> T.resultant, T.point.name
        (R1.j, 'G')
        """
        return (Torsor(self.lateral, Vector.zero(), self._at),)

    def action_torsor(self, label: str) -> tuple[Torsor, tuple]:
        """The action of S1 on S2 at P: {N n + T l ; 0} with the unknowns (N, T).

        Returns
        -------
        (Torsor, tuple of sympy.Symbol)
        """
        N, T = (sp.Symbol(f"{n}_{label}", real=True) for n in ("N", "T"))
        return Torsor((N * self._n + T * self.lateral).compact(), Vector.zero(), self._at), (N, T)

    def allowed_motion(self, label: str) -> tuple[Torsor, tuple]:
        """The relative kinematic torsor {omega_1 e + omega_2 l + omega_n n ; s e}_P with
        its four free components as symbols (the power of the action with it is zero)."""
        w1, w2, wn, s = (sp.Symbol(f"{n}_{label}", real=True)
                         for n in ("omega_1", "omega_2", "omega_n", "s"))
        rot = (w1 * self._e + w2 * self.lateral + wn * self._n).compact()
        return Torsor(rot, (s * self._e).compact(), self._at), (w1, w2, wn, s)

    def __repr__(self):
        return (f"KnifeEdge({self._blade.name} on {self._support.name} at {self._at.name}, "
                f"direction={self._e!r})")
