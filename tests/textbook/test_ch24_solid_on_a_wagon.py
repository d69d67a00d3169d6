"""Ch. 24.2 (motion of a solid placed on a wagon): a homogeneous cylinder of mass m and radius
r rolls without slipping on the floor of a wagon whose acceleration a along i0 is given.

Conventions: R0 Galilean, the wagon's reference Rw = R0 translated by x_w(t) i0, the floor the
line (O_w, i_w), gravity -g j0; the cylinder's centre C = (x, r) in Rw, its angle theta about
k. Closed form for a constant a (written in the wagon with the inertial action -m a i0 at C):

    m x'' = -m a + T,   (m r^2 / 2) theta'' = r T,   x' + r theta' = 0
    =>  x'' = -2 a / 3,   T = m a / 3,   N = m g,

T and N the tangential and normal components of the floor's action on the cylinder. The
non-Galilean route (``System(galilean=R0, reference=Rw)``) and the Galilean one (the wagon as a
body with its prescribed motion) give the same accelerations for any law x_w(t).
"""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import Circle, ContactKinematics

t = rm.t


def _cylinder_on_wagon(route, law):
    x, th = rm.coordinates("x theta")
    m, r, g = rm.constants("m r g", positive=True)
    R0 = rm.Frame("R0")
    Rw = R0.translated("Rw", R0.point("W", law, 0, 0))
    R1 = Rw.rotated("R1", about=Rw.k, angle=th, origin=Rw.point("C", x, r, 0))
    C = R1.origin
    cyl = rm.Body("cylinder", frame=R1, mass=m, centre=C,
                  inertia=rm.InertiaOperator.from_products(m * r**2 / 4, m * r**2 / 4,
                                                           m * r**2 / 2, frame=R1, at=C))
    if route == "galilean":
        s = rm.System(galilean=R0)
        wagon = rm.Body("wagon", frame=Rw)
        s.connect(R0, wagon, rm.joints.Prismatic(at=Rw.origin, axis=R0.i))
        floor = wagon
    else:
        s = rm.System(galilean=R0, reference=Rw)
        floor = Rw
    contact = ContactKinematics.between(R1, Circle(C, r, normal=Rw.k), Rw, rm.Line(Rw.origin, Rw.i))
    s.connect(floor, cyl, rm.joints.RollingContact(contact))
    s.act(rm.gravity(-g * R0.j))
    return s, floor, cyl, (x, th, m, r, g)


def test_ch24_cylinder_rolling_on_an_accelerating_wagon():
    a = sp.Symbol("a", positive=True)
    s, floor, cyl, (x, th, m, r, g) = _cylinder_on_wagon("reference", a * t**2 / 2)
    acc = s.equations_of_motion().accelerations()
    assert sp.simplify(acc[0] + 2 * a / 3) == 0
    assert sp.simplify(acc[1] - 2 * a / (3 * r)) == 0
    # the floor's action on the cylinder, at the contact point, with the motion's q''
    A = s.connection_action(floor, cyl).resultant
    moving = {x.diff(t, 2): acc[0], th.diff(t, 2): acc[1]}
    T = sp.simplify(A.dot(s.reference.i).subs(moving))
    N = sp.simplify(A.dot(s.reference.j).subs(moving))
    assert sp.simplify(T - m * a / 3) == 0 and sp.simplify(N - m * g) == 0


@pytest.mark.parametrize("law", ["uniform", "oscillating"])
def test_ch24_cylinder_on_a_wagon_same_accelerations_both_routes(law):
    a, b, c = sp.symbols("a b c", positive=True)
    x_w = a * t**2 / 2 if law == "uniform" else b * sp.sin(c * t)
    acc = [_cylinder_on_wagon(route, x_w)[0].equations_of_motion().accelerations()
           for route in ("galilean", "reference")]
    for u, v in zip(acc[0], acc[1], strict=True):
        assert sp.simplify(u - v) == 0
    assert sp.simplify(acc[0][0] - 2 * sp.diff(x_w, t, 2) / -3) == 0
