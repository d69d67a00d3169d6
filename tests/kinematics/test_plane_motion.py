"""Instantaneous centre of rotation and centrodes (book, ch. 9.4.5)."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import Solid, centrodes, instantaneous_centre

L, d = sp.symbols("L d", positive=True)


def test_icr_has_zero_velocity_for_a_two_parameter_motion():
    """For x(t), q(t) independent, v(I in S/R0) = 0 by the transport formula."""
    x, q = rm.coordinates("x q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q, origin=R0.point("P", x, 0, 0))
    I = instantaneous_centre(R1, relative_to=R0)
    v = Solid("S", R1).velocity(I, relative_to=R0)
    assert v.simplify().is_zero or sp.simplify(v.dot(v)) == 0


def test_rotation_about_a_fixed_point_has_it_as_icr_and_circles_as_centrodes():
    """A bar turning about the fixed point (d, 0): the ICR is that point; the base curve and
    the rolling curve are single points (the curves are constant)."""
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q, origin=R0.point("A", d, 0, 0))
    I = instantaneous_centre(R1, relative_to=R0)
    assert list(I.coordinates(R0)) == [d, 0, 0]
    base, rolling = centrodes(R1, relative_to=R0, parameter=q)
    assert list(base.position().components(R0)) == [d, 0, 0]


def test_bad_input_is_refused():
    x, y, q = rm.coordinates("x y q")
    R0 = rm.Frame("R0")
    T = R0.translated("T", R0.point("P", x, 0, 0))
    with pytest.raises(ValueError, match="is a translation"):
        instantaneous_centre(T, relative_to=R0)
    A = R0.rotated("A", about=R0.k, angle=q)
    tilted = A.rotated("B", about=A.i, angle=x)
    with pytest.raises(ValueError, match="must keep a fixed direction"):
        instantaneous_centre(tilted, relative_to=R0)
    lifting = R0.rotated("C", about=R0.k, angle=q, origin=R0.point("Q", 0, 0, x))
    with pytest.raises(ValueError, match="must be orthogonal to the rotation axis"):
        instantaneous_centre(lifting, relative_to=R0)
    two = R0.rotated("D", about=R0.k, angle=q, origin=R0.point("Q2", y, 0, 0))
    with pytest.raises(ValueError, match="must depend on the one parameter q"):
        centrodes(two, relative_to=R0, parameter=q)
    with pytest.raises(TypeError, match="`parameter` must be a parameter of situation"):
        centrodes(two, relative_to=R0, parameter=sp.Symbol("q"))
    with pytest.raises(TypeError, match="`moving` must be a Frame, a Solid or a Body"):
        instantaneous_centre("bar", relative_to=R0)
