"""Every connection of the catalogue (ch. 13.2.2) gets the symbol docs/drawing.rst promises,
drawn at its point, in a plane and in space."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech import models
from rigidmech.drawing import View, connection_kind, draw_connection, place
from rigidmech.systems import Link

PENDULUM = models.compound_pendulum()
R0 = PENDULUM.frame("R0")
G = PENDULUM.point("G")
J = rm.actions

CONNECTIONS = [
    (J.Pivot(at=G, axis=R0.k), "pivot"),
    (J.Revolute(at=G, axis=R0.k), "pivot"),
    (J.Helical(at=G, axis=R0.i, pitch=0.1), "helical"),
    (J.Prismatic(at=G, axis=R0.i), "slide"),
    (J.Cylindrical(at=G, axis=R0.i), "cylindrical"),
    (J.Spherical(at=G), "ball"),
    (J.SphericalWithFinger(at=G, axis=R0.k), "ball"),
    (J.PlanarSupport(at=G, normal=R0.j), "planar"),
    (J.PointContact(at=G, normal=R0.j), "contact"),
    (J.LinearRectilinear(at=G, normal=R0.j, direction=R0.k), "contact"),
    (J.LinearAnnular(at=G, axis=R0.i), "contact"),
    (J.Embedding(at=G), "embedding"),
]


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("ground", [True, False])
@pytest.mark.parametrize("connection, kind", CONNECTIONS,
                         ids=[f"{type(c).__name__}" for c, _ in CONNECTIONS])
def test_symbol_of_each_connection(connection, kind, dim, ground):
    assert connection_kind(connection) == kind
    p = place(PENDULUM, [0.4], {"L": 2.0})
    view = View.of(p, dim)
    fig = plt.figure()
    ax = fig.add_subplot(projection="3d" if dim == 3 else None)
    link = Link(PENDULUM.system.mechanism.ground, PENDULUM.body("bar"), connection, "1")
    symbol = draw_connection(ax, link, p, view, size=0.1, ground=ground)
    assert symbol.kind == kind and symbol.point == "G"
    assert_allclose(symbol.at, view.project([np.cos(0.4), np.sin(0.4), 0.0]), atol=1e-12)
    assert len(symbol.artists) >= 2                  # the symbol and its label
    fig.canvas.draw()


def test_rolling_contact_and_knife_edge_kinds():
    assert connection_kind(models.rolling_disc().connections[0]) == "rolling"
    assert connection_kind(models.sleigh().connections[0]) == "knife"
    assert connection_kind(object()) == "connection"
