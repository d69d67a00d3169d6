"""Euler parameters (unit quaternions): an orientation without singular set (book, ch. 9.1.2).

Three angles cannot locate a basis everywhere (see :mod:`rigidmech.vectors.singularities`).
Four Euler parameters (e0, e1, e2, e3) can: the rotation by the angle alpha about the unit
vector n has e0 = cos(alpha/2) and (e1, e2, e3) = sin(alpha/2) n. rigidmech uses the
direction cosines of the *normalised* parameters :math:`e / |e|`,

.. math:: C = \\frac{1}{|e|^2}\\begin{pmatrix}
          e_0^2+e_1^2-e_2^2-e_3^2 & 2(e_1e_2-e_0e_3) & 2(e_1e_3+e_0e_2)\\\\
          2(e_1e_2+e_0e_3) & e_0^2-e_1^2+e_2^2-e_3^2 & 2(e_2e_3-e_0e_1)\\\\
          2(e_1e_3-e_0e_2) & 2(e_2e_3+e_0e_1) & e_0^2-e_1^2-e_2^2+e_3^2
          \\end{pmatrix},

so that the orientation depends on the direction of e only: any e != 0 gives a rotation, and
the length :math:`|e|` is a gauge that the equations of motion keep constant (the constraint
e . e'' = -e' . e', see :meth:`rigidmech.dynamics.System.equations_of_motion`) instead of a
constraint the motion must satisfy.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError

__all__ = ["euler_parameter_matrix", "euler_parameters_of", "euler_parameter_rates"]

#: the matrices made by :func:`euler_parameter_matrix`, and their parameters (a memo of the
#: inverse of a pure function, so that a frame made from them is recognised)
_MADE: dict = {}


def euler_parameter_matrix(e0, e1, e2, e3):
    """Direction cosines of the Euler parameters (columns: the rotated basis in the parent
    basis), normalised by :math:`|e|^2`, as a 3x3 tuple of sympy expressions.

    Examples
    --------
    >>> import sympy as sp
    >>> a = sp.Symbol("a")
    >>> C = euler_parameter_matrix(sp.cos(a / 2), 0, 0, sp.sin(a / 2))  # about k by a
    >>> [sp.simplify(x) for x in C[0]]
    [cos(a), -sin(a), 0]
    """
    e = [sp.sympify(x) for x in (e0, e1, e2, e3)]
    a, b, c, d = e
    n2 = a**2 + b**2 + c**2 + d**2
    m = ((a**2 + b**2 - c**2 - d**2, 2 * (b * c - a * d), 2 * (b * d + a * c)),
         (2 * (b * c + a * d), a**2 - b**2 + c**2 - d**2, 2 * (c * d - a * b)),
         (2 * (b * d - a * c), 2 * (c * d + a * b), a**2 - b**2 - c**2 + d**2))
    out = tuple(tuple(x / n2 for x in row) for row in m)
    _MADE[out] = tuple(e)
    return out


def euler_parameters_of(frame):
    """The four Euler parameters that orient ``frame`` relative to its parent
    (:meth:`Frame.euler_parameters`), or None for a frame made otherwise.

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> e = coordinates("e0 e1 e2 e3")
    >>> R0 = Frame("R0")
    >>> euler_parameters_of(R0.euler_parameters("R", *e))
    (e0(t), e1(t), e2(t), e3(t))
    >>> euler_parameters_of(R0) is None
    True
    """
    matrix = getattr(frame, "_matrix", None)
    return None if matrix is None else _MADE.get(matrix)


def euler_parameter_rates(e, omega):
    """e' for the Euler parameters ``e`` and the rotation vector ``omega`` given in the
    rotated (body) basis: e' = (1/2) e * (0, omega), a quaternion product, so that
    e . e' = 0 (numbers; for initial conditions).

    Examples
    --------
    >>> euler_parameter_rates([1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 2.0])   # about k at 2 rad/s
    array([0., 0., 0., 1.])
    """
    e = np.asarray(e, dtype=float)
    w = np.asarray(omega, dtype=float)
    if e.shape != (4,) or w.shape != (3,):
        raise ArgumentError(f"`e` must give 4 numbers and `omega` 3; got shapes {e.shape} "
                            f"and {w.shape}.")
    e0, v = e[0], e[1:]
    return 0.5 * np.concatenate(([-v @ w], e0 * w + np.cross(v, w)))
