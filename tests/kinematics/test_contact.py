"""ContactKinematics of two solids, contact geometry and kinematic constraints (book, ch. 10.1).

Expected values are closed forms worked out in the comments (the geometry of spheres, circles
and planes; the velocity field of a solid, v(B) = v(A) + omega ^ AB)."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech._core.errors import ConnectionError_
from rigidmech.kinematics import (
    Circle,
    ContactKinematics,
    Cylinder,
    Sphere,
    VelocityConstraint,
    contact_geometry,
)

r, R, a = sp.symbols("r R a", positive=True)


@pytest.fixture
def R0():
    return rm.Frame("R0")


def _coords(point, frame):
    return list(point.coordinates(frame))


def test_sphere_on_plane_below_and_above(R0):
    # centre at height r above z = 0: I = (x, y, 0), n = +k; below the plane: n = -k
    g = contact_geometry(Sphere(R0.point("C", 1, 2, 3), 3), rm.Plane(R0.origin, R0.k))
    assert _coords(g.point, R0) == [1, 2, 0] and g.normal == R0.k
    g = contact_geometry(rm.Plane(R0.origin, 2 * R0.k), Sphere(R0.point("C", 1, 2, -3), 3))
    # first = plane, second = sphere: the normal points from the sphere towards the plane
    assert _coords(g.point, R0) == [1, 2, 0] and g.normal.equals(R0.k)


def test_cylinder_on_plane(R0):
    axis = rm.Line(R0.point("A", 0, 0, r), R0.i)
    g = contact_geometry(Cylinder(axis, r), rm.Plane(R0.origin, R0.k))
    assert _coords(g.point, R0) == [0, 0, 0] and g.normal == R0.k


def test_circles_external_and_internal(R0):
    # external: centres 0 and (r + R) i0; I at r i0; normal from the second towards the first
    g = contact_geometry(Circle(R0.origin, r, normal=R0.k),
                         Circle(R0.point("B", r + R, 0, 0), R, normal=R0.k))
    assert sp.simplify(_coords(g.point, R0)[0] - r) == 0
    assert g.normal.equals(-R0.i)
    # internal: a disc of radius 1 inside a ring of radius 3, centre at 2 i0: I = 3 i0, the
    # normal points from the ring into the disc (-i0)
    g = contact_geometry(Circle(R0.point("C", 2, 0, 0), 1, normal=R0.k),
                         Circle(R0.origin, 3, normal=R0.k))
    assert _coords(g.point, R0) == [3, 0, 0] and g.normal.equals(-R0.i)
    # symbolic radii: say which one is inside
    g = contact_geometry(Circle(R0.point("C", R - r, 0, 0), r, normal=R0.k),
                         Circle(R0.origin, R, normal=R0.k), inner="first")
    assert sp.simplify(_coords(g.point, R0)[0] - R) == 0


def test_disc_on_a_plane_in_3d(R0):
    """A disc tilted by theta about i0 (axis a = -sin(theta) j0 + cos(theta) k0), centre at
    height r sin(theta): d = n - (n . a) a = sin(theta) j_theta, the lowest point is C - r j_theta;
    a disc below the plane touches it with its highest point."""
    theta = rm.coordinates("theta")
    Rt = R0.rotated("Rt", about=R0.i, angle=theta)
    C = R0.origin.moved("C", r * Rt.j)
    g = contact_geometry(Circle(C, r, normal=Rt.k), rm.Plane(R0.origin, R0.k))
    assert [sp.simplify(c) for c in g.point.coordinates(R0)] == [0, 0, 0]
    assert g.normal == R0.k
    below = R0.origin.moved("C2", -r * Rt.j)
    g = contact_geometry(Circle(below, r, normal=Rt.k), rm.Plane(R0.origin, R0.k))
    assert [sp.simplify(c) for c in g.point.coordinates(R0)] == [0, 0, 0]
    # numeric tilt, no basis vector along d: the square-root branch
    Rn = R0.rotated("Rn", about=R0.vector(1, 1, 0), angle=sp.pi / 3)
    a_ = Rn.k
    d = R0.k - R0.k.dot(a_) * a_
    Cn = R0.origin.moved("Cn", 2 * d / d.magnitude())
    g = contact_geometry(Circle(Cn, 2, normal=a_), rm.Plane(R0.origin, R0.k))
    assert all(abs(float(v)) < 1e-14 for v in g.point.coordinates(R0))
    with pytest.raises(ConnectionError_, match="circle lies in a plane parallel"):
        contact_geometry(Circle(R0.point("F", 0, 0, 1), 1, normal=R0.k),
                         rm.Plane(R0.origin, R0.k))
    with pytest.raises(ConnectionError_, match="not in contact: the height of the centre"):
        contact_geometry(Circle(R0.origin.moved("C3", 2 * r * Rt.j), r, normal=Rt.k),
                         rm.Plane(R0.origin, R0.k))


def test_spheres_external(R0):
    g = contact_geometry(Sphere(R0.point("B", 0, 0, 5), 2), Sphere(R0.origin, 3))
    assert _coords(g.point, R0) == [0, 0, 3] and g.normal.equals(R0.k)


def test_not_in_contact_and_bad_radii_are_refused(R0):
    with pytest.raises(ConnectionError_, match="not in contact.*got a gap of 1"):
        contact_geometry(Sphere(R0.point("C", 0, 0, 2), 1), rm.Plane(R0.origin, R0.k))
    with pytest.raises(ConnectionError_, match="not in contact.*sum.*or the difference"):
        contact_geometry(Circle(R0.origin, 1, normal=R0.k),
                         Circle(R0.point("B", 5, 0, 0), 1, normal=R0.k))
    with pytest.raises(ConnectionError_, match="line must lie in the circle's plane"):
        contact_geometry(Circle(R0.origin, 1, normal=R0.k), rm.Line(R0.point("P", 0, -1, 1),
                                                                     R0.i))
    with pytest.raises(ConnectionError_, match="axis must be parallel to the plane"):
        contact_geometry(Cylinder(rm.Line(R0.origin, R0.k), 1), rm.Plane(R0.origin, R0.k))
    with pytest.raises(ValueError, match="`radius` must be positive; got -2"):
        Sphere(R0.origin, -2)
    with pytest.raises(ValueError, match="`radius` must be positive; got 0"):
        Circle(R0.origin, 0, normal=R0.k)
    with pytest.raises(ValueError, match="cannot tell which of the radii"):
        contact_geometry(Circle(R0.point("C", R - r, 0, 0), r, normal=R0.k),
                         Circle(R0.origin, R, normal=R0.k))
    with pytest.raises(TypeError, match="contact between a Sphere and a Line is not treated"):
        contact_geometry(Sphere(R0.origin, 1), rm.Line(R0.origin, R0.i))
    with pytest.raises(TypeError, match="`moving` must be a Solid, a Body or a Frame"):
        ContactKinematics("wheel", R0, at=R0.origin, normal=R0.k)
    with pytest.raises(ValueError, match="`inner` must be None, 'moving' or 'other'"):
        ContactKinematics.between(R0, Circle(R0.origin, 1, normal=R0.k), R0,
                        Circle(R0.origin, 2, normal=R0.k), inner="first")
    with pytest.raises(ValueError, match="`inner` must be None, 'first' or 'second'"):
        contact_geometry(Circle(R0.origin, 1, normal=R0.k), Circle(R0.origin, 2, normal=R0.k),
                         inner="moving")
    with pytest.raises(ValueError, match="`normal` must be a non-zero Vector"):
        ContactKinematics(R0, R0, at=R0.origin, normal=rm.Vector.zero())


def test_sliding_rolling_spinning_of_a_top_on_a_plane(R0):
    """A solid spinning by s about k0, then tilting by p about its horizontal axis i2, through
    the contact point, and translating by x i0: omega = s' k0 + p' i2; sliding velocity x' i0,
    rolling p' i2, spinning s' k0 (ch. 10.1.2)."""
    x, p, s = rm.coordinates("x p s")
    R1 = R0.translated("T", R0.point("P", x, 0, 0))
    R2 = R1.rotated("R2", about=R1.k, angle=s)
    R3 = R2.rotated("R3", about=R2.i, angle=p)
    c = ContactKinematics(R3, R0, at=R1.origin, normal=R0.k)
    w = R3.rotation_vector(R0)
    assert c.sliding_velocity.equals(x.diff(rm.t) * R0.i)
    assert (c.rolling + c.spinning).equals(w)
    assert c.rolling.equals(p.diff(rm.t) * R2.i) and c.spinning.equals(s.diff(rm.t) * R0.k)
    assert sp.simplify(c.rolling.dot(R0.k)) == 0 and c.spinning.cross(R0.k).equals(
        rm.Vector.zero())
    assert c.without_pivoting_equations() == (s.diff(rm.t),)
    assert c.without_slipping() == c.sliding_velocity
    assert c.persistence_equation() == 0


def test_tangents_without_an_orthogonal_basis_vector(R0):
    n = (R0.i + R0.j + R0.k) / sp.sqrt(3)
    c = ContactKinematics(R0, R0, at=R0.origin, normal=n)
    t1, t2 = c.tangents()
    for u, v in ((t1, t1), (t2, t2), (n, n)):
        assert sp.simplify(u.dot(v) - 1) == 0
    assert sp.simplify(t1.dot(n)) == 0 and sp.simplify(t2.dot(n)) == 0
    assert sp.simplify(rm.mixed(t1, t2, n) - 1) == 0  # direct


def test_velocity_constraints_exact_and_not():
    x, y, th, ph = rm.coordinates("x y th ph")
    t = rm.t
    # d/dt (x y) = y x' + x y': exact
    c = VelocityConstraint(y * x.diff(t) + x * y.diff(t))
    assert c.holonomic and sp.simplify(c.position_form - x * y) == 0
    # a knife edge x' sin(th) - y' cos(th) = 0 is not exact (not integrable either)
    c = VelocityConstraint(sp.sin(th) * x.diff(t) - sp.cos(th) * y.diff(t))
    assert not c.holonomic and c.position_form is None
    with pytest.raises(ConnectionError_, match="is not holonomic"):
        c.position_constraint()
    # a rheonomic constraint x' - a cos(t) = 0 integrates to x - a sin(t)
    c = VelocityConstraint(x.diff(t) - a * sp.cos(t))
    assert sp.simplify(c.position_constraint({x: 0, t: 0}) - (x - a * sp.sin(t))) == 0
    # y x' alone is not exact: its coefficient depends on y, which has no speed term
    assert not VelocityConstraint(y * x.diff(t)).holonomic
    with pytest.raises(ValueError, match="must be linear in the derivatives"):
        VelocityConstraint(x.diff(t) ** 2)
    with pytest.raises(ValueError, match="first derivatives only"):
        VelocityConstraint(x.diff(t, 2))
    with pytest.raises(TypeError, match="`initial` must be a dict"):
        VelocityConstraint(x.diff(t)).position_constraint([0])


def test_sliding_velocity_on_a_moving_solid_is_the_difference_of_velocities(R0):
    """A wheel (centre (x, r), angle theta) on a conveyor belt translating by s(t) i0: by the
    composition of motions (ch. 9.3) v(I in W/B) = v(I in W/R0) - v(I in B/R0)
    = (x' + r theta' - s') i0, and the relative rotation is that of the wheel."""
    x, theta, s = rm.coordinates("x theta s")
    belt = R0.translated("B", R0.point("S", s, 0, 0))
    wheel = R0.rotated("W", about=R0.k, angle=theta, origin=R0.point("C", x, r, 0))
    I = R0.point("I", x, 0, 0)
    c = ContactKinematics(wheel, belt, at=I, normal=R0.j)
    d = [q.diff(rm.t) for q in (x, theta, s)]
    assert c.sliding_velocity.equals((d[0] + r * d[1] - d[2]) * R0.i)
    absolute = rm.Solid("W", wheel).velocity(I, relative_to=R0) - rm.Solid(
        "B", belt).velocity(I, relative_to=R0)
    assert c.sliding_velocity.equals(absolute)
    assert c.rotation.equals(d[1] * R0.k)
    (eq,) = c.without_slipping_equations()
    assert sp.simplify(eq - (d[0] + r * d[1] - d[2])) == 0
    assert VelocityConstraint(eq).holonomic


@settings(max_examples=10, deadline=None)
@given(n=st.tuples(*[st.integers(-3, 3)] * 3).filter(any),
       rates=st.tuples(*[st.floats(-5, 5, allow_nan=False)] * 3))
def test_rotation_splits_into_rolling_and_spinning(n, rates):
    """Ch. 10.1.2: omega = rolling + spinning, rolling in the tangent plane, spinning along
    the normal, for any normal and any rotation (three chained rotations)."""
    q1, q2, q3 = rm.coordinates("q1 q2 q3")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.i, angle=q2)
    R3 = R2.rotated("R3", about=R2.k, angle=q3)
    c = ContactKinematics(R3, R0, at=R0.origin, normal=R0.vector(*n))
    values = {q.diff(rm.t): v for q, v in zip((q1, q2, q3), rates, strict=True)}
    values.update({q1: 0.3, q2: -1.1, q3: 2.0})
    num = [np.array(v.components(R0).subs(values), dtype=float).ravel()
           for v in (c.rotation, c.rolling, c.spinning, c.normal)]
    w, rolling, spinning, normal = num
    assert_allclose(rolling + spinning, w, atol=1e-12)
    assert abs(rolling @ normal) < 1e-12
    assert_allclose(np.cross(spinning, normal), 0, atol=1e-12)


@pytest.mark.parametrize("height, touches", [
    (0.1, True), (0.7 - 0.6, True),                # 0.09999999999999998: rounding only
    (0.1 * (1 + 0.5e-12), True), (0.1 * (1 - 0.5e-12), True),
    (0.1 * (1 + 2e-12), False), (0.1 + 1e-6, False),
])
def test_contact_of_float_data_is_decided_relative_to_the_size(height, touches):
    """A sphere of radius 0.1 on the plane z = 0, centre at `height`: in contact when the gap
    is at most 1e-12 of the radius (numbers given in floats), not only when it is exactly 0."""
    R0 = rm.Frame("R0")
    sphere, plane = Sphere(R0.point("C", 0, 0, height), 0.1), rm.Plane(R0.origin, R0.k)
    if touches:
        g = contact_geometry(sphere, plane)
        assert g.normal == R0.k
    else:
        with pytest.raises(rm.errors.ConnectionError_, match="not in contact"):
            contact_geometry(sphere, plane)


@pytest.mark.parametrize("gap, touches", [(0.5e-12, True), (2e-12, False)])
def test_contact_of_two_float_circles_relative_threshold(gap, touches):
    """Circles of radii 0.3 and 0.2 whose centres are 0.5 (1 + gap) apart."""
    R0 = rm.Frame("R0")
    a = Circle(R0.origin, 0.3, normal=R0.k)
    b = Circle(R0.point("B", 0.5 * (1 + gap), 0, 0), 0.2, normal=R0.k)
    if touches:
        contact_geometry(a, b)
    else:
        with pytest.raises(rm.errors.ConnectionError_, match="not in contact"):
            contact_geometry(a, b)


@pytest.mark.parametrize("height, touches", [(0.7 - 0.6, True), (0.1 + 1e-6, False)])
def test_contact_of_symbolic_data_with_floats_uses_the_one_zero_rule(height, touches):
    """A sphere of radius 0.1 r on the plane z = 0, centre at `height` r (r a symbol): the gap
    (0.7 - 0.6) r - 0.1 r arrives as -2.8e-17 r, rounding of the floats: a contact, decided by
    the rule of every exact-or-rounded zero (``_core.symbolic.vanishes``), not refused because
    ``simplify`` cannot make -2.8e-17 r zero; a gap of 1e-6 r is refused."""
    R0 = rm.Frame("R0")
    sphere, plane = Sphere(R0.point("C", 0, 0, height * r), 0.1 * r), rm.Plane(R0.origin, R0.k)
    if touches:
        assert contact_geometry(sphere, plane).normal == R0.k
    else:
        with pytest.raises(rm.errors.ConnectionError_, match="not in contact"):
            contact_geometry(sphere, plane)

