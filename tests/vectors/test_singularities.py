"""Singular sets of orientation parametrisations (book, ch. 9.1.2).

Independent reference: scipy.spatial.transform.Rotation builds the rotation matrix of any
intrinsic sequence ("ZXZ" = rotations about the moving z, x, z axes, the chain that
``Frame.rotated`` makes about the current frame's axes). The matrix mapping the angle rates
to the rotation vector (in the body basis) is obtained from it by central differences,
omega^ = R^T dR/dt; its determinant is the mixed product of the unit axes of rotation, whose
absolute value :meth:`OrientationSingularity.measure` must return. Closed forms: |sin(middle)|
for the six proper Euler sequences, |cos(middle)| for the six Cardan (Tait-Bryan) ones.
"""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from rigidmech._core.errors import ArgumentError, ArgumentTypeError, FrameError
from rigidmech.vectors import (
    Frame,
    OrientationSingularity,
    constants,
    coordinates,
    orientation_singularity,
)

PROPER = ["xyx", "xzx", "yxy", "yzy", "zxz", "zyz"]
CARDAN = ["xyz", "xzy", "yxz", "yzx", "zxy", "zyx"]


def chain(sequence, names=("a", "b", "c")):
    qs = coordinates(" ".join(names))
    R0 = Frame("R0")
    f = R0
    for n, (axis, q) in enumerate(zip(sequence, qs, strict=True)):
        about = {"x": f.i, "y": f.j, "z": f.k}[axis]
        f = f.rotated(f"R{n + 1}", about=about, angle=q)
    return R0, f, qs


def rate_matrix_det(sequence, angles, h=1e-6):
    """det of d omega / d(angle rates) in the body basis, from scipy's rotation matrices."""
    seq = sequence.upper()
    R = Rotation.from_euler(seq, angles).as_matrix()
    cols = []
    for j in range(3):
        da = np.zeros(3)
        da[j] = h
        dR = (Rotation.from_euler(seq, angles + da).as_matrix()
              - Rotation.from_euler(seq, angles - da).as_matrix()) / (2 * h)
        W = R.T @ dR  # skew-symmetric: omega^ in the body basis
        cols.append([W[2, 1], W[0, 2], W[1, 0]])
    return np.linalg.det(np.array(cols).T)


@pytest.mark.parametrize("sequence", PROPER + CARDAN)
def test_condition_and_measure_of_each_sequence(sequence):
    """Condition: sin(b) = 0 (proper Euler) or cos(b) = 0 (Cardan), b the middle angle; the
    measure equals |det| of scipy's rate matrix at random angles (central differences,
    h = 1e-6: error about 1e-10)."""
    R0, R, (a, b, c) = chain(sequence)
    s = R.singular_set()
    expected = sp.sin(b) if sequence[0] == sequence[2] else sp.cos(b)
    assert s.condition == sp.Eq(expected, 0)
    assert s.sequence == sequence
    assert s.coordinates == (a, b, c)
    assert s.relative_to == R0 and s.frame == R
    rng = np.random.default_rng(9)
    angles = rng.uniform(-np.pi, np.pi, size=(3, 20))
    got = s.measure(angles)
    ref = [abs(rate_matrix_det(sequence, angles[:, k])) for k in range(20)]
    assert_allclose(got, ref, rtol=0, atol=1e-8)


_SETS = {}


@given(st.sampled_from(PROPER + CARDAN), st.floats(-3.0, 3.0), st.floats(-1.5, 1.5),
       st.floats(-3.0, 3.0))
def test_distance_is_angle_to_nearest_singular_value(sequence, a, b, c):
    """For the middle angle b: distance = |b - nearest k pi| (proper) or
    |b - nearest pi/2 + k pi| (Cardan), a property of arcsin|sin| and arcsin|cos|."""
    if sequence not in _SETS:  # built (and compiled) once per sequence
        _SETS[sequence] = chain(sequence)[1].singular_set()
    s = _SETS[sequence]
    if sequence[0] == sequence[2]:
        expected = abs(b - np.pi * np.round(b / np.pi))
    else:
        expected = abs(b - (np.pi / 2 + np.pi * np.floor(b / np.pi)))
        expected = min(expected, np.pi - expected)
    # distance = arcsin|sin b| or arcsin|cos b|: near the set (small values, where the warning
    # reads it) to 1e-9; far from it arcsin is ill-conditioned at 1 (cos(1e-9) rounds to 1.0),
    # an error up to sqrt(2 eps) ~ 2.1e-8 at distance pi/2
    tol = 1e-9 if expected < 1.0 else 1e-9 + np.sqrt(2 * np.finfo(float).eps)
    assert abs(s.distance([a, b, c]) - expected) < tol


def test_euler_frame_and_names():
    psi, theta, phi = coordinates("psi theta phi")
    R0 = Frame("R0")
    R = R0.euler("R", psi, theta, phi)
    s = R.singular_set()
    assert s.condition == sp.Eq(sp.sin(theta), 0)
    assert s.distance({"psi": 1.0, "theta": 1e-3, "phi": 2.0}) == pytest.approx(1e-3, rel=1e-9)
    assert s.distance({theta: np.pi - 0.2, psi: 0.0, phi: 0.0}) == pytest.approx(0.2, rel=1e-9)
    assert s.describe() == ("the angles z-x-z (psi, theta, phi) of frame R relative to R0, "
                            "singular where sin(theta) = 0")
    assert "Cardan sequence such as z-x-y" in s.suggestion()
    assert repr(s) == ("OrientationSingularity(frame=R, relative_to=R0, sequence='zxz', "
                       "condition=Eq(sin(theta(t)), 0))")
    # the same through the function, and relative to an explicit reference; == is
    # structural and agrees with hash
    assert orientation_singularity(R, R0) == s and hash(orientation_singularity(R, R0)) == hash(s)
    assert R0.euler("S", psi, theta, phi).singular_set() != s  # another frame


def test_cardan_suggests_euler():
    _, R, _ = chain("zyx")
    assert "Euler sequence z-y-z" in R.singular_set().suggestion()


def test_relative_to_a_frame_below_the_root():
    """Euler angles of body 2 relative to body 1 (a chain of six angles from the root): the
    singular set is found relative to the given frame."""
    q = coordinates("p1 t1 s1 p2 t2 s2")
    R0 = Frame("R0")
    R1 = R0.euler("R1", *q[:3])
    R2 = R1.euler("R2", *q[3:])
    assert R2.singular_set(R1).condition == sp.Eq(sp.sin(q[4]), 0)
    with pytest.raises(FrameError, match=r"6 angles .* between R0 and R2, more than a "
                                         r"rotation has; give a nearer reference frame"):
        R2.singular_set()


@pytest.mark.parametrize("build", [
    pytest.param(lambda R0, a, b: R0.rotated("R1", about=R0.k, angle=a), id="one-angle"),
    pytest.param(lambda R0, a, b: (lambda R1: R1.rotated("R2", about=R1.i, angle=b))(
        R0.rotated("R1", about=R0.k, angle=a)), id="two-angles-z-x"),
    pytest.param(lambda R0, a, b: R0.rotated("R1", about=R0.k, angle=1), id="constant"),
    pytest.param(lambda R0, a, b: R0.translated("R1", R0.point("P", a, b, 0)), id="translated"),
])
def test_no_singular_set(build):
    """One angle, or two about axes at a constant angle to each other: never singular."""
    a, b = coordinates("a b")
    R0 = Frame("R0")
    assert build(R0, a, b).singular_set() is None


def test_dependent_angles_raise():
    """Two angles about the same axis (merged into one rotation by a + b) are redundant."""
    a, b = coordinates("a b")
    R0 = Frame("R0")
    R = R0.rotated("R1", about=R0.k, angle=a).rotated("R2", about=R0.k, angle=b)
    with pytest.raises(FrameError, match="turn about dependent axes everywhere"):
        R.singular_set()


def test_constant_angle_in_the_chain_is_a_parameter():
    """z(a), then a constant tilt alpha about y, then x(b), z(c): not a standard sequence;
    the measure is |det| of the unit axes (checked against scipy's elementary rotation
    matrices multiplied in that order, differentiated in a, b, c)."""
    a, b, c = coordinates("a b c")
    alpha = constants("alpha")
    R0 = Frame("R0")
    f = R0.rotated("R1", about=R0.k, angle=a)
    f = f.rotated("R2", about=f.j, angle=alpha)
    f = f.rotated("R3", about=f.i, angle=b)
    R = f.rotated("R", about=f.k, angle=c)
    s = R.singular_set()
    assert s.parameters == (alpha,) and s.sequence is None
    x = np.array([0.3, 0.7, -0.4])
    al, h = 0.6, 1e-6

    def matrix(v):  # intrinsic z(a) y(alpha) x(b) z(c): product of the elementary matrices
        return (Rotation.from_euler("z", v[0]).as_matrix()
                @ Rotation.from_euler("y", al).as_matrix()
                @ Rotation.from_euler("x", v[1]).as_matrix()
                @ Rotation.from_euler("z", v[2]).as_matrix())

    cols = []
    for j in range(3):
        d = np.zeros(3)
        d[j] = h
        W = matrix(x).T @ (matrix(x + d) - matrix(x - d)) / (2 * h)
        cols.append([W[2, 1], W[0, 2], W[1, 0]])
    assert s.measure(x, alpha=al) == pytest.approx(abs(np.linalg.det(np.array(cols).T)),
                                                   abs=1e-8)
    with pytest.raises(ArgumentError, match=r"missing values for the constants \['alpha'\]"):
        s.measure(x)


def test_bad_values():
    psi, theta, phi = coordinates("psi theta phi")
    s = Frame("R0").euler("R", psi, theta, phi).singular_set()
    with pytest.raises(ArgumentError, match=r"`values` must give 3 angles \(psi, theta, phi\)"):
        s.measure([0.1, 0.2])
    with pytest.raises(ArgumentError, match="`values` must give the angle phi"):
        s.measure({"psi": 0.0, "theta": 0.1})
    with pytest.raises(ArgumentTypeError, match="`values` must be numbers"):
        s.measure(["a", "b", "c"])
    with pytest.raises(ArgumentTypeError, match="`frame` must be a Frame"):
        orientation_singularity("R")
    with pytest.raises(ArgumentTypeError, match="`relative_to` must be a Frame"):
        orientation_singularity(Frame("R0"), 3)
    with pytest.raises(TypeError, match="Frame.singular_set"):
        OrientationSingularity()
