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

import rigidmech as rm
from rigidmech.actions import Coulomb, FrictionContact
from rigidmech.errors import ArgumentError
from rigidmech.kinematics import ContactKinematics
from rigidmech.regimes import contact_motion

R, E, TH0 = 0.1, 0.03, 0.5


@pytest.fixture(scope="module")
def rocking():
    x, y, th = rm.coordinates("x y theta")
    m, r, ecc, g = sp.symbols("m r ecc g", positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    xc, yc, _ = G.moved("C", ecc * R1.j).coordinates(R0)
    disk = rm.Body("disk", frame=R1, mass=m, centre=G,
                   inertia=rm.inertia.disk(m, r, axis=R1.k, centre=G))
    s = rm.System(galilean=R0)
    s.connect(R0, disk, FrictionContact(
        ContactKinematics(R1, R0, at=R0.point("I", xc, yc - r, 0), normal=R0.j),
        friction=Coulomb(0.8), gap=yc - r))
    s.act(rm.gravity(-g * R0.j))
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
