"""Mechanisms shared by the tests of the systems layer and of the linked parameters."""

import rigidmech as rm
from rigidmech.dynamics import System

L0, L1, L2, L3 = 2.0, 1.0, 2.0, 1.5


def bar(name, frame, length, origin, m):
    G = origin.moved("G" + name, length / 2 * frame.i)
    return rm.Body(name, frame=frame, mass=m, centre=G,
                   inertia=rm.inertia.rod(m, length, axis=frame.i, centre=G))


def four_bar(lengths=(L0, L1, L2, L3), gravity=True, stabilization=(5.0, 5.0)):
    """Crank O-B (q1), coupler B-C (q2, relative to the crank), rocker D-C (q3), ground
    O-D along i; the loop is closed by the pivot at C (the coupler's C meets the rocker's).
    A length may be a sympy symbol; `stabilization` is Baumgarte's (alpha, beta)."""
    l0, l1, l2, l3 = lengths
    q1, q2, q3 = rm.coordinates("q1 q2 q3")
    m, g = rm.constants("m g", positive=True)
    R0 = rm.Frame("R0")
    k = R0.k
    R1 = R0.rotated("R1", about=k, angle=q1)
    B = R0.origin.moved("B", l1 * R1.i)
    R2 = R1.rotated("R2", about=k, angle=q2, origin=B)
    D = R0.point("D", l0, 0, 0)
    R3 = R0.rotated("R3", about=k, angle=q3, origin=D)
    crank, coupler, rocker = (bar("crank", R1, l1, R0.origin, m), bar("coupler", R2, l2, B, m),
                              bar("rocker", R3, l3, D, m))
    s = System(galilean=R0, stabilization=stabilization)
    s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=k))
    s.connect(crank, coupler, rm.joints.Pivot(at=B, axis=k))
    s.connect(R0, rocker, rm.joints.Pivot(at=D, axis=k))
    C2, C3 = B.moved("C", l2 * R2.i), D.moved("C3", l3 * R3.i)
    s.connect(coupler, rocker, rm.joints.Pivot(at=C2, axis=k), meets=C3)
    if gravity:
        s.act(rm.gravity(-g * R0.j))
    return s, (q1, q2, q3), (R0, R1, R2, R3), (B, C2, C3)


def slider_crank(r=0.5, ell=1.5):
    """Crank O-A (q1), rod A-B (q2 relative to the crank), slider at x on the line (O, i); the
    loop is closed by the pivot at B between the rod and the slider."""
    q1, q2, x = rm.coordinates("q1 q2 x")
    m, g = rm.constants("m g", positive=True)
    R0 = rm.Frame("R0")
    k = R0.k
    R1 = R0.rotated("R1", about=k, angle=q1)
    A = R0.origin.moved("A", r * R1.i)
    R2 = R1.rotated("R2", about=k, angle=q2, origin=A)
    P = R0.point("P", x, 0, 0)
    R3 = R0.translated("R3", P)
    crank, rod = bar("crank", R1, r, R0.origin, m), bar("rod", R2, ell, A, m)
    slider = rm.Body("slider", frame=R3, mass=m, centre=P)
    s = System(galilean=R0)
    s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=k))
    s.connect(crank, rod, rm.joints.Pivot(at=A, axis=k))
    s.connect(R0, slider, rm.joints.Prismatic(at=P, axis=R0.i))
    s.connect(rod, slider, rm.joints.Pivot(at=A.moved("B", ell * R2.i), axis=k), meets=P)
    s.act(rm.gravity(-g * R0.j))
    return s, (q1, q2, x), R0
