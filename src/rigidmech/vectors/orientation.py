"""Euler-angle rates from a rotation vector, and the rotation between two orientations
(book, ch. 4 and 9.1-9.2), in numbers.

The Euler angles z-x-z (precession psi about k0, nutation theta about the line of nodes u,
spin phi about the body's k; :meth:`rigidmech.vectors.Frame.euler`) give the rotation vector

.. math:: \\boldsymbol\\omega = \\dot\\psi\\,\\mathbf k_0 + \\dot\\theta\\,\\mathbf u
          + \\dot\\varphi\\,\\mathbf k,

whose components in the body basis (i, j, k) are (ch. 9.2.3)

.. math:: \\omega_x = \\dot\\psi\\sin\\theta\\sin\\varphi + \\dot\\theta\\cos\\varphi,\\quad
          \\omega_y = \\dot\\psi\\sin\\theta\\cos\\varphi - \\dot\\theta\\sin\\varphi,\\quad
          \\omega_z = \\dot\\psi\\cos\\theta + \\dot\\varphi,

and in the reference basis (i0, j0, k0)

.. math:: \\omega_X = \\dot\\theta\\cos\\psi + \\dot\\varphi\\sin\\psi\\sin\\theta,\\quad
          \\omega_Y = \\dot\\theta\\sin\\psi - \\dot\\varphi\\cos\\psi\\sin\\theta,\\quad
          \\omega_Z = \\dot\\psi + \\dot\\varphi\\cos\\theta.

Solving them for the rates divides by sin(theta): where it vanishes (the body's k along k0)
only psi' + phi' is defined, the singular set of :mod:`rigidmech.vectors.singularities`.
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ._rotations import FrameBase

__all__ = ["euler_angle_rates", "rotation_between", "axis_angle", "SINGULAR_TOL"]

#: Default threshold on abs(sin(theta)) at and below which :func:`euler_angle_rates` refuses
#: the angles: the rates psi' and phi' grow as 1/sin(theta) and are not determined at 0.
SINGULAR_TOL = 1e-9


def _floats(x, shape, argument):
    try:
        a = np.asarray(x, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentTypeError(
            f"`{argument}` must be numbers of shape {shape}; got {type(x).__name__}.") from None
    if a.shape != shape:
        raise ArgumentError(f"`{argument}` must have shape {shape}; got shape {a.shape}.")
    if not np.all(np.isfinite(a)):
        raise ArgumentError(f"`{argument}` must be finite; got {a.tolist()}.")
    return a


def euler_angle_rates(angles, omega, *, basis="body", tol=SINGULAR_TOL) -> np.ndarray:
    """The rates (psi', theta', phi') of the z-x-z Euler angles for a rotation vector
    (book, ch. 9.2.3).

    Parameters
    ----------
    angles : array_like, shape (3,)
        (psi, theta, phi) in radians, as in :meth:`rigidmech.vectors.Frame.euler`.
    omega : array_like, shape (3,)
        The rotation vector of the body relative to the reference.
    basis : {"body", "reference"}
        Whether `omega` is given by its components in the body basis (i, j, k) or in the
        reference basis (i0, j0, k0).
    tol : float
        The angles are refused when ``abs(sin(theta)) <= tol`` (default :data:`SINGULAR_TOL`).

    Returns
    -------
    ndarray, shape (3,)
        (psi', theta', phi').

    Raises
    ------
    ArgumentError
        On the singular set ``abs(sin(theta)) <= tol``, a wrong shape, non-finite values, an
        unknown `basis` or a negative `tol`.

    Examples
    --------
    A spin of 2 rad/s about the body's k at theta = pi/2 is all phi':

    >>> import math
    >>> euler_angle_rates([0.3, math.pi / 2, 0.1], [0.0, 0.0, 2.0]).round(12).tolist()
    [0.0, 0.0, 2.0]
    """
    psi, theta, phi = _floats(angles, (3,), "angles")
    w = _floats(omega, (3,), "omega")
    if basis not in ("body", "reference"):
        raise ArgumentError(f"`basis` must be 'body' or 'reference'; got {basis!r}.")
    if isinstance(tol, bool) or not isinstance(tol, int | float) or not tol >= 0:
        raise ArgumentError(f"`tol` must be a number >= 0; got {tol!r}.")
    s, c = math.sin(theta), math.cos(theta)
    if abs(s) <= tol:
        raise ArgumentError(
            f"`angles` lie on the singular set of the Euler angles z-x-z: abs(sin(theta)) = "
            f"{abs(s):.3g} <= tol = {tol:g} (theta = {theta:.6g}); there the body's k is along "
            "k0 and only psi' + phi' is defined. Use Euler parameters "
            "(Frame.euler_parameters and euler_parameter_rates) near this orientation.")
    if basis == "body":
        sf, cf = math.sin(phi), math.cos(phi)
        psi_dot = (w[0] * sf + w[1] * cf) / s
        theta_dot = w[0] * cf - w[1] * sf
        phi_dot = w[2] - psi_dot * c
    else:
        sp_, cp = math.sin(psi), math.cos(psi)
        phi_dot = (w[0] * sp_ - w[1] * cp) / s
        theta_dot = w[0] * cp + w[1] * sp_
        psi_dot = w[2] - phi_dot * c
    return np.array([psi_dot, theta_dot, phi_dot])


def _substitute(matrix, values):
    values = {} if values is None else values
    if not isinstance(values, dict):
        raise ArgumentTypeError(
            f"`values` must be a mapping from coordinates or constants (or their names) to "
            f"numbers; got {type(values).__name__}.")
    free = [a for a in matrix.atoms(sp.core.function.AppliedUndef)]
    free += [s for s in matrix.free_symbols if s.name != "t"]
    subs = {}
    for a in free:
        name = a.func.__name__ if isinstance(a, sp.core.function.AppliedUndef) else a.name
        if a in values:
            subs[a] = values[a]
        elif name in values:
            subs[a] = values[name]
    m = matrix.subs(subs)
    try:
        return np.array(m.evalf(), dtype=float)
    except (TypeError, ValueError):
        left = sorted({x.func.__name__ for x in m.atoms(sp.core.function.AppliedUndef)}
                      | {s.name for s in m.free_symbols if s.name != "t"})
        raise ArgumentError(
            f"`values` must give a number to every coordinate and constant of the two "
            f"orientations; missing {left}.") from None


def rotation_between(frame_a, frame_b, values=None) -> np.ndarray:
    """The rotation taking frame A's basis to frame B's, as a matrix in A's components.

    The matrix R has for columns B's basis vectors expressed in A (the direction cosines
    ``frame_a.dcm(frame_b)``, ch. 1.5.2 and 9.1): R e_i = b_i in A's components, and
    ``R @ x_B`` gives in A the components of the vector whose components in B are x_B.

    Parameters
    ----------
    frame_a, frame_b : Frame
        Two frames of the same tree.
    values : mapping, optional
        Numbers for the coordinates and constants the orientations depend on, keyed by the
        objects or by their names.

    Returns
    -------
    ndarray, shape (3, 3)

    Raises
    ------
    ArgumentTypeError
        If a frame is not a Frame or `values` not a mapping.
    ArgumentError
        If a coordinate or constant is left without a number.

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> q = coordinates("q")
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> rotation_between(R0, R1, {"q": 0.5}).round(6)[0].tolist()
    [0.877583, -0.479426, 0.0]
    """
    for f, argument in ((frame_a, "frame_a"), (frame_b, "frame_b")):
        if not isinstance(f, FrameBase):
            raise ArgumentTypeError(f"`{argument}` must be a Frame; got {type(f).__name__}.")
    return _substitute(frame_a.dcm(frame_b), values)


def axis_angle(matrix, *, tol=1e-9):
    """The unit axis and the angle in [0, pi] of a rotation matrix (Euler's theorem, ch. 9.1).

    Computed by :class:`scipy.spatial.transform.Rotation` (its rotation vector). The axis is
    in the components the matrix is written in (those of A for :func:`rotation_between`;
    the axis has the same components in B).

    Parameters
    ----------
    matrix : array_like, shape (3, 3)
        A proper rotation: ``R.T @ R = I`` and ``det R = 1``, to `tol`.
    tol : float
        Largest accepted ``max |R.T R - I|`` and ``|det R - 1|``.

    Returns
    -------
    (ndarray of shape (3,), float)
        The unit axis (the zero vector for the identity, where it is not defined) and the
        angle.

    Raises
    ------
    ArgumentError
        If `matrix` is not a proper rotation (a reflection, a scaling...) or not 3x3.

    Examples
    --------
    >>> import numpy as np
    >>> axis, angle = axis_angle([[0, -1, 0], [1, 0, 0], [0, 0, 1]])   # a quarter turn about z
    >>> axis.round(12).tolist(), round(angle, 12)
    ([0.0, 0.0, 1.0], 1.570796326795)
    """
    R = _floats(matrix, (3, 3), "matrix")
    defect = float(np.max(np.abs(R.T @ R - np.eye(3))))
    det = float(np.linalg.det(R))
    if defect > tol or abs(det - 1) > tol:
        raise ArgumentError(
            f"`matrix` must be a proper rotation (R.T R = I, det R = 1, to {tol:g}); got "
            f"max |R.T R - I| = {defect:.3g} and det R = {det:.6g}.")
    # lazy: import cost (scipy takes as long as sympy to import; see docs/performance)
    from scipy.spatial.transform import Rotation

    rotvec = Rotation.from_matrix(R).as_rotvec()
    angle = float(np.linalg.norm(rotvec))
    axis = rotvec / angle if angle > 0 else np.zeros(3)
    return axis, angle
