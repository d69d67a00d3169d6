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


# --- vectors documented as unit: normalised where they enter (like ContactKinematics) -------

def _box_limit(normal, tangent, rolling_axis):
    """The box of ch. 14 (W = 10, base half-width 0.5, f = 0.6) pushed at height 1: it tips
    at P = W a / h = 5 before it slides at f W = 6."""
    from rigidmech.actions import Force
    from rigidmech.statics import Statics, limiting_equilibrium

    P = sp.Symbol("P", real=True)
    box = rm.Body("box", frame=R0)
    st_ = Statics(R0)
    st_.connect(R0, box, ContactLaws(at=R0.origin, normal=normal, tangent=tangent,
                                     friction=Coulomb(0.6), footprint=0.5,
                                     rolling_axis=rolling_axis), label="floor")
    st_.act(Force(on=box, vector=-10.0 * R0.j, at=R0.point("G", 0, 0.5, 0)))
    st_.act(Force(on=box, vector=P * R0.i, at=R0.point("H", -0.5, 1.0, 0)))
    return limiting_equilibrium(st_, P, (0.0, 20.0))


@pytest.mark.parametrize("n, t, r", [
    pytest.param(1, 1, 1, id="unit"),
    pytest.param(2, 1, 1, id="normal-2"),
    pytest.param(1, 3, 0.5, id="tangent-3-axis-half"),
    pytest.param(sp.Rational(1, 4), 7, 2, id="all-scaled"),
])
def test_contact_laws_normalise_their_normal_tangent_and_axis(n, t, r):
    """N, T and M_r are components along the unit vectors: scaling the vectors given must not
    scale the forces nor the friction and tipping limits (P = 5 tipping, 6 sliding)."""
    lim = _box_limit(n * R0.j, t * R0.i, r * R0.k)
    assert lim.kinds == ("tipping",)
    assert math.isclose(lim.value, 5.0, rel_tol=1e-9)
    assert math.isclose(lim.by_kind["sliding"], 6.0, rel_tol=1e-9)


def test_contact_laws_unit_vectors_exposed_and_symbolic_norms():
    c = ContactLaws(at=I, normal=2 * R0.j, tangent=-3 * R0.i, friction=Coulomb(0.5))
    assert c.normal == R0.j
    T, (N, Tt) = c.action_torsor("I")
    assert T.resultant == N * R0.j - Tt * R0.i
    a = sp.Symbol("a", positive=True)
    assert ContactLaws(at=I, normal=a * R0.j).normal == R0.j
    b = sp.Symbol("b", real=True)            # sign unknown: normalised symbolically
    nb = ContactLaws(at=I, normal=b * R0.j).normal
    assert sp.simplify(nb.dot(R0.j) - b / sp.Abs(b)) == 0


@pytest.mark.parametrize("kwargs, match", [
    ({"normal": 0 * R0.j}, r"`normal` must be a non-zero vector"),
    ({"normal": R0.j, "tangent": R0.i + R0.j, "friction": Coulomb(0.5)},
     r"`tangent` must be perpendicular to `normal`"),
    ({"normal": R0.j, "footprint": 0.5, "rolling_axis": R0.j},
     r"`rolling_axis` must be perpendicular to `normal`"),
    ({"normal": R0.j, "footprint": 0.5, "rolling_axis": 0 * R0.k},
     r"`rolling_axis` must be a non-zero vector"),
])
def test_contact_laws_refuse_zero_or_oblique_vectors(kwargs, match):
    with pytest.raises(ArgumentError, match=match):
        ContactLaws(at=I, **kwargs)


def test_in_cone_normalises_the_normal():
    """10 j + 6 i is outside the cone f = 0.5 of axis j, whatever the length of the axis."""
    law = Coulomb(0.5)
    assert law.in_cone(10 * R0.j + 6 * R0.i, 2 * R0.j) is False
    assert law.in_cone(10 * R0.j + 4 * R0.i, 0.5 * R0.j) is True
    with pytest.raises(ArgumentError, match=r"`normal` must be a non-zero vector"):
        law.in_cone(10 * R0.j, 0 * R0.j)


def test_torsional_damper_and_spring_normalise_their_axis():
    """The couple about the unit axis: -c q' k and -k q k whatever the length of `axis`."""
    from rigidmech.actions import TorsionalDamper, TorsionSpring

    q = rm.coordinates("q")
    c, k = sp.symbols("c k", positive=True)
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    disk = rm.Body("disk", frame=R1, mass=1)
    damper = TorsionalDamper(c, axis=2 * R0.k, on=disk)
    assert damper.contributions([disk])[0][1].moment == -c * q.diff() * R0.k
    assert sp.simplify(damper.dissipation_function() - c * q.diff() ** 2 / 2) == 0
    spring = TorsionSpring(k, q, axis=3 * R0.k, on=disk)
    assert spring.contributions([disk])[0][1].moment == -k * q * R0.k
    with pytest.raises(ArgumentError, match=r"`axis` must be a non-zero vector"):
        TorsionSpring(k, q, axis=0 * R0.k, on=disk)


@pytest.mark.parametrize("cosine, ok", [(0.0, True), (0.5e-12, True), (1e-12, True),
                                        (2e-12, False), (1e-6, False)])
def test_perpendicular_is_decided_by_one_rule(cosine, ok):
    """A tangent (ContactLaws) and a blade direction (KnifeEdge) must be perpendicular to the
    normal: one rule, |cos| <= 1e-12 for numbers (the boundary included), shown zero for
    symbols."""
    from rigidmech.actions import KnifeEdge

    x, y, th = rm.coordinates("x y theta")
    G = R0.point("G", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=G)
    slanted_t = R0.i + cosine * R0.j                  # against the normal R0.j
    slanted_e = R1.i + cosine * R1.k                  # against the normal R0.k
    if ok:
        ContactLaws(at=I, normal=R0.j, tangent=slanted_t, friction=Coulomb(0.5))
        KnifeEdge(R1, R0, at=G, direction=slanted_e, normal=R0.k)
    else:
        with pytest.raises(ArgumentError, match=r"`tangent` must be perpendicular"):
            ContactLaws(at=I, normal=R0.j, tangent=slanted_t, friction=Coulomb(0.5))
        with pytest.raises(ArgumentError, match=r"`direction` must be perpendicular"):
            KnifeEdge(R1, R0, at=G, direction=slanted_e, normal=R0.k)


def test_action_does_not_take_a_direction_from_rounding_noise():
    """A velocity at I along the normal with a tangential part of rounding size (1e-16 of
    it): no sliding (the law needs a rate: refused), not a full friction force f_k N along the
    noise. A tangential part of 1e-6 of it slides."""
    c = ContactLaws(at=I, normal=R0.j, tangent=R0.i, friction=Coulomb(0.5, 0.4))
    noisy = rm.Torsor(rm.Vector.zero(), 3.0 * R0.j + 3e-16 * R0.i, I)
    with pytest.raises(ArgumentError, match="`sliding_velocity` must be non-zero"):
        c.action(10, noisy)
    real = rm.Torsor(rm.Vector.zero(), 3.0 * R0.j + 3e-6 * R0.i, I)
    assert c.action(10, real).resultant == -4.0 * R0.i + 10 * R0.j
    r = ContactLaws(at=I, normal=R0.j, rolling=0.1, rolling_axis=R0.k)
    with pytest.raises(ArgumentError, match="must be non-zero"):
        r.action(10, rm.Torsor(2.0 * R0.j + 2e-16 * R0.k, rm.Vector.zero(), I))


@pytest.mark.parametrize("fraction, slides", [(0.5e-12, False), (2e-12, True)])
def test_rate_noise_threshold_either_side(fraction, slides):
    c = ContactLaws(at=I, normal=R0.j, tangent=R0.i, friction=Coulomb(0.5, 0.4))
    V = rm.Torsor(rm.Vector.zero(), 1.0 * R0.j + fraction * R0.i, I)
    if slides:
        assert c.action(10, V).resultant == -4.0 * R0.i + 10 * R0.j
    else:
        with pytest.raises(ArgumentError, match="`sliding_velocity` must be non-zero"):
            c.action(10, V)
