"""Euler-angle rates and the rotation between two orientations (ch. 9.1-9.2).

Independent routes: the rotation vector of Frame.euler computed by sympy (components in the
body and the reference bases) for the rates, and scipy's Rotation.from_euler("ZXZ") (intrinsic
z-x-z) for the direction cosines and the axis-angle."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.vectors import Frame, axis_angle, coordinates, euler_angle_rates, rotation_between

psi, theta, phi = coordinates("psi theta phi")
R0 = Frame("R0")
R = R0.euler("R", psi, theta, phi)
OMEGA = R.rotation_vector(R0)


def omega_numeric(angles, rates, frame):
    comps = OMEGA.components(frame)
    subs = {q.diff(): r for q, r in zip((psi, theta, phi), rates, strict=True)}
    expr = comps.subs(subs)
    expr = expr.subs(dict(zip((psi, theta, phi), angles, strict=True)))
    return np.array(expr.evalf(), dtype=float).ravel()


CASES = [((0.3, 1.1, -0.7), (0.5, -1.2, 2.0)), ((2.0, 0.2, 4.0), (-3.0, 0.1, 0.4)),
         ((-1.0, 2.9, 0.5), (1.0, 1.0, 1.0)), ((0.0, math.pi / 2, 0.0), (0.0, 0.0, 0.0))]


@pytest.mark.parametrize(("angles", "rates"), CASES)
@pytest.mark.parametrize(("basis", "frame"), [("body", R), ("reference", R0)])
def test_rates_recover_the_rates_of_the_rotation_vector(angles, rates, basis, frame):
    w = omega_numeric(angles, rates, frame)
    assert_allclose(euler_angle_rates(angles, w, basis=basis), rates, atol=1e-12)


def test_singular_set_boundary_and_either_side():
    angles = [0.2, 1e-10, 0.4]
    s = abs(math.sin(1e-10))
    with pytest.raises(ArgumentError, match=r"`angles` lie on the singular set"):
        euler_angle_rates(angles, [0, 0, 1], tol=s)                          # at the threshold
    euler_angle_rates(angles, [0, 0, 1], tol=np.nextafter(s, 0))             # just below it
    with pytest.raises(ArgumentError, match=r"abs\(sin\(theta\)\)"):
        euler_angle_rates(angles, [0, 0, 1], tol=np.nextafter(s, 1))         # just above it


@pytest.mark.parametrize("th", [0.0, math.pi, -math.pi, 2 * math.pi])
def test_singular_orientations_refused_by_default(th):
    with pytest.raises(ArgumentError, match=r"only psi' \+ phi' is defined.*Euler parameters"):
        euler_angle_rates([0.1, th, 0.2], [1.0, 0.0, 0.0])


@pytest.mark.parametrize(("kwargs", "error", "match"), [
    (dict(angles=[0.1, 0.2]), ArgumentError, r"`angles` must have shape \(3,\)"),
    (dict(omega=[0.0, math.nan, 1.0]), ArgumentError, r"`omega` must be finite"),
    (dict(omega="spin"), ArgumentTypeError, r"`omega` must be numbers of shape"),
    (dict(basis="inertial"), ArgumentError, r"`basis` must be 'body' or 'reference'"),
    (dict(tol=-1.0), ArgumentError, r"`tol` must be a number >= 0"),
])
def test_rates_bad_input(kwargs, error, match):
    args = dict(angles=[0.1, 1.0, 0.2], omega=[0.0, 0.0, 1.0]) | kwargs
    with pytest.raises(error, match=match):
        euler_angle_rates(**args)


# --- rotation between two orientations --------------------------------------------------------

a1, a2, a3, b1, b2, b3 = coordinates("a1 a2 a3 b1 b2 b3")
A = R0.euler("A", a1, a2, a3)
B = R0.euler("B", b1, b2, b3)
VA, VB = (0.3, 1.0, -0.4), (2.0, 0.5, 1.2)
VALUES = dict(zip(["a1", "a2", "a3", "b1", "b2", "b3"], VA + VB, strict=True))


def test_rotation_between_matches_scipy_zxz():
    CA = Rotation.from_euler("ZXZ", VA).as_matrix()     # columns: A's axes in R0
    CB = Rotation.from_euler("ZXZ", VB).as_matrix()
    assert_allclose(rotation_between(R0, A, VALUES), CA, atol=1e-14)
    Rab = rotation_between(A, B, VALUES)
    assert_allclose(Rab, CA.T @ CB, atol=1e-14)
    assert_allclose(rotation_between(B, A, VALUES), Rab.T, atol=1e-14)


def test_axis_angle_of_the_relative_rotation():
    rel = Rotation.from_euler("ZXZ", VA).inv() * Rotation.from_euler("ZXZ", VB)
    axis, angle = axis_angle(rotation_between(A, B, VALUES))
    assert angle == pytest.approx(rel.magnitude(), abs=1e-13)
    assert_allclose(axis * angle, rel.as_rotvec(), atol=1e-13)
    # the axis is left fixed: R axis = axis
    assert_allclose(rotation_between(A, B, VALUES) @ axis, axis, atol=1e-13)


def test_values_keyed_by_the_coordinates_themselves():
    values = dict(zip((a1, a2, a3, b1, b2, b3), VA + VB, strict=True))
    assert_allclose(rotation_between(A, B, values), rotation_between(A, B, VALUES), atol=0)


def test_missing_values_refused():
    with pytest.raises(ArgumentError, match=r"missing \['b2'\]"):
        rotation_between(A, B, {k: v for k, v in VALUES.items() if k != "b2"})
    with pytest.raises(ArgumentTypeError, match=r"`values` must be a mapping"):
        rotation_between(A, B, [1, 2])
    with pytest.raises(ArgumentTypeError, match=r"`frame_b` must be a Frame"):
        rotation_between(A, "B")


def test_axis_angle_special_rotations():
    axis, angle = axis_angle(np.eye(3))
    assert angle == 0.0 and axis.tolist() == [0.0, 0.0, 0.0]
    axis, angle = axis_angle(np.diag([1.0, -1.0, -1.0]))       # half turn about x
    assert angle == pytest.approx(math.pi, abs=1e-15)
    assert_allclose(np.abs(axis), [1, 0, 0], atol=1e-15)


def test_axis_angle_tolerance_boundary():
    d = 1e-7
    M = np.diag([1.0 + d, 1.0, 1.0])
    defect = max(float(np.max(np.abs(M.T @ M - np.eye(3)))), abs(float(np.linalg.det(M)) - 1))
    axis_angle(M, tol=defect)                                                 # at the threshold
    with pytest.raises(ArgumentError, match=r"`matrix` must be a proper rotation"):
        axis_angle(M, tol=np.nextafter(defect, 0))                            # just below


@pytest.mark.parametrize(("matrix", "match"), [
    (np.diag([1.0, 1.0, -1.0]), r"det R = -1"),                 # a reflection
    (2 * np.eye(3), r"max \|R.T R - I\| = 3"),
    (np.eye(2), r"`matrix` must have shape \(3, 3\)"),
])
def test_axis_angle_bad_matrix(matrix, match):
    with pytest.raises(ArgumentError, match=match):
        axis_angle(matrix)
