"""Property: the two routes to the degrees of mobility and hyperstaticity agree (duality of
kinematics and statics for perfect connections, ch. 13.2.4, 14.2): the rank of the
equilibrium equations of the bodies is 6 N_b - m, with m counted from the loop-closure
equations of the connections' allowed motions."""

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidmech as rm
from rigidmech.systems import Mechanism

R0 = rm.Frame("R0")
AXES = (R0.i, R0.j, R0.k)


def joint(kind, name, axis):
    P = R0.point("P" + name, *sp.symbols(f"a{name} b{name} c{name}"))
    e = AXES[axis]
    return {
        "pivot": lambda: rm.joints.Pivot(at=P, axis=e),
        "prismatic": lambda: rm.joints.Prismatic(at=P, axis=e),
        "cylindrical": lambda: rm.joints.Cylindrical(at=P, axis=e),
        "spherical": lambda: rm.joints.Spherical(at=P),
        "planar": lambda: rm.joints.PlanarSupport(at=P, normal=e),
        "annular": lambda: rm.joints.LinearAnnular(at=P, axis=e),
        "point": lambda: rm.joints.PointContact(at=P, normal=e),
        "fixed": lambda: rm.joints.Embedding(at=P, axis=e),
    }[kind]()


KINDS = st.sampled_from(["pivot", "prismatic", "cylindrical", "spherical", "planar",
                         "annular", "point", "fixed"])


@st.composite
def mechanisms(draw):
    n = draw(st.integers(1, 3))
    bodies = [rm.Body(f"b{i}", frame=R0) for i in range(1, n + 1)]
    solids = [R0, *bodies]
    g = Mechanism(R0)
    count = 0
    for i, b in enumerate(bodies, start=1):          # a tree: each body to an earlier solid
        parent = solids[draw(st.integers(0, i - 1))]
        count += 1
        g = g.with_connection(parent, b, joint(draw(KINDS), str(count),
                                               draw(st.integers(0, 2))))
    for _ in range(draw(st.integers(0, 3))):         # loops
        i, j = draw(st.integers(0, n)), draw(st.integers(0, n))
        if i == j:
            continue
        count += 1
        g = g.with_connection(solids[i], solids[j], joint(draw(KINDS), str(count),
                                                          draw(st.integers(0, 2))))
    return g


@settings(max_examples=40, deadline=None)
@given(mechanisms())
def test_statics_rank_is_six_bodies_minus_mobility(g):
    r = g.mobility()
    assert r.statics_rank == 6 * r.bodies - r.mobility
    assert r.hyperstaticity == r.static_unknowns - 6 * r.bodies + r.mobility
    assert r.loops == len(g.links) - len(g.bodies)
    assert r.hyperstaticity >= 0 and r.mobility >= 0
