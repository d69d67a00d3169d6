"""System.assemble and System.multipliers (ch. 25.3): constants whose names are also argument
names (u, q, t, values, rates) through ``params=``, constraints that depend on the time
(a driven pin) assembled at the time asked for, and a dependent set whose rates the
constraints do not determine refused."""

import math

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, ConnectionError_

M, U, G_, C = 2.0, 1.0, 9.81, 0.5


def pinned_rod(names=("u", "q", "g"), driven=False):
    """A rod of mass `q` and half-length `u` (constants with those names), its centre G at
    (x, y) and angle theta, its end A = G + u R1.j pinned at P: O, or (c t, 0) if driven."""
    x, y, th = rm.coordinates("x y theta")
    half, mass, g = rm.constants(" ".join(names), positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    body = rm.Body("rod", frame=R1, mass=mass, centre=G,
                   inertia=rm.inertia.rod(mass, 2 * half, axis=R1.j, centre=G))
    s = rm.System(galilean=R0)
    s.connect(R0, body, rm.joints.PlanarSupport(at=G, normal=R0.k))
    P = R0.point("P", rm.constants("c") * rm.t, 0, 0) if driven else R0.origin
    s.connect(R0, body, rm.joints.Pivot(at=P, axis=R0.k), meets=G.moved("A", half * R1.j),
              label="pin")
    s.act(rm.gravity(-g * R0.j))
    return s


def pin_force(theta, rate):
    """By hand: the pendulum about the pin, I = 4/3 m u^2, theta'' = -3 g sin(theta)/(4u);
    the pin's force on the rod m a_G + m g j with G - P = u (sin theta, -cos theta)."""
    acc = -3 * G_ * math.sin(theta) / (4 * U)
    ax = U * (acc * math.cos(theta) - rate**2 * math.sin(theta))
    ay = U * (acc * math.sin(theta) + rate**2 * math.cos(theta))
    return [M * ax, M * ay + M * G_]


@pytest.mark.parametrize("names", [("u", "q", "g"), ("values", "rates", "independent")])
def test_constants_named_like_arguments_go_through_params(names):
    s = pinned_rod(names)
    half, mass, g = names
    consts = {half: U, mass: M, g: G_}
    q0, u0 = s.assemble({"theta": 0.3, "x": 0.0, "y": -1.0}, independent=["theta"],
                        rates={"theta": 1.0}, params={half: U})
    assert q0["x"] == pytest.approx(U * math.sin(0.3), abs=1e-12)
    assert u0["y"] == pytest.approx(U * math.sin(0.3), abs=1e-12)
    lam = s.multipliers(list(q0.values()), list(u0.values()), params=consts)
    np.testing.assert_allclose(lam, pin_force(0.3, 1.0), rtol=1e-10)
    with pytest.raises(ArgumentError, match=r"given twice"):
        s.multipliers(list(q0.values()), list(u0.values()), params=consts, **{g: G_})


def test_a_constant_named_t():
    """A constant `t` is not the time: its value goes through params=."""
    s = pinned_rod(("u", "q", "t"))
    q0, u0 = s.assemble({"theta": 0.3, "x": 0.0, "y": -1.0}, independent=["theta"],
                        rates={"theta": 1.0}, params={"u": U})
    lam = s.multipliers(list(q0.values()), list(u0.values()), params={"u": U, "q": M, "t": G_})
    np.testing.assert_allclose(lam, pin_force(0.3, 1.0), rtol=1e-10)


def test_driven_constraint_is_assembled_at_the_time_given():
    """The pin moves at P = (c t, 0): at t = 2, theta = 0.3, theta' = 1 the rod's centre is
    P + u (sin theta, -cos theta) and its velocity (c + u cos(theta) theta', u sin(theta)
    theta'); the pin's force is the fixed pin's (a uniform motion of the pin)."""
    s = pinned_rod(driven=True)
    guess = {"theta": 0.3, "x": 0.0, "y": -1.0}
    q0, u0 = s.assemble(guess, independent=["theta"], rates={"theta": 1.0}, t=2.0, u=U, c=C)
    assert q0["x"] == pytest.approx(C * 2.0 + U * math.sin(0.3), abs=1e-12)
    assert q0["y"] == pytest.approx(-U * math.cos(0.3), abs=1e-12)
    assert u0["x"] == pytest.approx(C + U * math.cos(0.3), abs=1e-12)
    assert u0["y"] == pytest.approx(U * math.sin(0.3), abs=1e-12)
    consts = {"u": U, "q": M, "g": G_, "c": C}
    lam = s.multipliers(list(q0.values()), list(u0.values()), 2.0, params=consts)
    np.testing.assert_allclose(lam, pin_force(0.3, 1.0), rtol=1e-10)
    with pytest.raises(ArgumentError, match=r"`t` must be given.*depend on the time"):
        s.assemble(guess, independent=["theta"], u=U, c=C)
    with pytest.raises(ArgumentError, match=r"`t` must be given.*depend on the time"):
        s.multipliers(list(q0.values()), list(u0.values()), params=consts)
    # without time in the constraints, t is not needed (and not used)
    fixed = pinned_rod()
    a, b = fixed.assemble(guess, independent=["theta"], u=U), \
        fixed.assemble(guess, independent=["theta"], u=U, t=5.0)
    assert a == b


def test_dependent_rates_not_determined_are_refused():
    """The rod horizontal (theta = pi/2) with x independent: the pin's rows are x' = 0 and
    y' - u theta' = 0, two unknowns (y', theta') for one row: refused, not a least-squares
    (minimum-norm) guess."""
    s = pinned_rod()
    with pytest.raises(ConnectionError_, match=r"dependent rates .* not determined"):
        s.assemble({"theta": math.pi / 2, "x": U, "y": 0.0}, independent=["x"],
                   rates={"x": 0.0}, u=U)


def test_an_input_given_as_a_function_of_time_needs_t():
    """A horizontal force F(t) at G: theta'' = (-m g u sin + F u cos) / (4/3 m u^2), the pin's
    force m a_G + m g j - F i; F = 3 t given as a function, evaluated at the t given."""
    s = pinned_rod()
    F = sp.Function("F")(rm.t)
    body = s.bodies[0]
    s.act(rm.Force(on=body, vector=F * s.galilean.i, at=body.frame.origin))
    q0, u0 = s.assemble({"theta": 0.3, "x": 0.0, "y": -1.0}, independent=["theta"],
                        rates={"theta": 1.0}, u=U)
    consts = {"u": U, "q": M, "g": G_, "F": lambda t: 3 * t}
    lam = s.multipliers(list(q0.values()), list(u0.values()), 0.5, params=consts)
    th, w, f = 0.3, 1.0, 1.5
    acc = (-M * G_ * U * math.sin(th) + f * U * math.cos(th)) / (4 / 3 * M * U**2)
    ax = U * (acc * math.cos(th) - w**2 * math.sin(th))
    ay = U * (acc * math.sin(th) + w**2 * math.cos(th))
    np.testing.assert_allclose(lam, [M * ax - f, M * ay + M * G_], rtol=1e-10)
    with pytest.raises(ArgumentError, match=r"`t` must be given"):
        s.multipliers(list(q0.values()), list(u0.values()), params=consts)
    # a number for F: no time needed
    lam2 = s.multipliers(list(q0.values()), list(u0.values()), params={**consts, "F": f})
    np.testing.assert_allclose(lam2, lam, rtol=1e-12)


def test_multipliers_need_a_state_on_the_constraints():
    """The docs ask for a state on the constraints (elsewhere the values carry Baumgarte's
    correction): a state off them by more than 1e-9 of the magnitude of their terms
    (assemble's rule) is refused and the conditions named; within it, accepted."""
    s = pinned_rod()
    consts = {"u": U, "q": M, "g": G_}
    q0, u0 = s.assemble({"theta": 0.3, "x": 0.0, "y": -1.0}, independent=["theta"],
                        rates={"theta": 1.0}, params={"u": U})
    q, u = np.array(list(q0.values())), np.array(list(u0.values()))
    with pytest.raises(ArgumentError, match=r"not on the constraints.*pin\.u"):
        s.multipliers(q + [1e-6, 0, 0], u, params=consts)
    with pytest.raises(ArgumentError, match=r"not on the constraints.*pin\.v \(rate\)"):
        s.multipliers(q, u + [0, 1e-6, 0], params=consts)
    # the boundary: 1e-9 of the magnitude of the condition's terms (every rate at the
    # largest |q'_j|; the rule of rigidmech._core.rules, issue 19), here read from the
    # compiled closure: the rate of y moved just inside it is accepted, just outside refused
    from rigidmech.dynamics.assembly import Closure

    closure = Closure(s.equations_of_motion().constraints)
    row = closure.labels.index("pin.v")
    scale = closure.scales(q, u, 0.0, closure.constants(consts))[1][row]
    np.testing.assert_allclose(
        s.multipliers(q, u + [0, 1e-9 * scale * (1 - 1e-3), 0], params=consts),
        pin_force(0.3, 1.0), rtol=1e-7)
    with pytest.raises(ArgumentError, match=r"not on the constraints"):
        s.multipliers(q, u + [0, 1e-9 * scale * (1 + 1e-3), 0], params=consts)


def test_multipliers_decide_the_time_dependence_once_per_equations(monkeypatch):
    """Whether the equations depend on t explicitly is a property of the equations: decided at
    the first multipliers() call, not re-derived (symbolically) at every state of a motion."""
    import rigidmech.dynamics.linked as linked

    calls = []

    def counting(*args, **kwargs):
        calls.append(1)
        return rm.dynamics.assembly.explicit_time(*args, **kwargs)

    monkeypatch.setattr(linked, "explicit_time", counting)
    s = pinned_rod()
    consts = {"u": U, "q": M, "g": G_}
    for theta in (0.3, 0.5):
        q0, u0 = s.assemble({"theta": theta, "x": 0.0, "y": -1.0}, independent=["theta"],
                            rates={"theta": 1.0}, params={"u": U})
        np.testing.assert_allclose(
            s.multipliers(list(q0.values()), list(u0.values()), params=consts),
            pin_force(theta, 1.0), rtol=1e-10)
    assert len(calls) == 1
