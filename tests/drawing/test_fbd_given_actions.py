"""Given actions on a free-body diagram (book, ch. 11.1-11.2): springs as forces at their
ends, couples as curved (2D) or double (3D) arrows, actions inside the isolated set left out;
limiting_values' bad input.

Two sliders on the floor y = 0 (x1, x2), a spring of stiffness k and free length 0 from the
wall point W = (0, 1) to the first, another from the first to the second: the spring on body
1 from W pulls it by k (W - P1); between the two bodies the spring pulls body 1 towards body 2
by k (P2 - P1) and body 2 back by k (P1 - P2).
"""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.actions import ContactLaws, Coulomb, Couple, Force, Spring
from rigidmech.drawing import external_actions, free_body_diagram, limiting_values
from rigidmech.errors import ArgumentError, ArgumentTypeError


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def two_sliders():
    x1, x2 = rm.coordinates("x1 x2")
    R0 = rm.Frame("R0")
    P1, P2 = R0.point("P1", x1, 0, 0), R0.point("P2", x2, 0, 0)
    b1 = rm.Body("b1", frame=R0.translated("R1", P1), mass=1, centre=P1)
    b2 = rm.Body("b2", frame=R0.translated("R2", P2), mass=1, centre=P2)
    s = rm.System(galilean=R0)
    s.connect(R0, b1, rm.joints.Prismatic(at=P1, axis=R0.i), label="A")
    s.connect(R0, b2, rm.joints.Prismatic(at=P2, axis=R0.i), label="B")
    s.act(Spring(3, 0, a=R0.point("W", 0, 1, 0), b=P1, on_b=b1))
    s.act(Spring(2, 0, a=P1, b=P2, on_a=b1, on_b=b2))
    return s, b1, b2


def test_springs_are_forces_at_their_ends():
    s, b1, b2 = two_sliders()
    acts = external_actions(s, b1, q=[1.0, 3.0])
    springs = [a for a in acts if a.kind == "spring"]
    assert [a.label for a in springs] == ["spring1", "spring2"]
    assert np.allclose(springs[0].force, 3 * np.array([-1.0, 1.0, 0.0]))    # k (W - P1)
    assert np.allclose(springs[1].force, 2 * np.array([2.0, 0.0, 0.0]))     # k (P2 - P1)
    assert all(np.allclose(a.point, [1.0, 0, 0]) for a in springs)


def test_a_spring_inside_the_isolated_set_is_internal():
    s, b1, b2 = two_sliders()
    acts = external_actions(s, [b1, b2], q=[1.0, 3.0])
    assert [a.label for a in acts if a.kind == "spring"] == ["spring"]
    assert [a.label for a in acts if a.kind == "connection"] == ["A", "B"]


def couple_on_a_box(moment):
    R0 = rm.Frame("R0")
    box = rm.Body("box", frame=R0)
    st = rm.statics.Statics(R0)
    st.connect(R0, box, rm.joints.Pivot(at=R0.origin, axis=R0.k), label="O")
    st.act(Couple(on=box, moment=moment(R0)))
    st.act(Force(on=box, vector=-R0.j, at=R0.point("G", 1, 0, 0)))
    return st, box


@pytest.mark.parametrize(("sign", "turn"), [(1, "counterclockwise"), (-1, "clockwise")])
def test_a_couple_is_a_curved_arrow_in_the_plane(sign, turn):
    st, box = couple_on_a_box(lambda R0: sign * 2 * R0.k)
    d = free_body_diagram(st, box)
    assert d.dim == 2
    (name, (arc,)), = [c for c in d.couples if c[0] == "C"]
    xy = arc.get_path().vertices
    (a, b), (c, e) = xy[1] - xy[0], xy[2] - xy[1]
    cross = a * e - b * c
    assert (cross > 0) == (turn == "counterclockwise")
    assert f"C = {sign * 2}" in d.label_texts


def test_a_couple_is_a_double_arrow_in_space():
    st, box = couple_on_a_box(lambda R0: 2 * R0.i)
    d = free_body_diagram(st, box)
    assert d.dim == 3
    (name, arts), = [c for c in d.couples if c[0] == "C"]
    assert len(arts) == 2                         # two heads along the moment


def test_limiting_values_bad_input():
    R0 = rm.Frame("R0")
    block = rm.Body("block", frame=R0)
    P = sp.Symbol("P")
    st = rm.statics.Statics(R0)
    st.connect(R0, block, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
                                      friction=Coulomb(0.3)), label="I")
    st.act(Force(on=block, vector=-10 * R0.j + P * R0.i, at=R0.origin))
    holds = st.limit(P, (0, 2))                   # slides at P = 3: not reached
    with pytest.raises(ArgumentError, match="`limit` must be a limit reached in its interval"):
        limiting_values(st, holds)
    with pytest.raises(ArgumentTypeError, match="`limit` must be a Limit"):
        limiting_values(st, 3.0)
    with pytest.raises(ArgumentTypeError, match="`statics` must be a Statics"):
        limiting_values("statics", holds)
