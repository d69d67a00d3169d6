"""Spring and Damper handle their two ends the same way (book, ch. 11.2, 21.3.1): the same
checks of the points and solids, the same handles, and equal and opposite forces along AB,
on b and on a (an end on the ground, None, gets none). The forces by hand: a spring of free
length 0 pulls b by -k AB; a damper pushes b by -c (AB . AB') AB / |AB|^2."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.actions import Damper, Spring
from rigidmech.errors import ArgumentError, ArgumentTypeError

x, y = rm.coordinates("x y")
R0 = rm.Frame("R0")
R1 = R0.translated("R1", R0.point("P", x, y, 0))
A, P = R0.point("A", -1, 0, 0), R1.origin
S = rm.Body("S", frame=R1, mass=1)
MAKERS = {"spring": lambda **kw: Spring(3, 0, **kw), "damper": lambda **kw: Damper(3, **kw)}


@pytest.mark.parametrize("kind", list(MAKERS))
def test_the_same_checks_of_the_ends(kind):
    make = MAKERS[kind]
    with pytest.raises(ArgumentError, match=rf"`on_a` and `on_b` cannot both be None: the "
                                            rf"{kind} would act on nothing\."):
        make(a=A, b=P)
    with pytest.raises(ArgumentTypeError, match=r"`on_b` must be a Body; got Frame\."):
        make(a=A, b=P, on_b=R0)
    with pytest.raises(ArgumentTypeError, match=r"`a`"):
        make(a="A", b=P, on_b=S)


@pytest.mark.parametrize("kind", list(MAKERS))
def test_the_same_handles(kind):
    action = MAKERS[kind](a=A, b=P, on_b=S)
    assert action.a is A and action.b is P and action.on_a is None and action.on_b is S
    assert action.ends == (A, P)


@pytest.mark.parametrize("kind", list(MAKERS))
def test_equal_and_opposite_forces_along_ab(kind):
    T = rm.Body("T", frame=R0.translated("R2", A), mass=1)
    action = MAKERS[kind](a=A, b=P, on_a=T, on_b=S)
    (on_b, Fb), (on_a, Fa) = action.contributions([T, S])
    assert on_b is S and on_a is T and Fb.point is P and Fa.point is A
    ab = sp.Matrix([x + 1, y, 0])
    rate = (x + 1) * x.diff(rm.t) + y * y.diff(rm.t)
    expected = -3 * ab if kind == "spring" else -3 * rate / (ab.dot(ab)) * ab
    assert sp.simplify(Fb.resultant.components(R0) - expected) == sp.zeros(3, 1)
    assert sp.simplify(Fa.resultant.components(R0) + expected) == sp.zeros(3, 1)
    one_end = MAKERS[kind](a=A, b=P, on_b=S).contributions([S])
    assert [s for s, _ in one_end] == [S]
