"""Drawings of a system (rigidmech.drawing.draw): the artists drawn and where the connection
symbols are, checked against positions computed here independently (closed forms)."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.patches import Circle
from numpy.testing import assert_allclose

from rigidmech import models
from rigidmech.drawing import draw, shape_mesh
from rigidmech.drawing.symbols import MEETS_GAP, meets_apart
from rigidmech.errors import ArgumentError


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def four_bar_closed(q1, lengths=models.FOUR_BAR_LENGTHS):
    """(q1, q2, q3) closing the four-bar, and C: the circles of centres B (radius BC) and D
    (radius DC) meet at C (the upper intersection)."""
    l0, l1, l2, l3 = lengths
    B, D = l1 * np.array([np.cos(q1), np.sin(q1)]), np.array([l0, 0.0])
    d = np.linalg.norm(D - B)
    a = (l2**2 - l3**2 + d**2) / (2 * d)
    h = np.sqrt(l2**2 - a**2)
    e = (D - B) / d
    C = B + a * e + h * np.array([-e[1], e[0]])
    q2 = np.arctan2(*(C - B)[::-1]) - q1
    q3 = np.arctan2(*(C - D)[::-1])
    return [q1, q2, q3], B, C, D


def circles_at(symbol):
    return [a for a in symbol.artists if isinstance(a, Circle)]


def texts(drawing):
    return sorted(t.get_text() for t in drawing.ax.texts)


def test_double_pendulum_artists_and_joint_positions():
    q1, q2, L = 0.6, 1.2, 1.0
    d = draw(models.double_pendulum(), [q1, q2], {"L": L})
    assert d.view.dim == 2
    assert sorted(d.bodies) == ["bar1", "bar2"]
    assert [(c.kind, c.point) for c in d.connections] == [("pivot", "O"), ("pivot", "A")]
    assert texts(d) == ["A", "O", "bar1", "bar2"]
    # gravity along +R0.i: the page's x is R0.j and its y is -R0.i (View.of)
    O, A = np.zeros(2), np.array([L * np.sin(q1), -L * np.cos(q1)])
    for symbol, expected in zip(d.connections, (O, A), strict=True):
        assert_allclose(symbol.at, expected, atol=1e-12)
        (circle,) = circles_at(symbol)
        assert_allclose(circle.center, expected, atol=1e-12)
    # each rod a line from its pivot to its tip
    tip = A + L * np.array([np.sin(q2), -np.cos(q2)])
    line = d.bodies["bar2"][0]
    assert_allclose(np.c_[line.get_xdata(), line.get_ydata()], [A, tip], atol=1e-12)
    # the ground pivot has its support (a triangle) and hatching; the other none
    assert len(d.connections[0].artists) > len(d.connections[1].artists)


def test_four_bar_artists_and_joint_positions():
    q, B, C, D = four_bar_closed(1.2)
    d = draw(models.four_bar(), q, frames=True)
    assert sorted(d.bodies) == ["coupler", "crank", "rocker"]
    assert [c.kind for c in d.connections] == ["pivot"] * 4
    # gravity -R0.j: the page is (R0.i, R0.j)
    expected = {"O": np.zeros(2), "B": B, "D": D, "C": C}
    assert {c.point for c in d.connections} == set(expected)
    for symbol in d.connections:
        assert_allclose(symbol.at, expected[symbol.point], atol=1e-12)
        assert_allclose(circles_at(symbol)[0].center, expected[symbol.point], atol=1e-12)
    # trihedra: the reference and the three bodies' frames, two in-plane vectors each
    assert sorted(d.frames) == ["R0", "R1", "R2", "R3"]
    assert all(len(arts) == 4 for arts in d.frames.values())
    assert {"$i_{R1}$", "$j_{R3}$"} <= set(texts(d))


def test_loop_closing_joint_shows_its_meets_point_when_apart():
    # the four-bar closes its loop at the pivot C (coupler's end) meeting C3 (rocker's end)
    (q1, q2, q3), B, C, D = four_bar_closed(1.2)
    l3 = models.FOUR_BAR_LENGTHS[3]
    opened = q3 + 0.3                           # the rocker turned: the loop is open
    C3 = D + l3 * np.array([np.cos(opened), np.sin(opened)])
    d = draw(models.four_bar(), [q1, q2, opened])
    (closing,) = [c for c in d.connections if c.point == "C"]
    assert_allclose(closing.at, C, atol=1e-12)
    assert_allclose(closing.meets, C3, atol=1e-12)
    dashed = [a for a in closing.artists if getattr(a, "get_linestyle", lambda: "")() == "--"]
    (gap,) = dashed
    assert_allclose(np.c_[gap.get_xdata(), gap.get_ydata()], [C, C3], atol=1e-12)
    assert "C3" in texts(d)
    assert [c.meets for c in d.connections if c.point != "C"] == [None] * 3
    # closed: one symbol, no meeting point drawn
    closed = draw(models.four_bar(), [q1, q2, q3])
    assert all(c.meets is None for c in closed.connections)
    assert "C3" not in texts(closed)


def test_a_contact_closing_a_loop_counts_its_gap_along_the_normal_only():
    # a bar on a pivot at O whose tip T touches the plane y = -0.5 (a point contact at A):
    # the contact point slides on the plane, so only the distance to the plane is a gap
    import rigidmech as rm
    from rigidmech.actions import PointContact

    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    bar = rm.Body("bar", frame=R1, mass=1, centre=R0.origin.moved("G", R1.i / 2),
                  inertia=rm.inertia.rod(1, 1, axis=R1.i))
    s = rm.System(galilean=R0)
    s.connect(R0, bar, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(R0, bar, PointContact(at=R0.point("A", 0, -0.5, 0), normal=R0.j),
              meets=R0.origin.moved("T", R1.i))
    touching = draw(s, [-np.pi / 6])            # T = (cos, sin)(-pi/6): on the plane
    assert [c.meets for c in touching.connections] == [None, None]
    lifted = draw(s, [0.0])                     # T = (1, 0): 0.5 above the plane
    (contact,) = [c for c in lifted.connections if c.kind == "contact"]
    assert_allclose(contact.meets, lifted.view.project([1.0, 0.0, 0.0]), atol=1e-12)


@pytest.mark.parametrize("gap, shown", [
    pytest.param(0.1 - 1e-12, False, id="just-below"),
    pytest.param(0.1, False, id="at"),
    pytest.param(0.1 + 1e-12, True, id="just-above"),
])
def test_meets_point_shown_beyond_a_tenth_of_the_symbol(gap, shown):
    # one rule: the meeting point is drawn apart when the gap exceeds MEETS_GAP * size
    assert MEETS_GAP == 0.1
    assert meets_apart(np.zeros(3), np.array([gap, 0.0, 0.0]), size=1.0) is shown


def test_heavy_top_in_3d_ball_joint_at_the_fixed_point():
    psi, theta, phi, l = 0.4, 0.5, 0.0, 1.0
    d = draw(models.heavy_top(), [psi, theta, phi], {"l": l, "A": 1.0, "C": 0.5})
    assert d.view.dim == 3 and d.ax.name == "3d"
    (ball,) = d.connections
    assert ball.kind == "ball" and ball.point == "O"
    assert_allclose(ball.at, [0, 0, 0], atol=1e-12)
    # the top is drawn as its shape, a cone with its apex at O (no principal axes)
    arts = d.bodies["top"]
    assert [type(a).__name__ for a in arts] == ["Poly3DCollection", "Text3D"]
    k = np.array([np.sin(psi) * np.sin(theta), -np.cos(psi) * np.sin(theta), np.cos(theta)])
    G = d.view.project(l * k)
    shape = models.heavy_top().bodies[0].shape
    vertices, _ = shape_mesh(shape, {"radius": l / 2, "height": 4 * l / 3})
    world = vertices @ d.placement.rotation(shape.frame).T + l * k
    along = world @ k            # the cone's extent along its axis, from O
    assert_allclose([along.min(), along.max()], [0, 4 * l / 3], atol=1e-12)
    apex = world[np.argmin(along)]
    assert_allclose(apex, [0, 0, 0], atol=1e-12)                  # the apex on the ball joint
    radial = np.linalg.norm(world - np.outer(along, k), axis=1)
    assert_allclose(radial.max(), l / 2, rtol=1e-12)              # the base, radius l/2
    # gravity -R0.k: the view's vertical is R0.k
    assert_allclose(G[2], np.cos(theta))


def test_catalogue_shapes_are_drawn_as_such():
    d = draw(models.rolling_disc(), [0.0, 0.0, 0.3, 1.2, 0.0], {"r": 0.5})
    (disc,) = [a for a in d.bodies["disc"] if type(a).__name__ == "Poly3DCollection"]
    d.figure.canvas.draw()                  # a 3D collection is projected when drawn
    assert len(disc.get_paths()) > 30
    assert d.connections[0].kind == "rolling"
    wheel = draw(models.wheel_on_incline(0.3), [1.0, 0.0], {"r": 0.5})
    polygon = wheel.bodies["wheel"][0]
    centre = wheel.placement.point("C")
    radii = np.linalg.norm(polygon.get_xy() - wheel.view.project(centre), axis=1)
    assert_allclose(radii, 0.5, rtol=0.02)    # a disc of radius r seen along its axis


@pytest.mark.parametrize("fmt", ["png", "svg", "pdf"])
def test_saved_in_each_format(tmp_path, fmt):
    d = draw(models.double_pendulum(), [0.6, 1.2], {"L": 1.0})
    path = d.save(tmp_path / f"pendulum.{fmt}")
    with open(path, "rb") as file:
        head = file.read(64)
    magic = {"png": b"\x89PNG", "svg": b"<?xml", "pdf": b"%PDF"}[fmt]
    assert head.startswith(magic)


def test_save_refuses_other_formats(tmp_path):
    d = draw(models.double_pendulum(), [0.6, 1.2], {"L": 1.0})
    with pytest.raises(ArgumentError, match=r"`path` must end with one of \.png, \.svg, \.pdf"):
        d.save(tmp_path / "pendulum.jpg")
    with pytest.raises(ArgumentError, match="`path` is in a folder that does not exist"):
        d.save(tmp_path / "missing" / "pendulum.png")


@pytest.mark.parametrize("q, params, match", [
    pytest.param([0.1, 0.2, 0.3], {"L": 1.0}, r"`q` must give 2 values", id="too-many"),
    pytest.param([0.1, 0.2], {}, r"missing L", id="missing-parameter"),
])
def test_bad_input(q, params, match):
    with pytest.raises(ArgumentError, match=match):
        draw(models.double_pendulum(), q, params)


def test_2d_axes_refused_for_a_spatial_system():
    fig, ax = plt.subplots()
    with pytest.raises(ArgumentError, match=r"`ax` must be 3D axes \(projection='3d'\)"):
        draw(models.heavy_top(), [0.0, 0.5, 0.0], {"l": 1.0}, ax=ax)


def test_a_planar_system_drawn_in_3d_on_request():
    d = draw(models.double_pendulum(), [0.6, 1.2], {"L": 1.0}, dim=3)
    assert d.ax.name == "3d" and len(d.connections[1].at) == 3


def test_spring_drawn_between_its_end_points():
    from rigidmech.scenes.catalogue import get

    scene = get("spring-mass")                    # P = (l0 + x, 0, 0), spring from O to P
    built = scene.build()
    d = draw(built.system, [0.5], {"l0": 1.0})
    zigzags = [line for line in d.ax.lines if len(line.get_xdata()) == 19]
    assert len(zigzags) == 1
    xy = np.c_[zigzags[0].get_xdata(), zigzags[0].get_ydata()]
    assert_allclose(xy[[0, -1]], d.view.project(np.array([[0, 0, 0], [1.5, 0, 0]])),
                    atol=1e-12)
    assert [c.kind for c in d.connections] == ["slide"]


def test_dim_and_placer_checked():
    with pytest.raises(ArgumentError, match="`dim` must be None, 2 or 3; got 1"):
        draw(models.double_pendulum(), [0.0, 0.0], {"L": 1.0}, dim=1)
    with pytest.raises(TypeError, match="`placer` must be a Placer"):
        draw(models.double_pendulum(), [0.0, 0.0], placer="compiled")


def test_damper_drawn_as_a_dashpot():
    from rigidmech.drawing import draw_spring

    fig, ax = plt.subplots()
    arts = draw_spring(ax, np.array([0.0, 0.0]), np.array([2.0, 0.0]), size=0.2, damper=True)
    # rod a -> cup, the cup (3 sides), piston rod -> b, the piston plate across
    assert len(arts) == 4
    assert_allclose(arts[0].get_xydata(), [[0, 0], [0.7, 0]])
    assert_allclose(arts[2].get_xydata(), [[1.1, 0], [2.0, 0]])
    assert draw_spring(ax, np.zeros(2), np.zeros(2), size=0.2) == []
