"""Book ch. 21 (vibrations of a system with one degree of freedom), ch. 25.4.3 and 27.5.2
(double pendulum, small oscillations), ch. 24/25 (cart and pendulum), relative equilibria in a
rotating reference (bead on a hoop): each exercise posed with rm.System, then analysed by
rigidmech.vibrations, against the book's closed forms (written out in each test).

Conventions (ch. 21.3): m x'' + c x' + k x = F(t), w0 = sqrt(k/m), zeta = c / (2 sqrt(k m)),
F = F0 cos(w t), steady response X cos(w t - phi), r = w / w0.
"""

import math

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech import models
from rigidmech.actions import Damper
from rigidmech.vibrations import (
    coulomb_stop,
    damping_ratio,
    dry_friction_equivalent_damping,
    equilibria,
    free_response,
    half_power_frequencies,
    harmonic_response,
    linearize,
    natural_frequency,
    resonance,
    stability,
    transmissibility,
)


def oscillator():
    """Block m on a spring k and a viscous damper c to the wall (ch. 21.3.1)."""
    x = rm.coordinates("x")
    m, k, c = rm.constants("m k c", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    block = rm.Body("block", frame=R1, mass=m)
    s = rm.System(galilean=R0)
    s.connect(R0, block, rm.joints.Prismatic(at=R1.origin, axis=R0.i))
    s.act(rm.Spring(k, 0, a=R0.origin, b=R1.origin, on_b=block))
    s.act(Damper(c, a=R0.point("A", -1, 0, 0), b=R1.origin, on_b=block))
    return s.equations_of_motion()


@pytest.mark.parametrize("c, zeta, case", [
    pytest.param(4.0, 0.1, "underdamped", id="21.3.2-underdamped-zeta0.1"),
    pytest.param(40.0, 1.0, "critical", id="21.3.2-critical"),
    pytest.param(100.0, 2.5, "overdamped", id="21.3.2-overdamped-zeta2.5"),
])
def test_ch21_3_2_free_damped_oscillator(c, zeta, case):
    """m = 2, k = 200: w0 = 10 rad/s; zeta = c / (2 sqrt(400)) = c / 40. The motion
    simulated from the System's equations is the closed-form free response (ch. 21.3.2)."""
    eqs = oscillator()
    lin = linearize(eqs)
    values = {"m": 2.0, "k": 200.0, "c": c}
    M, C, K, _ = lin.numeric(**values)
    assert natural_frequency(K[0, 0], M[0, 0]) == pytest.approx(10.0, rel=1e-15)
    assert damping_ratio(C[0, 0], K[0, 0], M[0, 0]) == pytest.approx(zeta, rel=1e-15)
    sim = eqs.simulate(t=(0, 2), q0=[0.1], u0=[-0.5], rtol=1e-12, atol=1e-14, **values)
    assert_allclose(sim.q[0], free_response(sim.t, 0.1, -0.5, 10.0, zeta), atol=1e-11)


def test_ch21_3_3_resonance_peak_amplitude_and_bandwidth():
    """w0 = 10, zeta = 0.05: peak at w0 sqrt(1 - 2 zeta^2) = 9.974968..., amplification
    1 / (2 zeta sqrt(1 - zeta^2)) = 10.012523...; half-power bandwidth close to
    2 zeta w0 = 1 and Q = 1/(2 zeta) = 10 (ch. 21.3.3)."""
    wr, Xr = resonance(10.0, 0.05)
    assert wr == pytest.approx(10 * math.sqrt(1 - 2 * 0.05**2), rel=1e-15)
    assert Xr == pytest.approx(1 / (2 * 0.05 * math.sqrt(1 - 0.05**2)), rel=1e-15)
    w1, w2 = half_power_frequencies(10.0, 0.05)
    assert w2**2 - w1**2 == pytest.approx(4 * 0.05 * math.sqrt(1 - 0.05**2) * 100, rel=1e-14)
    assert w2 - w1 == pytest.approx(1.0, rel=0.05**2 * 1.1)  # 2 zeta w0, to O(zeta^2)
    X0, phi0 = harmonic_response(10.0, 10.0, 0.05)
    assert (X0, phi0) == (pytest.approx(10.0), pytest.approx(math.pi / 2))


@pytest.mark.parametrize("r, zeta, expected", [
    pytest.param(math.sqrt(2), 0.3, 1.0, id="21.3.6-r=sqrt2-any-damping"),
    pytest.param(3.0, 0.0, 1 / 8, id="21.3.6-r=3-undamped-1/(r^2-1)"),
    pytest.param(1.0, 0.1, math.sqrt(1 + 0.04) / 0.2, id="21.3.6-r=1-sqrt(1+4z^2)/(2z)"),
])
def test_ch21_3_6_transmissibility(r, zeta, expected):
    assert transmissibility(r, zeta) == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize("x0, n, stop", [
    pytest.param(10.0, 5, 0.0, id="21.4.2-x0=10a-stops-at-0"),
    pytest.param(10.5, 5, -0.5, id="21.4.2-x0=10.5a-stops-at--0.5a"),
    pytest.param(0.8, 0, 0.8, id="21.4.2-inside-the-band-no-motion"),
])
def test_ch21_4_2_coulomb_damping_stop(x0, n, stop):
    """a = F/k = 1: the turning points lose 2a per half-cycle (x0, -(x0-2a), x0-4a, ...)
    and the mass stops at the first one with |x| <= a (ch. 21.4.2)."""
    got_n, t_stop, x_stop = coulomb_stop(x0, 2.0, 1.0)
    assert got_n == n
    assert t_stop == pytest.approx(n * math.pi / 2.0)
    assert x_stop == pytest.approx(stop, abs=1e-14)


def test_ch21_5_4_equivalent_damping_of_dry_friction():
    """Energy dissipated per cycle 4 F X = pi c_eq w X^2 (ch. 21.5.4)."""
    F, w, X = sp.symbols("F omega X", positive=True)
    c_eq = dry_friction_equivalent_damping(F, w, X)
    assert sp.simplify(sp.pi * c_eq * w * X**2 - 4 * F * X) == 0


def test_ch25_4_3_double_pendulum_natural_modes():
    """Two equal point masses m on rods l, absolute angles: w^2 = (g/l)(2 -+ sqrt 2),
    shapes (1, +-sqrt 2) (ch. 25.4.3, 27.5.2)."""
    model = models.point_mass_double_pendulum()
    s, (_, l, g) = model.system, model.constants
    modes = linearize(s.equations_of_motion()).modes()
    w1, w2 = modes.frequencies
    assert sp.simplify(w1**2 - g / l * (2 - sp.sqrt(2))) == 0
    assert sp.simplify(w2**2 - g / l * (2 + sp.sqrt(2))) == 0
    assert sp.simplify(modes.shapes - sp.Matrix([[1, 1], [sp.sqrt(2), -sp.sqrt(2)]])) \
        == sp.zeros(2, 2)


def test_cart_pendulum_linearised_frequency():
    """Cart M free to slide, point mass m on a rod L: besides the free translation (w = 0),
    w^2 = (M + m) g / (M L)."""
    model = models.cart_pendulum()
    s, (M, m, L, g) = model.system, model.constants
    w0, w1 = linearize(s.equations_of_motion()).modes().frequencies
    assert w0 == 0
    assert sp.simplify(w1**2 - (M + m) * g / (M * L)) == 0


def test_bead_on_a_rotating_hoop():
    """Hoop of radius R turning at Omega about its vertical diameter, posed with rm.System
    (the hoop's frame turns by the prescribed angle Omega t): equilibria theta = 0, pi and,
    for Omega^2 > g/R, cos(theta) = g/(R Omega^2); the bottom is stable below
    Omega^2 = g/R and unstable above, where the side equilibria are stable."""
    theta = rm.coordinates("theta")
    m, R, g, W = rm.constants("m R g Omega", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=W * rm.t)
    R2 = R1.rotated("R2", about=R1.j, angle=theta)
    s = rm.System(galilean=R0)
    s.add(rm.Body("bead", frame=R2, mass=m, centre=R0.origin.moved("P", -R * R2.k)))
    s.act(rm.gravity(-g * R0.k))
    eqs = s.equations_of_motion()
    found = [e["theta"] for e in equilibria(eqs)]
    assert 0 in found and sp.pi in found and sp.acos(g / (R * W**2)) in found
    K_bottom = linearize(eqs).K[0]
    assert sp.solve(sp.Eq(K_bottom, 0), W) == [sp.sqrt(g / R)]
    values = {"m": 0.2, "R": 0.3, "g": 9.81}
    crit = math.sqrt(9.81 / 0.3)
    assert stability(eqs, [0], Omega=0.99 * crit, **values) == "stable"
    assert stability(eqs, [0], Omega=1.01 * crit, **values) == "unstable"
    side = math.acos(1 / 1.01**2)
    assert stability(eqs, [side], Omega=1.01 * crit, **values) == "stable"
    # small oscillations about the side equilibrium: w^2 = Omega^2 sin^2(theta*)
    w = linearize(eqs, [side], parameters=dict(values, Omega=1.01 * crit)).modes() \
        .frequencies[0]
    assert w == pytest.approx(1.01 * crit * math.sin(side), rel=1e-10)
    assert_allclose(np.cos(side), 9.81 / (0.3 * (1.01 * crit) ** 2), rtol=1e-14)


def test_ch25_4_3_double_pendulum_of_two_uniform_rods_natural_modes():
    """Two uniform rods m, L, absolute angles: M = m L^2 [[4/3, 1/2], [1/2, 1/3]],
    K = m g L [[3/2, 0], [0, 1/2]]; with x = w^2 L/g, det(K - w^2 M) = 0 reads
    7 x^2 - 42 x + 27 = 0, x = 3 -+ 6 sqrt(7)/7; theta2/theta1 = (-1 +- 2 sqrt 7)/3."""
    model = models.double_pendulum()
    s, (m, L, g) = model.system, model.constants
    lin = linearize(s.equations_of_motion())
    assert lin.M == sp.Matrix([[4, sp.Rational(3, 2)], [sp.Rational(3, 2), 1]]) * m * L**2 / 3
    assert lin.K == sp.Matrix([[3, 0], [0, 1]]) * m * g * L / 2
    modes = lin.modes()
    for w, sign in zip(modes.frequencies, (-1, 1), strict=True):
        assert sp.simplify(w**2 - g / L * (3 + sign * 6 * sp.sqrt(7) / 7)) == 0
    for r, sign in enumerate((1, -1)):
        ratio = modes.shapes[1, r] / modes.shapes[0, r]
        assert sp.simplify(ratio - (-1 + sign * 2 * sp.sqrt(7)) / 3) == 0


def test_ch21_3_3_steady_forced_response_measured_on_a_simulation():
    """m = 1, k = 100, c = 4 (w0 = 10, zeta = 0.2) driven by F0 cos(w t), F0 = 2, w = 8:
    after the transient (decaying as exp(-zeta w0 t) = exp(-2 t)) the simulated motion of the
    System is X cos(w t - phi) with X, phi of ch. 21.3.3."""
    x = rm.coordinates("x")
    m, k, c = rm.constants("m k c", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    block = rm.Body("block", frame=R1, mass=m)
    s = rm.System(galilean=R0)
    s.connect(R0, block, rm.joints.Prismatic(at=R1.origin, axis=R0.i))
    s.act(rm.Spring(k, 0, a=R0.origin, b=R1.origin, on_b=block))
    s.act(Damper(c, a=R0.point("A", -1, 0, 0), b=R1.origin, on_b=block))
    s.act(rm.Force(on=block, vector=2 * sp.cos(8 * rm.t) * R0.i, at=R1.origin))
    eqs = s.equations_of_motion()
    sim = eqs.simulate(t=(0, 20), q0=[0.0], rtol=1e-12, atol=1e-14, n_output=4001,
                       m=1.0, k=100.0, c=4.0)
    X, phi = harmonic_response(8.0, 10.0, 0.2, 2.0 / 100.0)
    late = sim.t > 17
    assert_allclose(sim.q[0][late], X * np.cos(8.0 * sim.t[late] - phi), atol=1e-10)
