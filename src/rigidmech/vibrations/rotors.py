"""Rotation of a solid about a fixed axis: unbalanced rotors and their balancing, compound
and torsion pendulums (book, ch. 22), in closed form.

Conventions (ch. 22.1): the solid turns about the fixed axis (O, k) at the rate ω = q' (and
ω' = q''); in the frame R1 = (O; i1, j1, k) attached to it the mass centre G has coordinates
(a, b, c) and the operator of inertia at O has the products D = ∫ yz dm, E = ∫ zx dm.
The fundamental principle gives, for the action of the bearings (other actions aside), in R1
(ch. 22.1.6, 22.3.1):

.. math:: \\mathbf R = m\\,(-b\\,\\omega' - a\\,\\omega^2,\\ a\\,\\omega' - b\\,\\omega^2,\\ 0),
          \\qquad \\mathbf M(O) = (D\\,\\omega^2 - E\\,\\omega',\\ -E\\,\\omega^2 - D\\,\\omega',
          \\ C\\,\\omega').

A rotor is balanced statically when a = b = 0 and dynamically when, besides, D = E = 0: the
bearings then carry nothing at constant speed (ch. 22.3.3). Two masses in two planes
normal to the axis always suffice.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError
from ._scalars import _as, _lib, _positive

__all__ = ["rotor_bearing_action", "bearing_forces", "balancing_masses",
           "equivalent_length", "centre_of_percussion", "kater_conjugate",
           "compound_pendulum_period", "torsion_pendulum_period"]


def rotor_bearing_action(mass, centre, products, rate, acceleration=0, C=0):
    """The action of the bearings on a rotor turning about (O, k) (ch. 22.3.1), other
    actions aside: resultant and moment at O, components in the rotor's frame R1.

    Parameters
    ----------
    mass : m
    centre : (a, b, c), coordinates of G in R1
    products : (D, E), products of inertia at O in R1 (D = ∫yz dm, E = ∫zx dm)
    rate, acceleration : ω and ω'
    C : moment of inertia about the axis (for the axial moment C ω')

    Returns
    -------
    (resultant (3,), moment at O (3,)) : tuples of expressions or floats

    Examples
    --------
    >>> import sympy as sp
    >>> m, a, b, c, D, E, w = sp.symbols("m a b c D E omega")
    >>> rotor_bearing_action(m, (a, b, c), (D, E), w)
    ((-a*m*omega**2, -b*m*omega**2, 0), (D*omega**2, -E*omega**2, 0))
    """
    a, b, _ = centre
    D, E = products
    w, wd = rate, acceleration
    R = (mass * (-b * wd - a * w**2), mass * (a * wd - b * w**2), 0)
    M = (D * w**2 - E * wd, -E * w**2 - D * wd, C * wd)
    if all(isinstance(x, sp.Basic) for x in (*R[:2], *M)) or any(
            isinstance(x, sp.Basic) and not x.is_number for x in (*R[:2], *M)):
        return tuple(sp.sympify(x) for x in R), tuple(sp.sympify(x) for x in M)
    return tuple(float(x) for x in R), tuple(float(x) for x in M)


def bearing_forces(mass, centre, products, rate, acceleration=0, *, planes):
    """Transverse forces (X, Y) in R1 of two bearings at z = z_A and z = z_B on the axis,
    from :func:`rotor_bearing_action` (ch. 22.3.2): :math:`\\mathbf R_A + \\mathbf R_B =
    \\mathbf R`, :math:`z_A\\,\\mathbf k\\wedge\\mathbf R_A + z_B\\,\\mathbf k\\wedge
    \\mathbf R_B = (M_x, M_y, 0)`.

    Returns
    -------
    ((X_A, Y_A), (X_B, Y_B))

    Examples
    --------
    A point mass m at radius e in the plane z = 0 midway between bearings at ±L:

    >>> import sympy as sp
    >>> m, e, L, w = sp.symbols("m e L omega", positive=True)
    >>> bearing_forces(m, (e, 0, 0), (0, 0), w, planes=(-L, L))
    ((-e*m*omega**2/2, 0), (-e*m*omega**2/2, 0))
    """
    zA, zB = planes
    if sp.simplify(sp.sympify(zA) - zB) == 0:
        raise ArgumentError(f"`planes` must be two distinct positions; got {planes}.")
    (X, Y, _), (Mx, My, _) = rotor_bearing_action(mass, centre, products, rate, acceleration)
    # X_A + X_B = X, zA X_A + zB X_B = My ; Y_A + Y_B = Y, zA Y_A + zB Y_B = -Mx
    XA = (zB * X - My) / (zB - zA)
    YA = (zB * Y + Mx) / (zB - zA)
    out = ((XA, YA), (X - XA, Y - YA))
    if any(isinstance(v, sp.Basic) and not v.is_number for p in out for v in p):
        return tuple(tuple(sp.simplify(v) for v in p) for p in out)
    return tuple(tuple(float(v) for v in p) for p in out)


def balancing_masses(mass, centre, products, *, planes, radius):
    """Two masses, one in each plane z = z1, z = z2, at distance ``radius`` from the axis,
    that balance the rotor statically and dynamically (ch. 22.3.3).

    With :math:`u_i = m_i x_i`, :math:`v_i = m_i y_i` the conditions are linear:
    :math:`m a + u_1 + u_2 = 0`, :math:`E + z_1 u_1 + z_2 u_2 = 0`,
    :math:`m b + v_1 + v_2 = 0`, :math:`D + z_1 v_1 + z_2 v_2 = 0`; then
    :math:`m_i = \\sqrt{u_i^2 + v_i^2}/r` at the angle :math:`\\operatorname{atan2}(v_i, u_i)`
    from i1.

    Returns
    -------
    list of two (mass, angle, (x, y, z)) : the added masses and their positions in R1

    Examples
    --------
    A static unbalance m e at z = 0, planes at ±L, radius r: two equal masses m e/(2r)
    opposite the unbalance.

    >>> import sympy as sp
    >>> m, e, L, r = sp.symbols("m e L r", positive=True)
    >>> [(mi, angle) for mi, angle, _ in balancing_masses(m, (e, 0, 0), (0, 0),
    ...                                                  planes=(-L, L), radius=r)]
    [(e*m/(2*r), pi), (e*m/(2*r), pi)]
    """
    a, b, _ = centre
    D, E = products
    z1, z2 = planes
    if sp.simplify(sp.sympify(z1) - z2) == 0:
        raise ArgumentError(f"`planes` must be two distinct positions; got {planes}.")
    _positive(radius, "radius")
    lib = _lib(mass, a, b, D, E, z1, z2, radius)
    m, a, b, D, E, z1, z2, r = (_as(x, lib) for x in (mass, a, b, D, E, z1, z2, radius))
    u1 = (E - m * a * z2) / (z2 - z1)
    v1 = (D - m * b * z2) / (z2 - z1)
    u2, v2 = -m * a - u1, -m * b - v1
    out = []
    for u, v, z in ((u1, v1, z1), (u2, v2, z2)):
        if lib is sp:
            u, v = sp.simplify(u), sp.simplify(v)
            mi = sp.simplify(sp.sqrt(u**2 + v**2) / r)
            angle = sp.atan2(v, u)
            pos = (sp.simplify(r * sp.cos(angle)), sp.simplify(r * sp.sin(angle)), z)
        else:
            mi = float(np.hypot(u, v) / r)
            angle = float(np.arctan2(v, u))
            pos = (float(r * np.cos(angle)), float(r * np.sin(angle)), float(z))
        out.append((mi, angle, pos))
    return out


def equivalent_length(distance, radius_of_gyration):
    """Length of the simple pendulum with the period of a compound pendulum (ch. 22.2.1):
    :math:`l = J_O/(m d) = d + k_G^2/d`, d = OG, :math:`k_G` the radius of gyration about
    the axis through G.

    Examples
    --------
    A uniform rod of length L hung from one end: d = L/2, k² = L²/12, l = 2L/3.

    >>> import sympy as sp
    >>> L = sp.Symbol("L", positive=True)
    >>> equivalent_length(L / 2, L / sp.sqrt(12))
    2*L/3
    """
    _positive(distance, "distance")
    lib = _lib(distance, radius_of_gyration)
    d, k = _as(distance, lib), _as(radius_of_gyration, lib)
    return d + k**2 / d


def centre_of_percussion(distance, radius_of_gyration):
    """Distance from the pivot O of the centre of percussion (on OG): a blow normal to OG
    there causes no impulsive reaction at O; it is at the equivalent length
    :math:`p = d + k_G^2/d` (the centre of oscillation), ch. 22.2.1.

    Examples
    --------
    >>> round(float(centre_of_percussion(0.5, 1 / 12**0.5)), 12)
    0.666666666667
    """
    return equivalent_length(distance, radius_of_gyration)


def kater_conjugate(distance, radius_of_gyration):
    """Distance from G, on the other side of G from the pivot, of the conjugate suspension
    point: hung there the pendulum has the same period (reversibility, Kater's pendulum,
    ch. 22.2.1): :math:`d' = k_G^2/d`, so that :math:`d + d'` is the equivalent length.

    Examples
    --------
    >>> import sympy as sp
    >>> L = sp.Symbol("L", positive=True)
    >>> kater_conjugate(L / 2, L / sp.sqrt(12))
    L/6
    """
    _positive(distance, "distance")
    lib = _lib(distance, radius_of_gyration)
    return _as(radius_of_gyration, lib) ** 2 / _as(distance, lib)


def compound_pendulum_period(distance, radius_of_gyration, g):
    """Period of small oscillations of a compound pendulum, :math:`2\\pi\\sqrt{l/g}` with l
    the equivalent length (ch. 22.2.1).

    Examples
    --------
    >>> import sympy as sp
    >>> L, g = sp.symbols("L g", positive=True)
    >>> compound_pendulum_period(L / 2, L / sp.sqrt(12), g)
    2*sqrt(6)*pi*sqrt(L)/(3*sqrt(g))
    """
    lib = _lib(distance, radius_of_gyration, g)
    return 2 * lib.pi * lib.sqrt(equivalent_length(distance, radius_of_gyration) / _as(g, lib))


def torsion_pendulum_period(inertia, stiffness):
    """Period of a torsion pendulum, :math:`2\\pi\\sqrt{J/k}`: a body of moment of inertia J
    about the wire hung from a wire of torsional stiffness k (ch. 22.2.2; see
    :func:`rigidmech.actions.wire_torsional_stiffness`).

    Examples
    --------
    >>> import sympy as sp
    >>> J, k = sp.symbols("J k", positive=True)
    >>> torsion_pendulum_period(J, k)
    2*pi*sqrt(J)/sqrt(k)
    """
    _positive(inertia, "inertia")
    _positive(stiffness, "stiffness")
    lib = _lib(inertia, stiffness)
    return 2 * lib.pi * lib.sqrt(_as(inertia, lib) / _as(stiffness, lib))
