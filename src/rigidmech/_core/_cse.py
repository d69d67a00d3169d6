"""Common-subexpression elimination for :mod:`rigidmech._core.compile` (private).

sympy's own algorithm (``match_common_args`` of ``sympy.simplify.cse_main``) with a lighter
driver than ``sympy.cse``: derived equations of motion are large DAGs (the forcing of a 3D
chain of 6 links on ball joints is 10 million operations as a tree, 16 000 after
elimination) and every pass must visit each distinct subexpression once. The naming of
repeated subexpressions and the printing are one pass, in :mod:`rigidmech._core._emit`.
"""

from collections import OrderedDict, defaultdict

import sympy
from sympy.simplify.cse_main import Unevaluated

__all__: list[str] = []

#: cse settings (:func:`sympy_cse`).  ``optimizations="basic"`` was measured on the n-link
#: pendulum's Kane equations (benchmarks/compile_rhs.py): at n = 5 it cut no operation and
#: made cse slower, so it is off (None: the lighter passes here, not sympy.cse);
#: ``order="none"`` keeps the (already canonical) order and saves sorting time.
_CSE_OPTIMIZATIONS = None
_CSE_ORDER = "none"


def sympy_cse(flat):
    """``sympy.cse`` of `flat` with ``_CSE_OPTIMIZATIONS`` (the route kept for comparisons)."""
    return sympy.cse(list(flat), symbols=sympy.numbered_symbols("_x"),
                     optimizations=_CSE_OPTIMIZATIONS, order=_CSE_ORDER)


def common_arguments(flat):
    """The rewritings of sympy's ``opt_cse`` that share common sub-sums and sub-products
    (``x + y + z`` and ``sin(x + y)`` share ``x + y``), as ``{expression: Unevaluated}``;
    one walk over the distinct subexpressions.

    ``sympy.cse`` is two passes over the distinct subexpressions: ``opt_cse`` looks for
    rewritings that expose more sharing, then ``tree_cse`` names every subexpression met
    twice. Of ``opt_cse`` this keeps the one rewriting that pays on equations of motion
    (common sub-sums and sub-products, sympy's ``match_common_args``) and drops the negation
    pass (for every sum and product, can -e be shared with e?), which costs as much and saves
    nothing there. Measured before the naming and printing became one pass
    (benchmarks/first_rhs.py, mass matrix and forcing; seconds, operations of the generated
    code):

    ==========================  ==================  ==================  ==================
    equations                    sympy.cse           this + tree_cse     tree_cse alone
    ==========================  ==================  ==================  ==================
    3D chain, 4 ball joints      1.99 s, 5775 ops    0.66 s, 5352 ops    0.53 s, 8190 ops
    3D chain, 6 ball joints      9.58 s, 17044 ops   3.61 s, 15851 ops   0.91 s, 23457 ops
    planar 20-link pendulum      3.29 s, 11421 ops   2.43 s, 11451 ops   1.45 s, 18141 ops
    ==========================  ==================  ==================  ==================

    ``tree_cse`` alone is faster still, but its code costs up to twice as much per call (the
    common sub-sums and sub-products both pay: without either, 22118 and 17027 operations for
    the chain of 6).
    """
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
    _match_common_args(sympy.Add, list(adds), opt_subs)
    _match_common_args(sympy.Mul, list(muls), opt_subs)
    return opt_subs


def repeated(flat, opt_subs):
    """The subexpressions of `flat` reached twice (after the rewritings `opt_subs`), and the
    names of the symbols it holds: the first pass of sympy's ``tree_cse``."""
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
    return to_name, taken


# sympy's match_common_args and FuncArgTracker (sympy/simplify/cse_main.py, BSD licence),
# the same steps in the same order with Python dicts as ordered sets: sympy's OrderedSet is a
# MutableSet over an OrderedDict whose every operation goes through generic Python code, and
# was most of the 0.3 to 0.8 s match_common_args took on the planar 20-link pendulum and the
# 3D chain of 6 links. A dict keeps insertion order as OrderedDict does, so the result (the
# sub-sums and sub-products extracted) is the same. Hand-rolled because sympy's functions take
# their set type from their module.


class _ArgTracker:
    """sympy's ``FuncArgTracker``: functions to argument numbers and back, as ordered sets
    (dicts with None values)."""

    def __init__(self, funcs):
        self.value_numbers, self.value_number_to_value = {}, []
        self.arg_to_funcset, self.func_to_argset = [], []
        for func_i, func in enumerate(funcs):
            argset = {}
            for arg in func.args:
                number = self.number(arg)
                argset[number] = None
                self.arg_to_funcset[number][func_i] = None
            self.func_to_argset.append(argset)

    def args_in_value_order(self, argset):
        return [self.value_number_to_value[n] for n in sorted(argset)]

    def number(self, value):
        count = len(self.value_numbers)
        number = self.value_numbers.setdefault(value, count)
        if number == count:
            self.value_number_to_value.append(value)
            self.arg_to_funcset.append({})
        return number

    def stop_tracking(self, func_i):
        for arg in self.func_to_argset[func_i]:
            del self.arg_to_funcset[arg][func_i]

    def common_arg_candidates(self, argset, min_func_i):
        count_map = defaultdict(int)
        if not argset:
            return count_map
        funcsets = [self.arg_to_funcset[arg] for arg in argset]
        largest = max(funcsets, key=len)
        for funcset in funcsets:
            if funcset is largest:
                continue
            for func_i in funcset:
                if func_i >= min_func_i:
                    count_map[func_i] += 1
        smaller, larger = sorted([largest, count_map], key=len)
        for func_i in smaller:
            if count_map[func_i] < 1:
                continue
            if func_i in larger:
                count_map[func_i] += 1
        return {k: v for k, v in count_map.items() if v >= 2}

    def subset_candidates(self, argset, restrict):
        args = iter(argset)
        indices = dict.fromkeys(self.arg_to_funcset[next(args)])
        indices = {i: None for i in indices if i in restrict}
        for arg in args:
            funcset = self.arg_to_funcset[arg]
            indices = {i: None for i in indices if i in funcset}
        return indices

    def update(self, func_i, new_args):
        old_args = self.func_to_argset[func_i]
        for deleted in [a for a in old_args if a not in new_args]:
            del self.arg_to_funcset[deleted][func_i]
        for added in [a for a in new_args if a not in old_args]:
            self.arg_to_funcset[added][func_i] = None
        old_args.clear()
        old_args.update(new_args)


def _match_common_args(func_class, funcs, opt_subs):
    """sympy's ``match_common_args``: extract the common arguments of the sums (or products)
    `funcs` as sub-sums (sub-products), recorded in `opt_subs`."""
    funcs = sorted(funcs, key=lambda f: len(f.args))
    tracker = _ArgTracker(funcs)
    changed = {}
    for i in range(len(funcs)):
        counts = tracker.common_arg_candidates(tracker.func_to_argset[i], i + 1)
        candidates = OrderedDict.fromkeys(sorted(counts, key=lambda k: (counts[k], k)))
        while candidates:
            j = candidates.popitem(last=False)[0]
            argset_i, argset_j = tracker.func_to_argset[i], tracker.func_to_argset[j]
            com_args = {a: None for a in argset_i if a in argset_j}
            if len(com_args) <= 1:
                continue
            diff_i = {a: None for a in argset_i if a not in com_args}
            if diff_i:
                com_func = Unevaluated(func_class, tracker.args_in_value_order(com_args))
                com_number = tracker.number(com_func)
                diff_i[com_number] = None
                tracker.update(i, diff_i)
                changed[i] = None
            else:
                com_number = tracker.number(funcs[i])
            diff_j = {a: None for a in tracker.func_to_argset[j] if a not in com_args}
            diff_j[com_number] = None
            tracker.update(j, diff_j)
            changed[j] = None
            for k in tracker.subset_candidates(com_args, candidates):
                diff_k = {a: None for a in tracker.func_to_argset[k] if a not in com_args}
                diff_k[com_number] = None
                tracker.update(k, diff_k)
                changed[k] = None
        if i in changed:
            opt_subs[funcs[i]] = Unevaluated(
                func_class, tracker.args_in_value_order(tracker.func_to_argset[i]))
        tracker.stop_tracking(i)
