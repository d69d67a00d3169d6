"""A System refuses what would make its equations silently wrong (issue 9): two bodies or two
frames of one name, one coordinate moved by two connections, gravity added twice, an action on
a body that is not in the system, and a "Galilean" reference that moves relative to the root."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ConnectionError_, FrameError

m, L, g = rm.constants("m L g", positive=True)


def pendulum(R0, name, angle, frame_name=None):
    R1 = R0.rotated(frame_name or f"R_{name}", about=R0.k, angle=angle)
    G = R0.origin.moved(f"G_{name}", L * R1.i)
    return rm.Body(name, frame=R1, mass=m, centre=G)


def pivot(R0):
    return rm.joints.Pivot(at=R0.origin, axis=R0.k)


def test_two_bodies_of_one_name():
    q1, q2 = rm.coordinates("q1 q2")
    R0 = rm.Frame("R0")
    s = rm.System(galilean=R0)
    s.connect(R0, pendulum(R0, "bob", q1), pivot(R0))
    with pytest.raises(ConnectionError_, match=r"two bodies named 'bob'"):
        s.connect(R0, pendulum(R0, "bob", q2), pivot(R0))
    with pytest.raises(ConnectionError_, match=r"two bodies named 'bob'"):
        s.add(pendulum(R0, "bob", q2))


def test_two_frames_of_one_name():
    q1, q2 = rm.coordinates("q1 q2")
    R0 = rm.Frame("R0")
    s = rm.System(galilean=R0)
    s.connect(R0, pendulum(R0, "a", q1, frame_name="R1"), pivot(R0))
    with pytest.raises(ConnectionError_,
                       match=r"two different frames named 'R1' \(of bodies a and b\)"):
        s.connect(R0, pendulum(R0, "b", q2, frame_name="R1"), pivot(R0))


def test_one_coordinate_moved_by_two_connections():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    s = rm.System(galilean=R0)
    s.connect(R0, pendulum(R0, "a", q), pivot(R0))
    with pytest.raises(ConnectionError_,
                       match=r"the coordinate q\(t\) of body b is already moved by the "
                             r"connection R0 -> a"):
        s.connect(R0, pendulum(R0, "b", q), pivot(R0))


def test_one_coordinate_in_a_chain_is_fine():
    # the cart-pole: the pole's frame depends on x through the cart, but its own coordinate
    # is only theta
    x, th = rm.coordinates("x theta")
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    R2 = R1.rotated("R2", about=R1.k, angle=th)
    cart = rm.Body("cart", frame=R1, mass=m)
    pole = rm.Body("pole", frame=R2, mass=m, centre=R1.origin.moved("G", L * R2.i))
    s = rm.System(galilean=R0)
    s.connect(R0, cart, rm.joints.Prismatic(at=R1.origin, axis=R0.i))
    s.connect(cart, pole, rm.joints.Pivot(at=R1.origin, axis=R1.k))
    assert s.coordinates == (x, th)


def test_gravity_added_twice():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    s = rm.System(galilean=R0)
    s.connect(R0, pendulum(R0, "a", q), pivot(R0))
    s.act(rm.gravity(g * R0.i))
    with pytest.raises(ConnectionError_, match=r"gravity is already acting"):
        s.act(rm.gravity(g * R0.i))


def test_same_action_twice():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    s = rm.System(galilean=R0)
    bob = pendulum(R0, "a", q)
    s.connect(R0, bob, pivot(R0))
    push = rm.Force(on=bob, vector=R0.j, at=bob.centre)
    s.act(push)
    with pytest.raises(ConnectionError_, match=r"this action is already in the system"):
        s.act(push)


def test_action_on_a_body_not_in_the_system():
    q1, q2 = rm.coordinates("q1 q2")
    R0 = rm.Frame("R0")
    s = rm.System(galilean=R0)
    s.connect(R0, pendulum(R0, "a", q1), pivot(R0))
    stranger = pendulum(R0, "stranger", q2)
    with pytest.raises(ConnectionError_,
                       match=r"`action` acts on body stranger, which is not in the system"):
        s.act(rm.Force(on=stranger, vector=R0.j, at=stranger.centre))
    with pytest.raises(ConnectionError_, match=r"acts on body stranger"):
        s.act(rm.Couple(on=s.bodies[0], moment=R0.k, reaction_on=stranger))
    with pytest.raises(ConnectionError_, match=r"acts on body stranger"):
        s.act(rm.Spring(1, 0, a=R0.origin, b=stranger.centre, on_b=stranger))


@pytest.mark.parametrize("moving", ["rotating", "translating", "in time"])
def test_galilean_reference_moving_relative_to_the_root(moving):
    q, x = rm.coordinates("q x")
    R0 = rm.Frame("R0")
    if moving == "rotating":
        R = R0.rotated("R", about=R0.k, angle=q)
    elif moving == "translating":
        R = R0.translated("R", R0.point("P", x, 0, 0))
    else:
        R = R0.rotated("R", about=R0.k, angle=2 * rm.t)
    with pytest.raises(FrameError,
                       match=r"`galilean` frame R moves relative to the root frame R0 .*"
                             r"the Galilean reference must not"):
        rm.System(galilean=R)


def test_galilean_reference_fixed_relative_to_the_root():
    R0 = rm.Frame("R0")
    a = sp.Symbol("alpha")
    R = R0.rotated("R", about=R0.k, angle=a).translated("RT", R0.point("P", 1, L, 0))
    assert rm.System(galilean=R).galilean is R


@pytest.mark.parametrize("bad", [(-1.0, 5.0), (5.0, float("nan")), (5.0, float("inf")),
                                 (5.0,), "fast"])
def test_stabilization_must_be_two_finite_non_negative_rates(bad):
    # Baumgarte's residual equation c' + 2 alpha c + beta^2 Phi = 0 is damped only for
    # alpha >= 0 (beta enters squared, but a negative or non-finite one is a typo)
    from rigidmech.errors import ArgumentError
    with pytest.raises(ArgumentError, match=r"`stabilization` must be two finite numbers "
                                            r">= 0 \(alpha, beta\)"):
        rm.System(galilean=rm.Frame("R0"), stabilization=bad)


@pytest.mark.parametrize("good", [(0.0, 0.0), (0, 1e-300), (5.0, 5.0)])
def test_stabilization_at_and_above_zero_is_accepted(good):
    rm.System(galilean=rm.Frame("R0"), stabilization=good)
