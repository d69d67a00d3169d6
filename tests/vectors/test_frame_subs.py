"""Substitution reaches the frames a value depends on (ARCHITECTURE principle 6): Frame.subs,
and Point.subs, Vector.subs, Torsor.subs substitute in the angles and origins of the frames
they use, so that a substituted value no longer depends on the symbol.

Expected values are the book's elementary basis change (ch. 2.5.2): R1 turned by q about k0
has i1 = cos q i0 + sin q j0.
"""

import sympy as sp

import rigidmech as rm


def _free(value):
    """The coordinates q(t) and symbols a value of the frame tree still depends on."""
    return {a for a in sp.sympify(value).atoms(sp.Symbol, sp.core.function.AppliedUndef)}


def setup():
    q, x = rm.coordinates("q x")
    a = sp.Symbol("a")
    R0 = rm.Frame("R0")
    O1 = R0.point("O1", x, a, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=q, origin=O1)
    R2 = R1.rotated("R2", about=R1.i, angle=2 * q)
    return q, x, a, R0, R1, R2


def test_frame_subs_substitutes_angle_origin_and_ancestors():
    q, x, a, R0, R1, R2 = setup()
    S2 = R2.subs({q: sp.Rational(1, 3), x: 2, a: 5})
    assert S2.name == "R2" and S2.parent.name == "R1"
    assert S2.angle == sp.Rational(2, 3) and S2.parent.angle == sp.Rational(1, 3)
    assert S2.origin.coordinates(R0) == sp.Matrix([2, 5, 0])
    assert S2.dcm(R0).free_symbols == set()
    assert S2.dcm(R0) == R2.dcm(R0).subs(q, sp.Rational(1, 3))
    assert R0.subs(q, 1) is R0                       # a root has nothing to substitute
    assert R2.subs(sp.Symbol("other"), 1) is R2      # nothing changes: the same frame


def test_vector_subs_reaches_its_bases():
    q, x, a, R0, R1, R2 = setup()
    v = R1.i.subs(q, 0.25)
    assert not _free(v.components(R0))
    assert v.components(R0) == sp.Matrix([sp.cos(0.25), sp.sin(0.25), 0])
    w = (a * R2.k + x * R0.i).subs({q: 0, a: 1})
    assert w.components(R0) == sp.Matrix([x, 0, 1])


def test_point_subs_reaches_the_origins():
    q, x, a, R0, R1, R2 = setup()
    P = R2.origin.moved("P", R2.i)
    Ps = P.subs({q: 0, x: 1, a: 2})
    assert Ps.coordinates(R0) == sp.Matrix([2, 2, 0])
    assert Ps.name == "P"


def test_torsor_subs_reaches_the_frames():
    q, x, a, R0, R1, R2 = setup()
    T = rm.Torsor(resultant=R1.i, moment=a * R2.j, at=R2.origin)
    Ts = T.subs({q: 0, x: 3, a: 1})
    assert Ts.resultant.components(R0) == sp.Matrix([1, 0, 0])
    assert Ts.moment.components(R0) == sp.Matrix([0, 1, 0])
    assert Ts.point.coordinates(R0) == sp.Matrix([3, 1, 0])


# --- printing that does not mislead: a frame fixed at an instant is shown as such -----------

def test_vector_substituted_at_an_instant_does_not_print_as_the_moving_frame():
    """(2 R1.i).subs(theta, 0): R1 fixed at theta = 0 is not the moving R1 (its derivative is
    zero): repr and str show the substitution; the moving R1 still prints as R1."""
    th = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    v = (2 * R1.i).subs(th, 0)
    assert repr(v) == "2*R1[theta=0].i"
    assert str(v) == "2 i_R1[theta=0]"
    assert v.dt(R0) == rm.Vector.zero() and (2 * R1.i).dt(R0) != rm.Vector.zero()
    assert repr(v + R1.j) == "2*R1[theta=0].i + R1.j"
    assert repr(2 * R1.i) == "2*R1.i"
    F = R1.subs(th, sp.pi / 2)
    assert str(F) == "R1[theta=pi/2]" and F.name == "R1"          # the name is kept
    assert F.label == "R1[theta=pi/2]" and R1.label == "R1"
    assert "R1[theta=pi/2]" in repr(F)


def test_substitution_label_shows_what_reaches_each_frame():
    """A child of a substituted frame is substituted too; each frame's label lists the values
    that reach it (its angle, origin, ancestors), a rate q' as q'; a symbol not in the frame
    does not appear."""
    q, x, a, R0, R1, R2 = setup()
    S2 = R2.subs({q: sp.Rational(1, 3), a: 5})
    assert S2.label == "R2[a=5, q=1/3]" and S2.parent.label == "R1[a=5, q=1/3]"
    assert repr(R2.k.subs(q, 0)) == "R2[q=0].k"
    b = sp.Symbol("b")
    assert (b * R1.i).subs({b: 2, q: 1}).__repr__() == "2*R1[q=1].i"
    w = sp.Symbol("w")
    R3 = R0.rotated("R3", about=R0.k, angle=w * q.diff(rm.t))
    assert R3.subs(q.diff(rm.t), 2).label == "R3[q'=2]"
    # the LaTeX form shows it too
    assert "[" not in R1.i._repr_latex_()
    assert "q=0" in (R1.i.subs(q, 0))._repr_latex_()
