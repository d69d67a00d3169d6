"""Common-subexpression elimination for :mod:`rigidmech._core.compile` (private).

sympy's own building blocks (``match_common_args`` of ``sympy.simplify.cse_main``) with a
lighter driver than ``sympy.cse``: derived equations of motion are large DAGs (the forcing of
a 3D chain of 6 links on ball joints is 10 million operations as a tree, 16 000 after
elimination) and every pass must visit each distinct subexpression once.
"""

import sympy
from sympy.simplify.cse_main import match_common_args

__all__: list[str] = []

#: cse settings (:func:`common_subexpressions`).  ``optimizations="basic"`` was measured on the
#: n-link pendulum's Kane equations (benchmarks/compile_rhs.py): at n = 5 it cut no operation and
#: made cse slower, so it is off (None: the lighter passes here, not sympy.cse);
#: ``order="none"`` keeps the (already canonical) order and saves sorting time.
_CSE_OPTIMIZATIONS = None
_CSE_ORDER = "none"

#: Operations rebuilt unevaluated by :func:`_tree_cse`: sums only. Products rebuilt
#: unevaluated keep their numeric factors apart (2*(3*x)): 1.6 % more operations for the
#: planar 6-link pendulum (675 instead of 664), for no measurable gain in time.
_UNEVALUATED = (sympy.Add,)


def common_subexpressions(flat, use_cse):
    """Return ``(replacements, reduced)`` for the flat expression list, named ``_x0, _x1, ...``.

    ``sympy.cse`` is two passes, both over the distinct subexpressions (a DAG walk):
    ``opt_cse`` looks for rewritings that expose more sharing, then ``tree_cse`` names every
    subexpression met twice. Here ``opt_cse`` is replaced by :func:`_common_arguments`, which
    keeps its one rewriting that pays on equations of motion (common sub-sums and
    sub-products, sympy's ``match_common_args``) and drops the negation pass (for every sum
    and product, can -e be shared with e?), which costs as much and saves nothing there; and
    ``tree_cse`` by :func:`_tree_cse`, the same naming that rebuilds sums unevaluated
    (sympy's re-sorts and re-flattens each one: 1.5 times slower on the planar 20-link
    pendulum, for the same code). Measured with sympy's ``tree_cse`` (benchmarks/first_rhs.py,
    mass matrix and forcing; seconds, operations of the generated code):

    ==========================  ==================  ==================  ==================
    equations                    sympy.cse           this                tree_cse alone
    ==========================  ==================  ==================  ==================
    3D chain, 4 ball joints      1.99 s, 5775 ops    0.66 s, 5352 ops    0.53 s, 8190 ops
    3D chain, 6 ball joints      9.58 s, 17044 ops   3.61 s, 15851 ops   0.91 s, 23457 ops
    planar 20-link pendulum      3.29 s, 11421 ops   2.43 s, 11451 ops   1.45 s, 18141 ops
    ==========================  ==================  ==================  ==================

    ``tree_cse`` alone is faster still, but its code costs up to twice as much per call (the
    common sub-sums and sub-products both pay: without either, 22118 and 17027 operations for
    the chain of 6).
    ``_CSE_OPTIMIZATIONS`` other than None go through ``sympy.cse`` (for comparisons).
    """
    if not use_cse:
        return [], list(flat)
    if _CSE_OPTIMIZATIONS is not None:
        return sympy.cse(
            list(flat),
            symbols=sympy.numbered_symbols("_x"),
            optimizations=_CSE_OPTIMIZATIONS,
            order=_CSE_ORDER,
        )
    flat = list(flat)
    return _tree_cse(flat, _common_arguments(flat))


def _common_arguments(flat):
    """The rewritings of sympy's ``opt_cse`` that share common sub-sums and sub-products
    (``x + y + z`` and ``sin(x + y)`` share ``x + y``), for ``tree_cse``; one walk over the
    distinct subexpressions."""
    opt_subs, adds, muls, seen = {}, {}, {}, set()
    stack = list(flat)
    while stack:
        e = stack.pop()
        if e.is_Atom or e in seen:
            continue
        seen.add(e)
        stack.extend(e.args)
        if e.is_Add:
            adds[e] = None
        elif e.is_Mul and e.is_commutative:
            muls[e] = None
    match_common_args(sympy.Add, list(adds), opt_subs)
    match_common_args(sympy.Mul, list(muls), opt_subs)
    return opt_subs


def _tree_cse(flat, opt_subs):
    """``(replacements, reduced)``: every subexpression of `flat` reached twice named
    ``_x0, _x1, ...`` (skipping names of symbols in `flat`), `opt_subs` applied first.

    sympy's ``tree_cse`` with one change: a sum whose arguments changed is rebuilt
    unevaluated (``_UNEVALUATED``). Evaluating it again only re-sorts and re-flattens what was
    canonical already (its arguments are named symbols now); the printed code is the same.
    Hand-rolled because sympy's function has no option for it.
    """
    to_name, seen, taken = set(), set(), set()
    stack = list(flat)
    while stack:
        e = stack.pop()
        if isinstance(e, sympy.Basic) and e.is_Atom:
            if e.is_Symbol:
                taken.add(e.name)
            continue
        if e in seen:
            to_name.add(e)
            continue
        seen.add(e)
        stack.extend(opt_subs.get(e, e).args)
    symbols = (s for s in sympy.numbered_symbols("_x") if s.name not in taken)
    replacements, named, memo = [], {}, {}

    def rebuild(e):
        if not e.args:
            return e
        hit = named.get(e)
        if hit is None:
            hit = memo.get(e)
        if hit is not None:
            return hit
        source = opt_subs.get(e, e)
        args = [rebuild(a) for a in source.args]
        if not isinstance(source, sympy.Basic) or any(
                a is not b for a, b in zip(args, source.args, strict=True)):
            # a rewriting of opt_subs (sympy's Unevaluated), or new arguments
            if source.func in _UNEVALUATED:
                out = source.func(*args, evaluate=False)
            else:
                out = source.func(*args)
        else:
            out = source
        if e in to_name:
            symbol = next(symbols)
            replacements.append((symbol, out))
            named[e] = symbol
            return symbol
        memo[e] = out
        return out

    return replacements, [rebuild(e) for e in flat]
