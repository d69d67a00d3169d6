"""The holonomy test of a velocity constraint (the curl of its coefficients, book ch. 9.3)
is the library's one exact zero decision (``vanishes``): a non-holonomic condition is refused
from sample values without ``sympy.simplify`` (issue 20), a holonomic one still integrated."""

import pytest
import sympy as sp

import rigidmech.kinematics.constraints as constraints
from rigidmech import coordinates, t
from rigidmech.kinematics.constraints import VelocityConstraint


@pytest.fixture
def no_simplify(monkeypatch):
    def refuse(*args, **kwargs):
        raise AssertionError("simplify called")

    monkeypatch.setattr(constraints.sp, "simplify", refuse)


def test_knife_edge_condition_is_not_holonomic_without_simplify(no_simplify):
    x, y, theta = coordinates("x y theta")
    c = VelocityConstraint(-sp.sin(theta) * x.diff(t) + sp.cos(theta) * y.diff(t))
    assert c.holonomic is False and c.position_form is None


def test_holonomic_conditions_are_still_integrated():
    x, theta = coordinates("x theta")
    r = sp.Symbol("r", positive=True)
    c = VelocityConstraint(x.diff(t) + r * theta.diff(t))
    assert c.holonomic and sp.simplify(c.position_form - (x + r * theta)) == 0
    # the curl vanishes only through sin^2 + cos^2 = 1
    k = VelocityConstraint((sp.sin(theta) ** 2 + sp.cos(theta) ** 2) * x.diff(t)
                           + sp.cos(x) * theta.diff(t) - sp.cos(x) * theta.diff(t))
    assert k.holonomic
