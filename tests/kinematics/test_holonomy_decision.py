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


def test_knife_edge_decides_its_zeros_by_the_same_rule(monkeypatch):
    """KnifeEdge's checks (the blade's point stays in the plane) use ``vanishes``: an
    identity in the angles is zero without ``simplify``."""
    import rigidmech.actions.knife_edge as knife_edge
    from rigidmech import Frame
    from rigidmech.actions import KnifeEdge

    monkeypatch.setattr(knife_edge.sp, "simplify", _refuse_trigonometric)
    x, y, th = coordinates("x y theta")
    a = sp.Symbol("a", positive=True)
    lift = sp.sin(2 * th) - 2 * sp.sin(th) * sp.cos(th)   # zero: the point stays in the plane
    R0 = Frame("R0")
    G = R0.point("G", x, y, lift)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    knife = KnifeEdge(R1, R0, at=G.moved("P", -a * R1.i), direction=R1.i, normal=R0.k)
    assert knife.holonomic is False


_SIMPLIFY = sp.simplify


def _refuse_trigonometric(expr, *args, **kwargs):
    """simplify, refused for an expression with sines or cosines (a decision to take by
    sampling); allowed on constants (the blade's direction normalised)."""
    if sp.sympify(expr).has(sp.sin, sp.cos):
        raise AssertionError(f"simplify called on {expr}")
    return _SIMPLIFY(expr, *args, **kwargs)


def test_perpendicular_check_decides_by_the_same_rule(monkeypatch):
    """The check that a blade lies in the plane (direction . normal = 0) uses ``vanishes``."""
    import rigidmech.actions.actions as actions
    from rigidmech import Frame
    from rigidmech.actions import KnifeEdge

    monkeypatch.setattr(actions.sp, "simplify", _refuse_trigonometric)
    x, y, th = coordinates("x y theta")
    b = sp.Symbol("b", positive=True)
    R0 = Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    tilt = sp.sin(2 * b) - 2 * sp.sin(b) * sp.cos(b)      # zero: the blade is in the plane
    knife = KnifeEdge(R1, R0, at=G, direction=R1.i + tilt * R1.k, normal=R0.k)
    assert knife.holonomic is False
