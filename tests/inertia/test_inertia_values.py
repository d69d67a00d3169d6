"""Non-finite or complex values in operators of inertia are refused (issue 9); strings are not
read as symbols."""

import math

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ArgumentError, ArgumentTypeError

R0 = rm.Frame("R0")
BAD = [(math.nan, ArgumentError, "finite real"), (math.inf, ArgumentError, "finite real"),
       (1 + 2j, ArgumentError, "finite real"), (sp.zoo, ArgumentError, "finite real"),
       ("A", ArgumentTypeError, "number or a sympy expression")]


@pytest.mark.parametrize(("value", "error", "match"), BAD)
def test_from_products(value, error, match):
    with pytest.raises(error, match=rf"`A` must be (a )?{match}"):
        rm.InertiaOperator.from_products(value, 1, 1, frame=R0)
    with pytest.raises(error, match=rf"`F` must be (a )?{match}"):
        rm.InertiaOperator.from_products(1, 1, 1, F=value, frame=R0)


@pytest.mark.parametrize(("value", "error", "match"), BAD)
def test_from_matrix(value, error, match):
    with pytest.raises(error, match=rf"`matrix` must be (a )?{match}"):
        rm.InertiaOperator.from_matrix([[value, 0, 0], [0, 1, 0], [0, 0, 1]], frame=R0)


@pytest.mark.parametrize(("value", "error", "match"), BAD)
@pytest.mark.parametrize("argument", ["mass", "radius"])
def test_catalogue(value, error, match, argument):
    args = {"mass": 1, "radius": 1} | {argument: value}
    with pytest.raises(error, match=rf"`{argument}` must be (a )?{match}"):
        rm.inertia.disk(args["mass"], args["radius"], axis=R0.k)


@pytest.mark.parametrize(("value", "error", "match"), BAD)
def test_moved_mass(value, error, match):
    J = rm.inertia.disk(1, 1, axis=R0.k)
    with pytest.raises(error, match=rf"`mass` must be (a )?{match}"):
        J.moved(R0.point("P", 1, 0, 0), mass=value, centre=R0.origin)


def test_overflowing_moments_are_an_error():
    # found by the fuzz test: sphere(1, 1e300) has moments 4e599, which overflow a float; the
    # eigenvalue check then raised numpy's LinAlgError instead of a rigidmech error
    with pytest.raises(ArgumentError, match=r"overflow floating-point numbers"):
        rm.inertia.sphere(1, 1e300, frame=R0)
    with pytest.raises(ArgumentError, match=r"`matrix` gives moments .* that overflow"):
        rm.InertiaOperator.from_matrix([[sp.Float(1e300) ** 2, 0, 0], [0, 1, 0], [0, 0, 1]],
                                       frame=R0)


@pytest.mark.parametrize("entries", [[0, 0, 0, None], [[1, 0, 0], [0, 1, object()], [0, 0, 1]]])
def test_from_matrix_refuses_entries_that_are_not_numbers(entries):
    # found by the fuzz test in CI: None in a list reached sympy.Matrix, which warns
    # (deprecated non-Expr entries) instead of a clear error
    with pytest.raises(ArgumentTypeError, match=r"`matrix` must be a number or a sympy "
                       r"expression in every entry; got (NoneType None|object)"):
        rm.InertiaOperator.from_matrix(entries, frame=rm.Frame("R0"))
