"""The public read-only views of a System that the report and the drawings read: the given
actions' contributions, the partial kinematic torsors (ch. 25.1.2) and the point that closes
a loop (ch. 25.3). Checked against independent computations (derivatives of the velocities
with respect to q_i')."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import models
from rigidmech.errors import ArgumentError


def same(a, b, frame):
    return all(sp.simplify(a.dot(e) - b.dot(e)) == 0 for e in frame.basis)


def test_partial_kinematic_torsors_are_the_derivatives_with_respect_to_the_rates():
    # V_i(P) = d v(P)/d q_i', Omega_i = d omega/d q_i' (ch. 25.1.2), by differentiation here
    for model in (models.double_pendulum(), models.heavy_top()):
        s = model.system
        R0 = s.galilean
        rates = [q.diff(rm.t) for q in s.coordinates]
        for body in s.bodies:
            for point in (body.centre, R0.origin):
                parts = s.partial_kinematic_torsors(body, point)
                assert isinstance(parts, tuple) and len(parts) == len(rates)
                K = body.kinematic_torsor(relative_to=R0, at=point)
                w, v = K.resultant, K.moment
                for V, rate in zip(parts, rates, strict=True):
                    assert V.point == point
                    for e in R0.basis:
                        assert sp.simplify(V.resultant.dot(e) - w.dot(e).diff(rate)) == 0
                        assert sp.simplify(V.moment.dot(e) - v.dot(e).diff(rate)) == 0


def test_partial_kinematic_torsors_default_to_the_mass_centre():
    pendulum = models.compound_pendulum()
    bar, L = pendulum.body("bar"), pendulum.constant("L")
    (V,) = pendulum.system.partial_kinematic_torsors(bar)
    R1 = pendulum.frame("R1")
    assert V.point == bar.centre
    R0 = pendulum.frame("R0")
    assert same(V.resultant, R0.k, R0) and same(V.moment, L / 2 * R1.j, R0)


def test_partial_kinematic_torsors_bad_input():
    s = models.compound_pendulum().system
    other = rm.Body("other", frame=rm.Frame("Rx"), mass=1)
    with pytest.raises(ArgumentError, match=r"`body` must be a body of this system \(bar\); "
                                            r"got Body\('other'"):
        s.partial_kinematic_torsors(other)
    with pytest.raises(rm.errors.ArgumentTypeError, match="`point`"):
        s.partial_kinematic_torsors(s.bodies[0], "O")


def test_action_contributions_are_the_given_actions_on_the_bodies():
    dp = models.double_pendulum()
    s = dp.system
    got = s.action_contributions()
    assert isinstance(got, tuple)
    assert list(got) == list(s._contributions())     # the same objects the equations use
    by_body = {b.name: T for b, T, a in got}
    assert sorted(by_body) == ["bar1", "bar2"]
    for b in s.bodies:                              # its weight m g at G
        T = by_body[b.name]
        assert T.point == b.centre
        assert same(T.resultant, b.mass * s.actions[0].field, s.galilean)
        assert same(T.moment, 0 * s.galilean.i, s.galilean)


def test_meets_is_the_point_given_to_close_the_loop():
    fb = models.four_bar()
    s = fb.system
    links = s.mechanism.links
    assert [s.meets(k) for k in links[:3]] == [None, None, None]
    assert s.meets(links[3]) is fb.point("C3")
    with pytest.raises(ArgumentError, match=r"`link` must be one of this system's links"):
        s.meets(models.double_pendulum().system.mechanism.links[0])
