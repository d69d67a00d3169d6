"""The graph of bodies, connections and actions (rigidmech.systems.Mechanism): building,
validation, spanning tree and loops."""

import pytest

import rigidmech as rm
from rigidmech.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from rigidmech.systems import Mechanism


def pendulum_chain(n):
    R0 = rm.Frame("R0")
    frames, bodies = [R0], []
    qs = rm.coordinates(" ".join(f"q{i}" for i in range(1, n + 1)))
    qs = qs if isinstance(qs, tuple) else (qs,)
    g = Mechanism(R0)
    for i, q in enumerate(qs, start=1):
        parent = frames[-1]
        F = parent.rotated(f"R{i}", about=R0.k, angle=q,
                           origin=parent.origin.moved(f"P{i}", parent.i) if i > 1 else None)
        b = rm.Body(f"b{i}", frame=F)
        g = g.with_connection(parent if i == 1 else bodies[-1], b,
                              rm.joints.Pivot(at=F.origin, axis=R0.k))
        frames.append(F)
        bodies.append(b)
    return g, R0, bodies


def test_graph_is_immutable_and_each_step_returns_a_new_graph():
    g, R0, bodies = pendulum_chain(2)
    g2 = g.with_body(rm.Body("free", frame=R0.translated("RF", R0.point("F", *rm.coordinates(
        "x y z")))))
    assert len(g.bodies) == 2 and len(g2.bodies) == 3
    with pytest.raises(AttributeError):
        g.bodies = ()


def test_a_tree_has_no_loop_and_every_link_in_the_tree():
    g, _, _ = pendulum_chain(3)
    assert g.loops() == () and g.closing_links() == ()
    assert g.tree_links() == g.links


def test_loops_of_a_four_bar_go_round_the_four_links():
    # the closing link (4) and, back to its first solid, the links 3, 1, 2 (crank, ground,
    # rocker): going round, the relative motions compose to zero
    g, R0, (b1, b2) = pendulum_chain(2)
    R3 = R0.rotated("R3", about=R0.k, angle=rm.coordinates("q3"),
                    origin=R0.point("D", 2, 0, 0))
    rocker = rm.Body("rocker", frame=R3)
    g = g.with_connection(R0, rocker, rm.joints.Pivot(at=R3.origin, axis=R0.k))
    g = g.with_connection(b2, rocker, rm.joints.Pivot(at=R3.origin.moved("C", R3.i),
                                                      axis=R0.k))
    (loop,) = g.loops()
    assert [(k.label, s) for k, s in loop] == [("4", 1), ("3", -1), ("1", 1), ("2", 1)]
    # going round: b2 -> rocker -> ground -> b1 -> b2
    solids = [loop[0][0].first]
    for link, sign in loop:
        nxt = link.second if sign == 1 else link.first
        assert (link.first if sign == 1 else link.second) is solids[-1]
        solids.append(nxt)
    assert solids[0] is solids[-1]


def test_number_of_loops_is_links_minus_bodies():
    # gamma = N_c - N_b for a graph connected to the ground (ch. 13.2)
    g, R0, (b1, b2) = pendulum_chain(2)
    g = g.with_connection(R0, b2, rm.joints.PointContact(at=b2.frame.origin, normal=R0.j))
    g = g.with_connection(R0, b1, rm.joints.PointContact(at=b1.frame.origin, normal=R0.j))
    assert len(g.loops()) == len(g.links) - len(g.bodies) == 2


def test_validation_messages_are_those_of_the_system():
    R0 = rm.Frame("R0")
    q = rm.coordinates("q")
    a = rm.Body("bob", frame=R0.rotated("R1", about=R0.k, angle=q))
    b = rm.Body("bob", frame=R0.rotated("R2", about=R0.k, angle=q))
    g = Mechanism(R0).with_body(a)
    with pytest.raises(ConnectionError_, match=r"two bodies named 'bob'"):
        g.with_body(b)
    with pytest.raises(ConnectionError_, match=r"body bob is already in the system"):
        g.with_body(a)
    with pytest.raises(ConnectionError_, match=r"gravity is already acting"):
        g.with_action(rm.gravity(R0.j)).with_action(rm.gravity(R0.i))


def test_bad_connections_are_refused():
    R0 = rm.Frame("R0")
    b = rm.Body("b", frame=R0.rotated("R1", about=R0.k, angle=rm.coordinates("q")))
    g = Mechanism(R0)
    with pytest.raises(ArgumentTypeError, match=r"`connection` must have an action_torsor"):
        g.with_connection(R0, b, "pivot")
    with pytest.raises(ConnectionError_, match=r"`first` and `second` must be two different"):
        g.with_connection(b, b, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    g = g.with_connection(R0, b, rm.joints.Pivot(at=R0.origin, axis=R0.k), label="O")
    with pytest.raises(ArgumentError, match=r"`label` must be unique; 'O'"):
        g.with_connection(R0, b, rm.joints.Pivot(at=R0.origin, axis=R0.k), label="O")
    with pytest.raises(ConnectionError_, match=r"`first` is the frame R1; only the Galilean"):
        g.with_connection(b.frame, b, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    with pytest.raises(ArgumentTypeError, match=r"`reference` must be a Frame"):
        Mechanism("R0")


def test_the_tree_is_the_order_of_construction():
    # a -> b hangs from the ground through a; the link ground-b given last closes the loop,
    # even though it is the shortest way from the ground to b
    R0 = rm.Frame("R0")
    q1, q2 = rm.coordinates("q1 q2")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R1.rotated("R2", about=R0.k, angle=q2, origin=R0.origin.moved("A", R1.i))
    a, b = rm.Body("a", frame=R1), rm.Body("b", frame=R2)
    g = (Mechanism(R0)
         .with_connection(R0, a, rm.joints.Pivot(at=R0.origin, axis=R0.k))
         .with_connection(a, b, rm.joints.Pivot(at=R2.origin, axis=R0.k))
         .with_connection(R0, b, rm.joints.PointContact(at=R0.origin, normal=R0.j)))
    assert [k.label for k in g.closing_links()] == ["3"]
    assert [x.name for x in g.carried_by(g.links[1])] == ["b"]
    with pytest.raises(ConnectionError_, match=r"not in the spanning tree"):
        g.carried_by(g.links[2])
