"""Dampers and torsion springs (book, ch. 11.2, 21.3, 22.2.2).

A viscous damper (dashpot) between a point A of one solid and a point B of another pulls
along AB against the rate of change of the length l = AB: the force on B is
:math:`-c\\,\\dot l\\,\\mathbf{e}`, :math:`\\mathbf{e} = \\mathbf{AB}/l`, and the opposite
force acts on A. Its Rayleigh dissipation function is :math:`\\mathcal{D} = c\\,\\dot l^2/2`
(the power it develops is :math:`-2\\mathcal{D}`), so that Lagrange's equations with
dissipation read :math:`\\frac{d}{dt}\\frac{\\partial T}{\\partial \\dot q_i} -
\\frac{\\partial T}{\\partial q_i} + \\frac{\\partial V}{\\partial q_i} +
\\frac{\\partial \\mathcal{D}}{\\partial \\dot q_i} = Q_i` (ch. 21.3.1, 25). Its potential
energy is zero.

A torsional damper exerts the couple :math:`-c\\,(\\boldsymbol{\\omega}(S_1/S_2)\\cdot
\\mathbf{u})\\,\\mathbf{u}` on S1 about the axis u (and the opposite couple on S2); a torsion
spring (a torsion wire, ch. 22.2.2) the couple :math:`-k\\,(\\theta - \\theta_0)\\,\\mathbf{u}`,
θ the angle of S1 relative to S2 about u, with potential :math:`k(\\theta-\\theta_0)^2/2`.
A wire of shear modulus G, diameter d and length L has :math:`k = G\\pi d^4/(32 L)`.

The actions follow the :class:`~rigidmech.actions.Action` protocol: a
:class:`~rigidmech.dynamics.System` includes them in the equations of motion and in the
energy without anything else to do.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError
from ..torsors import couple
from ..vectors import Point, Vector, t
from .actions import (
    _END_PROPERTIES,
    Action,
    _along_ab,
    _check_solid,
    _coincide,
    _set_ends,
    _unit_vector,
)

__all__ = ["Damper", "TorsionalDamper", "TorsionSpring", "wire_torsional_stiffness"]


def _coefficient(value, name):
    try:
        x = sp.sympify(value)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentError(f"`{name}` must be a number or a symbol; got {value!r}.") from exc
    if x.is_negative or (x.is_number and x.is_real and x < 0):
        raise ArgumentError(f"`{name}` must be >= 0; got {value}.")
    if x.is_number and not x.is_finite:
        raise ArgumentError(f"`{name}` must be finite; got {value}.")
    return x


def _root(frame):
    while frame.parent is not None:
        frame = frame.parent
    return frame


def _relative_rotation(on, reaction_on):
    reference = reaction_on.frame if reaction_on is not None else _root(on.frame)
    return on.frame.rotation_vector(reference)


class Damper(Action):
    """A linear viscous damper of coefficient ``damping`` between point ``a`` of ``on_a``
    and point ``b`` of ``on_b`` (ch. 21.3.1).

    Parameters
    ----------
    damping : number or symbol, >= 0
        c, in N s/m.
    a, b : Point
        The attachment points (fixed in their solids).
    on_a, on_b : Body, optional
        The solids; None for a point fixed in the reference (not both).

    Notes
    -----
    Ends that coincide at all times have v_B - v_A = 0 along every direction: l' = 0, no force
    and no dissipation (the 0/0 of AB / l is not formed). Ends that coincide at an instant
    only leave the direction of the force undefined there: a run reaching that instant stops
    with "the right-hand side is not finite at t = ...", naming the damper whose ends meet and
    the instant (a spring of free length l0 > 0 likewise).

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> x = rm.coordinates("x"); c, k, m = rm.constants("c k m", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    >>> block = rm.Body("block", frame=R1, mass=m)
    >>> s = rm.System(galilean=R0)
    >>> s.add(block)
    >>> s.act(rm.Spring(k, 0, a=R0.origin, b=R1.origin, on_b=block))
    >>> s.act(Damper(c, a=R0.point("A", -1, 0, 0), b=R1.origin, on_b=block))
    >>> eqs = s.equations_of_motion()
    >>> sp.simplify(eqs.forcing[0]).xreplace(eqs.display_rule())
    -c*x_dot - k*x
    >>> Damper(-1, a=R0.origin, b=R1.origin, on_b=block)
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `damping` must be >= 0; got -1.
    """

    __slots__ = ("_c", "_a", "_b", "_on_a", "_on_b")

    def __init__(self, damping, *, a: Point, b: Point, on_a=None, on_b=None):
        self._c = _coefficient(damping, "damping")
        _set_ends(self, a, b, on_a, on_b, "damper")

    a, b, on_a, on_b, ends = _END_PROPERTIES

    @property
    def damping(self):
        """The coefficient c."""
        return self._c

    def _ab_and_rate(self):
        ab = self._b - self._a
        # AB . d(AB)/dt = l l' is the same in every reference: use the root of the tree
        return ab, ab.dot(ab.dt(self._a.root))

    def length_rate(self) -> sp.Expr:
        """The rate l' of the length l = AB: :math:`\\dot l = \\mathbf{AB}\\cdot
        \\frac{d\\mathbf{AB}}{dt} / l` (the same in every reference).

        Examples
        --------
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> R0 = rm.Frame("R0"); R1 = R0.translated("R1", R0.point("P", x, 0, 0))
        >>> b = rm.Body("b", frame=R1, mass=1)
        >>> Damper(2, a=R0.point("A", -1, 0, 0), b=R1.origin, on_b=b).length_rate()
        (x(t) + 1)*Derivative(x(t), t)/Abs(x(t) + 1)
        """
        if _coincide(self._a, self._b):
            return sp.S.Zero
        ab, rate = self._ab_and_rate()
        return rate / sp.sqrt(ab.dot(ab))

    def contributions(self, solids):
        ab, rate = self._ab_and_rate()
        # ends coincident at all times: l' = 0, no force (and no 0/0)
        factor = 0 if _coincide(self._a, self._b) else self._c * rate / ab.dot(ab)
        return _along_ab(self, ab, factor)                 # force on b is -factor * AB

    def potential_energy(self, solids, frame):
        """Zero: a damper stores no energy."""
        return sp.S.Zero

    def dissipation_function(self, solids=None, frame=None) -> sp.Expr:
        """Rayleigh's dissipation function c l'^2 / 2 (the power of the damper is minus
        twice it).

        Examples
        --------
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> R0 = rm.Frame("R0"); R1 = R0.translated("R1", R0.point("P", 0, x, 0))
        >>> b = rm.Body("b", frame=R1, mass=1)
        >>> Damper(3, a=R0.point("A", 0, -2, 0), b=R1.origin, on_b=b).dissipation_function()
        3*Derivative(x(t), t)**2/2
        """
        if _coincide(self._a, self._b):
            return sp.S.Zero
        ab, rate = self._ab_and_rate()
        return sp.cancel(self._c * rate**2 / (2 * ab.dot(ab)))

    def __repr__(self):
        names = [s.name if s is not None else "ground" for s in (self._on_a, self._on_b)]
        return f"Damper({self._c}, between {names[0]}:{self._a.name} and {names[1]}:" \
               f"{self._b.name})"


class TorsionalDamper(Action):
    """A torsional viscous damper of coefficient ``damping`` (N m s/rad) about the unit
    vector of ``axis`` (normalised here), between ``on`` and ``reaction_on`` (the reference
    if None).

    Couple on ``on``: :math:`-c\\,(\\boldsymbol\\omega(on/reaction)\\cdot\\mathbf u)\\,
    \\mathbf u`; the opposite one on ``reaction_on``.

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> q = rm.coordinates("q"); c = sp.Symbol("c", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> disk = rm.Body("disk", frame=R1, mass=1)
    >>> TorsionalDamper(c, axis=R0.k, on=disk).contributions([disk])[0][1].moment
    -c*Derivative(q(t), t)*R0.k
    """

    __slots__ = ("_c", "_axis", "_on", "_reaction_on")

    def __init__(self, damping, *, axis: Vector, on, reaction_on=None):
        self._c = _coefficient(damping, "damping")
        axis = _unit_vector(axis, "axis")
        _check_solid(on, "on")
        if reaction_on is not None:
            _check_solid(reaction_on, "reaction_on")
        self._axis, self._on, self._reaction_on = axis, on, reaction_on

    def _rate(self):
        return _relative_rotation(self._on, self._reaction_on).dot(self._axis)

    def contributions(self, solids):
        c = couple(-self._c * self._rate() * self._axis, self._on.frame.origin)
        out = [(self._on, c)]
        if self._reaction_on is not None:
            out.append((self._reaction_on, -c))
        return out

    def potential_energy(self, solids, frame):
        """Zero: a damper stores no energy."""
        return sp.S.Zero

    def dissipation_function(self, solids=None, frame=None) -> sp.Expr:
        """Rayleigh's dissipation function c (omega . u)^2 / 2.

        Examples
        --------
        >>> import rigidmech as rm
        >>> q = rm.coordinates("q")
        >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> d = rm.Body("d", frame=R1, mass=1)
        >>> TorsionalDamper(4, axis=R0.k, on=d).dissipation_function()
        2*Derivative(q(t), t)**2
        """
        return self._c * self._rate() ** 2 / 2

    def __repr__(self):
        return f"TorsionalDamper({self._c}, axis={self._axis!r}, on={self._on.name})"


class TorsionSpring(Action):
    """A torsion spring (torsion wire) of stiffness ``stiffness`` (N m/rad) about the unit
    vector ``axis``: the couple :math:`-k(\\theta - \\theta_0)\\,\\mathbf u` on ``on``, the
    opposite one on ``reaction_on`` (the reference if None), ch. 22.2.2.

    Parameters
    ----------
    stiffness : number or symbol, >= 0
    angle : sympy expression
        θ, the angle of ``on`` relative to ``reaction_on`` about ``axis`` (usually a parameter
        of situation): checked against the frames, :math:`\\dot\\theta =
        \\boldsymbol\\omega(on/reaction)\\cdot\\mathbf u`.
    axis : Vector
        The axis u (normalised here: the couple is about the unit vector whatever the length
        given; a zero vector is refused).
    on, reaction_on : Body
    free_angle : θ0, the angle at which the spring is unloaded (default 0)

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> q = rm.coordinates("q"); k = sp.Symbol("k", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> disk = rm.Body("disk", frame=R1, mass=1)
    >>> spring = TorsionSpring(k, q, axis=R0.k, on=disk)
    >>> spring.potential_energy([disk], R0)
    k*q(t)**2/2
    >>> TorsionSpring(k, 2 * q, axis=R0.k, on=disk)
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `angle` must be the angle of disk relative to R0 ...
    """

    __slots__ = ("_k", "_angle", "_axis", "_on", "_reaction_on", "_free")

    def __init__(self, stiffness, angle, *, axis: Vector, on, reaction_on=None, free_angle=0):
        self._k = _coefficient(stiffness, "stiffness")
        axis = _unit_vector(axis, "axis")
        _check_solid(on, "on")
        if reaction_on is not None:
            _check_solid(reaction_on, "reaction_on")
        angle = sp.sympify(angle)
        rate = _relative_rotation(on, reaction_on).dot(axis)
        if sp.simplify(rate - angle.diff(t)) != 0:
            ref = reaction_on.name if reaction_on is not None else _root(on.frame).name
            raise ArgumentError(
                f"`angle` must be the angle of {on.name} relative to {ref} about `axis`: its "
                f"rate {angle.diff(t)} differs from omega . axis = {rate}.")
        self._angle, self._axis, self._on = angle, axis, on
        self._reaction_on, self._free = reaction_on, sp.sympify(free_angle)

    @property
    def stiffness(self):
        """The torsional stiffness k."""
        return self._k

    def contributions(self, solids):
        c = couple(-self._k * (self._angle - self._free) * self._axis, self._on.frame.origin)
        out = [(self._on, c)]
        if self._reaction_on is not None:
            out.append((self._reaction_on, -c))
        return out

    def potential_energy(self, solids, frame):
        return self._k * (self._angle - self._free) ** 2 / 2

    def __repr__(self):
        return f"TorsionSpring({self._k}, {self._angle}, axis={self._axis!r}, on={self._on.name})"


def wire_torsional_stiffness(shear_modulus, diameter, length):
    """Torsional stiffness of a round wire (or shaft) of shear modulus G, diameter d and
    length L: :math:`k = G J / L = G\\pi d^4 / (32 L)` (ch. 22.2.2), J the polar moment of
    area of the section.

    Examples
    --------
    >>> import sympy as sp
    >>> G, d, L = sp.symbols("G d L", positive=True)
    >>> wire_torsional_stiffness(G, d, L)
    pi*G*d**4/(32*L)
    >>> wire_torsional_stiffness(80e9, 1e-3, -1)
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `length` must be > 0; got -1.
    """
    G = _coefficient(shear_modulus, "shear_modulus")
    d = _coefficient(diameter, "diameter")
    L = sp.sympify(length)
    if L.is_nonpositive:
        raise ArgumentError(f"`length` must be > 0; got {length}.")
    return sp.pi * G * d**4 / (32 * L)
