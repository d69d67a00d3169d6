"""Box pushed on a rough floor, posed from bodies (two corner contacts A, B with friction)
and integrated by contact_motion: it slides or tips first (ch. 13.1, 14, 23).

Geometry: a box of width 2a, height 2b, mass m, centre G = (x, y), tilt phi about k; its
rear corner A = G - a i1 - b j1 and front corner B = G + a i1 - b j1 on the floor y = 0
(each with its gap, the corner's height); a horizontal push P(t) i on the rear face at the
height h above the floor. At rest both corners stick: the split of the friction between A
and B is undetermined (hyperstatic), the total T_A + T_B = -P and the normal forces
N_A = (m g - P h / a) / 2, N_B = (m g + P h / a) / 2 are determined. The box starts sliding
when P = f_s m g (total friction at the sum of the limits f_s (N_A + N_B)) and tipping about
B when N_A = 0, P = m g a / h: it slides first iff f_s < a / h.

References: the hand-written :func:`rigidmech.regimes.pushed_box` (same phases, switching
instants to 1e-9 at rtol 1e-12) and closed forms.
"""

import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad
from scipy.optimize import brentq

import rigidmech as rm
from rigidmech.actions import Coulomb, Force, FrictionContact
from rigidmech.kinematics import ContactKinematics
from rigidmech.regimes import contact_motion, pushed_box
from rigidmech.vectors import t as time

M, A, B, H, G_ACC = 1.0, 0.5, 0.5, 1.0, 10.0
P0 = sp.Symbol("P0", positive=True)


def box_system(law, push):
    x, y, phi = rm.coordinates("x y phi")
    m, a, b, h, g = sp.symbols("m a b h g", positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=phi, origin=G)
    box = rm.Body("box", frame=R1, mass=m, centre=G,
                  inertia=rm.inertia.rectangular_plate(m, 2 * a, 2 * b, frame=R1, centre=G))
    s = rm.System(galilean=R0)
    for name, side in (("A", -1), ("B", 1)):
        corner = G.moved(name, side * a * R1.i - b * R1.j)
        s.connect(R0, box, FrictionContact(ContactKinematics(R1, R0, at=corner, normal=R0.j),
                                           friction=law, gap=corner.coordinates(R0)[1]))
    s.act(rm.gravity(-g * R0.j))
    s.act(Force(on=box, vector=push * R0.i, at=G.moved("P", -a * R1.i + (h - b) * R1.j)))
    return s


def run(law, push, p0, t_end):
    ours = contact_motion(box_system(law, push), t_end, {"y": B}, rtol=1e-12, max_step=0.1,
                          m=M, a=A, b=B, h=H, g=G_ACC, P0=p0)
    fn = sp.lambdify(time, push.subs(P0, p0))
    hand = pushed_box(mass=M, half_width=A, half_height=B, push_height=H, push=fn,
                      friction=law, g=G_ACC, t_end=t_end, max_step=0.1)
    return ours, hand


def test_box_at_rest_normal_forces_and_friction_split_by_the_limits():
    law, p0 = Coulomb(0.6), 4.0
    ours, _ = run(law, P0 * sp.sin(time), p0, 1.0)
    assert ours.regimes == ("A: stick; B: stick",)
    for s in (0.3, 0.9):
        P = p0 * math.sin(s)
        f = ours.contact_actions(s)
        (NA, TA, vA), (NB, TB, vB) = f["A"], f["B"]
        assert NA == pytest.approx((M * G_ACC - P * H / A) / 2, rel=1e-12)
        assert NB == pytest.approx((M * G_ACC + P * H / A) / 2, rel=1e-12)
        assert TA[0] + TB[0] == pytest.approx(-P, rel=1e-12)
        # split in proportion to the limits f_s N: same fraction of each cone
        assert TA[0] / (0.6 * NA) == pytest.approx(TB[0] / (0.6 * NB), rel=1e-12)
        assert abs(vA[0]) < 1e-12 and abs(vB[0]) < 1e-12


@pytest.mark.parametrize("factor", [1 - 1e-6, 1 + 1e-6])
def test_pushed_box_slides_or_tips_first_at_the_closed_form_thresholds(factor):
    """P = P0 sin t: slides at sin t = f_s m g / P0 if f_s < a / h, tips at
    sin t = m g a / (h P0) otherwise."""
    fs, p0 = factor * A / H, 5.05
    ours, hand = run(Coulomb(fs), P0 * sp.sin(time), p0, 1.6)
    slides = fs < A / H
    first = ours.regimes[1]
    assert first == ("A: slip+; B: slip+" if slides else "A: open; B: stick")
    assert hand.regimes[1] == ("slide" if slides else "tip")
    expected = math.asin((fs * M * G_ACC if slides else M * G_ACC * A / H) / p0)
    assert ours.switch_times[0] == pytest.approx(expected, abs=1e-9)
    assert hand.switch_times[0] == pytest.approx(expected, abs=1e-9)


def test_pushed_box_tips_and_falls_back_as_the_hand_written_box():
    """f_s = 1 (the edge B holds), P0 = 5.05: tips at P = m g a / h, rotates about B and
    falls back on A (plastic impact), then stays at rest; phases and states against
    pushed_box (its tilt angle is -phi)."""
    ours, hand = run(Coulomb(1.0), P0 * sp.sin(time), 5.05, math.pi)
    assert ours.regimes == ("A: stick; B: stick", "A: open; B: stick", "A: stick; B: stick")
    assert hand.regimes == ("rest", "tip", "rest")
    assert [p.ended_by for p in ours.phases[:2]] == ["A lifts off", "A lands"]
    np.testing.assert_allclose(ours.switch_times, hand.switch_times, rtol=0, atol=1e-9)
    assert ours.switch_times[0] == pytest.approx(math.asin(M * G_ACC * A / (H * 5.05)),
                                                 abs=1e-9)
    t_mid = 0.5 * sum(ours.switch_times)
    (x, y, phi, _, _, w), (_, _, tilt, tilt_rate) = ours(t_mid), hand(t_mid)
    assert phi == pytest.approx(-tilt, abs=1e-9) and w == pytest.approx(-tilt_rate, abs=1e-9)
    # rotation about the front corner B = (a, 0): G = B + R(phi) (-a, b)
    assert x == pytest.approx(A - A * math.cos(phi) - B * math.sin(phi), abs=1e-9)
    assert y == pytest.approx(-A * math.sin(phi) + B * math.cos(phi), abs=1e-9)
    assert ours.contact_actions(t_mid)["A"][0] == 0.0
    np.testing.assert_allclose(ours.phases[-1].y_end[3:], 0.0, atol=1e-12)


def test_pushed_box_slides_stops_and_slides_again_against_closed_forms():
    """P = P0 sin^2 t, P0 = 4 < m g a / h (never tips), f_s = 0.3, f_k = 0.25: it slides
    where P = f_s m g (sin^2 t = 3/4, t = pi/3), x'' = (P - f_k m g) / m until x' = 0
    (brentq on the closed-form velocity), sticks (P <= f_s m g there) and slides again a
    period pi later; both corners slide and stop together (no spurious phase)."""
    law, p0 = Coulomb(0.3, 0.25), 4.0
    ours, hand = run(law, P0 * sp.sin(time) ** 2, p0, 6.5)
    t1 = math.pi / 3

    def velocity(t):
        return (p0 * ((t - t1) / 2 - (math.sin(2 * t) - math.sin(2 * t1)) / 4)
                - 0.25 * M * G_ACC * (t - t1)) / M

    t2 = brentq(velocity, t1 + 0.1, t1 + math.pi)
    assert p0 * math.sin(t2) ** 2 <= 0.3 * M * G_ACC
    assert ours.regimes == ("A: stick; B: stick", "A: slip+; B: slip+") * 2 + (
        "A: stick; B: stick",)
    assert hand.regimes == ("rest", "slide") * 2 + ("rest",)
    np.testing.assert_allclose(ours.switch_times, hand.switch_times, rtol=0, atol=1e-9)
    np.testing.assert_allclose(ours.switch_times[:2], [t1, t2], atol=1e-9)
    np.testing.assert_allclose(ours.switch_times[2:4], [t1 + math.pi, t2 + math.pi],
                               atol=1e-9)
    x2 = quad(velocity, t1, t2, epsabs=1e-13, epsrel=1e-13)[0]
    assert ours.phases[1].y_end[0] == pytest.approx(x2, abs=1e-9)
    assert ours.phases[-1].y_end[0] == pytest.approx(2 * x2, abs=1e-9)
    assert ours.phases[-1].y_end[0] == pytest.approx(hand.phases[-1].y_end[0], abs=1e-9)
    # sliding: T = -f_k (N_A + N_B) = -f_k m g; no rotation, so the moment about G is zero:
    # a (N_B - N_A) + b T - (h - b) P = 0
    P = p0 * math.sin(1.5) ** 2
    f = ours.contact_actions(1.5)
    (NA, TA, _), (NB, TB, _) = f["A"], f["B"]
    assert TA[0] + TB[0] == pytest.approx(-0.25 * M * G_ACC, rel=1e-12)
    assert NA + NB == pytest.approx(M * G_ACC, rel=1e-12)
    assert NB - NA == pytest.approx(((H - B) * P + B * 0.25 * M * G_ACC) / A, rel=1e-12)
