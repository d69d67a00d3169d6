"""Tests of rigidmech.vectors.functions: derivatives of vector functions relative to a frame
(book, ch. 3)."""

import itertools

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.vectors import Frame, coordinates, t
from rigidmech.vectors.functions import derivation_formula, derivative, jacobian, partial

Q = coordinates("q1 q2 q3")
_TAGS = itertools.count()
R0 = Frame("R0")


def numeric(matrix, values, rates):
    """Evaluate components at q = values, q' = rates (derivatives replaced first)."""
    m = sp.Matrix(matrix).xreplace({qi.diff(t): r for qi, r in zip(Q, rates, strict=True)})
    m = m.xreplace({qi: v for qi, v in zip(Q, values, strict=True)}).xreplace({t: 0.7})
    return np.array(m.evalf(), dtype=float).ravel()


@st.composite
def frame_chains(draw):
    """A random tree of three rotated frames below R0: each rotates by q_n about an axis
    (i, j or k, possibly reversed) of a randomly chosen earlier frame.

    Names are unique per example: equal frames built twice as distinct objects trip
    _rotations.common_ancestor (reported to the lead: it matches by == but path_to_ancestor
    walks by identity)."""
    frames = [R0]
    tag = next(_TAGS)
    for n in range(3):
        parent = frames[draw(st.integers(0, len(frames) - 1))]
        axis = parent.basis[draw(st.integers(0, 2))] * draw(st.sampled_from([1, -1]))
        frames.append(parent.rotated(f"F{n}_{tag}", about=axis, angle=Q[n]))
    return frames


coefficient = st.sampled_from([sp.S(1), sp.S(-2), Q[0], Q[1] ** 2, sp.cos(Q[2]), t])


@settings(max_examples=20, deadline=None)
@given(frames=frame_chains(), picks=st.lists(st.tuples(st.integers(0, 3), st.integers(0, 2),
                                                          coefficient), min_size=1, max_size=4),
       values=st.lists(st.floats(-3, 3), min_size=3, max_size=3),
       rates=st.lists(st.floats(-2, 2), min_size=3, max_size=3))
def test_derivation_formula_on_random_frames(frames, picks, values, rates):
    # d/dt|R0 u = d/dt|R1 u + omega(R1/R0) ^ u (ch. 3.1.4, 9.2.3) for every frame R1 of a
    # random tree; the reference is independent of rotation vectors: the components of u in R0,
    # differentiated one by one. Compared numerically at a random state: the terms are sums of
    # products of O(1) trigonometric factors, rtol 1e-9 and atol 1e-9 allow for round-off.
    u = sum((c * frames[f].basis[a] for f, a, c in picks), R0.i * 0)
    reference = numeric(u.components(R0).diff(t), values, rates)
    assert_allclose(numeric(derivative(u, t, R0).components(R0), values, rates), reference,
                    rtol=1e-9, atol=1e-9)
    for via in frames[1:]:
        got = numeric(derivation_formula(u, R0, via).components(R0), values, rates)
        assert_allclose(got, reference, rtol=1e-9, atol=1e-9)


def test_derivative_orders_and_variables():
    q = Q[0]
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    assert derivative(R1.i, q, R0, order=0) == R1.i
    assert derivative(R1.i, q, R0).equals(R1.j)
    assert derivative(R1.i, q, R0, order=4).equals(R1.i)
    assert derivative(R1.i, t, R0, order=2).equals(q.diff(t, 2) * R1.j - q.diff(t) ** 2 * R1.i)
    assert derivative(q.diff(t) * R1.i, q.diff(t), R0) == R1.i
    assert derivative(R1.i, q, R1) == R0.i * 0


def test_chain_rule_of_n_variables():
    # ch. 3.3: du/dt = sum_i (du/dq_i) q_i' + du/dt|explicit, relative to one frame.
    q1, q2, _ = Q
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R1.i, angle=q2)
    s = sp.Symbol("s")
    u = s * R2.j + t * q2 * R1.i
    explicit = (q2 * R1.i).express(R0)  # d/dt at fixed q1, q2, expressed where bases are fixed
    chain = (derivative(u, q1, R0) * q1.diff(t) + derivative(u, q2, R0) * q2.diff(t)
             + explicit)
    assert derivative(u, t, R0).equals(chain, frame=R0)


def test_partial_derivatives_commute():
    x, y = sp.symbols("x y", real=True)
    R1 = R0.rotated("R1", about=R0.k, angle=x * y)
    u = x**2 * R1.i + sp.sin(y) * x * R1.j + R0.k * y**3
    assert partial(u, (x, y), R0).equals(partial(u, (y, x), R0), frame=R0)
    assert partial(u, x, R0).equals(derivative(u, x, R0))


def test_jacobian_spherical_coordinates():
    r, th, ph = sp.symbols("r theta phi", positive=True)
    u = R0.vector(r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph), r * sp.cos(th))
    J = jacobian(u, (r, th, ph), R0)
    assert J.shape == (3, 3)
    assert sp.simplify(J.det() - r**2 * sp.sin(th)) == 0  # volume element of ch. 3.3
    assert jacobian(u, r, R0).shape == (3, 1)


def test_errors():
    x = sp.Symbol("x")
    with pytest.raises(ArgumentError, match=r"`order` must be a non-negative integer; got -1"):
        derivative(x * R0.i, x, R0, order=-1)
    with pytest.raises(ArgumentError, match=r"`order` must be a non-negative integer; got True"):
        derivative(x * R0.i, x, R0, order=True)
    with pytest.raises(ArgumentError, match=r"`variable` must be a symbol, a parameter q\(t\) or "
                                            r"a derivative q'\(t\); got x \+ 1"):
        derivative(x * R0.i, x + 1, R0)
    with pytest.raises(ArgumentTypeError, match=r"`variable` must be a sympy symbol or a "
                                                r"parameter q\(t\); got object"):
        derivative(x * R0.i, object(), R0)
    with pytest.raises(ArgumentTypeError, match=r"`frame` must be a Frame; got str"):
        derivative(x * R0.i, x, "R0")
    with pytest.raises(ArgumentTypeError, match=r"`u` must be a Vector; got int"):
        derivative(3, x, R0)
    with pytest.raises(ArgumentError, match=r"`variables` must hold at least one variable"):
        partial(x * R0.i, (), R0)
    with pytest.raises(ArgumentError, match=r"`variables` must hold at least one variable"):
        jacobian(x * R0.i, [], R0)
    with pytest.raises(ArgumentTypeError, match=r"`via` must be a Frame; got NoneType"):
        derivation_formula(R0.i, R0, None)
