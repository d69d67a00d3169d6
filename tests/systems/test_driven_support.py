"""Linking conditions on a support whose motion is prescribed (a function of t written in
its frame: a conveyor belt, a driven turntable; book, ch. 10.1.3, 13.1).

Reference: a disc of radius r (centre C = (x, r), rotation theta about k) rolling without
slipping on a belt translated by v t along i: the sliding velocity at the contact point is
x' + r theta' - v (the belt point's velocity is v i), so the one linking condition is
x' + r theta' - v = 0 up to its sign.
"""

import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import Circle, ContactKinematics
from rigidmech.systems import Link, closure_conditions


def _disc_on_belt():
    x, th = rm.coordinates("x theta")
    r, v = rm.constants("r v", positive=True)
    R0 = rm.Frame("R0")
    belt = R0.translated("Rb", R0.point("B", v * rm.t, 0, 0))
    R1 = R0.rotated("R1", about=R0.k, angle=th, origin=R0.point("C", x, r, 0))
    contact = ContactKinematics.between(R1, Circle(R1.origin, r, normal=R0.k), belt,
                                        rm.Line(belt.origin, belt.i))
    link = Link(rm.Body("belt", frame=belt), rm.Body("disc", frame=R1),
                rm.actions.RollingContact(contact), "I")
    contact.sliding_velocity, contact.tangents()  # the kinematics, before the decision
    return link, (x, th), (r, v)


def test_rolling_on_a_driven_belt_decided_by_sampling_not_simplify(monkeypatch):
    """The no-slip rows carry t explicitly (the belt moves with time): whether each one
    vanishes identically is decided by its values at sample points (t sampled like the other
    symbols), not by ``sympy.simplify`` -- which the time-dependent rows of a ball on a driven
    turntable paid 7 s for. The row kept is x' + r theta' - v."""
    link, (x, th), (r, v) = _disc_on_belt()

    def refuse(*args, **kwargs):
        raise AssertionError("sympy.simplify called to decide a no-slip row")

    monkeypatch.setattr(sp, "simplify", refuse)
    rows = closure_conditions(link)
    monkeypatch.undo()
    assert [label for label, _, _ in rows] == ["I.t1"]
    expected = x.diff(rm.t) + r * th.diff(rm.t) - v
    c = rows[0][1]
    assert sp.simplify(c - expected) == 0 or sp.simplify(c + expected) == 0
