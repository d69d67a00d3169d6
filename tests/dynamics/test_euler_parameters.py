"""Euler parameters: a free body oriented without singular set (book, ch. 9.1.2, 18.4).

References, independent of rigidmech's derivation:

* scipy.spatial.transform.Rotation.from_quat (scalar last, normalising) for the direction
  cosines;
* sympy's Quaternion algebra for the rotation vector of the unit quaternion p = e / |e|:
  omega (body basis) = 2 vec(conj(p) * p'), differentiated once more for omega';
* Euler's equations of a free body (the moment of gravity about G is zero, ch. 18.4):
  J omega' + omega x J omega = 0 with J = diag(A, B, C), and m a(G) = m g.
"""

import warnings

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation
from sympy.algebras.quaternion import Quaternion

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, SingularityWarning
from rigidmech.inertia import InertiaOperator
from rigidmech.vectors import euler_parameter_rates, euler_parameters_of, partial_rotation_vector

PARAMS = dict(m=1.3, g=9.81, A=1.0, B=2.0, C=2.5)


def free_body(frame_of):
    """Free body of mass m, principal moments A, B, C at G, under gravity -g k0."""
    x, y, z = rm.coordinates("x y z")
    m, g, A, B, C = rm.constants("m g A B C", positive=True)
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, z)
    R = frame_of(R0, G)
    body = rm.Body("body", frame=R, mass=m, centre=G,
                   inertia=InertiaOperator.from_products(A, B, C, frame=R, at=G))
    system = rm.System(galilean=R0)
    system.add(body)
    system.act(rm.gravity(-g * R0.k))
    return system


@pytest.fixture(scope="module")
def quaternion_eqs():
    e = rm.coordinates("e0 e1 e2 e3")
    return free_body(lambda R0, G: R0.euler_parameters("R", *e, origin=G)) \
        .equations_of_motion()


def test_direction_cosines_match_scipy():
    """Columns of dcm(R0 <- R) against scipy's matrix of the normalised quaternion, for
    parameters of any length (the orientation depends on the direction of e only)."""
    e = rm.coordinates("e0 e1 e2 e3")
    R0 = rm.Frame("R0")
    R = R0.euler_parameters("R", *e)
    assert euler_parameters_of(R) == e and euler_parameters_of(R0) is None
    assert R.singular_set() is None
    f = sp.lambdify([e], R0.dcm(R), "numpy")
    rng = np.random.default_rng(11)
    for _ in range(10):
        v = rng.normal(size=4) * rng.uniform(0.2, 3.0)
        expected = Rotation.from_quat([v[1], v[2], v[3], v[0]]).as_matrix()
        assert_allclose(np.array(f(v), dtype=float), expected, rtol=0, atol=1e-14)


def test_rates_from_rotation_vector():
    """e' = (1/2) e * (0, omega): omega recovered from scipy's matrices along e + h e'
    (central differences, h = 1e-6), and e . e' = 0."""
    rng = np.random.default_rng(12)
    for _ in range(5):
        e = rng.normal(size=4)
        e /= np.linalg.norm(e)
        w = rng.normal(size=3)
        ed = euler_parameter_rates(e, w)
        h = 1e-6

        def matrix(v):
            return Rotation.from_quat([v[1], v[2], v[3], v[0]]).as_matrix()

        W = matrix(e).T @ (matrix(e + h * ed) - matrix(e - h * ed)) / (2 * h)
        assert_allclose([W[2, 1], W[0, 2], W[1, 0]], w, rtol=0, atol=1e-8)
        assert abs(e @ ed) < 1e-15
    with pytest.raises(ArgumentError, match="`e` must give 4 numbers and `omega` 3"):
        euler_parameter_rates([1, 0, 0], [0, 0, 1])


def _euler_equations_residual():
    """J omega' + omega x J omega as a function of (e, e', e'', A, B, C), with omega the
    rotation vector of p = e / |e| from sympy's quaternion algebra."""
    t = sp.Symbol("t")
    E = [sp.Function(f"E{i}")(t) for i in range(4)]
    norm = sp.sqrt(sum(x**2 for x in E))
    p = Quaternion(*[x / norm for x in E])
    pd = Quaternion(*[sp.diff(x / norm, t) for x in (E[0], E[1], E[2], E[3])])
    prod = p.conjugate() * pd
    omega = sp.Matrix([2 * prod.b, 2 * prod.c, 2 * prod.d])
    omega_dot = omega.diff(t)
    A, B, C = sp.symbols("A B C")
    J = sp.diag(A, B, C)
    residual = J * omega_dot + omega.cross(J * omega)
    e, ed, edd = (sp.symbols(f"{s}0:4") for s in ("e", "ed", "edd"))
    rule = {}
    for i in range(4):
        rule[E[i].diff(t, 2)] = edd[i]
        rule[E[i].diff(t)] = ed[i]
        rule[E[i]] = e[i]
    residual = residual.subs(rule)
    scale = (J * omega).subs(rule)
    return sp.lambdify([e, ed, edd, A, B, C], [residual, omega.subs(rule), scale], "numpy")


def test_free_body_accelerations_satisfy_euler_equations(quaternion_eqs):
    """At random states (e of any length, e' with any radial part) the q'' of the equations
    satisfies Euler's equations (residual below 1e-10 of the terms' scale), keeps |e|
    (e . e'' = -e' . e') and gives the mass centre the acceleration g."""
    eqs = quaternion_eqs
    names = [q.func.__name__ for q in eqs.coordinates]
    ie = [names.index(f"e{i}") for i in range(4)]
    ix = [names.index(c) for c in "xyz"]
    residual = _euler_equations_residual()
    rhs = eqs.rhs(**PARAMS)
    rng = np.random.default_rng(13)
    n = len(names)
    for _ in range(8):
        y = rng.normal(size=2 * n)
        y[ie] *= rng.uniform(0.3, 3.0)
        qdd = rhs(0.0, y)[n:]
        e, ed, edd = y[ie], y[n:][ie], qdd[ie]
        r, omega, Jw = (np.array(v, dtype=float).ravel() for v in residual(
            e, ed, edd, PARAMS["A"], PARAMS["B"], PARAMS["C"]))
        scale = np.linalg.norm(omega) * np.linalg.norm(Jw) + 1.0
        assert np.max(np.abs(r)) < 1e-10 * scale
        assert abs(e @ edd + ed @ ed) < 1e-10 * (ed @ ed + 1.0)
        assert_allclose(qdd[ix], [0.0, 0.0, -PARAMS["g"]], rtol=0, atol=1e-12)


def test_tumbling_through_the_euler_pole(quaternion_eqs):
    """A body turning about its principal axis i0 at 2 rad/s from a tilt of 0.3 rad: its
    axis k passes through -k0 at t = (pi - 0.3)/2 (sin(theta) = 0 for Euler angles, where
    the z-x-z model warns). With Euler parameters: no warning, the exact motion (rotation
    by 0.3 + 2 t about i0) to 1e-9, |e| = 1 and the energy kept to 1e-10."""
    eqs = quaternion_eqs
    assert eqs.singular_sets == ()
    names = [q.func.__name__ for q in eqs.coordinates]
    a0, w = 0.3, 2.0
    e0 = np.array([np.cos(a0 / 2), np.sin(a0 / 2), 0.0, 0.0])
    start = dict(zip(("e0", "e1", "e2", "e3"), e0, strict=True))
    rates = dict(zip(("e0", "e1", "e2", "e3"), euler_parameter_rates(e0, [w, 0, 0]),
                     strict=True))
    q0 = [start.get(k, 0.0) for k in names]
    u0 = [rates.get(k, 0.0) for k in names]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sim = eqs.simulate(t=(0.0, 3.0), q0=q0, u0=u0, rtol=1e-12, atol=1e-12, **PARAMS)
    ie = [names.index(f"e{i}") for i in range(4)]
    e = sim.q[ie]
    alpha = a0 + w * sim.t
    exact = np.array([np.cos(alpha / 2), np.sin(alpha / 2), 0 * alpha, 0 * alpha])
    assert_allclose(e, exact, rtol=0, atol=1e-9)
    assert np.max(np.abs(np.linalg.norm(e, axis=0) - 1.0)) < 1e-10
    assert sim.energy_drift() < 1e-10

    # the same motion in Euler angles z-x-z (psi = phi = 0, theta = 0.3 + 2 t) warns
    psi, theta, phi = rm.coordinates("psi theta phi")
    euler = free_body(lambda R0, G: R0.euler("R", psi, theta, phi, origin=G)) \
        .equations_of_motion()
    names = [q.func.__name__ for q in euler.coordinates]
    with pytest.warns(SingularityWarning, match="sin\\(theta\\) = 0"):
        euler.simulate(t=(0.0, 3.0), q0=[a0 if k == "theta" else 0.0 for k in names],
                       u0=[w if k == "theta" else 0.0 for k in names], **PARAMS)


def test_rotation_vector_of_euler_parameters_in_closed_form(monkeypatch):
    """omega(R/R0) of a frame on Euler parameters is written in closed form,
    2 vec(conj(e) * e') / |e|^2 in the basis of R, without ``sympy.simplify`` of C^T C' (that
    simplify took 86 % of the derivation of a ball on a turntable); its value equals the
    rotation vector 2 vec(conj(p) * p') of p = e / |e| from sympy's quaternion algebra, and the
    partial rotation vectors its derivatives with respect to the rates, at random e of any
    length and any e' (radial part included)."""
    e = rm.coordinates("e0 e1 e2 e3")
    R0 = rm.Frame("R0")
    R = R0.euler_parameters("R", *e)

    def refuse(*args, **kwargs):
        raise AssertionError("sympy.simplify called for the rotation vector")

    monkeypatch.setattr(sp, "simplify", refuse)
    omega = R.rotation_vector(R0).components(R)
    partials = [partial_rotation_vector(R, R0, x).components(R) for x in e]
    monkeypatch.undo()

    t = rm.t
    norm = sp.sqrt(sum(x**2 for x in e))
    p = Quaternion(*[x / norm for x in e])
    pd = Quaternion(*[sp.diff(x / norm, t) for x in e])
    prod = p.conjugate() * pd
    reference = sp.Matrix([2 * prod.b, 2 * prod.c, 2 * prod.d])
    v, vd = sp.symbols("v0:4"), sp.symbols("vd0:4")
    rule = {x.diff(t): s for x, s in zip(e, vd, strict=True)}
    rule |= dict(zip(e, v, strict=True))
    ours = sp.lambdify([v, vd], [omega.subs(rule), *[P.subs(rule) for P in partials]], "numpy")
    theirs = sp.lambdify([v, vd], [reference.subs(rule),
                                   *[reference.diff(x.diff(t)).subs(rule) for x in e]], "numpy")
    rng = np.random.default_rng(21)
    for _ in range(10):
        ev = rng.normal(size=4) * rng.uniform(0.3, 3.0)
        edv = rng.normal(size=4)
        for a, b in zip(ours(ev, edv), theirs(ev, edv), strict=True):
            assert_allclose(np.array(a, dtype=float).ravel(), np.array(b, dtype=float).ravel(),
                            rtol=0, atol=1e-13 * (1 + np.max(np.abs(np.array(b, dtype=float)))))
