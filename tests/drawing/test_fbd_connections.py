"""Free-body diagrams of the catalogue's models at a state: a rolling contact, a loop-closing
joint and a body in space (book, ch. 10.1.3, 18.2, 20, 25.3).

Independent values: a uniform disk rolling without slipping down a slope alpha has the
acceleration a = 2/3 g sin(alpha); the plane's action on it is N = m g cos(alpha) along the
normal and a friction F = m a / 2 = m g sin(alpha) / 3 up the slope (theorem of the moment
about the centre, I = m r^2 / 2). For any isolated set, the resultant of the external actions
is the sum of m a(G) over its bodies (theorem of the resultant, ch. 18.1.3), a(G) computed
here by differentiating the mass centres' positions.
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import models
from rigidmech.drawing import external_actions, free_body_diagram


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def acceleration_sum(system, bodies, q, u, params):
    """sum m a(G) over ``bodies`` at the state, q'' from the equations of motion."""
    eqs = system.equations_of_motion()
    coords = system.coordinates
    rhs = eqs.rhs(**{p.name: params[p.name] for p in eqs.parameters})
    acc = rhs(0.0, np.concatenate([q, u]))[len(coords):]
    rule = {}
    for c, qi, ui, ai in zip(coords, q, u, acc, strict=True):
        rule[c.diff(rm.t, 2)] = ai
        rule[c.diff(rm.t)] = ui
        rule[c] = qi
    R0 = system.reference
    consts = {s: params[s.name] for s in system.parameters if s.name in params}
    total = np.zeros(3)
    for b in bodies:
        a = [sp.sympify(c).diff(rm.t, 2) for c in b.centre.coordinates(R0)]
        total += float(b.mass.xreplace(consts)) * np.array(
            [float(x.xreplace(rule).xreplace(consts)) for x in a])
    return total


def test_rolling_disk_down_a_slope():
    alpha = 0.3
    wheel = models.wheel_on_incline(alpha)
    params = {"m": 2.0, "g": 9.81, "r": 0.5}
    d = free_body_diagram(wheel.system, wheel.bodies[0], q=[0.0, 0.0], u=[0.0, 0.0],
                          params=params)
    contact, weight = d.actions
    assert contact.kind == "rolling" and weight.kind == "weight"
    assert [c.name for c in contact.components] == ["N_1", "T1_1", "T2_1"]
    normal = np.array([math.sin(alpha), math.cos(alpha), 0.0])
    down = np.array([math.cos(alpha), -math.sin(alpha), 0.0])
    m, g = 2.0, 9.81
    assert contact.force @ normal == pytest.approx(m * g * math.cos(alpha), rel=1e-10)
    assert contact.force @ down == pytest.approx(-m * g * math.sin(alpha) / 3, rel=1e-10)
    values = {c.name: c.value for c in contact.components}
    assert values["N_1"] == pytest.approx(m * g * math.cos(alpha), rel=1e-10)
    arrow = next(a for a in d.arrows if a.name == "1")
    assert np.allclose(d.view.rows.T @ arrow.vector * d.scale, contact.force, rtol=1e-10)


def test_four_bar_coupler_and_its_loop_closing_joint():
    bar4 = models.four_bar()
    s = bar4.system
    q, u = s.assemble({"q1": 1.2, "q2": -1.0, "q3": 1.6}, independent=["q1"],
                      rates={"q1": 1.0})
    params = {"m": 1.0, "g": 9.81}
    coupler = bar4.body("coupler")
    # the pivots are spatial: the out-of-plane 4.Z, 4.L, 4.M are hyperstatic, taken zero
    with pytest.warns(rm.errors.HyperstaticWarning, match=r"4\.Z, 4\.L, 4\.M, "):
        acts = external_actions(s, coupler, q=q, u=u, params=params)
    assert [(a.kind, a.label) for a in acts] == [("connection", "2"), ("connection", "4"),
                                                  ("weight", "W")]
    # joint 4 closes the loop (coupler -> rocker): on the coupler, its reaction
    assert [c.name for c in acts[1].components][:2] == ["X_4", "Y_4"]
    assert np.allclose(acts[1].components[0].direction, [-1, 0, 0])
    qv = np.array([q["q1"], q["q2"], q["q3"]])
    uv = np.array([u["q1"], u["q2"], u["q3"]])
    total = sum(a.force for a in acts)
    assert np.allclose(total, acceleration_sum(s, [coupler], qv, uv, params), atol=1e-9)
    # the three bars together: the ground's pivots and the weights only
    everything = [bar4.body(n) for n in ("crank", "coupler", "rocker")]
    with pytest.warns(rm.errors.HyperstaticWarning, match=r"4\.Z, 4\.L, 4\.M, "):
        d = free_body_diagram(s, everything, q=q, u=u, params=params)
    assert [a.name for a in d.arrows] == ["1", "3", "W_crank", "W_coupler", "W_rocker"]
    total = sum(a.force for a in d.actions)
    assert np.allclose(total, acceleration_sum(s, everything, qv, uv, params), atol=1e-9)


def test_heavy_top_is_drawn_in_space():
    top = models.heavy_top()
    params = {"m": 1.0, "g": 9.81, "l": 0.1, "A": 0.01, "C": 0.02}
    q, u = np.array([0.1, 0.5, 0.0]), np.array([0.0, 0.0, 20.0])
    d = free_body_diagram(top.system, top.bodies[0], q=q, u=u, params=params)
    assert d.dim == 3 and d.ax.name == "3d"
    assert [a.name for a in d.arrows] == ["1", "W"]
    assert d.label_texts[0].startswith("X_1 = ") and "Z_1 = " in d.label_texts[0]
    total = sum(a.force for a in d.actions)
    assert np.allclose(total, acceleration_sum(top.system, top.bodies, q, u, params),
                       atol=1e-9)
    with pytest.raises(rm.errors.ArgumentError, match="`dim` = 2 needs a planar diagram"):
        free_body_diagram(top.system, top.bodies[0], q=q, u=u, params=params, dim=2)


def test_a_one_sided_contact_with_friction_of_a_system():
    """The ball sliding on the floor (FrictionContact at I): its action depends on the
    regime, so the diagram shows its unknowns (named as rigidmech.regimes names the contact,
    after its point) and its cone; values given by name (those of
    ContactMotion.contact_actions) place it in the cone."""
    ball = models.sliding_ball(mu=0.3)
    params = {"m": 1.0, "r": 0.1, "g": 9.81}
    q = [0.0, 0.0, 0.1, 0.0, 0.0, 0.0]
    acts = external_actions(ball.system, ball.bodies[0], q=q, params=params)
    contact = next(a for a in acts if a.kind == "contact")
    assert contact.label == "I" and contact.force is None
    assert [c.name for c in contact.components] == ["N_I", "T1_I", "T2_I"]
    assert contact.cone.half_angle == pytest.approx(math.atan(0.3), rel=1e-15)
    sliding = external_actions(ball.system, ball.bodies[0], q=q, params=params,
                               values={"N_I": 9.81, "T1_I": -0.3 * 9.81, "T2_I": 0.0})
    contact = next(a for a in sliding if a.kind == "contact")
    assert contact.cone.status == "edge"
    assert np.allclose(contact.force, [-0.3 * 9.81, 0.0, 9.81])
