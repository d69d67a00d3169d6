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
