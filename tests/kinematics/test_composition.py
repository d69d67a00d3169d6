"""Composition of velocities and accelerations (book, ch. 17.1): relative, entrainment and
Coriolis terms, checked against the velocity and acceleration computed directly in R0."""

import random

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidmech as rm
from rigidmech._core.errors import ArgumentTypeError, FrameError
from rigidmech.kinematics import (
    Composition,
    Solid,
    acceleration_composition,
    velocity_composition,
)

Q = rm.coordinates("q1 q2 q3 q4 q5 q6")
T = rm.t


def _numeric(vec, frame, values):
    """Components in `frame` at the numeric values of q, q', q'' (highest order first)."""
    rule = {}
    for q, (v0, v1, v2) in zip(Q, values, strict=True):
        rule[q.diff(T, 2)] = v2
        rule[q.diff(T)] = v1
        rule[q] = v0
    comps = vec.components(frame).xreplace(rule)
    return [complex(sp.N(c.subs(T, 0.37))) for c in comps]


def _chain(draw_ints):
    """A random frame tree R0 -> Ra -> Rb (rotations about random axes by q's, moving
    origins) and a point moving in Rb."""
    rnd = random.Random(draw_ints)
    R0 = rm.Frame("R0")
    frames = [R0]
    for n, name in enumerate(("Ra", "Rb")):
        parent = frames[-1]
        axis = parent.basis[rnd.randrange(3)]
        origin = parent.origin.moved(
            "O" + name, parent.vector(Q[2 * n] * rnd.choice((0, 1)), rnd.randint(-2, 2),
                                      T * rnd.randint(0, 2)))
        frames.append(parent.rotated(name, about=axis, angle=Q[2 * n + 1] + rnd.random() * T,
                                     origin=origin))
    Rb = frames[-1]
    where = frames[rnd.randrange(3)]
    M = Rb.origin.moved("M", where.vector(Q[4], sp.sin(Q[5]), T**2 * rnd.random()))
    return frames, M


@settings(max_examples=20)
@given(seed=st.integers(0, 10**6),
       values=st.lists(st.tuples(*[st.floats(-2, 2)] * 3), min_size=6, max_size=6),
       pair=st.sampled_from([(1, 0), (2, 0), (2, 1)]))
def test_composition_of_accelerations_property(seed, values, pair):
    """a(M/R0) = a_rel + a_ent + a_cor and v(M/R0) = v_rel + v_ent for random frame chains
    and points (ch. 17.1.2), at random numeric values of q, q', q'' to 1e-12."""
    frames, M = _chain(seed)
    R1, R0 = frames[pair[0]], frames[pair[1]]
    acc = acceleration_composition(M, relative_to=R1, absolute=R0)
    vel = velocity_composition(M, relative_to=R1, absolute=R0)
    for got, direct in ((acc.absolute, M.acceleration(R0)), (vel.absolute, M.velocity(R0))):
        g, d = _numeric(got, R0, values), _numeric(direct, R0, values)
        for x, y in zip(g, d, strict=True):
            assert abs(x - y) <= 1e-12 * max(1.0, abs(y))


def test_composition_symbolic_zero_on_a_chain():
    """The same law, symbolically: the difference simplifies to zero."""
    q1, q2, x = Q[:3]
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1, origin=R0.point("O1", x, 0, 0))
    R2 = R1.rotated("R2", about=R1.i, angle=q2)
    M = R2.origin.moved("M", Q[3] * R2.j + R2.k)
    c = acceleration_composition(M, relative_to=R2, absolute=R0)
    assert (c.absolute - M.acceleration(R0)).simplify(R0).is_zero


def test_velocity_composition_has_no_coriolis_term():
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=Q[0])
    c = velocity_composition(R1.point("M", Q[1], 0, 0), relative_to=R1, absolute=R0)
    assert c.coriolis.is_zero and c.kind == "velocity"
    assert tuple(c) == (c.relative, c.entrainment, c.coriolis)


def test_solid_coinciding_point_turntable():
    """A disc S spinning at phi about its axis k1 whose centre C is carried by a turntable
    R1 turning at theta about k0 at distance d (ch. 17.1.3): the composition at a point P of
    the disc equals a(P in S/R0) computed by the solid's acceleration field."""
    th, ph = Q[:2]
    d, rho = sp.symbols("d rho", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    S = Solid("S", frame=R1.rotated("RS", about=R1.k, angle=ph,
                                    origin=R0.origin.moved("C", d * R1.i)))
    P = S.frame.origin.moved("P", rho * S.frame.i)
    acc = acceleration_composition(S, relative_to=R1, absolute=R0, at=P)
    assert (acc.absolute - S.acceleration(P, relative_to=R0)).simplify(R0).is_zero
    # Coriolis: 2 theta' k0 ^ (phi' k ^ rho i_S) = -2 rho theta' phi' i_S
    assert (acc.coriolis + 2 * rho * th.diff() * ph.diff() * S.frame.i).simplify(R0).is_zero
    vel = velocity_composition(S.frame, relative_to=R1, absolute=R0, at=P)
    assert (vel.absolute - S.velocity(P, relative_to=R0)).simplify(R0).is_zero


def test_value_object():
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=Q[0])
    M = R1.point("M", Q[1], 0, 0)
    c = acceleration_composition(M, relative_to=R1, absolute=R0)
    assert c == acceleration_composition(M, relative_to=R1, absolute=R0)
    assert hash(c) == hash(acceleration_composition(M, relative_to=R1, absolute=R0))
    assert c.relative_to is R1 and c.absolute_frame is R0
    assert isinstance(c, Composition) and "coriolis=" in repr(c)
    assert c.subs(Q[1].diff(), 0).coriolis.is_zero
    with pytest.raises(AttributeError):
        c.relative = R0.i


def test_bad_input():
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=Q[0])
    M = R1.point("M", 1, 0, 0)
    with pytest.raises(FrameError, match="same frame tree"):
        velocity_composition(M, relative_to=R1, absolute=rm.Frame("X"))
    with pytest.raises(ArgumentTypeError, match="`at` is needed"):
        acceleration_composition(R1, relative_to=R1, absolute=R0)
    with pytest.raises(ArgumentTypeError, match="`at` is only for a solid"):
        acceleration_composition(M, relative_to=R1, absolute=R0, at=M)
    with pytest.raises(ArgumentTypeError, match="`moving` must be a Point"):
        acceleration_composition(R0.i, relative_to=R1, absolute=R0)
    with pytest.raises(ArgumentTypeError, match="`relative_to` must be a Frame"):
        acceleration_composition(M, relative_to=M, absolute=R0)
