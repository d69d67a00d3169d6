"""How the values of a derivation report are shown: plain symbols for the parameters of
situation, optional simplification, long expressions named (``sympy.cse``), and the printers
for plain text and LaTeX.

The values a report keeps (torsors, vectors, matrices, expressions) are the library's own,
written with q(t), q'(t) and q''(t). Shown, they are rewritten with the plain symbols of
:meth:`System.symbols <rigidmech.dynamics.System.symbols>` (``theta1``, ``theta1_dot``,
``theta1_ddot``; in LaTeX with a dot or two dots over the coordinate's name), simplified if
asked, and every scalar longer than ``max_ops`` operations (``sympy.count_ops``) is named: the
long scalars of the whole report go through one ``sympy.cse`` (their common subexpressions
become z1, z2, ...) and any that is still long after it gets a name of its own. The names and
their definitions are the report's last step.

Examples
--------
>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> is_long(sp.sin(x) + x, 2), is_long(sp.sin(x) + x, 1)
(False, True)
"""

from __future__ import annotations

from typing import NamedTuple

import sympy as sp
from sympy.printing.latex import LatexPrinter

from .._core.errors import ArgumentError, ArgumentTypeError
from ..torsors import Torsor
from ..vectors import Vector

__all__ = ["Words", "Relation", "Display", "is_long", "tex_name", "tex_text", "check_max_ops"]


class Words(NamedTuple):
    """A label or a formula made of names, in plain text and in LaTeX.

    Examples
    --------
    >>> Words("{V(bar/R0)}", r"\\{\\mathcal{V}(\\mathrm{bar}/R_{0})\\}").text
    '{V(bar/R0)}'
    """

    text: str
    latex: str


class Relation(NamedTuple):
    """``lhs = rhs``, both sympy expressions (an equation of the report).

    Examples
    --------
    >>> import sympy as sp
    >>> Relation(sp.Symbol("a"), sp.Integer(2)).rhs
    2
    """

    lhs: object
    rhs: object
    termwise: bool = False   # simplify the left side term by term (keeps M_ij q_j'' apart)


def check_max_ops(max_ops):
    """``max_ops`` as an int >= 1, or a clear error.

    Examples
    --------
    >>> check_max_ops(40)
    40
    """
    if isinstance(max_ops, bool) or not isinstance(max_ops, int):
        raise ArgumentTypeError(
            f"`max_ops` must be an int (the number of operations above which an expression is "
            f"named); got {type(max_ops).__name__}. Pass e.g. max_ops=40.")
    if max_ops < 1:
        raise ArgumentError(
            f"`max_ops` must be >= 1 (the number of operations above which an expression is "
            f"named); got {max_ops}. Pass e.g. max_ops=40.")
    return max_ops


def is_long(expr, max_ops) -> bool:
    """Whether ``expr`` has more than ``max_ops`` operations (``sympy.count_ops``): the one
    rule by which a report names an expression instead of printing it.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> sp.count_ops(x * y + x), is_long(x * y + x, 2), is_long(x * y + x, 1)
    (2, False, True)
    """
    return sp.count_ops(expr) > max_ops


def tex_text(text) -> str:
    """``text`` with LaTeX's special characters escaped, for ``\\mathrm``/``\\texttt``.

    Examples
    --------
    >>> tex_text("bar_1 & co")
    'bar\\\\_1 \\\\& co'
    """
    out = []
    for ch in str(text):
        if ch in "&%$#_{}":
            out.append("\\" + ch)
        elif ch == "\\":
            out.append(r"\textbackslash{}")
        elif ch in "^~":
            out.append(rf"\char`\{ch}")
        else:
            out.append(ch)
    return "".join(out)


def tex_name(name) -> str:
    """A body's, an action's or a frame's name in LaTeX: roman, special characters escaped.

    Examples
    --------
    >>> tex_name("bar1")
    '\\\\mathrm{bar1}'
    """
    return rf"\mathrm{{{tex_text(name)}}}"


def _map_scalars(value, func):
    """``value`` (expression, Vector, Torsor, matrix, tuple, Relation, Words) with ``func``
    applied to each of its scalars."""
    if isinstance(value, Words) or value is None:
        return value
    if isinstance(value, Relation):
        lhs = (sp.Add(*[func(a) for a in sp.Add.make_args(value.lhs)]) if value.termwise
               else func(value.lhs))
        return Relation(lhs, func(value.rhs), value.termwise)
    if isinstance(value, Torsor):
        return Torsor(value.resultant.applyfunc(func), value.moment.applyfunc(func), value.point)
    if isinstance(value, Vector):
        return value.applyfunc(func)
    if isinstance(value, sp.MatrixBase):
        return sp.ImmutableMatrix(value.applyfunc(func))
    if isinstance(value, (tuple, sp.Tuple)):
        return sp.Tuple(*[func(x) for x in value])
    return func(sp.sympify(value))


class Display:
    """The shown form of the values of one report: plain symbols, simplification, names.

    Parameters
    ----------
    rule : dict
        q(t), q'(t), q''(t) -> plain symbols (:meth:`System.symbols`).
    dots : dict
        plain symbol -> its LaTeX (a dot over the rate, two over the acceleration).
    simplify : bool
        Simplify each scalar shown (``sympy.simplify``).
    max_ops : int
        Scalars with more operations are named.

    Examples
    --------
    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> d = Display({}, {}, simplify=True, max_ops=3)
    >>> shown = d.prepare([sp.sin(x)**2 + sp.cos(x)**2, sp.Tuple(*[x**k for k in range(6)])])
    >>> d.name_long(shown)
    >>> d.text(shown[0]), d.named
    ('1', ())
    """

    def __init__(self, rule, dots, *, simplify, max_ops):
        self._rule = rule
        self._simplify = bool(simplify)
        self._max_ops = max_ops
        self._memo = {}
        self._final = {}
        self.named = ()
        self._printer = LatexPrinter({"symbol_names": dict(dots)})

    def _scalar(self, expr):
        expr = sp.sympify(expr)
        hit = self._memo.get(expr)
        if hit is None:
            hit = expr.xreplace(self._rule)
            if self._simplify and hit.free_symbols:
                hit = sp.simplify(hit)
            self._memo[expr] = hit
        return hit

    def prepare(self, values):
        """The values rewritten with plain symbols (and simplified): call once with every
        value of the report, then :meth:`name_long` with the result."""
        return [_map_scalars(v, self._scalar) for v in values]

    def name_long(self, prepared):
        """Name the long scalars of the ``prepared`` values (one ``sympy.cse`` for all)."""
        longs = []
        seen = set()

        def collect(e):
            if e not in seen and is_long(e, self._max_ops):
                seen.add(e)
                longs.append(e)
            return e

        for v in prepared:
            _map_scalars(v, collect)
        if not longs:
            return
        used = {s.name for e in longs for s in e.free_symbols}
        prefix = next((p for p in ("z", "zeta", "w_", "xi") if not any(
            n.startswith(p) for n in used)), "named_")
        names = sp.numbered_symbols(prefix, start=1)
        replacements, reduced = sp.cse(longs, symbols=names, order="none")
        named = list(replacements)
        for k, e in enumerate(reduced):
            if is_long(e, self._max_ops):
                s = next(names)
                named.append((s, e))
                reduced[k] = s
        self._final = dict(zip(longs, reduced, strict=True))
        self.named = tuple(named)

    def final(self, value):
        """A prepared value with its long scalars replaced by their names."""
        return _map_scalars(value, lambda e: self._final.get(e, e))

    # -- printers -------------------------------------------------------------------------
    def text(self, value) -> str:
        """Plain text of a final value."""
        if isinstance(value, Words):
            return value.text
        if isinstance(value, Relation):
            return f"{sp.sstr(value.lhs)} = {sp.sstr(value.rhs)}"
        if isinstance(value, (Vector, Torsor)):
            return str(value)
        if isinstance(value, sp.MatrixBase):
            return sp.sstr(value.tolist())
        if isinstance(value, sp.Tuple):
            return "(" + ", ".join(sp.sstr(x) for x in value) + ")"
        return sp.sstr(value)

    def latex(self, value) -> str:
        """LaTeX (math mode) of a final value; matrices as amsmath's ``bmatrix``."""
        p = self._printer
        if isinstance(value, Words):
            return value.latex
        if isinstance(value, Relation):
            return f"{p.doprint(value.lhs)} = {p.doprint(value.rhs)}"
        if isinstance(value, (Vector, Torsor)):
            return value._latex(p)
        if isinstance(value, sp.MatrixBase):
            rows = r" \\ ".join(" & ".join(p.doprint(x) for x in row)
                                for row in value.tolist())
            return rf"\begin{{bmatrix}} {rows} \end{{bmatrix}}"
        return p.doprint(value)
