"""Values of expressions at probe points in high precision, and the exact zero decision they
give without algebra.

Deciding that an exact expression vanishes identically by ``sympy.simplify`` costs seconds on
the residuals of a 3D derivation (a thousand operations of sines and cosines of the angles),
while its value at a point, in 64-digit arithmetic, costs milliseconds.
:func:`sampled_zero_decision` decides by values at random points (the classical randomised
identity test, Schwartz--Zippel for polynomials) and says when it cannot;
:func:`~rigidmech._core.symbolic.vanishes` uses it before ``simplify``, and
:func:`~rigidmech._core.symbolic.fold_numbers` shares its evaluation and its threshold.
"""

from __future__ import annotations

import random

import mpmath
import sympy as sp

__all__ = ["FOLD_DIGITS", "FOLD_ZERO_RELATIVE", "SAMPLED_NONZERO_RELATIVE",
           "sampled_zero_decision", "sampled_decisions"]

#: Working precision (decimal digits) and relative threshold of the zero test at probe points
#: (:func:`~rigidmech._core.symbolic.fold_numbers`, :func:`sampled_zero_decision`): an
#: expression whose value at every probe point is at most ``FOLD_ZERO_RELATIVE`` times the
#: largest magnitude met while evaluating it is zero. Rounding at 64 digits leaves about
#: (number of operations) x 1e-64 of that magnitude, far below 1e-40 even for a million
#: operations; a non-zero expression smaller than 1e-40 of its own terms at two random points
#: would need a coincidence of that order.
FOLD_DIGITS = 64
FOLD_ZERO_RELATIVE = mpmath.mpf(10) ** -40

#: Relative magnitude (of the largest met while evaluating) above which a value at a probe
#: point proves "not zero" in :func:`sampled_zero_decision`: 1e34 times the rounding of the
#: 64-digit arithmetic. Between ``FOLD_ZERO_RELATIVE`` and this, the sample does not decide.
SAMPLED_NONZERO_RELATIVE = mpmath.mpf(10) ** -30

#: Number of random points of :func:`sampled_zero_decision`.
SAMPLED_POINTS = 2

_MPMATH = {sp.sin: mpmath.sin, sp.cos: mpmath.cos, sp.tan: mpmath.tan, sp.exp: mpmath.exp,
           sp.log: mpmath.log, sp.asin: mpmath.asin, sp.acos: mpmath.acos,
           sp.atan: mpmath.atan, sp.sinh: mpmath.sinh, sp.cosh: mpmath.cosh,
           sp.tanh: mpmath.tanh, sp.Abs: abs}

#: Functions analytic (or meromorphic) in their argument over the whole complex plane: an
#: expression made of them, of sums, products and integer powers is meromorphic in its symbols.
_MEROMORPHIC = frozenset({sp.sin, sp.cos, sp.tan, sp.exp, sp.sinh, sp.cosh, sp.tanh})

#: What every sample value (a float in (0.5, 1.5), not an integer, or its opposite) is: an
#: atom that declares otherwise is not sampled (an integer symbol, a symbol declared even).
_SAMPLE_FACTS = {"commutative": True, "complex": True, "real": True, "extended_real": True,
                 "finite": True, "infinite": False, "nonzero": True, "zero": False,
                 "extended_nonzero": True, "imaginary": False, "integer": False,
                 "noninteger": True, "rational": True, "irrational": False, "algebraic": True,
                 "transcendental": False, "even": False, "odd": False, "prime": False,
                 "composite": False}
_SIGN_FACTS = ("positive", "nonnegative", "extended_positive", "extended_nonnegative",
               "negative", "nonpositive", "extended_negative", "extended_nonpositive")


def _probe_values(exprs, points, digits=FOLD_DIGITS):
    """Values (one per point) and largest magnitudes of every distinct node of ``exprs``; None
    for a node with a function mpmath is not given here. ``points`` maps each leaf (symbol,
    applied function ``q(t)``, derivative ``q'(t)``) to its values; a leaf is not entered.
    Numbers are evaluated to ``digits`` + 10 digits; the caller sets mpmath's precision.
    Iterative: no recursion limit on deep DAGs. Also returns, for every node, whether it is
    constant (free of symbols)."""
    values, largest, constant = {}, {}, {}
    k = len(next(iter(points.values()))) if points else 1
    stack = list(exprs)
    while stack:
        e = stack[-1]
        if e in values:
            stack.pop()
            continue
        leaf = e in points
        if leaf or e.is_Symbol:
            out = points.get(e)
        elif e.is_Number or e.is_NumberSymbol:
            out = [mpmath.mpmathify(e.evalf(digits + 10))] * k
        elif not e.args:
            out = None
        else:
            pending = [a for a in e.args if a not in values]
            if pending:
                stack.extend(pending)
                continue
            args = [values[a] for a in e.args]
            out = None
            if all(a is not None for a in args):
                columns = list(zip(*args, strict=True))
                try:
                    if e.is_Add:
                        out = [mpmath.fsum(c) for c in columns]
                    elif e.is_Mul:
                        out = [mpmath.fprod(c) for c in columns]
                    elif e.is_Pow:
                        out = [mpmath.power(b, x) for b, x in columns]
                    elif e.func in _MPMATH:
                        out = [_MPMATH[e.func](*c) for c in columns]
                except (ZeroDivisionError, ValueError, TypeError):
                    out = None
        stack.pop()
        values[e] = out
        constant[e] = not (leaf or e.is_Symbol) and all(constant[a] for a in e.args)
        if out is None:
            largest[e] = None
        else:
            sub = [] if leaf else [largest[a] for a in e.args if a in largest]
            here = [abs(v) for v in out]
            for s in sub:
                here = [max(h, x) for h, x in zip(here, s, strict=True)] if s else here
            largest[e] = here
    return values, largest, constant


def _point_verdict(value, largest):
    """The verdict of one probe point: True (zero: at most ``FOLD_ZERO_RELATIVE`` of the
    largest magnitude), False (not zero: above ``SAMPLED_NONZERO_RELATIVE`` of it, finite),
    None (between, or not evaluated, or not finite)."""
    if value is None or largest is None:
        return None
    if not (mpmath.isfinite(value) and mpmath.isfinite(largest)):
        return None
    size = abs(value)
    if size <= FOLD_ZERO_RELATIVE * largest:
        return True
    if size > SAMPLED_NONZERO_RELATIVE * largest:
        return False
    return None


def _connected(atom) -> bool:
    """Whether the values the assumptions of ``atom`` allow form a connected set (a real
    "nonzero" without a sign does not: two half-lines)."""
    return not (atom.is_nonzero and atom.is_positive is not True
                and atom.is_negative is not True)


def _branch_free(base) -> bool:
    """Whether a power with a non-integer exponent (or a logarithm) of ``base`` is analytic
    over every value the assumptions allow: ``base`` positive there, on a connected set."""
    return base.is_positive is True and all(
        _connected(a) for a in base.atoms(sp.Symbol, sp.core.function.AppliedUndef))


def _node(e, skip, leaves):
    """Whether the node ``e`` itself keeps an expression meromorphic (see
    :func:`sampled_zero_decision`), and the arguments to look into; a leaf to sample (a symbol
    but those in ``skip``, an applied function ``q(t)``, a derivative of one) joins ``leaves``."""
    if e.is_Symbol:
        if e in skip:
            return False, ()
        leaves.add(e)
        return True, ()
    if isinstance(e, sp.core.function.AppliedUndef):
        leaves.add(e)
        return True, ()
    if isinstance(e, sp.Derivative):
        if isinstance(e.expr, sp.core.function.AppliedUndef):
            leaves.add(e)
            return True, ()
        return False, ()
    if e.is_Number or e.is_NumberSymbol or e is sp.S.ImaginaryUnit:
        return True, ()
    if e.is_Add or e.is_Mul or e.func in _MEROMORPHIC:
        return True, e.args
    if e.is_Pow:
        return bool(e.exp.is_Integer or not e.free_symbols or _branch_free(e.base)), e.args
    return (not e.free_symbols or (e.func is sp.log and _branch_free(e.args[0]))), e.args


def _leaves(exprs, skip):
    """The leaves to sample in ``exprs`` and, for every distinct node, whether it is
    meromorphic in them over a connected set of admissible values (see
    :func:`sampled_zero_decision`). One iterative walk over the shared DAG."""
    leaves, analytic = set(), {}
    stack = list(exprs)
    while stack:
        e = stack[-1]
        if e in analytic:
            stack.pop()
            continue
        own, inner = _node(e, skip, leaves)
        pending = [x for x in inner if x not in analytic]
        if pending:
            stack.extend(pending)
            continue
        stack.pop()
        analytic[e] = own and all(analytic[x] for x in inner)
    return sorted(leaves, key=sp.default_sort_key), analytic


def _sign(atom):
    """The sign of the sample values of ``atom`` (-1 for a negative atom), or None when a
    number in (0.5, 1.5) (not an integer), or its opposite, breaks an assumption ``atom``
    declares (an integer symbol, a symbol declared even, ...)."""
    negative = bool(atom.is_negative or atom.is_nonpositive)
    facts = dict(_SAMPLE_FACTS)
    for i, name in enumerate(_SIGN_FACTS):
        facts[name] = (i >= 4) == negative
    for name, fact in facts.items():
        declared = getattr(atom, "is_" + name, None)
        if declared is not None and declared != fact:
            return None
    return -1 if negative else 1


def sampled_zero_decision(expr, skip=(), *, seed=0) -> bool | None:
    """Whether the scalar ``expr`` vanishes for every value of its symbols (but those in
    ``skip``), decided by its values at random points without algebra: True, False, or None
    when the sample does not decide (then decide with ``sympy.simplify``).

    The points: every symbol, applied function ``q(t)`` and derivative ``q'(t)`` drawn
    independently, uniformly in (0.5, 1.5), negative for a negative atom; an atom whose
    declared assumptions such a number would break (integer, even, ...) or a symbol in ``skip``
    left out. The value at each of ``SAMPLED_POINTS`` points is computed with ``FOLD_DIGITS``
    (64) digits and compared with the largest magnitude L met while evaluating it (constants,
    sample values, intermediate results).

    * False when, at some point, the value exceeds ``SAMPLED_NONZERO_RELATIVE`` (1e-30) L: an
      admissible value of the symbols where the expression is not zero (the rounding of 64
      digits is ~1e-64 L, 34 orders below).
    * True when, at every point, the value is at most ``FOLD_ZERO_RELATIVE`` (1e-40) L, and
      the expression is meromorphic in its atoms over a connected set of admissible values:
      made of numbers, sums, products, integer powers, sin, cos, tan, exp, sinh, cosh, tanh,
      and powers or logarithms only of bases positive for every admissible value (sqrt of
      positive-declared constants). Such an expression that is not identically zero vanishes
      only on a set of measure zero (identity theorem; Schwartz--Zippel for polynomials of
      degree d: probability at most d / 2**52 per point for 53-bit samples), so the chance
      that two independent random points both fall within 1e-40 L of it is negligible; that
      the functions ``q(t)`` and their derivatives are sampled independently is exact, since
      any values of q, q', ... at an instant are those of some function.
    * None otherwise: values between the thresholds (near-cancellation), a point where the
      evaluation fails (a pole, a function mpmath is not given here), or an expression that
      is not shown meromorphic (``Abs``, ``atan``, ``sqrt`` of a base of unknown sign:
      ``atan(tan(a)) - a`` vanishes on the sampled interval but not at a = 3), or with
      integer symbols.

    The limit of any sampling at a finite precision: an exact expression whose value is below
    1e-40 of its own terms everywhere (a constant 1e-45, or 1e45 times an identity, next to
    terms of order one) is taken for zero; quantities in mechanics do not span 40 orders.
    Float constants count as the exact binary numbers they are (for the rounding of floats,
    see :func:`~rigidmech._core.symbolic.vanishes`).

    Parameters
    ----------
    expr : sympy expression
    skip : iterable of sympy symbols
        Symbols not given values (an expression with one of them is not decided True).
    seed : int
        Seed of the random points (fixed: the verdict does not change between runs).

    Returns
    -------
    bool or None

    Examples
    --------
    >>> a, b = sp.symbols("a b")
    >>> rotation = sp.sin(a + b) - sp.sin(a) * sp.cos(b) - sp.cos(a) * sp.sin(b)
    >>> sampled_zero_decision(rotation), sampled_zero_decision(sp.sin(a - b))
    (True, False)
    >>> sampled_zero_decision(sp.atan(sp.tan(a)) - a) is None
    True
    """
    expr = sp.sympify(expr)
    if expr.is_Number:
        return bool(expr == 0)
    with mpmath.workdps(FOLD_DIGITS):
        return sampled_decisions([expr], skip, seed=seed)[0][0]


def sampled_decisions(exprs, skip=(), *, seed=0):
    """The decisions of :func:`sampled_zero_decision` on every expression of ``exprs`` (the
    same rule: points, thresholds, analyticity), sampled at the same points, and the values
    at them: ``(decisions, (values, largest, constant))``, as :func:`_probe_values` gives
    them (for :func:`~rigidmech._core.symbolic.fold_numbers`). An atom that cannot be sampled
    (see :func:`sampled_zero_decision`) is given no value: an expression with it is not
    decided. Call it with mpmath's precision set to ``FOLD_DIGITS``.

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> with mpmath.workdps(FOLD_DIGITS):
    ...     decisions, _ = sampled_decisions([sp.sin(a)**2 + sp.cos(a)**2 - 1, sp.Abs(a) - a, a])
    >>> decisions
    [True, None, False]
    """
    exprs = [sp.sympify(e) for e in exprs]
    leaves, analytic = _leaves(exprs, frozenset(skip))
    rng = random.Random(seed)
    points = {}
    for atom in leaves:
        sign = _sign(atom)
        samples = [rng.uniform(0.5, 1.5) for _ in range(SAMPLED_POINTS)]
        if sign is not None and 1.0 not in samples:
            points[atom] = [mpmath.mpf(sign * x) for x in samples]
    values, largest, constant = _probe_values(exprs, points)
    decisions = []
    for e in exprs:
        value, size = values[e], largest[e]
        verdicts = [None] if value is None else [
            _point_verdict(v, m) for v, m in zip(value, size, strict=True)]
        if False in verdicts:
            decisions.append(False)
        elif analytic[e] and all(v is True for v in verdicts):
            decisions.append(True)
        else:
            decisions.append(None)
    return decisions, (values, largest, constant)
