"""The critical value of a parameter where a linearised motion changes stability
(rigidmech.vibrations.critical_value, stability_changes): issue 22 (book, ch. 20, 25.4)."""

import math

import numpy as np
import pytest
import scipy.optimize
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ArgumentError, ArgumentTypeError
from rigidmech.vibrations import (
    LinearSystem,
    StabilityChange,
    critical_value,
    linearize,
    stability,
    stability_changes,
)
from rigidmech.vibrations.critical import STABILITY_TOL


def test_the_critical_spin_of_a_sleeping_top_is_the_closed_form():
    # a symmetric top on a ball joint, oriented by Cardan angles (regular at the vertical):
    # the sleeping top spinning at w is stable iff C^2 w^2 > 4 A_O m g l, A_O = A + m l^2
    a, b, phi = rm.coordinates("alpha beta phi")
    m, g, l, A, C = rm.constants("m g l A C", positive=True)
    w = sp.Symbol("omega")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.i, angle=a)
    R2 = R1.rotated("R2", about=R1.j, angle=b)
    R = R2.rotated("R", about=R2.k, angle=phi)
    G = R0.origin.moved("G", l * R.k)
    top = rm.Body("top", frame=R, mass=m, centre=G,
                  inertia=rm.InertiaOperator.from_products(A, A, C, frame=R, at=G))
    s = rm.System(galilean=R0)
    s.connect(R0, top, rm.joints.Spherical(at=R0.origin))
    s.act(rm.gravity(-g * R0.k))
    lin = linearize(s.equations_of_motion(), {a: 0, b: 0, phi: 0}, velocities={phi: w})
    values = dict(m=0.5, g=9.81, l=0.04, A=2e-4, C=3e-4)
    A_O = values["A"] + values["m"] * values["l"] ** 2
    closed = 2 * math.sqrt(A_O * values["m"] * values["g"] * values["l"]) / values["C"]
    w_c = critical_value(lin, "omega", (1.0, 10 * closed), **values)
    assert w_c == pytest.approx(closed, rel=1e-9)
    assert lin.eigenvalues(omega=0.999 * closed, **values).real.max() > 0
    assert stability_changes(lin, w, np.linspace(1, 3 * closed, 7), **values) == (
        StabilityChange(pytest.approx(closed, rel=1e-9), "stable"),)


def test_the_rolling_disc_stands_up_above_the_closed_form_speed():
    # a thin disc rolling upright at v = r |phi'| is stable iff v^2 > g r / 3 (book, ch. 25;
    # the closed form of tests/vibrations/test_linearize_constrained.py): |phi'| = sqrt(g/3r)
    from rigidmech import models
    eqs = models.rolling_disc().system.equations_of_motion()
    spin = sp.Symbol("Omega")
    lin = linearize(eqs, about={"theta": sp.pi / 2}, velocities={"phi": spin})
    values = dict(m=1.0, g=9.81, r=0.3)
    closed = math.sqrt(values["g"] / (3 * values["r"]))
    assert critical_value(lin, spin, (0.1, 20.0), **values) == pytest.approx(closed, rel=1e-8)
    assert critical_value(lin, spin, (-20.0, -0.1), **values) == pytest.approx(-closed,
                                                                                rel=1e-8)


# Meijaard, Papadopoulos, Ruina, Schwab (2007), Proc. R. Soc. A 463, eq. (A 3)-(A 5)
M_PAPER = [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]]
C1_PAPER = sp.Matrix([[0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0_PAPER = sp.Matrix([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2_PAPER = sp.Matrix([[0, 76.59734589573222], [0, 2.65431523794604]])


def _paper_bicycle():
    v = sp.Symbol("v")
    return LinearSystem(sp.symbols("phi delta"), {}, {}, M_PAPER, v * C1_PAPER,
                        9.81 * K0_PAPER + v**2 * K2_PAPER, sp.zeros(2, 0), ())


def _split_route():
    """Independent route: brentq on the real parts of the oscillatory (weave) and real
    (capsize) eigenvalues separately, from numpy matrices."""
    M = np.array(M_PAPER)
    C1, K0, K2 = (np.array(X, dtype=float) for X in (C1_PAPER, K0_PAPER, K2_PAPER))

    def eig(v):
        Mi = np.linalg.inv(M)
        return np.linalg.eigvals(np.block([[np.zeros((2, 2)), np.eye(2)],
                                           [-Mi @ (9.81 * K0 + v**2 * K2), -v * Mi @ C1]]))

    def weave(v):
        ev = eig(v)
        return ev[np.abs(ev.imag) > 1e-6].real.max()

    def capsize(v):
        ev = eig(v)
        return ev[np.abs(ev.imag) < 1e-9].real.max()

    return (scipy.optimize.brentq(weave, 4.0, 4.5, xtol=1e-14),
            scipy.optimize.brentq(capsize, 5.5, 6.5, xtol=1e-14))


def test_the_benchmark_bicycle_weave_and_capsize_speeds():
    bike = _paper_bicycle()
    changes = stability_changes(bike, "v", np.arange(0.5, 10.01, 0.5))
    assert [c.becomes for c in changes] == ["stable", "unstable"]
    weave, capsize = (c.value for c in changes)
    # the paper: v_w = 4.292382..., v_c = 6.024262... m/s
    assert weave == pytest.approx(4.292382, abs=1e-6)
    assert capsize == pytest.approx(6.024262, abs=1e-6)
    split = _split_route()
    # the margin tol max|s| moves the zero by about tol max|s| / slope (< 1e-7 here)
    assert weave == pytest.approx(split[0], abs=1e-7)
    assert capsize == pytest.approx(split[1], abs=1e-7)
    assert critical_value(bike, "v", (5.0, 8.0)) == pytest.approx(capsize, abs=1e-11)


def _damped(c_symbol=True):
    x = rm.coordinates("x")
    c = sp.Symbol("c")
    return rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                                forcing=sp.ImmutableMatrix([[-c * x.diff(rm.t) - 4 * x]]))


def test_the_critical_value_is_the_boundary_of_the_stability_verdict():
    # x'' + c x' + 4 x = 0: exponents -c/2 +- i sqrt(4 - c^2/4), |s| = 2; the rule
    # (unstable iff max Re s > tol max|s|) puts the change at c* = -2 tol * 2
    eqs = _damped()
    lin = linearize(eqs)
    c_star = critical_value(lin, "c", (-1.0, 1.0), xtol=1e-22)
    assert c_star == pytest.approx(-4 * STABILITY_TOL, rel=1e-6)
    # the same decision as vibrations.stability, just either side of it
    assert stability(eqs, [0], c=c_star * (1 + 1e-4)) == "unstable"
    assert stability(eqs, [0], c=c_star * (1 - 1e-4)) != "unstable"


def test_a_growth_exactly_zero_at_an_end_returns_that_end():
    calls = []

    def exponents(p):
        calls.append(p)
        return np.array([p + 0j])
    assert critical_value(exponents, None, (0.0, 1.0), tol=0.0) == 0.0
    assert critical_value(exponents, None, (-1.0, 0.0), tol=0.0) == 0.0


def test_a_bracket_without_a_change_of_stability_is_refused():
    lin = linearize(_damped())
    with pytest.raises(ArgumentError, match=r"`bracket` must hold a change of stability, "
                       r"but the system is stable at both ends"):
        critical_value(lin, "c", (0.5, 1.0))
    with pytest.raises(ArgumentError, match="unstable at both ends"):
        critical_value(lin, "c", (-1.0, -0.5))


def test_bad_arguments_are_named():
    lin = linearize(_damped())
    with pytest.raises(ArgumentError, match=r"`parameter` must name a parameter .*\(c\); got 'k'"):
        critical_value(lin, "k", (-1, 1))
    with pytest.raises(ArgumentError, match="`bracket` must be two numbers"):
        critical_value(lin, "c", 1.0)
    with pytest.raises(ArgumentError, match="`bracket` must be two different finite"):
        critical_value(lin, "c", (1.0, 1.0))
    with pytest.raises(ArgumentTypeError, match="`system` must be a LinearSystem"):
        critical_value(3, "c", (-1, 1))
    with pytest.raises(ArgumentError, match="`tol` must be a finite number"):
        critical_value(lin, "c", (-1, 1), tol=-1.0)
    with pytest.raises(ArgumentError, match="`grid` must be at least two increasing"):
        stability_changes(lin, "c", [1.0, 0.0])


def test_without_margin_the_bicycle_speeds_are_the_zeros_of_the_real_parts():
    bike = _paper_bicycle()
    split = _split_route()
    assert critical_value(bike, "v", (4.0, 4.5), tol=0.0, xtol=1e-14) == pytest.approx(
        split[0], abs=1e-12)
    assert critical_value(bike, "v", (5.5, 6.5), tol=0.0, xtol=1e-14) == pytest.approx(
        split[1], abs=1e-12)


@pytest.mark.slow
def test_the_derived_bicycle_changes_stability_at_the_paper_speeds():
    # the catalogue's Whipple bicycle, derived and linearised (roll, steer, rear wheel: the
    # wheel's exponent 0 stays on the stable side by the margin)
    from rigidmech import models
    model = models.whipple_bicycle()
    rR = models.BENCHMARK_BICYCLE["rR"]
    v = sp.Symbol("v")
    lin = linearize(model.system.equations_of_motion(), velocities={"theta_R": v / rR},
                    parameters={"g": 9.81}, independent=["phi", "delta", "theta_R"],
                    simplify=False)
    changes = stability_changes(lin, v, np.arange(0.5, 10.01, 0.5))
    assert [c.becomes for c in changes] == ["stable", "unstable"]
    paper = stability_changes(_paper_bicycle(), "v", np.arange(0.5, 10.01, 0.5))
    for ours, theirs in zip(changes, paper, strict=True):
        assert ours.value == pytest.approx(theirs.value, abs=1e-8)
