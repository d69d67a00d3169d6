"""Torsors of fields of sliders and measure centres (book, ch. 5.3).

A field of sliders attaches a vector to every point of a domain. For a finite set of points
(ch. 5.3.1) its torsor at A is

.. math:: \\mathbf{R} = \\sum_i \\mathbf{v}_i,\\qquad
          \\mathbf{M}(A) = \\sum_i \\mathbf{AP}_i \\wedge \\mathbf{v}_i ,

and for a curve, a surface or a volume with a density :math:`\\mathbf{f}(P)` per unit of
measure :math:`d\\mu` (length, area or volume, ch. 5.3.2)

.. math:: \\mathbf{R} = \\int_D \\mathbf{f}(P)\\,d\\mu,\\qquad
          \\mathbf{M}(A) = \\int_D \\mathbf{AP}\\wedge\\mathbf{f}(P)\\,d\\mu .

For a field :math:`\\mathbf{f}(P) = \\rho(P)\\,\\mathbf{u}` with a fixed direction the torsor
is a slider through the measure centre G, :math:`\\mathbf{OG} = \\int_D \\rho\\,\\mathbf{OP}
\\,d\\mu \\,/ \\int_D \\rho\\,d\\mu` (ch. 5.3.3); with ρ a mass density, G is the mass centre.

A domain is a parametrisation :math:`P(u)`, :math:`P(u, v)` or :math:`P(u, v, w)` in a frame
with parameter ranges (:class:`Domain`); its measure element :math:`|P_u|\\,du`,
:math:`|P_u\\wedge P_v|\\,du\\,dv` or :math:`|\\det J|\\,du\\,dv\\,dw` is derived from it.
Integrals are symbolic (``sympy.integrate``) with a numeric fallback (Gauss-Legendre
product rule, or ``scipy.integrate.nquad``).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..vectors import Point, Vector
from ..vectors.points import check_point
from ._checks import _check_vector
from .domain import Domain  # Domain moved there (split); re-exported here
from .torsor import Torsor

__all__ = ["Domain", "torsor_of_sliders", "torsor_of_field", "total_measure",
           "measure_centre", "barycentre"]


def torsor_of_sliders(pairs, at: Point | None = None) -> Torsor:
    """The torsor of a finite set of sliders (P_i, v_i), reduced at ``at`` (ch. 5.3.1).

    Parameters
    ----------
    pairs : iterable of (Point, Vector)
        The points P_i and the vectors v_i of the sliders (forces and their points of
        application, for example).
    at : Point, optional
        Point of reduction; by default the first point P_1.

    Returns
    -------
    Torsor
        :math:`\\{\\sum_i \\mathbf{v}_i ;\\ \\sum_i \\mathbf{AP}_i\\wedge\\mathbf{v}_i\\}`.

    Raises
    ------
    ArgumentTypeError
        If a pair is not (Point, Vector), for example with its elements swapped.
    ArgumentError
        If ``pairs`` is empty and ``at`` is not given.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> A, B = R0.point("A", 1, 0, 0), R0.point("B", -1, 0, 0)
    >>> T = torsor_of_sliders([(A, R0.j), (B, -R0.j)], at=R0.origin)   # a couple
    >>> T
    Torsor(resultant=0, moment=2*R0.k, at=O_R0)
    >>> T.kind
    'couple'
    """
    items = []
    for n, pair in enumerate(pairs):
        try:
            point, vector = pair
        except (TypeError, ValueError) as exc:
            raise ArgumentTypeError(
                f"`pairs[{n}]` must be a (Point, Vector) pair; got {pair!r}.") from exc
        if isinstance(point, Vector) and isinstance(vector, Point):
            raise ArgumentTypeError(
                f"`pairs[{n}]` must be (Point, Vector); got (Vector, Point): swap them.")
        check_point(point, f"pairs[{n}][0]")
        _check_vector(vector, f"pairs[{n}][1]")
        items.append((point, vector))
    if at is None:
        if not items:
            raise ArgumentError("`at` is needed when `pairs` is empty; got no pair and no point.")
        at = items[0][0]
    check_point(at, "at")
    resultant, moment = Vector.zero(), Vector.zero()
    for point, vector in items:
        resultant = resultant + vector
        moment = moment + (point - at).cross(vector)
    return Torsor._new(resultant, moment, at)


def _density_components(density, domain, argument):
    """Components in ``domain.frame`` of a Vector density, or of a callable of (x, y, z)."""
    if callable(density) and not isinstance(density, Vector | sp.Basic):
        density = density(*domain.coordinates)
    if isinstance(density, Point):
        raise ArgumentTypeError(
            f"`{argument}` must be a Vector (density of the field); got the Point "
            f"{density.name}.")
    _check_vector(density, argument)
    return tuple(density.components(domain.frame))


def _scalar_density(density, domain):
    if callable(density) and not isinstance(density, sp.Basic):
        density = density(*domain.coordinates)
    if isinstance(density, Vector | Point):
        raise ArgumentTypeError(
            f"`density` must be a scalar (measure per unit length, area or volume); got a "
            f"{type(density).__name__}. For a field of vectors use torsor_of_field.")
    try:
        return sp.sympify(density)
    except (sp.SympifyError, TypeError) as exc:
        raise ArgumentTypeError(f"`density` must be a scalar; got {density!r}.") from exc


def _check_domain(domain):
    if not isinstance(domain, Domain):
        raise ArgumentTypeError(f"`domain` must be a Domain; got {type(domain).__name__}.")


def torsor_of_field(density, domain: Domain, at: Point | None = None, *, method="auto",
                    order=32) -> Torsor:
    """The torsor of a field of sliders over a curve, a surface or a volume (ch. 5.3.2).

    Parameters
    ----------
    density : Vector or callable
        The vector per unit of measure, :math:`\\mathbf{f}(P)`: a Vector whose components
        are functions of the domain's parameters, or a callable ``f(x, y, z)`` of the
        coordinates of P in ``domain.frame`` returning such a Vector.
    domain : Domain
    at : Point, optional
        Point of reduction; by default the origin of ``domain.frame``.
    method, order
        As in :meth:`Domain.integrate`.

    Returns
    -------
    Torsor
        :math:`\\{\\int_D \\mathbf{f}\\,d\\mu ;\\ \\int_D \\mathbf{AP}\\wedge\\mathbf{f}
        \\,d\\mu\\}`, components in the basis of ``domain.frame``.

    Examples
    --------
    A uniform load p per unit length on a beam [0, L] along i, pushing along -j: a slider of
    resultant -pL j through the middle.

    >>> import sympy as sp
    >>> from rigidmech import Frame, constants
    >>> p, L = constants("p L", positive=True)
    >>> x = sp.Symbol("x")
    >>> R0 = Frame("R0")
    >>> beam = Domain(R0, x * R0.i, (x, 0, L))
    >>> T = torsor_of_field(-p * R0.j, beam)
    >>> T
    Torsor(resultant=-L*p*R0.j, moment=-L**2*p/2*R0.k, at=O_R0)
    >>> T.central_point().coordinates(R0).T
    Matrix([[L/2, 0, 0]])
    """
    _check_domain(domain)
    f = _density_components(density, domain, "density")
    x, y, z = domain.coordinates
    integrands = list(f) + [y * f[2] - z * f[1], z * f[0] - x * f[2], x * f[1] - y * f[0]]
    values = domain.integrate(integrands, method=method, order=order)
    frame = domain.frame
    resultant = Vector.from_components(frame, values[:3])
    moment = Vector.from_components(frame, values[3:])
    torsor = Torsor._new(resultant, moment, frame.origin)
    if at is None:
        return torsor
    check_point(at, "at")
    return torsor.at(at)


def total_measure(density, domain: Domain, *, method="auto", order=32) -> sp.Expr:
    """The measure of the domain weighted by a scalar density: its mass for a mass density
    (ch. 5.3.3).

    Parameters
    ----------
    density : scalar expression or callable
        Measure per unit length, area or volume (1 for the length, area or volume), as a
        function of the parameters or as a callable of the coordinates ``(x, y, z)``.
    domain : Domain
    method, order
        As in :meth:`Domain.integrate`.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame, constants
    >>> R = constants("R", positive=True)
    >>> r, th = sp.symbols("r theta")
    >>> disk = Domain(Frame("R0"), [r * sp.cos(th), r * sp.sin(th), 0], (r, 0, R),
    ...               (th, 0, 2 * sp.pi))
    >>> total_measure(1, disk)
    pi*R**2
    """
    _check_domain(domain)
    rho = _scalar_density(density, domain)
    return domain.integrate([rho], method=method, order=order)[0]


def measure_centre(density, domain: Domain, *, method="auto", order=32,
                   name: str = "G") -> Point:
    """The measure centre G of a domain with a scalar density (ch. 5.3.3).

    .. math:: \\mathbf{OG} = \\frac{\\int_D \\rho\\,\\mathbf{OP}\\,d\\mu}{\\int_D \\rho\\,d\\mu}

    With a mass density it is the mass centre (ch. 12.3); with ``density=1`` the centroid
    of the line, surface or volume.

    Parameters
    ----------
    density : scalar expression or callable
        As in :func:`total_measure`.
    domain : Domain
    method, order
        As in :meth:`Domain.integrate`.
    name : str
        Name of the returned point.

    Returns
    -------
    Point

    Raises
    ------
    ArgumentError
        If the total measure is zero.

    Examples
    --------
    A homogeneous semicircular wire of radius R: G on the axis of symmetry at 2R/pi from
    the centre.

    >>> import sympy as sp
    >>> from rigidmech import Frame, constants
    >>> R = constants("R", positive=True)
    >>> u = sp.Symbol("u")
    >>> R0 = Frame("R0")
    >>> wire = Domain(R0, [R * sp.cos(u), R * sp.sin(u), 0], (u, 0, sp.pi))
    >>> measure_centre(1, wire).coordinates(R0).T
    Matrix([[0, 2*R/pi, 0]])
    """
    _check_domain(domain)
    rho = _scalar_density(density, domain)
    values = domain.integrate([rho] + [rho * c for c in domain.coordinates], method=method,
                              order=order)
    total = values[0]
    if total == 0:
        raise ArgumentError(
            "the total measure of the domain is zero: the measure centre is undefined.")
    coords = [sp.simplify(v / total) for v in values[1:]]
    return domain.frame.origin.moved(name, Vector.from_components(domain.frame, coords))


def barycentre(pairs, *, name: str = "G") -> Point:
    """The measure centre of a finite set of weighted points (ch. 5.3.1, 5.3.3).

    .. math:: \\mathbf{OG} = \\frac{\\sum_i m_i\\,\\mathbf{OP}_i}{\\sum_i m_i}

    Parameters
    ----------
    pairs : iterable of (Point, scalar)
        The points P_i and their weights m_i (masses, for example).
    name : str
        Name of the returned point.

    Returns
    -------
    Point

    Raises
    ------
    ArgumentTypeError
        If a pair is not (Point, scalar).
    ArgumentError
        If there is no pair or the weights add up to zero.

    Examples
    --------
    >>> from rigidmech import Frame
    >>> R0 = Frame("R0")
    >>> G = barycentre([(R0.point("A", 0, 0, 0), 1), (R0.point("B", 4, 0, 0), 3)])
    >>> G.coordinates(R0).T
    Matrix([[3, 0, 0]])
    """
    items = []
    for n, pair in enumerate(pairs):
        try:
            point, weight = pair
        except (TypeError, ValueError) as exc:
            raise ArgumentTypeError(
                f"`pairs[{n}]` must be a (Point, weight) pair; got {pair!r}.") from exc
        check_point(point, f"pairs[{n}][0]")
        if isinstance(weight, Vector | Point):
            raise ArgumentTypeError(
                f"`pairs[{n}][1]` must be a scalar weight; got a {type(weight).__name__}.")
        items.append((point, sp.sympify(weight)))
    if not items:
        raise ArgumentError("`pairs` must hold at least one (Point, weight) pair; got none.")
    total = sp.Add(*(m for _, m in items))
    if sp.simplify(total) == 0:
        raise ArgumentError("the weights add up to zero: the barycentre is undefined.")
    origin = items[0][0]
    offset = Vector.zero()
    for point, m in items:
        offset = offset + m * (point - origin)
    return origin.moved(name, (offset / total).applyfunc(sp.simplify))

