"""Pivoting resistance in FrictionContact (ch. 13.1.3): a thin disk (mass m, radius a,
moment of inertia m a^2 / 2 about its axis) lying on a table, centre (x, 0, z), spinning by
psi about the vertical k; against closed forms.

While it spins the couple of pivoting resistance about the normal is -eta N sign(psi'),
N = m g: psi'' = -2 eta g sign(psi') / a^2, so spun at psi'0 it stops at
t* = psi'0 a^2 / (2 eta g). Under a couple C k it stays at rest iff |C| <= eta m g.
"""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.actions import Coulomb, Couple, FrictionContact, PivotingResistance
from rigidmech.errors import ArgumentTypeError
from rigidmech.kinematics import ContactKinematics
from rigidmech.regimes import contact_motion

G_ACC, A, MASS, ETA = 9.81, 0.2, 1.5, 0.004


def spinning_disk(torque=0):
    x, z, psi = rm.coordinates("x z psi")
    m, a, g = sp.symbols("m a g", positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, 0, z)
    R1 = R0.rotated("R1", about=R0.k, angle=psi, origin=G)
    disk = rm.Body("disk", frame=R1, mass=m, centre=G,
                   inertia=rm.inertia.disk(m, a, axis=R1.k, centre=G))
    s = rm.System(galilean=R0)
    s.connect(R0, disk, FrictionContact(ContactKinematics(R1, R0, at=R0.point("I", x, 0, z),
                                                          normal=R0.k),
                                        friction=Coulomb(0.4), pivoting=PivotingResistance(ETA)))
    s.act(rm.gravity(-g * R0.k))
    if torque:
        s.act(Couple(on=disk, moment=torque * R0.k))
    return s


def test_spinning_disk_stops_at_the_closed_form_time():
    w0 = 12.0
    t_stop = w0 * A**2 / (2 * ETA * G_ACC)
    m = contact_motion(spinning_disk(), t_stop + 1.0, {}, {"psi": w0}, rtol=1e-12, m=MASS,
                       a=A, g=G_ACC)
    assert m.regimes == ("stick, spins+", "stick, no spin")
    assert m.phases[0].ended_by == "I stops spinning"
    assert m.switch_times[0] == pytest.approx(t_stop, abs=1e-9)
    assert m.phases[0].y_end[2] == pytest.approx(w0 * t_stop / 2, abs=1e-9)
    N, M_p, w = m.pivoting_couples(0.5 * t_stop)["I"]
    assert N == pytest.approx(MASS * G_ACC, rel=1e-12)
    assert M_p == pytest.approx(-ETA * N, rel=1e-12) and w == pytest.approx(w0 / 2, abs=1e-9)
    np.testing.assert_allclose(m.phases[-1].y_end[3:], 0.0, atol=1e-12)


@pytest.mark.parametrize("factor", [1 - 1e-6, 1 + 1e-6])
def test_disk_under_a_couple_stays_at_rest_iff_within_eta_m_g(factor):
    C = factor * ETA * MASS * G_ACC
    m = contact_motion(spinning_disk(sp.Symbol("C")), 1.0, {}, rtol=1e-12, m=MASS, a=A,
                       g=G_ACC, C=C)
    if factor < 1:
        assert m.regimes == ("stick, no spin",)
        assert m.pivoting_couples(0.5)["I"][1] == pytest.approx(-C, rel=1e-12)
    else:
        assert m.regimes == ("stick, spins+",)
        accel = 2 * (C - ETA * MASS * G_ACC) / (MASS * A**2)
        assert m(1.0)[2] == pytest.approx(accel / 2, abs=1e-12)


def test_pivoting_must_be_a_pivoting_resistance():
    R0 = rm.Frame("R0")
    with pytest.raises(ArgumentTypeError, match="`pivoting` must be a PivotingResistance"):
        FrictionContact(ContactKinematics(R0, R0, at=R0.origin, normal=R0.k), pivoting=0.01)


def test_pivoting_couple_never_does_positive_work():
    m = contact_motion(spinning_disk(sp.Symbol("C") * sp.sin(rm.t)), 6.0, {}, {"psi": 1.0},
                       rtol=1e-10, m=MASS, a=A, g=G_ACC, C=3 * ETA * MASS * G_ACC)
    assert len(m.phases) >= 2                   # it stops spinning one way at least once
    for p in m.phases:
        for s in np.linspace(p.start, p.end, 5):
            N, M_p, w = m.pivoting_couples(s)["I"]
            assert abs(M_p) <= ETA * N * (1 + 1e-12) and M_p * w <= 1e-12
    assert math.isfinite(m(6.0)[2])
