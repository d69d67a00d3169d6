"""Laws of contact between solids: Coulomb friction, rolling and pivoting resistance,
one-sided contact (book, ch. 13.1).

The action of a solid S1 on a solid S2 touching it at a point I, with the common normal n
pointing into S2, is an action torsor reduced at I (ch. 13.1.2)

.. math:: \\{\\mathcal{A}_{1\\to 2}\\} = \\{N\\,\\mathbf{n} + \\mathbf{T} ;\\
          \\mathbf{M}_r + M_p\\,\\mathbf{n}\\}_I ,

normal force N, tangential force T, rolling couple M_r (perpendicular to n) and pivoting
(spinning) couple M_p n (ch. 13.1.3). The laws are:

* **one-sided contact**: N >= 0; the contact opens when N would become negative;
* **Coulomb's laws of friction**: while S2 slides on S1 with the sliding velocity
  :math:`\\mathbf{v}_s = \\mathbf{v}(I \\in S_2/S_1)`, T opposes it with
  :math:`|\\mathbf{T}| = f_k N`; while it sticks, :math:`|\\mathbf{T}| \\le f_s N`: the
  resultant lies inside the **friction cone** of axis n and half-angle
  :math:`\\varphi_s = \\arctan f_s`;
* **rolling resistance**: while S2 rolls (rolling rotation :math:`\\boldsymbol{\\omega}_r`,
  the part of :math:`\\boldsymbol{\\omega}(S_2/S_1)` perpendicular to n) the rolling couple
  opposes it with :math:`|\\mathbf{M}_r| = \\delta N`, and is bounded by it otherwise;
* **pivoting resistance**: likewise about n, :math:`|M_p| \\le \\eta N`.

The coefficients δ and η of rolling and pivoting resistance are **lengths** (ch. 13.1.3),
whereas the friction coefficients f_s >= f_k are numbers. Every action returned here is a
:class:`~rigidmech.torsors.Torsor`, so :func:`~rigidmech.actions.power`, comoments and sums
of torsors apply to it unchanged.

Kinetic above static: rigidmech **refuses** ``Coulomb(static=f_s, kinetic=f_k)`` with
f_k > f_s (an :class:`~rigidmech._core.errors.ArgumentError`): under Coulomb's laws a body
that slides would then stop and start again at once, a law without a physical motion.
"""

from __future__ import annotations

import sympy as sp

from .._core.deprecation import deprecated_aliases
from .._core.errors import ArgumentError, ArgumentTypeError
from ..torsors import Torsor
from ..vectors import Point, Vector
from ..vectors.points import check_point
from .actions import _check_perpendicular, _unit_vector

__all__ = ["Coulomb", "RollingResistance", "PivotingResistance", "ContactLaws"]


def _coefficient(value, argument, what="a number >= 0"):
    if isinstance(value, str | bool):
        raise ArgumentTypeError(f"`{argument}` must be {what}; got {value!r}.")
    try:
        v = sp.sympify(value)
    except (sp.SympifyError, TypeError):
        raise ArgumentTypeError(f"`{argument}` must be {what}; got {value!r}.") from None
    if not isinstance(v, sp.Expr) or v.is_real is False:
        raise ArgumentTypeError(f"`{argument}` must be {what}; got {value!r}.")
    if v.is_negative or (v.is_number and (not v.is_finite or v < 0)):
        raise ArgumentError(f"`{argument}` must be {what}; got {value!r}.")
    return v


def _check_vector(v, argument):
    if isinstance(v, Point):
        raise ArgumentTypeError(
            f"`{argument}` must be a Vector; got the Point {v.name}. Use a bipoint B - A.")
    if not isinstance(v, Vector):
        raise ArgumentTypeError(f"`{argument}` must be a Vector; got {type(v).__name__}.")


def _is_zero_vector(v: Vector) -> bool:
    if v.is_zero:
        return True
    comps = v.components(v.frames[0])
    return all(c == 0 or sp.simplify(c) == 0 for c in comps)


# A numeric rate (the sliding velocity, the rolling or pivoting rotation) whose magnitude is at
# most this fraction of the vector it is a part of (the velocity of I, the rotation) is rounding
# noise: zero, not a direction to oppose.
_RATE_RTOL = 1e-12


def _part(part: Vector, whole: Vector) -> Vector:
    """``part`` of ``whole`` (its tangential or normal component), or zero when both are
    numbers and |part| <= _RATE_RTOL |whole|."""
    frame = whole.frames[0] if whole.frames else None
    if frame is None or part.is_zero:
        return part
    p2, w2 = sp.sympify(part.dot(part)), sp.sympify(whole.dot(whole))
    if p2.is_number and w2.is_number and float(p2) <= _RATE_RTOL**2 * float(w2):
        return Vector.zero()
    return part


def _opposing(magnitude, rate: Vector) -> Vector:
    """-magnitude * rate / |rate|."""
    return -magnitude * rate / rate.magnitude()


class Coulomb:
    """Coulomb's law of friction with a static and a kinetic coefficient (ch. 13.1.2).

    Parameters
    ----------
    static : number or sympy expression
        f_s >= 0, the bound of ``|T|/N`` while the contact sticks.
    kinetic : number or sympy expression, optional
        f_k >= 0, the ratio ``|T|/N`` while it slides (default f_s). f_k > f_s is refused.

    Raises
    ------
    ArgumentError
        A negative coefficient, or f_k > f_s.

    Examples
    --------
    >>> law = Coulomb(static=0.4, kinetic=0.3)
    >>> law
    Coulomb(static=0.4, kinetic=0.3)
    >>> round(float(law.cone_half_angle), 6)          # arctan(0.4)
    0.380506
    """

    __slots__ = ("_static", "_kinetic")

    def __init__(self, static, kinetic=None):
        self._static = _coefficient(static, "static", "a friction coefficient >= 0")
        self._kinetic = (self._static if kinetic is None
                         else _coefficient(kinetic, "kinetic", "a friction coefficient >= 0"))
        excess = sp.simplify(self._kinetic - self._static)
        if excess.is_positive:
            raise ArgumentError(
                f"`kinetic` must not exceed `static` (f_k <= f_s, ch. 13.1.2); got "
                f"kinetic={kinetic!r} > static={static!r}.")

    static = property(lambda self: self._static, doc="Static coefficient f_s.")
    kinetic = property(lambda self: self._kinetic, doc="Kinetic coefficient f_k.")

    @property
    def cone_half_angle(self):
        """Half-angle phi_s = arctan(f_s) of the friction cone.

        Examples
        --------
        >>> import sympy as sp
        >>> Coulomb(static=sp.Symbol("f", positive=True)).cone_half_angle
        atan(f)
        """
        return sp.atan(self._static)

    def bound(self, normal_force):
        """Largest tangential force f_s N while sticking.

        Examples
        --------
        >>> Coulomb(0.5).bound(10)
        5.00000000000000
        """
        return self._static * sp.sympify(normal_force)

    def in_cone(self, action, normal: Vector, *, rtol: float = 1e-12) -> bool:
        """Whether the resultant of ``action`` (a Torsor or a Vector) lies inside the friction
        cone of axis ``normal`` (pointing into the body acted on, normalised here): N >= 0
        and ``|T| <= f_s N``, with a relative tolerance ``rtol`` on ``|R|``.

        Raises
        ------
        ArgumentError
            If the decision needs values of symbols.

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> law = Coulomb(0.5)
        >>> law.in_cone(10 * R0.j + 4 * R0.i, R0.j), law.in_cone(10 * R0.j + 6 * R0.i, R0.j)
        (True, False)
        """
        R = action.resultant if isinstance(action, Torsor) else action
        _check_vector(R, "action")
        normal = _unit_vector(normal, "normal")
        N = R.dot(normal)
        T2 = R.dot(R) - N**2
        try:
            N, T2, f = float(N), float(T2), float(self._static)
            scale = float(R.dot(R)) ** 0.5
        except TypeError:
            raise ArgumentError(
                f"`action` must be numeric to decide whether it lies in the friction cone; "
                f"got N = {N}, |T|^2 = {T2}: substitute values first.") from None
        tol = rtol * scale
        return N >= -tol and max(T2, 0.0) ** 0.5 <= f * N + tol

    def sliding_action(self, normal_force, sliding_velocity: Vector, at: Point) -> Torsor:
        """The tangential action while sliding: the slider ``{-f_k N v_s/|v_s| ; 0}`` at the
        contact point ``at`` (ch. 13.1.2).

        Raises
        ------
        ArgumentError
            If the sliding velocity is zero (the contact sticks: the tangential force is then
            an unknown bounded by f_s N, see :class:`ContactLaws`).

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> Coulomb(0.4, 0.3).sliding_action(10, 2 * R0.i, R0.origin)
        Torsor(resultant=-3.0*R0.i, moment=0, at=O_R0)
        """
        _check_vector(sliding_velocity, "sliding_velocity")
        check_point(at, "at")
        if _is_zero_vector(sliding_velocity):
            raise ArgumentError(
                "`sliding_velocity` must be non-zero for the sliding law; got zero: the "
                "contact sticks and its tangential force is an unknown with |T| <= f_s N.")
        N = sp.sympify(normal_force)
        return Torsor(_opposing(self._kinetic * N, sliding_velocity), Vector.zero(), at)

    def __eq__(self, other):
        return (isinstance(other, Coulomb) and self._static == other._static
                and self._kinetic == other._kinetic)

    def __hash__(self):
        return hash(("Coulomb", self._static, self._kinetic))

    def __repr__(self):
        return f"Coulomb(static={self._static}, kinetic={self._kinetic})"


class _Resistance:
    __slots__ = ("_coefficient",)
    _name = ""

    def __init__(self, coefficient):
        self._coefficient = _coefficient(coefficient, "coefficient", "a length >= 0")

    coefficient = property(lambda self: self._coefficient,
                           doc="The coefficient (a length).")

    def bound(self, normal_force):
        """Largest couple coefficient * N while the contact does not turn."""
        return self._coefficient * sp.sympify(normal_force)

    def __eq__(self, other):
        return type(other) is type(self) and other._coefficient == self._coefficient

    def __hash__(self):
        return hash((type(self).__name__, self._coefficient))

    def __repr__(self):
        return f"{type(self).__name__}({self._coefficient})"


class RollingResistance(_Resistance):
    """Resistance to rolling of coefficient delta, a length (ch. 13.1.3): while the body
    rolls with the rolling rotation omega_r the couple is ``-delta N omega_r/|omega_r|``, and
    ``|M_r| <= delta N`` otherwise.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> RollingResistance(0.002).couple(100, -3 * R0.k, R0.origin)
    Torsor(resultant=0, moment=0.2*R0.k, at=O_R0)
    """

    __slots__ = ()

    def couple(self, normal_force, rolling_rotation: Vector, at: Point) -> Torsor:
        """The rolling couple opposing ``rolling_rotation`` (non-zero)."""
        _check_vector(rolling_rotation, "rolling_rotation")
        if _is_zero_vector(rolling_rotation):
            raise ArgumentError("`rolling_rotation` must be non-zero for the rolling law; "
                                "got zero: the couple is then an unknown with |M_r| <= delta N.")
        return Torsor(Vector.zero(), _opposing(self.bound(normal_force), rolling_rotation), at)


class PivotingResistance(_Resistance):
    """Resistance to pivoting (spinning) of coefficient eta, a length (ch. 13.1.3): the couple
    about the normal opposes the pivoting rotation with ``|M_p| = eta N``, bounded by it otherwise.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> PivotingResistance(0.01).couple(50, 2 * R0.j, R0.origin)
    Torsor(resultant=0, moment=-0.5*R0.j, at=O_R0)
    """

    __slots__ = ()

    def couple(self, normal_force, pivoting_rotation: Vector, at: Point) -> Torsor:
        """The pivoting couple opposing ``pivoting_rotation`` (non-zero)."""
        _check_vector(pivoting_rotation, "pivoting_rotation")
        if _is_zero_vector(pivoting_rotation):
            raise ArgumentError("`pivoting_rotation` must be non-zero for the pivoting law; "
                                "got zero: the couple is then an unknown with |M_p| <= eta N.")
        return Torsor(Vector.zero(), _opposing(self.bound(normal_force), pivoting_rotation), at)


_KIND_NAMES = {"friction": "sliding", "rolling": "rolling", "footprint": "tipping",
               "pivoting": "pivoting"}


class ContactLaws:
    """A one-sided point contact with its laws (ch. 13.1), as a connection for statics.

    The action of the first body on the second at ``at`` is
    {N n + T t ; M_r r + M_p n}_I with the unknowns N (always), T (with ``friction``), M_r
    (with ``rolling`` or ``footprint``) and M_p (with ``pivoting``). :meth:`action_torsor`
    gives it with unknown symbols, as the joints of :mod:`rigidmech.actions.joints` do, and
    :meth:`conditions` the inequalities of its laws (each ``expr >= 0``), used by
    :mod:`rigidmech.statics` to find where an equilibrium breaks.

    Parameters
    ----------
    at : Point
        The contact point I.
    normal : Vector
        Common normal, pointing into the body acted on; normalised here (N is the component
        along the unit normal n whatever the length given; a symbolic norm is divided out
        symbolically). A zero vector is refused.
    tangent : Vector, optional
        Tangent t (perpendicular to n, normalised here) along which friction may act; needed
        with ``friction``. The planar contact of the book's plane problems. One not
        perpendicular to n (numeric cosine above 1e-12) is refused.
    friction : Coulomb, optional
        Without it (or with f_s = 0) the contact is frictionless: T = 0, no unknown T.
    rolling : number, optional
        Rolling-resistance coefficient delta (a length); the rolling couple is along
        ``rolling_axis`` r.
    footprint : number, optional
        Half-width a of a flat base centred on I (a box on a floor, seen in its plane): the
        contact pressure may move its resultant anywhere on the base, i.e. a couple
        ``|M_r| <= a N`` about ``rolling_axis``; when it reaches a N the body **tips** about an
        edge of the base. Mathematically a rolling resistance of coefficient a.
    rolling_axis : Vector, optional
        Axis r of the rolling couple (perpendicular to n, normalised here), needed with
        ``rolling`` or ``footprint``.
    pivoting : number, optional
        Pivoting-resistance coefficient eta (a length).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> c = ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i, friction=Coulomb(0.5))
    >>> T, unknowns = c.action_torsor("I")
    >>> T, unknowns
    (Torsor(resultant=T_I*R0.i + N_I*R0.j, moment=0, at=O_R0), (N_I, T_I))
    >>> c.conditions("I")
    [('lift-off', N_I), ('sliding', 0.5*N_I - T_I), ('sliding', 0.5*N_I + T_I)]
    """

    __slots__ = ("_at", "_normal", "_tangent", "_friction", "_rolling", "_rolling_kind",
                 "_axis", "_pivoting")

    def __init__(self, *, at: Point, normal: Vector, tangent: Vector | None = None,
                 friction: Coulomb | None = None, rolling=None, footprint=None,
                 rolling_axis: Vector | None = None, pivoting=None):
        check_point(at, "at")
        normal = _unit_vector(normal, "normal")
        self._at, self._normal = at, normal
        if friction is not None and not isinstance(friction, Coulomb):
            raise ArgumentTypeError(
                f"`friction` must be a Coulomb law; got {type(friction).__name__}.")
        if friction is not None and tangent is None:
            raise ArgumentError("`tangent` is needed with `friction`: the direction t along "
                                "which the friction force acts; got None.")
        if tangent is not None:
            tangent = _unit_vector(tangent, "tangent")
            _check_perpendicular(tangent, normal, "tangent", "normal")
        if friction is not None and friction.static.is_zero:
            friction = None                   # f_s = 0: frictionless, no tangential unknown
        self._tangent, self._friction = tangent, friction
        if rolling is not None and footprint is not None:
            raise ArgumentError("give at most one of `rolling` and `footprint`; got both.")
        if rolling is not None:
            self._rolling, self._rolling_kind = RollingResistance(rolling), "rolling"
        elif footprint is not None:
            self._rolling, self._rolling_kind = RollingResistance(footprint), "footprint"
        else:
            self._rolling, self._rolling_kind = None, None
        if self._rolling is not None:
            if rolling_axis is None:
                raise ArgumentError(f"`rolling_axis` is needed with `{self._rolling_kind}`; "
                                    "got None.")
            rolling_axis = _unit_vector(rolling_axis, "rolling_axis")
            _check_perpendicular(rolling_axis, normal, "rolling_axis", "normal")
        self._axis = rolling_axis
        self._pivoting = None if pivoting is None else PivotingResistance(pivoting)

    at = property(lambda self: self._at, doc="The contact point I.")
    normal = property(lambda self: self._normal, doc="The unit normal n.")
    friction = property(lambda self: self._friction, doc="The Coulomb law, or None.")

    def _symbols(self, label):
        names = ["N"]
        if self._friction is not None:
            names.append("T")
        if self._rolling is not None:
            names.append("Mr")
        if self._pivoting is not None:
            names.append("Mp")
        return {n: sp.Symbol(f"{n}_{label}", real=True) for n in names}

    def action_torsor(self, label: str) -> tuple[Torsor, tuple]:
        """The action torsor with unknown components ``N_label``, ``T_label``, ... (ch. 13.1).

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> ContactLaws(at=R0.origin, normal=R0.j).action_torsor("A")[1]
        (N_A,)
        """
        s = self._symbols(label)
        R = s["N"] * self._normal
        M = Vector.zero()
        if "T" in s:
            R = R + s["T"] * self._tangent
        if "Mr" in s:
            M = M + s["Mr"] * self._axis
        if "Mp" in s:
            M = M + s["Mp"] * self._normal
        return Torsor(R, M, self._at), tuple(s.values())

    def conditions(self, label: str) -> list:
        """The laws as inequalities ``(kind, expr)`` meaning ``expr >= 0``, linear in the
        unknowns of :meth:`action_torsor`: ``'lift-off'`` N >= 0; ``'sliding'``
        f_s N -+ T >= 0; ``'rolling'`` (or ``'tipping'`` for a footprint) delta N -+ M_r >= 0;
        ``'pivoting'`` eta N -+ M_p >= 0.

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> ContactLaws(at=R0.origin, normal=R0.j, footprint=0.5, rolling_axis=R0.k).conditions("B")
        [('lift-off', N_B), ('tipping', -Mr_B + 0.5*N_B), ('tipping', Mr_B + 0.5*N_B)]
        """
        s = self._symbols(label)
        N = s["N"]
        out = [("lift-off", N)]
        for key, law, kind in (("T", self._friction, "friction"),
                               ("Mr", self._rolling, self._rolling_kind),
                               ("Mp", self._pivoting, "pivoting")):
            if key in s:
                b = law.bound(N)
                out += [(_KIND_NAMES[kind], b - s[key]), (_KIND_NAMES[kind], b + s[key])]
        return out

    def action(self, normal_force, motion: Torsor) -> Torsor:
        """The contact action while the second body moves relative to the first with the
        kinematic torsor ``motion`` (ch. 13.1): N n, the friction opposing the sliding
        velocity v(I) - (v(I).n) n, and the rolling and pivoting couples opposing the
        rolling and pivoting rotations. Each law needs a non-zero rate (sliding, rolling,
        pivoting); with a zero rate its action is a reaction, an unknown of statics. With
        numbers, a rate at most 1e-12 of the vector it is part of (the velocity of I, the
        rotation) is rounding noise and counts as zero.

        Examples
        --------
        >>> from rigidmech import Frame, Torsor
        >>> from rigidmech.actions import power
        >>> R0 = Frame("R0")
        >>> c = ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i, friction=Coulomb(0.5, 0.4))
        >>> V = Torsor(Vector.zero(), 3 * R0.i, R0.origin)        # sliding along i at 3
        >>> A = c.action(10, V); A
        Torsor(resultant=-4.0*R0.i + 10*R0.j, moment=0, at=O_R0)
        >>> power(A, V)
        -12.0000000000000
        """
        if not isinstance(motion, Torsor):
            raise ArgumentTypeError(f"`motion` must be a Torsor; got {type(motion).__name__}.")
        N = sp.sympify(normal_force)
        n = self._normal
        V = motion.at(self._at)
        v, w = V.moment, V.resultant
        action = Torsor(N * n, Vector.zero(), self._at)
        if self._friction is not None:
            action = action + self._friction.sliding_action(N, _part(v - v.dot(n) * n, v),
                                                            self._at)
        if self._rolling is not None:
            action = action + self._rolling.couple(N, _part(w - w.dot(n) * n, w), self._at)
        if self._pivoting is not None:
            action = action + self._pivoting.couple(N, _part(w.dot(n) * n, w), self._at)
        return action

    def __repr__(self):
        parts = [f"at={self._at.name}", f"normal={self._normal!r}"]
        if self._friction is not None:
            parts.append(f"friction={self._friction!r}")
        return f"ContactLaws({', '.join(parts)})"


# ``Contact`` was this class's name, also that of rigidmech.kinematics.ContactKinematics
__getattr__ = deprecated_aliases(
    __name__, {"Contact": ("rigidmech.actions.ContactLaws", ContactLaws)})
