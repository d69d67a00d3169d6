"""Connections that impose kinematic constraints: rolling contact and gear mesh (book,
ch. 10.1.3, 10.2, 13.1).

Unlike the joints of the catalogue, whose allowed motion is fixed by the frames, these
connections **link** parameters of situation: a wheel rolling without slipping ties its
rotation to its position, a gear mesh ties the angles of two gears. Each one says which solids
it joins and which constraints it imposes, as :class:`~rigidmech.kinematics.constraints.
VelocityConstraint` (holonomic or not, with the relation between the parameters when it is
one), and gives the action torsor of the connection with its unknown components, like the
joints of :mod:`rigidmech.actions.joints`.

* :class:`RollingContact`: S2 rolls without slipping (and, optionally, without pivoting) on
  S1 at the contact point I (ch. 10.1.3). The action of S1 on S2 is a force through I with a
  normal component N and two tangential components T1, T2 (the friction that prevents the
  slipping, ch. 13.1.2), plus a spinning couple C n when pivoting is prevented. Its power with
  every allowed motion (v(I in S2/S1) = 0) is zero.
* :class:`GearMesh`: two gears on axes fixed in a carrier, omega(S2/C) = lambda omega(S1/C)
  (ch. 10.2.3). The action of gear 1 on gear 2 is a force through the pitch point along the
  line of action (pressure angle alpha): F (t + s tan(alpha) e), with e the unit vector of the
  line of the centres and t = k ^ e; s = 1 for an external mesh (the gears are pushed apart),
  -1 for an internal one.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from ..kinematics.constraints import VelocityConstraint
from ..kinematics.contact import ContactKinematics
from ..kinematics.solid import as_solid as _solid
from ..kinematics.transmissions import GearPair
from ..torsors import Torsor
from ..vectors import Point, Vector
from ..vectors.points import check_point
from .contact_laws import Coulomb, PivotingResistance, RollingResistance

__all__ = ["RollingContact", "GearMesh", "FrictionContact"]


class RollingContact:
    """S2 rolls without slipping on S1 at a point (ch. 10.1.3).

    Parameters
    ----------
    contact : ContactKinematics
        The two solids, the contact point and the common normal
        (see :class:`~rigidmech.kinematics.ContactKinematics` and
        ``ContactKinematics.between``).
    pivoting : bool
        Whether S2 may spin about the normal (default True); False adds the condition
        "without pivoting".

    Examples
    --------
    A wheel of radius r on the line (O, i0): planar rolling is holonomic, x + r theta = const.

    >>> import sympy as sp
    >>> from rigidmech import Frame, Line, coordinates
    >>> from rigidmech.kinematics import Circle, ContactKinematics
    >>> x, theta = coordinates("x theta"); r = sp.Symbol("r", positive=True)
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.k, angle=theta, origin=R0.point("C", x, r, 0))
    >>> rc = RollingContact(ContactKinematics.between(R1, Circle(R1.origin, r, normal=R0.k),
    ...                                     R0, Line(R0.origin, R0.i)))
    >>> rc.holonomic, rc.position_constraints({x: 0, theta: 0})
    (True, (r*theta(t) + x(t),))
    >>> rc.action_torsor("01")[0].resultant
    T1_01*R0.i + N_01*R0.j - T2_01*R0.k
    """

    __slots__ = ("_contact", "_pivoting", "_constraints")

    def __init__(self, contact: ContactKinematics, *, pivoting: bool = True):
        if not isinstance(contact, ContactKinematics):
            raise ArgumentTypeError(
                f"`contact` must be a ContactKinematics (rigidmech.kinematics, or "
                f"ContactKinematics.between for surfaces); got {type(contact).__name__}.")
        if not isinstance(pivoting, bool):
            raise ArgumentTypeError(f"`pivoting` must be a bool; got {type(pivoting).__name__}.")
        self._contact = contact
        self._pivoting = pivoting
        self._constraints = None

    @property
    def contact(self) -> ContactKinematics:
        """The kinematics of the contact (point, normal, sliding velocity, ...)."""
        return self._contact

    @property
    def solids(self) -> tuple:
        """(S2, S1): the rolling solid and the one it rolls on."""
        return self._contact.moving, self._contact.other

    @property
    def pivoting(self) -> bool:
        """Whether spinning about the normal is allowed."""
        return self._pivoting

    @property
    def degrees_of_freedom(self) -> int:
        """Relative motions left at the contact: the rotations (3, or 2 without pivoting)."""
        return 3 if self._pivoting else 2

    def velocity_constraints(self) -> tuple:
        """The constraints "without slipping" (tangential components of v(I in S2/S1)) and,
        if pivoting is prevented, "without pivoting" (omega(S2/S1) . n).

        Returns
        -------
        tuple of VelocityConstraint
        """
        if self._constraints is None:
            c = self._contact
            eqs = c.without_slipping_equations()
            if not self._pivoting:
                eqs = eqs + c.without_pivoting_equations()
            self._constraints = tuple(VelocityConstraint(e) for e in eqs)
        return self._constraints

    @property
    def holonomic(self) -> bool:
        """True when every constraint integrates to a relation between the parameters."""
        return all(c.holonomic for c in self.velocity_constraints())

    def position_constraints(self, initial: dict | None = None) -> tuple:
        """The holonomic relations between the parameters (see
        :meth:`VelocityConstraint.position_constraint`).

        Raises
        ------
        ConnectionError\\_
            If a constraint is not holonomic (a disc rolling on a plane in 3D).
        """
        return tuple(c.position_constraint(initial) for c in self.velocity_constraints())

    def action_torsor(self, label: str) -> tuple[Torsor, tuple]:
        """The action of S1 on S2 at I: {N n + T1 t1 + T2 t2 ; C n} with the unknowns
        (N, T1, T2) and C only when pivoting is prevented (ch. 13.1).

        Returns
        -------
        (Torsor, tuple of sympy.Symbol)
        """
        N, T1, T2, C = (sp.Symbol(f"{n}_{label}", real=True) for n in ("N", "T1", "T2", "C"))
        n = self._contact.normal
        t1, t2 = self._contact.tangents()
        moment = Vector.zero() if self._pivoting else C * n
        unknowns = (N, T1, T2) if self._pivoting else (N, T1, T2, C)
        return Torsor(N * n + T1 * t1 + T2 * t2, moment, self._contact.point), unknowns

    def allowed_motion(self, label: str) -> tuple[Torsor, tuple]:
        """The relative kinematic torsor {omega ; v(I) = 0} of rolling without slipping, with
        the rotation components (omega_1, omega_2 on the tangents, omega_n) as symbols.

        Examples
        --------
        >>> from rigidmech import Frame
        >>> from rigidmech.kinematics import ContactKinematics
        >>> R0 = Frame("R0")
        >>> rc = RollingContact(ContactKinematics(R0, R0, at=R0.origin, normal=R0.k),
        ...                     pivoting=False)
        >>> rc.allowed_motion("a")[0].resultant
        omega_1_a*R0.i + omega_2_a*R0.j
        """
        w1, w2, wn = (sp.Symbol(f"omega_{n}_{label}", real=True) for n in ("1", "2", "n"))
        t1, t2 = self._contact.tangents()
        rot = w1 * t1 + w2 * t2 + (wn * self._contact.normal if self._pivoting else 0)
        free = (w1, w2, wn) if self._pivoting else (w1, w2)
        return Torsor(rot, Vector.zero(), self._contact.point), free

    def __repr__(self):
        c = self._contact
        extra = "" if self._pivoting else ", pivoting=False"
        return f"RollingContact({c.moving.name} on {c.other.name} at {c.point.name}{extra})"


class GearMesh:
    """Two gears in mesh on axes fixed in a carrier (ch. 10.2.3): omega(S2/C) . k =
    lambda omega(S1/C) . k with lambda the pair's ratio.

    Parameters
    ----------
    pair : GearPair
        The ratio and the pitch radii.
    first, second : Solid, Body or Frame
        The driving gear S1 and the driven gear S2.
    carrier : Frame, Solid or Body
        The solid that carries both axes (the casing, or the planet carrier).
    axis : Vector
        The common direction k of the axes, fixed in the carrier.
    centres : (Point, Point), optional
        Points of the two axes in the plane of the pitch circles (default: the origins of the
        gears' frames). Their distance must be the pair's centre distance.
    pressure_angle : scalar
        The pressure angle alpha of the teeth (default 20 degrees).

    Raises
    ------
    ConnectionError\\_
        If the distance between the centres is not the pair's centre distance.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame, coordinates
    >>> from rigidmech.kinematics import Gear, GearPair
    >>> q1, q2 = coordinates("q1 q2")
    >>> R0 = Frame("R0")
    >>> pair = GearPair(Gear(20, 2), Gear(40, 2))
    >>> g1 = R0.rotated("G1", about=R0.k, angle=q1)
    >>> g2 = R0.rotated("G2", about=R0.k, angle=q2, origin=R0.point("O2", 60, 0, 0))
    >>> mesh = GearMesh(pair, g1, g2, carrier=R0, axis=R0.k)
    >>> mesh.ratio, mesh.position_constraints({q1: 0, q2: 0})
    (-1/2, (q1(t)/2 + q2(t),))
    """

    __slots__ = ("_pair", "_first", "_second", "_carrier", "_axis", "_centres", "_alpha",
                 "_constraints")

    def __init__(self, pair: GearPair, first, second, *, carrier, axis: Vector,
                 centres: tuple | None = None, pressure_angle=sp.pi / 9):
        if not isinstance(pair, GearPair):
            raise ArgumentTypeError(f"`pair` must be a GearPair; got {type(pair).__name__}.")
        self._first = _solid(first, "first")
        self._second = _solid(second, "second")
        self._carrier = _solid(carrier, "carrier").frame
        if isinstance(axis, Point) or not isinstance(axis, Vector) or axis.is_zero:
            raise ArgumentTypeError(f"`axis` must be a non-zero Vector; got {axis!r}.")
        if not axis.dt(self._carrier).is_zero:
            raise ArgumentError(f"`axis` must be fixed in the carrier; got {axis!r}.")
        self._axis = axis / sp.sqrt(sp.simplify(axis.dot(axis)))
        if centres is None:
            centres = (self._first.frame.origin, self._second.frame.origin)
        if not (isinstance(centres, tuple) and len(centres) == 2):
            raise ArgumentTypeError("`centres` must be a pair of Points (O1, O2).")
        check_point(centres[0], "centres[0]")
        check_point(centres[1], "centres[1]")
        d2 = (centres[1] - centres[0]).dot(centres[1] - centres[0])
        a = pair.centre_distance
        if sp.simplify(d2 - a**2) != 0:
            raise ConnectionError_(
                f"the gears' axes must be at the pair's centre distance {a}; got a distance "
                f"of {sp.simplify(sp.sqrt(d2))} between {centres[0].name} and "
                f"{centres[1].name}.")
        self._pair = pair
        self._centres = centres
        self._alpha = sp.sympify(pressure_angle)
        self._constraints = None

    @property
    def pair(self) -> GearPair:
        """The gear pair."""
        return self._pair

    @property
    def ratio(self):
        """lambda = omega(S2/C) / omega(S1/C)."""
        return self._pair.ratio

    @property
    def solids(self) -> tuple:
        """(S1, S2): the driving and the driven gear."""
        return self._first, self._second

    @property
    def pitch_point(self) -> Point:
        """The point of contact of the pitch circles, on the line of the centres."""
        O1, O2 = self._centres
        r1, _ = self._pair.radii
        e = (O2 - O1) / self._pair.centre_distance
        return O1.moved("I", (-r1 if self._pair.internal else r1) * e)

    def velocity_constraints(self) -> tuple:
        """(omega(S2/C) . k - lambda omega(S1/C) . k,) as a VelocityConstraint."""
        if self._constraints is None:
            k, C = self._axis, self._carrier
            w1 = self._first.frame.rotation_vector(C).dot(k)
            w2 = self._second.frame.rotation_vector(C).dot(k)
            self._constraints = (VelocityConstraint(w2 - self.ratio * w1),)
        return self._constraints

    @property
    def holonomic(self) -> bool:
        """True when the ratio integrates to a relation between the angles (always, for
        gears whose angles are parameters about the fixed axes)."""
        return all(c.holonomic for c in self.velocity_constraints())

    def position_constraints(self, initial: dict | None = None) -> tuple:
        """The relation theta2 - lambda theta1 = const between the angles."""
        return tuple(c.position_constraint(initial) for c in self.velocity_constraints())

    @property
    def degrees_of_freedom(self) -> int:
        """The pair turning in its carrier has one degree of freedom (two angles, one
        relation)."""
        return 1

    def allowed_motion(self, label: str) -> tuple[Torsor, tuple]:
        """The relative motion of gear 2 relative to gear 1 that the mesh allows, with the
        carrier's motion removed: {(lambda - 1) omega_1 k ; 0 at the pitch point}, with the
        angular velocity omega_1 of gear 1 relative to the carrier as a symbol
        ``omega_1_label``. The pitch circles roll without slipping on each other.

        Examples
        --------
        >>> from rigidmech import Frame, coordinates
        >>> from rigidmech.kinematics import GearPair
        >>> R0 = Frame("R0"); q1, q2 = coordinates("q1 q2")
        >>> g1 = R0.rotated("G1", about=R0.k, angle=q1)
        >>> g2 = R0.rotated("G2", about=R0.k, angle=q2, origin=R0.point("O2", 3, 0, 0))
        >>> mesh = GearMesh(GearPair.from_radii(1, 2), g1, g2, carrier=R0, axis=R0.k)
        >>> mesh.allowed_motion("a")[0].resultant
        -3*omega_1_a/2*R0.k
        """
        w = sp.Symbol(f"omega_1_{label}", real=True)
        return Torsor((self.ratio - 1) * w * self._axis, Vector.zero(), self.pitch_point), (w,)

    def action_torsor(self, label: str) -> tuple[Torsor, tuple]:
        """The action of gear 1 on gear 2: the force F (t + s tan(alpha) e) through the pitch
        point (see the module's notes), with the unknown F.

        Examples
        --------
        >>> from rigidmech import Frame, coordinates
        >>> from rigidmech.kinematics import GearPair
        >>> R0 = Frame("R0"); q1, q2 = coordinates("q1 q2")
        >>> g1 = R0.rotated("G1", about=R0.k, angle=q1)
        >>> g2 = R0.rotated("G2", about=R0.k, angle=q2, origin=R0.point("O2", 3, 0, 0))
        >>> mesh = GearMesh(GearPair.from_radii(1, 2), g1, g2, carrier=R0, axis=R0.k,
        ...                 pressure_angle=0)
        >>> T, (F,) = mesh.action_torsor("12")
        >>> T.resultant, T.point.coordinates(R0).T
        (F_12*R0.j, Matrix([[1, 0, 0]]))
        """
        F = sp.Symbol(f"F_{label}", real=True)
        O1, O2 = self._centres
        e = (O2 - O1) / self._pair.centre_distance
        t = self._axis.cross(e)
        s = -1 if self._pair.internal else 1
        force = (F * (t + s * sp.tan(self._alpha) * e)).compact()
        return Torsor(force, Vector.zero(), self.pitch_point), (F,)

    def __repr__(self):
        return (f"GearMesh({self._pair!r}, {self._first.name}, {self._second.name}, "
                f"carrier={self._carrier.name})")


class FrictionContact:
    """A one-sided point contact with Coulomb friction between two solids of a
    :class:`~rigidmech.dynamics.System` (ch. 13.1, 21.4, 23).

    S2 touches S1 at I with the normal n (from S1 into S2). The action of S1 on S2 is
    {N n + T ; 0}_I with N >= 0 (the contact opens when N would become negative) and, by
    Coulomb's laws, ``|T| <= f_s N`` while S2 **sticks** (or rolls without slipping) on S1,
    and ``T = -f_k N v_s/|v_s|`` while it **slips** with the sliding velocity
    v_s = v(I in S2/S1). Its equations therefore change with the regime: a system that holds
    such a contact is integrated phase by phase with
    :func:`rigidmech.regimes.contact_motion`, which writes each regime itself (the contact as
    a no-slip constraint while sticking, the friction force while slipping).

    The coordinates of S2 must leave the contact free in every direction the regimes use:
    the normal direction (so that N is a Lagrange multiplier) and the tangential ones.

    Parameters
    ----------
    contact : ContactKinematics
        The two solids (S2 ``moving``, S1 ``other``), the contact point I and the normal
        (:class:`~rigidmech.kinematics.ContactKinematics`, or ``ContactKinematics.between``
        for two surfaces).
    friction : Coulomb, optional
        The law of friction; None for a frictionless contact (T = 0).
    gap : sympy expression, optional
        The distance between the two surfaces as a function of the coordinates (and t): 0 in
        contact, > 0 when the contact is open (for a block whose bottom is at height y above
        the floor, ``y``). With it, a contact that lifts off **opens** and the motion goes on
        in flight until the gap closes again (a perfectly plastic impact: the normal relative
        velocity drops to zero); without it, the motion stops where the contact lifts off.
    rolling : RollingResistance, optional
        Resistance to rolling of coefficient delta, a length (ch. 13.1.3): while S2 rolls on
        S1 (rolling rotation omega_r, the part of omega(S2/S1) perpendicular to n) the
        couple ``-delta N omega_r/|omega_r|`` acts on it at I; while it does not roll the
        couple that holds it is bounded by ``delta N``. Supported for a planar rolling
        (omega_r along one tangent).
    pivoting : PivotingResistance, optional
        Resistance to pivoting of coefficient eta, a length (ch. 13.1.3): while S2 spins on
        S1 about the normal (omega_n = omega(S2/S1) . n) the couple ``-eta N sign(omega_n) n``
        acts on it; while it does not spin the couple that holds it is bounded by ``eta N``.

    Examples
    --------
    A block (centre (x, y)) on the floor y = 0, its bottom point I at (x, y - h):

    >>> import sympy as sp
    >>> from rigidmech import Frame, coordinates
    >>> from rigidmech.kinematics import ContactKinematics
    >>> x, y = coordinates("x y"); h = sp.Symbol("h", positive=True)
    >>> R0 = Frame("R0"); R1 = R0.translated("R1", R0.point("G", x, y, 0))
    >>> c = FrictionContact(ContactKinematics(R1, R0, at=R0.point("I", x, y - h, 0),
    ...                                       normal=R0.j), friction=Coulomb(0.5, 0.4))
    >>> c
    FrictionContact(R1 on R0 at I, friction=Coulomb(static=0.5, kinetic=0.4))
    >>> c.action_torsor("I")[0].resultant
    T1_I*R0.i + N_I*R0.j - T2_I*R0.k

    A wheel with a rolling resistance of 2 mm:

    >>> from rigidmech.actions import RollingResistance
    >>> w = FrictionContact(c.contact, friction=Coulomb(0.5), rolling=RollingResistance(0.002))
    >>> w.rolling
    RollingResistance(0.00200000000000000)
    """

    __slots__ = ("_contact", "_friction", "_gap", "_rolling", "_pivoting")
    one_sided = True

    def __init__(self, contact: ContactKinematics, *, friction: Coulomb | None = None,
                 gap=None, rolling: RollingResistance | None = None,
                 pivoting: PivotingResistance | None = None):
        if not isinstance(contact, ContactKinematics):
            raise ArgumentTypeError(
                f"`contact` must be a ContactKinematics (rigidmech.kinematics, or "
                f"ContactKinematics.between for surfaces); got {type(contact).__name__}.")
        if friction is not None and not isinstance(friction, Coulomb):
            raise ArgumentTypeError(
                f"`friction` must be a Coulomb law or None; got {type(friction).__name__}.")
        if gap is not None:
            try:
                gap = sp.sympify(gap)
            except (sp.SympifyError, TypeError):
                raise ArgumentTypeError(f"`gap` must be a sympy expression of the coordinates; "
                                        f"got {gap!r}.") from None
            if not isinstance(gap, sp.Expr) or gap.is_number:
                raise ArgumentError(f"`gap` must be an expression of the coordinates (the "
                                    f"distance between the surfaces); got {gap!r}.")
        if rolling is not None and not isinstance(rolling, RollingResistance):
            raise ArgumentTypeError(
                f"`rolling` must be a RollingResistance law or None; got "
                f"{type(rolling).__name__}.")
        if pivoting is not None and not isinstance(pivoting, PivotingResistance):
            raise ArgumentTypeError(
                f"`pivoting` must be a PivotingResistance law or None; got "
                f"{type(pivoting).__name__}.")
        self._contact, self._friction, self._gap = contact, friction, gap
        self._rolling, self._pivoting = rolling, pivoting

    gap = property(lambda self: self._gap,
                   doc="The distance between the surfaces (an expression), or None.")
    contact = property(lambda self: self._contact,
                       doc="The kinematics of the contact (point, normal, sliding velocity).")
    friction = property(lambda self: self._friction, doc="The Coulomb law, or None.")
    rolling = property(lambda self: self._rolling,
                       doc="The law of rolling resistance, or None.")
    pivoting = property(lambda self: self._pivoting,
                        doc="The law of pivoting resistance, or None.")

    @property
    def solids(self) -> tuple:
        """(S2, S1): the solid acted on and the one it touches."""
        return self._contact.moving, self._contact.other

    def action_torsor(self, label: str) -> tuple[Torsor, tuple]:
        """The action of S1 on S2 at I, {N n + T1 t1 + T2 t2 ; 0}, with its unknowns
        (N, T1, T2) (see :meth:`ContactKinematics.tangents`)."""
        N, T1, T2 = (sp.Symbol(f"{n}_{label}", real=True) for n in ("N", "T1", "T2"))
        t1, t2 = self._contact.tangents()
        return (Torsor(N * self._contact.normal + T1 * t1 + T2 * t2, Vector.zero(),
                       self._contact.point), (N, T1, T2))

    def __repr__(self):
        c = self._contact
        extra = "" if self._friction is None else f", friction={self._friction!r}"
        extra += "" if self._rolling is None else f", rolling={self._rolling!r}"
        extra += "" if self._pivoting is None else f", pivoting={self._pivoting!r}"
        return f"FrictionContact({c.moving.name} on {c.other.name} at {c.point.name}{extra})"
