"""Linearisation of equations of motion (ch. 21.1, 25.4): closed forms, agreement with
small-amplitude simulations, symmetry, bad input."""

import math

import numpy as np
import pytest
import scipy.integrate
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech import models
from rigidmech._core.errors import ArgumentError, SingularMassMatrixError
from rigidmech.actions import Damper, TorsionalDamper
from rigidmech.vibrations import damping_ratio, linearize


def spring_mass_damper():
    x = rm.coordinates("x")
    m, k, c, F = rm.constants("m k c F", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    block = rm.Body("block", frame=R1, mass=m)
    s = rm.System(galilean=R0)
    s.connect(R0, block, rm.joints.Prismatic(at=R1.origin, axis=R0.i))
    s.act(rm.Spring(k, 0, a=R0.origin, b=R1.origin, on_b=block))
    s.act(Damper(c, a=R0.point("A", -1, 0, 0), b=R1.origin, on_b=block))
    s.act(rm.Force(on=block, vector=F * R0.i, at=R1.origin))
    return s, (m, k, c, F)


def test_spring_mass_damper_built_with_a_system_has_the_closed_form_damping_ratio():
    s, (m, k, c, F) = spring_mass_damper()
    lin = linearize(s.equations_of_motion(), inputs=["F"])
    assert (lin.M, lin.C, lin.K, lin.B) == (sp.Matrix([[m]]), sp.Matrix([[c]]),
                                            sp.Matrix([[k]]), sp.Matrix([[1]]))
    assert sp.simplify(damping_ratio(lin.C[0], lin.K[0], lin.M[0]) - c / (2 * sp.sqrt(k * m))) \
        == 0
    A, B = lin.first_order()
    assert A == sp.Matrix([[0, 1], [-k / m, -c / m]])
    assert B == sp.Matrix([[0], [1 / m]])


def test_damped_compound_pendulum_has_the_closed_form_damping_ratio():
    """Rod of length L on a pivot at one end with a torsional damper c: J_O = m L^2/3,
    stiffness m g L/2, zeta = c / (2 sqrt(J_O m g L/2))."""
    q = rm.coordinates("q")
    m, L, g, c = rm.constants("m L g c", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", L / 2 * R1.i)
    rod = rm.Body("rod", frame=R1, mass=m, centre=G, inertia=rm.inertia.rod(m, L, axis=R1.i))
    s = rm.System(galilean=R0)
    s.connect(R0, rod, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.gravity(g * R0.i))
    s.act(TorsionalDamper(c, axis=R0.k, on=rod))
    lin = linearize(s.equations_of_motion())
    zeta = damping_ratio(lin.C[0], lin.K[0], lin.M[0])
    expected = c / (2 * sp.sqrt(m * L**2 / 3 * m * g * L / 2))
    assert sp.simplify(zeta - expected) == 0


def _eqs_with_functions_of_time(eqs):
    """The same equations written with q(t), Derivative(q(t), t) in M and f (the other
    representation EquationsOfMotion may use)."""
    rule = {}
    for c, qs, us in zip(eqs.coordinates, eqs.q, eqs.u, strict=True):
        rule[qs], rule[us] = c, c.diff(rm.t)
    return rm.EquationsOfMotion(coordinates=eqs.coordinates, q=eqs.coordinates,
                                u=[c.diff(rm.t) for c in eqs.coordinates],
                                mass_matrix=eqs.mass_matrix.xreplace(rule),
                                forcing=eqs.forcing.xreplace(rule))


def double_pendulum():
    """Two point masses m on massless rods l, absolute angles (ch. 25.4.3)."""
    return models.point_mass_double_pendulum().system.equations_of_motion()


def test_linearisation_does_not_depend_on_how_q_and_q_dot_are_written():
    eqs = double_pendulum()
    a = linearize(eqs)
    b = linearize(_eqs_with_functions_of_time(eqs))
    for X, Y in ((a.M, b.M), (a.C, b.C), (a.K, b.K)):
        assert sp.simplify(X - Y) == sp.zeros(2, 2)


def _measured_frequency(eqs, q0, params, periods=6, omega_guess=1.0):
    """Angular frequency of the first coordinate from its upward zero crossings on a
    small-amplitude simulation (scipy, events located to round-off)."""
    rhs = eqs.rhs(**params)
    n = len(q0)

    def crossing(_, y):
        return y[0]

    crossing.direction = 1
    t_end = periods * 2 * math.pi / omega_guess
    sol = scipy.integrate.solve_ivp(rhs, (0, t_end), np.concatenate((q0, np.zeros(n))),
                                    method="DOP853", rtol=1e-13, atol=1e-20, events=crossing)
    times = sol.t_events[0]
    return 2 * math.pi / np.mean(np.diff(times))


@pytest.mark.parametrize("mode", [0, 1])
def test_linearised_frequencies_equal_small_amplitude_simulation(mode):
    eqs = double_pendulum()
    params = {"m": 1.3, "l": 0.7, "g": 9.81}
    modes = linearize(eqs).modes(**params)
    eps = 1e-5
    q0 = eps * modes.shapes[:, mode] / np.max(np.abs(modes.shapes[:, mode]))
    w = _measured_frequency(eqs, q0, params, omega_guess=modes.frequencies[mode])
    assert w == pytest.approx(modes.frequencies[mode], rel=1e-6)


def n_link(n):
    return models.n_link_pendulum(n).system.equations_of_motion()


_N_LINK = {n: n_link(n) for n in (2, 3)}


@settings(max_examples=20)
@given(st.sampled_from([2, 3]), st.lists(st.sampled_from([0, 1]), min_size=3, max_size=3),
       st.lists(st.floats(0.5, 2.0), min_size=7, max_size=7))
def test_M_and_K_are_symmetric_for_a_conservative_holonomic_system(n, flips, values):
    """n-link pendulum (gravity -g y, relative angles) about an equilibrium where each link
    hangs down or stands up: M and K symmetric (K is the Hessian of the potential)."""
    eqs = _N_LINK[n]
    absolute = [-sp.pi / 2 + sp.pi * f for f in flips[:n]]  # each link down or up
    about = [absolute[0]] + [absolute[k] - absolute[k - 1] for k in range(1, n)]
    params = {"g": 9.81} | {f"m{i + 1}": values[i] for i in range(n)} | {
        f"l{i + 1}": values[3 + i] for i in range(n)}
    lin = linearize(eqs, about, parameters=params, simplify=False)
    M, C, K, _ = lin.numeric()
    assert_allclose(M, M.T, atol=1e-12)
    assert_allclose(K, K.T, atol=1e-12)
    assert_allclose(C, 0, atol=1e-12)


def spherical_pendulum():
    phi, theta = rm.coordinates("phi theta")
    m, l, g = rm.constants("m l g", positive=True)
    R0 = rm.Frame("R0")
    Ra = R0.rotated("Ra", about=R0.k, angle=phi)
    Rb = Ra.rotated("Rb", about=Ra.j, angle=theta)
    bob = rm.Body("bob", frame=Rb, mass=m, centre=R0.origin.moved("Q", -l * Rb.k))
    s = rm.System(galilean=R0)
    s.connect(R0, bob, rm.joints.Spherical(at=R0.origin))
    s.act(rm.gravity(-g * R0.k))
    return s.equations_of_motion(), (phi, theta)


def test_conical_motion_of_a_spherical_pendulum_is_a_steady_motion():
    """Steady motion theta = a, phi' = W with W^2 = g/(l cos a); small oscillations about it
    have w^2 = W^2 (1 + 3 cos^2 a) (classical result) and phi is cyclic (a zero root)."""
    eqs, (phi, theta) = spherical_pendulum()
    a = 0.6
    params = {"m": 1.0, "l": 1.0, "g": 9.81}
    W = math.sqrt(9.81 / math.cos(a))
    lin = linearize(eqs, {theta: a}, velocities={phi: W}, parameters=params)
    s = np.sort_complex(lin.eigenvalues())
    expected = W * math.sqrt(1 + 3 * math.cos(a) ** 2)
    assert_allclose(np.sort(np.abs(s.imag))[-2:], [expected, expected], rtol=1e-10)
    assert_allclose(s.real, 0, atol=1e-6)
    C = lin.numeric()[1]  # gyroscopic coupling: C antisymmetric, not zero
    assert abs(C[0, 1]) > 1 and C[0, 1] == pytest.approx(-C[1, 0], rel=1e-12)


def test_a_point_that_is_not_an_equilibrium_is_refused_with_its_residual():
    eqs = double_pendulum()
    with pytest.raises(ArgumentError, match=r"not an equilibrium .* f\(q\*, q'\*\) = \[.*g"):
        linearize(eqs, [0.3, 0])
    eqs2, (phi, theta) = spherical_pendulum()
    with pytest.raises(ArgumentError, match="not a steady motion"):
        linearize(eqs2, {theta: 0.6}, velocities={phi: 1.0})


def test_a_singular_mass_matrix_is_refused():
    """Spherical coordinates at the pole theta = 0: M = diag(m l^2 sin^2 theta, m l^2)."""
    eqs, _ = spherical_pendulum()
    with pytest.raises(SingularMassMatrixError, match="mass matrix is singular at q\\*"):
        linearize(eqs)


@pytest.mark.parametrize("kwargs, match", [
    ({"about": [0, 0, 0]}, "`about` must give 2 values"),
    ({"inputs": ["nope"]}, "`inputs` must name parameters"),
    ({"about": {"psi": 0}}, "unknown coordinate"),
])
def test_bad_arguments(kwargs, match):
    with pytest.raises(ArgumentError, match=match):
        linearize(double_pendulum(), **kwargs)


def test_frequency_response_of_the_linearised_oscillator():
    s, _ = spring_mass_damper()
    lin = linearize(s.equations_of_motion(), inputs=["F"])
    w = np.array([0.5, 2.0, 3.5])
    H = lin.frequency_response(w, input="F", m=2.0, k=8.0, c=0.4)[0]
    assert_allclose(H, 1 / (8.0 - 2.0 * w**2 + 0.4j * w), rtol=1e-13)


def test_linearisation_accepts_sympy_mechanics_dynamicsymbols():
    """Equations written with sympy.physics.mechanics dynamicsymbols (their own time symbol)
    linearise like the others."""
    from sympy.physics.mechanics import dynamicsymbols

    th = dynamicsymbols("theta")
    tt = dynamicsymbols._t
    m, g, L = sp.symbols("m g L", positive=True)
    eqs = rm.EquationsOfMotion(coordinates=(th,), q=(th,), u=(th.diff(tt),),
                               mass_matrix=sp.ImmutableMatrix([[m * L**2]]),
                               forcing=sp.ImmutableMatrix([[-m * g * L * sp.sin(th)
                                                            - th.diff(tt)]]))
    lin = linearize(eqs, {th: sp.pi})
    assert (lin.C[0], lin.K[0]) == (1, -g * L * m)


def _pendulum_eqs():
    th = rm.coordinates("theta")
    q, u = sp.symbols("theta theta_dot")
    m, g, L = sp.symbols("m g L", positive=True)
    return rm.EquationsOfMotion(coordinates=(th,), q=(q,), u=(u,),
                                mass_matrix=sp.ImmutableMatrix([[m * L**2]]),
                                forcing=sp.ImmutableMatrix([[-m * g * L * sp.sin(q)]]))


@pytest.mark.parametrize("rate", [2.0, sp.Symbol("Omega")])
def test_a_rate_on_a_coordinate_the_equations_depend_on_is_not_steady(rate):
    """The pendulum at theta = 0 with theta' = 2: f(0, 2) = 0 but theta = 2t is no motion
    (f(2t) = -m g L sin 2t); the rate of the residual along the motion, (df/dq) q'* = -m g L q'*,
    is not zero: refused like on the path with constraints."""
    with pytest.raises(ArgumentError, match=r"not a steady motion .*rate .*\(df/dq\) q'\* = "
                                            r"\[.*g"):
        linearize(_pendulum_eqs(), velocities={"theta": rate})


def test_steadiness_uses_one_tolerance_on_the_residual_and_its_rate():
    """x'' = -x - d y, y'' = 0 about 0 with y' = 1: residual 0, rate (df/dq) q'* = (-d, 0).
    |d| <= tol is steady (the boundary included; plus the rounding allowance 8 eps
    sum |df/dq| max(|q'|, 1) = 1.8e-15), above it is not."""
    x, y = rm.coordinates("x y")
    qx, qy, ux, uy = sp.symbols("x y x_dot y_dot")
    d = sp.Symbol("d")
    eqs = rm.EquationsOfMotion(coordinates=(x, y), q=(qx, qy), u=(ux, uy),
                               mass_matrix=sp.ImmutableMatrix(sp.eye(2)),
                               forcing=sp.ImmutableMatrix([-qx - d * qy, 0]))
    for value in (1e-10, 1e-9):
        lin = linearize(eqs, velocities={"y": 1.0}, parameters={"d": value}, tol=1e-9)
        assert lin.velocities == {"x": 0, "y": 1.0}
    for value in (1.00001e-9, -2e-9):           # tol + 8 eps (|J| |q|) = 1e-9 + 1.8e-15
        with pytest.raises(ArgumentError, match="not a steady motion"):
            linearize(eqs, velocities={"y": 1.0}, parameters={"d": value}, tol=1e-9)
    with pytest.raises(ArgumentError, match="not a steady motion"):
        linearize(eqs, velocities={"y": 1.0})          # d symbolic: not identically zero


def test_values_must_respect_what_the_symbols_declare():
    """m, g, L declared positive: a negative mass given as a number is refused where it
    enters (linearize, stability, equilibria), not turned into M = -1."""
    from rigidmech.vibrations import equilibria, stability

    eqs = _pendulum_eqs()
    with pytest.raises(ArgumentError, match=r"`parameters`: the value of `m` must be > 0 "
                                            r"\(declared positive\); got -1.0"):
        linearize(eqs, parameters={"m": -1.0, "g": 9.81, "L": 1.0})
    with pytest.raises(ArgumentError, match=r"the value of `L` must be > 0"):
        stability(eqs, [0], m=1.0, g=9.81, L=0)
    with pytest.raises(ArgumentError, match=r"the value of `g` must be > 0"):
        equilibria(eqs, within=(-3, 3), m=1.0, g=-9.81, L=1.0)
    # boundary: any positive value passes
    assert linearize(eqs, parameters={"m": 1e-300, "g": 9.81, "L": 1.0}).K[0, 0] > 0
