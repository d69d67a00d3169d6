"""The numeric core of the drawings: a system at a state in numbers (rigidmech.drawing)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from rigidmech import models
from rigidmech.drawing import Placer, View, place
from rigidmech.errors import ArgumentError, ArgumentTypeError


def test_double_pendulum_positions_closed_form():
    # O at the origin, A = L (cos q1, sin q1), G2 = A + L/2 (cos q2, sin q2) in (R0.i, R0.j)
    dp = models.double_pendulum()
    q1, q2, L = 0.4, -1.1, 1.3
    p = place(dp, [q1, q2], {"L": L, "g": 9.81, "m": 2.0})
    A = L * np.array([np.cos(q1), np.sin(q1), 0])
    assert_allclose(p.point("A"), A, atol=1e-14)
    assert_allclose(p.point("G2"), A + L / 2 * np.array([np.cos(q2), np.sin(q2), 0]),
                    atol=1e-14)
    assert_allclose(p.rotation("R2"), [[np.cos(q2), -np.sin(q2), 0],
                                       [np.sin(q2), np.cos(q2), 0], [0, 0, 1]], atol=1e-14)
    assert_allclose(p.origin("R1"), 0, atol=1e-14)
    assert_allclose(p.gravity, [1, 0, 0])


def test_heavy_top_axis_from_euler_angles():
    # the axis R.k in R0 for z-x-z Euler angles: (sin psi sin theta, -cos psi sin theta, cos theta)
    top = models.heavy_top()
    psi, theta, phi, l = 0.7, 0.5, 1.9, 0.8
    p = place(top, [psi, theta, phi], {"l": l})
    k = [np.sin(psi) * np.sin(theta), -np.cos(psi) * np.sin(theta), np.cos(theta)]
    assert_allclose(p.rotation("R")[:, 2], k, atol=1e-14)
    assert_allclose(p.point("G"), l * np.array(k), atol=1e-14)
    assert p.placer.plane is None


@pytest.mark.parametrize("build, plane", [
    pytest.param(models.double_pendulum, 2, id="double-pendulum"),
    pytest.param(models.four_bar, 2, id="four-bar"),
    pytest.param(models.block_on_incline, 2, id="incline"),
    pytest.param(models.heavy_top, None, id="heavy-top"),
    pytest.param(models.rolling_disc, None, id="rolling-disc"),
])
def test_plane_of_motion(build, plane):
    m = build()
    values = {s.name: 1.0 for s in m.constants}
    assert Placer(m, values).plane == plane


def test_view_puts_gravity_down_the_page():
    p = place(models.four_bar(), [1.0, -1.0, 1.0])        # gravity -g R0.j
    assert_allclose(View.of(p).project([0, -1.0, 0]), [0, -1.0], atol=1e-14)
    top = place(models.heavy_top(), [0.0, 0.3, 0.0], {"l": 1.0})   # gravity -g R0.k
    view = View.of(top)
    assert view.dim == 3
    assert_allclose(view.project([0, 0, 1.0])[2], 1.0)


def test_placement_evaluates_points_and_vectors_it_did_not_compile():
    dp = models.double_pendulum()
    p = place(dp, [0.0, np.pi / 2], {"L": 2.0})
    R2 = dp.frame("R2")
    tip = dp.point("A").moved("tip", 2.0 * R2.i)
    assert_allclose(p.point(tip), [2.0, 2.0, 0.0], atol=1e-14)
    assert_allclose(p.vector(R2.i), [0.0, 1.0, 0.0], atol=1e-14)


def test_state_by_name():
    dp = models.double_pendulum()
    a = place(dp, {"theta1": 0.2, "theta2": 0.3}, {"L": 1.0})
    b = place(dp, [0.2, 0.3], {"L": 1.0})
    assert_allclose(a.point("G2"), b.point("G2"))


@pytest.mark.parametrize("q, params, error, match", [
    pytest.param([0.1], {"L": 1.0}, ArgumentError,
                 r"`q` must give 2 values \(theta1, theta2\), one per coordinate of the system; "
                 r"got 1", id="too-few"),
    pytest.param([0.1, 0.2, 0.3], {"L": 1.0}, ArgumentError, "`q` must give 2 values",
                 id="too-many"),
    pytest.param([0.1, np.nan], {"L": 1.0}, ArgumentError, "`q` must be finite", id="nan"),
    pytest.param({"theta1": 0.1}, {"L": 1.0}, ArgumentError,
                 "`q` must give every coordinate; missing theta2", id="dict-missing"),
    pytest.param([0.1, 0.2], {}, ArgumentError,
                 r"`params` must give a value to every constant the positions depend on; "
                 r"missing L\. Pass params=\{'L': \.\.\.\}", id="missing-L"),
    pytest.param([0.1, 0.2], {"L": 1.0, "Lx": 2.0}, ArgumentError,
                 "`params` names 'Lx', which is not a constant of the system", id="unknown"),
    pytest.param([0.1, 0.2], {"L": "long"}, ArgumentError, "`params` must give numbers",
                 id="not-a-number"),
    pytest.param([0.1, 0.2], [1.0], ArgumentTypeError, "`params` must be a dict",
                 id="params-type"),
])
def test_bad_input(q, params, error, match):
    with pytest.raises(error, match=match):
        place(models.double_pendulum(), q, params)


def test_not_a_system():
    with pytest.raises(ArgumentTypeError, match="`system` must be a rigidmech System"):
        Placer("double pendulum")


def test_ambiguous_or_unknown_point_name():
    p = place(models.double_pendulum(), [0.0, 0.0], {"L": 1.0})
    with pytest.raises(ArgumentError, match="`point` must name one point"):
        p.point("Z")


@pytest.mark.parametrize("rows, dim, match", [
    pytest.param([[1, 0, 0], [0, 1, 0], [0, 0, 1.001]], 2, "`rows` must be an orthonormal",
                 id="not-unit"),
    pytest.param([[1, 0, 0], [0, 1, 0]], 2, "`rows` must be an orthonormal", id="shape"),
    pytest.param(np.eye(3), 4, "`dim` must be 2 or 3; got 4", id="dim"),
])
def test_view_bad_input(rows, dim, match):
    with pytest.raises(ArgumentError, match=match):
        View(rows, dim)


def test_view_orthonormality_tolerance():
    # |R R^T - I| <= 1e-9 entrywise: a rotation computed in floating point passes
    c, s = np.cos(0.3), np.sin(0.3)
    View([[c, -s, 0], [s, c, 0], [0, 0, 1]], 2)
    View(np.diag([1 + 4.9e-10, 1, 1]), 2)                    # (1 + e)^2 - 1 = 0.98e-9
    with pytest.raises(ArgumentError):
        View(np.diag([1 + 5.1e-10, 1, 1]), 2)                # 1.02e-9
