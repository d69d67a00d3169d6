"""Rolling resistance in FrictionContact (ch. 13.1.3): a cylinder (mass m, radius r,
moment of inertia beta m r^2 about its axis, beta = 1/2) on a plane of slope alpha, x down
the slope, theta its rotation (x' = r theta' when it rolls without slipping), against
closed forms.

While it rolls the couple of rolling resistance is -delta N sign(theta') (delta a length),
N = m g cos(alpha). Rolling without slipping: m x'' = m g sin(alpha) + T and
beta m r^2 theta'' = -T r - delta N sign(theta'), so
x'' = g (sin(alpha) - (delta / r) cos(alpha) sign(x')) / (1 + beta). At rest the couple that
holds it is m g r sin(alpha) (moments about the centre with T = -m g sin(alpha)): it stays
at rest iff tan(alpha) <= delta / r.
"""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.actions import Coulomb, FrictionContact, RollingResistance
from rigidmech.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from rigidmech.kinematics import ContactKinematics
from rigidmech.regimes import contact_motion

G_ACC, R, MASS, DELTA, BETA = 9.81, 0.1, 2.0, 0.002, 0.5


def cylinder_system(law, delta=DELTA):
    x, y, th = rm.coordinates("x y theta")
    m, r, g, alpha = sp.symbols("m r g alpha", positive=True)
    R0 = rm.Frame("R0")
    C = R0.point("C", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=-th, origin=C)
    cyl = rm.Body("cylinder", frame=R1, mass=m, centre=C,
                  inertia=rm.inertia.disk(m, r, axis=R1.k, centre=C))
    s = rm.System(galilean=R0)
    s.connect(R0, cyl, FrictionContact(
        ContactKinematics(R1, R0, at=R0.point("I", x, y - r, 0), normal=R0.j),
        friction=law, rolling=RollingResistance(delta)))
    s.act(rm.gravity(g * (sp.sin(alpha) * R0.i - sp.cos(alpha) * R0.j)))
    return s


@pytest.fixture(scope="module")
def cylinder():
    return cylinder_system(Coulomb(0.3, 0.25))


def run(system, t_end, alpha, v0=0.0, omega0=None):
    omega0 = v0 / R if omega0 is None else omega0
    return contact_motion(system, t_end, {"y": R}, {"x": v0, "theta": omega0}, rtol=1e-12,
                          m=MASS, r=R, g=G_ACC, alpha=alpha)


def test_cylinder_rolling_on_a_horizontal_plane_stops_at_the_closed_form_time(cylinder):
    """x'' = -delta g / (r (1 + beta)): stops at t* = v0 r (1 + beta) / (delta g), after
    x* = v0 t* / 2, and stays at rest."""
    v0 = 2.0
    decel = DELTA * G_ACC / (R * (1 + BETA))
    t_stop = v0 / decel
    m = run(cylinder, t_stop + 2.0, 0.0, v0)
    assert m.regimes == ("stick, rolls+", "stick, locked")
    assert m.phases[0].ended_by == "I stops rolling"
    assert m.switch_times[0] == pytest.approx(t_stop, abs=1e-9)
    assert m.phases[0].y_end[0] == pytest.approx(v0 * t_stop / 2, abs=1e-9)
    assert m(0.5 * t_stop)[3] == pytest.approx(v0 / 2, abs=1e-9)
    N, M_r, w = m.rolling_couples(1.0)["I"]
    assert N == pytest.approx(MASS * G_ACC, rel=1e-12)
    assert M_r == pytest.approx(-DELTA * N, rel=1e-12) and w > 0
    N, T, _ = m.contact_actions(1.0)["I"]
    assert T[0] == pytest.approx(-MASS * decel, rel=1e-12)       # m x'' = T
    np.testing.assert_allclose(m.phases[-1].y_end[3:], 0.0, atol=1e-12)
    assert m.rolling_couples(t_stop + 1.0)["I"][1] == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("factor", [1 - 1e-6, 1 + 1e-6])
def test_cylinder_on_an_incline_stays_at_rest_iff_tan_alpha_below_delta_over_r(cylinder,
                                                                                factor):
    alpha = math.atan(factor * DELTA / R)
    m = run(cylinder, 1.0, alpha)
    N, M_r, _ = m.rolling_couples(0.0)["I"]
    assert N == pytest.approx(MASS * G_ACC * math.cos(alpha), rel=1e-12)
    if factor < 1:
        assert m.regimes == ("stick, locked",)
        assert abs(M_r) == pytest.approx(MASS * G_ACC * R * math.sin(alpha), rel=1e-12)
        np.testing.assert_allclose(m.phases[-1].y_end[3:], 0.0, atol=1e-12)
    else:
        assert m.regimes == ("stick, rolls+",)
        a = G_ACC * (math.sin(alpha) - DELTA / R * math.cos(alpha)) / (1 + BETA)
        assert m(1.0)[0] == pytest.approx(a / 2, abs=1e-12)


@pytest.mark.parametrize("tan_alpha, regimes", [
    (0.01, ("stick, rolls-", "stick, locked")),      # held: tan(alpha) < delta / r = 0.02
    (0.05, ("stick, rolls-", "stick, rolls+")),      # rolls back down, no phase between
])
def test_cylinder_launched_uphill_stops_then_rests_or_rolls_back(cylinder, tan_alpha,
                                                                 regimes):
    """Uphill (x' < 0): x'' = g (sin(alpha) + (delta / r) cos(alpha)) / (1 + beta) until
    x' = 0; then at rest iff tan(alpha) <= delta / r, else rolls down with
    x'' = g (sin(alpha) - (delta / r) cos(alpha)) / (1 + beta)."""
    alpha, v0 = math.atan(tan_alpha), -1.0
    up = G_ACC * (math.sin(alpha) + DELTA / R * math.cos(alpha)) / (1 + BETA)
    t1 = -v0 / up
    m = run(cylinder, t1 + 1.0, alpha, v0)
    assert m.regimes == regimes
    assert m.switch_times[0] == pytest.approx(t1, abs=1e-9)
    x1 = v0 * t1 / 2
    if regimes[-1] == "stick, locked":
        assert m.phases[-1].y_end[0] == pytest.approx(x1, abs=1e-9)
    else:
        down = G_ACC * (math.sin(alpha) - DELTA / R * math.cos(alpha)) / (1 + BETA)
        assert m.phases[-1].y_end[0] == pytest.approx(x1 + down / 2, abs=1e-9)


def test_cylinder_launched_sliding_without_spin_slips_then_rolls_then_stops(cylinder):
    """Horizontal, v0 without spin: while slipping, s = x' - r theta' decreases at the rate
    g (f_k (1 + 1/beta) - delta / (beta r)) (friction f_k N at I, rolling couple -delta N);
    then it rolls without slipping with x'' = -delta g / (r (1 + beta)) and stops."""
    fk, v0 = 0.25, 2.0
    rate = G_ACC * (fk * (1 + 1 / BETA) - DELTA / (BETA * R))
    t1 = v0 / rate
    v1 = v0 - fk * G_ACC * t1
    t2 = t1 + v1 * R * (1 + BETA) / (DELTA * G_ACC)
    m = run(cylinder, t2 + 1.0, 0.0, v0, omega0=0.0)
    assert m.regimes == ("slip+, rolls+", "stick, rolls+", "stick, locked")
    np.testing.assert_allclose(m.switch_times, [t1, t2], atol=1e-9)
    assert m.phases[0].y_end[3] == pytest.approx(v1, abs=1e-9)


@pytest.mark.parametrize("tan_alpha, v0, omega0", [(0.0, 1.5, 15.0), (0.03, -1.0, -10.0),
                                                    (0.01, 2.0, 0.0), (0.3, 0.0, 0.0)])
def test_rolling_couple_never_does_positive_work(cylinder, tan_alpha, v0, omega0):
    m = run(cylinder, 3.0, math.atan(tan_alpha), v0, omega0)
    for p in m.phases:
        for s in np.linspace(p.start, p.end, 7):
            N, M_r, w = m.rolling_couples(s)["I"]
            assert N > 0 and abs(M_r) <= DELTA * N * (1 + 1e-12)
            assert M_r * w <= 1e-12 * (1 + N)


def test_rolling_resistance_bad_input():
    R0 = rm.Frame("R0")
    kin = ContactKinematics(R0, R0, at=R0.origin, normal=R0.j)
    with pytest.raises(ArgumentTypeError, match="`rolling` must be a RollingResistance"):
        FrictionContact(kin, friction=Coulomb(0.2), rolling=0.002)
    with pytest.raises(ArgumentError, match="`coefficient` must be a length >= 0"):
        RollingResistance(-0.001)
    symbolic = cylinder_system(Coulomb(0.2), sp.Symbol("delta", positive=True))
    with pytest.raises(ArgumentError, match="rolling-resistance coefficient of contact I"):
        run(symbolic, 1.0, 0.0)


def test_rolling_resistance_of_a_ball_in_space_is_refused():
    """Two tangential components of the rolling rotation: not supported (planar only)."""
    x, y, z, a, b, c = rm.coordinates("x y z a b c")
    R0 = rm.Frame("R0")
    C = R0.point("C", x, y, z)
    Ra = R0.rotated("Ra", about=R0.i, angle=a, origin=C)
    Rb = Ra.rotated("Rb", about=Ra.j, angle=b)
    Rc = Rb.rotated("Rc", about=Rb.k, angle=c)
    s = rm.System(galilean=R0)
    s.connect(R0, rm.Body("ball", frame=Rc, mass=1, centre=C,
                          inertia=rm.inertia.sphere(1, 1, frame=Rc, centre=C)),
              FrictionContact(ContactKinematics(Rc, R0, at=R0.point("I", x, y, z - 1),
                                                normal=R0.k), friction=Coulomb(0.3),
                              rolling=RollingResistance(0.01)))
    s.act(rm.gravity(-R0.k))
    with pytest.raises(ConnectionError_, match="needs a planar rolling"):
        contact_motion(s, 1.0, {"z": 1.0})
