"""The sleighs of rigidmech.models: the knife edge's condition and the mass matrix against
closed forms (book, ch. 13.1, 25.3.3)."""

import sympy as sp

from rigidmech import models


def _condition(system):
    (row,) = [condition for _, condition, _ in system.closure_conditions()]
    return row


def _equal_up_to_sign(a, b):
    return sp.simplify(a - b) == 0 or sp.simplify(a + b) == 0


def test_sleigh_blade_moves_along_the_sleigh_axis_only():
    # v(P) . j1 = (x', y') . (-sin th, cos th) - a th' = 0 for P = G - a i1
    model = models.sleigh()
    x, y, th = model.coordinates
    m, r, g, a = model.constants
    lateral = -x.diff() * sp.sin(th) + y.diff() * sp.cos(th) - a * th.diff()
    assert _equal_up_to_sign(_condition(model.system), lateral)
    # a disc of mass m, radius r: M = diag(m, m, m r^2 / 2)
    M = model.system.equations_of_motion().mass_matrix
    assert sp.simplify(M - sp.diag(m, m, m * r**2 / 2)) == sp.zeros(3, 3)
    assert model.connections[0] is not None and model.point("P").name == "P"


def test_sleigh_with_a_given_blade_distance_keeps_it():
    model = models.sleigh(sp.Rational(1, 2), gravity=False)
    assert model.constants[-1] == sp.Rational(1, 2)
    x, y, th = model.coordinates
    lateral = -x.diff() * sp.sin(th) + y.diff() * sp.cos(th) - th.diff() / 2
    assert _equal_up_to_sign(_condition(model.system), lateral)


def test_sleigh_on_incline_feels_the_slope_along_y_only():
    # gravity -g k0 on the plane tilted by beta about i0: the component along Ri.j is
    # -g sin(beta), none along Ri.i; an offset b of the blade does not enter the condition
    beta = sp.Symbol("beta")
    model = models.sleigh_on_incline(beta)
    x, y, th = model.coordinates
    m, r, g, a, b = model.constants
    eqs = model.system.equations_of_motion()
    rest = eqs.forcing.subs({q.diff(): 0 for q in model.coordinates})
    assert sp.simplify(rest - sp.Matrix([0, -m * g * sp.sin(beta), 0])) == sp.zeros(3, 1)
    lateral = -x.diff() * sp.sin(th) + y.diff() * sp.cos(th) - a * th.diff()
    assert _equal_up_to_sign(_condition(model.system), lateral)


def test_sleigh_on_turntable_condition_is_relative_to_the_table():
    # the blade's velocity relative to the table, across the sleigh: the table's rate phi'
    # does not enter
    model = models.sleigh_on_turntable()
    phi, x, y, th = model.coordinates
    m, r, M, R, a = model.constants
    lateral = -x.diff() * sp.sin(th) + y.diff() * sp.cos(th) - a * th.diff()
    assert _equal_up_to_sign(_condition(model.system), lateral)
    assert [b.name for b in model.bodies] == ["table", "sleigh"]
