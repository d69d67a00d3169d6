"""Tests of ``python -m rigidmech modes`` (rigidmech.scenes.modes, issue 14).

The double pendulum of two uniform rods (mass m, length L, absolute angles) is checked
against M and K derived here independently from its Lagrangian with sympy (ch. 25.4.3):
M = m L^2 [[4/3, 1/2], [1/2, 1/3]], K = m g L diag(3/2, 1/2), whose frequency equation
7 x^2 - 42 x + 27 = 0 (x = ω² L / g) gives ω² = (g/L)(3 ∓ 6/√7).
"""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import SceneError
from rigidmech.actions import Pivot, gravity
from rigidmech.scenes import Built, Scene, cli
from rigidmech.scenes.modes import SceneModes, scene_modes


def _double_pendulum_MK():
    """M and K of two uniform rods from T and V written by hand (sympy only)."""
    t = sp.Symbol("t")
    m, L, g = sp.symbols("m L g", positive=True)
    a, b = sp.Function("a")(t), sp.Function("b")(t)
    G1 = sp.Matrix([L / 2 * sp.cos(a), L / 2 * sp.sin(a)])
    G2 = sp.Matrix([L * sp.cos(a) + L / 2 * sp.cos(b), L * sp.sin(a) + L / 2 * sp.sin(b)])
    v1, v2 = G1.diff(t), G2.diff(t)
    T = (m * v1.dot(v1) / 2 + m * L**2 / 12 * a.diff(t) ** 2 / 2
         + m * v2.dot(v2) / 2 + m * L**2 / 12 * b.diff(t) ** 2 / 2)
    V = -m * g * (G1[0] + G2[0])  # x points down
    qd = [a.diff(t), b.diff(t)]
    M = sp.Matrix(2, 2, lambda i, j: sp.diff(T, qd[i], qd[j])).subs({a: 0, b: 0})
    K = sp.Matrix(2, 2, lambda i, j: sp.diff(V, [a, b][i], [a, b][j])).subs({a: 0, b: 0})
    return sp.simplify(M), sp.simplify(K), (m, L, g)


def test_independent_M_K_are_the_textbook_ones():
    M, K, (m, L, g) = _double_pendulum_MK()
    assert M == m * L**2 * sp.Matrix([[sp.Rational(4, 3), sp.Rational(1, 2)],
                                      [sp.Rational(1, 2), sp.Rational(1, 3)]])
    assert K == m * g * L * sp.diag(sp.Rational(3, 2), sp.Rational(1, 2))
    w2 = sp.Symbol("w2")
    roots = sorted(sp.solve((K - w2 * M).det(), w2), key=lambda r: float(r.subs(
        {m: 1, L: 1, g: 1})))
    assert [sp.simplify(r - g / L * (3 + s * 6 / sp.sqrt(7))) for r, s in
            zip(roots, (-1, 1), strict=True)] == [0, 0]


@pytest.mark.parametrize(("m", "L", "g"), [pytest.param(1.0, 1.0, 9.81, id="defaults"),
                                           pytest.param(2.5, 0.4, 3.7, id="other")])
def test_double_pendulum_frequencies_and_shapes(m, L, g):
    sm = scene_modes("double-pendulum", params={"m": m, "L": L, "g": g})
    expected = [math.sqrt(g / L * (3 + s * 6 / math.sqrt(7))) for s in (-1, 1)]
    np.testing.assert_allclose(sm.frequencies, expected, rtol=1e-12)
    M, K, syms = _double_pendulum_MK()
    values = dict(zip(syms, (m, L, g), strict=True))
    Mn = np.array(M.subs(values).tolist(), dtype=float)
    Kn = np.array(K.subs(values).tolist(), dtype=float)
    for r, w in enumerate(sm.frequencies):  # (K - ω² M) φ = 0, largest component 1
        phi = sm.shapes[:, r]
        np.testing.assert_allclose((Kn - w**2 * Mn) @ phi, 0, atol=1e-10 * np.abs(Kn).max())
        assert np.max(np.abs(phi)) == pytest.approx(1.0)
    # symbolic M and K of the linearisation: the independent ones
    lin = sm.linear
    by_name = {str(s): s for s in lin.parameters}
    rule = {s: by_name[str(s)] for s in syms}
    assert sp.simplify(lin.M - M.xreplace(rule)) == sp.zeros(2)
    assert sp.simplify(lin.K - K.xreplace(rule)) == sp.zeros(2)


def test_other_scenes_of_the_catalogue():
    # compound pendulum: ω² = 3 g / (2 L) (ch. 22.2.1); spring: ω² = k / m
    assert scene_modes("simple-pendulum", params={"L": 2.0}).frequencies[0] == pytest.approx(
        math.sqrt(3 * 9.81 / 4), rel=1e-12)
    assert scene_modes("spring-mass", params={"k": 8.0, "m": 2.0}).frequencies[0] == (
        pytest.approx(2.0, rel=1e-12))
    # block on a slide: a free (zero-frequency) mode, and ω² = 6 g (M + m) / (L (4 M + m))
    sm = scene_modes("slider-pendulum")
    M, m, L, g = 2.0, 1.0, 1.0, 9.81
    w = math.sqrt(6 * g * (M + m) / (L * (4 * M + m)))
    np.testing.assert_allclose(sm.frequencies, [0.0, w], rtol=1e-12, atol=1e-12)


def test_scene_modes_is_immutable():
    sm = scene_modes("spring-mass")
    assert isinstance(sm, SceneModes) and "spring-mass" in repr(sm)
    with pytest.raises(AttributeError, match="immutable"):
        sm.frequencies = None


def _sideways_pendulum():
    theta = rm.coordinates("theta")
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=theta)
    G = R0.origin.moved("G", L / 2 * R1.i)
    bar = rm.Body("bar", frame=R1, mass=m, centre=G,
                  inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G))
    system = rm.System(galilean=R0)
    system.connect(R0, bar, Pivot(at=R0.origin, axis=R0.k))
    system.act(gravity(g * R0.j))      # gravity along j: the equilibrium is theta = pi/2
    return Built(system, (bar,))


SIDEWAYS = Scene("sideways", "Pendulum with gravity along j", "test", coordinates=("theta",),
                 parameters=(("m", 1.0, ""), ("L", 1.0, ""), ("g", 9.81, "")), q0=(0.0,),
                 builder=_sideways_pendulum)


def test_no_equilibrium_at_zero_is_refused():
    with pytest.raises(SceneError, match=r"scene 'sideways' has no equilibrium at q = 0 "
                       r"\(q' = 0\): there f\(0, 0\) = \[4\.905\]"):
        scene_modes(SIDEWAYS)


def _upside_down():
    theta = rm.coordinates("theta")
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=theta)
    G = R0.origin.moved("G", L / 2 * R1.i)
    bar = rm.Body("bar", frame=R1, mass=m, centre=G,
                  inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G))
    system = rm.System(galilean=R0)
    system.connect(R0, bar, Pivot(at=R0.origin, axis=R0.k))
    system.act(gravity(-g * R0.i))     # the rod stands upright: q = 0 is unstable
    return Built(system, (bar,))


def test_unstable_equilibrium_is_refused():
    scene = Scene("inverted", "Inverted compound pendulum", "test", coordinates=("theta",),
                  parameters=(("m", 1.0, ""), ("L", 1.0, ""), ("g", 9.81, "")), q0=(0.0,),
                  builder=_upside_down)
    with pytest.raises(SceneError, match=r"scene 'inverted': no natural modes about q = 0: "
                       r"`stiffness` must be positive semi-definite"):
        scene_modes(scene)


@pytest.mark.parametrize(("params", "match"), [
    pytest.param({"l": 1.0}, "unknown parameter 'l' for scene 'double-pendulum'; its "
                 "parameters are m, L, g.", id="unknown"),
    pytest.param({"L": -1.0}, r"parameter `L` must be > 0 \(the scene declares it positive\); "
                 "got -1", id="negative"),
    pytest.param({"L": float("nan")}, "parameter `L` must be finite; got nan", id="nan"),
])
def test_bad_parameters(params, match):
    with pytest.raises(SceneError, match=match):
        scene_modes("double-pendulum", params=params)


def test_cli_modes_default_is_the_double_pendulum(capsys):
    assert cli.main(["modes"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Double pendulum of two uniform rods (double-pendulum, book ch. "
                          "25.4.3, 27.5)\nparameters: m=1, L=1, g=9.81\n"
                          "equilibrium: theta1 = 0, theta2 = 0, with q' = 0\n")
    assert "  M = [[4*L**2*m/3, L**2*m/2], [L**2*m/2, L**2*m/3]]" in out
    assert "  K = [[3*L*g*m/2, 0], [0, L*g*m/2]]" in out
    w1 = math.sqrt(9.81 * (3 - 6 / math.sqrt(7)))
    w2 = math.sqrt(9.81 * (3 + 6 / math.sqrt(7)))
    assert f"mode 1: omega = {w1:.6g} rad/s" in out and f"mode 2: omega = {w2:.6g} rad/s" in out
    assert "theta2: 1" in out


def test_cli_modes_with_param(capsys):
    assert cli.main(["modes", "simple-pendulum", "--param", "L=2"]) == 0
    out = capsys.readouterr().out
    assert "parameters: m=1, L=2, g=9.81" in out
    assert f"omega = {math.sqrt(3 * 9.81 / 4):.6g} rad/s" in out


@pytest.mark.parametrize(("argv", "match"), [
    pytest.param(["modes", "quadruple-pendulum"], "rigidmech: error: unknown scene "
                 "'quadruple-pendulum'; known scenes: ", id="unknown"),
    pytest.param(["modes", "coulomb-oscillator"], "rigidmech: error: scene "
                 "'coulomb-oscillator' changes regime along its motion", id="regime"),
    pytest.param(["modes", "--param", "m=1", "--param", "m=2"], "rigidmech: error: --param m "
                 "given twice", id="twice"),
    pytest.param(["modes", "--param", "m"], "rigidmech: error: argument --param: expected "
                 "NAME=VALUE", id="form"),
])
def test_cli_modes_bad_input_one_line(capsys, argv, match):
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith(match) and err.count("\n") == 1
