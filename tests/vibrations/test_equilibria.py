"""Equilibria, stability and bifurcations (ch. 20, 25): the bead on a rotating hoop posed
with rm.System (the hoop's rotation is prescribed through a frame whose angle is Omega t),
numeric searches, the potential-energy test."""

import math

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech._core.errors import ArgumentError
from rigidmech.vibrations import (
    bifurcation,
    equilibria,
    linearize,
    potential_stability,
    stability,
)


def hoop():
    """A bead of mass m on a hoop of radius R turning at the prescribed rate Omega about its
    vertical diameter: the hoop's frame R1 turns by Omega t (a given function of time, not a
    parameter of situation), the bead's position on the hoop is theta from the bottom."""
    theta = rm.coordinates("theta")
    m, R, g, W = rm.constants("m R g Omega", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=W * rm.t)
    R2 = R1.rotated("R2", about=R1.j, angle=theta)
    bead = rm.Body("bead", frame=R2, mass=m, centre=R0.origin.moved("P", -R * R2.k))
    s = rm.System(galilean=R0)
    s.add(bead)
    s.act(rm.gravity(-g * R0.k))
    return s.equations_of_motion(), theta, (m, R, g, W)


def test_hoop_equations_are_the_textbook_ones():
    eqs, theta, (m, R, g, W) = hoop()
    q = eqs.q[0]
    assert sp.simplify(eqs.mass_matrix[0] - m * R**2) == 0
    assert sp.simplify(eqs.forcing[0] - m * R * sp.sin(q) * (R * W**2 * sp.cos(q) - g)) == 0


def test_hoop_equilibria_symbolic():
    eqs, theta, (m, R, g, W) = hoop()
    found = {e["theta"] for e in equilibria(eqs)}
    c = sp.acos(g / (R * W**2))
    assert {0, sp.pi} <= found
    assert c in found
    assert any(sp.simplify(sp.cos(x) - g / (R * W**2)) == 0 and x != c for x in found)


def test_hoop_stability_switches_at_omega_squared_equal_g_over_R():
    eqs, theta, (m, R, g, W) = hoop()
    K = linearize(eqs).K[0]  # about theta = 0
    assert sp.simplify(K - m * R * (g - R * W**2)) == 0  # > 0 iff W^2 < g/R
    base = {"m": 1.0, "R": 0.5, "g": 9.81}
    critical = math.sqrt(9.81 / 0.5)
    slow = equilibria(eqs, within=(-3.0, 3.0), Omega=0.9 * critical, **base)
    fast = equilibria(eqs, within=(-3.0, 3.0), Omega=1.1 * critical, **base)
    assert [e["theta"] for e in slow] == [0.0]
    side = math.acos(1 / 1.1**2)
    assert_allclose([e["theta"] for e in fast], [-side, 0.0, side], atol=1e-12)
    assert stability(eqs, [0.0], Omega=0.9 * critical, **base) == "stable"
    assert stability(eqs, [0.0], Omega=1.1 * critical, **base) == "unstable"
    assert stability(eqs, [side], Omega=1.1 * critical, **base) == "stable"
    assert stability(eqs, [math.pi], Omega=1.1 * critical, **base) == "unstable"


def test_hoop_bifurcation_data():
    eqs, *_ = hoop()
    base = {"m": 1.0, "R": 1.0, "g": 9.81}
    values = np.linspace(0.5, 2.0, 7) * math.sqrt(9.81)
    b = bifurcation(eqs, "Omega", values, within=(-3.0, 3.0), **base)
    p, x, stable = b.points("theta")
    for v, eq_, st_ in zip(b.values, b.equilibria, b.stabilities, strict=True):
        if v**2 < 9.81 * 0.999:
            assert [e["theta"] for e in eq_] == [0.0] and st_ == ["stable"]
        elif v**2 > 9.81 * 1.001:
            side = math.acos(9.81 / v**2)
            assert_allclose([e["theta"] for e in eq_], [-side, 0, side], atol=1e-12)
            assert st_ == ["stable", "unstable", "stable"]
    assert p.shape == x.shape == stable.shape
    ax = b.plot("theta")
    assert ax.get_xlabel() == "Omega"


def test_numeric_search_finds_every_root_in_the_range():
    th = rm.coordinates("x")
    q, u = sp.symbols("x x_dot")
    c = sp.Symbol("c")
    eqs = rm.EquationsOfMotion(coordinates=(th,), q=(q,), u=(u,),
                               mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-sp.sin(3 * q) * (q - c)]]))
    found = [e["x"] for e in equilibria(eqs, within=(-2.5, 2.5), c=0.4)]
    expected = sorted([k * math.pi / 3 for k in range(-2, 3)] + [0.4])
    assert_allclose(found, expected, atol=1e-12)


def test_double_pendulum_equilibria_numeric_in_a_box():
    q1, q2 = rm.coordinates("q1 q2")
    m, l, g = rm.constants("m l g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.k, angle=q2)
    A = R0.origin.moved("A", l * R1.i)
    s = rm.System(galilean=R0)
    b1 = rm.Body("b1", frame=R1, mass=m, centre=A)
    b2 = rm.Body("b2", frame=R2, mass=m, centre=A.moved("B", l * R2.i))
    s.connect(R0, b1, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(b1, b2, rm.joints.Pivot(at=A, axis=R0.k))
    s.act(rm.gravity(g * R0.i))
    eqs = s.equations_of_motion()
    found = equilibria(eqs, within=[(-3.5, 3.5), (-3.5, 3.5)], samples=9, m=1, l=1, g=9.81)
    got = sorted((round(e["q1"], 9), round(e["q2"], 9)) for e in found)
    pis = [-math.pi, 0.0, math.pi]
    expected = sorted((round(a, 9), round(b, 9)) for a in pis for b in pis)
    assert got == expected
    verdicts = {(round(e["q1"], 9), round(e["q2"], 9)):
                stability(eqs, e, m=1, l=1, g=9.81) for e in found}
    assert verdicts[(0.0, 0.0)] == "stable"
    assert all(v == "unstable" for k, v in verdicts.items() if k != (0.0, 0.0))


def test_lagrange_dirichlet_by_the_potential():
    eqs, theta, (m, R, g, W) = hoop()
    # effective potential of the relative motion: V = -m g R cos(theta) - m (R W sin)^2 / 2
    V = -m * g * R * sp.cos(theta) - m * (R * W * sp.sin(theta)) ** 2 / 2
    base = {"m": 1.0, "R": 1.0, "g": 9.81}
    assert potential_stability(eqs, V, [0], Omega=2.0, **base) == "stable"
    assert potential_stability(eqs, V, [0], Omega=4.0, **base) == "unstable"
    assert potential_stability(eqs, V, [sp.pi]) == "unstable"
    with pytest.raises(ArgumentError, match="not a stationary point"):
        potential_stability(eqs, V, [0.3], Omega=2.0, **base)


@pytest.mark.parametrize("kwargs, match", [
    ({"within": (-1, 1)}, "missing values for parameters"),
    ({"within": (1, -1), "m": 1, "R": 1, "g": 1, "Omega": 1}, "`within` must give 1 range"),
    ({"m": 1, "R": 1, "g": 1, "Omega": 1}, "a numeric search needs `within`"),
    ({"within": (-1, 1), "m": 1, "R": 1, "g": 1, "Omega": 1, "zz": 2}, "unknown parameters"),
])
def test_bad_arguments(kwargs, match):
    eqs, *_ = hoop()
    with pytest.raises(ArgumentError, match=match):
        equilibria(eqs, **kwargs)


def test_symbolic_equilibria_of_several_coordinates_and_a_free_one():
    """Double pendulum (absolute angles): the four combinations of 0 and pi; spherical
    pendulum: theta = 0 or pi with phi free (any azimuth)."""
    q1, q2 = rm.coordinates("q1 q2")
    m, l, g = rm.constants("m l g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R0.rotated("R2", about=R0.k, angle=q2)
    A = R0.origin.moved("A", l * R1.i)
    s = rm.System(galilean=R0)
    b1 = rm.Body("b1", frame=R1, mass=m, centre=A)
    s.connect(R0, b1, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(b1, rm.Body("b2", frame=R2, mass=m, centre=A.moved("B", l * R2.i)),
              rm.joints.Pivot(at=A, axis=R0.k))
    s.act(rm.gravity(g * R0.i))
    found = {(e["q1"], e["q2"]) for e in equilibria(s.equations_of_motion())}
    assert found == {(a, b) for a in (0, sp.pi) for b in (0, sp.pi)}
    phi, theta = rm.coordinates("phi theta")
    Ra = R0.rotated("Ra", about=R0.k, angle=phi)
    Rb = Ra.rotated("Rb", about=Ra.j, angle=theta)
    s2 = rm.System(galilean=R0)
    s2.connect(R0, rm.Body("bob", frame=Rb, mass=m, centre=R0.origin.moved("Q", -l * Rb.k)),
               rm.joints.Spherical(at=R0.origin))
    s2.act(rm.gravity(-g * R0.k))
    found2 = equilibria(s2.equations_of_motion())
    assert sorted(e["theta"] for e in found2) == [0, sp.pi]
    assert all(e["free"] == ["phi"] for e in found2)


def _two_springs(k2):
    """x'' = -x, y'' = -k2 y: V = x^2/2 + k2 y^2/2, K = diag(1, k2)."""
    x, y = rm.coordinates("x y")
    qx, qy, ux, uy = sp.symbols("x y x_dot y_dot")
    k = sp.Symbol("k")
    eqs = rm.EquationsOfMotion(coordinates=(x, y), q=(qx, qy), u=(ux, uy),
                               mass_matrix=sp.ImmutableMatrix(sp.eye(2)),
                               forcing=sp.ImmutableMatrix([-qx, -k * qy]))
    return eqs, x**2 / 2 + k * y**2 / 2, {"k": k2}


@pytest.mark.parametrize("k2, verdict", [
    (1e-10, "stable"), (2e-12, "stable"),                   # above the rounding level
    (0.5e-12, "undecided"), (0.0, "undecided"),            # at rounding: not decided
    (-0.5e-12, "undecided"), (-2e-12, "unstable"), (-1e-10, "unstable"),
])
def test_stability_and_potential_stability_decide_definiteness_by_one_rule(k2, verdict):
    """The Lagrange-Dirichlet decision on K = diag(1, k2) (the Hessian of V): the same verdict
    from the linearised equations and from the potential, one relative tolerance 1e-12
    (boundary: |k2| = 1e-12 of the largest eigenvalue)."""
    eqs, V, params = _two_springs(k2)
    assert potential_stability(eqs, V, [0, 0], **params) == verdict
    lin_verdict = stability(eqs, [0, 0], **params)
    # an unstable K gives a real positive exponent sqrt(-k2): found by the eigenvalues
    assert lin_verdict == verdict


@pytest.mark.parametrize("offset, ok", [(1e-10, True), (1e-9, True), (1.00001e-9, False),
                                         (1e-8, False)])
def test_stationarity_uses_linearize_tolerance(offset, ok):
    """A point off the equilibrium by `offset` (|f| = |dV/dq| = offset): one absolute
    tolerance, linearize's 1e-9 (boundary included), for the linearised equations and for the
    potential."""
    eqs, V, params = _two_springs(1.0)
    if ok:
        assert potential_stability(eqs, V, [offset, 0], **params) == "stable"
        assert stability(eqs, [offset, 0], **params) == "stable"
    else:
        with pytest.raises(ArgumentError, match="not a stationary point"):
            potential_stability(eqs, V, [offset, 0], **params)
        with pytest.raises(ArgumentError, match="not an equilibrium"):
            stability(eqs, [offset, 0], **params)
    with pytest.raises(ArgumentError, match="not a stationary point"):
        potential_stability(eqs, V, [1e-10, 0], tol=1e-11, **params)


def test_equilibria_of_a_stiff_system_are_accepted_by_stability():
    """theta'' = -k sin(theta) with k = 1e8: pi is not a float, k sin(pi) = 1.2e-8 > 1e-9.
    The equilibria found are accepted by stability/linearize/potential_stability (the rule
    allows the rounding of q*: 8 eps |df/dq| max(|q|, 1) = 5.6e-7 here), a point off by 1e-6
    (residual 100) is not."""
    th = rm.coordinates("theta")
    q, u = sp.symbols("theta theta_dot")
    k = sp.Symbol("k", positive=True)
    eqs = rm.EquationsOfMotion(coordinates=(th,), q=(q,), u=(u,),
                               mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[-k * sp.sin(q)]]))
    found = equilibria(eqs, within=(-4, 4), k=1e8)
    assert_allclose([e["theta"] for e in found], [-math.pi, 0.0, math.pi], atol=1e-15)
    assert [stability(eqs, e, k=1e8) for e in found] == ["unstable", "stable", "unstable"]
    V = -k * sp.cos(th)
    assert potential_stability(eqs, V, [math.pi], k=1e8) == "unstable"
    with pytest.raises(ArgumentError, match="not an equilibrium"):
        stability(eqs, [math.pi + 1e-6], k=1e8)
    with pytest.raises(ArgumentError, match="not a stationary point"):
        potential_stability(eqs, V, [math.pi + 1e-6], k=1e8)
