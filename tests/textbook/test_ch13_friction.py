"""Book ch. 13.1: laws of contact between solids — Coulomb friction and its cone, rolling and
pivoting resistance, one-sided contact.

Conventions: R0 = (O; i, j, k), j pointing up, the contact normal pointing into the body
acted on. Expected values are the classical closed forms stated with each case.
"""

import math

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.actions import ContactLaws, Coulomb, Couple, Force, gravity, power
from rigidmech.statics import Statics, limiting_equilibrium


def test_ch13_limit_angle_of_an_incline_is_the_cone_half_angle():
    # a block on an incline is at rest up to alpha = phi_s = arctan(f_s) (ch. 13.1.2): the
    # weight leaves the friction cone there
    alpha = sp.Symbol("alpha", real=True)
    law = Coulomb(0.35, 0.3)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=alpha)
    block = rm.Body("block", frame=R1, mass=1.0, centre=R1.origin)
    st = Statics(R0)
    st.connect(R0, block, ContactLaws(at=R1.origin, normal=R1.j, tangent=R1.i, friction=law),
               label="I")
    st.act(gravity(-9.81 * R0.j))
    lim = limiting_equilibrium(st, alpha, (0.0, 1.2))
    assert math.isclose(lim.value, float(law.cone_half_angle), rel_tol=1e-9)


def test_ch13_power_of_sliding_friction_is_minus_f_N_v():
    # a block translating with x(t) on a floor: the friction slider at I has power
    # {-f_k N v/|v| ; 0} . {0 ; v} = -f_k N |x'| (ch. 11.3.1, 13.1.2)
    x = rm.coordinates("x")
    f, N = rm.constants("f N", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    V = rm.kinematic_torsor(R1, relative_to=R0, at=R1.origin)
    c = ContactLaws(at=R1.origin, normal=R0.j, tangent=R0.i, friction=Coulomb(f))
    A = c.action(N, V)
    p = power(A, V)
    v = sp.Symbol("v", positive=True)
    xdot = sp.diff(x, rm.t)
    assert sp.simplify(p.subs(xdot, v) + f * N * v) == 0          # sliding along +i
    assert sp.simplify(p.subs(xdot, -v) + f * N * v) == 0         # sliding along -i


@pytest.mark.parametrize("delta, fs, kind, expected", [
    # wheel of radius r = 0.3 and weight W = 100 pushed at its axle by F: it starts rolling at
    # F = delta W / r (moments about I: F r = M_r <= delta N), sliding at F = f_s W
    pytest.param(0.003, 0.5, "rolling", 0.003 * 100 / 0.3, id="rolls-F=delta-W-over-r"),
    pytest.param(0.2, 0.5, "sliding", 0.5 * 100, id="slides-when-delta-over-r>fs"),
])
def test_ch13_rolling_resistance_wheel(delta, fs, kind, expected):
    F = sp.Symbol("F", real=True)
    R0 = rm.Frame("R0")
    wheel = rm.Body("wheel", frame=R0)
    st = Statics(R0)
    st.connect(R0, wheel, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
                                  friction=Coulomb(fs), rolling=delta, rolling_axis=R0.k),
               label="I")
    axle = R0.point("C", 0, 0.3, 0)
    st.act(Force(on=wheel, vector=-100.0 * R0.j, at=axle))
    st.act(Force(on=wheel, vector=F * R0.i, at=axle))
    lim = limiting_equilibrium(st, F, (0.0, 100.0))
    assert lim.kinds == (kind,)
    assert math.isclose(lim.value, expected, rel_tol=1e-9)


def test_ch13_pivoting_resistance_disc():
    # a disc pressed on a floor by W = 40 turns about the normal once the couple C reaches
    # eta N = eta W (ch. 13.1.3)
    C = sp.Symbol("C", real=True)
    R0 = rm.Frame("R0")
    disc = rm.Body("disc", frame=R0)
    st = Statics(R0)
    st.connect(R0, disc, ContactLaws(at=R0.origin, normal=R0.j, pivoting=0.02), label="I")
    st.act(Force(on=disc, vector=-40.0 * R0.j, at=R0.point("G", 0, 0.01, 0)))
    st.act(Couple(on=disc, moment=C * R0.j))
    lim = limiting_equilibrium(st, C, (0.0, 5.0))
    assert lim.kinds == ("pivoting",)
    assert math.isclose(lim.value, 0.02 * 40.0, rel_tol=1e-9)


def test_ch13_one_sided_contact_opens():
    # a bar of weight W on two supports A (x=0) and B (x=2) with a load P at x=3 (overhang):
    # N_A = W/2 - P/2 (moments about B) vanishes at P = W: contact A opens (lift-off)
    P = sp.Symbol("P", real=True)
    W = 10.0
    R0 = rm.Frame("R0")
    bar = rm.Body("bar", frame=R0)
    st = Statics(R0)
    st.connect(R0, bar, ContactLaws(at=R0.origin, normal=R0.j), label="A")
    st.connect(R0, bar, ContactLaws(at=R0.point("B", 2, 0, 0), normal=R0.j), label="B")
    st.act(Force(on=bar, vector=-W * R0.j, at=R0.point("G", 1, 0, 0)))
    st.act(Force(on=bar, vector=-P * R0.j, at=R0.point("D", 3, 0, 0)))
    lim = limiting_equilibrium(st, P, (0.0, 30.0))
    assert lim.kinds == ("lift-off",) and lim.contacts == ("A",)
    assert math.isclose(lim.value, W, rel_tol=1e-9)
