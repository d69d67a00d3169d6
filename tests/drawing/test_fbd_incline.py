"""Free-body diagram of a block on a rough incline (book, ch. 13.1.2, 14.4, 23.2.5).

Conventions: the model's slope Ri = R0 turned by -alpha about k, x down the slope along Ri.i;
the plane's action on the block at its centre P is N Ri.j + T Ri.i (normal into the block,
tangent down the slope), gravity -g R0.j. At rest: N = m g cos(alpha), T = -m g sin(alpha)
(the friction holds the block up the slope), inside the friction cone while
tan(alpha) < f_s; on its edge at tan(alpha) = f_s (limiting equilibrium).
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
from rigidmech.actions import ContactLaws, Coulomb
from rigidmech.drawing import (
    external_actions,
    free_body_diagram,
    limiting_values,
)
from rigidmech.drawing.fbd_actions import CONE_RTOL

M, G, F_S = 2.0, 9.81, 0.5


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


class _Block:
    """The catalogue model's frames, constants and gravity, the block held at the origin
    of the slope (statics takes no coordinate: the model's x(t) would stay a symbol)."""

    def __init__(self):
        model = models.block_on_incline()
        R0, Ri, _ = model.frames
        m = model.constants[0]
        self.frames = (R0, Ri)
        self.bodies = (rm.Body("block", frame=Ri, mass=m, centre=Ri.origin),)
        self.gravity = model.system.actions[0]          # -g R0.j


def rough_incline(friction=F_S):
    block = _Block()
    R0, Ri = block.frames
    st = rm.statics.Statics(R0)
    st.connect(R0, block.bodies[0], ContactLaws(at=Ri.origin, normal=Ri.j, tangent=Ri.i,
                                                friction=Coulomb(friction)), label="A")
    st.act(block.gravity)
    return block, st


def test_at_rest_inside_the_cone_with_the_books_names_and_values():
    block, st = rough_incline()
    numbers = {"m": M, "g": G, "alpha": 0.3}
    d = free_body_diagram(st, block.bodies[0], params=numbers,
                          equilibrium=st.solve(values=numbers))
    contact, weight = d.actions
    assert contact.kind == "contact" and weight.kind == "weight"
    assert [c.name for c in contact.components] == ["N_A", "T_A"]
    N, T = (c.value for c in contact.components)
    assert N == pytest.approx(M * G * math.cos(0.3), rel=1e-12)
    assert T == pytest.approx(-M * G * math.sin(0.3), rel=1e-12)
    assert len(d.arrows) == 2 and d.couples == []
    assert d.label_texts == [f"N_A = {N:.3g}, T_A = {T:.3g}", f"W = {M * G:.3g}"]
    assert contact.cone.status == "inside"
    assert contact.cone.half_angle == pytest.approx(math.atan(F_S), rel=1e-15)
    # the arrow of the contact action points along the computed action: + m g R0.j
    arrow = next(a for a in d.arrows if a.name == "A")
    assert np.allclose(arrow.vector / np.linalg.norm(arrow.vector), [0, 1, 0], atol=1e-12)
    assert np.allclose(arrow.vector * d.scale, contact.force, rtol=1e-12)
    assert np.allclose(arrow.tail, contact.point)


def test_unknown_components_drawn_along_their_axes_before_the_solve():
    block, st = rough_incline()
    d = free_body_diagram(st, block.bodies[0], params={"m": M, "g": G, "alpha": 0.3})
    assert [a.name for a in d.arrows] == ["N_A", "T_A", "W"]
    assert d.label_texts == ["N_A", "T_A", f"W = {M * G:.3g}"]
    a = 0.3
    normal, tangent = np.array([math.sin(a), math.cos(a), 0]), np.array([math.cos(a),
                                                                         -math.sin(a), 0])
    for arrow, axis in zip(d.arrows[:2], (normal, tangent), strict=True):
        assert np.allclose(arrow.vector / np.linalg.norm(arrow.vector), axis, atol=1e-12)
    assert d.actions[0].cone.status is None


def test_limiting_equilibrium_on_the_edge_of_the_cone():
    block, st = rough_incline()
    alpha = sp.Symbol("alpha", positive=True)
    lim = st.limit(alpha, (0.1, 1.2), values={"m": M, "g": G})
    assert lim.value == pytest.approx(math.atan(F_S), rel=1e-9)      # tan(alpha) = f_s
    x = limiting_values(st, lim, values={"m": M, "g": G})
    (contact, _) = external_actions(st, block.bodies[0],
                                    params={"m": M, "g": G, "alpha": lim.value}, values=x)
    assert contact.cone.status == "edge"
    # the side of the cone: the friction up the slope, -Ri.i
    up = -np.array([math.cos(lim.value), -math.sin(lim.value), 0.0])
    assert np.allclose(contact.cone.side, up, atol=1e-7)
    # the action makes the angle arctan(f_s) with the normal
    n = contact.cone.normal
    angle = math.acos(contact.force @ n / np.linalg.norm(contact.force))
    assert angle == pytest.approx(math.atan(F_S), rel=1e-7)
    d = free_body_diagram(st, block.bodies[0], params={"m": M, "g": G, "alpha": lim.value},
                          values=x)
    (label, lines, edge), = d.cones
    assert label == "A" and len(lines) == 2 and edge is not None


@pytest.mark.parametrize(("excess", "status"), [
    (-2.0, "inside"), (-1.0, "edge"), (-0.5, "edge"), (0.0, "edge"), (0.5, "edge"),
    (1.0, "edge"), (2.0, "outside")])
def test_the_edge_decision_at_its_threshold(excess, status):
    """| |T| - f N | <= CONE_RTOL |R|: at the boundary and either side."""
    block, st = rough_incline()
    N = 10.0
    T0 = F_S * N
    R = math.hypot(N, T0)
    T = T0 + excess * CONE_RTOL * R
    if excess in (-1.0, 1.0):   # exactly at the boundary, up to the rounding of |R|
        T = T0 + excess * CONE_RTOL * math.hypot(N, T) * (1 - 1e-9)
    (contact, _) = external_actions(st, block.bodies[0], params={"m": M, "g": G, "alpha": 0.3},
                                    values={"N_A": N, "T_A": T})
    assert contact.cone.status == status


def test_dynamics_state_of_the_catalogue_model():
    """The frictionless model at a state: its prismatic joint's action from the fundamental
    principle, X_1 = m g cos(alpha) along the normal (the joint's u = Ri.j)."""
    block = models.block_on_incline()
    params = {"m": M, "g": G, "alpha": 0.3}
    d = free_body_diagram(block.system, block.bodies[0], q=[0.5], params=params)
    joint, weight = d.actions
    names = [c.name for c in joint.components]
    assert names == ["X_1", "Y_1", "L_1", "M_1", "N_1"]
    values = dict(zip(names, (c.value for c in joint.components), strict=True))
    assert values["X_1"] == pytest.approx(M * G * math.cos(0.3), rel=1e-12)
    assert all(abs(values[n]) < 1e-12 for n in names[1:])
    # independently: the connection action's resultant, substituted
    R0 = block.frames[0]
    A = block.system.connection_action(R0, block.bodies[0])
    x = block.coordinates[0]
    alpha = sp.Symbol("alpha", positive=True)
    rule = {x.diff(rm.t, 2): G * math.sin(0.3), sp.Symbol("m", positive=True): M,
            sp.Symbol("g", positive=True): G, alpha: 0.3}
    expected = np.array([float(c.xreplace(rule)) for c in A.resultant.components(R0)])
    arrow = next(a for a in d.arrows if a.name == "1")
    assert np.allclose(arrow.vector * d.scale, expected, rtol=1e-12)
    # in the plane: X_1 along u = Ri.j and the moment M_1 about v = R0.k (the joint's basis
    # for the axis w = Ri.i); Y_1 (along k), L_1 and N_1 (in the plane) are out of the view
    assert d.label_texts[0] == f"X_1 = {M * G * math.cos(0.3):.3g}, M_1 = 0"
    assert len(d.arrows) == 2 and d.couples == []
