"""Tests of rigidmech.vectors.symbols: time, parameters of situation, constants."""

import pytest
import sympy as sp

from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.vectors import constants, coordinates, is_coordinate, t, time_derivative


def test_time_is_one_symbol_shared_with_sympy_mechanics():
    from sympy.physics.mechanics import dynamicsymbols

    assert t == sp.Symbol("t") and t == dynamicsymbols._t
    assert t != sp.Symbol("t", real=True)  # assumptions are part of a sympy symbol


@pytest.mark.parametrize(
    "names",
    [pytest.param("q1 q2", id="spaces"), pytest.param("q1,q2", id="comma"),
     pytest.param(" q1 ,  q2 ", id="mixed"), pytest.param(["q1", "q2"], id="list")],
)
def test_coordinates_are_real_functions_of_time(names):
    q1, q2 = coordinates(names)
    assert str(q1) == "q1(t)" and q1.args == (t,) and q2.func.__name__ == "q2"
    assert q1.is_real
    assert q1.diff(t) == sp.Derivative(q1, t)
    assert sp.diff(sp.sin(q1), t) == sp.cos(q1) * q1.diff(t)  # chain rule
    assert coordinates("q1") == q1  # same name, same function: a value
    assert q1 != q2


def test_single_coordinate_is_returned_bare():
    q = coordinates("q")
    assert isinstance(q, sp.Expr) and not isinstance(q, tuple)
    assert isinstance(coordinates("a b c"), tuple) and len(coordinates("a b c")) == 3


def test_constants():
    m, L = constants("m L", positive=True)
    assert m.is_positive and L.is_positive
    g = constants("g")
    assert isinstance(g, sp.Symbol) and g.is_real and g.is_positive is None
    assert g == sp.Symbol("g", real=True)
    z = constants("z", real=False)
    assert z.is_real is False
    assert sp.diff(m * L, t) == 0


def test_is_coordinate():
    q = coordinates("q")
    assert is_coordinate(q)
    assert not is_coordinate(t)
    assert not is_coordinate(q.diff(t))
    assert not is_coordinate(2 * q)
    assert not is_coordinate(constants("m"))
    assert not is_coordinate(sp.Function("f")(sp.Symbol("x")))
    assert not is_coordinate("q")


def test_time_derivative():
    q = coordinates("q")
    assert time_derivative(sp.sin(q)) == sp.cos(q) * q.diff(t)
    assert time_derivative(q, 2) == q.diff(t, 2)
    assert time_derivative(q, 0) == q
    assert time_derivative(3) == 0
    assert time_derivative(t**2) == 2 * t


@pytest.mark.parametrize(
    "names",
    [pytest.param("", id="empty"), pytest.param("   ", id="blank"),
     pytest.param("1q", id="not-identifier"), pytest.param("q-1", id="dash"),
     pytest.param(["q", 2], id="not-a-string"), pytest.param([], id="empty-list")],
)
def test_bad_names(names):
    with pytest.raises(ArgumentError, match="`names` must be identifiers separated by spaces "
                       "or commas; got "):
        coordinates(names)
    with pytest.raises(ValueError, match="`names` must be identifiers"):
        constants(names)


def test_time_derivative_errors():
    with pytest.raises(ArgumentError, match="`order` must be a non-negative integer; got -1"):
        time_derivative(t, -1)
    with pytest.raises(ArgumentError, match="`order` must be a non-negative integer; got 1.5"):
        time_derivative(t, 1.5)
    with pytest.raises(ArgumentTypeError, match="`expr` must be a scalar sympy expression; "
                       "got object"):
        time_derivative(object())
