"""The torsor algebra of ch. 5.1-5.2: identities as property tests, geometry, errors, printing.

Property tests draw rational components (exact arithmetic: every identity must hold exactly,
checked by expanding the components of the difference to zero) in two bases, R0 and R1 rotated
by pi/2 about k0 (the identities must also hold across bases; a quarter turn keeps the
arithmetic rational, hence exact and fast).
"""

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rigidmech import Frame
from rigidmech.torsors import Resolution, Torsor, couple, slider
from rigidmech.vectors import Vector
from rigidmech.vectors.geometry import Line

R0 = Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=sp.pi / 2)
SETTINGS = settings(max_examples=20, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])

rationals = st.fractions(min_value=-5, max_value=5, max_denominator=7).map(sp.Rational)
triples = st.tuples(rationals, rationals, rationals)
frames = st.sampled_from([R0, R1])


@st.composite
def vectors(draw):
    return Vector.from_components(draw(frames), draw(triples))


@st.composite
def points(draw):
    return R0.origin.moved("P", draw(vectors()))


@st.composite
def torsors(draw):
    return Torsor(resultant=draw(vectors()), moment=draw(vectors()), at=draw(points()))


def zero(expr):
    return sp.expand(expr) == 0


def same(u: Vector, v: Vector) -> bool:
    return all(zero(c) for c in (u - v).components(R0))


def same_torsor(T1: Torsor, T2: Torsor, at) -> bool:
    return same(T1.resultant, T2.resultant) and same(T1.moment_at(at), T2.moment_at(at))


def parallel(u: Vector, v: Vector) -> bool:
    return same(u.cross(v), Vector.zero())


# -- identities of ch. 5.1 ------------------------------------------------------------------
@SETTINGS
@given(torsors(), points())
def test_automoment_unchanged_by_transport(T, B):
    assert zero(T.at(B).automoment - T.automoment)


@SETTINGS
@given(torsors(), points())
def test_transport_there_and_back_is_identity(T, B):
    back = T.at(B).at(T.point)
    assert back.point == T.point
    assert same(back.resultant, T.resultant) and same(back.moment, T.moment)


@SETTINGS
@given(torsors(), points(), points())
def test_moment_field_is_the_transport_formula(T, B, C):
    # M(C) = M(B) + CB ^ R (ch. 5.1.2), whatever the point of reduction.
    assert same(T.moment_at(C), T.moment_at(B) + (B - C).cross(T.resultant))


@SETTINGS
@given(torsors(), torsors(), points())
def test_comoment_symmetric_and_point_independent(T1, T2, B):
    c = T1.comoment(T2)
    assert zero(c - T2.comoment(T1))
    assert zero(c - T1.at(B).comoment(T2))
    assert zero(c - T1.at(B).comoment(T2.at(B)))


@SETTINGS
@given(torsors(), torsors(), points())
def test_sum_at_a_common_point_independent_of_the_point(T1, T2, B):
    S = T1 + T2
    assert S.point == T1.point
    assert same_torsor(S, T1.at(B) + T2.at(B), B)
    assert same_torsor(S, T2 + T1, B)
    assert same_torsor(sum([T1, T2]), S, B)
    assert same_torsor(S - T2, T1, B)


@SETTINGS
@given(torsors(), rationals, points())
def test_scalar_multiples(T, k, B):
    assert same((k * T).moment_at(B), k * T.moment_at(B))
    assert same_torsor(T * k, k * T, B)
    assert zero((k * T).automoment - k**2 * T.automoment)
    if k != 0:
        assert same_torsor((k * T) / k, T, B)
    assert same_torsor(-T, (-1) * T, B)


@SETTINGS
@given(torsors(), points())
def test_pitch_unchanged_by_transport(T, B):
    if T.resultant.components(R0) == sp.zeros(3, 1):
        return
    assert zero(T.at(B).pitch - T.pitch)


# -- central axis (ch. 5.1.7) -----------------------------------------------------------------
@SETTINGS
@given(torsors(), points(), rationals)
def test_central_axis_is_where_the_moment_is_parallel_and_least(T, P, lam):
    if T.kind in ("zero", "couple"):
        return
    axis = T.central_axis()
    assert isinstance(axis, Line)
    assert parallel(axis.direction, T.resultant)
    Q = axis.point.moved("Q", lam * axis.direction)  # any point of the axis
    M_Q = T.moment_at(Q)
    assert parallel(M_Q, T.resultant)
    assert same(M_Q, T.moment_at(axis.point))  # the same moment all along the axis
    assert axis.contains(T.central_point(near=P))
    # least norm: |M(P)|^2 = |M(I)|^2 + |IP ^ R|^2 >= |M(I)|^2
    assert sp.nsimplify(T.moment_at(P).dot(T.moment_at(P)) - M_Q.dot(M_Q)) >= 0
    # and M(I) = pitch * R
    assert same(M_Q, T.pitch * T.resultant)


@SETTINGS
@given(torsors(), points(), vectors(), rationals)
def test_moment_about_an_axis_independent_of_its_point(T, P, u, lam):
    if u.components(R0) == sp.zeros(3, 1):
        return
    Q = P.moved("Q", lam * u)
    a = T.moment_about(P, direction=u)
    assert zero(sp.radsimp(a - T.moment_about(Q, direction=3 * u)))
    assert zero(sp.radsimp(a - T.moment_about(Line(Q, u))))
    assert zero(sp.radsimp(a * u.magnitude() - T.moment_at(P).dot(u)))


# -- resolution (ch. 5.2.3-5.2.4) ---------------------------------------------------------------
@SETTINGS
@given(torsors(), points(), points())
def test_slider_plus_couple_reproduces_the_torsor_everywhere(T, B, P):
    s, c = T.resolve(B)
    assert s.point == B and same(s.moment, Vector.zero()) and same(c.resultant, Vector.zero())
    assert same_torsor(s + c, T, P)
    assert same_torsor(T.resolve(B).torsor, T, P)
    if T.kind not in ("zero", "couple"):
        assert same_torsor(T.resolve(Line(B, 2 * T.resultant)).torsor, T, P)


@SETTINGS
@given(torsors(), points())
def test_simplest_form(T, P):
    form = T.simplest_form()
    assert same_torsor(form.torsor, T, P)
    if T.kind in ("zero", "couple"):
        assert same(form.slider.resultant, Vector.zero())
        assert same(form.couple.moment, T.moment)
    else:
        assert T.central_axis().contains(form.slider.point)
        assert parallel(form.couple.moment, T.resultant)
        assert zero(form.couple.moment.dot(T.resultant) - T.automoment)


# -- the same identities with float components, compared with is_close ---------------------------
floats = st.floats(min_value=-10, max_value=10, allow_nan=False, allow_infinity=False)


@st.composite
def float_torsors(draw):
    def vec():
        return Vector.from_components(draw(frames), [draw(floats) for _ in range(3)])

    return Torsor(resultant=vec(), moment=vec(), at=R0.origin.moved("P", vec()))


@SETTINGS
@given(float_torsors(), float_torsors())
def test_float_identities_with_is_close(T, U):
    B = U.point
    # atol: components up to 10 and lever arms up to 20 give moments up to ~1e3; round-off of
    # a few operations stays below 1e-9 in absolute terms
    assert T.at(B).at(T.point).is_close(T, rtol=1e-12, atol=1e-9)
    assert abs(float(T.at(B).automoment - T.automoment)) <= 1e-9
    assert abs(float(T.comoment(U) - U.comoment(T))) <= 1e-9
    assert (T + U).at(B).is_close(T.at(B) + U.at(B), rtol=1e-12, atol=1e-9)
    if T.classify(atol=1e-9) in ("slider", "torsor"):
        assert T.simplest_form().torsor.is_close(T, rtol=1e-9, atol=1e-9)
        M_I = T.moment_at(T.central_point())
        assert M_I.cross(T.resultant).is_close(Vector.zero(), atol=1e-8)


# -- classification --------------------------------------------------------------------------
A = R0.point("A", 1, 2, 3)


@pytest.mark.parametrize(
    ("resultant", "moment", "kind"),
    [
        pytest.param(Vector.zero(), Vector.zero(), "zero", id="zero"),
        pytest.param(Vector.zero(), R0.i, "couple", id="couple"),
        pytest.param(R0.k, R0.i, "slider", id="slider"),
        pytest.param(R0.k, R0.k + R0.i, "torsor", id="torsor"),
        pytest.param(R1.i, R0.k, "slider", id="slider-mixed-bases"),
        pytest.param(R1.i, R0.j, "torsor", id="torsor-mixed-bases"),
    ],
)
def test_kind(resultant, moment, kind):
    T = Torsor(resultant=resultant, moment=moment, at=A)
    assert T.kind == kind
    assert T.classify() == kind
    assert T.at(R0.origin).kind == kind


def test_kind_symbolic_exact_and_undecidable():
    a = sp.Symbol("a")
    b = sp.Symbol("b", positive=True)
    th = sp.Symbol("theta")
    # decided: a component equal to 1 makes the resultant non-zero whatever a is
    assert Torsor(resultant=a * R0.i + R0.j, moment=a * R0.k, at=A).kind == "slider"
    # decided through simplification: sin^2 + cos^2 - 1 = 0
    T = Torsor(resultant=(sp.sin(th) ** 2 + sp.cos(th) ** 2 - 1) * R0.i, moment=b * R0.j,
               at=A)
    assert T.kind == "couple"
    assert Torsor(resultant=b * R0.k, moment=b * R0.k, at=A).kind == "torsor"
    with pytest.raises(ValueError, match="cannot decide whether the resultant is zero"):
        _ = Torsor(resultant=a * R0.i, moment=R0.k, at=A).kind
    with pytest.raises(ValueError, match="cannot decide whether the automoment"):
        _ = Torsor(resultant=R0.i, moment=a * R0.i, at=A).kind


def test_classify_numeric_tolerance():
    T = Torsor(resultant=R0.k * 1.0, moment=R0.i + 1e-13 * R0.k, at=A)
    assert T.kind == "torsor"
    assert T.classify(atol=1e-9) == "slider"
    assert Torsor(resultant=1e-12 * R0.k, moment=R0.i, at=A).classify(atol=1e-9) == "couple"
    assert Torsor(resultant=1e-12 * R0.k, moment=1e-12 * R0.i, at=A).classify(
        atol=1e-9) == "zero"
    with pytest.raises(ValueError, match="`atol` classification needs numeric components"):
        Torsor(resultant=sp.Symbol("a") * R0.k, moment=R0.i, at=A).classify(atol=1e-9)


# -- geometry by hand ------------------------------------------------------------------------
def test_central_axis_by_hand():
    # R = k, M(O) = i + 2k: I = R ^ M / R^2 = k ^ i = j, pitch 2.
    T = Torsor(resultant=R0.k, moment=R0.i + 2 * R0.k, at=R0.origin)
    axis = T.central_axis()
    assert axis.point.coordinates(R0) == sp.Matrix([0, 1, 0])
    assert axis.direction == R0.k
    assert T.pitch == 2
    form = T.simplest_form()
    assert form.couple.moment == 2 * R0.k
    assert form.axis() == axis


def test_moment_about_axis_by_hand():
    # force F = F j at P(a, 0, 0): moment about the z axis through O is a F.
    a, F = sp.symbols("a F", positive=True)
    T = slider(F * R0.j, R0.point("P", a, 0, 0))
    assert T.moment_about(R0.origin, direction=R0.k) == a * F
    assert T.moment_about(Line(R0.point("Q", 0, 0, 5), -2 * R0.k)) == -a * F


def test_slider_and_couple_constructors():
    s = slider(R0.i, R0.point("B", 0, 1, 0))
    assert s.kind == "slider"
    assert s.moment_at(R0.origin) == -R0.k
    c = couple(R0.k)
    assert c.kind == "couple" and c.point == R0.origin
    assert c.moment_at(A) == R0.k
    with pytest.raises(ValueError, match="`at` is needed for a zero couple"):
        couple(Vector.zero())


# -- errors ----------------------------------------------------------------------------------
def test_vector_where_point_expected():
    with pytest.raises(TypeError, match=r"`at` must be a Point \(a Vector is not a Point"):
        Torsor(resultant=R0.i, moment=R0.j, at=R0.i)
    T = Torsor(resultant=R0.i, moment=R0.j, at=A)
    with pytest.raises(TypeError, match="`point` must be a Point"):
        T.at(R0.k)
    with pytest.raises(TypeError, match="`point` must be a Point"):
        T.moment_at(R0.k)
    with pytest.raises(TypeError, match="`axis` must be a Line or a Point"):
        T.moment_about(R0.k)
    with pytest.raises(TypeError, match="`through` must be a Point or a Line"):
        T.resolve(R0.k)
    with pytest.raises(TypeError, match="`through` must be a Point"):
        slider(R0.i, through=R0.j)


def test_point_where_vector_expected():
    with pytest.raises(TypeError, match="`resultant` must be a Vector; got the Point A"):
        Torsor(resultant=A, moment=R0.j, at=A)
    with pytest.raises(TypeError, match="`moment` must be a Vector; got the Point A"):
        Torsor(resultant=R0.i, moment=A, at=R0.origin)
    with pytest.raises(TypeError, match="`direction` must be a Vector"):
        Torsor(resultant=R0.i, moment=R0.j, at=A).moment_about(A, direction=A)
    with pytest.raises(TypeError, match="`resultant` must be a Vector; got the Point A"):
        slider(A, through=A)


def test_torsor_times_torsor_and_other_misuse():
    T = Torsor(resultant=R0.i, moment=R0.j, at=A)
    with pytest.raises(TypeError, match="a torsor is multiplied by scalars only; use comoment"):
        T * T
    with pytest.raises(TypeError, match="a torsor is multiplied by scalars only"):
        T * R0.i
    with pytest.raises(TypeError, match="a Torsor can only be added to a Torsor; got Vector"):
        T + R0.i
    with pytest.raises(ValueError, match="`scalar` must be non-zero to divide a torsor"):
        T / 0
    with pytest.raises(TypeError, match="`other` must be a Torsor; got Vector"):
        T.comoment(R0.i)


def test_geometry_errors():
    C = couple(R0.k, at=A)
    with pytest.raises(ValueError, match="zero resultant .* has no central axis"):
        C.central_axis()
    with pytest.raises(ValueError, match="zero resultant .* has no central axis"):
        Torsor.zero(A).central_axis()
    with pytest.raises(ValueError, match="zero resultant .* has no pitch"):
        _ = C.pitch
    with pytest.raises(ValueError, match="has no slider line"):
        C.simplest_form().axis()
    T = Torsor(resultant=R0.i, moment=R0.j, at=A)
    with pytest.raises(ValueError, match="`direction` is needed when `axis` is the Point A"):
        T.moment_about(A)
    with pytest.raises(ValueError, match="`direction` must be omitted when `axis` is a Line"):
        T.moment_about(Line(A, R0.k), direction=R0.k)
    with pytest.raises(ValueError, match="`direction` must be a non-zero Vector"):
        T.moment_about(A, direction=Vector.zero())
    with pytest.raises(ValueError, match="`through` must be a line parallel to the resultant"):
        T.resolve(Line(A, R0.j))
    with pytest.raises(TypeError, match="`slider` must be a Torsor; got Vector"):
        Resolution(R0.i, T)
    with pytest.raises(ValueError, match="`slider` must have a zero moment"):
        Resolution(T, couple(R0.k, at=A))
    with pytest.raises(ValueError, match="`couple` must have a zero resultant"):
        Resolution(slider(R0.i, A), T)


# -- equality, printing ----------------------------------------------------------------------
def test_equality_and_hash():
    T = Torsor(resultant=R0.k, moment=R0.i, at=A)
    same_T = Torsor(resultant=R0.k, moment=R0.i, at=R0.point("A", 1, 2, 3))
    assert T == same_T and hash(T) == hash(same_T)
    moved = T.at(R0.origin)
    assert moved != T  # == is structural
    assert moved.equals(T) and moved.is_close(T)
    assert T.resolve(A) == T.resolve(A) and hash(T.resolve(A)) == hash(T.resolve(A))


def test_repr_str_latex():
    T = Torsor(resultant=R0.k, moment=2 * R0.i - R0.j, at=A)
    assert repr(T) == "Torsor(resultant=R0.k, moment=2*R0.i - R0.j, at=A)"
    assert str(T) == "{k_R0 ; 2 i_R0 - j_R0}_A"
    expected = (r"\left\{ \begin{matrix} \vec{k}_{R_{0}} \\ 2 \vec{i}_{R_{0}} - "
                r"\vec{j}_{R_{0}} \end{matrix} \right\}_{A}")
    assert sp.latex(T) == expected
    assert T._repr_latex_() == f"$\\displaystyle {expected}$"
    assert sp.pretty(T) == ("\u23a7 k_R0          \u23ab \n"
                            "\u23a8               \u23ac \n"
                            "\u23a9 2 i_R0 - j_R0 \u23adA")
    assert sp.pretty(T, use_unicode=False) == str(T)
    form = T.resolve(A)
    assert repr(form) == ("Resolution(slider=Torsor(resultant=R0.k, moment=0, at=A), "
                          "couple=Torsor(resultant=0, moment=2*R0.i - R0.j, at=A))")
    assert str(form) == "{k_R0 ; 0}_A + {0 ; 2 i_R0 - j_R0}_A"
    assert sp.latex(form).count(r"\begin{matrix}") == 2
    assert form._repr_latex_().startswith("$\\displaystyle")


def test_latex_symbolic_components():
    a = sp.Symbol("alpha")
    T = Torsor(resultant=a * R0.k, moment=Vector.zero(), at=A)
    assert sp.latex(T) == (r"\left\{ \begin{matrix} \alpha \vec{k}_{R_{0}} \\ 0 "
                           r"\end{matrix} \right\}_{A}")
