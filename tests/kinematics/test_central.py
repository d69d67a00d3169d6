"""Motion with central acceleration (ch. 8): areal velocity and constant, Binet's formulas
checked against the velocity and acceleration of a point computed by the frames."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentTypeError
from rigidmech.kinematics import (
    areal_constant,
    areal_velocity,
    binet_acceleration,
    binet_speed_squared,
    is_central,
)


def _polar_point(u_of_theta, theta_sym, C):
    """M at r = 1/u(theta(t)) on the ray of angle theta(t), with theta' = C u^2 (areal law)."""
    th = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    M = R0.origin.moved("M", (1 / u_of_theta.subs(theta_sym, th)) * R1.i)
    # theta' = C u^2 and theta'' = d/dt (C u^2) = 2 C u u_theta theta'
    u = u_of_theta.subs(theta_sym, th)
    thd = C * u**2
    thdd = 2 * C * u * sp.diff(u_of_theta, theta_sym).subs(theta_sym, th) * thd
    rule = {th.diff(rm.t, 2): thdd, th.diff(rm.t): thd}
    return th, R0, R1, M, rule


@pytest.mark.parametrize("u", [
    pytest.param("(1 + e*cos(theta))/p", id="conic"),
    pytest.param("1/(a + b*theta)", id="spiral"),
    pytest.param("exp(-theta)/a", id="log-spiral"),
])
def test_binet_formulas_against_the_point_kinematics(u):
    """With r = 1/u(theta) and r^2 theta' = C, v^2 and the radial acceleration of M
    computed by the frames equal Binet's formulas; the orthoradial acceleration is zero
    (ch. 8.3)."""
    theta = sp.Symbol("theta", real=True)
    C = sp.Symbol("C", positive=True)
    u_expr = sp.sympify(u, locals={"theta": theta})
    th, R0, R1, M, rule = _polar_point(u_expr, theta, C)
    v = M.velocity(R0)
    a = M.acceleration(R0).components(R1)
    v2 = v.dot(v).xreplace(rule)
    assert sp.simplify(v2 - binet_speed_squared(u_expr, theta, C).subs(theta, th)) == 0
    assert sp.simplify(a[0].xreplace(rule) - binet_acceleration(u_expr, theta, C)
                       .subs(theta, th)) == 0
    assert sp.simplify(a[1].xreplace(rule)) == 0


def test_areal_velocity_and_constant():
    """dA/dt = r^2 theta'/2 along k (ch. 8.2); constant for uniform circular motion."""
    r, th = rm.coordinates("r theta")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=th)
    M = R0.origin.moved("M", r * R1.i)
    assert areal_velocity(M, centre=R0.origin, frame=R0).equals(r**2 * th.diff() / 2 * R0.k)
    assert (areal_constant(M, centre=R0.origin, frame=R0)
            .equals(2 * areal_velocity(M, centre=R0.origin, frame=R0)))
    w, R = sp.symbols("omega R", positive=True)
    N = R0.point("N", R * sp.cos(w * rm.t), R * sp.sin(w * rm.t), 0)
    assert areal_constant(N, centre=R0.origin, frame=R0).equals(R**2 * w * R0.k)
    assert is_central(N, centre=R0.origin, frame=R0)
    assert not is_central(N, centre=R0.point("A", 1, 0, 0), frame=R0)


def test_bad_input():
    theta = sp.Symbol("theta")
    with pytest.raises(ArgumentTypeError, match="`theta` must be a sympy Symbol"):
        binet_acceleration(1 / theta, "theta", 1)
    with pytest.raises(ArgumentTypeError, match="`u` must be a sympy expression"):
        binet_speed_squared(object(), theta, 1)
    R0 = rm.Frame("R0")
    with pytest.raises(ArgumentTypeError, match="`frame` must be a Frame"):
        areal_velocity(R0.origin, centre=R0.origin, frame=R0.origin)
    with pytest.raises(ArgumentTypeError, match="`centre` must be a Point"):
        areal_constant(R0.origin, centre=R0.i, frame=R0)
