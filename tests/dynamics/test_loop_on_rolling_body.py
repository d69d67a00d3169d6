"""A joint closing a loop on a body whose only connection is a rolling contact.

Found by the differential fuzzer (a disc rolling on a plane, a point of it held by a ball joint):
``System.connect(..., meets=...)`` refused the closing joint with "`meets` ... got it for b1,
which has no connection yet", although the rolling contact connects the body and the joint
does close a loop (the same call without ``meets`` is taken as closing). ``meets`` must be
accepted wherever the joint closes a loop.
"""

import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import ContactKinematics


def _ball_on_a_rail():
    """A uniform ball (mass m, radius r) rolling without slipping on the plane z = 0, its
    centre held on the line y = 0, z = r by a linear annular joint (the loop): x and the
    three angles remain, the rolling conditions leave the rolling along x and the spin
    about the vertical."""
    x, y, a, b, c = rm.coordinates("x y a b c")
    m, r, F = rm.constants("m r F", positive=True)
    R0 = rm.Frame("R0")
    I = R0.point("I", x, y, 0)
    G = I.moved("G", r * R0.k)
    B = R0.euler("B", a, b, c, origin=G)  # z-x-z angles
    ball = rm.Body("ball", frame=B, mass=m, centre=G, inertia=rm.inertia.sphere(m, r, frame=B))
    s = rm.System(galilean=R0)
    s.connect(R0, ball, rm.actions.RollingContact(ContactKinematics(ball, R0, at=I,
                                                                     normal=R0.k)))
    s.connect(R0, ball, rm.joints.LinearAnnular(at=R0.point("D", 0, 0, r), axis=R0.i),
              meets=G)
    s.act(rm.Force(on=ball, vector=F * R0.i, at=G))
    return s, (x, y, a, b, c)


def test_meets_is_accepted_on_a_body_connected_by_a_rolling_contact():
    s, _ = _ball_on_a_rail()
    assert len(s.constraints()) >= 3  # two rolling conditions and the rail's


def test_ball_pushed_along_the_rail_rolls_with_five_sevenths_of_f_over_m():
    """F along the rail at the centre: F - T = m x'', T r = (2/5) m r^2 (x''/r):
    x'' = 5 F / (7 m) (ch. 23.4); at rest nothing else moves."""
    s, q = _ball_on_a_rail()
    eqs = s.equations_of_motion()
    names = [c.func.__name__ for c in eqs.coordinates]
    rhs = eqs.rhs(m=2.0, r=0.5, F=3.5)
    state = dict(zip(("x", "y", "a", "b", "c"), (0.3, 0.0, 0.4, 1.1, -0.7), strict=True))
    qv = np.array([state[n] for n in names])
    out = rhs(0.0, np.concatenate([qv, np.zeros(len(names))]))
    acc = dict(zip(names, out[len(names):], strict=True))
    assert np.isclose(acc["x"], 5 * 3.5 / (7 * 2.0), rtol=1e-12, atol=0)
    assert abs(acc["y"]) < 1e-12
    assert sp.Symbol("F") in {sp.Symbol(p.name) for p in eqs.parameters}
