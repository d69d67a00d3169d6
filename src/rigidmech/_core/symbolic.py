"""Symbolic helpers: replacement that keeps shared subexpressions shared, and the decisions
"is this zero?", one function per meaning.

sympy's ``xreplace`` walks an expression as a tree: a subexpression reached along many paths
is rebuilt once per path. Derived equations of motion are DAGs in which the same velocity
components appear in many entries, so a tree walk costs as much as the swollen expression.
:func:`xreplace_shared` walks each distinct node once (memoised), which keeps the cost
proportional to the size of the DAG (no expression swell). sympy has no memoised
replacement, hence this small function.

"Is it zero?" has four meanings in rigidmech, each with its own cost and answer; each has one
function here (and only here):

* :func:`is_exactly_zero` -- structurally zero, no algebra (cheap; used to skip terms);
* :func:`is_identically_zero` -- zero for every value of the symbols, decided by ``simplify``,
  numbers to 25 digits (geometry: are two vectors parallel, is a basis orthonormal);
* :func:`simplifies_to_zero` -- the same question for trigonometric expressions of angles
  (operators of inertia after rotations): a cheap canonical form first, ``simplify`` last;
* :func:`zero_decision` -- three-valued: True, False, or None when sympy cannot decide (the
  torsors layer reports an undecided case instead of guessing);
* :func:`vanishes` -- zero for every value of the symbols *to the rounding of the floats the
  expression carries*: an exact expression is decided by its values at random points in
  64-digit arithmetic (:func:`~rigidmech._core.probes.sampled_zero_decision`), by ``simplify``
  when they do not decide, one with float constants by its value at two sample points, at most
  ``SAMPLE_ZERO`` (1e-9) of the largest magnitude met while evaluating it (the relative motion
  a joint allows, closure conditions, energies that vanish identically);
* :func:`fold_numbers` -- the decision of ``sampled_zero_decision`` (values at two random
  points, in 64-digit arithmetic, below 1e-40 of the largest intermediate value, and an
  expression meromorphic in its symbols), without ``simplify`` (large matrices compiled for
  numbers, where ``simplify`` costs minutes and ``evalf`` of a zero costs seconds).
"""

from __future__ import annotations

import cmath
import math

import mpmath
import sympy as sp

from .probes import (
    FOLD_DIGITS,
    FOLD_ZERO_RELATIVE,
    sampled_decisions,
    sampled_zero_decision,
)
from .rules import magnitude

__all__ = ["xreplace_shared", "free_symbols_shared", "atoms_shared", "is_exactly_zero",
           "complex_values",
           "nonzero_somewhere", "vanishes", "SAMPLE_ZERO", "fold_numbers",
           "is_identically_zero", "simplifies_to_zero", "zero_decision"]


def xreplace_shared(exprs, rule, memo=None, *, evaluate=True):
    """Apply ``rule`` (an exact, structural replacement like ``xreplace``) to each expression
    of ``exprs``, rebuilding every distinct subexpression only once.

    Parameters
    ----------
    exprs : iterable of sympy expressions
    rule : dict
        Mapping of subexpressions to replacements; a matched node is not entered.
    memo : dict, optional
        Cache shared between calls (pass the same dict to share work across calls).
    evaluate : bool, optional
        Whether powers and functions whose arguments changed are evaluated again (default
        True; sums and products never are). False when ``rule`` puts symbols in place of
        leaves and the result is to be computed with (compiled code): the value is the same,
        and ``Pow`` asks the assumptions of its base, a large sum, again (0.2 s for the 210
        powers of the 3D chain of 6 links), ``sin`` and ``cos`` look for multiples of pi
        (0.1 s for the planar 20-link pendulum; benchmarks/first_rhs.py).

    Returns
    -------
    list of sympy expressions

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> f = sp.Function("f")(x)
    >>> xreplace_shared([sp.sin(f) + f**2, f], {f: y})
    [y**2 + sin(y), y]
    """
    memo = {} if memo is None else memo

    def walk(e):
        hit = memo.get(e)
        if hit is not None:
            return hit
        if e in rule:
            out = rule[e]
        elif not e.args or isinstance(e, sp.Symbol):
            out = e
        else:
            args = tuple(walk(a) for a in e.args)
            if all(a is b for a, b in zip(args, e.args, strict=True)):
                out = e
            elif isinstance(e, sp.Add | sp.Mul) or (
                    not evaluate and isinstance(e, sp.Pow | sp.Function)):
                # Replacing leaves by leaves keeps sums and products as they are: skip the
                # canonical re-sorting that dominates the cost of rebuilding them.
                out = e.func(*args, evaluate=False)
            else:
                out = e.func(*args)
        memo[e] = out
        return out

    return [walk(sp.sympify(e)) for e in exprs]


def free_symbols_shared(exprs) -> set:
    """The free symbols of ``exprs``, visiting every distinct subexpression once.

    ``Expr.free_symbols`` walks a DAG as a tree (every path again); this walk is linear in
    the number of distinct nodes.

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> e = sp.sin(x) * y
    >>> sorted(free_symbols_shared([e + e**2, 3]), key=str)
    [x, y]
    """
    seen = set()
    out = set()
    stack = [sp.sympify(e) for e in exprs]
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if isinstance(e, sp.Symbol):
            out.add(e)
        elif isinstance(e, sp.Derivative | sp.Subs | sp.Integral):
            out |= e.free_symbols
        else:
            stack.extend(e.args)
    return out


def atoms_shared(exprs):
    """The free symbols, the applied undefined functions (``q(t)``) and the derivatives
    (``Derivative(q(t), t)``) of ``exprs``, visiting every distinct subexpression once.

    A derivative is listed as a whole; its expression is not entered.

    Returns
    -------
    (set, set, set)
        Symbols, applied undefined functions, derivatives.

    Examples
    --------
    >>> t, k = sp.symbols("t k")
    >>> q, F = sp.Function("q")(t), sp.Function("F")(t)
    >>> s, f, d = atoms_shared([k * q.diff(t) + F, q])
    >>> sorted(s, key=str), sorted(f, key=str), d
    ([k, t], [F(t), q(t)], {Derivative(q(t), t)})
    """
    seen = set()
    symbols, functions, derivatives = set(), set(), set()
    stack = [sp.sympify(e) for e in exprs]
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if isinstance(e, sp.Symbol):
            symbols.add(e)
        elif isinstance(e, sp.Derivative):
            derivatives.add(e)
            symbols |= e.free_symbols
        elif isinstance(e, sp.core.function.AppliedUndef):
            functions.add(e)
            stack.extend(e.args)
        else:
            stack.extend(e.args)
    return symbols, functions, derivatives
def is_exactly_zero(x) -> bool:
    """Whether the sympy scalar ``x`` is structurally zero: the integer 0 or a float zero
    (``Float(0.0) != 0`` in sympy >= 1.13). No algebra: ``sin(a)**2 + cos(a)**2 - 1`` is not
    exactly zero.

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> is_exactly_zero(sp.Float(0.0)), is_exactly_zero(a - a)
    (True, True)
    >>> is_exactly_zero(sp.sin(a)**2 + sp.cos(a)**2 - 1)
    False
    """
    if x is sp.S.Zero:
        return True
    if isinstance(x, sp.Basic):  # class attributes and the number's own value: no
        if not x.is_Number:      # sympify, no assumption deduced for a new number
            return False
        return x.p == 0 if x.is_Rational else (not bool(x) if x.is_Float else bool(x.is_zero))
    return x == 0


def is_identically_zero(expr) -> bool:
    """Whether the scalar ``expr`` is zero for every value of its symbols, decided with
    ``sympy.simplify``; a number counts as zero when its magnitude, evaluated to 30 digits, is
    below 1e-25 (an exact number whose simplification sympy would not find).

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> is_identically_zero(sp.sin(a)**2 + sp.cos(a)**2 - 1)
    True
    >>> is_identically_zero(sp.cos(sp.pi / 5) - (1 + sp.sqrt(5)) / 4), is_identically_zero(a)
    (True, False)
    """
    expr = sp.sympify(expr)
    if expr == 0:
        return True
    if expr.is_number:
        return bool(abs(sp.N(expr, 30)) < 1e-25)
    return sp.simplify(expr) == 0


def simplifies_to_zero(x) -> bool:
    """Whether ``x`` simplifies to 0, trying first a cheap trigonometric canonical form
    (multiple angles expanded, sin^2 replaced by 1 - cos^2) and ``sympy.simplify`` only if that
    fails. Made for entries of rotated operators of inertia; numbers are not rounded.

    Examples
    --------
    >>> q = sp.Symbol("q")
    >>> simplifies_to_zero(sp.cos(2 * q) - 1 + 2 * sp.sin(q)**2)
    True
    >>> simplifies_to_zero(sp.cos(q))
    False
    """
    if x == 0:
        return True
    e = sp.expand(sp.expand_trig(x))
    if e == 0:
        return True
    rule = {sp.sin(a) ** 2: 1 - sp.cos(a) ** 2 for a in {s.args[0] for s in e.atoms(sp.sin)}}
    if rule and sp.expand(e.subs(rule)) == 0:
        return True
    return sp.simplify(x) == 0


def zero_decision(expr) -> bool | None:
    """Three-valued decision on the scalar ``expr``: True if it simplifies to 0, False if it is
    known not to be zero (a non-zero number, or sympy's assumptions say so), None if sympy cannot
    decide (a symbol of unknown value).

    Examples
    --------
    >>> a = sp.Symbol("a"); b = sp.Symbol("b", positive=True)
    >>> zero_decision(sp.sin(a)**2 + sp.cos(a)**2 - 1), zero_decision(b + 1), zero_decision(a)
    (True, False, None)
    """
    if expr == 0:
        return True
    z = sp.simplify(expr)
    if z == 0:
        return True
    if z.is_zero is False or (z.is_number and z != 0):
        return False
    return None


_CMATH = {sp.sin: cmath.sin, sp.cos: cmath.cos, sp.tan: cmath.tan, sp.exp: cmath.exp,
          sp.log: cmath.log, sp.asin: cmath.asin, sp.acos: cmath.acos, sp.atan: cmath.atan,
          sp.sinh: cmath.sinh, sp.cosh: cmath.cosh, sp.tanh: cmath.tanh}


def _complex_value(e, values, memo):
    """Value of ``e`` with the leaves in ``values`` (plain Python complex arithmetic); raises
    KeyError or TypeError on what it does not know (then sympy evaluates)."""
    if e in memo:
        return memo[e]
    if e in values:
        out = values[e]
    elif e.is_Number or e.is_NumberSymbol:
        out = complex(e)
    elif e.is_Add:
        out = sum(_complex_value(a, values, memo) for a in e.args)
    elif e.is_Mul:
        out = 1
        for a in e.args:
            out *= _complex_value(a, values, memo)
    elif e.is_Pow:
        out = _complex_value(e.base, values, memo) ** _complex_value(e.exp, values, memo)
    elif isinstance(e, sp.Abs):
        out = abs(_complex_value(e.args[0], values, memo))
    else:
        out = _CMATH[e.func](_complex_value(e.args[0], values, memo))
    memo[e] = out
    return out


def complex_values(exprs, values) -> list:
    """The values (Python complex numbers) of ``exprs`` with the symbols of ``values`` given
    those numbers: one walk in double precision over the distinct subexpressions (shared by
    all the expressions), where ``evalf`` walks each expression as a tree in multiple
    precision; an expression with a function this walk does not know is evaluated by
    ``evalf`` (its symbols replaced by Floats).

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> complex_values([sp.sqrt(x) * y, sp.exp(x) * y], {x: 0.25, y: 2.0})
    [(1+0j), (2.568050833375483+0j)]
    """
    rule = {s: complex(v) for s, v in values.items()}
    memo, out = {}, []
    for e in exprs:
        e = sp.sympify(e)
        try:
            out.append(complex(_complex_value(e, rule, memo)))
        except (KeyError, TypeError, ValueError, ZeroDivisionError, OverflowError,
                RecursionError):
            floats = {s: sp.Float(v) for s, v in values.items()}
            out.append(complex(e.xreplace(floats).evalf()))
    return out


def _sample(atom, value, i):
    """A sample value that honours the atom's sign and integrality assumptions (an
    expression that vanishes only under them must not be seen non-zero)."""
    if not isinstance(atom, sp.Symbol):  # q(t), q'(t): real, no assumption to ask
        return value
    if atom.is_integer:
        value = float(1 + i % 3)
    if atom.is_negative or atom.is_nonpositive:
        value = -value
    return value


#: Magnitude under which a value at a sample point (symbols in (0.37, 1.4)) is not taken as a
#: proof of "non-zero" (:func:`nonzero_somewhere`), and, relative to the largest magnitude met
#: while evaluating an expression with float constants, under which it is their rounding
#: (:func:`vanishes`): float arithmetic leaves about (number of operations) x 1.1e-16 of the
#: terms, far below; a genuine term 1e-9 times smaller than the others is not resolved.
SAMPLE_ZERO = 1e-9


def _sample_values(atoms, seed):
    return {a: complex(_sample(a, seed + 0.1 * (i % 8), i)) for i, a in enumerate(atoms)}


def _derivatives_done(expr):
    """``expr`` with its derivatives of expressions evaluated by the chain rule
    (``Derivative(sin(q), t)`` -> ``cos(q) q'``): only derivatives of functions ``q(t)`` are
    atoms a value can be given to independently. Unchanged (no rebuild) when there is none."""
    done = {d: d.doit() for d in atoms_shared([expr])[2]
            if not isinstance(d.expr, sp.core.function.AppliedUndef)}
    return expr.xreplace(done) if done else expr


def _sample_atoms(expr, skip):
    return [*sorted(expr.atoms(sp.Derivative), key=str),
            *sorted(expr.atoms(sp.core.function.AppliedUndef), key=str),
            *sorted((x for x in expr.free_symbols if x not in skip), key=str)]


def nonzero_somewhere(expr, skip=()) -> bool:
    """Whether the scalar ``expr`` is shown not to vanish identically by its value at two
    sample points (every symbol, function q(t) and derivative q'(t) but those in ``skip``
    given values in (0.37, 1.4), of the sign its assumptions give, integers for integer
    symbols): a magnitude above 1e-9 at either point. False means only
    "not shown": decide then with algebra (``sympy.simplify``). Cheap, unlike ``simplify``
    of an expression that is not zero.

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> nonzero_somewhere(sp.sin(a)**2 + sp.cos(a)**2 - 1), nonzero_somewhere(sp.sin(a))
    (False, True)
    """
    expr = _derivatives_done(sp.sympify(expr))
    if expr == 0:
        return False
    atoms = _sample_atoms(expr, skip)
    for seed in _SEEDS:
        values = _sample_values(atoms, seed)
        try:
            value = _complex_value(expr, values, {})
        except (KeyError, TypeError, ValueError, ZeroDivisionError, OverflowError):
            rule = {a: sp.Float(v.real) for a, v in values.items()}
            try:
                value = complex(expr.xreplace(rule).evalf())
            except (TypeError, ValueError):
                return False
        if math.isfinite(abs(value)) and abs(value) > SAMPLE_ZERO:
            return True
    return False


_SEEDS = (0.3711, 0.6173)


def vanishes(expr, skip=(), scale=None) -> bool:
    """Whether the scalar ``expr`` vanishes for every value of its symbols (but those in
    ``skip``), to the rounding of the float constants it carries.

    * An expression without floats has no rounding: its values at random points in 64-digit
      arithmetic decide (:func:`~rigidmech._core.probes.sampled_zero_decision`: zero when
      they are at most 1e-40 of the terms and the expression is meromorphic in its symbols,
      not zero when one is above 1e-30 of them), after the cheaper double-precision
      :func:`nonzero_somewhere` (a value above 1e-9 says no); when they do not decide (a
      near-cancellation, ``Abs``, ``atan``, a square root of a base of unknown sign, integer
      symbols), ``sympy.simplify`` does.
    * An expression with floats (``0.0625``, ``sin(0.0625)``: sympy combines their terms as it
      builds, so ``0.0625 sin(0.0625) q' - 0.0625 sin(0.0625) q'`` may arrive as
      ``6.9e-18 q'``) vanishes when, at two sample points (:func:`nonzero_somewhere`'s), its
      value is at most ``SAMPLE_ZERO`` times the largest magnitude met while evaluating it
      (its constants, its symbols' values, its intermediate results).
    * With ``scale`` (expressions of the same kind of quantity: the other components of a
      motion, the positions of the points of a condition), that reference is instead the
      magnitude of the terms (:func:`~rigidmech._core.rules.magnitude`) of ``expr`` and of the
      ``scale`` expressions at the same sample point: the verdict is then relative to the
      size of the quantities, not to the sample values of the symbols (about 1), so that a
      mechanism of size 1e-10 keeps a condition of size 1e-10. The boundary vanishes.

    Examples
    --------
    >>> q = sp.Symbol("q")
    >>> vanishes(sp.sin(q)**2 + sp.cos(q)**2 - 1), vanishes(sp.Rational(1, 10**12) * q)
    (True, False)
    >>> vanishes(6.9e-18 * q), vanishes(1e-6 * q)
    (True, False)
    >>> vanishes(1e-10 * sp.cos(q)), vanishes(1e-10 * sp.cos(q), scale=[2e-10 * sp.sin(q)])
    (True, False)
    """
    expr = sp.sympify(expr)
    if is_exactly_zero(expr):
        return True
    expr = _derivatives_done(expr)  # the chain rule on both paths (one rule)
    if not expr.atoms(sp.Float):
        if nonzero_somewhere(expr, skip):
            return False
        decided = sampled_zero_decision(expr, skip)
        if decided is not None:
            return decided
        return sp.simplify(expr) == 0
    refs = None if scale is None else [magnitude(e) for e in (expr, *scale)]
    # the symbols of the expression and of its references (a magnitude turns sin(q) into 1:
    # drawn from the references alone, q had no value and every such row went to simplify)
    atoms = _sample_atoms(expr if refs is None else sp.Tuple(expr, *refs), skip)
    for seed in _SEEDS:
        values, memo = _sample_values(atoms, seed), {}
        try:
            value = _complex_value(expr, values, memo)
            size = (max(abs(v) for v in memo.values()) if refs is None else
                    sum(abs(_complex_value(r, values, memo)) for r in refs))
        except (KeyError, TypeError, ValueError, ZeroDivisionError, OverflowError):
            # a function this evaluation does not know: algebra decides, with the floats
            # made exact (their rounding then cancels only if it is an exact identity)
            return sp.simplify(sp.nsimplify(expr, rational=True)) == 0
        if not (math.isfinite(size) and abs(value) <= SAMPLE_ZERO * size):
            return False
    return True


def fold_numbers(exprs, *, seed=0):
    """Prepare expressions for compilation to floating point: every constant subexpression
    becomes one Float (its value to 64 digits, correctly rounded to 17), and every expression
    decided zero by :func:`~rigidmech._core.probes.sampled_zero_decision` becomes an exact 0.

    Made for large matrices compiled for numbers (linearised equations of motion): sympy's
    ``evalf`` of an entry that is zero costs seconds (it raises the precision until it gives
    up: ``0.e-253``) and ``simplify`` minutes, while the float arithmetic of the generated code
    would leave a rounding residue (1e-17) where the entry is zero. The test is the one of
    :func:`~rigidmech._core.probes.sampled_zero_decision`, on all the expressions at the same
    points (:func:`~rigidmech._core.probes.sampled_decisions`): evaluated with ``FOLD_DIGITS``
    digits at two points (every symbol, ``q(t)`` and ``q'(t)`` drawn in (0.5, 1.5) with the
    sign its assumptions give; integer symbols not sampled), the magnitude is at most
    ``FOLD_ZERO_RELATIVE`` times the largest magnitude met in the evaluation, at both points,
    and the expression is meromorphic in its atoms (``Abs(v) - v`` vanishes at every sample
    point but is not zero: it is kept). A function without an mpmath counterpart here leaves
    its expression unchanged.

    Parameters
    ----------
    exprs : sequence of sympy expressions
    seed : int
        Seed of the random points (fixed: the result does not change between runs).

    Returns
    -------
    list of sympy expressions

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> zero = (sp.sqrt(2) + a)**2 - a**2 - 2 * sp.sqrt(2) * a - 2
    >>> fold_numbers([zero, sp.pi * sp.sqrt(2) * a + sp.sin(sp.pi / 7)])
    [0, 4.4428829381583662*a + 0.43388373911755812]
    """
    exprs = [sp.sympify(e) for e in exprs]
    with mpmath.workdps(FOLD_DIGITS):
        decisions, probe = sampled_decisions(exprs, seed=seed)
        memo = {}
        out = [sp.S.Zero if zero is True else _folded(e, probe, memo)
               for e, zero in zip(exprs, decisions, strict=True)]
    return out


def _constant(e, probe):
    """The Float of the constant subexpression ``e`` (real to the zero test), else None."""
    values, largest, constant = probe
    value = values.get(e)
    if value is None or not constant[e]:
        return None
    v = value[0]
    if abs(mpmath.im(v)) > FOLD_ZERO_RELATIVE * max(largest[e][0], 1e-300):
        return None
    return sp.Float(mpmath.re(v), 17)


def _folded(e, probe, memo):
    """``e`` with its constant subexpressions folded (see :func:`fold_numbers`); in a sum or
    product, the constant terms or factors become one Float."""
    hit = memo.get(e)
    if hit is not None:
        return hit
    values, _, constant = probe
    if not e.args or e.is_Symbol:
        out = e if not e.is_NumberSymbol else _constant(e, probe) or e
    elif e not in constant:     # inside a sampled leaf (the (t, 1) of Derivative(q(t), t))
        out = e
    elif constant[e]:
        out = _constant(e, probe) or e
    elif e.is_Add or e.is_Mul:
        constants = [a for a in e.args if constant[a]]
        rest = [_folded(a, probe, memo) for a in e.args if not constant[a]]
        if len(constants) > 1 or (constants and not isinstance(constants[0], sp.Rational)):
            with mpmath.workdps(FOLD_DIGITS):
                columns = list(zip(*(values.get(a) or [None] for a in constants), strict=True))
                if all(x is not None for x in columns[0]):
                    combine = mpmath.fsum if e.is_Add else mpmath.fprod
                    v = combine(columns[0])
                    if abs(mpmath.im(v)) <= FOLD_ZERO_RELATIVE * max(abs(v), 1e-300):
                        constants = [sp.Float(mpmath.re(v), 17)]
        out = e.func(*constants, *rest)
    else:
        out = e.func(*(_folded(a, probe, memo) for a in e.args))
    memo[e] = out
    return out

