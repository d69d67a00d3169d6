"""Bodies made of parts, and the mass properties of a parametrised domain (book, ch. 12.3,
15.2.2, 15.4.4).

A composite body is the union of parts: solids of the catalogue placed (mass centre) and
oriented (the frame of their operator), point masses, and holes (parts removed, counted with
a negative mass). Its mass is :math:`m = \\sum_i \\pm m_i`, its mass centre
:math:`\\mathbf{OG} = \\sum_i \\pm m_i\\,\\mathbf{OG}_i / m` (ch. 12.3) and its operator of
inertia at G the sum of the parts' operators moved to G by the relations of Huygens
(ch. 15.2.2, 15.4.4):

.. math:: \\mathcal{J}_G = \\sum_i \\pm\\left(\\mathcal{J}_{G_i}(S_i) + \\mathcal{J}_G(G_i, m_i)
          \\right).

:func:`mass_properties` integrates a density over a :class:`~rigidmech.torsors.Domain`
(curve, surface or volume): mass, mass centre and operator of inertia by the book's
definitions (ch. 15.1.3).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..torsors import Domain
from ..torsors.fields import _scalar_density
from ..vectors import Point, Vector
from ._checks import check_frame, check_point, nonnegative
from .operator import InertiaOperator

__all__ = ["Part", "MassProperties", "composite", "mass_properties"]


class Part:
    """A part of a composite body: a mass, its mass centre and its central operator.

    Parameters
    ----------
    mass : number or sympy expression, >= 0
    operator : InertiaOperator, optional
        The part's operator of inertia: a catalogue operator (central; placed at ``centre``)
        or an operator at any point of the part (moved to ``centre`` by Huygens). None for a
        point mass.
    centre : Point, optional
        The part's mass centre; defaults to the point of a central ``operator``.
    hole : bool
        A part removed from the body (counted negatively).

    Examples
    --------
    >>> from rigidmech import Frame
    >>> from rigidmech.inertia import sphere
    >>> R0 = Frame("R0")
    >>> Part(2, sphere(2, 1, frame=R0), centre=R0.point("C", 1, 0, 0))
    Part(mass=2, centre=C)
    """

    __slots__ = ("mass", "centre", "operator", "hole")

    def __init__(self, mass, operator=None, *, centre=None, hole=False):
        mass = nonnegative(mass, "mass")
        if operator is not None and not isinstance(operator, InertiaOperator):
            raise ArgumentTypeError(
                f"`operator` must be an InertiaOperator (rigidmech.inertia catalogue); got "
                f"{type(operator).__name__}.")
        if centre is None:
            if operator is None or not operator.is_central:
                raise ArgumentError(
                    "`centre` is needed for a point mass or for an operator not taken at "
                    "the part's mass centre.")
            centre = operator.at
        check_point(centre, "centre")
        if operator is not None and operator.at != centre:
            operator = (operator.placed_at(centre) if operator.is_central
                        else operator.moved(centre, mass=mass, centre=centre))
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "centre", centre)
        object.__setattr__(self, "operator", operator)
        object.__setattr__(self, "hole", bool(hole))

    def __setattr__(self, name, value):
        raise AttributeError("Part is immutable.")

    def __repr__(self):
        hole = ", hole=True" if self.hole else ""
        return f"Part(mass={self.mass}, centre={self.centre.name}{hole})"


class MassProperties:
    """Mass m, mass centre G and operator of inertia at G of a body (ch. 12.3, 15).

    Use them to make a body: ``rm.Body(name, frame=..., mass=p.mass, centre=p.centre,
    inertia=p.inertia)``.

    Attributes
    ----------
    mass : sympy expression
    centre : Point
    inertia : InertiaOperator
        At :attr:`centre`, in the basis of the frame given.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> p = composite([Part(1, centre=R0.point("A", 1, 0, 0)),
    ...                Part(1, centre=R0.point("B", -1, 0, 0))], frame=R0)
    >>> p.mass, p.inertia.matrix.diagonal()
    (2, Matrix([[0, 2, 2]]))
    """

    __slots__ = ("mass", "centre", "inertia")

    def __init__(self, mass, centre, inertia):
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "centre", centre)
        object.__setattr__(self, "inertia", inertia)

    def __setattr__(self, name, value):
        raise AttributeError("MassProperties is immutable.")

    def inertia_at(self, point: Point) -> InertiaOperator:
        """The operator of inertia at ``point`` (Huygens, ch. 15.2.2).

        Examples
        --------
        >>> from rigidmech import Frame
        >>> R0 = Frame("R0")
        >>> p = composite([Part(3, centre=R0.point("A", 0, 2, 0))], frame=R0)
        >>> p.inertia_at(R0.origin).A
        12
        """
        check_point(point, "point")
        return self.inertia.moved(point, mass=self.mass, centre=self.centre)

    def __repr__(self):
        return f"MassProperties(mass={self.mass}, centre={self.centre.name}, " \
               f"inertia={self.inertia!r})"


def composite(parts, *, frame, name="G") -> MassProperties:
    """Mass, mass centre and operator of inertia of a body made of ``parts``
    (ch. 12.3, 15.4.4).

    Parameters
    ----------
    parts : iterable of Part
        Solids, point masses and holes (``Part(..., hole=True)``).
    frame : Frame
        The frame whose basis the composite operator is given in (the body's frame).
    name : str
        Name of the mass centre point.

    Returns
    -------
    MassProperties

    Raises
    ------
    ArgumentError
        No part, a total mass that is zero or negative (holes larger than the body), or
        holes that leave a matrix that is not an operator of inertia.

    Examples
    --------
    A disk of radius R with a hole of radius R/2 centred at R/2 (masses proportional to
    the areas):

    >>> import sympy as sp
    >>> from rigidmech import Frame
    >>> from rigidmech.inertia import disk
    >>> m, R = sp.symbols("m R", positive=True)
    >>> R0 = Frame("R0")
    >>> C = R0.point("C", R / 2, 0, 0)
    >>> p = composite([Part(m, disk(m, R, axis=R0.k)),
    ...                Part(m / 4, disk(m / 4, R / 2, axis=R0.k, centre=C), hole=True)],
    ...               frame=R0)
    >>> p.mass, p.centre.coordinates(R0).T
    (3*m/4, Matrix([[-R/6, 0, 0]]))
    >>> sp.factor(p.inertia.C)
    37*R**2*m/96
    """
    check_frame(frame, "frame")
    parts = list(parts)
    if not parts:
        raise ArgumentError("`parts` must hold at least one Part; got none.")
    for n, p in enumerate(parts):
        if not isinstance(p, Part):
            raise ArgumentTypeError(f"`parts[{n}]` must be a Part; got {type(p).__name__}.")
    O = frame.origin
    signs = [-1 if p.hole else 1 for p in parts]
    mass = sp.Add(*(s * p.mass for s, p in zip(signs, parts, strict=True)))
    if mass.is_nonpositive or (mass.is_number and mass <= 0):
        raise ArgumentError(
            f"the parts add up to a mass {mass} <= 0: the holes remove more than the body.")
    offset = Vector.zero()
    for s, p in zip(signs, parts, strict=True):
        offset = offset + (s * p.mass) * (p.centre - O)
    coords = [sp.simplify(c) for c in (offset / mass).components(frame)]
    G = O.moved(name, Vector.from_components(frame, coords))
    zero = InertiaOperator.from_products(0, 0, 0, frame=frame, at=G)
    total, removed = zero, zero
    for s, p in zip(signs, parts, strict=True):
        J = p.operator.in_basis(frame) if p.operator is not None else InertiaOperator._make(
            zero.matrix, frame, p.centre, True)
        J = J.moved(G, mass=p.mass, centre=p.centre)
        J = InertiaOperator._make(J.matrix, frame, G)
        if s > 0:
            total = total + J
        else:
            removed = removed + J
    if removed.matrix != zero.matrix:
        try:
            total = total - removed
        except ArgumentError as exc:
            raise ArgumentError(
                f"the holes do not fit the body: removing them leaves a matrix that is not an "
                f"operator of inertia ({exc}).") from None
    matrix = total.matrix.applyfunc(sp.simplify)
    return MassProperties(mass, G, InertiaOperator._make(matrix, frame, G, True))


def mass_properties(density, domain: Domain, *, method="auto", order=32,
                    name="G") -> MassProperties:
    """Mass, mass centre and operator of inertia of a body occupying ``domain`` with the
    mass per unit measure ``density`` (ch. 12.3, 15.1.3), by integration over the domain:

    .. math:: m = \\int_D \\rho\\,d\\mu,\\quad A_O = \\int_D \\rho\\,(y^2 + z^2)\\,d\\mu,\\
              \\ldots,\\quad F_O = \\int_D \\rho\\,x y\\,d\\mu,

    (x, y, z) the coordinates in the domain's frame; the operator is then moved to G.

    Parameters
    ----------
    density : scalar expression or callable of (x, y, z)
        Mass per unit length, area or volume (a function of the domain's parameters).
    domain : Domain
    method, order
        As in :meth:`rigidmech.torsors.Domain.integrate`.
    name : str
        Name of the mass centre.

    Examples
    --------
    A solid hemisphere of radius R and density ρ, flat face on z = 0:

    >>> import sympy as sp
    >>> from rigidmech import Frame, Domain, constants
    >>> R, rho = constants("R rho", positive=True)
    >>> r, th, ph = sp.symbols("r theta phi")
    >>> R0 = Frame("R0")
    >>> ball = Domain(R0, [r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph),
    ...                    r * sp.cos(th)], (r, 0, R), (th, 0, sp.pi / 2), (ph, 0, 2 * sp.pi))
    >>> p = mass_properties(rho, ball)
    >>> p.mass, p.centre.coordinates(R0).T
    (2*pi*R**3*rho/3, Matrix([[0, 0, 3*R/8]]))
    >>> sp.factor(p.inertia.A / p.mass)
    83*R**2/320
    """
    if not isinstance(domain, Domain):
        raise ArgumentTypeError(f"`domain` must be a Domain; got {type(domain).__name__}.")
    rho = _scalar_density(density, domain)
    x, y, z = domain.coordinates
    integrands = [rho, rho * x, rho * y, rho * z, rho * (y**2 + z**2), rho * (z**2 + x**2),
                  rho * (x**2 + y**2), rho * y * z, rho * z * x, rho * x * y]
    v = [sp.simplify(e) for e in domain.integrate(integrands, method=method, order=order)]
    mass = v[0]
    if mass == 0 or mass.is_nonpositive:
        raise ArgumentError(f"the mass of the domain must be > 0; got {mass}.")
    frame = domain.frame
    G = frame.origin.moved(name, Vector.from_components(
        frame, [sp.simplify(c / mass) for c in v[1:4]]))
    A, B, C, D, E, F = v[4:]
    J_O = InertiaOperator._make(sp.ImmutableMatrix([[A, -F, -E], [-F, B, -D], [-E, -D, C]]),
                                frame, frame.origin)
    J_G = J_O.moved(G, mass=mass, centre=G)
    matrix = J_G.matrix.applyfunc(sp.simplify)
    return MassProperties(mass, G, InertiaOperator._make(matrix, frame, G, True))
