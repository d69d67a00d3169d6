"""Tests of rigidmech.scenes: the catalogue, the run pipeline and the physics of its scenes.

Physics checks against closed forms of the book:

* compound pendulum (ch. 22.2.1): J_O theta'' = -m g (L/2) sin(theta) with J_O = m L^2/3, so
  small oscillations have the period T0 = 2 pi sqrt(2L/(3g)) and large ones
  T = 4 sqrt(2L/(3g)) K(k), k = sin(theta0/2) (complete elliptic integral of the first kind);
* double pendulum (ch. 25.4.3): conservative, its energy is a first integral;
* mass on a spring (ch. 21.2.2): x(t) = x0 cos(sqrt(k/m) t);
* pendulum on a frictionless slide (ch. 24.3): no horizontal external force, so the horizontal
  momentum (M + m) x' + m (L/2) cos(theta) theta' is conserved.
"""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.optimize import brentq
from scipy.special import ellipk

from rigidmech import scenes
from rigidmech._core.errors import SceneError
from rigidmech.dynamics import System


def _upward_zero_crossings(report):
    """Times where the first coordinate crosses zero upwards, located on the solver's dense
    output (brentq to a few ulps: the accuracy is that of the dense output)."""
    sim = report.simulation
    sol = sim.result.sol
    q = sim.q[0]
    idx = np.nonzero((q[:-1] < 0) & (q[1:] >= 0))[0]
    return np.array([brentq(lambda t: sol(t)[0], sim.t[i], sim.t[i + 1], xtol=1e-15,
                            rtol=4 * np.finfo(float).eps) for i in idx])


# -- catalogue ----------------------------------------------------------------------------
def test_names_and_catalogue_agree():
    assert scenes.names() == tuple(s.name for s in scenes.catalogue())
    assert {"simple-pendulum", "double-pendulum", "slider-pendulum", "spring-mass"} <= set(
        scenes.names())


@pytest.mark.parametrize("scene", scenes.catalogue(), ids=lambda s: s.name)
def test_scene_description_matches_its_system(scene):
    built = scene.build()
    assert isinstance(built.system, System)
    assert built.bodies == built.system.bodies
    eqs = built.system.equations_of_motion()
    assert tuple(c.func.__name__ for c in eqs.coordinates) == scene.coordinates
    assert {p.name for p in eqs.parameters} == set(scene.defaults)
    assert len(scene.q0) == len(scene.u0) == scene.dof
    assert scene.section.startswith("ch. ")


def test_get_passes_a_scene_through_and_rejects_unknown_names():
    sc = scenes.get("double-pendulum")
    assert scenes.get(sc) is sc
    with pytest.raises(SceneError, match=r"unknown scene 'triple'; known scenes: "
                       r"simple-pendulum, double-pendulum, slider-pendulum, spring-mass"):
        scenes.get("triple")
    with pytest.raises(SceneError, match=r"unknown scene 3; known scenes"):
        scenes.get(3)


def test_scene_is_immutable_value():
    sc = scenes.get("simple-pendulum")
    with pytest.raises(AttributeError):
        sc.t_end = 3.0
    d = sc.defaults
    d["m"] = 5.0
    assert sc.defaults["m"] == 1.0
    assert sc == scenes.get("simple-pendulum") and hash(sc) == hash(scenes.get("simple-pendulum"))
    assert repr(sc) == ("Scene('simple-pendulum', title='Compound pendulum: a uniform rod on a "
                        "pivot', section='ch. 22.2.1')")


def test_scene_checks_its_initial_state():
    with pytest.raises(SceneError, match=r"scene 'bad': `q0` and `u0` must give 1 values"):
        scenes.Scene("bad", "t", "ch. 1", coordinates=("x",), parameters=(), q0=(1.0, 2.0),
                     builder=None)


# -- run pipeline -------------------------------------------------------------------------
def test_run_report_fields_and_summary(tmp_path):
    path = tmp_path / "out.png"
    rep = scenes.run("double-pendulum", t_end=0.5, params={"m": 2}, q0=[1.0, 0.5], plot=path)
    assert rep.parameters == {"m": 2.0, "L": 1.0, "g": 9.81}
    assert rep.q0 == (1.0, 0.5) and rep.u0 == (0.0, 0.0) and rep.t_end == 0.5
    assert set(rep.timings) == {"derive", "compile", "integrate", "energy"}
    assert all(v >= 0 for v in rep.timings.values())
    assert rep.nfev > 0 and rep.nsteps > 0
    assert rep.final_q == tuple(rep.simulation.q[:, -1])
    assert path.stat().st_size > 1000 and rep.plot_path == str(path)
    text = rep.summary()
    assert "Double pendulum of two uniform rods (double-pendulum, book ch. 25.4.3, 27.5)" in text
    assert "energy drift:" in text and "timings: derive" in text and "plot written to" in text
    assert str(rep) == text
    assert repr(rep).startswith("RunReport(scene='double-pendulum', t_end=0.5, method='dop853'")
    with pytest.raises(AttributeError, match="RunReport is immutable"):
        rep.nfev = 0


def test_equations_text_one_line_per_equation():
    eqs = scenes.get("double-pendulum").build().system.equations_of_motion()
    lines = scenes.equations_text(eqs).splitlines()
    assert lines == [
        "(4*L**2*m/3)*theta1_ddot + (L**2*m*cos(theta1 - theta2)/2)*theta2_ddot = "
        "-L**2*m*theta2_dot**2*sin(theta1 - theta2)/2 - 3*L*g*m*sin(theta1)/2",
        "(L**2*m*cos(theta1 - theta2)/2)*theta1_ddot + (L**2*m/3)*theta2_ddot = "
        "L**2*m*theta1_dot**2*sin(theta1 - theta2)/2 - L*g*m*sin(theta2)/2",
    ]
    pretty = scenes.equations_text(eqs, pretty=True)
    assert "θ̈₁" in pretty and "θ̇₂" in pretty


def test_run_with_a_fixed_step_method():
    rep = scenes.run("spring-mass", method="rk4", step=1e-3, t_end=1.0)
    # rk4, h = 1e-3, omega = 2: global error ~ (omega h)^4 t ~ 1e-11
    assert_allclose(rep.final_q[0], 0.5 * math.cos(2.0), atol=1e-9)
    assert rep.step == 1e-3 and "step=0.001" in rep.summary()


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        pytest.param({"params": {"l": 1}}, r"unknown parameter 'l' for scene 'simple-pendulum'; "
                     r"its parameters are m, L, g\.", id="param-name"),
        pytest.param({"params": {"m": "heavy"}}, r"parameter `m` must be a number; got 'heavy'",
                     id="param-value"),
        pytest.param({"params": {"m": math.inf}}, r"parameter `m` must be finite; got inf",
                     id="param-inf"),
        pytest.param({"q0": [1.0, 2.0]}, r"`q0` must give 1 values for scene 'simple-pendulum' "
                     r"\(one per coordinate theta\); got 2", id="q0-length"),
        pytest.param({"q0": 1.0}, r"`q0` must be a sequence of 1 numbers; got 1\.0",
                     id="q0-scalar"),
        pytest.param({"u0": [math.nan]}, r"`u0` entry 0 must be finite; got nan", id="u0-nan"),
        pytest.param({"method": "rk99"}, r"unknown method 'rk99'; known methods: .*dop853",
                     id="method"),
        pytest.param({"method": "rk4"}, r"method 'rk4' has a fixed step: give `step`",
                     id="fixed-no-step"),
        pytest.param({"step": 0.1}, r"`step` is only for fixed-step methods; 'dop853'",
                     id="step-adaptive"),
        pytest.param({"method": "rk4", "step": -1}, r"`step` must be > 0; got -1",
                     id="step-negative"),
        pytest.param({"method": "verlet"}, r"method 'verlet' has a fixed step: give `step`",
                     id="second-order-no-step"),
        pytest.param({"t_end": 0}, r"`t_end` must be > 0; got 0", id="t-end"),
        pytest.param({"rtol": -1e-3}, r"`rtol` must be > 0 and `atol` >= 0", id="rtol"),
    ],
)
def test_run_rejects_misuse(kwargs, match):
    with pytest.raises(SceneError, match=match):
        scenes.run("simple-pendulum", **kwargs)


def test_run_refuses_a_second_order_method_on_velocity_dependent_equations():
    # The double pendulum's forcing has q'^2 terms: q'' = a(t, q) does not hold. (The simple
    # pendulum's equation, m L^2/3 theta'' = -m g L sin(theta)/2, has none: verlet runs it.)
    with pytest.raises(SceneError, match=r"method 'verlet' integrates q'' = a\(t, q\) only; "
                       r"the equations of scene 'double-pendulum' depend on q' too"):
        scenes.run("double-pendulum", method="verlet", step=0.01, t_end=0.1)


# -- physics ------------------------------------------------------------------------------
def test_compound_pendulum_small_angle_period():
    # theta0 = 0.01 rad: T = T0 (1 + theta0^2/16 + 11 theta0^4/3072 + ...), the correction
    # is 6.25e-6, so T0 holds to rtol 1e-5 and T0 (1 + theta0^2/16) to 1e-8 (next term 3.6e-11
    # plus the error of the integration at rtol 1e-12).
    L, g, theta0 = 0.7, 9.81, 0.01
    rep = scenes.run("simple-pendulum", q0=[theta0], params={"L": L}, t_end=8.0,
                     rtol=1e-12, atol=1e-14, n_output=2001)
    crossings = _upward_zero_crossings(rep)
    assert crossings.size >= 4
    periods = np.diff(crossings)
    T0 = 2 * math.pi * math.sqrt(2 * L / (3 * g))
    assert_allclose(periods, T0, rtol=1e-5)
    assert_allclose(periods, T0 * (1 + theta0**2 / 16), rtol=1e-8)


@pytest.mark.parametrize("theta0", [1.0, 2.0, 3.0])
def test_compound_pendulum_large_amplitude_period(theta0):
    # T = 4 sqrt(2L/(3g)) K(k), k = sin(theta0/2); scipy's ellipk takes m = k^2. At rtol 1e-12
    # the dense output of dop853 locates the crossings to ~1e-12 s: 1e-9 relative holds.
    m, L, g = 2.0, 0.8, 9.81
    T = 4 * math.sqrt(2 * L / (3 * g)) * ellipk(math.sin(theta0 / 2) ** 2)
    rep = scenes.run("simple-pendulum", q0=[theta0], params={"m": m, "L": L},
                     t_end=3.2 * T, rtol=1e-12, atol=1e-14, n_output=2001)
    periods = np.diff(_upward_zero_crossings(rep))
    assert periods.size >= 2
    assert_allclose(periods, T, rtol=1e-9)


def test_double_pendulum_energy_is_conserved():
    # conservative system (perfect pivots, gravity): E = T + V is a first integral. dop853 at
    # rtol 1e-12, atol 1e-14 keeps the local errors ~1e-13; over 10 s of chaotic motion
    # (~1700 steps) the drift stays below 1e-9 relative.
    rep = scenes.run("double-pendulum", t_end=10.0, rtol=1e-12, atol=1e-14)
    assert rep.energy_drift < 1e-9
    e = rep.simulation.energy()
    assert_allclose(e, e[0], rtol=1e-9)


def test_spring_mass_free_vibration():
    # x'' = -(k/m) x for x > -l0: x(t) = x0 cos(omega t), omega = sqrt(k/m) (ch. 21.2.2);
    # rtol 1e-12 over ~5 periods: 1e-9 absolute on an amplitude of 0.3.
    m, k, x0 = 2.0, 9.0, 0.3
    rep = scenes.run("spring-mass", q0=[x0], params={"m": m, "k": k}, t_end=10.0,
                     rtol=1e-12, atol=1e-14)
    sim = rep.simulation
    assert_allclose(sim.q[0], x0 * np.cos(math.sqrt(k / m) * sim.t), atol=1e-9)


def test_slider_pendulum_horizontal_momentum_is_conserved():
    # no horizontal external force on {block, rod} (ch. 24.3): the horizontal momentum
    # (M + m) x' + m (L/2) cos(theta) theta' stays at its initial value 0. Its scale is
    # m (L/2) max|theta'| ~ 2; rtol 1e-10 gives ~1e-9 absolute.
    M, m, L = 3.0, 1.5, 0.9
    rep = scenes.run("slider-pendulum", params={"M": M, "m": m, "L": L}, q0=[0.0, 2.5],
                     t_end=5.0, rtol=1e-11, atol=1e-13)
    sim = rep.simulation
    x_dot, theta, theta_dot = sim.u[0], sim.q[1], sim.u[1]
    p = (M + m) * x_dot + m * L / 2 * np.cos(theta) * theta_dot
    assert_allclose(p, 0.0, atol=1e-8)
    assert np.max(np.abs(x_dot)) > 0.1  # the block does move
    assert rep.energy_drift < 1e-9
