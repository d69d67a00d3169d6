"""Laws of contact (ch. 13.1): Coulomb, rolling and pivoting resistance, one-sided contact."""

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.actions import ContactLaws, Coulomb, PivotingResistance, RollingResistance, power

R0 = rm.Frame("R0")
I = R0.origin


def test_coulomb_values_and_cone():
    law = Coulomb(static=0.4, kinetic=0.3)
    assert law.static == sp.Float(0.4) and law.kinetic == sp.Float(0.3)
    assert math.isclose(float(law.cone_half_angle), math.atan(0.4), rel_tol=1e-15)
    assert Coulomb(0.5).kinetic == Coulomb(0.5).static           # kinetic defaults to static
    assert Coulomb(0.5) == Coulomb(0.5, 0.5) and hash(Coulomb(0.5)) == hash(Coulomb(0.5, 0.5))


@pytest.mark.parametrize("angle, inside", [
    pytest.param(0.0, True, id="along-normal"),
    pytest.param(math.atan(0.4) * (1 - 1e-9), True, id="just-inside"),
    pytest.param(math.atan(0.4) * (1 + 1e-6), False, id="just-outside"),
    pytest.param(math.pi - 0.1, False, id="pulling"),
])
def test_in_cone_by_the_angle_with_the_normal(angle, inside):
    # inside the cone iff the angle between R and n is at most phi_s = arctan f_s
    R = 7.0 * (math.cos(angle) * R0.j + math.sin(angle) * R0.k)
    assert Coulomb(0.4).in_cone(R, R0.j) is inside
    assert Coulomb(0.4).in_cone(rm.slider(R, I), R0.j) is inside


@pytest.mark.parametrize("kwargs, match", [
    pytest.param(dict(static=-0.1), r"`static` must be a friction coefficient >= 0",
                 id="negative-static"),
    pytest.param(dict(static=0.3, kinetic=-0.2), r"`kinetic` must be a friction coefficient",
                 id="negative-kinetic"),
    pytest.param(dict(static=0.3, kinetic=0.4), r"`kinetic` must not exceed `static`",
                 id="kinetic-above-static"),
    pytest.param(dict(static=sp.Symbol("f", negative=True)), r"`static` must be",
                 id="negative-symbol"),
])
def test_coulomb_bad_input(kwargs, match):
    with pytest.raises(ArgumentError, match=match):
        Coulomb(**kwargs)


def test_bad_input_types_and_missing_directions():
    with pytest.raises(ArgumentTypeError, match=r"`static` must be"):
        Coulomb("slippery")
    with pytest.raises(ArgumentError, match=r"`tangent` is needed with `friction`"):
        ContactLaws(at=I, normal=R0.j, friction=Coulomb(0.3))
    with pytest.raises(ArgumentError, match=r"`rolling_axis` is needed with `rolling`"):
        ContactLaws(at=I, normal=R0.j, rolling=0.01)
    with pytest.raises(ArgumentError, match=r"`coefficient` must be a length >= 0"):
        RollingResistance(-1)
    with pytest.raises(ArgumentError, match=r"`sliding_velocity` must be non-zero"):
        Coulomb(0.3).sliding_action(1, rm.Vector.zero(), I)
    with pytest.raises(ArgumentError, match=r"substitute values first"):
        Coulomb(0.3).in_cone(sp.Symbol("a") * R0.j, R0.j)


def test_sliding_action_is_a_slider_opposing_the_sliding_velocity():
    N, f = sp.symbols("N f", positive=True)
    v = sp.Symbol("v", positive=True)
    A = Coulomb(f).sliding_action(N, v * R0.i, I)
    assert isinstance(A, rm.Torsor)
    assert sp.simplify(A.resultant.dot(R0.i) + f * N) == 0     # |T| = f N, against v
    assert A.kind == "slider"


def test_contact_action_torsor_and_conditions():
    c = ContactLaws(at=I, normal=R0.j, tangent=R0.i, friction=Coulomb(0.3),
                rolling=0.01, rolling_axis=R0.k, pivoting=0.02)
    T, unknowns = c.action_torsor("1")
    assert [str(u) for u in unknowns] == ["N_1", "T_1", "Mr_1", "Mp_1"]
    N, Tt, Mr, Mp = unknowns
    assert T.resultant == Tt * R0.i + N * R0.j and T.moment == Mr * R0.k + Mp * R0.j
    kinds = [k for k, _ in c.conditions("1")]
    assert kinds == ["lift-off"] + ["sliding"] * 2 + ["rolling"] * 2 + ["pivoting"] * 2


def _unit(v):
    return v / np.linalg.norm(v)


@settings(max_examples=80, deadline=None)
@given(st.lists(st.floats(-5, 5), min_size=6, max_size=6), st.floats(0, 100),
       st.floats(0, 1), st.floats(0, 0.05), st.floats(0, 0.05))
def test_friction_never_does_positive_work(vals, N, f, delta, eta):
    # power of the dissipative part (friction, rolling and pivoting couples) with the relative
    # motion that causes it = -f N |v_s| - delta N |w_r| - eta N |w_p| <= 0 (ch. 11.3, 13.1)
    w = np.array(vals[:3])
    v = np.array(vals[3:])
    v[1] = 0.0                                     # contact kept: no velocity along n = j
    if np.linalg.norm(v) < 1e-6 or np.linalg.norm(w[[0, 2]]) < 1e-6 or abs(w[1]) < 1e-6:
        return
    c = ContactLaws(at=I, normal=R0.j, tangent=R0.i, friction=Coulomb(f), rolling=delta,
                rolling_axis=R0.k, pivoting=eta)
    V = rm.Torsor(R0.vector(*w), R0.vector(*v), I)
    A = c.action(N, V)
    p = float(power(A, V))
    expected = -(f * N * np.linalg.norm(v) + delta * N * np.linalg.norm(w[[0, 2]])
                 + eta * N * abs(w[1]))
    assert p <= 1e-12 * max(1.0, abs(expected))
    assert math.isclose(p, expected, rel_tol=1e-12, abs_tol=1e-12)


def test_resistance_couples():
    assert RollingResistance(0.002).bound(100) == sp.Float(0.2)
    C = PivotingResistance(0.01).couple(50, -2 * R0.j, I)
    assert C.kind == "couple" and C.moment == 0.5 * R0.j
