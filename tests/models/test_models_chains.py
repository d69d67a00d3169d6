"""The chains of rigidmech.models against their closed forms (Lagrange's equations written by
hand from T and V, book ch. 22.2.1, 25.4.3)."""

import pytest
import sympy as sp

from rigidmech import models
from rigidmech.errors import ArgumentError
from rigidmech.vectors import t


def _zero(expr):
    return sp.simplify(expr) == 0


def _rates(coords):
    return [q.diff(t) for q in coords]


def test_compound_pendulum_is_the_rod_on_a_pivot_of_ch22():
    # T = (m L^2 / 3) theta'^2 / 2, V = -m g (L / 2) cos(theta) with i pointing down
    model = models.compound_pendulum()
    (theta,), (m, L, g) = model.coordinates, model.constants
    eqs = model.system.equations_of_motion()
    assert eqs.mass_matrix == sp.Matrix([[m * L**2 / 3]])
    assert _zero(eqs.forcing[0] + m * g * L / 2 * sp.sin(theta))
    assert [b.name for b in model.bodies] == ["bar"]


def test_double_pendulum_of_two_rods_matches_lagrange_by_hand():
    # T = m L^2 (4/3 th1'^2 + 1/3 th2'^2 + th1' th2' cos(th1 - th2)) / 2,
    # V = -m g L (3/2 cos th1 + 1/2 cos th2)
    model = models.double_pendulum()
    (th1, th2), (m, L, g) = model.coordinates, model.constants
    w1, w2 = _rates(model.coordinates)
    eqs = model.system.equations_of_motion()
    c, s = sp.cos(th1 - th2), sp.sin(th1 - th2)
    M = m * L**2 * sp.Matrix([[sp.Rational(4, 3), c / 2], [c / 2, sp.Rational(1, 3)]])
    f = sp.Matrix([-sp.Rational(3, 2) * m * g * L * sp.sin(th1) - m * L**2 / 2 * s * w2**2,
                   -m * g * L / 2 * sp.sin(th2) + m * L**2 / 2 * s * w1**2])
    assert sp.simplify(eqs.mass_matrix - M) == sp.zeros(2, 2)
    assert sp.simplify(eqs.forcing - f) == sp.zeros(2, 1)


def test_point_mass_double_pendulum_matches_lagrange_by_hand():
    # T = m l^2 (2 q1'^2 + q2'^2 + 2 q1' q2' cos(q1 - q2)) / 2, V = -m g l (2 cos q1 + cos q2)
    model = models.point_mass_double_pendulum()
    (q1, q2), (m, l, g) = model.coordinates, model.constants
    u1, u2 = _rates(model.coordinates)
    eqs = model.system.equations_of_motion()
    c, s = sp.cos(q1 - q2), sp.sin(q1 - q2)
    M = m * l**2 * sp.Matrix([[2, c], [c, 1]])
    f = sp.Matrix([-2 * m * g * l * sp.sin(q1) - m * l**2 * s * u2**2,
                   -m * g * l * sp.sin(q2) + m * l**2 * s * u1**2])
    assert sp.simplify(eqs.mass_matrix - M) == sp.zeros(2, 2)
    assert sp.simplify(eqs.forcing - f) == sp.zeros(2, 1)


def test_two_link_pendulum_in_relative_angles_matches_lagrange_by_hand():
    # rods m_i, l_i, relative angles, gravity -g j: the classical two-link mass matrix and,
    # at rest, f = -dV/dq with V = m1 g l1/2 sin q1 + m2 g (l1 sin q1 + l2/2 sin(q1 + q2))
    model = models.n_link_pendulum(2)
    q1, q2 = model.coordinates
    g, m1, l1, m2, l2 = model.constants
    assert [c.name for c in model.constants] == ["g", "m1", "l1", "m2", "l2"]
    eqs = model.system.equations_of_motion()
    c2 = sp.cos(q2)
    M12 = m2 * (l2**2 / 3 + l1 * l2 * c2 / 2)
    M = sp.Matrix([[m1 * l1**2 / 3 + m2 * (l1**2 + l2**2 / 3 + l1 * l2 * c2), M12],
                   [M12, m2 * l2**2 / 3]])
    assert sp.simplify(eqs.mass_matrix - M) == sp.zeros(2, 2)
    at_rest = eqs.forcing.subs({d: 0 for d in _rates(model.coordinates)})
    f = sp.Matrix([-(m1 / 2 + m2) * g * l1 * sp.cos(q1) - m2 * g * l2 / 2 * sp.cos(q1 + q2),
                   -m2 * g * l2 / 2 * sp.cos(q1 + q2)])
    assert sp.simplify(at_rest - f) == sp.zeros(2, 1)


def test_one_link_pendulum_is_a_rod_on_a_pivot_with_gravity_across():
    model = models.n_link_pendulum(1)
    (q1,), (g, m1, l1) = model.coordinates, model.constants
    eqs = model.system.equations_of_motion()
    assert eqs.mass_matrix == sp.Matrix([[m1 * l1**2 / 3]])
    assert _zero(eqs.forcing[0] + m1 * g * l1 / 2 * sp.cos(q1))


def test_n_link_pendulum_names_its_parts_for_any_n():
    model = models.n_link_pendulum(4)
    assert [f.name for f in model.frames] == ["R0", "R1", "R2", "R3", "R4"]
    assert [b.name for b in model.bodies] == ["b1", "b2", "b3", "b4"]
    assert [p.name for p in model.points][1:] == ["P1", "P2", "P3", "P4"]
    assert model.system.coordinates == model.coordinates


@pytest.mark.parametrize("n", [0, -1, True, 2.0, "3"])
def test_n_link_pendulum_rejects_a_count_that_is_not_a_positive_integer(n):
    with pytest.raises(ArgumentError, match=r"`n` must be an integer >= 1"):
        models.n_link_pendulum(n)


def test_model_lookup_by_an_unknown_name_lists_the_known_ones():
    model = models.double_pendulum()
    assert model.point("A").name == "A" and model.body("bar2").name == "bar2"
    with pytest.raises(ArgumentError, match=r"one of the model's frames \('R0', 'R1', 'R2'\)"):
        model.frame("R3")


def test_cart_pendulum_matches_lagrange_by_hand():
    # P = (x + L sin th, -L cos th): T = M x'^2 / 2 + m (x'^2 + 2 L cos th x' th' + L^2 th'^2) / 2,
    # V = -m g L cos th
    model = models.cart_pendulum()
    (_, th), (M, m, L, g) = model.coordinates, model.constants
    eqs = model.system.equations_of_motion()
    c, s = sp.cos(th), sp.sin(th)
    assert sp.simplify(eqs.mass_matrix - sp.Matrix([[M + m, m * L * c], [m * L * c, m * L**2]])) \
        == sp.zeros(2, 2)
    f = sp.Matrix([m * L * s * th.diff(t) ** 2, -m * g * L * s])
    assert sp.simplify(eqs.forcing - f) == sp.zeros(2, 1)
