"""Numbers that cannot describe a frame or a vector are refused where they are given (issue 9:
a string as a rotation angle was accepted and the system later reported "nothing moves";
``Vector.normalized()`` of a vector that is zero only after simplification returned 0/0)."""

import math

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ArgumentError, ArgumentTypeError


@pytest.mark.parametrize(
    ("angle", "error", "match"),
    [
        ("q", ArgumentTypeError,
         r"`angle` must be a number or a sympy expression; got str 'q'\. For a parameter of "
         r"situation use rm.coordinates"),
        (math.nan, ArgumentError, r"`angle` must be a finite real number; got nan"),
        (math.inf, ArgumentError, r"`angle` must be a finite real number; got inf"),
        (1j, ArgumentError, r"`angle` must be a finite real number; got 1j"),
        (sp.oo, ArgumentError, r"`angle` must be a finite real number; got oo"),
    ],
)
def test_rotation_angle_must_be_a_finite_real(angle, error, match):
    R0 = rm.Frame("R0")
    with pytest.raises(error, match=match):
        R0.rotated("R1", about=R0.k, angle=angle)
    with pytest.raises(error, match=match):
        R0.euler("R", angle, 0, 0)


@pytest.mark.parametrize(
    ("value", "error", "match"),
    [
        ("x", ArgumentTypeError, r"`x` must be a number or a sympy expression; got str"),
        (math.nan, ArgumentError, r"`x` must be a finite real number; got nan"),
        (2 + 1j, ArgumentError, r"`x` must be a finite real number; got \(2\+1j\)"),
    ],
)
def test_point_and_vector_coordinates(value, error, match):
    R0 = rm.Frame("R0")
    with pytest.raises(error, match=match):
        R0.point("A", value, 0, 0)
    with pytest.raises(error, match=match):
        R0.vector(value, 0, 0)


@pytest.mark.parametrize("value", [math.nan, math.inf, 1j])
def test_scaling_a_vector_by_a_non_finite_number(value):
    R0 = rm.Frame("R0")
    with pytest.raises(ArgumentError, match=r"`scalar` must be a finite real number"):
        value * R0.k
    with pytest.raises(ArgumentError, match=r"`scalar` must be a finite real number"):
        R0.k / value


def test_normalized_vector_zero_after_simplification():
    a = sp.Symbol("a")
    R0 = rm.Frame("R0")
    v = (sp.sin(a) ** 2 + sp.cos(a) ** 2 - 1) * R0.i
    assert not v.is_zero  # structurally non-zero: the old test let it through
    with pytest.raises(ArgumentError,
                       match=r"cannot normalise the zero vector: .* simplifies to zero"):
        v.normalized()
    # a direction that is not zero is still normalised
    assert (3 * R0.i + 4 * R0.j).normalized() == sp.Rational(3, 5) * R0.i + \
        sp.Rational(4, 5) * R0.j


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"stiffness": "k"}, r"`stiffness` must be a number or a sympy expression; got str"),
        ({"stiffness": math.nan}, r"`stiffness` must be a finite real number; got nan"),
        ({"stiffness": -2}, r"`stiffness` must be >= 0; got -2"),
        ({"free_length": math.inf}, r"`free_length` must be a finite real number; got inf"),
        ({"free_length": -1}, r"`free_length` must be >= 0; got -1"),
    ],
)
def test_spring_constants(kwargs, match):
    x = rm.coordinates("x")
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    body = rm.Body("b", frame=R1, mass=1)
    args = {"stiffness": 1, "free_length": 0.5} | kwargs
    with pytest.raises((ArgumentError, ArgumentTypeError), match=match):
        rm.Spring(args["stiffness"], args["free_length"], a=R0.origin, b=R1.origin, on_b=body)
