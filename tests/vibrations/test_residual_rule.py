"""The vibrations modules decide "is this residual zero?" by the one rule of
:mod:`rigidmech._core.rules` (:func:`~rigidmech._core.rules.vanishes`): a number vanishes when
``|x| <= tol + allowance`` (the caller's absolute tolerance plus what the rounding of the
reference state leaves; the boundary holds), an expression when it is identically zero. The
steadiness of a reference state (``linearize``), the stationarity of a potential
(``equilibria``), the invariance of a steady motion (``steady``) and the entries of the reduced
stiffness on the parameters a nonholonomic constraint fixes (``constrained``) all use it.

Reference for the end-to-end case: a mass on a spring, m x'' = -k x, is at equilibrium at x*
only where k |x*| <= tol + 8 eps k max(|x*|, 1) (the residual -k x*, its rounding allowance
from ``rounding_allowance``).
"""

import ast
import pathlib

import numpy as np
import pytest
import sympy as sp

import rigidmech
from rigidmech import EquationsOfMotion
from rigidmech._core.errors import ArgumentError
from rigidmech._core.rules import vanishes
from rigidmech.vibrations import linearize

TOL = 1e-9
EPS8 = 8 * float(np.finfo(float).eps)


@pytest.mark.parametrize("allowance", [0.0, 3e-12])
@pytest.mark.parametrize("factor, zero", [(1.0, True), (1 - 1e-12, True), (1 + 1e-12, False),
                                          (1 - 1e-6, True), (1 + 1e-6, False)])
def test_vanishes_at_the_boundary_and_either_side(allowance, factor, zero):
    edge = (TOL + allowance) * factor
    for x in (edge, -edge, sp.Float(edge, 30), complex(0, edge)):
        assert vanishes(x, TOL, allowance) is zero


def test_an_expression_vanishes_only_identically():
    a = sp.Symbol("a")
    assert vanishes(sp.sin(a) ** 2 + sp.cos(a) ** 2 - 1, TOL)
    assert not vanishes(1e-30 * a, TOL)
    assert vanishes(0, 0.0) and not vanishes(1e-300, 0.0)


def test_the_vibrations_modules_keep_no_zero_rule_of_their_own():
    package = pathlib.Path(rigidmech.__file__).parent / "vibrations"
    defined = [f"{path.name}:{node.name}" for path in package.rglob("*.py")
               for node in ast.parse(path.read_text()).body
               if isinstance(node, ast.FunctionDef) and "vanish" in node.name]
    assert defined == []


@pytest.mark.parametrize("factor, steady", [(1 - 1e-6, True), (1 + 1e-6, False)])
def test_linearize_decides_an_equilibrium_by_the_rule(factor, steady):
    x, v = sp.symbols("x v")
    k, m = 1.0, 1.0
    eqs = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
                            mass_matrix=sp.ImmutableMatrix([[m]]),
                            forcing=sp.ImmutableMatrix([[-k * x]]))
    x_star = (TOL + EPS8 * k) * factor / k                  # |x*| < 1: max(|x*|, 1) = 1
    if steady:
        assert linearize(eqs, about={x: x_star}, tol=TOL).K[0, 0] == k
    else:
        with pytest.raises(ArgumentError, match=r"`about` is not an equilibrium"):
            linearize(eqs, about={x: x_star}, tol=TOL)
