"""A uniform ball on Euler parameters rolling without slipping on a turntable driven at the
constant rate Omega about the vertical (book, ch. 9.1.2, 10.1.3, 25.3): the catalogue's
:func:`rigidmech.models.ball_on_turntable` (the table a body whose frame turns by Omega t),
the model ``benchmarks/derive_ball_turntable.py`` times.

References, independent of rigidmech's derivation:

* sympy.physics.mechanics.KanesMethod on the same ball (sympy's "Quaternion" orientation,
  the body components of the rotation vector independent speeds, the velocity of the centre
  dependent; in the benchmark's file): the same q'' at random states on the conditions;
* the classical closed form: with the friction F at the contact, m v' = F and
  (2/5) m r^2 omega' = -r k ^ F; the derivative of the no-slip condition
  v + omega ^ (-r k) = Omega k ^ rho (rho the horizontal position of the centre) gives
  v' + (5/2) v' = Omega k ^ v, so v' = (2/7) Omega k ^ v: the velocity of the centre turns at
  lambda = 2 Omega / 7 and the centre runs on a circle in the inertial frame,
  z(t) = z0 + v0 (exp(i lambda t) - 1) / (i lambda) in complex notation z = x + i y.
"""

import importlib.util
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

from rigidmech import models
from rigidmech.vectors import euler_parameter_rates

_PATH = Path(__file__).resolve().parents[2] / "benchmarks" / "derive_ball_turntable.py"
TIGHT = dict(rtol=1e-12, atol=1e-12)


@pytest.fixture(scope="module")
def bench():
    spec = importlib.util.spec_from_file_location("derive_ball_turntable", _PATH)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def equations():
    return models.ball_on_turntable().system.equations_of_motion()


def test_ball_on_turntable_matches_kanes_method(bench, equations):
    """q'' (x'', y'', e'') equal KanesMethod's at 5 random states on the conditions (unit e,
    e' from the rotation vector, the velocity of the centre from the no-slip conditions),
    relative difference below 1e-12."""
    assert [q.func.__name__ for q in equations.coordinates] == ["x", "y", "e0", "e1", "e2",
                                                                 "e3"]
    rhs = equations.rhs(**bench.PARAMS)
    for y, expected in bench.kane_accelerations(seed=3):
        got = rhs(0.0, y)[6:]
        assert np.max(np.abs(got - expected)) < 1e-12 * np.max(np.abs(expected))


def test_ball_on_turntable_circles_at_two_sevenths_of_omega(bench, equations):
    """From (x, y) = (0.5, -0.2), e = (cos 0.2, sin 0.2, 0, 0), omega = (0.7, -1.1, 0.4) in
    the ball's basis and v from the no-slip condition, the centre follows
    z0 + v0 (exp(i lambda t) - 1) / (i lambda), lambda = 2 Omega / 7, to 1e-8 over 8 s (more
    than half a turn of the circle); |e| stays 1 to 1e-9."""
    p = bench.PARAMS
    r, W = p["r"], p["Omega"]
    pos = np.array([0.5, -0.2])
    e = np.array([np.cos(0.2), np.sin(0.2), 0.0, 0.0])
    w = np.array([0.7, -1.1, 0.4])
    wi = bench._dcm(e) @ w
    v = W * np.array([-pos[1], pos[0], 0.0]) - np.cross(wi, [0.0, 0.0, -r])
    ed = euler_parameter_rates(e, w)
    q0 = dict(zip(("x", "y", "e0", "e1", "e2", "e3"), [*pos, *e], strict=True))
    u0 = dict(zip(("x", "y", "e0", "e1", "e2", "e3"), [*v[:2], *ed], strict=True))
    sim = equations.simulate(t=(0.0, 8.0), q0=q0, u0=u0, n_output=81, **TIGHT, **p)
    lam = 2 * W / 7
    z = (pos[0] + 1j * pos[1]) + (v[0] + 1j * v[1]) * (np.exp(1j * lam * sim.t) - 1) / (
        1j * lam)
    assert_allclose(sim.q[0], z.real, rtol=0, atol=1e-8)
    assert_allclose(sim.q[1], z.imag, rtol=0, atol=1e-8)
    assert np.max(np.abs(np.linalg.norm(sim.q[2:6], axis=0) - 1.0)) < 1e-9
