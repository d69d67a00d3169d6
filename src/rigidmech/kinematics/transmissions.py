"""Transmission of a motion of rotation: friction wheels, gears, gear trains, epicyclic trains
and belts (book, ch. 10.2).

Sign convention (stated once for the whole module): a **ratio** is omega_out / omega_in, the
angular velocities being measured about parallel axes oriented the same way, relative to the
frame that carries the axes (the casing, or the planet carrier of an epicyclic train). A
negative ratio reverses the direction of rotation.

* Two wheels or gears in **external** contact turn in opposite directions; rolling without
  slipping at the pitch point gives r1 omega1 = -r2 omega2, so omega2 / omega1 = -r1 / r2
  (ch. 10.2.2-10.2.3). In **internal** contact (a pinion inside a ring) they turn the same
  way: omega2 / omega1 = r1 / r2.
* A gear has the pitch radius r = m z / 2 (module m, z teeth); two gears mesh only if their
  modules are equal, so that the ratio is also -z1 / z2 (ch. 10.2.3).
* In a gear train each mesh's driven gear turns with the next mesh's driving gear (same shaft,
  or the same gear for an idler): the train's ratio is the product of the ratios,
  of sign (-1)^(number of external meshes).
* An **epicyclic train** with planet carrier c obeys Willis' relation
  (omega_last - omega_c) / (omega_first - omega_c) = lambda, where lambda is the ratio of the
  same train with the carrier held fixed (the basic ratio).
* A **belt** on two pulleys (radii r1, r2, centre distance a) does not slip: r1 omega1 =
  r2 omega2 for an open belt (same direction), r1 omega1 = -r2 omega2 for a crossed one
  (ch. 10.2.4).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError

__all__ = ["Gear", "GearPair", "GearTrain", "EpicyclicTrain", "BeltDrive"]


def _scalar(x, argument, *, positive=True):
    try:
        v = sp.sympify(x)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got {type(x).__name__}."
        ) from exc
    if not isinstance(v, sp.Expr):
        raise ArgumentTypeError(
            f"`{argument}` must be a number or a sympy expression; got {type(x).__name__}.")
    if positive and (v.is_positive is False or (v.is_number and v.is_zero)):
        raise ArgumentError(f"`{argument}` must be positive; got {v}.")
    return v


def _is_false(x) -> bool:
    """True when the sympy relation is provably false."""
    return sp.simplify(x) is sp.false


class Gear:
    """A spur gear of ``teeth`` teeth and module ``module`` (ch. 10.2.3).

    Examples
    --------
    >>> Gear(teeth=20, module=2).pitch_radius
    20
    """

    __slots__ = ("_teeth", "_module")

    def __init__(self, teeth, module):
        z = _scalar(teeth, "teeth")
        if z.is_number and not z.is_integer:
            raise ArgumentError(f"`teeth` must be a positive integer; got {z}.")
        self._teeth = z
        self._module = _scalar(module, "module")

    @property
    def teeth(self):
        """The number of teeth z."""
        return self._teeth

    @property
    def module(self):
        """The module m (pitch diameter / number of teeth)."""
        return self._module

    @property
    def pitch_radius(self):
        """r = m z / 2."""
        return self._module * self._teeth / 2

    def __repr__(self):
        return f"Gear(teeth={self._teeth}, module={self._module})"


class GearPair:
    """Two gears (or friction wheels) in mesh, external or internal (ch. 10.2.2-10.2.3).

    Parameters
    ----------
    first, second : Gear
        The driving and the driven gear; for an internal pair, ``second`` is the ring.
    internal : bool
        True for a pinion inside a ring gear.

    Raises
    ------
    ArgumentError
        If the modules differ, or if an internal ring is not larger than its pinion.

    Examples
    --------
    >>> pair = GearPair(Gear(20, 2), Gear(50, 2))
    >>> pair.ratio, pair.centre_distance
    (-2/5, 70)
    >>> GearPair(Gear(20, 2), Gear(50, 2), internal=True).centre_distance
    30
    """

    __slots__ = ("_r1", "_r2", "_internal", "_gears")

    def __init__(self, first: Gear, second: Gear, *, internal: bool = False):
        for g, name in ((first, "first"), (second, "second")):
            if not isinstance(g, Gear):
                raise ArgumentTypeError(
                    f"`{name}` must be a Gear; got {type(g).__name__}. For friction wheels or "
                    "pitch radii use GearPair.from_radii.")
        if sp.simplify(first.module - second.module) != 0:
            raise ArgumentError(
                f"gears mesh only with equal modules; got `first` of module {first.module} "
                f"and `second` of module {second.module}.")
        self._set(first.pitch_radius, second.pitch_radius, internal, (first, second))

    @classmethod
    def from_radii(cls, first, second, *, internal: bool = False) -> GearPair:
        """A pair from the pitch radii (or the radii of two friction wheels rolling without
        slipping, ch. 10.2.2).

        Examples
        --------
        >>> import sympy as sp
        >>> r1, r2 = sp.symbols("r1 r2", positive=True)
        >>> GearPair.from_radii(r1, r2).ratio
        -r1/r2
        """
        obj = object.__new__(cls)
        obj._set(_scalar(first, "first"), _scalar(second, "second"), internal, None)
        return obj

    def _set(self, r1, r2, internal, gears):
        if not isinstance(internal, bool):
            raise ArgumentTypeError(f"`internal` must be a bool; got {type(internal).__name__}.")
        if internal and _is_false(sp.Gt(r2, r1)):
            raise ArgumentError(
                f"an internal pair needs the ring (`second`) larger than the pinion; got radii "
                f"{r1} and {r2}.")
        self._r1, self._r2, self._internal, self._gears = r1, r2, internal, gears

    @property
    def radii(self):
        """The pitch radii (r1, r2)."""
        return self._r1, self._r2

    @property
    def internal(self) -> bool:
        """True for a pinion inside a ring."""
        return self._internal

    @property
    def gears(self):
        """The two gears, or None for a pair given by its radii."""
        return self._gears

    @property
    def ratio(self):
        """omega2 / omega1: -r1 / r2 (external), r1 / r2 (internal)."""
        r = self._r1 / self._r2
        return r if self._internal else -r

    @property
    def centre_distance(self):
        """Distance between the axes: r1 + r2 (external), r2 - r1 (internal)."""
        return self._r2 - self._r1 if self._internal else self._r1 + self._r2

    def __repr__(self):
        kind = ", internal=True" if self._internal else ""
        if self._gears:
            return f"GearPair({self._gears[0]!r}, {self._gears[1]!r}{kind})"
        return f"GearPair.from_radii({self._r1}, {self._r2}{kind})"


class GearTrain:
    """A train of gear pairs in series (ch. 10.2.3): each pair's driven gear turns with the
    next pair's driving gear.

    Examples
    --------
    Two external meshes 20/40 and 15/45 (compound: the 40 and the 15 share a shaft):

    >>> train = GearTrain(GearPair(Gear(20, 1), Gear(40, 1)), GearPair(Gear(15, 1), Gear(45, 1)))
    >>> train.ratio, train.external_meshes
    (1/6, 2)
    """

    __slots__ = ("_pairs",)

    def __init__(self, *pairs: GearPair):
        if not pairs:
            raise ArgumentError("`pairs` must hold at least one GearPair; got none.")
        for n, p in enumerate(pairs):
            if not isinstance(p, GearPair):
                raise ArgumentTypeError(
                    f"`pairs[{n}]` must be a GearPair; got {type(p).__name__}.")
        self._pairs = tuple(pairs)

    @property
    def pairs(self) -> tuple:
        """The pairs, from the input to the output."""
        return self._pairs

    @property
    def ratio(self):
        """omega_out / omega_in, the product of the pairs' ratios."""
        return sp.Mul(*(p.ratio for p in self._pairs))

    @property
    def external_meshes(self) -> int:
        """The number of external meshes; the ratio has the sign (-1) ** this."""
        return sum(not p.internal for p in self._pairs)

    def __repr__(self):
        return f"GearTrain({', '.join(map(repr, self._pairs))})"


class EpicyclicTrain:
    """An epicyclic (planetary) train of basic ratio ``ratio`` (ch. 10.2.3): Willis' relation

    .. math:: \\frac{\\omega_{last} - \\omega_c}{\\omega_{first} - \\omega_c} = \\lambda ,

    with lambda the ratio omega_last / omega_first of the train when the planet carrier c is
    held fixed.

    Parameters
    ----------
    ratio : number, sympy expression or GearTrain
        The basic ratio lambda (not 1: the train would not transmit anything), or the train
        seen from the carrier.

    Examples
    --------
    Sun of 20 teeth, planets of 30, ring of 80: with the carrier fixed, sun -> planet ->
    ring gives lambda = (-20/30)(30/80) = -1/4. Ring held, sun at 100 rad/s:

    >>> sun_planet = GearPair(Gear(20, 1), Gear(30, 1))
    >>> planet_ring = GearPair(Gear(30, 1), Gear(80, 1), internal=True)
    >>> train = EpicyclicTrain(GearTrain(sun_planet, planet_ring))
    >>> train.ratio, train.solve(first=100, last=0)
    (-1/4, {'carrier': 20})
    """

    __slots__ = ("_ratio",)

    def __init__(self, ratio):
        if isinstance(ratio, GearTrain):
            ratio = ratio.ratio
        lam = _scalar(ratio, "ratio", positive=False)
        if sp.simplify(lam - 1) == 0:
            raise ArgumentError(
                "`ratio` must not be 1: a basic ratio of 1 locks the train (Willis' relation "
                "then gives no speed); got 1.")
        self._ratio = lam

    @property
    def ratio(self):
        """The basic ratio lambda (carrier fixed)."""
        return self._ratio

    def relation(self, first, last, carrier):
        """Willis' relation as an expression that vanishes:
        (omega_last - omega_c) - lambda (omega_first - omega_c).

        Examples
        --------
        >>> import sympy as sp
        >>> w1, w3, wc = sp.symbols("w1 w3 wc")
        >>> EpicyclicTrain(-sp.Rational(1, 4)).relation(w1, w3, wc)
        w1/4 + w3 - 5*wc/4
        """
        f, l_, c = (_scalar(x, n, positive=False)
                    for x, n in ((first, "first"), (last, "last"), (carrier, "carrier")))
        return sp.expand((l_ - c) - self._ratio * (f - c))

    def solve(self, *, first=None, last=None, carrier=None) -> dict:
        """The unknown angular velocity from the two others by Willis' relation.

        Exactly one of ``first``, ``last``, ``carrier`` must be None.

        Returns
        -------
        dict
            ``{name: value}`` for the unknown one.

        Examples
        --------
        >>> EpicyclicTrain(-3).solve(first=10, carrier=2)
        {'last': -22}
        """
        given = {"first": first, "last": last, "carrier": carrier}
        missing = [k for k, v in given.items() if v is None]
        if len(missing) != 1:
            raise ArgumentError(
                "exactly one of `first`, `last`, `carrier` must be None (the unknown); got "
                f"{len(missing)} unknowns ({', '.join(missing) or 'none'}).")
        x = sp.Dummy("x")
        values = {k: (x if v is None else v) for k, v in given.items()}
        (sol,) = sp.solve(self.relation(**values), x)
        return {missing[0]: sp.simplify(sol)}

    def __repr__(self):
        return f"EpicyclicTrain({self._ratio})"


class BeltDrive:
    """A belt on two pulleys, open or crossed, without slipping (ch. 10.2.4).

    Parameters
    ----------
    first, second : positive scalars
        Radii r1 (driving pulley) and r2.
    centre_distance : positive scalar
        Distance a between the pulleys' axes.
    crossed : bool
        True for a crossed belt (the pulleys turn in opposite directions).

    Notes
    -----
    With beta the angle between a straight strand and the line of the centres,
    sin(beta) = (r2 - r1) / a (open) or (r1 + r2) / a (crossed):

    * open: wrap angles pi - 2 beta (on pulley 1) and pi + 2 beta (on pulley 2), length
      L = 2 a cos(beta) + pi (r1 + r2) + 2 beta (r2 - r1);
    * crossed: both wrap angles pi + 2 beta, L = 2 a cos(beta) + (pi + 2 beta)(r1 + r2).

    Raises
    ------
    ArgumentError
        If a radius or the centre distance is not positive, or if the pulleys overlap
        (a <= abs(r2 - r1) for an open belt, a <= r1 + r2 for a crossed one).

    Examples
    --------
    >>> import sympy as sp
    >>> belt = BeltDrive(1, 1, 4)
    >>> belt.ratio, belt.length, belt.wrap_angles
    (1, 2*pi + 8, (pi, pi))
    """

    __slots__ = ("_r1", "_r2", "_a", "_crossed")

    def __init__(self, first, second, centre_distance, *, crossed: bool = False):
        r1, r2 = _scalar(first, "first"), _scalar(second, "second")
        a = _scalar(centre_distance, "centre_distance")
        if not isinstance(crossed, bool):
            raise ArgumentTypeError(f"`crossed` must be a bool; got {type(crossed).__name__}.")
        reach = r1 + r2 if crossed else sp.Abs(r2 - r1)
        if _is_false(sp.Gt(a, reach)):
            raise ArgumentError(
                f"`centre_distance` must exceed {'r1 + r2' if crossed else 'abs(r2 - r1)'} = "
                f"{reach} for a{' crossed' if crossed else 'n open'} belt; got {a}.")
        self._r1, self._r2, self._a, self._crossed = r1, r2, a, crossed

    @property
    def crossed(self) -> bool:
        """True for a crossed belt."""
        return self._crossed

    @property
    def ratio(self):
        """omega2 / omega1: r1 / r2 (open), -r1 / r2 (crossed)."""
        r = self._r1 / self._r2
        return -r if self._crossed else r

    @property
    def angle(self):
        """beta, the angle of the straight strands to the line of the centres."""
        num = self._r1 + self._r2 if self._crossed else self._r2 - self._r1
        return sp.asin(num / self._a)

    @property
    def wrap_angles(self):
        """The angles of contact of the belt on the pulleys 1 and 2 (radians)."""
        b = self.angle
        if self._crossed:
            return sp.pi + 2 * b, sp.pi + 2 * b
        return sp.pi - 2 * b, sp.pi + 2 * b

    @property
    def length(self):
        """The length of the belt (see Notes)."""
        b, a, r1, r2 = self.angle, self._a, self._r1, self._r2
        straight = 2 * sp.sqrt(a**2 - (a * sp.sin(b)) ** 2)  # 2 a cos(beta), beta in [0, pi/2)
        w1, w2 = self.wrap_angles
        return sp.simplify(straight + r1 * w1 + r2 * w2)

    def belt_speed(self, omega1):
        """The speed of the belt's strands, r1 omega1 (signed like omega1).

        Examples
        --------
        >>> BeltDrive(2, 3, 10).belt_speed(5)
        10
        """
        return self._r1 * _scalar(omega1, "omega1", positive=False)

    def __repr__(self):
        kind = ", crossed=True" if self._crossed else ""
        return f"BeltDrive({self._r1}, {self._r2}, {self._a}{kind})"
