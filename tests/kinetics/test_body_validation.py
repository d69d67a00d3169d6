"""A body's mass and inertia are refused when they cannot describe a rigid body (issue 9:
``Body(mass='heavy' | nan | inf | 1+2j)`` was accepted, and so was an operator of inertia
given in a basis that turns relative to the body)."""

import math

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ArgumentError, ArgumentTypeError


@pytest.fixture
def frames():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    return q, R0, R0.rotated("R1", about=R0.k, angle=q)


@pytest.mark.parametrize(
    ("mass", "error", "match"),
    [
        ("heavy", ArgumentTypeError, r"`mass` must be a number or a sympy expression; got str"),
        (math.nan, ArgumentError, r"`mass` must be a finite real number; got nan"),
        (math.inf, ArgumentError, r"`mass` must be a finite real number; got inf"),
        (-math.inf, ArgumentError, r"`mass` must be a finite real number; got -inf"),
        (1 + 2j, ArgumentError, r"`mass` must be a finite real number; got \(1\+2j\)"),
        (sp.I, ArgumentError, r"`mass` must be a finite real number; got I"),
        (sp.zoo, ArgumentError, r"`mass` must be a finite real number; got zoo"),
        (-1, ArgumentError, r"`mass` must be >= 0; got -1"),
        (-1e-300, ArgumentError, r"`mass` must be >= 0; got -1e-300"),
        (sp.Symbol("m", negative=True), ArgumentError, r"`mass` must be >= 0; got m"),
        (True, ArgumentTypeError, r"`mass` must be a number or a sympy expression; got bool"),
        ([1.0], ArgumentTypeError, r"`mass` must be a number or a sympy expression; got list"),
    ],
)
def test_mass_must_be_positive_finite_real(frames, mass, error, match):
    _, _, R1 = frames
    with pytest.raises(error, match=match):
        rm.Body("b", frame=R1, mass=mass)


@pytest.mark.parametrize("mass", [2, 0.5, sp.Rational(3, 2), sp.Symbol("m", positive=True),
                                  sp.Symbol("m")])
def test_valid_masses_are_kept(frames, mass):
    # a symbol of unknown sign cannot be decided: it is accepted (its value is checked when
    # numbers are given)
    _, _, R1 = frames
    assert rm.Body("b", frame=R1, mass=mass).mass == sp.sympify(mass)


def test_massless_link_is_mass_none_or_zero(frames):
    # the documented rule: a massless link is mass=None or mass=0, with no inertia
    q, R0, R1 = frames
    link = rm.Body("link", frame=R1)
    assert link.mass is None and link.inertia is None
    zero = rm.Body("link", frame=R1, mass=0)
    assert zero.mass == 0 and zero.inertia is None and zero.kinetic_energy(R0) == 0
    with pytest.raises(ArgumentError, match=r"`inertia` given with `mass=0`: a massless link "
                                            r"has no inertia"):
        rm.Body("link", frame=R1, mass=0, inertia=rm.inertia.sphere(1, 1, frame=R1))


def test_inertia_in_a_basis_turning_relative_to_the_body_is_refused(frames):
    q, R0, R1 = frames
    m = sp.Symbol("m", positive=True)
    # the disk's matrix is given in R0, but the body turns with R1 relative to R0
    J = rm.inertia.InertiaOperator.from_products(1, 2, 3, frame=R0)
    with pytest.raises(ArgumentError,
                       match=r"`inertia` must be given in a basis fixed in the body: its "
                             r"frame R0 turns relative to the body's frame R1"):
        rm.Body("b", frame=R1, mass=m, inertia=J)


def test_inertia_in_a_basis_fixed_in_the_body_is_accepted(frames):
    q, R0, R1 = frames
    m = sp.Symbol("m", positive=True)
    # a frame fixed in the body, at a constant angle, and a frame of revolution about R1.k
    R1b = R1.rotated("R1b", about=R1.k, angle=sp.pi / 6)
    J = rm.inertia.InertiaOperator.from_products(1, 2, 3, frame=R1b)
    body = rm.Body("b", frame=R1, mass=m, inertia=J)
    assert body.inertia.frame == R1
    assert body.inertia.in_basis(R1b).equals(J)
    # the inertia of revolution in R0 about R0.k = R1.k is the same in R1, but R0 still turns
    # relative to the body: refused (the matrix's basis must be fixed in the body)
    with pytest.raises(ArgumentError, match=r"turns relative to the body's frame R1"):
        rm.Body("b", frame=R1, mass=m,
                inertia=rm.inertia.InertiaOperator.from_products(1, 2, 3, frame=R0))


def test_catalogue_operator_built_at_another_centre_is_refused(frames):
    # rod(..., centre=A) says the rod's mass centre is A; the body says G: which one is meant
    # cannot be guessed, and placing the operator at G silently would hide the mistake
    q, R0, R1 = frames
    m, L = sp.symbols("m L", positive=True)
    A = R0.origin.moved("A", L * R1.i)
    G = R0.origin.moved("G", L / 2 * R1.i)
    with pytest.raises(ArgumentError, match=r"`inertia` is a central operator taken at A, but "
                                            r"the body's mass centre `centre` is G"):
        rm.Body("bar", frame=R1, mass=m, centre=G,
                inertia=rm.inertia.rod(m, L, axis=R1.i, centre=A))
    # built at G, or without centre= (placed by the body): accepted, same operator
    at_g = rm.Body("bar", frame=R1, mass=m, centre=G,
                   inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G))
    placed = rm.Body("bar", frame=R1, mass=m, centre=G, inertia=rm.inertia.rod(m, L, axis=R1.i))
    assert at_g.inertia == placed.inertia
