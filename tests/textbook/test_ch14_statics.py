"""Book ch. 14: statics of rigid bodies (ch. 14.2, 14.4), with the laws of contact (ch. 13.1).

Conventions of these exercises: R0 = (O; i, j, k) is the ground, i horizontal, j pointing
**up**, the problems are planar in (i, j). Joints carry their 3-D unknowns (a pivot about k has
X, Y, Z, L, M), so the out-of-plane unknowns of several pivots are reported as undetermined
(hyperstatic out of the plane), as the book's count of unknowns does (ch. 13.2).

The expected values are closed forms derived by hand in the comment of each case: the three
equations of a plane problem (forces along i and j, moment about k at a convenient point).
"""

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidmech as rm
from rigidmech.actions import ContactLaws, Coulomb, Couple, Force, Pivot, Spherical, gravity
from rigidmech.statics import EquilibriumError, Statics, limiting_equilibrium
from rigidmech.torsors import Domain


def S(name):
    return sp.Symbol(name, real=True)


def simplify_zero(e):
    return sp.simplify(e) == 0


# -- beam on a pivot and a roller -----------------------------------------------------------
def beam(L, c, F, q, numeric=False):
    R0 = rm.Frame("R0")
    A, B = R0.origin, R0.point("B", L, 0, 0)
    bar = rm.Body("beam", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, bar, Pivot(at=A, axis=R0.k), label="A")
    st_.connect(R0, bar, ContactLaws(at=B, normal=R0.j), label="B")
    st_.act(Force(on=bar, vector=-F * R0.j, at=R0.point("C", c, 0, 0)))
    x = sp.Symbol("x", real=True)
    st_.distributed_load(bar, -q * R0.j, Domain(R0, x * R0.i, (x, 0, L)))
    return st_, bar


def test_ch14_beam_on_pivot_and_roller_point_and_distributed_loads():
    # moment about A: N_B L = F c + q L^2/2; forces along j: Y_A + N_B = F + q L; along i: X_A = 0
    L, c, F, q = rm.constants("L c F q", positive=True)
    st_, bar = beam(L, c, F, q)
    eq = st_.solve()
    v = eq.values
    assert simplify_zero(v[S("N_B")] - (F * c / L + q * L / 2))
    assert simplify_zero(v[S("Y_A")] - (F * (L - c) / L + q * L / 2))
    assert v[S("X_A")] == 0 and v[S("Z_A")] == 0 and v[S("L_A")] == 0 and v[S("M_A")] == 0
    assert eq.hyperstaticity == 0 and eq.undetermined == () and not eq.is_mechanism
    # symbolic zero: the sum of the action torsors on the beam vanishes
    R = eq.residual(bar)
    assert R.resultant.simplify().is_zero and R.moment.simplify().is_zero


@settings(max_examples=25, deadline=None)
@given(L=st.floats(0.5, 20), c_ratio=st.floats(0, 1), F=st.floats(0, 1e4), q=st.floats(0, 1e3))
def test_beam_equilibrium_residual_is_zero_numerically(L, c_ratio, F, q):
    # at the numeric solution, the sum of every action torsor on the beam is zero to 1e-12
    # relative to the loads
    st_, bar = beam(L, c_ratio * L, F, q)
    eq = st_.solve()
    R = eq.residual(bar)
    scale = max(F + q * L, 1.0) * max(L, 1.0)
    comps = [float(x) for x in list(R.resultant.components(st_.reference))
             + list(R.moment.components(st_.reference))]
    assert max(abs(x) for x in comps) <= 1e-12 * scale
    assert math.isclose(float(eq.values[S("N_B")]), F * c_ratio + q * L / 2, rel_tol=1e-12,
                        abs_tol=1e-12 * scale)


# -- three-hinged arch: two bodies --------------------------------------------------------
def test_ch14_three_hinged_arch_two_bodies():
    # bars AC and CB, pivots at A(0,0), B(2a,0) on the ground and at C(a,h) between them, load
    # F down at C on bar 1. Symmetry and moments about C for bar 2: vertical reactions F/2,
    # horizontal thrust F a / (2 h) (bar 2 pushes outward on its foot, the ground inward).
    a, h, F = rm.constants("a h F", positive=True)
    R0 = rm.Frame("R0")
    A, B, C = R0.origin, R0.point("B", 2 * a, 0, 0), R0.point("C", a, h, 0)
    bar1, bar2 = rm.Body("bar1", frame=R0), rm.Body("bar2", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, bar1, Pivot(at=A, axis=R0.k), label="A")
    st_.connect(R0, bar2, Pivot(at=B, axis=R0.k), label="B")
    st_.connect(bar1, bar2, Pivot(at=C, axis=R0.k), label="C")
    st_.act(Force(on=bar1, vector=-F * R0.j, at=C))
    eq = st_.solve()
    v = eq.values
    assert simplify_zero(v[S("Y_A")] - F / 2) and simplify_zero(v[S("Y_B")] - F / 2)
    assert simplify_zero(v[S("X_A")] - F * a / (2 * h))
    assert simplify_zero(v[S("X_B")] + F * a / (2 * h))
    # in plane: 6 unknowns, 6 equations; out of the plane 9 unknowns (Z, L, M of each pivot)
    # for 6 equations: hyperstatic of degree 3, the out-of-plane unknowns undetermined
    assert eq.hyperstaticity == 3
    assert set(eq.undetermined) <= {S(f"{n}_{p}") for n in "ZLM" for p in "ABC"}
    assert all(simplify_zero(x) for b in (bar1, bar2)
               for x in list(eq.residual(b).resultant.components(R0))
               + list(eq.residual(b).moment.components(R0)))


# -- shaft in two bearings under belt tension --------------------------------------------
def test_ch14_shaft_in_two_ball_bearings_under_belt_tension():
    # shaft along k on ball bearings (spherical joints) at A (z=0) and B (z=d); pulley of
    # radius r at z=e, belt strands pulling along i with T1 at (0, r, e) and T2 at (0, -r, e);
    # motor couple C k. Moments about k: C = r (T1 - T2); about j at A: e (T1+T2) + d X_B = 0;
    # along i: X_A + X_B + T1 + T2 = 0. Axial components Z_A, Z_B: only Z_A + Z_B = 0 is known,
    # hyperstatic of degree 1 (ch. 13.2, 14.2).
    d, e, r, T1, T2 = rm.constants("d e r T1 T2", positive=True)
    C = S("C")
    R0 = rm.Frame("R0")
    shaft = rm.Body("shaft", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, shaft, Spherical(at=R0.origin, axis=R0.k), label="A")
    st_.connect(R0, shaft, Spherical(at=R0.point("B", 0, 0, d), axis=R0.k), label="B")
    st_.act(Force(on=shaft, vector=T1 * R0.i, at=R0.point("P1", 0, r, e)))
    st_.act(Force(on=shaft, vector=T2 * R0.i, at=R0.point("P2", 0, -r, e)))
    st_.act(Couple(on=shaft, moment=C * R0.k))
    eq = st_.solve(unknowns=[C])
    v = eq.values
    assert simplify_zero(v[C] - r * (T1 - T2))
    assert simplify_zero(v[S("X_B")] + e * (T1 + T2) / d)
    assert simplify_zero(v[S("X_A")] + (T1 + T2) * (1 - e / d))
    assert v[S("Y_A")] == 0 and v[S("Y_B")] == 0
    assert eq.hyperstaticity == 1 and set(eq.undetermined) == {S("Z_A"), S("Z_B")}
    assert "hyperstatic of degree 1" in str(eq)


# -- mechanisms and no equilibrium --------------------------------------------------------
def lever():
    a, b, F, P = rm.constants("a b F P", positive=True)
    R0 = rm.Frame("R0")
    bar = rm.Body("lever", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, bar, Pivot(at=R0.origin, axis=R0.k), label="O")
    st_.act(Force(on=bar, vector=-F * R0.j, at=R0.point("A", a, 0, 0)))
    st_.act(Force(on=bar, vector=-P * R0.j, at=R0.point("B", -b, 0, 0)))
    return st_, (a, b, F, P)


def test_ch14_lever_is_a_mechanism_the_condition_and_the_holding_load():
    st_, (a, b, F, P) = lever()
    eq = st_.solve()
    assert eq.is_mechanism and len(eq.conditions) == 1
    (name, cond), = eq.conditions
    assert "moment about k" in name and simplify_zero(cond / (a * F - b * P) - 1) or \
        simplify_zero(cond / (a * F - b * P) + 1)
    held = st_.solve(unknowns=[P])                 # the load P that holds it: P = F a / b
    assert simplify_zero(held.values[P] - F * a / b) and not held.is_mechanism


def test_ch14_no_equilibrium_is_a_clear_error():
    st_, (a, b, F, P) = lever()
    with pytest.raises(EquilibriumError, match=r"no equilibrium.*lever: moment about k"):
        st_.solve(values={a: 1.0, b: 1.0, F: 10.0, P: 3.0})
    with pytest.raises(EquilibriumError, match=r"no equilibrium.*lever: moment about k"):
        st_.solve(values={a: 1, b: 1, F: 10, P: 3}, method="symbolic")


# -- friction: block on an incline, ladder, box ----------------------------------------------
def incline(alpha, f, m=2.0, g=9.81):
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=alpha)        # R1.i up the slope, R1.j normal
    block = rm.Body("block", frame=R1, mass=m, centre=R1.origin.moved("G", 0.1 * R1.j))
    st_ = Statics(R0)
    # a flat base of half-width 0.5 (the weight does not pass through I once tilted): it
    # would tip only at tan(alpha) = 0.5 / 0.1, far beyond sliding
    contact = ContactLaws(at=R1.origin, normal=R1.j, tangent=R1.i, friction=Coulomb(f),
                      footprint=0.5, rolling_axis=R0.k)
    st_.connect(R0, block, contact, label="I")
    st_.act(gravity(-g * R0.j))
    return st_, contact


@pytest.mark.parametrize("alpha, f, at_rest", [
    pytest.param(0.3, 0.4, True, id="tan0.3<0.4-at-rest"),
    pytest.param(0.45, 0.4, False, id="tan0.45>0.4-slides"),
])
def test_ch14_block_on_an_incline_at_rest_or_sliding(alpha, f, at_rest):
    # N = m g cos(alpha), T = m g sin(alpha) (up the slope); at rest iff tan(alpha) <= f_s
    # (the resultant in the friction cone, ch. 13.1.2)
    st_, contact = incline(alpha, f)
    eq = st_.solve()
    N, T = eq.values[S("N_I")], eq.values[S("T_I")]
    assert math.isclose(N, 2.0 * 9.81 * math.cos(alpha), rel_tol=1e-12)
    assert math.isclose(T, 2.0 * 9.81 * math.sin(alpha), rel_tol=1e-12)
    torsor, _ = contact.action_torsor("I")
    action = torsor.subs(eq.values)
    assert contact.friction.in_cone(action, contact.normal) is at_rest
    assert (math.tan(alpha) <= f) is at_rest


def test_ch14_block_on_an_incline_limit_angle_is_arctan_f():
    alpha = sp.Symbol("alpha", real=True)
    st_, _ = incline(alpha, 0.4)
    lim = limiting_equilibrium(st_, alpha, (0.0, 1.5))
    # LP tolerance 1e-10 on scaled data: 1e-9 relative on the angle
    assert math.isclose(lim.value, math.atan(0.4), rel_tol=1e-9)
    assert lim.kinds == ("sliding",) and lim.contacts == ("I",)


@pytest.mark.parametrize("fA, fB", [
    pytest.param(0.3, 0.2, id="fA0.3-fB0.2"),
    pytest.param(0.5, 0.0, id="smooth-wall"),
    pytest.param(0.25, 0.6, id="fA0.25-fB0.6"),
])
def test_ch14_ladder_against_a_wall_limit_angle(fA, fB):
    # uniform ladder AB, length l, weight W, foot A on the floor (f_A), top B on the wall (f_B),
    # angle theta with the floor. At the limit both ends slide: T_A = f_A N_A, T_B = f_B N_B;
    # forces: N_B = f_A N_A, N_A + f_B N_B = W; moments about A: N_B l sin + f_B N_B l cos =
    # W l/2 cos  =>  tan(theta*) = (1 - f_A f_B) / (2 f_A)  (classical, e.g. ch. 14.4).
    theta = sp.Symbol("theta", real=True)
    l, W = 3.0, 50.0
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=theta)
    A = R0.origin
    B = A.moved("B", l * R1.i)
    ladder = rm.Body("ladder", frame=R1)
    st_ = Statics(R0)
    st_.connect(R0, ladder, ContactLaws(at=A, normal=R0.j, tangent=R0.i, friction=Coulomb(fA)),
                label="A")
    st_.connect(R0, ladder, ContactLaws(at=B, normal=-R0.i, tangent=R0.j, friction=Coulomb(fB)),
                label="B")
    st_.act(Force(on=ladder, vector=-W * R0.j, at=A.moved("G", l / 2 * R1.i)))
    eq = st_.solve(values={theta: 1.3})
    # 4 unknowns for 3 equations of the plane (3 with a smooth wall: no T_B)
    assert eq.hyperstaticity == (1 if fB > 0 else 0)
    lim = limiting_equilibrium(st_, theta, (math.pi / 2 - 1e-3, 0.05))
    assert math.isclose(lim.value, math.atan((1 - fA * fB) / (2 * fA)), rel_tol=1e-9)
    assert lim.kinds == ("sliding",)
    assert lim.contacts == (("A", "B") if fB > 0 else ("A",))


@pytest.mark.parametrize("f, h, first, expected", [
    # box of weight W = 10, base half-width a = 0.5, pushed horizontally at height h:
    # slides at P = f W, tips about the front edge at P = W a / h (moments about the edge)
    pytest.param(0.4, 1.0, "sliding", 4.0, id="slides-first"),
    pytest.param(0.6, 1.0, "tipping", 5.0, id="tips-first"),
    pytest.param(0.4, 2.0, "tipping", 2.5, id="high-push-tips"),
])
def test_ch14_box_pushed_on_a_floor_slides_or_tips(f, h, first, expected):
    P = sp.Symbol("P", real=True)
    R0 = rm.Frame("R0")
    box = rm.Body("box", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
                                 friction=Coulomb(f), footprint=0.5, rolling_axis=R0.k),
                label="floor")
    st_.act(Force(on=box, vector=-10.0 * R0.j, at=R0.point("G", 0, 0.5, 0)))
    st_.act(Force(on=box, vector=P * R0.i, at=R0.point("H", -0.5, h, 0)))
    lim = limiting_equilibrium(st_, P, (0.0, 20.0))
    assert lim.kinds == (first,)
    assert math.isclose(lim.value, expected, rel_tol=1e-9)
    assert math.isclose(lim.by_kind["sliding"], f * 10.0, rel_tol=1e-9)
    assert math.isclose(lim.by_kind["tipping"], 10.0 * 0.5 / h, rel_tol=1e-9)
    assert first in str(lim)



def test_each_kind_scans_only_beyond_where_all_the_laws_hold(monkeypatch):
    # a subset of the laws has a margin at least that of all the laws (fewer inequalities in
    # the same linear program): where all of them hold, each kind's scan need not solve again.
    # Box of weight 10, f = 0.4, pushed at h = 1 over (0, 10) in 200 intervals: all the laws
    # break at P = 4 (80 intervals); then sliding (at 4), tipping (at 5, 20 intervals further)
    # and lift-off (never: to the end, 120 intervals) each scan on from there. The scan from
    # P = 0 for each kind solved 471 programs; from the known points, 231.
    import rigidmech.statics.limits as limits

    solved = []
    lp = limits._lp_margin
    monkeypatch.setattr(limits, "_lp_margin", lambda *a, **k: solved.append(1) or lp(*a, **k))
    P = sp.Symbol("P", real=True)
    R0 = rm.Frame("R0")
    box = rm.Body("box", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
                                     friction=Coulomb(0.4), footprint=0.5, rolling_axis=R0.k),
                label="floor")
    st_.act(Force(on=box, vector=-10.0 * R0.j, at=R0.point("G", 0, 0.5, 0)))
    st_.act(Force(on=box, vector=P * R0.i, at=R0.point("H", -0.5, 1.0, 0)))
    lim = limiting_equilibrium(st_, P, (0.0, 10.0), samples=200)
    assert lim.kinds == ("sliding",) and math.isclose(lim.value, 4.0, rel_tol=1e-9)
    assert math.isclose(lim.by_kind["sliding"], 4.0, rel_tol=1e-9)
    assert math.isclose(lim.by_kind["tipping"], 5.0, rel_tol=1e-9)
    assert lim.by_kind["lift-off"] is None
    assert len(solved) < 81 + 1 + 20 + 120 + 40   # the scans above, 40 for the root findings

def test_limit_bad_input():
    alpha = sp.Symbol("alpha", real=True)
    st_, _ = incline(alpha, 0.4)
    with pytest.raises(EquilibriumError, match=r"no equilibrium at the start of `interval`"):
        limiting_equilibrium(st_, alpha, (0.6, 1.0))
    st2, _ = incline(alpha, sp.Symbol("f", positive=True))
    with pytest.raises(ValueError, match=r"`values` must give numbers for \[f\]"):
        limiting_equilibrium(st2, alpha, (0.0, 1.0))


def test_statics_bad_input():
    R0 = rm.Frame("R0")
    st_ = Statics(R0)
    bar = rm.Body("bar", frame=R0)
    with pytest.raises(TypeError, match=r"`connection` must have an action_torsor"):
        st_.connect(R0, bar, "pivot")
    st_.connect(R0, bar, Pivot(at=R0.origin, axis=R0.k), label="O")
    with pytest.raises(ValueError, match=r"`label` must be unique"):
        st_.connect(R0, bar, Pivot(at=R0.origin, axis=R0.k), label="O")
    with pytest.raises(TypeError, match=r"`action` must be an Action"):
        st_.act(rm.slider(R0.i, R0.origin))
    with pytest.raises(ValueError, match=r"`method` must be"):
        st_.solve(method="magic")


def test_numeric_and_symbolic_routes_agree_on_the_beam():
    L, c, F, q = rm.constants("L c F q", positive=True)
    st_, _ = beam(L, c, F, q)
    vals = {L: 4.0, c: 1.0, F: 100.0, q: 20.0}
    num = st_.solve(values=vals)
    sym = st_.solve()
    for x, v in num.values.items():
        assert math.isclose(v, float(sym.values[x].subs(vals)), rel_tol=1e-12, abs_tol=1e-12)
    np.testing.assert_allclose(num.values[S("N_B")], 100 * 1 / 4 + 20 * 4 / 2, rtol=1e-12)


def test_limit_that_is_not_reached_in_the_interval():
    # the box of the cases above is pushed at most by P = 3 < f W = 4 < W a / h = 5
    P = sp.Symbol("P", real=True)
    R0 = rm.Frame("R0")
    box = rm.Body("box", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
                                 friction=Coulomb(0.4), footprint=0.5, rolling_axis=R0.k),
                label="floor")
    st_.act(Force(on=box, vector=-10.0 * R0.j, at=R0.point("G", 0, 0.5, 0)))
    st_.act(Force(on=box, vector=P * R0.i, at=R0.point("H", -0.5, 1.0, 0)))
    lim = limiting_equilibrium(st_, P, (0.0, 3.0), samples=20)
    assert lim.value is None and lim.kinds == ()
    assert lim.by_kind == {"sliding": None, "tipping": None, "lift-off": None}
    assert str(lim) == "the equilibrium holds for every P of the interval"


@pytest.mark.parametrize("f_floor, f_top, contact, expected", [
    # block 1 (W1 = 30) on the floor, block 2 (W2 = 10) on block 1, P pulls block 2
    # horizontally: block 2 slides on block 1 at P = f_top W2, the pair slides on the floor at
    # P = f_floor (W1 + W2), whichever is smaller (ch. 14.4.2, two bodies)
    pytest.param(0.3, 0.5, "top", 5.0, id="top-block-slides"),
    pytest.param(0.1, 0.5, "floor", 4.0, id="both-slide-on-the-floor"),
])
def test_ch14_two_stacked_blocks_which_interface_slides(f_floor, f_top, contact, expected):
    P = sp.Symbol("P", real=True)
    R0 = rm.Frame("R0")
    b1, b2 = rm.Body("block1", frame=R0), rm.Body("block2", frame=R0)
    st_ = Statics(R0)
    # wide bases (half-width 10): no tipping in the range searched
    st_.connect(R0, b1, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
                                friction=Coulomb(f_floor), footprint=10, rolling_axis=R0.k),
                label="floor")
    st_.connect(b1, b2, ContactLaws(at=R0.point("I", 0, 1, 0), normal=R0.j, tangent=R0.i,
                                friction=Coulomb(f_top), footprint=10, rolling_axis=R0.k),
                label="top")
    st_.act(Force(on=b1, vector=-30.0 * R0.j, at=R0.point("G1", 0, 0.5, 0)))
    st_.act(Force(on=b2, vector=-10.0 * R0.j, at=R0.point("G2", 0, 1.5, 0)))
    st_.act(Force(on=b2, vector=P * R0.i, at=R0.point("H", 0, 1.5, 0)))
    eq = st_.solve(values={P: 1.0})
    assert eq.hyperstaticity == 0 and len(st_.bodies) == 2
    lim = limiting_equilibrium(st_, P, (0.0, 20.0))
    assert lim.kinds == ("sliding",) and lim.contacts == (contact,)
    assert math.isclose(lim.value, expected, rel_tol=1e-9)


def test_values_must_respect_what_the_symbols_declare():
    """W declared positive: a negative weight given as a number is refused where it enters."""
    from rigidmech._core.errors import ArgumentError as _ArgumentError

    R0 = rm.Frame("R0")
    box = rm.Body("box", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
                                     friction=Coulomb(0.5)), label="A")
    W = rm.constants("W", positive=True)
    P = sp.Symbol("P", real=True)
    st_.act(Force(on=box, vector=-W * R0.j + P * R0.i, at=R0.origin))
    with pytest.raises(_ArgumentError, match=r"the value of `W` must be > 0"):
        st_.solve(values={W: -2, P: 0})
    with pytest.raises(_ArgumentError, match=r"the value of `W` must be > 0"):
        limiting_equilibrium(st_, P, (0.0, 10.0), values={W: -2})
    assert st_.solve(values={W: 2, P: 0}).values[sp.Symbol("N_A", real=True)] == 2.0


def _wedge(delta):
    """A weight W = 1 held at O by two frictionless contacts whose normals make the angle
    delta with the horizontal, one on each side: N1 = N2 = W / (2 sin delta)."""
    R0 = rm.Frame("R0")
    body = rm.Body("block", frame=R0)
    st_ = Statics(R0)
    c, s = math.cos(delta), math.sin(delta)
    st_.connect(R0, body, ContactLaws(at=R0.origin, normal=c * R0.i + s * R0.j), label="1")
    st_.connect(R0, body, ContactLaws(at=R0.origin, normal=-c * R0.i + s * R0.j), label="2")
    st_.act(Force(on=body, vector=-1.0 * R0.j, at=R0.origin))
    return st_


def test_an_ill_conditioned_statics_problem_warns():
    """delta = 0.1: N = 1 / (2 sin 0.1), no warning. delta = 1e-11 (condition number ~1e11,
    above 1e10): the values are still given (they are right to about cond * eps) with a
    RigidmechWarning naming the condition number."""
    import warnings

    from rigidmech.errors import RigidmechWarning

    N1 = sp.Symbol("N_1", real=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        values = _wedge(0.1).solve().values
    assert math.isclose(values[N1], 1 / (2 * math.sin(0.1)), rel_tol=1e-12)
    with pytest.warns(RigidmechWarning, match=r"ill-conditioned.*condition number"):
        values = _wedge(1e-11).solve().values
    assert math.isclose(values[N1], 1 / (2 * math.sin(1e-11)), rel_tol=1e-4)


def test_values_by_name_reach_symbols_with_assumptions():
    """values={"W": 2} means the problem's W (declared positive), not a new plain symbol that
    matches nothing; a name of no symbol of the problem is refused (also "Q", which sympify
    reads as sympy's assumptions object)."""
    from rigidmech._core.errors import ArgumentError as _ArgumentError

    R0 = rm.Frame("R0")
    box = rm.Body("box", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
                                     friction=Coulomb(0.5)), label="A")
    W = rm.constants("W", positive=True)
    P = sp.Symbol("P", real=True)
    st_.act(Force(on=box, vector=-W * R0.j + P * R0.i, at=R0.origin))
    assert st_.solve(values={"W": 2, "P": 0}).values[sp.Symbol("N_A", real=True)] == 2.0
    lim = limiting_equilibrium(st_, P, (0.0, 10.0), values={"W": 10.0})
    assert math.isclose(lim.value, 5.0, rel_tol=1e-9)
    for name in ("Q", "V"):
        with pytest.raises(_ArgumentError, match=rf"`values`: '{name}' names no symbol"):
            st_.solve(values={name: 2})
    with pytest.raises(_ArgumentError, match=r"the value of `W` must be > 0"):
        st_.solve(values={"W": -1, "P": 0})
