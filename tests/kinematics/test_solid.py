"""Kinematics of a rigid body (book, ch. 9): kinematic torsor, velocity and acceleration
fields, composition of motions."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import KinematicTorsor, Solid, kinematic_torsor


@pytest.fixture
def arm():
    q1, q2 = rm.coordinates("q1 q2")
    r = sp.Symbol("r", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.i, angle=q2)
    return q1, q2, r, R0, R1, R2


def test_rotation_about_a_fixed_axis_velocity_and_acceleration(arm):
    """Ch. 9.4.1: a point at distance r on a solid turning about (O, k0): v = r q' e_theta,
    a = r q'' e_theta - r q'^2 e_r."""
    q1, _, r, R0, R1, _ = arm
    S = Solid("S", frame=R1)
    P = R0.origin.moved("P", r * R1.i)
    assert S.velocity(P, relative_to=R0).equals(r * q1.diff() * R1.j)
    expected = r * q1.diff(rm.t, 2) * R1.j - r * q1.diff() ** 2 * R1.i
    assert S.acceleration(P, relative_to=R0).equals(expected)


def test_velocity_field_is_the_moment_field_of_the_kinematic_torsor(arm):
    """v(B) = v(A) + BA ^ omega (ch. 9.2.4): the transport of the torsor reproduces the
    velocity computed at B directly."""
    _, _, r, R0, R1, R2 = arm
    A = R0.origin.moved("A", r * R1.i)
    B = A.moved("B", 2 * R2.j + R2.k)
    V = kinematic_torsor(R2, relative_to=R0, at=A)
    direct = kinematic_torsor(R2, relative_to=R0, at=B).velocity
    assert V.velocity_at(B).equals(direct)
    assert V.moment_at(B).equals((B - R0.origin).dt(R0))  # B is fixed in R2, O fixed in R0


def test_composition_of_kinematic_torsors(arm):
    """{V(2/1)} + {V(1/0)} = {V(2/0)} (ch. 9.3.1), in either order."""
    _, _, _, R0, R1, R2 = arm
    A = R0.point("A", 1, 2, 3)
    V21 = kinematic_torsor(R2, relative_to=R1, at=A)
    V10 = kinematic_torsor(R1, relative_to=R0, at=A)
    V20 = kinematic_torsor(R2, relative_to=R0, at=A)
    for total in (V21 + V10, V10 + V21):
        assert (total.moving, total.reference) == (R2, R0)
        assert total.equals(V20)


def test_inverse_motion(arm):
    _, _, _, R0, R1, _ = arm
    V10 = kinematic_torsor(R1, relative_to=R0, at=R0.origin)
    V01 = -V10
    assert (V01.moving, V01.reference) == (R0, R1)
    assert V01.equals(kinematic_torsor(R0, relative_to=R1, at=R0.origin))


def test_composing_torsors_whose_frames_do_not_chain_is_an_error(arm):
    _, _, _, R0, R1, R2 = arm
    R3 = R0.rotated("R3", about=R0.j, angle=sp.Symbol("a"))
    V21 = kinematic_torsor(R2, relative_to=R1, at=R0.origin)
    V30 = kinematic_torsor(R3, relative_to=R0, at=R0.origin)
    with pytest.raises(ValueError, match=r"cannot compose V\(R2/R1\) with V\(R3/R0\)"):
        V21 + V30


def test_kinematic_torsor_refuses_plain_torsors_and_scaling(arm):
    _, _, _, R0, R1, _ = arm
    V = kinematic_torsor(R1, relative_to=R0, at=R0.origin)
    with pytest.raises(TypeError, match="composes only with a kinematic torsor"):
        V + rm.Torsor(R0.i, R0.j, R0.origin)
    with pytest.raises(TypeError, match="is not scaled"):
        2 * V
    assert isinstance(V, KinematicTorsor)


def test_a_vector_where_a_point_is_expected(arm):
    _, _, _, R0, R1, _ = arm
    with pytest.raises(TypeError, match="`at` must be a Point .*a Vector is not a Point"):
        kinematic_torsor(R1, relative_to=R0, at=R0.i)
    with pytest.raises(TypeError, match="`relative_to` must be a Frame"):
        kinematic_torsor(R1, relative_to="R0", at=R0.origin)
