"""The rolling models of rigidmech.models: the no-slip conditions and the accelerations
against closed forms (book, ch. 10.1, 23.4)."""

import pytest
import sympy as sp

from rigidmech import models
from rigidmech.errors import ArgumentError


def _conditions(system):
    return [condition for _, condition, _ in system.closure_conditions()]


@pytest.mark.parametrize("contact", ["between", "given"])
def test_rolling_disc_no_slip_is_v_G_plus_omega_cross_GI_zero(contact):
    # v(I in disc) = v_G + omega ^ (-r B.j) = (x', y', 0) + r phi' B.i with B.i = A.i =
    # (cos psi, sin psi, 0): the contact point moves along the heading at -r phi'
    model = models.rolling_disc(contact)
    x, y, psi, th, phi = model.coordinates
    m, g, r = model.constants
    expected = [x.diff() + r * sp.cos(psi) * phi.diff(), y.diff() + r * sp.sin(psi) * phi.diff()]
    got = _conditions(model.system)
    assert len(got) == 2
    assert all(sp.simplify(a - b) == 0 for a, b in zip(got, expected, strict=True))
    assert model.system.mobility().mobility == 3


def test_rolling_disc_given_or_found_contact_gives_the_same_equations():
    # the contact found from the rim and the plane is the lowest point I0 = (x, y, 0) with
    # normal k: the two ways give the same mass matrix, forcing and constraint rows
    found = models.rolling_disc("between").system.equations_of_motion()
    given = models.rolling_disc("given").system.equations_of_motion()
    assert sp.simplify(found.mass_matrix - given.mass_matrix) == sp.zeros(5, 5)
    assert sp.simplify(found.forcing - given.forcing) == sp.zeros(5, 1)


def test_rolling_disc_mass_matrix_of_the_translation_is_m():
    model = models.rolling_disc()
    m = model.constant("m")
    M = model.system.equations_of_motion().mass_matrix
    assert M[0, 0] == m and M[1, 1] == m and M[0, 1] == 0


def test_rolling_disc_rejects_an_unknown_contact():
    with pytest.raises(ArgumentError, match=r"`contact` must be one of \('between', 'given'\)"):
        models.rolling_disc("found")


@pytest.mark.parametrize(("inertia", "ratio"), [("disk", sp.Rational(2, 3)),
                                                ("ring", sp.Rational(1, 2))])
def test_wheel_rolls_down_the_incline_at_g_sin_alpha_over_one_plus_k2_over_r2(inertia, ratio):
    # x'' = g sin(alpha) / (1 + J / (m r^2)), J / (m r^2) = 1/2 (disk), 1 (ring) (ch. 23.4)
    alpha = sp.Symbol("alpha", positive=True)
    model = models.wheel_on_incline(alpha, inertia)
    m, g, r = model.constants
    acc = model.system.equations_of_motion().accelerations()
    assert sp.simplify(acc[0] - ratio * g * sp.sin(alpha)) == 0


def test_wheel_rejects_an_unknown_inertia():
    with pytest.raises(ArgumentError, match=r"`inertia` must be one of \('disk', 'ring'\)"):
        models.wheel_on_incline(0.1, "rod")


def test_ball_on_turntable_handles_and_the_table_driven_without_a_coordinate():
    model = models.ball_on_turntable()
    assert [q.func.__name__ for q in model.coordinates] == ["x", "y", "e0", "e1", "e2", "e3"]
    assert [c.name for c in model.constants] == ["m", "r", "g", "Omega"]
    assert [b.name for b in model.bodies] == ["table", "ball"]
    assert [f.name for f in model.frames] == ["R0", "Rt", "R"]
    # the table turns by Omega t about R0.k and adds no parameter of situation
    assert model.system.coordinates == model.coordinates
    assert len(model.system.constraints()) == 2


def test_ball_on_turntable_no_slip_is_v_G_equal_to_the_table_velocity_omega_k_cross_rho():
    # at e = (1, 0, 0, 0), e' = 0 (the ball not turning), t = 0, the conditions read
    # v_G - Omega k ^ (x i + y j) = 0: x' + Omega y = 0 and y' - Omega x = 0 (ch. 10.1, 17.1)
    # (the conditions are written in the table's axes, turned by Omega t)
    model = models.ball_on_turntable()
    x, y, e0, e1, e2, e3 = model.coordinates
    W = model.constant("Omega")
    t = sp.Symbol("t")
    at_rest = {**{e.diff(): 0 for e in (e0, e1, e2, e3)}, e0: 1, e1: 0, e2: 0, e3: 0}
    at_t0 = {sp.sin(W * t): 0, sp.cos(W * t): 1}
    got = [sp.simplify(c.subs(at_rest).subs(at_t0)) for c in _conditions(model.system)]
    expected = [x.diff() + W * y, y.diff() - W * x]
    assert all(sp.simplify(a - b) == 0 for a, b in zip(got, expected, strict=True))


def test_ball_on_turntable_takes_a_given_rate():
    model = models.ball_on_turntable(Omega=sp.Rational(3, 2))
    assert model.constants[-1] == sp.Rational(3, 2)
    symbols = set().union(*(c.free_symbols for c in _conditions(model.system)))
    assert "Omega" not in {s.name for s in symbols}
    assert sp.Rational(3, 2) * sp.Symbol("t") in {a for c in _conditions(model.system)
                                                  for a in sp.preorder_traversal(c)}
