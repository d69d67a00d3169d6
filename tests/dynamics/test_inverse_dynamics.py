"""Inverse dynamics (book, ch. 20.2, 25.3): the generalised forces that give a prescribed
motion, against closed forms, sympy.physics.mechanics and Newton's law on a cart."""

import numpy as np
import pytest
import scipy.integrate
import sympy as sp

import rigidmech as rm
from rigidmech import EquationsOfMotion, models
from rigidmech.dynamics import inverse_dynamics
from rigidmech.errors import ArgumentError

TIMES = np.linspace(0.0, 2.0, 9)


def test_pendulum_driven_at_constant_speed_needs_m_g_L_sin_omega_t():
    th = rm.coordinates("theta")
    m, g, L, w = sp.symbols("m g L omega", positive=True)
    eqs = EquationsOfMotion(coordinates=(th,), mass_matrix=sp.Matrix([[m * L**2]]),
                            forcing=sp.Matrix([[-m * g * L * sp.sin(th)]]))
    tau = inverse_dynamics(eqs, {th: w * rm.t})
    assert sp.simplify(tau[0] - m * g * L * sp.sin(w * rm.t)) == 0
    got = inverse_dynamics(eqs, {"theta": 1.5 * rm.t}, times=TIMES, m=2.0, g=9.81, L=0.7)
    assert got.shape == (1, TIMES.size)
    assert got[0] == pytest.approx(2.0 * 9.81 * 0.7 * np.sin(1.5 * TIMES), rel=1e-13, abs=1e-13)


Q1 = 0.3 * sp.sin(2 * rm.t)
Q2 = 0.5 * sp.cos(3 * rm.t) + rm.t


def _arm_closed_form(m, l, g):
    # two point masses m on massless links l, absolute angles from the vertical R0.i (gravity
    # g R0.i): M = m l^2 [[2, c], [c, 1]], c = cos(q1 - q2);
    # f = m l^2 s [-q2'^2, q1'^2] - m g l [2 sin q1, sin q2], s = sin(q1 - q2)
    q1, q2 = Q1, Q2
    d1, d2 = q1.diff(rm.t), q2.diff(rm.t)
    c, s = sp.cos(q1 - q2), sp.sin(q1 - q2)
    M = m * l**2 * sp.Matrix([[2, c], [c, 1]])
    f = m * l**2 * s * sp.Matrix([-d2**2, d1**2]) - m * g * l * sp.Matrix(
        [2 * sp.sin(q1), sp.sin(q2)])
    return M * sp.Matrix([q1.diff(rm.t, 2), q2.diff(rm.t, 2)]) - f


def test_two_link_arm_torques_equal_the_closed_form():
    model = models.point_mass_double_pendulum()
    q1, q2 = model.coordinates
    m, l, g = model.constants
    eqs = model.system.equations_of_motion()
    tau = inverse_dynamics(eqs, {q1: Q1, q2: Q2})
    expected = _arm_closed_form(m, l, g)
    values = {m: 1.3, l: 0.8, g: 9.81}
    for time in TIMES:
        point = values | {rm.t: time}
        for i in range(2):
            assert float(tau[i].xreplace(point)) == pytest.approx(
                float(expected[i].xreplace(point)), rel=1e-12, abs=1e-12)
    got = inverse_dynamics(eqs, {q1: Q1, q2: Q2}, times=TIMES, m=1.3, l=0.8, g=9.81)
    want = np.array([[float(expected[i].xreplace(values | {rm.t: s})) for s in TIMES]
                     for i in range(2)])
    assert got == pytest.approx(want, rel=1e-12, abs=1e-12)


def test_two_link_arm_torques_equal_sympy_mechanics():
    me = pytest.importorskip("sympy.physics.mechanics")
    a, b = me.dynamicsymbols("a b")
    m, l, g = sp.symbols("m l g", positive=True)
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    A = O.locatenew("A", l * (sp.cos(a) * N.x + sp.sin(a) * N.y))
    B = A.locatenew("B", l * (sp.cos(b) * N.x + sp.sin(b) * N.y))
    for P in (A, B):
        P.set_vel(N, P.pos_from(O).dt(N))
    pa, pb = me.Particle("pa", A, m), me.Particle("pb", B, m)
    pa.potential_energy = -m * g * A.pos_from(O).dot(N.x)
    pb.potential_energy = -m * g * B.pos_from(O).dot(N.x)
    lm = me.LagrangesMethod(me.Lagrangian(N, pa, pb), [a, b])
    lm.form_lagranges_equations()
    ts = me.dynamicsymbols._t
    motion = {a: Q1.subs(rm.t, ts), b: Q2.subs(rm.t, ts)}
    acc = sp.Matrix([motion[a].diff(ts, 2), motion[b].diff(ts, 2)])
    theirs = (lm.mass_matrix * acc - lm.forcing).subs(motion).doit()
    values = {m: 1.3, l: 0.8, g: 9.81}
    want = np.array([[float(theirs[i].subs(values | {ts: s})) for s in TIMES] for i in range(2)])
    model = models.point_mass_double_pendulum()
    q1, q2 = model.coordinates
    got = inverse_dynamics(model.system.equations_of_motion(), {q1: Q1, q2: Q2}, times=TIMES,
                           m=1.3, l=0.8, g=9.81)
    assert got == pytest.approx(want, rel=1e-12, abs=1e-12)


def test_cart_at_constant_speed_needs_the_rate_of_the_pendulum_momentum():
    # x = v t prescribed, theta free: the pendulum swings as in a Galilean frame
    # (theta'' = -g/L sin theta) and the cart's force is the rate of the horizontal momentum,
    # F = m L (theta'' cos theta - theta'^2 sin theta) (Newton)
    model = models.cart_pendulum()
    x, th = model.coordinates
    p = {"M": 2.0, "m": 0.5, "L": 0.8, "g": 9.81}
    got = inverse_dynamics(model.system.equations_of_motion(), {x: 0.7 * rm.t}, times=TIMES,
                           free_initial={th: (0.4, 0.0)}, **p)
    sol = scipy.integrate.solve_ivp(
        lambda _, y: [y[1], -p["g"] / p["L"] * np.sin(y[0])], (0, TIMES[-1]), [0.4, 0.0],
        method="DOP853", t_eval=TIMES, rtol=1e-12, atol=1e-13)
    theta, rate = sol.y
    acc = -p["g"] / p["L"] * np.sin(theta)
    want = p["m"] * p["L"] * (acc * np.cos(theta) - rate**2 * np.sin(theta))
    assert got.shape == (1, TIMES.size)
    assert got[0] == pytest.approx(want, rel=1e-7, abs=1e-8)


def test_partial_prescription_is_symbolic_in_the_free_coordinates():
    model = models.cart_pendulum()
    x, th = model.coordinates
    M, m, L, g = model.constants
    F = inverse_dynamics(model.system.equations_of_motion(), {x: 0.7 * rm.t})
    expected = m * L * (th.diff(rm.t, 2) * sp.cos(th) - th.diff(rm.t)**2 * sp.sin(th))
    assert sp.simplify(F[0] - expected) == 0


def test_errors_name_the_argument():
    th = rm.coordinates("theta")
    eqs = EquationsOfMotion(coordinates=(th,), mass_matrix=sp.Matrix([[1]]),
                            forcing=sp.Matrix([[-sp.sin(th)]]))
    with pytest.raises(ArgumentError, match="`prescribed` names an unknown coordinate"):
        inverse_dynamics(eqs, {"phi": rm.t})
    with pytest.raises(ArgumentError, match="`prescribed` must give expressions of t"):
        inverse_dynamics(eqs, {th: th + rm.t})
    with pytest.raises(ArgumentError, match="`prescribed` must be a non-empty dict"):
        inverse_dynamics(eqs, {})
    cart = models.cart_pendulum()
    with pytest.raises(ArgumentError, match=r"`free_initial` must give .* \['theta'\]"):
        inverse_dynamics(cart.system.equations_of_motion(), {"x": rm.t}, times=TIMES,
                         M=1, m=1, L=1, g=1)
    k = sp.Symbol("k")
    stiff = EquationsOfMotion(coordinates=(th,), mass_matrix=sp.Matrix([[1]]),
                              forcing=sp.Matrix([[-k * sp.sin(th)]]))
    with pytest.raises(ArgumentError, match=r"missing values for parameters \['k'\]"):
        inverse_dynamics(stiff, {th: rm.t}, times=TIMES)
    with pytest.raises(ArgumentError, match=r"unknown parameters \['m'\]"):
        inverse_dynamics(stiff, {th: rm.t}, times=TIMES, k=1, m=1)
    with pytest.raises(ArgumentError, match="has constraints"):
        inverse_dynamics(models.rolling_disc().system.equations_of_motion(), {"x": rm.t})
