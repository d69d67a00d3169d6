"""Scenes of the Earth and of space: a satellite, a probe between the Earth and the Moon, the
Foucault pendulum (book, ch. 19, 24, 27).

The first three are written in a Galilean reference with :class:`~rigidmech.dynamics.System`,
the last in a non-Galilean one:

* ``satellite`` (ch. 27, central motion ch. 8): a satellite S, a point mass, moves in the plane
  (i, j) of the geocentric frame R0 under the attraction of the Earth
  (:class:`~rigidmech.actions.SphericalBodyAttraction`; outside its radius a homogeneous
  Earth attracts as a point mass of parameter mu = G M). Coordinates x, y of S in km, time in
  s. Its energy is conserved and its orbit is the Kepler conic of
  :class:`~rigidmech.kinematics.orbits.Orbit`.
* ``moon-probe`` (ch. 27, the restricted three-body problem): a probe P in the plane of the
  Earth-Moon orbit, in the Galilean frame R0 centred at their barycentre, in the units where
  the Earth-Moon distance and G are 1; the masses mE and mM default to the Earth's and the
  Moon's shares of their total (then the Moon's angular rate is 1 and the time unit 4.34
  days). The Earth E and the Moon M move on their circular orbits, prescribed with time: the
  frame R1 of the pair turns with the angle Omega t about k, Omega = sqrt(mE + mM) (Kepler's
  third law), E = -mu R1.i, M = (1 - mu) R1.i, mu = mM / (mE + mM). The probe (coordinates
  x, y in R0) feels the field of each (:meth:`~rigidmech.actions.Attractor.field`), given as
  forces. The Galilean energy of the probe is not conserved (the Moon moves); Jacobi's
  integral C = Omega² (ξ² + η²) + 2 mE/r_E + 2 mM/r_M - (ξ'² + η'²), with ξ, η the
  coordinates in R1, is.
* ``foucault-pendulum`` (ch. 19, 24): a spherical pendulum (a bob of mass m on a massless rod
  of length L) hung at the point O of the Earth, at the latitude ``lat`` (radians). R0 = (O;
  i east, j north, k up) at t = 0 is taken Galilean; the Earth frame RE turns relative to it
  at the rate Omega about the polar axis cos(lat) j + sin(lat) k (through O: the entrainment
  acceleration of O is part of the apparent gravity g, taken along -RE.k, the local vertical
  that turns with the Earth). The bob's angles alpha (about RE.i, the bob moves north) and
  beta (then about the new j, the bob moves west) are measured in RE. The plane of the swing
  turns relative to the Earth at -Omega sin(lat) (clockwise seen from above in the northern
  hemisphere). Omega can be exaggerated (default 0.05 rad/s) for a short run. Gravity is given
  as a force: its direction turns, so the Galilean energy is not an invariant.

* ``wagon-pendulum`` (ch. 19, 24): a pendulum (a bob of mass m on a massless rod of length L)
  hung at the point O of a wagon whose acceleration a along i0 is constant, written in the
  wagon's reference (``System(galilean=R0, reference=Rw)``: the inertial action of
  entrainment, -m a i0, is added to the bob). theta is the angle of the rod from the downward
  vertical, positive towards the front. The bob oscillates about its relative equilibrium
  tan(theta*) = -a/g with the period 2 pi sqrt(L / sqrt(g^2 + a^2)); the energy relative to the
  wagon, with the potential m a x of the inertial action, is conserved.

Examples
--------
>>> [s.name for s in SPACE_SCENES]
['satellite', 'moon-probe', 'foucault-pendulum', 'wagon-pendulum']
>>> EARTH_MU_KM, round(EARTH_MOON_MU, 5)
(398600.4418, 0.01215)
>>> from rigidmech import scenes
>>> rep = scenes.run("satellite", t_end=600.0)
>>> rep.status, rep.energy_drift < 1e-9
('finished', True)
"""

from __future__ import annotations

import math

import sympy as sp

from ..actions import (
    Force,
    Pivot,
    Spherical,
    SphericalBodyAttraction,
    gravity,
    point_mass_attractor,
)
from ..dynamics import System
from ..kinetics import Body
from ..vectors import Frame, constants, coordinates, t
from .catalogue import Built, Scene

__all__ = ["SPACE_SCENES", "EARTH_MU_KM", "EARTH_MOON_MU"]

EARTH_MU_KM = 398600.4418
"""G M of the Earth in km^3/s^2."""

EARTH_MOON_MU = 0.01215058560962404
"""The Moon's share of the Earth-Moon mass, M_M / (M_E + M_M)."""


def _satellite() -> Built:
    x, y = coordinates("x y")
    m, mu = constants("m mu", positive=True)
    R0 = Frame("R0")
    S = R0.point("S", x, y, 0)
    sat = Body("satellite", frame=R0.translated("Rs", S), mass=m, centre=S)
    system = System(galilean=R0)
    system.add(sat)
    system.act(SphericalBodyAttraction(point_mass_attractor(mu, G=1), centre=R0.origin))
    return Built(system, (sat,))


def _moon_probe() -> Built:
    x, y = coordinates("x y")
    m, mE, mM = constants("m mE mM", positive=True)
    R0 = Frame("R0")
    Omega = sp.sqrt(mE + mM)                       # Kepler's third law with D = 1, G = 1
    R1 = R0.rotated("R1", about=R0.k, angle=Omega * t)   # the Earth-Moon line
    E = R0.origin.moved("E", -mM / (mE + mM) * R1.i)
    M = R0.origin.moved("M", mE / (mE + mM) * R1.i)
    P = R0.point("P", x, y, 0)
    probe = Body("probe", frame=R0.translated("Rp", P), mass=m, centre=P)
    system = System(galilean=R0)
    system.add(probe)
    for body, centre in ((point_mass_attractor(mE, G=1), E), (point_mass_attractor(mM, G=1), M)):
        system.act(Force(on=probe, vector=m * body.field(P, centre=centre), at=P))
    return Built(system, (probe,))


def _foucault_pendulum() -> Built:
    alpha, beta = coordinates("alpha beta")
    m, L, g, Omega = constants("m L g Omega", positive=True)
    lat = constants("lat", real=True)
    R0 = Frame("R0")
    RE = R0.rotated("RE", about=sp.cos(lat) * R0.j + sp.sin(lat) * R0.k, angle=Omega * t)
    Ra = RE.rotated("Ra", about=RE.i, angle=alpha)
    Rb = Ra.rotated("Rb", about=Ra.j, angle=beta)
    O = R0.origin
    P = O.moved("P", -L * Rb.k)
    bob = Body("bob", frame=Rb, mass=m, centre=P)
    system = System(galilean=R0)
    system.connect(R0, bob, Spherical(at=O))
    system.act(Force(on=bob, vector=-m * g * RE.k, at=P))
    return Built(system, (bob,))


def _wagon_pendulum() -> Built:
    th = coordinates("theta")
    m, L, g, a = constants("m L g a", positive=True)
    R0 = Frame("R0")
    Rw = R0.translated("Rw", R0.point("W", a * t**2 / 2, 0, 0))
    Rp = Rw.rotated("Rp", about=Rw.k, angle=th)
    bob = Body("bob", frame=Rp, mass=m, centre=Rw.origin.moved("P", -L * Rp.j))
    system = System(galilean=R0, reference=Rw)
    system.connect(Rw, bob, Pivot(at=Rw.origin, axis=Rw.k))
    system.act(gravity(-g * R0.j))
    return Built(system, (bob,))


SPACE_SCENES = (
    Scene("satellite", "A satellite on its orbit about the Earth", "ch. 8.3, 27",
          coordinates=("x", "y"),
          parameters=(("m", 1.0, "mass of the satellite (drops out)"),
                      ("mu", EARTH_MU_KM, "G M of the Earth, km^3/s^2")),
          q0=(7000.0, 0.0), u0=(0.0, 8.0), t_end=7200.0, rtol=1e-11, atol=1e-8,
          builder=_satellite, units={"x": "km", "y": "km"},
          notes="x, y: position of the satellite in the geocentric frame, km; time in s. "
                "The default state gives an ellipse of period about 7100 s."),
    Scene("moon-probe", "A probe in the field of the Earth and the Moon (restricted three "
          "bodies)", "ch. 27",
          coordinates=("x", "y"),
          parameters=(("m", 1.0, "mass of the probe (drops out)"),
                      ("mE", 1.0 - EARTH_MOON_MU, "mass of the Earth (G = 1)"),
                      ("mM", EARTH_MOON_MU, "mass of the Moon (G = 1)")),
          q0=(0.1 - EARTH_MOON_MU, 0.0), u0=(0.0, 4.2), t_end=6.0, rtol=1e-11, atol=1e-12,
          builder=_moon_probe, units={"x": "D", "y": "D"}, time_unit="4.34 days",
          notes="x, y: position of the probe in the barycentric Galilean frame; units: the "
                "Earth-Moon distance D and G = 1 (with the default masses, t = 2 pi is 27.3 "
                "days). The Earth and the Moon move on circular orbits; Jacobi's integral "
                "is conserved."),
    Scene("foucault-pendulum", "Foucault pendulum on the rotating Earth", "ch. 19, 24",
          coordinates=("alpha", "beta"),
          parameters=(("m", 1.0, "mass of the bob"), ("L", 1.0, "length of the pendulum"),
                      ("g", 9.81, "apparent gravity"),
                      ("Omega", 0.05, "rotation rate of the Earth, rad/s (exaggerated; the "
                       "Earth's is 7.292115e-5)"),
                      ("lat", math.pi / 4, "latitude, radians")),
          q0=(0.05, 0.0), t_end=40.0, builder=_foucault_pendulum,
          notes="alpha, beta: angles of the pendulum relative to the Earth (the bob moves "
                "north with alpha, west with beta); the swing plane turns at -Omega sin(lat)."),
    Scene("wagon-pendulum", "Pendulum in an accelerating wagon (non-Galilean reference)",
          "ch. 19, 24",
          coordinates=("theta",),
          parameters=(("m", 1.0, "mass of the bob"), ("L", 1.0, "length of the pendulum"),
                      ("g", 9.81, "gravity"), ("a", 3.0, "acceleration of the wagon")),
          q0=(0.0,), t_end=10.0, builder=_wagon_pendulum,
          notes="theta: angle of the pendulum from the downward vertical, positive towards "
                "the front of the wagon; written in the wagon's reference with the inertial "
                "action. It swings about tan(theta*) = -a/g."),
)
