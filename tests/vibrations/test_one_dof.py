"""One degree of freedom (ch. 21): the closed forms checked against the differential equation
itself (sympy), against independent integrations (scipy) and against energy balances."""

import math

import numpy as np
import pytest
import scipy.integrate
import scipy.optimize
import sympy as sp
from numpy.testing import assert_allclose

from rigidmech._core.errors import ArgumentError
from rigidmech.vibrations import (
    coulomb_free_response,
    coulomb_stop,
    damped_frequency,
    damping_case,
    damping_ratio,
    dry_friction_equivalent_damping,
    duhamel_response,
    equivalent_viscous_damping,
    free_response,
    half_power_frequencies,
    harmonic_response,
    logarithmic_decrement,
    natural_frequency,
    quality_factor,
    resonance,
    structural_equivalent_damping,
    support_motion_response,
    transmissibility,
)


@pytest.mark.parametrize("zeta", [sp.Rational(1, 5), sp.S.One, sp.Rational(5, 2), sp.S.Zero],
                         ids=["underdamped", "critical", "overdamped", "undamped"])
def test_free_response_solves_the_equation_and_the_initial_conditions(zeta):
    t, w, x0, v0 = sp.symbols("t omega_0 x_0 v_0", positive=True)
    x = free_response(t, x0, v0, w, zeta)
    residual = x.diff(t, 2) + 2 * zeta * w * x.diff(t) + w**2 * x
    assert sp.simplify(residual) == 0
    assert sp.simplify(x.subs(t, 0) - x0) == 0
    assert sp.simplify(x.diff(t).subs(t, 0) - v0) == 0


@pytest.mark.parametrize("zeta", [0.05, 1.0, 3.0], ids=["underdamped", "critical", "overdamped"])
def test_free_response_numeric_matches_an_integration(zeta):
    w0, x0, v0 = 7.0, 0.3, -1.2
    t = np.linspace(0, 3, 31)
    sol = scipy.integrate.solve_ivp(lambda _, y: [y[1], -2 * zeta * w0 * y[1] - w0**2 * y[0]],
                                    (0, 3), [x0, v0], t_eval=t, rtol=1e-12, atol=1e-14)
    assert_allclose(free_response(t, x0, v0, w0, zeta), sol.y[0], rtol=1e-8, atol=1e-11)


def test_parameters_of_the_oscillator():
    k, m, c = 400.0, 4.0, 8.0
    assert natural_frequency(k, m) == pytest.approx(10.0, rel=1e-15)
    assert damping_ratio(c, k, m) == pytest.approx(0.1, rel=1e-15)
    assert damped_frequency(10.0, 0.1) == pytest.approx(10 * math.sqrt(0.99), rel=1e-15)
    assert damping_case(0.1) == "underdamped"


def test_logarithmic_decrement_is_the_log_ratio_of_successive_maxima():
    w0, zeta = 5.0, 0.08
    Td = 2 * math.pi / damped_frequency(w0, zeta)
    t1 = 0.3
    ratio = free_response(t1, 1.0, 0.0, w0, zeta) / free_response(t1 + Td, 1.0, 0.0, w0, zeta)
    assert logarithmic_decrement(zeta) == pytest.approx(math.log(ratio), rel=1e-12)


def test_harmonic_response_is_the_steady_solution():
    """X cos(wt - phi) solves x'' + 2 zeta w0 x' + w0^2 x = w0^2 (F0/k) cos wt."""
    w0, zeta, w, xs = 10.0, 0.07, 8.5, 0.02
    X, phi = harmonic_response(w, w0, zeta, xs)
    t = np.linspace(0, 2, 50)
    x = X * np.cos(w * t - phi)
    xd = -w * X * np.sin(w * t - phi)
    xdd = -(w**2) * x
    assert_allclose(xdd + 2 * zeta * w0 * xd + w0**2 * x, w0**2 * xs * np.cos(w * t),
                    atol=1e-12)


def test_resonance_peak_and_half_power_bandwidth():
    w0, zeta = 10.0, 0.05
    peak = scipy.optimize.minimize_scalar(lambda w: -harmonic_response(w, w0, zeta)[0],
                                          bounds=(5, 15), method="bounded",
                                          options={"xatol": 1e-12})
    wr, Xr = resonance(w0, zeta)
    assert wr == pytest.approx(peak.x, rel=1e-7)
    assert Xr == pytest.approx(-peak.fun, rel=1e-12)
    w1, w2 = half_power_frequencies(w0, zeta)
    assert_allclose(harmonic_response(np.array([w1, w2]), w0, zeta)[0], Xr / math.sqrt(2),
                    rtol=1e-12)
    assert (w2 - w1) == pytest.approx(2 * zeta * w0, rel=0.01)  # book: Delta w ~ 2 zeta w0
    assert quality_factor(zeta) == pytest.approx(10.0)


def test_transmissibility_from_complex_amplitudes():
    w0, zeta, Y = 10.0, 0.2, 0.003
    m = 2.0
    k, c = m * w0**2, 2 * zeta * m * w0
    for w in (3.0, 10.0, 14.15, 40.0):
        H = (k + 1j * c * w) / (k - m * w**2 + 1j * c * w)  # x / y for support motion
        X, phi, Z = support_motion_response(w, w0, zeta, Y)
        assert X == pytest.approx(abs(H) * Y, rel=1e-13)
        assert phi == pytest.approx(-np.angle(H), rel=1e-12)
        assert Z == pytest.approx(abs(H - 1) * Y, rel=1e-12)
        force_ratio = abs(k + 1j * c * w) / abs(k - m * w**2 + 1j * c * w)
        assert transmissibility(w / w0, zeta) == pytest.approx(force_ratio, rel=1e-13)
    assert transmissibility(math.sqrt(2), 0.3) == pytest.approx(1.0, rel=1e-14)


def _coulomb_simulation(x0, w0, a):
    """Independent: integrate x'' = -w0^2 x -+ w0^2 a half-cycle by half-cycle with an event
    at x' = 0, stopping where the spring cannot overcome friction (|x| <= a)."""
    t0, x, n = 0.0, x0, 0
    while abs(x) > a:
        s = -np.sign(x)  # direction of motion

        def rhs(_, y, s=s):
            return [y[1], -(w0**2) * y[0] - w0**2 * a * s]

        def stop(_, y):
            return y[1]

        stop.terminal, stop.direction = True, -s
        sol = scipy.integrate.solve_ivp(rhs, (t0, t0 + 10 / w0), [x, 0.0], events=stop,
                                        rtol=1e-12, atol=1e-14, first_step=1e-6)
        t0, x = sol.t_events[0][0], sol.y_events[0][0][0]
        n += 1
    return n, t0, x


@pytest.mark.parametrize("x0, a", [(1.0, 0.1), (-0.73, 0.05), (0.35, 0.1)])
def test_coulomb_damping_stops_after_the_right_number_of_half_cycles(x0, a):
    w0 = 3.0
    n, t_stop, x_stop = coulomb_stop(x0, w0, a)
    n_sim, t_sim, x_sim = _coulomb_simulation(x0, w0, a)
    assert n == n_sim
    assert t_stop == pytest.approx(t_sim, rel=1e-8)
    assert x_stop == pytest.approx(x_sim, abs=1e-8)
    # the amplitude drops by 4a = 4F/k per cycle
    tp = np.arange(n + 1) * math.pi / w0
    turning = np.abs(coulomb_free_response(tp, x0, w0, a))
    assert_allclose(-np.diff(turning[: n]), 2 * a, rtol=1e-12)


def test_coulomb_response_solves_each_half_cycle():
    x0, w0, a = 1.0, 2.0, 0.1
    t = np.linspace(0.01, 0.99, 40) * math.pi / w0 + math.pi / w0  # second half-cycle
    x = coulomb_free_response(t, x0, w0, a)
    # moving up (x' > 0): x'' = -w0^2 (x + a)
    h = 1e-4
    xdd = (coulomb_free_response(t + h, x0, w0, a) - 2 * x
           + coulomb_free_response(t - h, x0, w0, a)) / h**2
    assert_allclose(xdd, -(w0**2) * (x + a), atol=1e-5)


def test_equivalent_viscous_damping_from_the_energy_dissipated_per_cycle():
    w, X, c, F = 3.0, 0.2, 1.5, 0.7
    period = 2 * math.pi / w

    def per_cycle(power):
        return scipy.integrate.quad(power, 0, period, epsabs=1e-13, limit=200)[0]

    viscous = per_cycle(lambda t: c * (X * w * math.sin(w * t)) ** 2)
    assert equivalent_viscous_damping(viscous, w, X) == pytest.approx(c, rel=1e-12)
    dry = per_cycle(lambda t: F * abs(X * w * math.sin(w * t)))
    assert dry == pytest.approx(4 * F * X, rel=1e-10)
    assert dry_friction_equivalent_damping(F, w, X) == pytest.approx(
        equivalent_viscous_damping(dry, w, X), rel=1e-10)
    alpha = 0.9
    assert structural_equivalent_damping(alpha, w) == pytest.approx(
        equivalent_viscous_damping(alpha * X**2, w, X), rel=1e-14)


def test_duhamel_response_matches_an_integration():
    m, w0, zeta = 2.0, 6.0, 0.1
    k, c = m * w0**2, 2 * zeta * m * w0

    def force(t):
        return 3.0 * math.sin(2.0 * t) * math.exp(-0.1 * t) + (1.0 if t > 1.0 else 0.0)

    t = np.linspace(0, 4, 17)
    sol = scipy.integrate.solve_ivp(lambda s, y: [y[1], (force(s) - c * y[1] - k * y[0]) / m],
                                    (0, 4), [0.1, 0.0], t_eval=t, rtol=1e-12, atol=1e-14,
                                    max_step=0.01)
    x = duhamel_response(force, t, mass=m, omega0=w0, zeta=zeta, x0=0.1)
    assert_allclose(x, sol.y[0], rtol=1e-7, atol=1e-10)


@pytest.mark.parametrize("call, match", [
    (lambda: natural_frequency(1.0, 0.0), "`mass` must be finite and > 0"),
    (lambda: damping_ratio(-1.0, 1.0, 1.0), "`damping` must be finite and >= 0"),
    (lambda: resonance(1.0, 0.9), "`zeta` must be < 1/sqrt"),
    (lambda: free_response(1.0, 1, 0, 1, sp.Symbol("z")), "`zeta` must be a number"),
    (lambda: coulomb_stop(1.0, 1.0, -0.1), "`friction_displacement` must be > 0"),
    (lambda: duhamel_response(3.0, [1.0], mass=1.0, omega0=1.0), "`force` must be a callable"),
])
def test_bad_input_is_refused(call, match):
    with pytest.raises(ArgumentError, match=match):
        call()


def _free_response_mp(t, x0, v0, w, z):
    """Reference: the closed form evaluated with 50 digits (mpmath)."""
    import mpmath as mp

    with mp.workdps(50):
        t, x0, v0, w, z = (mp.mpf(x) for x in (t, x0, v0, w, z))
        if z < 1:
            wd = w * mp.sqrt(1 - z * z)
            out = mp.e ** (-z * w * t) * (x0 * mp.cos(wd * t) + (v0 + z * w * x0) / wd
                                         * mp.sin(wd * t))
        elif z == 1:
            out = mp.e ** (-w * t) * (x0 + (v0 + w * x0) * t)
        else:
            r = mp.sqrt(z * z - 1)
            out = mp.e ** (-z * w * t) * (x0 * mp.cosh(r * w * t) + (v0 + z * w * x0)
                                         / (r * w) * mp.sinh(r * w * t))
        return float(out)


@pytest.mark.parametrize("zeta", [1 - 1e-6, 1 - 1e-12, 1.0, 1 + 1e-15, 1 + 1e-12, 1 + 1e-6,
                                  2.0, 1e4, 1e8])
def test_free_response_is_accurate_across_critical_damping_and_for_heavy_damping(zeta):
    """Across zeta = 1 (the boundary between the three formulas) and for zeta >> 1 the numeric
    response agrees with the closed form in 50 digits to 1e-12 relative: no cancellation in
    (e^{s1 t} - e^{s2 t}) / (s1 - s2) near zeta = 1 nor in s1 = -w (zeta - sqrt(zeta^2 - 1))."""
    t = np.array([0.0, 0.05, 0.5, 2.0, 20.0])
    got = free_response(t, 1.0, 0.3, 10.0, zeta)
    ref = np.array([_free_response_mp(ti, 1.0, 0.3, 10.0, zeta) for ti in t])
    assert np.all(np.abs(got - ref) <= 1e-12 * np.abs(ref)), (got - ref) / ref


def test_free_response_refuses_a_case_that_contradicts_zeta():
    with pytest.raises(ArgumentError, match=r"`case` 'critical' contradicts zeta = 0.5"):
        free_response(1.0, 1.0, 0.0, 10.0, 0.5, case="critical")
    assert free_response(1.0, 1.0, 0.0, 10.0, 0.5, case="underdamped") == \
        free_response(1.0, 1.0, 0.0, 10.0, 0.5)
