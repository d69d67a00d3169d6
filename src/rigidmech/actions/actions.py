"""Mechanical actions exerted on solids (book, ch. 11-12): forces, couples, gravity, springs.

Every mechanical action is represented by an action torsor {R ; M(A)} (ch. 11.1.2). An action
object of this module describes *which* torsors act on *which* solids; the dynamics layer
asks it for its contributions when it writes the fundamental principle. The power of an action
on a solid S relative to R is the comoment of its torsor with the kinematic torsor {V(S/R)}
(ch. 11.3.1), see :func:`power`.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import is_exactly_zero, vanishes
from .._core.validation import nonnegative
from ..kinematics import Solid
from ..torsors import Torsor, couple, slider
from ..vectors import Point, Vector
from ..vectors.points import check_point

__all__ = ["Action", "Force", "Couple", "Gravity", "gravity", "Spring", "power"]


def _check_solid(s, argument):
    if not isinstance(s, Solid):
        raise ArgumentTypeError(f"`{argument}` must be a Body; got {type(s).__name__}.")


def _check_vector(v, argument):
    if isinstance(v, Point):
        raise ArgumentTypeError(
            f"`{argument}` must be a Vector; got the Point {v.name}. Use a bipoint B - A.")
    if not isinstance(v, Vector):
        raise ArgumentTypeError(f"`{argument}` must be a Vector; got {type(v).__name__}.")


def _unit_vector(v, argument):
    """``v`` for an argument documented as a unit vector: ``v`` itself when ``v . v``
    simplifies to 1, otherwise ``v / sqrt(v . v)`` (symbolically when the norm holds symbols:
    ``b R0.j`` with b real becomes ``b / |b| R0.j``), the rule of
    :class:`~rigidmech.kinematics.ContactKinematics`. The components along the vector (a
    normal force N, a couple about an axis) are then those along the unit vector whatever the
    length given. Refuses a Point, a non-Vector and a zero vector."""
    _check_vector(v, argument)
    square = sp.simplify(v.dot(v)) if not v.is_zero else sp.S.Zero
    if square == 0 or (square.is_number and abs(complex(square)) == 0):
        raise ArgumentError(f"`{argument}` must be a non-zero vector (a direction, used as "
                            f"a unit vector); got {v!r}.")
    if square == 1:
        return v
    return (v / sp.sqrt(square)).compact()


_PERPENDICULAR_TOL = 1e-12


def _check_perpendicular(u, n, argument, other, what="", word="perpendicular"):
    """Refuse unit vectors ``u`` and ``n`` that are not perpendicular. One rule for every
    action that needs it (ContactLaws' tangent and rolling axis, KnifeEdge's blade,
    LinearRectilinear's direction): a numeric cosine must be at most 1e-12 in magnitude
    (rounding of vectors given in floats), a symbolic one must vanish by the library's one
    rule (:func:`~rigidmech._core.symbolic.vanishes`: values at sample points, ``simplify``
    when they do not decide)."""
    cosine = sp.sympify(u.dot(n))
    if cosine.is_number:
        ok = abs(complex(cosine)) <= _PERPENDICULAR_TOL
    else:
        ok = vanishes(cosine)
    if not ok:
        raise ArgumentError(
            f"{what}`{argument}` must be {word} to `{other}`; got {argument} . {other} "
            f"= {sp.simplify(cosine)} (unit vectors). Pass its part in the plane "
            f"perpendicular to `{other}`.")


class Action:
    """Base of the mechanical actions known to a system (ch. 11.1).

    Subclasses implement :meth:`contributions`, the list of ``(solid, torsor)`` pairs the
    action exerts, and may implement :meth:`potential_energy` (ch. 11.3.3).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> isinstance(gravity(Frame("R0").k), Action)
    True
    """

    __slots__ = ()

    def contributions(self, solids):
        """Pairs (solid, action torsor on that solid) for the given solids."""
        raise NotImplementedError

    def potential_energy(self, solids, frame):
        """Potential energy relative to ``frame`` (ch. 11.3.3), or None if there is none."""
        return None


class Force(Action):
    """A force (slider) ``vector`` applied at ``at`` on ``on`` (ch. 11.1.3).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> from rigidmech.kinematics import Solid
    >>> R0 = Frame("R0"); S = Solid("S", frame=R0)
    >>> F = Force(on=S, vector=2 * R0.i, at=R0.point("A", 0, 1, 0))
    >>> F.contributions([S])[0][1].moment_at(R0.origin)
    -2*R0.k
    """

    __slots__ = ("_on", "_vector", "_at")

    def __init__(self, *, on, vector: Vector, at: Point):
        _check_solid(on, "on")
        _check_vector(vector, "vector")
        check_point(at, "at")
        self._on, self._vector, self._at = on, vector, at

    def contributions(self, solids):
        return [(self._on, slider(self._vector, self._at))]

    def __repr__(self):
        return f"Force(on={self._on.name}, vector={self._vector!r}, at={self._at.name})"


class Couple(Action):
    """A couple of moment ``moment`` exerted on ``on`` and, if ``reaction_on`` is given, the
    opposite couple on that solid (a motor between two solids, ch. 11.1.4).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> from rigidmech.kinematics import Solid
    >>> R0 = Frame("R0"); S = Solid("S", frame=R0)
    >>> Couple(on=S, moment=3 * R0.k).contributions([S])[0][1].resultant
    0
    """

    __slots__ = ("_on", "_moment", "_reaction_on")

    def __init__(self, *, on, moment: Vector, reaction_on=None):
        _check_solid(on, "on")
        _check_vector(moment, "moment")
        if reaction_on is not None:
            _check_solid(reaction_on, "reaction_on")
        self._on, self._moment, self._reaction_on = on, moment, reaction_on

    def contributions(self, solids):
        at = self._on.frame.origin
        c = couple(self._moment, at)
        out = [(self._on, c)]
        if self._reaction_on is not None:
            out.append((self._reaction_on, -c))
        return out

    def __repr__(self):
        return f"Couple(on={self._on.name}, moment={self._moment!r})"


class Gravity(Action):
    """Uniform gravity field ``g`` acting on every solid that has a mass (ch. 12.2).

    The action on a solid of mass m and mass centre G is the slider {m g ; 0}_G (ch. 12.2.2);
    its potential energy relative to R is -m g . OG (ch. 12.2.3).

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame
    >>> g = sp.Symbol("g")
    >>> R0 = Frame("R0")
    >>> gravity(-g * R0.k)
    Gravity(-g*R0.k)
    """

    __slots__ = ("_g",)

    def __init__(self, g: Vector):
        _check_vector(g, "g")
        self._g = g

    @property
    def field(self) -> Vector:
        """The gravity field g."""
        return self._g

    @staticmethod
    def _massive(solids):
        return [s for s in solids if getattr(s, "mass", None) is not None
                and s.mass != 0]

    def contributions(self, solids):
        return [(s, slider(s.mass * self._g, s.centre)) for s in self._massive(solids)]

    def potential_energy(self, solids, frame):
        return sp.Add(*[-s.mass * self._g.dot(s.centre - frame.origin)
                        for s in self._massive(solids)])

    def __repr__(self):
        return f"Gravity({self._g!r})"


def gravity(g: Vector) -> Gravity:
    """The action of uniform gravity ``g`` on every massive solid (ch. 12.2).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> gravity(9.81 * R0.i).field
    9.81*R0.i
    """
    return Gravity(g)


def _coincide(a: Point, b: Point) -> bool:
    """Whether the ends ``a`` and ``b`` of a spring or damper coincide at all times (AB
    vanishes identically, :func:`~rigidmech._core.symbolic.vanishes`): then AB / l is 0/0."""
    ab = b - a
    return ab.is_zero or all(vanishes(c) for c in ab.components(a.root))


# -- actions between two points (Spring, and Damper in dampers.py): their ends -------------
def _set_ends(action, a, b, on_a, on_b, what):
    """Check and store the ends of an action between point ``a`` of ``on_a`` and point ``b``
    of ``on_b`` (None: a point fixed in the reference, not both); ``what`` names it."""
    check_point(a, "a")
    check_point(b, "b")
    if on_a is None and on_b is None:
        raise ArgumentError(f"`on_a` and `on_b` cannot both be None: the {what} would act on "
                            "nothing.")
    for s, name in ((on_a, "on_a"), (on_b, "on_b")):
        if s is not None:
            _check_solid(s, name)
    action._a, action._b, action._on_a, action._on_b = a, b, on_a, on_b


def _along_ab(action, ab, factor):
    """The contributions of a force -factor AB on b and +factor AB on a (ends on a solid)."""
    out = []
    if action._on_b is not None:
        out.append((action._on_b, slider(-factor * ab, action._b)))
    if action._on_a is not None:
        out.append((action._on_a, slider(factor * ab, action._a)))
    return out


def _ends(action) -> tuple:
    """The points (a, b) the action joins.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> from rigidmech.actions import Damper, Spring
    >>> from rigidmech.kinematics import Solid
    >>> R0 = Frame("R0"); B = R0.point("B", 1, 0, 0); S = Solid("S", frame=R0)
    >>> [p.name for p in Spring(1, 0, a=R0.origin, b=B, on_b=S).ends]
    ['O_R0', 'B']
    >>> Damper(2, a=R0.origin, b=B, on_b=S).ends == (R0.origin, B)
    True
    """
    return (action._a, action._b)


#: The handles of the ends, the same properties in Spring and Damper.
_END_PROPERTIES = (
    property(lambda self: self._a, doc="The end point a (on ``on_a``)."),
    property(lambda self: self._b, doc="The end point b (on ``on_b``)."),
    property(lambda self: self._on_a,
             doc="The solid that carries a (None: a point fixed in the reference)."),
    property(lambda self: self._on_b,
             doc="The solid that carries b (None: a point fixed in the reference)."),
    property(_ends))


class Spring(Action):
    """A linear spring of stiffness ``stiffness`` and free length ``free_length`` between
    point ``a`` of solid ``on_a`` and point ``b`` of solid ``on_b`` (ch. 11.2).

    ``on_a`` or ``on_b`` may be None for a point fixed in the reference. Potential energy
    k (l - l0)^2 / 2. A spring of free length 0 exerts -k AB on ``b``, also when its ends
    coincide; a spring of free length l0 > 0 whose ends coincide at all times has no direction
    and is refused.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame, coordinates
    >>> from rigidmech.kinematics import Solid
    >>> x = coordinates("x"); k = sp.Symbol("k")
    >>> R0 = Frame("R0"); R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    >>> S = Solid("S", frame=R1)
    >>> sp.simplify(Spring(k, 0, a=R0.origin, b=R1.origin, on_b=S).potential_energy([S], R0))
    k*x(t)**2/2
    """

    __slots__ = ("_k", "_l0", "_a", "_b", "_on_a", "_on_b")

    def __init__(self, stiffness, free_length, *, a: Point, b: Point, on_a=None, on_b=None):
        _set_ends(self, a, b, on_a, on_b, "spring")
        self._k = nonnegative(stiffness, "stiffness")
        self._l0 = nonnegative(free_length, "free_length")

    a, b, on_a, on_b, ends = _END_PROPERTIES

    @property
    def free_length(self):
        """The free length l0."""
        return self._l0

    def _length(self):
        return (self._b - self._a).magnitude()

    def contributions(self, solids):
        ab = self._b - self._a
        length = ab.magnitude()
        if is_exactly_zero(self._l0):
            tension = self._k  # k (l - 0) / l: no direction needed (the ends may coincide)
        elif _coincide(self._a, self._b):
            raise ArgumentError(
                f"`a` ({self._a.name}) and `b` ({self._b.name}) coincide at all times: the force "
                f"of a spring of free length {self._l0} has no direction (AB / l = 0/0). Attach "
                "the ends at distinct points, or use free_length=0.")
        else:
            tension = self._k * (length - self._l0) / length  # force on b is -tension * AB
        return _along_ab(self, ab, tension)

    def potential_energy(self, solids, frame):
        return self._k * (self._length() - self._l0) ** 2 / 2


def power(action: Torsor, motion: Torsor) -> sp.Expr:
    """Power of an action on a solid: the comoment of the action torsor and the kinematic
    torsor of the solid (ch. 11.3.1).

    Examples
    --------
    >>> from rigidmech import Frame, coordinates
    >>> from rigidmech.kinematics import kinematic_torsor
    >>> q = coordinates("q")
    >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> V = kinematic_torsor(R1, relative_to=R0, at=R0.origin)
    >>> power(couple(5 * R0.k, R0.origin), V)
    5*Derivative(q(t), t)
    """
    if not isinstance(action, Torsor):
        raise ArgumentTypeError(f"`action` must be a Torsor; got {type(action).__name__}.")
    if not isinstance(motion, Torsor):
        raise ArgumentTypeError(f"`motion` must be a Torsor; got {type(motion).__name__}.")
    return action.comoment(motion)
