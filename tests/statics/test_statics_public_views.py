"""Public read-only views of a Statics (its connections and loads, as given) and the linear
program of the limiting equilibrium (statics.limits.largest_margin), read by the free-body
diagrams."""

import numpy as np
import pytest

import rigidmech as rm
from rigidmech.actions import ContactLaws, Coulomb, Force
from rigidmech.statics.limits import largest_margin


def _block():
    R0 = rm.Frame("R0")
    block = rm.Body("block", frame=R0)
    st = rm.statics.Statics(R0)
    law = ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i, friction=Coulomb(0.3))
    st.connect(R0, block, law, label="I")
    weight = Force(on=block, vector=-10 * R0.j, at=R0.origin)
    st.act(weight)
    extra = rm.slider(2 * R0.i, R0.origin)
    st.load(block, extra)
    return R0, block, st, law, weight, extra


def test_connections_as_given():
    R0, block, st, law, _, _ = _block()
    (c,) = st.connections
    assert isinstance(st.connections, tuple)
    assert (c.first, c.second, c.connection, c.label) == (R0, block, law, "I")
    torsor, unknowns = law.action_torsor("I")
    assert c.torsor == torsor and c.unknowns == tuple(unknowns)
    assert c == tuple(st._connections[0])       # the same record the equations are made of


def test_loads_as_given():
    _, block, st, _, weight, extra = _block()
    assert st.loads == ((None, weight), (block, extra))
    st.load(block, extra)          # a new view each time: the earlier one is unchanged
    assert len(st.loads) == 3


def test_largest_margin_of_a_small_program():
    # max t with x1 + x2 = 2, x1 >= t, x2 >= t: x = (1, 1); t in units of max|b| = 2
    t, x = largest_margin(np.array([[1.0, 1.0]]), np.array([2.0]), np.eye(2))
    assert t == pytest.approx(0.5, abs=1e-12)
    np.testing.assert_allclose(x, [1.0, 1.0], atol=1e-9)
    # equations without a solution: the cap, no x
    t, x = largest_margin(np.array([[1.0], [1.0]]), np.array([1.0, 2.0]), np.eye(1))
    assert x is None and t < 0
