"""Degree of mobility and degree of hyperstaticity (book, ch. 13.2, 14.2).

Expected values, written out by hand from the book's formula h = N_s - 6 N_b + m (3 N_b in
a plane), with N_s the static unknowns of the perfect connections and m the mobility counted
from the motions the mechanism allows:

* four-bar linkage, planar, four pivots: N_s = 4 x 2, N_b = 3, m = 1 (the crank angle fixes
  the rest) -> h = 8 - 9 + 1 = 0;
* the same in space, four pivots of parallel axes: N_s = 4 x 5 -> h = 20 - 18 + 1 = 3 (the
  classical over-constrained four-bar: the axial forces and the two transverse moments of
  the pivots, Z, L, M, are not determined);
* shaft on a spherical joint and a linear annular (sphere-cylinder) one on its axis:
  N_s = 3 + 2, N_b = 1, m = 1 (rotation about the axis) -> h = 0 (isostatic mounting);
* shaft on two pivots of the same axis: N_s = 5 + 5 -> h = 10 - 6 + 1 = 5; the six
  equations of the shaft give X_A + X_B = 0, Y_A + Y_B = 0, Z_A + Z_B = 0 and, at A,
  L_A + L_B - d Y_B = 0, M_A + M_B + d X_B = 0 (the sixth is 0 = 0, the mobility): every one
  of the ten unknowns is left undetermined;
* gear pair on a casing (two pivots and a mesh, one unknown F): N_s = 5 + 5 + 1, N_b = 2,
  m = 1 -> h = 0;
* slider-crank, planar: three pivots and a slide, N_s = 4 x 2, N_b = 3, m = 1 -> h = 0.
"""

import sys
from pathlib import Path

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import Gear, GearPair
from rigidmech.systems import Mechanism

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "systems"))
from mechanisms import four_bar, slider_crank  # noqa: E402


def shaft(first, second):
    R0 = rm.Frame("R0")
    th = rm.coordinates("theta")
    body = rm.Body("shaft", frame=R0.rotated("R1", about=R0.k, angle=th))
    A, B = R0.origin, R0.point("B", 0, 0, sp.Symbol("d", positive=True))
    g = Mechanism(R0)
    g = g.with_connection(R0, body, first(A, R0), label="A")
    return g.with_connection(R0, body, second(B, R0), label="B")


def gears():
    q1, q2 = rm.coordinates("q1 q2")
    R0 = rm.Frame("R0")
    G1 = R0.rotated("G1", about=R0.k, angle=q1)
    G2 = R0.rotated("G2", about=R0.k, angle=q2, origin=R0.point("O2", 60, 0, 0))
    b1, b2 = rm.Body("g1", frame=G1), rm.Body("g2", frame=G2)
    mesh = rm.actions.GearMesh(GearPair(Gear(20, 2), Gear(40, 2)), b1, b2, carrier=R0,
                               axis=R0.k)
    return (Mechanism(R0)
            .with_connection(R0, b1, rm.joints.Pivot(at=G1.origin, axis=R0.k))
            .with_connection(R0, b2, rm.joints.Pivot(at=G2.origin, axis=R0.k))
            .with_connection(b1, b2, mesh))


CASES = [
    pytest.param(lambda: four_bar()[0].mechanism, True, 1, 0, 1, id="four_bar_planar"),
    pytest.param(lambda: four_bar()[0].mechanism, None, 1, 3, 1, id="four_bar_spatial"),
    pytest.param(lambda: shaft(lambda A, R0: rm.joints.Spherical(at=A),
                               lambda B, R0: rm.joints.LinearAnnular(at=B, axis=R0.k)),
                 None, 1, 0, 1, id="shaft_spherical_linear_annular"),
    pytest.param(lambda: shaft(lambda A, R0: rm.joints.Pivot(at=A, axis=R0.k),
                               lambda B, R0: rm.joints.Pivot(at=B, axis=R0.k)),
                 None, 1, 5, 1, id="shaft_two_pivots"),
    pytest.param(gears, None, 1, 0, 1, id="gear_pair"),
    pytest.param(lambda: slider_crank()[0].mechanism, True, 1, 0, 1,
                 id="slider_crank_planar"),
]


@pytest.mark.parametrize(("build", "plane", "m", "h", "loops"), CASES)
def test_mobility_and_hyperstaticity(build, plane, m, h, loops):
    g = build()
    if plane:  # a planar problem: the normal k of the reference
        plane = g.reference.k
    r = g.mobility(plane=plane)
    assert (r.mobility, r.hyperstaticity, r.loops) == (m, h, loops)
    # the book's formula and the rank of the equilibrium equations agree (duality)
    per_body = 3 if plane is not None else 6
    assert r.hyperstaticity == r.static_unknowns - per_body * r.bodies + r.mobility
    assert r.isostatic == (h == 0)


def test_two_pivots_leave_every_unknown_undetermined():
    r = shaft(lambda A, R0: rm.joints.Pivot(at=A, axis=R0.k),
              lambda B, R0: rm.joints.Pivot(at=B, axis=R0.k)).mobility()
    assert {str(u) for u in r.undetermined} == {
        f"{c}_{p}" for c in "XYZLM" for p in "AB"}
    assert "hyperstaticity h = 5" in str(r) and "undetermined by statics" in str(r)


def test_spatial_four_bar_reports_the_axial_unknowns():
    r = four_bar()[0].mobility()
    assert {str(u)[0] for u in r.undetermined} == {"Z", "L", "M"}


def test_isostatic_mechanism_reports_nothing_undetermined():
    s = four_bar()[0]
    r = s.mobility(plane=s.galilean.k)
    assert r.undetermined == () and "(isostatic)" in str(r)


def test_mobility_matches_the_rank_of_the_closure_jacobian():
    # second route for the four-bar: n coordinates minus the rank of Phi_q at a generic point
    s, qs, _, _ = four_bar()
    A = s.constraints().jacobian.subs({qs[0]: 0.7, qs[1]: -0.4, qs[2]: 1.9})
    assert len(qs) - A.rank() == s.mobility(plane=s.galilean.k).mobility == 1


def test_bad_plane_is_refused():
    with pytest.raises(rm.errors.ArgumentTypeError, match=r"`plane` must be the unit normal"):
        four_bar()[0].mobility(plane="k")


def test_shaft_in_two_bearings_statics_from_the_same_graph():
    # isostatic mounting: a load P at mid-span (z = d/2) along -j is shared equally by the
    # bearings, Y_A = Y_B = P/2, the axial force taken by the spherical joint alone
    from rigidmech.statics import Statics
    P = sp.Symbol("P", positive=True)
    g = shaft(lambda A, R0: rm.joints.Spherical(at=A),
              lambda B, R0: rm.joints.LinearAnnular(at=B, axis=R0.k))
    R0, body = g.reference, g.bodies[0]
    d = sp.Symbol("d", positive=True)
    g = g.with_action(rm.actions.Force(on=body, vector=-P * R0.j,
                                       at=R0.point("M", 0, 0, d / 2)))
    eq = Statics.from_mechanism(g).solve()
    values = {str(k): v for k, v in eq.values.items()}
    assert sp.simplify(values["Y_A"] - P / 2) == 0 and sp.simplify(values["Y_B"] - P / 2) == 0
    assert values["Z_A"] == 0 and eq.hyperstaticity == g.mobility().hyperstaticity == 0
    # two pivots: statics finds the same degree of hyperstaticity as the graph
    g2 = shaft(lambda A, R0: rm.joints.Pivot(at=A, axis=R0.k),
               lambda B, R0: rm.joints.Pivot(at=B, axis=R0.k))
    g2 = g2.with_action(rm.actions.Force(on=g2.bodies[0], vector=-P * g2.reference.j,
                                         at=g2.reference.point("M", 0, 0, d / 2)))
    assert Statics.from_mechanism(g2).solve().hyperstaticity == g2.mobility().hyperstaticity == 5
