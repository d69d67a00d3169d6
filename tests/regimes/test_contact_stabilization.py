"""Baumgarte's stabilisation of the conditions of a regime in contact_motion: an eccentric
disk (radius r, mass centre G at e from its centre C) rocking on a floor without slipping.
Its contact conditions are nonlinear in the coordinates, so an integration at the
acceleration level drifts off them (the gap y_C - r leaves 0); with
``stabilization=(alpha, beta)`` the gap (its position residual) and the normal and sliding
velocities are pulled back."""

import math

import numpy as np
import pytest
import sympy as sp

from rigidmech import models
from rigidmech.errors import ArgumentError
from rigidmech.regimes import contact_motion

R, E, TH0 = 0.1, 0.03, 0.5


@pytest.fixture(scope="module")
def rocking():
    model = models.eccentric_disc(0.8)
    s = model.system
    r, ecc = model.constant("r"), model.constant("ecc")
    xc, yc, _ = model.point("C").coordinates(model.frame("R0"))
    q_sym, _, _, rule = s.symbols()
    centre = sp.lambdify(q_sym, [e.xreplace(rule).subs({ecc: E, r: R}) for e in (xc, yc)])
    return s, centre


def residuals(rocking, stabilization, t_end=40.0):
    s, centre = rocking
    q0 = {"x": -R * TH0 + E * math.sin(TH0), "y": R - E * math.cos(TH0), "theta": TH0}
    m = contact_motion(s, t_end, q0, rtol=1e-8, atol=1e-10, stabilization=stabilization,
                       m=1.0, r=R, ecc=E, g=9.81)
    assert m.regimes == ("stick",)
    ts = np.linspace(0.0, t_end, 801)
    Y = m(ts)
    xc, yc = centre(*Y[:3])
    gap = float(np.max(np.abs(np.asarray(yc) - R)))
    rolling = float(np.max(np.abs(np.asarray(xc) + R * Y[2])))     # x_C = -r theta
    return gap, rolling


def test_stabilisation_keeps_a_rocking_disk_on_its_contact(rocking):
    """The default run's size (10 s): the gap without stabilisation is already about 40
    times the stabilised one (3e-10 against 7e-12); the long run below (slow stage) shows the
    drift growing (400 times at 40 s)."""
    gap0, roll0 = residuals(rocking, None, t_end=10.0)
    gap1, roll1 = residuals(rocking, (20.0, 20.0), t_end=10.0)
    assert gap1 < 1e-10 and roll1 < 1e-9
    assert gap0 > 10 * gap1                  # without: the gap drifts off zero


@pytest.mark.slow
def test_stabilisation_keeps_a_rocking_disk_on_its_contact_over_a_long_run(rocking):
    gap0, roll0 = residuals(rocking, None)
    gap1, roll1 = residuals(rocking, (20.0, 20.0))
    assert gap1 < 1e-10 and roll1 < 1e-9
    assert gap0 > 100 * gap1                 # without: the gap drifts off zero


def test_bad_stabilization_is_refused(rocking):
    with pytest.raises(ArgumentError, match="`stabilization` must be a pair"):
        contact_motion(rocking[0], 1.0, {"y": R - E}, stabilization=(-1.0, 5.0), m=1.0,
                       r=R, ecc=E, g=9.81)
    with pytest.raises(ArgumentError, match="`stabilization` must be a pair"):
        contact_motion(rocking[0], 1.0, {"y": R - E}, stabilization=5.0, m=1.0, r=R,
                       ecc=E, g=9.81)
