"""The closed loops of rigidmech.models: their closure conditions against the geometry of
the loop written by hand (book, ch. 13.2, 25.3.3)."""

import pytest
import sympy as sp

from rigidmech import models
from rigidmech.errors import ArgumentError


def _same_up_to_sign(got, expected):
    """Each closure condition equals one expected expression, up to its sign."""
    assert len(got) == len(expected)
    for e in expected:
        assert any(sp.simplify(c - e) == 0 or sp.simplify(c + e) == 0 for c in got), e


def _conditions(system):
    return [phi for _, _, phi in system.closure_conditions()]


def test_four_bar_closes_where_the_coupler_meets_the_rocker():
    l0, l1, l2, l3 = models.FOUR_BAR_LENGTHS
    model = models.four_bar()
    q1, q2, q3 = model.coordinates
    # C = l1 e(q1) + l2 e(q1 + q2) on the coupler, (l0, 0) + l3 e(q3) on the rocker
    _same_up_to_sign(_conditions(model.system), [
        l1 * sp.cos(q1) + l2 * sp.cos(q1 + q2) - l0 - l3 * sp.cos(q3),
        l1 * sp.sin(q1) + l2 * sp.sin(q1 + q2) - l3 * sp.sin(q3)])
    assert model.system.mobility(plane=model.frame("R0").k).mobility == 1
    assert [p.name for p in model.points] == ["B", "C", "C3", "D"]


def test_four_bar_without_gravity_has_no_forcing_at_rest():
    model = models.four_bar(gravity=False)
    eqs = model.system.equations_of_motion()
    rest = {q.diff(): 0 for q in model.coordinates}
    assert eqs.forcing.subs(rest) == sp.zeros(3, 1)


def test_a_chain_of_one_four_bar_is_the_four_bar():
    # same symbols, same frames, same bars (only the bodies' names differ): same equations
    one, bar4 = models.four_bar_chain(1), models.four_bar()
    assert one.coordinates == bar4.coordinates and one.constants == bar4.constants
    a, b = one.system.equations_of_motion(), bar4.system.equations_of_motion()
    assert a.mass_matrix == b.mass_matrix and a.forcing == b.forcing
    assert _conditions(one.system) == _conditions(bar4.system)


@pytest.mark.parametrize("n", [2, 3])
def test_a_chain_of_n_four_bars_has_2n_plus_1_parameters_and_mobility_one(n):
    model = models.four_bar_chain(n)
    assert len(model.coordinates) == 2 * n + 1
    assert len(model.system.closure_conditions()) == 2 * n
    assert model.system.mobility(plane=model.frame("R0").k).mobility == 1


def test_chain_loops_after_the_first_use_the_longer_coupler():
    model = models.four_bar_chain(2)
    q = model.coordinates
    L0, L1, L2, L3 = models.FOUR_BAR_LENGTHS
    lc = models.CHAIN_COUPLER
    # second loop: from the tip E1 = (L0, 0) + L3 e(q3), the coupler at q3 + q4, to
    # (2 L0, 0) + L3 e(q5)
    second = [L0 + L3 * sp.cos(q[2]) + lc * sp.cos(q[2] + q[3]) - 2 * L0 - L3 * sp.cos(q[4]),
              L3 * sp.sin(q[2]) + lc * sp.sin(q[2] + q[3]) - L3 * sp.sin(q[4])]
    _same_up_to_sign(_conditions(model.system)[2:], second)


@pytest.mark.parametrize("n", [0, 1.0, None])
def test_four_bar_chain_rejects_a_bad_count(n):
    with pytest.raises(ArgumentError, match=r"`n` must be an integer >= 1"):
        models.four_bar_chain(n)


def test_four_bar_passes_its_stabilisation_to_the_system():
    assert models.four_bar(stabilization=(0.0, 2.0)).system.constraints().stabilization \
        == (0.0, 2.0)
    assert models.four_bar_chain(1, stabilization=(1.0, 3.0)).system.constraints() \
        .stabilization == (1.0, 3.0)


def test_slider_crank_closes_where_the_rod_meets_the_slider():
    r, ell = 0.5, 1.5
    model = models.slider_crank(r, ell)
    q1, q2, x = model.coordinates
    _same_up_to_sign(_conditions(model.system), [
        r * sp.cos(q1) + ell * sp.cos(q1 + q2) - x, r * sp.sin(q1) + ell * sp.sin(q1 + q2)])
    assert [b.name for b in model.bodies] == ["crank", "rod", "slider"]
