"""One relative rule per decision (issue 19, "the same rule wherever the same decision is
made"): a state on the constraints is judged against the magnitude of the terms of each
condition, and the rank of a Jacobian against its largest singular value -- so that a model
in millimetres, or a mechanism of size 1e-10, gets the verdicts of the same model in metres.
The rules: rigidmech._core.rules (ON_CONSTRAINTS = RANK_RTOL = 1e-9)."""

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import models
from rigidmech._core.errors import ArgumentError
from rigidmech._core.rules import (
    ON_CONSTRAINTS,
    RANK_RTOL,
    numeric_rank,
    on_constraints,
    rank_of,
    rates_for_scale,
)
from rigidmech.dynamics import Constraints
from rigidmech.dynamics.assembly import assemble

TAU = ON_CONSTRAINTS


# -- the rules themselves, at the boundary and either side ----------------------------------
@pytest.mark.parametrize("scale", [1e-20, 1.0, 1e6])
@pytest.mark.parametrize("factor, holds", [(1.0, True), (1 - 1e-12, True), (1 + 1e-12, False),
                                           (1 - 1e-6, True), (1 + 1e-6, False)])
def test_on_constraints_at_the_boundary(scale, factor, holds):
    """|r| <= 1e-9 * (magnitude of the terms), the boundary included, at every scale."""
    r = TAU * scale * factor
    assert bool(on_constraints(np.array([r]), np.array([scale]))) is holds
    assert bool(on_constraints(np.array([-r]), np.array([scale]))) is holds


def test_a_residual_not_finite_is_off():
    assert not on_constraints(np.array([np.nan]), np.array([1.0]))[0]
    assert not on_constraints(np.array([np.inf]), np.array([np.inf]))[0]


def test_a_condition_without_terms_holds_only_exactly():
    assert on_constraints(np.array([0.0, 1e-300]), np.array([0.0, 0.0])).tolist() == [True,
                                                                                      False]


@pytest.mark.parametrize("scale", [1e-12, 1.0, 1e9])
@pytest.mark.parametrize("factor, rank", [(1.0, 1), (1 - 1e-12, 1), (1 + 1e-12, 2),
                                          (1 - 1e-6, 1), (1 + 1e-6, 2)])
def test_rank_at_the_boundary(scale, factor, rank):
    """Singular values above 1e-9 of the largest count; the boundary does not."""
    assert rank_of([scale, scale * RANK_RTOL * factor]) == rank


@pytest.mark.parametrize("factor, rank", [(1 - 1e-3, 1), (1 + 1e-3, 2)])
@pytest.mark.parametrize("row, column", [(1.0, 1.0), (1e-10, 1.0), (1.0, 1e3), (1e3, 1e-10)])
def test_rank_of_a_near_singular_matrix_in_any_units(factor, rank, row, column):
    """[[1, 1], [1, 1 - d]] has sigma_min / sigma_max = d / 4 to O(d^2): d = 4e-9 (1 +- 1e-3)
    straddles the threshold (the SVD resolves 1e-7 of it, not 1e-12: see rank_of). Its
    second row in other units (times `row`), its second column too (times `column`): the
    same rank (the rule scales rows and columns to a largest entry of 1 first)."""
    d = 4 * RANK_RTOL * factor
    A = np.array([[1.0, 1.0], [1.0, 1.0 - d]])
    A = np.diag([1.0, row]) @ A @ np.diag([1.0, column])
    assert numeric_rank(A) == rank


def test_rates_for_scale_are_the_largest_rate():
    assert rates_for_scale(np.array([1.0, -3.0])).tolist() == [3.0, 3.0]


# -- a circle of radius 1e-10 (it was accepted half off its constraint) ---------------------
def _circle():
    x, y = rm.coordinates("x y")
    r = sp.Symbol("r", positive=True)
    phi = x**2 + y**2 - r**2
    c = Constraints((x, y), [("circle", phi.diff(rm.t), phi)])
    return rm.EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
                                forcing=sp.Matrix([0, 0]), constraints=c), c


@pytest.mark.parametrize("r", [1e-10, 1.0, 1e3])
def test_assemble_a_circle_of_any_radius(r):
    """(0.6 r, 0.5 r) is off the circle x^2 + y^2 = r^2 by 39 % of r^2: y is moved to 0.8 r
    whatever r (with r = 1e-10 the residual 3.9e-21 passed the absolute 1e-9 and y stayed)."""
    _, c = _circle()
    q, _ = assemble(c, {"x": 0.6 * r, "y": 0.5 * r}, independent=["x"], params={"r": r})
    assert q["y"] == pytest.approx(0.8 * r, rel=1e-12)


@pytest.mark.parametrize("r", [1e-10, 1.0, 1e3])
def test_simulate_moves_a_small_circle_onto_its_constraint(r):
    eqs, _ = _circle()
    sim = eqs.simulate(t=(0, 1e-3), q0=[0.6 * r, 0.5 * r], n_output=2, independent=["x"],
                       r=r)
    assert sim.q[1, 0] == pytest.approx(0.8 * r, rel=1e-12)
    assert any("off the closure conditions" in n for n in sim.notes)


@pytest.mark.parametrize("r", [1e-10, 1.0, 1e3])
def test_simulate_keeps_a_state_on_a_circle_of_any_radius(r):
    eqs, _ = _circle()
    q0 = [0.6 * r, 0.8 * r]
    sim = eqs.simulate(t=(0, 1e-3), q0=q0, u0=[-0.8 * r, 0.6 * r], n_output=2, r=r)
    assert sim.q[:, 0].tolist() == q0 and sim.notes == ()


# -- the same four-bar in metres and in millimetres gets the same verdicts ------------------
LENGTHS = (2.0, 1.0, 2.0, 1.5)


def _four_bar(unit):
    return models.four_bar(tuple(unit * x for x in LENGTHS)).system


@pytest.fixture(scope="module")
def on_loop():
    """A state on the loop (angles: the same in both units) and a rate along it."""
    s = _four_bar(1.0)
    q, u = s.assemble({"q1": 1.0, "q2": 0.5, "q3": 1.5}, independent=["q1"],
                      rates={"q1": 1.0})
    return [q[k] for k in ("q1", "q2", "q3")], [u[k] for k in ("q1", "q2", "q3")]


@pytest.mark.parametrize("delta, on", [(3e-10, True), (1e-7, False)])
def test_multipliers_same_verdict_in_m_and_mm(on_loop, delta, on):
    """q3 moved by delta off the loop: the residuals are ~1.5 delta in m and 1500 delta in
    mm, the terms ~5 m and 5000 mm; a delta of 3e-10 (4.5e-10 m, under the absolute 1e-9;
    4.5e-7 mm, over it) was accepted in m and refused in mm."""
    q, u = on_loop
    q = [q[0], q[1], q[2] + delta]
    verdicts = []
    for unit in (1.0, 1000.0):
        s = _four_bar(unit)
        try:
            s.multipliers(q, u, m=1.0, g=9.81 * unit)
            verdicts.append(True)
        except ArgumentError as exc:
            assert "not on the constraints" in str(exc)
            verdicts.append(False)
    assert verdicts == [on, on]


@pytest.mark.parametrize("delta", [3e-10, 1e-7])
def test_simulate_same_verdict_in_m_and_mm(on_loop, delta):
    q, u = on_loop
    q = [q[0], q[1], q[2] + delta]
    moved = []
    for unit in (1.0, 1000.0):
        eqs = _four_bar(unit).equations_of_motion()
        sim = eqs.simulate(t=(0, 1e-3), q0=q, u0=u, n_output=2, m=1.0, g=9.81 * unit)
        moved.append(any("off the closure conditions" in n for n in sim.notes))
    assert moved == [delta > 1e-9] * 2


# -- a four-bar of size 1e-10 is a four-bar ----------------------------------------------------
@pytest.mark.parametrize("unit", [1e-10, 1.0, 1e3])
def test_a_four_bar_of_any_size_keeps_its_closure(unit):
    """Its closure conditions (size 1e-10 here) were judged against the sample values of the
    angles (about 1): at size 1e-10 both "vanished", the loop silently open (no
    constraints). They are judged now against the positions of the points that meet."""
    s = _four_bar(unit)
    assert len(s.closure_conditions()) == 2
    assert s.mobility().mobility == 1


@pytest.mark.parametrize("unit", [1e-10, 1.0, 1e3])
def test_reduced_equations_of_a_four_bar_of_any_size(unit):
    """The dependent coordinates and the check of their Jacobian block used the absolute
    1e-9 max(1, |A|): at size 1e-10 every column would look zero."""
    eqs = _four_bar(unit).equations_of_motion()
    assert [c.func.__name__ for c in eqs.reduced(independent=["q1"]).independent] == ["q1"]
    assert len(eqs.reduced().independent) == 1


# -- Joint.check: a blocked component relative to the components of its kind ----------------
@pytest.mark.parametrize("size", [1e-10, 1.0, 1e3])
@pytest.mark.parametrize("ratio, allowed", [(1e-12, True), (1e-9 * (1 - 1e-6), True),
                                            (1e-9 * (1 + 1e-6), False), (1e-6, False)])
def test_prismatic_check_is_relative_to_the_velocities(size, ratio, allowed):
    """A prismatic joint along i with a velocity (size x', ratio size x', 0) at its point:
    the blocked component is accepted as float rounding when at most 1e-9 of the magnitude
    of the velocity's terms, (1 + ratio) size |x'|, whatever the size (with size 1e-10 and
    ratio 1e-6 it was accepted: 1e-16 against the sample value of x', about 1)."""
    x = rm.coordinates("x")
    R0 = rm.Frame("R0")
    joint = rm.joints.Prismatic(at=R0.origin, axis=R0.i)
    xd = x.diff(rm.t)
    motion = rm.Torsor(rm.Vector.zero(), R0.vector(size * xd, ratio / (1 + ratio) * size * xd
                                                   * (1 + ratio), 0), R0.origin)
    if allowed:
        joint.check(motion)
    else:
        with pytest.raises(rm.errors.ConnectionError_, match="is not allowed by the joint"):
            joint.check(motion)


# -- linearize: q* on the constraints by the same rule ---------------------------------------
@pytest.mark.parametrize("r", [1e-10, 1.0, 1e3])
def test_linearize_refuses_a_reference_off_a_circle_of_any_radius(r):
    """A particle on the circle x^2 + y^2 = r^2: about (0.6 r, 0.5 r), 39 % of r^2 off it, is
    refused whatever r (with r = 1e-10 the residual 3.9e-21 passed the absolute tol 1e-9);
    about (0.6 r, 0.8 r) is accepted."""
    from rigidmech.vibrations import linearize

    eqs, _ = _circle()
    eqs = rm.EquationsOfMotion(coordinates=eqs.coordinates, mass_matrix=eqs.mass_matrix,
                               forcing=eqs.forcing,
                               constraints=eqs.constraints)
    with pytest.raises(ArgumentError, match="violates the constraints"):
        linearize(eqs, about={"x": 0.6 * r, "y": 0.5 * r}, independent=["x"],
                  parameters={"r": r})
    linearize(eqs, about={"x": 0.6 * r, "y": 0.8 * r}, independent=["x"], parameters={"r": r})
