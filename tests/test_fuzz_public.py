"""Fuzz the public constructors (issue 9): any input gives a result or a rigidmech error.

Never another exception type (a ``TypeError`` from deep inside sympy, a ``KeyError``...), never a
hang, never a non-finite number returned as success. Arguments are drawn from a pool of values
of every kind a user may pass by mistake (strings, nan, inf, complex numbers, None, bools,
lists, vectors where points are expected, frames of another tree...) mixed with valid ones, so
that every check is reached and the valid paths still run. Bounded: few examples per test,
simulations over tiny spans; the whole file runs in well under a minute.
"""

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rigidmech as rm
from rigidmech.errors import RigidmechError

FUZZ = settings(max_examples=60, deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])

q1, q2 = rm.coordinates("q1 q2")
m, L, g = rm.constants("m L g", positive=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=q1)
OTHER = rm.Frame("Other")
A = R0.point("A", L, 0, 0)
G1 = R0.origin.moved("G1", L * R1.i)

NUMBERS = [0, 1, -1, 2.5, -0.0, 1e-300, 1e300, math.nan, math.inf, -math.inf, 1 + 2j, 1j,
           np.float64(0.5), np.float64(math.nan), np.int64(3), sp.Rational(1, 3), sp.pi,
           sp.nan, sp.oo, sp.zoo, sp.I]
SYMBOLIC = [m, L, g, q1, sp.Symbol("x"), sp.Symbol("neg", negative=True), sp.sin(q1)]
JUNK = ["heavy", "", "q", None, True, False, [1, 2], (1, 2, 3), {"a": 1}, object(),
        np.array([1.0, 2.0])]
GEOMETRY = [R0, R1, OTHER, R0.i, R1.j, OTHER.k, R0.i + R0.j, 0 * R0.i, A, G1, R0.origin,
            OTHER.origin]
ANY = NUMBERS + SYMBOLIC + JUNK + GEOMETRY

anything = st.sampled_from(ANY)
scalars = st.sampled_from(NUMBERS + SYMBOLIC + JUNK[:5])
names = st.sampled_from(["R", "S", "", None, 3, "R0", "R1"])


def call(fn, *args, **kwargs):
    """Run ``fn``: a result, or a rigidmech error; anything else fails the test."""
    try:
        return fn(*args, **kwargs)
    except RigidmechError:
        return None


@FUZZ
@given(name=names, about=anything, angle=scalars, origin=anything)
def test_frames(name, about, angle, origin):
    call(R0.rotated, name, about=about, angle=angle, origin=origin)
    call(R0.euler, name, angle, angle, angle, origin=origin)
    call(R0.translated, name, origin)
    call(R0.point, name, angle, 0, angle)
    call(R0.vector, angle, angle, 0)
    call(rm.Frame, name)


@FUZZ
@given(name=names, frame=anything, mass=scalars, centre=anything, inertia=st.sampled_from(
    [None, "J", 3, rm.inertia.rod(m, L, axis=R1.i), rm.inertia.sphere(1, 1, frame=R0)]))
def test_bodies(name, frame, mass, centre, inertia):
    call(rm.Body, name, frame=frame, mass=mass, centre=centre, inertia=inertia)


CATALOGUE = [
    (rm.inertia.rod, ("mass", "length"), "axis"),
    (rm.inertia.ring, ("mass", "radius"), "axis"),
    (rm.inertia.disk, ("mass", "radius"), "axis"),
    (rm.inertia.cylinder, ("mass", "radius", "length"), "axis"),
    (rm.inertia.cone, ("mass", "radius", "height"), "axis"),
    (rm.inertia.sphere, ("mass", "radius"), "frame"),
    (rm.inertia.spherical_shell, ("mass", "radius"), "frame"),
    (rm.inertia.block, ("mass", "a", "b", "c"), "frame"),
]


@FUZZ
@given(entry=st.sampled_from(CATALOGUE), values=st.lists(scalars, min_size=4, max_size=4),
       where=anything, centre=anything, to=anything)
def test_inertia_catalogue(entry, values, where, centre, to):
    fn, params, keyword = entry
    J = call(fn, *values[:len(params)], **{keyword: where, "centre": centre})
    if J is not None:
        call(J.moved, to, mass=values[0], centre=centre)
        call(J.in_basis, where)
        call(J.apply, where)
    call(rm.InertiaOperator.from_products, *values[:3], frame=where)
    call(rm.InertiaOperator.from_matrix, values, frame=where)


@FUZZ
@given(kind=st.sampled_from(["Pivot", "Prismatic", "Cylindrical", "Spherical"]), at=anything,
       axis=anything)
def test_joints(kind, at, axis):
    cls = getattr(rm.joints, kind)
    if kind == "Spherical":
        call(cls, at=at)
    else:
        call(cls, at=at, axis=axis)


BOB = rm.Body("bob", frame=R1, mass=m, centre=G1)


@FUZZ
@given(on=st.sampled_from([BOB, None, R0, "bob", 3]), vector=anything, at=anything,
       k=scalars, l0=scalars)
def test_actions(on, vector, at, k, l0):
    call(rm.Force, on=on, vector=vector, at=at)
    call(rm.Couple, on=on, moment=vector, reaction_on=on)
    call(rm.Spring, k, l0, a=at, b=at, on_a=on, on_b=on)
    call(rm.gravity, vector)


def _parts():
    x = rm.coordinates("x")
    R2 = R0.translated("R2", R0.point("P", x, 0, 0))
    cart = rm.Body("cart", frame=R2, mass=2)
    bob = rm.Body("bob", frame=R1, mass=m, centre=G1,
                  inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G1))
    massless = rm.Body("link", frame=R0.rotated("R3", about=R0.k, angle=q2))
    joints = [rm.joints.Pivot(at=R0.origin, axis=R0.k), rm.joints.Prismatic(at=R2.origin,
              axis=R0.i), rm.joints.Spherical(at=R0.origin), rm.joints.Pivot(at=A, axis=R0.i)]
    actions = [rm.gravity(g * R0.i), rm.gravity(-9.81 * R0.j),
               rm.Force(on=bob, vector=R0.j, at=G1), rm.Couple(on=cart, moment=R0.k),
               rm.Spring(3, 0.5, a=R0.origin, b=R2.origin, on_b=cart)]
    return [cart, bob, massless], joints, actions


@FUZZ
@given(steps=st.lists(st.tuples(st.sampled_from(["connect", "add", "act"]),
                                st.integers(0, 3), st.integers(0, 3), st.integers(0, 4)),
                      max_size=5),
       galilean=st.sampled_from([R0, R1, OTHER, "R0"]))
def test_systems_and_equations(steps, galilean):
    bodies, joints, actions = _parts()
    system = call(rm.System, galilean=galilean)
    if system is None:
        return
    for op, a, b, c in steps:
        parent = R0 if a == 3 else bodies[a]
        if op == "connect":
            call(system.connect, parent, bodies[b % 3], joints[c % 4])
        elif op == "add":
            call(system.add, bodies[b % 3])
        else:
            call(system.act, actions[c])
    eqs = call(system.equations_of_motion)
    if eqs is not None:
        assert eqs.mass_matrix.shape == (len(eqs.q), len(eqs.q))


def _pendulum():
    bob = rm.Body("bob", frame=R1, mass=m, centre=G1,
                  inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G1))
    system = rm.System(galilean=R0)
    system.connect(R0, bob, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    system.act(rm.gravity(g * R0.i))
    return system.equations_of_motion()


EQS = _pendulum()
FLOATS = [0.0, 0.3, -1.0, 1e-3, 1e3, math.nan, math.inf, -math.inf, 1j, "1", None, [0.1]]


@FUZZ
@given(q0=st.sampled_from([[0.3], [math.nan], [math.inf], ["a"], [1j], [], [0.1, 0.2], None,
                           0.3, "q"]),
       u0=st.sampled_from([None, [0.0], [math.nan], ["b"], [0.0, 1.0], 2.0]),
       span=st.sampled_from([(0.0, 0.01), (0.0, -0.01), (0.0, 0.0), (0.0, math.nan),
                             (0.0, math.inf), ("0", 1), (0.0,), 1.0, None]),
       values=st.lists(st.sampled_from(FLOATS), min_size=3, max_size=3),
       method=st.sampled_from(["dop853", "rk4", "radau", "nope", 3, None]),
       n_output=st.sampled_from([5, 0, -1, 2.5, "many"]))
def test_simulate_small_spans(q0, u0, span, values, method, n_output):
    params = dict(zip(("m", "L", "g"), values, strict=True))
    kwargs = {"step": 0.005} if method == "rk4" else {}
    sim = call(EQS.simulate, t=span, q0=q0, u0=u0, method=method, n_output=n_output,
               **kwargs, **params)
    if sim is not None:
        # a success is finite, or it is not a success
        assert np.isfinite(sim.q).all() and np.isfinite(sim.u).all()
        assert np.isfinite(sim.t).all()


@pytest.mark.parametrize("value", [math.nan, math.inf])
def test_simulate_non_finite_parameter_is_an_error(value):
    # regression for the fuzz findings: a nan parameter used to give a nan motion as success
    with pytest.raises(RigidmechError, match=r"`g` must be a finite real number; got "):
        EQS.simulate(t=(0.0, 0.01), q0=[0.3], m=1.0, L=1.0, g=value)


@FUZZ
@given(parent=anything, child=anything, joint=st.sampled_from(
    [None, "pivot", 3, rm.joints.Pivot(at=R0.origin, axis=R0.k), rm.joints.Spherical(at=A)]),
    action=anything)
def test_system_methods_with_junk(parent, child, joint, action):
    system = rm.System(galilean=R0)
    call(system.connect, parent, child, joint)
    call(system.add, child)
    call(system.act, action)
    call(system.connection_action, parent, child)


@settings(max_examples=12, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(steps=st.lists(st.tuples(st.sampled_from(["connect", "add", "act"]),
                                st.integers(0, 3), st.integers(0, 3), st.integers(0, 4)),
                      min_size=1, max_size=4),
       state=st.sampled_from([0.0, 0.3, -2.0, 1e3]))
def test_random_systems_simulate_or_raise(steps, state):
    # a massless link with its own coordinate makes a singular mass matrix: that must be a
    # SingularMassMatrixError, never a motion
    bodies, joints, actions = _parts()
    system = rm.System(galilean=R0)
    for op, a, b, c in steps:
        parent = R0 if a == 3 else bodies[a]
        if op == "connect":
            call(system.connect, parent, bodies[b % 3], joints[c % 4])
        elif op == "add":
            call(system.add, bodies[b % 3])
        else:
            call(system.act, actions[c])
    eqs = call(system.equations_of_motion)
    if eqs is None:
        return
    n = len(eqs.q)
    params = {p.name: 1.0 for p in eqs.parameters}
    sim = call(eqs.simulate, t=(0.0, 1e-3), q0=[state] * n, u0=[0.1] * n, n_output=3,
               **params)
    if sim is not None:
        assert np.isfinite(sim.q).all() and np.isfinite(sim.u).all()
