"""Book ch. 11 (11.3) and 20: work of forces along given paths and of actions along given
motions, conservative fields and potential energy.

Conventions: R0 = (O; i, j, k) with k upwards; gravity -m g k; a spring of stiffness k and free
length l0 attached at O pulls its other end M with -k (r - l0) OM / r, r = OM; a dry-friction
force of constant magnitude f opposes the motion: -f T (T the unit tangent). Closed forms:
  gravity      W(A -> B) = -m g (z_B - z_A) on every path (E_p = m g z),
  spring       W(A -> B) = -k/2 [(r_B - l0)^2 - (r_A - l0)^2] (E_p = k (r - l0)^2 / 2),
  friction     W = -f L, L the length of the path travelled (no potential).
"""

import math

import pytest
import sympy as sp
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.actions import (
    curl,
    is_conservative,
    potential_energy_of,
    power_of,
    work_along_motion,
    work_along_path,
)

s = sp.Symbol("s", real=True)
x, y, z = sp.symbols("x y z", real=True)
m, g, a, b, k, l0, f = sp.symbols("m g a b k l0 f", positive=True)
R0 = rm.Frame("R0")


def _paths():
    return {
        "segment": (rm.Curve(R0.vector(1 + s, 2 * s, 3 * s), s, R0), 0, 1),
        "helix": (rm.Curve(R0.vector(a * sp.cos(s), a * sp.sin(s), b * s), s, R0),
                  0, 3 * sp.pi / 2),
        "parabola": (rm.Curve(R0.vector(s, 0, s**2), s, R0), -1, 2),
    }


@pytest.mark.parametrize("name", [
    pytest.param("segment", id="gravity-segment"),
    pytest.param("helix", id="gravity-helix"),
    pytest.param("parabola", id="gravity-parabola"),
])
def test_work_of_gravity_along_paths(name):
    """W = -m g (z_B - z_A), whatever the path (ch. 11.3.2)."""
    path, s0, s1 = _paths()[name]
    zA = path.position(at=s0).components(R0)[2]
    zB = path.position(at=s1).components(R0)[2]
    W = work_along_path(-m * g * R0.k, path, s0, s1)
    assert sp.simplify(W + m * g * (zB - zA)) == 0


def _spring_force(l0_=l0):
    r = sp.sqrt(x**2 + y**2 + z**2)
    return -k * (r - l0_) / r * R0.vector(x, y, z)


@pytest.mark.parametrize("path, s0, s1, rA, rB", [
    pytest.param(rm.Curve(R0.vector(s, 0, 0), s, R0), 1, 3, 1, 3, id="spring-radial"),
    pytest.param(rm.Curve(R0.vector(2 * sp.cos(s), 2 * sp.sin(s), 0), s, R0), 0, 2, 2, 2,
                 id="spring-arc-of-circle"),
    pytest.param(rm.Curve(R0.vector(1 - s, 2 * s, s), s, R0), 0, 1, 1, math.sqrt(5),
                 id="spring-oblique-segment"),
])
def test_work_of_a_spring_along_paths(path, s0, s1, rA, rB):
    """W = -k/2 [(r_B - l0)^2 - (r_A - l0)^2], here with k = 3, l0 = 1/2 (numeric
    integration where sympy cannot)."""
    force = _spring_force().subs({k: 3, l0: sp.Rational(1, 2)})
    W = work_along_path(force, path, s0, s1, variables=(x, y, z))
    expected = -3 / 2 * ((rB - 0.5) ** 2 - (rA - 0.5) ** 2)
    assert_allclose(float(W), expected, rtol=1e-11, atol=1e-12)


@pytest.mark.parametrize("path, s0, s1, length", [
    pytest.param(rm.Curve(R0.vector(a * sp.cos(s), a * sp.sin(s), 0), s, R0), 0, sp.pi / 3,
                 a * sp.pi / 3, id="friction-arc"),
    pytest.param(rm.Curve(R0.vector(a * sp.cos(s), a * sp.sin(s), b * s), s, R0), 0,
                 2 * sp.pi, 2 * sp.pi * sp.sqrt(a**2 + b**2), id="friction-helix-turn"),
    pytest.param(rm.Curve(R0.vector(s, s**2, 0), s, R0), 0, 1,
                 (2 * sp.sqrt(5) + sp.asinh(2)) / 4, id="friction-parabola"),
])
def test_work_of_constant_friction_along_paths(path, s0, s1, length):
    """W = -f L with L the arc length (closed forms: a phi for an arc, 2 pi sqrt(a^2 + b^2)
    for one turn of helix, (2 sqrt 5 + asinh 2)/4 for y = x^2 on [0, 1])."""
    W = work_along_path(-f * path.tangent(), path, s0, s1)
    if W.has(sp.Integral):  # sympy left it: evaluate numerically at f = 1
        W = work_along_path(-path.tangent(), path, s0, s1, method="numeric") * f
    assert_allclose(float((W / (-f * length)).evalf()), 1.0, rtol=1e-11)


def test_work_along_a_parametrised_point():
    """A point M(t) = (R cos wt, R sin wt, h t): gravity does -m g h T over [0, T]."""
    R, w, h, T = sp.symbols("R w h T", positive=True)
    M = R0.point("M", R * sp.cos(w * rm.t), R * sp.sin(w * rm.t), h * rm.t)
    W = work_along_path(-m * g * R0.k, M, 0, T, parameter=rm.t, frame=R0)
    assert sp.simplify(W + m * g * h * T) == 0


@pytest.mark.parametrize("field, expected", [
    pytest.param(-m * g * R0.k, m * g * z, id="gravity"),
    pytest.param(-k * R0.vector(x, y, z), k * (x**2 + y**2 + z**2) / 2, id="linear-spring"),
    pytest.param(R0.vector(2 * x * y, x**2, 0), -(x**2) * y, id="gradient-field"),
])
def test_potential_energy_of_conservative_fields(field, expected):
    """F = -grad E_p with E_p(O) = 0 (ch. 11.3.3)."""
    assert is_conservative(field, R0, (x, y, z))
    assert sp.simplify(potential_energy_of(field, R0, (x, y, z)) - expected) == 0


def test_spring_potential_with_free_length():
    """E_p = k (r - l0)^2 / 2 - k l0^2 / 2 with E_p(O) = 0."""
    Ep = potential_energy_of(_spring_force(), R0, (x, y, z))
    r = sp.sqrt(x**2 + y**2 + z**2)
    assert sp.simplify(Ep - (k * (r - l0) ** 2 / 2 - k * l0**2 / 2)) == 0


def test_non_conservative_field_has_no_potential():
    field = R0.vector(-y, x, 0)
    assert not is_conservative(field, R0, (x, y, z))
    assert tuple(curl(field, R0, (x, y, z))) == (0, 0, 2)
    with pytest.raises(ArgumentError, match="`field` must be conservative .* curl \\(0, 0, 2\\)"):
        potential_energy_of(field, R0, (x, y, z))


def test_work_along_motions():
    """Ch. 11.3, 20: a couple C k0 on a body turning at w does C w T; gravity on a pendulum
    bob from q = 0 to q = pi/2 (q = w t) does -m g L (E_p(start) - E_p(end) with E_p =
    -m g L cos q measured downwards along i0 = vertical down)."""
    q = rm.coordinates("q")
    C, w, T, L = sp.symbols("C w T L", positive=True)
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    bar = rm.Body("bar", frame=R1, mass=m, centre=R0.origin.moved("G", L * R1.i))
    V = rm.kinematic_torsor(R1, relative_to=R0, at=R0.origin)
    assert work_along_motion(rm.couple(C * R0.k, R0.origin), V, start=0, end=T,
                             trajectory={q: w * rm.t}) == C * w * T
    weight = rm.gravity(g * R0.i)  # i0 points down
    P = power_of(weight, [bar], relative_to=R0)
    assert sp.simplify(P + m * g * L * sp.sin(q) * q.diff()) == 0
    W = work_along_motion(weight, [bar], relative_to=R0, start=0, end=sp.pi / (2 * w),
                          trajectory={q: w * rm.t})
    Ep = weight.potential_energy([bar], R0)
    assert sp.simplify(W - (Ep.subs(q, 0) - Ep.subs(q, sp.pi / 2))) == 0
    assert sp.simplify(W + m * g * L) == 0


def test_bad_input():
    with pytest.raises(ArgumentTypeError, match="`path` must be a Curve or a Point"):
        work_along_path(R0.i, R0.i, 0, 1)
    with pytest.raises(ArgumentTypeError, match="`parameter` and `frame` are needed"):
        work_along_path(R0.i, R0.origin, 0, 1)
    with pytest.raises(ArgumentTypeError, match="`variables` must be the 3 symbols"):
        work_along_path(R0.i, rm.Curve(R0.vector(s, 0, 0), s, R0), 0, 1, variables=(x, y))
    with pytest.raises(ArgumentError, match="`method` must be"):
        work_along_path(R0.i, rm.Curve(R0.vector(s, 0, 0), s, R0), 0, 1, method="fast")
    with pytest.raises(ArgumentTypeError, match="`relative_to` is needed"):
        work_along_motion(rm.gravity(R0.k), [], start=0, end=1)
    with pytest.raises(ArgumentTypeError, match="`action` must be a Torsor or an Action"):
        work_along_motion(1, [], start=0, end=1)
    with pytest.raises(ArgumentTypeError, match="`field` must be a Vector"):
        is_conservative(1, R0, (x, y, z))
