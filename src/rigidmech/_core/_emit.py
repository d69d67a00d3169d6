"""From the eliminated DAG to code, in one pass (private, for :mod:`rigidmech._core.compile`).

The subexpressions :mod:`rigidmech._core._cse` finds repeated are named ``_x0, _x1, ...`` and
every expression is printed for both code paths of a compiled function while walking the
DAG once: no sympy expression is rebuilt for the printers and no printer visits a node twice.
"""

import math

import sympy

from . import _cse

__all__: list[str] = []


class Code:
    """One expression printed for both code paths: ``math`` (single state: floats and the
    ``math`` module) and ``array`` (numpy over a batch), with the operation count of the
    ``math`` code (:func:`~rigidmech._core._codegen.count_operations`)."""

    __slots__ = ("array", "math", "ops")

    def __init__(self, math_code, array_code, ops):
        self.math = math_code
        self.array = array_code
        self.ops = ops

    def __repr__(self):
        return f"Code({self.math!r}, {self.array!r}, {self.ops})"


#: Precedence of a printed piece (what it may be an operand of without parentheses):
#: a name, number or call; a power; a product, quotient or negation; a sum.
_ATOM, _POW, _MUL, _ADD = 4, 3, 2, 1

#: Functions of one argument printed from a template (``math.sin(_)``, ``numpy.sin(_)``)
#: taken from the printers once per run; any other function goes through the printers.
_TEMPLATED = (sympy.sin, sympy.cos, sympy.tan, sympy.exp, sympy.log, sympy.asin, sympy.acos,
              sympy.atan, sympy.sinh, sympy.cosh, sympy.tanh)


def generate(flat, use_cse, math_printer, array_printer):
    """``(replacements, reduced)`` of the flat expression list as code: ``replacements`` a
    list of ``(name, Code)`` to assign in order (``_x0, _x1, ...``), ``reduced`` one
    :class:`Code` per expression.

    The elimination of :mod:`rigidmech._core._cse` (the common sub-sums and sub-products of
    :func:`~rigidmech._core._cse.common_arguments`, then every subexpression met twice
    named), with the naming pass printing the code directly instead of rebuilding sympy
    expressions for the printers: rebuilding (``Mul`` re-flattened and re-sorted, 0.3 s on
    the 3D chain of 6 links) and sympy's printers (precedence and dispatch per node, twice:
    0.5 to 0.7 s) were half of the compilation of the planar 20-link pendulum and of that chain
    (``benchmarks/first_rhs.py``). Sums, products, integer and half powers, symbols,
    numbers and the functions of ``_TEMPLATED`` are printed here, by the rules of the
    printers (``_MathPrinter``: ``x*x`` for a name squared, ``1/x``, ``math.sqrt``);
    anything else by the printers themselves, its arguments standing in as symbols printed
    as their code. ``_cse._CSE_OPTIMIZATIONS`` other than None go through ``sympy.cse`` and
    the printers (for comparisons).
    """
    flat = list(flat)
    if _cse._CSE_OPTIMIZATIONS is not None and use_cse:
        replacements, reduced = _cse.sympy_cse(flat)
        return ([(symbol.name, _printed(rhs, math_printer, array_printer))
                 for symbol, rhs in replacements],
                [_printed(e, math_printer, array_printer) for e in reduced])
    opt_subs = _cse.common_arguments(flat) if use_cse else {}
    to_name, taken = _cse.repeated(flat, opt_subs) if use_cse else (set(), set())
    emitter = _Emitter(opt_subs, to_name, taken, math_printer, array_printer)
    reduced = []
    for e in flat:
        m, r, _, ops = emitter.emit(e)
        reduced.append(Code(m, r, ops))
    return emitter.lines, reduced


def _printed(expr, math_printer, array_printer):
    from ._codegen import count_operations, print_expr

    code = print_expr(math_printer, expr)
    return Code(code, print_expr(array_printer, expr), count_operations([code]))


def _number(e):
    """``(code, precedence, operations)`` of a finite sympy number, or None (a negative
    number is a negation, a fraction a division, as Python's syntax tree has them)."""
    if e.is_Integer:
        value = int(e)
        return (str(value), _ATOM, 0) if value >= 0 else (str(value), _MUL, 1)
    if e.is_Rational:
        return f"{e.p}/{e.q}", _MUL, 1 if e.p > 0 else 2
    if e.is_Float:
        value = float(e)
        if math.isfinite(value):
            return (repr(value), _ATOM, 0) if value >= 0 else (repr(value), _MUL, 1)
    return None


def _wrap(code, prec, least):
    return code if prec >= least else f"({code})"


class _Emitter:
    """The naming pass of :func:`generate`: ``emit(e)`` returns ``(math, array, precedence,
    operations)`` of node `e` (its code inline: a name if it is named), appending an
    assignment to ``lines`` for every node of ``to_name``.

    The operations are counted as the code is written, by the rule of
    :func:`~rigidmech._core._codegen.count_operations` (operators, negations and calls of
    the ``math`` code; a piece printed by sympy's printers is counted on its code): counting
    on the code's syntax tree afterwards took 0.1 to 0.3 s on the planar 20-link pendulum and
    the 3D chain of 6 links.
    """

    def __init__(self, opt_subs, to_name, taken, math_printer, array_printer):
        self.opt_subs, self.to_name = opt_subs, to_name
        self.printers = (math_printer, array_printer)
        self.memo, self.lines, self.templates = {}, [], {}
        self.names = (s.name for s in sympy.numbered_symbols("_x") if s.name not in taken)

    def emit(self, e):
        hit = self.memo.get(e)
        if hit is not None:
            return hit
        source = self.opt_subs.get(e, e)
        if isinstance(source, sympy.Basic) and source.is_Atom:
            out = self._atom(source)
        else:
            func = source.func
            if func is sympy.Add:
                out = self._add(source.args)
            elif func is sympy.Mul:
                out = self._mul(source.args, False)
            elif func is sympy.Pow:
                out = self._pow(*source.args)
            elif func in _TEMPLATED and len(source.args) == 1:
                out = self._call(func, source.args[0])
            else:
                out = self._fallback(source)
        if e in self.to_name and (isinstance(e, sympy.Expr)
                                  or not isinstance(e, sympy.Basic)):  # or Unevaluated
            name = next(self.names)
            self.lines.append((name, Code(out[0], out[1], out[3])))
            out = (name, name, _ATOM, 0)
        self.memo[e] = out
        return out

    # -- leaves ---------------------------------------------------------------------------

    def _atom(self, e):
        number = _number(e) if e.is_Number else None
        if number is not None:
            return number[0], number[0], number[1], number[2]
        if e.is_Symbol:
            math_code, array_code = (p.doprint(e) for p in self.printers)
            return math_code, array_code, _ATOM, 0
        return self._fallback(e)

    # -- sums, products, powers -------------------------------------------------------------

    def _negative_product(self, e):
        """The factors of `e` if it is a product with a negative number among them (printed
        as a subtraction in a sum), else None; a named product is not looked into."""
        if e in self.to_name or e in self.memo:
            return None
        source = self.opt_subs.get(e, e)
        if source.func is not sympy.Mul:
            return None
        for a in source.args:
            if isinstance(a, sympy.Basic) and a.is_Number and a.is_extended_negative:
                return source.args
        return None

    def _add(self, args):
        math_parts, array_parts, ops = [], [], len(args) - 1
        for k, a in enumerate(args):
            factors = self._negative_product(a)
            if factors is not None:
                m, r, p, n = self._mul(factors, True)
                negative = True
            elif isinstance(a, sympy.Basic) and a.is_Number and a.is_extended_negative:
                m, r, p, n = self._atom(-a)
                negative = True
            else:
                m, r, p, n = self.emit(a)
                negative = False
            ops += n
            if negative:
                sign, least = ("-" if k == 0 else " - "), _MUL
                ops += k == 0               # a leading minus is a negation
            else:
                sign, least = ("" if k == 0 else " + "), (_ADD if k == 0 else _MUL)
            math_parts.append(sign + _wrap(m, p, least))
            array_parts.append(sign + _wrap(r, p, least))
        if len(args) == 1:
            return math_parts[0], array_parts[0], _MUL if negative else p, ops
        return "".join(math_parts), "".join(array_parts), _ADD, ops

    def _mul(self, args, negate):
        """A product (negated if `negate`): numbers first, then the factors, then ``/`` and
        the factors with a negative integer exponent, as sympy's printers write it."""
        coeff = sympy.S.NegativeOne if negate else sympy.S.One
        numerators, denominators = [], []
        for a in args:
            if isinstance(a, sympy.Basic) and a.is_Number:
                coeff *= a
            elif (isinstance(a, sympy.Pow) and a.exp.is_Integer and a.exp < 0
                  and a not in self.to_name and a not in self.opt_subs):
                denominators.append(self._pow(a.base, -a.exp))
            else:
                numerators.append(self.emit(a))
        negative = coeff.is_extended_negative
        if negative:
            coeff = -coeff
        if coeff != 1 or not numerators:
            numerators.insert(0, self._atom(coeff))
        if len(numerators) == 1 and not denominators and not negative:
            return numerators[0]
        math_code = "*".join(_wrap(m, p, _POW) for m, _, p, _ in numerators)
        array_code = "*".join(_wrap(r, p, _POW) for _, r, p, _ in numerators)
        ops = len(numerators) - 1 + sum(n for *_, n in numerators)
        if denominators:
            ops += len(denominators) + sum(n for *_, n in denominators)
            math_den = "*".join(_wrap(m, p, _POW) for m, _, p, _ in denominators)
            array_den = "*".join(_wrap(r, p, _POW) for _, r, p, _ in denominators)
            if len(denominators) > 1:
                math_den, array_den = f"({math_den})", f"({array_den})"
            math_code, array_code = f"{math_code}/{math_den}", f"{array_code}/{array_den}"
        if negative:
            return "-" + math_code, "-" + array_code, _MUL, ops + 1
        return math_code, array_code, _MUL, ops

    def _pow(self, base, exponent):
        if exponent.is_Rational and exponent.q == 2 and abs(exponent.p) == 1:
            m, r, _, n = self.emit(base)
            m, r = f"math.sqrt({m})", f"numpy.sqrt({r})"
            if exponent.is_negative:
                return f"1/{m}", f"1/{r}", _MUL, n + 2
            return m, r, _ATOM, n + 1
        if not exponent.is_Integer:
            return self._fallback(sympy.Pow(base, exponent, evaluate=False))
        k = int(exponent)
        m, r, p, n = self.emit(base)
        if k == 1:
            return m, r, p, n
        if p == _ATOM and m.isidentifier() and k in (2, 3, -2):
            m = "(" + "*".join([m] * abs(k)) + ")"
            r = "(" + "*".join([r] * abs(k)) + ")"
            if k < 0:
                return f"(1/{m})", f"(1/{r})", _ATOM, abs(k)
            return m, r, _ATOM, k - 1
        m, r = _wrap(m, p, _ATOM), _wrap(r, p, _ATOM)
        if k == -1:
            return f"1/{m}", f"1/{r}", _MUL, n + 1
        power = str(k) if k > 0 else f"({k})"
        return f"{m}**{power}", f"{r}**{power}", _POW, n + 1 + (k < 0)

    # -- functions and the rest ---------------------------------------------------------------

    def _call(self, func, arg):
        template = self.templates.get(func)
        if template is None:
            template = self.templates[func] = self._template(func)
        if not template:
            return self._fallback(func(arg))
        (mb, ma), (rb, ra), ops = template
        m, r, _, n = self.emit(arg)
        return mb + m + ma, rb + r + ra, _ATOM, n + ops

    def _template(self, func):
        """``((before, after), (before, after), operations)`` around the argument in each
        printer's code of ``func(x)``, or () if that code does not hold x exactly once."""
        from ._codegen import count_operations, print_expr

        x = sympy.Dummy("x")
        out = []
        for printer in self.printers:
            printer._names[x] = "_ARG_"
            try:
                parts = print_expr(printer, func(x, evaluate=False)).split("_ARG_")
            finally:
                del printer._names[x]
            if len(parts) != 2:
                return ()
            out.append(tuple(parts))
        return out[0], out[1], count_operations([out[0][0] + "x" + out[0][1]])

    def _fallback(self, e):
        """``e`` printed by the printers, its arguments that are expressions standing in as
        symbols printed as their code (parenthesised); its operations counted on its code."""
        from ._codegen import count_operations, print_expr

        stand_ins = ({}, {})

        def rebuild(x):
            if not isinstance(x, sympy.Basic) or x.is_Atom:
                return x
            if isinstance(x, sympy.Expr):
                m, r, _, _ = self.emit(x)
                s = sympy.Dummy()
                stand_ins[0][s], stand_ins[1][s] = f"({m})", f"({r})"
                return s
            return x.func(*[rebuild(a) for a in x.args])

        if isinstance(e, sympy.Basic) and not e.is_Atom:
            e = e.func(*[rebuild(a) for a in e.args])
        codes = []
        for printer, names in zip(self.printers, stand_ins, strict=True):
            printer._names.update(names)
            try:
                codes.append(print_expr(printer, e))
            finally:
                for s in names:
                    del printer._names[s]
        return f"({codes[0]})", f"({codes[1]})", _ATOM, count_operations([codes[0]])
