"""Principal axes and moments of inertia (book, ch. 15.2.3).

The matrix of inertia is symmetric and real: it has three real eigenvalues, the principal
moments of inertia, and an orthonormal basis of eigenvectors, the principal axes. In that basis
the matrix is diagonal. Three cases are handled:

- the matrix is diagonal (the basis is already principal, for example a body with material
  symmetries, ch. 15.4.1): the moments (A, B, C) and the basis vectors, exactly;
- one product of inertia only is non-zero (a plane of symmetry, ch. 15.4.1): the axis normal
  to that plane is principal and the other two follow from a rotation by
  :math:`\\theta = \\tfrac{1}{2}\\,\\mathrm{atan2}(2J_{ab}, J_{aa} - J_{bb})`, exactly;
- otherwise, numeric entries only: ``numpy.linalg.eigh``; also whenever an entry is a
  floating-point number (then the moments come in increasing order).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError
from ..vectors import Vector

__all__ = ["PrincipalAxes", "principal_axes"]


class PrincipalAxes(NamedTuple):
    """Principal moments of inertia and the principal axes (ch. 15.2.3).

    Attributes
    ----------
    moments : tuple of 3 sympy expressions or floats
        The principal moments; ``moments[n]`` goes with ``axes[n]``.
    axes : tuple of 3 Vector
        Unit vectors of the principal axes, forming a direct orthonormal basis, expressed in
        the basis of the operator's frame.

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> PrincipalAxes((1, 2, 3), R0.basis).moments
    (1, 2, 3)
    """

    moments: tuple
    axes: tuple


def principal_axes(matrix, frame) -> PrincipalAxes:
    """Principal moments and axes of a symmetric 3x3 matrix of inertia given in ``frame``.

    Parameters
    ----------
    matrix : sympy.ImmutableMatrix, shape (3, 3)
        Matrix of inertia in the book's layout.
    frame : Frame
        Frame whose basis the matrix is expressed in.

    Returns
    -------
    PrincipalAxes
        Entries with floating-point numbers: floats from ``numpy.linalg.eigh``, moments in
        increasing order, the third axis flipped if needed for a direct basis. Otherwise
        (exact entries): a diagonal matrix gives the moments (A, B, C) and the basis
        (i, j, k) of ``frame``; one non-zero product gives exact moments and axes (the axis
        normal to the plane of the product keeps its place); more products, numbers only,
        go through ``eigh`` as above.

    Raises
    ------
    ArgumentError
        For a symbolic matrix with more than one non-zero product of inertia.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> a, b = sp.symbols("a b", positive=True)
    >>> principal_axes(sp.ImmutableMatrix([[a, 0, 0], [0, a, 0], [0, 0, b]]), R0).axes
    (R0.i, R0.j, R0.k)
    >>> pa = principal_axes(sp.ImmutableMatrix([[2, -1, 0], [-1, 2, 0], [0, 0, 3]]), R0)
    >>> pa.moments
    (3, 1, 3)
    >>> pa.axes[0]
    sqrt(2)/2*R0.i - sqrt(2)/2*R0.j
    """
    floats = all(x.is_number for x in matrix) and any(x.has(sp.Float) for x in matrix)
    off = [(r, c) for r, c in ((0, 1), (0, 2), (1, 2)) if matrix[r, c] != 0]
    if not off and not floats:
        return PrincipalAxes(tuple(matrix[n, n] for n in range(3)), frame.basis)
    if len(off) == 1 and not floats:
        return _one_product(matrix, frame, off[0])
    if all(x.is_number for x in matrix):
        try:
            values = np.array(matrix.tolist(), dtype=float)
        except TypeError:
            values = None
        if values is not None:
            moments, vectors = np.linalg.eigh(values)
            if np.linalg.det(vectors) < 0:
                vectors[:, 2] = -vectors[:, 2]
            axes = tuple(Vector.from_components(frame, [float(x) for x in vectors[:, n]])
                         for n in range(3))
            return PrincipalAxes(tuple(float(x) for x in moments), axes)
    raise ArgumentError(
        "`matrix` has more than one non-zero product of inertia and symbolic entries: its "
        "principal axes are not computed symbolically; substitute numbers first (`subs`)."
    )


def _one_product(matrix, frame, rc):
    r, c = rc
    n = 3 - r - c
    a, b = (n + 1) % 3, (n + 2) % 3
    Jaa, Jbb, Jab, Jnn = matrix[a, a], matrix[b, b], matrix[a, b], matrix[n, n]
    radius = sp.sqrt((Jaa - Jbb) ** 2 + 4 * Jab**2)
    theta = sp.atan2(2 * Jab, Jaa - Jbb) / 2
    cs, sn = sp.cos(theta), sp.sin(theta)
    moments = [None] * 3
    axes = [None] * 3
    moments[n], moments[a], moments[b] = Jnn, (Jaa + Jbb + radius) / 2, (Jaa + Jbb - radius) / 2
    ea, eb = frame.basis[a], frame.basis[b]
    axes[n] = frame.basis[n]
    axes[a] = cs * ea + sn * eb
    axes[b] = -sn * ea + cs * eb
    return PrincipalAxes(tuple(moments), tuple(axes))
