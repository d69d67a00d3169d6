"""A particle constrained to a curve (Body.particle_on_curve), issue 22 (book, ch. 17-18,
25): the bead on a hoop turning about the vertical, and the isochronous cycloid."""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import Body
from rigidmech.errors import ArgumentError, ArgumentTypeError


def _bead_on_hoop():
    theta = rm.coordinates("theta")
    R, w, m, g = rm.constants("R omega m g", positive=True)
    phi = sp.Symbol("phi", real=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=w * rm.t)          # the hoop turns at omega
    hoop = rm.Curve(R1.vector(R * sp.sin(phi), 0, -R * sp.cos(phi)), phi, R1)
    bead = Body.particle_on_curve("bead", hoop, theta, mass=m)
    s = rm.System(galilean=R0)
    s.add(bead)
    s.act(rm.gravity(-g * R0.k))
    return s, theta, (R, w, m, g), bead


def test_the_bead_on_a_turning_hoop_has_the_closed_form_equation():
    # m R^2 theta'' = m R^2 omega^2 sin(theta) cos(theta) - m g R sin(theta)
    s, theta, (R, w, m, g), bead = _bead_on_hoop()
    eqs = s.equations_of_motion()
    acc = sp.simplify((eqs.mass_matrix.inv() * eqs.forcing)[0])
    q = eqs.coordinates[0]
    expected = (w**2 * sp.cos(q) - g / R) * sp.sin(q)
    assert sp.simplify(acc.subs(theta, q) - expected) == 0


def test_the_bead_rests_where_cos_theta_is_g_over_R_omega_squared():
    s, theta, (R, w, m, g), bead = _bead_on_hoop()
    values = dict(R=0.5, omega=7.0, m=0.1, g=9.81)
    theta_star = math.acos(values["g"] / (values["R"] * values["omega"] ** 2))
    sim = s.equations_of_motion().simulate(t=(0, 3), q0=[theta_star], rtol=1e-11,
                                           atol=1e-12, n_output=31, **values)
    np.testing.assert_allclose(sim.q[0], theta_star, atol=1e-9)
    # slightly off it, the bead oscillates about it (stable for R omega^2 > g), with the
    # small-oscillation frequency omega sin(theta*) (linearised closed form)
    off = s.equations_of_motion().simulate(t=(0, 20), q0=[theta_star + 1e-3], rtol=1e-11,
                                           atol=1e-13, n_output=4001, **values)
    assert np.max(np.abs(off.q[0] - theta_star)) < 1.1e-3
    crossings = off.t[1:][np.diff(np.sign(off.q[0] - theta_star)) != 0]
    half = np.diff(crossings).mean()
    assert math.pi / half == pytest.approx(values["omega"] * math.sin(theta_star), rel=2e-3)


def test_a_particle_on_a_cycloid_is_isochronous():
    # the cycloid x = R (phi + sin phi), z = R (1 - cos phi) (cusps up): the period is
    # 4 pi sqrt(R / g) whatever the amplitude (Huygens)
    phi = rm.coordinates("phi")
    R, m, g = rm.constants("R m g", positive=True)
    p = sp.Symbol("p", real=True)
    R0 = rm.Frame("R0")
    cycloid = rm.Curve(R0.vector(R * (p + sp.sin(p)), 0, R * (1 - sp.cos(p))), p, R0)
    s = rm.System(galilean=R0)
    s.add(Body.particle_on_curve("ball", cycloid, phi, mass=m))
    s.act(rm.gravity(-g * R0.k))
    eqs = s.equations_of_motion()
    values = dict(R=0.8, m=1.0, g=9.81)
    period = 4 * math.pi * math.sqrt(values["R"] / values["g"])
    for amplitude in (0.3, 2.5):
        sim = eqs.simulate(t=(0, 2.2 * period), q0=[amplitude], events=[phi], rtol=1e-11,
                           atol=1e-12, **values)
        crossings = sim.t_events[0]
        assert len(crossings) >= 4
        np.testing.assert_allclose(np.diff(crossings), period / 2, rtol=1e-8)
        assert crossings[0] == pytest.approx(period / 4, rel=1e-8)


def test_the_point_and_its_name():
    s, theta, consts, bead = _bead_on_hoop()
    assert bead.centre.name == "P_bead" and bead.inertia is None
    hoop = rm.Curve(rm.Frame("R0").vector(sp.Symbol("a"), 0, 0), sp.Symbol("a"),
                    rm.Frame("R0"))
    named = Body.particle_on_curve("b", hoop, theta, mass=1, point_name="M")
    assert named.centre.name == "M"


def test_bad_arguments_are_named():
    theta = rm.coordinates("theta")
    R0 = rm.Frame("R0")
    with pytest.raises(ArgumentTypeError, match="`curve` must be a rigidmech.vectors.Curve"):
        Body.particle_on_curve("b", R0.i, theta, mass=1)
    a = sp.Symbol("a", real=True)
    line = rm.Curve(R0.vector(a, 0, 0), a, R0)
    with pytest.raises(ArgumentTypeError, match="`coordinate` must be a sympy expression"):
        Body.particle_on_curve("b", line, object(), mass=1)
    with pytest.raises(ArgumentError, match="`mass` must be given"):
        Body.particle_on_curve("b", line, theta, mass=None)
