"""The compiler's one-pass code generation (``rigidmech._core._cse.generate``): the printing
of sums, products, powers, numbers and functions it does itself, and of everything else by
sympy's printers with the arguments standing in as symbols, give the values of the
expressions (sympy's evalf at 30 digits) on both code paths, with and without cse."""

import numpy as np
import pytest
import sympy

from rigidmech._core import _cse
from rigidmech._core.compile import compile_expressions

x, y, z = sympy.symbols("x y z", real=True)
s = sympy.sin(x + y)
h = sympy.Rational(1, 2)

EXPRESSIONS = [
    # sums with negative terms, numbers and floats first and last
    -x + y - 3 * z + sympy.Rational(-5, 7) - sympy.Float("0.125") * x * y + 2.5,
    -x * y / 3 - sympy.Rational(2, 3) * z / (x * y**2) + x / (y + z) ** 2,
    # integer powers of names and of sums, positive and negative
    x**2 + x**3 + x**-2 + x**5 + x**-3 + (x + y) ** 2 + (x + y) ** -1 + (x - z) ** -2
    + (x + z) ** 7,
    # products of powers, denominators alone and together
    1 / (x * y) + 1 / x + 3 / (y * z**2) - 1 / (x + y) - x**-1 * y**-2 * z**-3,
    # half and other powers, symbolic exponents
    sympy.sqrt(x) + 1 / sympy.sqrt(y + z) - 2 * sympy.sqrt(x * y) + x ** sympy.Rational(1, 3)
    + (x + y) ** sympy.Rational(-3, 2) + x**y + (x + y) ** (z / 2) + x ** sympy.Float(0.7),
    # functions printed from a template, and through the printers
    sympy.sin(s) + sympy.cos(x) ** 2 - sympy.tan(y) + sympy.exp(-x) + sympy.log(x + y)
    + sympy.atan(z) + sympy.cosh(x) * sympy.tanh(y) + sympy.asin(z / 3) + sympy.acos(z / 4),
    sympy.atan2(x, y) + sympy.Abs(x - y) + sympy.sign(z - 1) + sympy.Max(x, y * z)
    + sympy.Piecewise((x * s, x < y), (s**2, True)) + sympy.pi * x - sympy.E / y,
    # repeated subexpressions (named by cse), inside a product, a power and a function
    s**2 * y + s * z - sympy.cos(s) / s + (s + x) ** 3 + sympy.sqrt(s**2 + 1),
    -s,
    sympy.Integer(0),
    sympy.Float(-1.5),
    z,
]


def _exact(e, point):
    return float(e.xreplace(dict(zip((x, y, z), map(sympy.Float, point), strict=True)))
                 .evalf(30))


@pytest.mark.parametrize("cse", [True, False], ids=["cse", "no-cse"])
def test_generated_code_equals_the_expressions_on_both_paths(cse):
    f = compile_expressions(EXPRESSIONS, [x, y, z], cse=cse)
    rng = np.random.default_rng(7)
    points = rng.uniform(0.5, 2.0, (3, 4))
    batch = f(points[0], points[1], points[2])
    for k in range(points.shape[1]):
        want = [_exact(e, points[:, k]) for e in EXPRESSIONS]
        np.testing.assert_allclose(f(*points[:, k]), want, rtol=1e-13, atol=1e-13)
        np.testing.assert_allclose([b[k] for b in batch], want, rtol=1e-13, atol=1e-13)


def test_generated_code_names_what_cse_shares_and_counts_as_sympy_cse():
    """sin(x + y), met several times, is computed once; the code has at most 2 % more
    operations than sympy.cse's printed by sympy's printers (``_CSE_OPTIMIZATIONS`` not
    None): 138 against 136 here."""
    f = compile_expressions(EXPRESSIONS, [x, y, z])
    lines = [line.strip() for line in f.single_source.splitlines()]
    assert any(line.startswith("_x") and "= math.sin(" in line for line in lines)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(_cse, "_CSE_OPTIMIZATIONS", [])
        g = compile_expressions(EXPRESSIONS, [x, y, z])
    assert f.n_ops <= 1.02 * g.n_ops


def test_stand_ins_leave_powers_and_functions_unevaluated_only_when_asked():
    """``xreplace_shared(..., evaluate=False)`` (the stand-ins of compiled equations) does not
    evaluate a power or a function again after its arguments changed: sqrt(q(t)**2) and
    re(q(t)) with a real symbol for q(t) stay a square root and re, of the same value; by
    default they become |q| and q as with xreplace."""
    from rigidmech._core.symbolic import xreplace_shared

    t = sympy.Symbol("t")
    q = sympy.Function("q")(t)
    e = sympy.sqrt(q**2) + q**2 * x + sympy.re(q) * x
    kept, = xreplace_shared([e], {q: z}, evaluate=False)
    evaluated, = xreplace_shared([e], {q: z})
    assert evaluated.has(sympy.Abs(z)) and e.xreplace({q: z}).has(sympy.Abs(z))
    assert not evaluated.has(sympy.re)
    assert kept.has(sympy.sqrt(z**2, evaluate=False)) and not kept.has(sympy.Abs)
    assert kept.has(sympy.re(z, evaluate=False))
    assert float(kept.subs({z: -0.7, x: 2.0})) == pytest.approx(0.7 + 0.98 - 1.4, rel=1e-15)


@pytest.mark.parametrize("cse", [True, False], ids=["cse", "no-cse"])
def test_operations_counted_while_writing_equal_the_count_on_the_code(cse):
    from rigidmech._core._codegen import count_operations

    f = compile_expressions(EXPRESSIONS, [x, y, z], cse=cse)
    body = [line.split(" = ", 1)[1] for line in f.single_source.splitlines()[1:-1]]
    returned = f.single_source.splitlines()[-1].strip()[len("return "):]
    floats = returned.count("float(")     # the output's float(...) calls are not counted
    assert f.n_ops == count_operations(body + [returned]) - floats
