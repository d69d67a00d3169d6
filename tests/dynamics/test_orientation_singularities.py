"""Simulations near the singular set of Euler angles warn (book, ch. 9.1.2; issue 9).

Euler angles z-x-z are singular where sin(theta) = 0: there the rotation vector
psi' k0 + theta' u + phi' k does not determine psi' and phi' separately, the mass matrix of a
body oriented by them is singular, and near it the integration needs many small steps and
loses accuracy. A simulation that comes within ``NEAR`` (|sin(theta)| < 1e-2) of the set warns
with a :class:`SingularityWarning` naming the frame, the time and the distance; one that stays
away does not.
"""

import re
import warnings

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import models, scenes
from rigidmech._core.errors import (
    RigidmechWarning,
    SingularityWarning,
    SingularMassMatrixError,
)
from rigidmech.inertia import InertiaOperator

TOP = dict(m=1.0, g=9.81, l=0.3, A=0.05, C=0.02)


def heavy_top():
    """Symmetric heavy top: fixed point O, mass centre at l on its axis R.k, gravity -g k0,
    moments A (about axes through G normal to the axis) and C (about the axis): the
    catalogue's :func:`rigidmech.models.heavy_top`."""
    return models.heavy_top().system


def free_body():
    """Free asymmetric body (moments A, 1.5 A, C) under gravity; Euler angles z-x-z."""
    x, y, z, psi, theta, phi = rm.coordinates("x y z psi theta phi")
    m, g, A, C = rm.constants("m g A C", positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, z)
    R = R0.euler("R", psi, theta, phi, origin=G)
    body = rm.Body("body", frame=R, mass=m, centre=G,
                   inertia=InertiaOperator.from_products(A, 1.5 * A, C, frame=R, at=G))
    system = rm.System(galilean=R0)
    system.add(body)
    system.act(rm.gravity(-g * R0.k))
    return system


@pytest.fixture(scope="module")
def top_eqs():
    return heavy_top().equations_of_motion()


@pytest.fixture(scope="module")
def free_eqs():
    return free_body().equations_of_motion()


def _state(eqs, **values):
    return [values.get(q.func.__name__, 0.0) for q in eqs.coordinates]


def _warning_fields(message):
    """(time, measure) from a SingularityWarning's message."""
    m = re.search(r"at t = ([-+0-9.e]+) \(measure ([-+0-9.e]+) < ", message)
    return float(m.group(1)), float(m.group(2))


def test_singular_sets_of_the_equations(top_eqs, free_eqs):
    for eqs in (top_eqs, free_eqs):
        (s,) = eqs.singular_sets
        assert s.frame.name == "R" and s.relative_to.name == "R0"
        assert s.condition == sp.Eq(sp.sin(rm.coordinates("theta")), 0)


def test_planar_and_relative_chains():
    """Planar chains have no singular set; a body oriented by Euler angles relative to
    another body's frame is judged relative to that frame, not to the root."""
    assert scenes.get("double-pendulum").build().system.equations_of_motion() \
        .singular_sets == ()
    q = rm.coordinates("p1 t1 s1 p2 t2 s2")
    m = rm.constants("m")
    R0 = rm.Frame("R0")
    R1 = R0.euler("R1", *q[:3])
    R2 = R1.euler("R2", *q[3:])
    A = R0.origin.moved("A", R1.k)
    b1 = rm.Body("b1", frame=R1, mass=m, centre=R0.origin.moved("G1", R1.k / 2),
                 inertia=InertiaOperator.from_products(1, 1, 2, frame=R1))
    b2 = rm.Body("b2", frame=R2, mass=m, centre=A.moved("G2", R2.k / 2),
                 inertia=InertiaOperator.from_products(1, 1, 2, frame=R2))
    system = rm.System(galilean=R0)
    system.connect(R0, b1, rm.joints.Spherical(at=R0.origin))
    system.connect(b1, b2, rm.joints.Spherical(at=A))
    sets = system.equations_of_motion().singular_sets
    assert [(s.frame.name, s.relative_to.name, s.condition) for s in sets] == [
        ("R1", "R0", sp.Eq(sp.sin(q[1]), 0)), ("R2", "R1", sp.Eq(sp.sin(q[4]), 0))]


def test_free_body_released_near_the_pole_warns(free_eqs):
    """Released at theta = 1e-3 and spinning about its axis: theta stays near 1e-3."""
    eqs = free_eqs
    with pytest.warns(SingularityWarning) as record:
        eqs.simulate(t=(0.0, 2.0), q0=_state(eqs, theta=1e-3, psi=0.1, phi=0.2),
                     u0=_state(eqs, phi=5.0, psi=0.3), m=1.0, g=9.81, A=1.0, C=2.0)
    (w,) = record
    message = str(w.message)
    assert message.startswith("the angles z-x-z (psi, theta, phi) of frame R relative to R0, "
                              "singular where sin(theta) = 0; the motion comes within")
    assert "Use a Cardan sequence such as z-x-y" in message
    when, measure = _warning_fields(message)
    assert 0.0 <= when <= 2.0 and measure < 1e-2
    assert isinstance(w.message, RigidmechWarning) and isinstance(w.message, RuntimeWarning)
    assert w.filename == __file__  # attributed to the caller, not to rigidmech


def test_free_body_far_from_the_pole_is_silent(free_eqs):
    eqs = free_eqs
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        eqs.simulate(t=(0.0, 2.0), q0=_state(eqs, theta=1.0, psi=0.1, phi=0.2),
                     u0=_state(eqs, phi=5.0, psi=0.3), m=1.0, g=9.81, A=1.0, C=2.0)


def test_sleeping_top_near_vertical_warns_and_tilted_top_does_not(top_eqs):
    """A fast top released 2e-3 rad from the upward vertical stays near it (sleeping top);
    released at 0.5 rad with the same spin it precesses with theta near 0.5."""
    eqs = top_eqs
    with pytest.warns(SingularityWarning, match=r"of frame R relative to R0.* at t = "):
        eqs.simulate(t=(0.0, 1.0), q0=_state(eqs, theta=2e-3), u0=_state(eqs, phi=200.0),
                     **TOP)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sim = eqs.simulate(t=(0.0, 1.0), q0=_state(eqs, theta=0.5), u0=_state(eqs, phi=200.0),
                           **TOP)
    theta = sim.q[[q.func.__name__ for q in eqs.coordinates].index("theta")]
    assert np.min(np.abs(np.sin(theta))) > 0.4


def test_fast_passage_between_two_samples_is_seen(top_eqs):
    """A top without spin thrown over its upward vertical, recorded at three times only:
    the closest approach (found on a record of 20001 samples 1e-5 s apart) falls between
    samples, and the warning still reports it from the dense output: its time within 1e-4 s
    and its measure between the fine record's minimum minus the change over one fine sample
    (the true minimum lies between two fine samples) and that minimum."""
    eqs = top_eqs
    q0, u0 = _state(eqs, theta=0.5), _state(eqs, psi=0.02, theta=-6.0)
    row = [q.func.__name__ for q in eqs.coordinates].index("theta")
    with pytest.warns(SingularityWarning):
        fine = eqs.simulate(t=(0.0, 0.2), q0=q0, u0=u0, n_output=20001, rtol=1e-11,
                            atol=1e-12, **TOP)
    m = np.abs(np.sin(fine.q[row]))
    k = int(np.argmin(m))
    assert 1e-4 < m[k] < 1e-2 and 0.01 < fine.t[k] < 0.19
    step = max(abs(m[k + 1] - m[k]), abs(m[k - 1] - m[k]))
    with pytest.warns(SingularityWarning) as record:
        coarse = eqs.simulate(t=(0.0, 0.2), q0=q0, u0=u0, n_output=3, rtol=1e-11,
                              atol=1e-12, **TOP)
    assert np.min(np.abs(np.sin(coarse.q[row]))) > 1e-2  # the samples alone miss it
    when, measure = _warning_fields(str(record[0].message))
    assert abs(when - fine.t[k]) < 1e-4
    assert m[k] - step - 1e-9 <= measure <= m[k] + 1e-9


def test_scene_pipeline_warns():
    """The scenes pipeline (``scenes.run``) goes through the same check."""
    names = [q.func.__name__ for q in heavy_top().coordinates]
    scene = scenes.Scene(
        "test-top", "Heavy top (test)", "ch. 9.1.2", coordinates=names,
        parameters=[(k, v, k) for k, v in TOP.items()],
        q0=[2e-3 if n == "theta" else 0.0 for n in names],
        u0=[200.0 if n == "phi" else 0.0 for n in names], t_end=0.5, rtol=1e-8, atol=1e-10,
        builder=lambda: scenes.Built(heavy_top(), ()))
    with pytest.warns(SingularityWarning, match="frame R"):
        scenes.run(scene)


@pytest.mark.parametrize("C", [2.0, 0.3, 0.7])
def test_right_hand_side_on_the_singular_set_raises(free_eqs, C):
    """Exactly at theta = 0 with theta' != 0, psi'' and phi'' are not determined (only their
    sum is): the right-hand side must raise, not return a finite number."""
    eqs = free_eqs
    y = np.array(_state(eqs, psi=0.1, theta=0.0, phi=0.2)
                 + _state(eqs, psi=0.3, theta=0.5, phi=5.0))
    with pytest.raises(SingularMassMatrixError, match="singular"):
        eqs.rhs(m=1.0, g=9.81, A=1.0, C=C)(0.0, y)


def test_lagrange_route_knows_the_singular_sets_too():
    """``rm.lagrange_equations`` gives equations that warn the same way."""
    system = heavy_top()
    assert [s.condition for s in system.orientation_singularities()] == [
        sp.Eq(sp.sin(rm.coordinates("theta")), 0)]
    eqs = rm.lagrange_equations(system)
    assert eqs.singular_sets == system.orientation_singularities()
    with pytest.warns(SingularityWarning, match="frame R relative to R0"):
        eqs.simulate(t=(0.0, 0.2), q0=_state(eqs, theta=2e-3), u0=_state(eqs, phi=200.0),
                     **TOP)
