"""Butcher tableaux: identities and Butcher's rooted-tree order conditions (HNW I, II.2)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from rigidmech._core.errors import ArgumentError
from rigidmech.ode import tableaux as T

# Exact rational tableaux give residuals at rounding level; DOP853's 30-digit decimal
# coefficients, combined over up to 8 nested products, keep them below ~1e-14.
TOL = 5e-14


def test_number_of_rooted_trees_is_oeis_a000081():
    assert [len(T.rooted_trees(p)) for p in range(1, 9)] == [1, 1, 2, 4, 9, 20, 48, 115]
    with pytest.raises(ArgumentError, match=r"`order` must be an int >= 1; got 0"):
        T.rooted_trees(0)


def test_tree_densities_sum_rule():
    # sum over trees of order p of alpha(t)... checked on a classical identity:
    # the number of trees with gamma = p! is 1 (the tall tree) for every p.
    for p in range(1, 8):
        tall = sum(1 for t in T.rooted_trees(p) if T.tree_density(t) == np.prod(range(1, p + 1)))
        assert tall == 1
    # the bushy tree [tau, ..., tau] has gamma = p
    assert T.tree_density(((),) * 4) == 5


@pytest.mark.parametrize("tab", list(T.ALL.values()), ids=list(T.ALL))
def test_claimed_order_holds_and_next_order_fails(tab):
    assert tab.row_sum_defect() < 1e-15
    assert abs(tab.b.sum() - 1.0) < 1e-15
    assert np.max(np.abs(tab.order_residuals(tab.order))) < TOL
    # the order is exactly the claimed one: some condition of order p + 1 is violated
    assert np.max(np.abs(tab.order_residuals(tab.order + 1))) > 1e-6


@pytest.mark.parametrize("tab", [T.DOPRI5, T.DOP853, T.BS32], ids=["dopri5", "dop853", "bs32"])
def test_embedded_weights_have_their_order(tab):
    res = tab.order_residuals(tab.order_embedded, tab.b_embedded)
    assert np.max(np.abs(res)) < TOL
    assert np.max(np.abs(tab.order_residuals(tab.order_embedded + 1, tab.b_embedded))) > 1e-6


def test_dop853_third_order_estimator_and_dense_stages():
    b3 = T.DOP853.b - T.DOP853_E3[:12]
    assert np.max(np.abs(T.DOP853.order_residuals(3, b3))) < TOL
    # the extra stages of the dense output are consistent (row sums = nodes)
    assert_allclose(T.DOP853_A_EXTRA.sum(axis=1), T.DOP853_C_EXTRA, atol=1e-15)


def test_dopri5_dense_output_weights_reproduce_b_at_x_equal_1():
    # Shampine's interpolant: y(1) = y1, so the coefficients summed over powers give b
    assert_allclose(T.DOPRI5_P.sum(axis=1)[:7], T.DOPRI5.b, atol=1e-15)


def test_tableau_is_immutable_value():
    with pytest.raises(AttributeError, match=r"immutable"):
        T.RK4.order = 5
    with pytest.raises(ValueError, match=r"read-only"):
        T.RK4.A[1, 0] = 2.0
    copy = T.ButcherTableau("rk4", T.RK4.A, T.RK4.b, T.RK4.c, order=4)
    assert copy == T.RK4 and hash(copy) == hash(T.RK4)
    assert copy != T.RK38
    assert repr(T.DOP853) == "ButcherTableau('dop853', stages=12, order=8)"


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (([[0, 1], [0, 0]], [0.5, 0.5], [0, 1], 2), r"`A` must be strictly lower triangular"),
        (([[0]], [0.5, 0.5], [0, 1], 2), r"`A`, `b`, `c` must have shapes"),
        (([[0]], [1.0], [0.0], 0), r"`order` must be an int >= 1; got 0"),
    ],
)
def test_tableau_validation(args, match):
    with pytest.raises(ArgumentError, match=match):
        T.ButcherTableau("bad", *args[:3], order=args[3])


@given(st.floats(0.05, 1.0))
def test_two_stage_family_has_order_two_for_every_node(alpha):
    # the one-parameter family of 2-stage order-2 methods (HNW I, II.1): b2 = 1/(2 alpha)
    tab = T.ButcherTableau("fam", [[0, 0], [alpha, 0]], [1 - 1 / (2 * alpha), 1 / (2 * alpha)],
                           [0, alpha], order=2)
    assert np.max(np.abs(tab.order_residuals(2))) < 1e-12


def test_verify_names_the_violated_identity():
    for tab in T.ALL.values():
        tab.verify(tol=TOL)
    with pytest.raises(ArgumentError, match=r"`c` of tableau 'x' must equal the row sums"):
        T.ButcherTableau("x", [[0, 0], [1, 0]], [0.5, 0.5], [0, 0.5], order=2).verify()
    with pytest.raises(ArgumentError, match=r"`order` = 3 of tableau 'heun3' is not reached: "
                       r"the condition of tree \(\(\(\)\)\) \(order 3\) has residual -0.167"):
        T.ButcherTableau("heun3", [[0, 0], [1, 0]], [0.5, 0.5], [0, 1], order=3).verify()
    with pytest.raises(ArgumentError, match=r"`order_embedded` = 5 of tableau 'dp'"):
        T.ButcherTableau("dp", T.DOPRI5.A, T.DOPRI5.b, T.DOPRI5.c, order=5,
                         b_embedded=T.DOPRI5.b_embedded, order_embedded=5).verify()
