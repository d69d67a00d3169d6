"""Composite bodies and mass properties of domains (ch. 12.3, 15.2.2, 15.4.4)."""

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

import rigidmech as rm
from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.inertia import (
    Part,
    block,
    composite,
    cone,
    cylinder,
    hemisphere,
    mass_properties,
    point_mass,
    sphere,
)


def _matrix_in(op, frame):
    """Matrix of a part's operator in ``frame``'s basis by P J P^T, with P built from the
    components of the part frame's basis vectors (independent of in_basis)."""
    pf = op.frame
    P = np.array([[float(x) for x in v.components(frame)] for v in (pf.i, pf.j, pf.k)]).T
    return P @ np.array(op.matrix.tolist(), dtype=float) @ P.T


def _huygens(m, d):
    d = np.asarray(d, dtype=float)
    return m * (d @ d * np.eye(3) - np.outer(d, d))


parts_strategy = st.lists(
    st.tuples(st.sampled_from(["block", "cylinder", "sphere", "point"]),
              st.floats(0.1, 5.0), st.lists(st.floats(-2, 2), min_size=3, max_size=3),
              st.lists(st.floats(-3, 3), min_size=2, max_size=2),
              st.lists(st.floats(0.1, 1.5), min_size=3, max_size=3)),
    min_size=1, max_size=4)


@settings(max_examples=25)
@given(parts_strategy)
def test_composite_operator_is_the_sum_of_the_parts_moved_by_huygens(specs):
    R0 = rm.Frame("R0")
    parts, expected_mass, weighted = [], 0.0, np.zeros(3)
    data = []
    for n, (kind, m, pos, angles, dims) in enumerate(specs):
        f = R0.rotated(f"A{n}", about=R0.k, angle=angles[0]).rotated(
            f"B{n}", about=R0.i, angle=angles[1])
        C = R0.point(f"C{n}", *pos)
        if kind == "block":
            op = block(m, *dims, frame=f, centre=C)
        elif kind == "cylinder":
            op = cylinder(m, dims[0], dims[1], axis=f.k, centre=C)
        elif kind == "sphere":
            op = sphere(m, dims[0], frame=f, centre=C)
        else:
            op = point_mass(m, frame=f, centre=C)
        parts.append(Part(m, op))
        data.append((m, np.array(pos), _matrix_in(op, R0)))
        expected_mass += m
        weighted += m * np.array(pos)
    p = composite(parts, frame=R0)
    G = weighted / expected_mass
    J = sum(Jc + _huygens(m, np.asarray(pos) - G) for m, pos, Jc in data)
    assert float(p.mass) == pytest.approx(expected_mass, rel=1e-12)
    assert_allclose(np.array(p.centre.coordinates(R0), dtype=float).ravel(), G, atol=1e-12)
    # round-off is relative to the parts' own terms m (d^2 + size^2), not to the total
    # (which may vanish: one point mass at G)
    scale = sum(m * (1 + np.dot(pos, pos) + max(dims) ** 2)
                for (_, m, pos, _, dims) in specs)
    assert_allclose(np.array(p.inertia.matrix.tolist(), dtype=float), J,
                    rtol=1e-10, atol=1e-12 * scale)


def test_point_masses_give_the_discrete_sums():
    R0 = rm.Frame("R0")
    pts = [(1.0, (1, 2, 0)), (2.0, (-1, 0, 3)), (0.5, (0, -2, 1))]
    p = composite([Part(m, centre=R0.point(f"P{n}", *x)) for n, (m, x) in enumerate(pts)],
                  frame=R0)
    J_O = sum(m * (np.dot(x, x) * np.eye(3) - np.outer(x, x)) for m, x in pts)
    got = np.array(p.inertia_at(R0.origin).matrix.tolist(), dtype=float)
    assert_allclose(got, J_O, rtol=1e-14)


def test_hollow_sphere_as_a_sphere_with_a_hole():
    """Thick spherical shell: I = 2/5 M (R^5 - r^5)/(R^3 - r^3)."""
    rho, R, r = sp.symbols("rho R r", positive=True)
    R0 = rm.Frame("R0")
    m_out, m_in = rho * 4 * sp.pi * R**3 / 3, rho * 4 * sp.pi * r**3 / 3
    p = composite([Part(m_out, sphere(m_out, R, frame=R0)),
                   Part(m_in, sphere(m_in, r, frame=R0), hole=True)], frame=R0)
    M = m_out - m_in
    assert sp.simplify(p.inertia.A - sp.Rational(2, 5) * M * (R**5 - r**5) / (R**3 - r**3)) == 0


def test_mass_properties_of_a_cone_domain_match_the_catalogue():
    rho, R, h = sp.symbols("rho R h", positive=True)
    s, th, z = sp.symbols("s theta z")
    R0 = rm.Frame("R0")
    # solid cone, apex at the origin, base z = h: radius R z / h at height z
    dom = rm.Domain(R0, [s * R * z / h * sp.cos(th), s * R * z / h * sp.sin(th), z],
                    (s, 0, 1), (th, 0, 2 * sp.pi), (z, 0, h))
    p = mass_properties(rho, dom)
    m = sp.pi * R**2 * h * rho / 3
    assert sp.simplify(p.mass - m) == 0
    assert sp.simplify(p.centre.coordinates(R0)[2] - 3 * h / 4) == 0
    assert p.inertia.equals(cone(m, R, h, axis=R0.k, centre=p.centre))


def test_mass_properties_of_a_hemisphere_match_the_catalogue():
    R = sp.Symbol("R", positive=True)
    r, th, ph = sp.symbols("r theta phi")
    R0 = rm.Frame("R0")
    dom = rm.Domain(R0, [r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph),
                         r * sp.cos(th)], (r, 0, R), (th, 0, sp.pi / 2), (ph, 0, 2 * sp.pi))
    p = mass_properties(1, dom)
    assert p.inertia.equals(hemisphere(p.mass, R, axis=R0.k, centre=p.centre))


def test_mass_properties_numeric_density():
    """A rod along x with density 1 + x on [0, 1]: m = 3/2, x_G = 5/9, I_G = int (x-xG)^2."""
    x = sp.Symbol("x")
    R0 = rm.Frame("R0")
    p = mass_properties(1 + x, rm.Domain(R0, [x, 0, 0], (x, 0, 1)))
    xg = sp.Rational(5, 9)
    assert p.mass == sp.Rational(3, 2)
    assert p.centre.coordinates(R0)[0] == xg
    assert sp.simplify(p.inertia.C - sp.integrate((1 + x) * (x - xg) ** 2, (x, 0, 1))) == 0


def test_composite_makes_a_body():
    R0 = rm.Frame("R0")
    q = rm.coordinates("q")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    p = composite([Part(2, rm.inertia.rod(2, 1, axis=R1.i, centre=R1.point("G1", 0.5, 0, 0))),
                   Part(1, centre=R1.point("E", 1, 0, 0))], frame=R1)
    body = rm.Body("arm", frame=R1, mass=p.mass, centre=p.centre, inertia=p.inertia)
    # moment about the pivot: rod 2*1/3 + point 1*1
    assert sp.nsimplify(p.inertia_at(R0.origin).C) == sp.Rational(5, 3)
    assert body.mass == 3
    assert math.isclose(float(p.centre.coordinates(R1)[0]), 2 / 3)


@pytest.mark.parametrize("make, error, match", [
    (lambda R0: composite([], frame=R0), ArgumentError, "at least one Part"),
    (lambda R0: composite([Part(1, centre=R0.origin),
                           Part(2, centre=R0.point("B", 1, 0, 0), hole=True)], frame=R0),
     ArgumentError, "mass .* <= 0"),
    (lambda R0: composite(["rod"], frame=R0), ArgumentTypeError, "`parts\\[0\\]` must be a Part"),
    (lambda R0: Part(1), ArgumentError, "`centre` is needed"),
    (lambda R0: Part(-1, centre=R0.origin), ArgumentError, "`mass` must be >= 0"),
    (lambda R0: composite([Part(1, sphere(1, 1, frame=R0)),
                           Part(0.5, sphere(0.5, 1, frame=R0, centre=R0.point("C", 3, 0, 0)),
                                hole=True)], frame=R0),
     ArgumentError, "the holes do not fit the body"),
])
def test_bad_parts_are_refused(make, error, match):
    with pytest.raises(error, match=match):
        make(rm.Frame("R0"))
