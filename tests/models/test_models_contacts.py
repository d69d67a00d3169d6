"""The friction contacts of rigidmech.models: geometry and mass matrices against closed
forms, and the ball's switch from sliding to rolling at 5/7 of its speed (ch. 13.1.2)."""

import pytest
import sympy as sp

from rigidmech import models
from rigidmech.regimes import contact_motion


def test_sliding_ball_contact_point_is_r_below_the_centre():
    model = models.sliding_ball()
    x, y, z, *_ = model.coordinates
    m, r, g = model.constants
    R0 = model.frame("R0")
    assert list(model.point("I").coordinates(R0)) == [x, y, z - r]
    assert model.body("ball").inertia.matrix == sp.eye(3) * 2 * m * r**2 / 5
    M = model.system.equations_of_motion(open_contacts=True).mass_matrix
    assert M[:3, :3] == sp.eye(3) * m


def test_sliding_ball_slides_then_rolls_at_five_sevenths_of_v0():
    # launched at v0 without spin: slides until t* = 2 v0 / (7 mu g), then rolls at 5 v0 / 7
    v0, mu, r, g = 1.0, 0.3, 0.5, 9.81
    motion = contact_motion(models.sliding_ball(mu).system, 0.5, {"z": r}, {"x": v0},
                            rtol=1e-12, m=1.0, r=r, g=g)
    assert motion.regimes == ("slip", "stick")
    assert motion.switch_times[0] == pytest.approx(2 * v0 / (7 * mu * g), abs=1e-9)
    assert motion.phases[-1].y_end[6] == pytest.approx(5 * v0 / 7, abs=1e-9)


def test_eccentric_disc_gap_is_the_height_of_its_centre_minus_r():
    # C = G + ecc j1: y_C = y + ecc cos(theta); the contact point (x_C, y_C - r)
    model = models.eccentric_disc()
    x, y, th = model.coordinates
    m, r, ecc, g = model.constants
    R0 = model.frame("R0")
    xc, yc, _ = model.point("C").coordinates(R0)
    assert sp.simplify(xc - (x - ecc * sp.sin(th))) == 0
    assert sp.simplify(yc - (y + ecc * sp.cos(th))) == 0
    assert sp.simplify(model.point("I").coordinates(R0)[1] - (yc - r)) == 0
    M = model.system.equations_of_motion(open_contacts=True).mass_matrix
    assert sp.simplify(M - sp.diag(m, m, m * r**2 / 2)) == sp.zeros(3, 3)
