"""Book ch. 14.3: statics of wires and flexible cables.

Every expected value is an independent closed form written out in the comment of its case
(the catenary y = a cosh(x/a) about its vertex, a = H/w; the parabola H y'' = q; the
Euler-Eytelwein law T1 = T2 e^{f alpha}), or the defining equation of the quantity checked
against a second route (scipy's quad for lengths, the vertical equilibrium of the whole
cable for the support forces).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.integrate import quad

import rigidmech as rm
from rigidmech._core.errors import ArgumentError
from rigidmech.actions.contact_laws import Coulomb
from rigidmech.statics import (
    Catenary,
    ParabolicCable,
    belt_slip_torque,
    capstan_ratio,
    hoisting_force,
    holding_force,
)

L, w, H = 100.0, 10.0, 5000.0
a = H / w


def level_catenary_from_tension():
    # level supports, vertex at mid-span: sag = a (cosh(L/2a) - 1), S = 2 a sinh(L/2a),
    # T_support = H cosh(L/2a) (= H + w sag)
    c = Catenary(span=L, weight_per_length=w, horizontal_tension=H)
    got = [c.sag, c.length, *c.support_tensions, c.lowest_point[0]]
    u = L / (2 * a)
    expected = [a * (math.cosh(u) - 1), 2 * a * math.sinh(u), H * math.cosh(u),
                H * math.cosh(u), L / 2]
    return got, expected


def level_catenary_from_length():
    # the same cable given by its length: the horizontal tension must come back
    S = 2 * a * math.sinh(L / (2 * a))
    c = Catenary(span=L, weight_per_length=w, length=S)
    return [c.horizontal_tension, c.parameter], [H, a]


def uneven_catenary_tension_difference():
    # T = H + w (y - y_vertex) all along the cable, so T_B - T_A = w h (ch. 14.3.3)
    h = 20.0
    c = Catenary(span=L, weight_per_length=w, horizontal_tension=H, height=h)
    TA, TB = c.support_tensions
    return [TB - TA, float(c.y(L))], [w * h, h]


def uneven_catenary_vertical_equilibrium():
    # the supports carry the whole weight: V_A + V_B = w S
    c = Catenary(span=L, weight_per_length=w, horizontal_tension=800.0, height=-30.0)
    return [sum(c.support_vertical_forces)], [w * c.length]


def uneven_catenary_length_by_quadrature():
    # S = int_0^L sqrt(1 + y'^2) dx, by scipy's quad on the slope
    c = Catenary(span=L, weight_per_length=w, horizontal_tension=700.0, height=35.0)
    S, _ = quad(lambda x: math.sqrt(1 + float(c.slope(x)) ** 2), 0, L, epsabs=0,
                epsrel=2e-14, limit=200)
    return [c.length], [S]


def parabolic_cable_suspension_bridge():
    # y'' = q/H; sag q L^2/8H; support tension sqrt(H^2 + (qL/2)^2); length by quadrature
    q, f = 2.0, 10.0
    c = ParabolicCable(span=L, load_per_horizontal_length=q, sag=f)
    Hq = q * L**2 / (8 * f)
    S, _ = quad(lambda x: math.sqrt(1 + (q / Hq * (x - L / 2)) ** 2), 0, L, epsabs=0,
                epsrel=2e-14)
    return ([c.horizontal_tension, c.support_tensions[0], c.length, float(c.y(L / 2))],
            [Hq, math.hypot(Hq, q * L / 2), S, -f])


def capstan_three_turns():
    # Euler-Eytelwein: T1/T2 = exp(f alpha), alpha = 3 turns
    alpha = 6 * math.pi
    return [capstan_ratio(Coulomb(static=0.3, kinetic=0.25), alpha),
            holding_force(1000.0, 0.3, alpha), hoisting_force(1000.0, 0.3, alpha)], \
        [math.exp(0.3 * alpha), 1000.0 * math.exp(-0.3 * alpha), 1000.0 * math.exp(0.3 * alpha)]


def belt_drive_slip_limit():
    # pulley r = 0.1, f = 0.3, wrap pi: at the limit T1 = T2 e^{f pi} and T1 + T2 = 2 T0,
    # torque C = (T1 - T2) r; solved here by hand from the two equations
    r, T0, e = 0.1, 500.0, math.exp(0.3 * math.pi)
    T2 = 2 * T0 / (1 + e)
    T1 = e * T2
    return [belt_slip_torque(r, 0.3, math.pi, pretension=T0),
            belt_slip_torque(r, 0.3, math.pi, slack_tension=T2)], [(T1 - T2) * r] * 2


@pytest.mark.parametrize("case", [
    pytest.param(level_catenary_from_tension, id="catenary-from-tension-level"),
    pytest.param(level_catenary_from_length, id="catenary-from-length-level"),
    pytest.param(uneven_catenary_tension_difference, id="catenary-TB-minus-TA-equals-w-h"),
    pytest.param(uneven_catenary_vertical_equilibrium, id="catenary-supports-carry-weight"),
    pytest.param(uneven_catenary_length_by_quadrature, id="catenary-length-by-quad"),
    pytest.param(parabolic_cable_suspension_bridge, id="parabolic-cable"),
    pytest.param(capstan_three_turns, id="capstan-three-turns"),
    pytest.param(belt_drive_slip_limit, id="belt-drive-slip-torque"),
])
def test_ch14_cables(case):
    got, expected = case()
    # closed forms evaluated in double precision: agreement to 1e-12 relative
    assert_allclose(got, expected, rtol=1e-12, atol=0)


@settings(max_examples=60, deadline=None)
@given(span=st.floats(0.1, 1000), height_ratio=st.floats(-3, 3),
       slack=st.floats(1e-8, 20.0))
def test_catenary_from_length_meets_its_equations(span, height_ratio, slack):
    # from the length, the cable passes through B and its length is the one asked, to 1e-12,
    # from nearly taut (slack 1e-8) to very slack (20 times the chord)
    h = height_ratio * span
    S = math.hypot(span, h) * (1 + slack)
    c = Catenary(span=span, weight_per_length=3.0, length=S, height=h)
    assert_allclose(c.length, S, rtol=1e-12)
    assert_allclose(float(c.y(span)), h, rtol=1e-12, atol=1e-12 * span)
    assert_allclose(float(c.arc_length(span)), S, rtol=1e-12)
    # tension and horizontal tension: T(x) = H sqrt(1 + y'^2) at the supports
    TA, TB = c.support_tensions
    assert_allclose([TA, TB], c.horizontal_tension * np.sqrt(1 + c.slope([0, span]) ** 2),
                    rtol=1e-12)


def test_catenary_shape_is_a_curve_with_curvature_w_over_H_at_the_vertex():
    c = Catenary(span=L, weight_per_length=w, horizontal_tension=H, height=10.0)
    R0 = rm.Frame("R0")
    curve = c.shape(R0)
    assert isinstance(curve, rm.Curve)
    x0 = c.lowest_point[0]
    assert_allclose(float(curve.curvature(at=x0)), w / H, rtol=1e-12)
    assert_allclose(float(curve.arc_length(0, L, method="numeric")), c.length, rtol=1e-10)
    assert_allclose(float(curve.position(at=L).components(R0)[1]), 10.0, rtol=1e-12)


@pytest.mark.parametrize("kwargs, match", [
    pytest.param(dict(span=10.0, weight_per_length=1.0, length=9.0), r"`length` must exceed",
                 id="shorter-than-span"),
    pytest.param(dict(span=3.0, weight_per_length=1.0, length=5.0, height=4.0),
                 r"`length` must exceed", id="exactly-the-chord"),
    pytest.param(dict(span=10.0, weight_per_length=1.0), r"exactly one of", id="neither"),
    pytest.param(dict(span=10.0, weight_per_length=1.0, length=12.0, horizontal_tension=3.0),
                 r"exactly one of", id="both"),
    pytest.param(dict(span=-1.0, weight_per_length=1.0, length=12.0), r"`span` must be",
                 id="negative-span"),
    pytest.param(dict(span=1.0, weight_per_length=0.0, length=2.0),
                 r"`weight_per_length` must be", id="weightless"),
    pytest.param(dict(span=100.0, weight_per_length=10.0, horizontal_tension=1e-3),
                 r"`horizontal_tension` must exceed", id="tension-too-small-overflows"),
])
def test_catenary_bad_input(kwargs, match):
    with pytest.raises(ArgumentError, match=match):
        Catenary(**kwargs)


def test_capstan_bad_input():
    with pytest.raises(ValueError, match=r"`friction` must be a finite coefficient >= 0"):
        capstan_ratio(-0.1, 1.0)
    with pytest.raises(ValueError, match=r"`angle`"):
        capstan_ratio(0.1, -1.0)
    with pytest.raises(ValueError, match=r"exactly one of `slack_tension` and `pretension`"):
        belt_slip_torque(0.1, 0.3, 1.0)
    with pytest.raises(ValueError, match=r"exactly one of `horizontal_tension` and `sag`"):
        ParabolicCable(span=1.0, load_per_horizontal_length=1.0)
