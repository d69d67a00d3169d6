"""Drift of the contact conditions of contact_motion over a long run, without and with
Baumgarte's stabilisation (``stabilization=(alpha, beta)``), and its CPU cost.

The system: an eccentric disk (radius r = 0.1, mass centre at e = 0.03 from its centre)
rocking without slipping on a floor from a tilt of 0.5 rad, integrated over 200 s at
rtol 1e-8 (atol 1e-10); its contact conditions are nonlinear in the coordinates. The anchor
is the exact condition: the gap y_C - r and the rolling relation x_C + r theta are 0 on the
exact motion.

Run::

    PYTHONPATH=src python benchmarks/contact_drift.py

Prints, for each setting, the largest gap and rolling residuals over 2001 samples and the
CPU time (time.process_time) of the run.
"""
import math
import time

import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech.actions import Coulomb, FrictionContact
from rigidmech.kinematics import ContactKinematics
from rigidmech.regimes import contact_motion

R, E, TH0, T_END = 0.1, 0.03, 0.5, 200.0


def rocking_disk():
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


def main():
    s, centre = rocking_disk()
    q0 = {"x": -R * TH0 + E * math.sin(TH0), "y": R - E * math.cos(TH0), "theta": TH0}
    print(f"{'stabilization':>14}  {'max |gap|':>10}  {'max |x_C + r th|':>16}  cpu [s]")
    for stab in (None, (5.0, 5.0), (20.0, 20.0)):
        t0 = time.process_time()
        m = contact_motion(s, T_END, q0, rtol=1e-8, atol=1e-10, stabilization=stab, m=1.0,
                           r=R, ecc=E, g=9.81)
        cpu = time.process_time() - t0
        ts = np.linspace(0.0, T_END, 2001)
        Y = m(ts)
        xc, yc = centre(*Y[:3])
        gap = np.max(np.abs(np.asarray(yc) - R))
        roll = np.max(np.abs(np.asarray(xc) + R * Y[2]))
        print(f"{stab!s:>14}  {gap:10.2e}  {roll:16.2e}  {cpu:7.2f}")


if __name__ == "__main__":
    main()
