"""The orientation of an orbit from its angles and the state at the periapsis from the apsides
(book, ch. 8.2): helpers of :meth:`rigidmech.kinematics.orbits.Orbit.from_apsides` and
:meth:`~rigidmech.kinematics.orbits.Orbit.circular`. Private.

The plane and the periapsis are placed by the classical angles: the longitude of the ascending
node Omega, the inclination i and the argument of the periapsis omega, the rotation
R3(Omega) R1(i) R3(omega) taking the x axis to the periapsis direction P, the y axis to Q
(90 degrees ahead in the sense of the motion) and the z axis to the normal of the plane.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError


def finite_angle(x, argument) -> float:
    """`x` as a float, refusing bools, non-numbers and non-finite values."""
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        raise ArgumentTypeError(
            f"`{argument}` must be a real number (an angle in radians); got "
            f"{type(x).__name__}.")
    x = float(x)
    if not math.isfinite(x):
        raise ArgumentError(f"`{argument}` must be finite; got {x}.")
    return x


def perifocal_basis(raan, inclination, argument_of_periapsis):
    """Unit vectors P (to the periapsis) and Q (P turned by 90 degrees in the plane, in the
    sense of the motion) of the orbit with these angles, in the inertial frame."""
    O = finite_angle(raan, "raan")
    i = finite_angle(inclination, "inclination")
    w = finite_angle(argument_of_periapsis, "argument_of_periapsis")
    if not 0.0 <= i <= math.pi:
        raise ArgumentError(
            f"`inclination` must lie in [0, pi] (the angle between the normal and z); got "
            f"{i}. Add pi to `raan` instead of passing a negative inclination.")
    cO, sO, ci, si, cw, sw = (math.cos(O), math.sin(O), math.cos(i), math.sin(i),
                              math.cos(w), math.sin(w))
    P = np.array([cO * cw - sO * ci * sw, sO * cw + cO * ci * sw, si * sw])
    Q = np.array([-cO * sw - sO * ci * cw, -sO * sw + cO * ci * cw, si * cw])
    return P, Q


def periapsis_speed(mu, periapsis, apoapsis) -> float:
    """Vis-viva at the periapsis: v^2 = mu (2/r_p - 1/a), a = (r_p + r_a)/2, written as
    2 mu r_a / (r_p (r_p + r_a)) (no cancellation)."""
    return math.sqrt(2 * mu * apoapsis / (periapsis * (periapsis + apoapsis)))
