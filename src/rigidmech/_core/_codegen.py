"""Private code generation for :mod:`rigidmech._core.compile`.

Two printers turn the same common-subexpression-eliminated (cse) expression list into Python
source: :class:`_MathPrinter` for the single-state path (plain Python floats and the ``math``
module, about ten times faster than numpy scalars) and :class:`_ArrayPrinter` for the vectorised
path (numpy / scipy.special ufuncs over arrays of states).  The generated source is compiled
once with :func:`compile` and kept for inspection and pickling.
"""

import ast
import builtins
import functools
import keyword
import math
import re

import numpy as np
import sympy
from sympy.core.function import AppliedUndef
from sympy.printing.codeprinter import PrintMethodNotImplementedError
from sympy.printing.numpy import SciPyPrinter
from sympy.printing.pycode import PythonCodePrinter
from sympy.tensor.array import NDimArray

from ._emit import Code, generate
from .errors import ArgumentError, ArgumentTypeError, CompilationError

__all__: list[str] = []

#: Names the generated code needs for itself: module names and builtins used by the printers.
_RESERVED = frozenset(dir(builtins)) | {"math", "numpy", "scipy", "functools", "self"}


#: Printer settings. ``order="none"`` prints the terms of a sum in the order sympy stores them
#: instead of sorting them (sympy's default ``as_ordered_terms``): the sort was 60 % of the
#: printing time of the planar 20-link pendulum (benchmarks/first_rhs.py), and the generated
#: code computes the same floating-point sum in another order only.
_PRINTER_SETTINGS = {"fully_qualified_modules": True, "strict": True, "order": "none"}


class _Named:
    """Printer mixin: symbols print under the names given at construction (``{symbol: name}``)
    when they have one, so that a Dummy or a symbol whose name is no identifier needs no
    rewriting of the expressions (a rewrite of a large DAG costs seconds)."""

    def _print_Symbol(self, expr):
        name = self._names.get(expr)
        return name if name is not None else super()._print_Symbol(expr)

    def _print_Dummy(self, expr):
        name = self._names.get(expr)
        return name if name is not None else super()._print_Dummy(expr)


class _MathPrinter(_Named, PythonCodePrinter):
    """Python printer for the single-state path: floats and the ``math`` module.

    Departures from :class:`~sympy.printing.pycode.PythonCodePrinter`:

    * a non-integer power prints as ``math.pow(b, e)``, which raises ``ValueError`` for a
      negative base instead of silently returning a complex number as ``b ** e`` does; the
      caller then re-evaluates with numpy (giving ``nan`` like the vectorised path);
    * small integer powers of a symbol print as products (``x*x``), faster for floats;
    * a function the ``math`` module lacks (``re``, ``besselj``, ...) prints with the
      scipy/numpy printer: it still works on floats, only slower.
    """

    def __init__(self, names=None):
        super().__init__(_PRINTER_SETTINGS)
        self._names = dict(names or {})
        self._fallback = _ArrayPrinter(names)

    def _print_Pow(self, expr, rational=False):
        exponent = expr.exp
        if expr.base.is_Symbol and exponent in (2, 3, -2):
            # Python float multiplication costs about a third of float ** int
            product = "*".join([self._print(expr.base)] * abs(int(exponent)))
            return f"(1/({product}))" if exponent < 0 else f"({product})"
        if exponent.is_Integer or exponent in (sympy.S.Half, -sympy.S.Half):
            return super()._print_Pow(expr, rational=rational)
        if exponent.is_number:
            exponent = sympy.Float(exponent, 17)
        return f"math.pow({self._print(expr.base)}, {self._print(exponent)})"

    def _print_not_supported(self, expr):
        return self._fallback._print(expr)


class _ArrayPrinter(_Named, SciPyPrinter):
    """numpy / scipy.special printer for the vectorised path.

    Small integer powers of a symbol print as products, as on the single-state path: both
    paths then round the same products the same way (``x**3`` goes through ``pow``, which may
    differ from ``x*x*x`` by an ulp, enough to tell the paths apart after a cancellation).
    """

    def __init__(self, names=None):
        super().__init__(_PRINTER_SETTINGS)
        self._names = dict(names or {})

    def _print_Pow(self, expr, rational=False):
        if expr.base.is_Symbol and expr.exp in (2, 3, -2):
            product = "*".join([self._print(expr.base)] * abs(int(expr.exp)))
            return f"(1/({product}))" if expr.exp < 0 else f"({product})"
        return super()._print_Pow(expr, rational=rational)

    def _print_not_supported(self, expr):
        raise CompilationError(
            f"`exprs` contain {sympy.sstr(expr)} which has no numeric translation in numpy or "
            "scipy.special; replace that function or substitute it first."
        )


def print_expr(printer, expr):
    """Print one expression, turning a printer failure into a :class:`CompilationError`; an
    expression already printed (a :class:`~rigidmech._core._emit.Code`) gives its code for
    that printer's path."""
    if type(expr) is Code:
        return expr.array if isinstance(printer, _ArrayPrinter) else expr.math
    try:
        return printer.doprint(expr)
    except PrintMethodNotImplementedError as exc:
        raise CompilationError(
            f"`exprs` contain {sympy.sstr(expr)} which has no numeric translation "
            f"({exc.args[0].splitlines()[0]}); replace that function or substitute it first."
        ) from None


_IDENTIFIER = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")


def variable_names(symbols):
    """Python identifiers for `symbols`: their own names when usable, else ``a0``, ``a1``, ...

    A name is usable when it is a valid identifier that is neither a keyword, a builtin, a name
    the generated code reserves for itself (anything starting with ``_``) nor already taken.
    """
    names = []
    taken = set()
    for k, symbol in enumerate(symbols):
        name = symbol.name
        if (
            not _IDENTIFIER.match(name)
            or keyword.iskeyword(name)
            or name in _RESERVED
            or name in taken
        ):
            name = f"a{k}"
            while name in taken or name in {s.name for s in symbols}:
                name = "a" + name
        taken.add(name)
        names.append(name)
    return names


_OPERATIONS = (ast.BinOp, ast.UnaryOp, ast.Call, ast.IfExp)


def count_operations(printed):
    """Operations in the printed expressions `printed` (strings of Python code): arithmetic
    operators, negations, function calls and conditional expressions, counted on their syntax
    tree.

    Counted on the generated code rather than with ``sympy.count_ops`` over the expressions:
    the count is the same kind of number (``x*y + 1`` is 2 either way) at a small fraction of
    the cost (``count_ops`` took 2 s of the compilation of the planar 20-link pendulum).

    Examples
    --------
    >>> count_operations(["x*y + 1", "math.sin(-x)"])
    4
    """
    tree = ast.parse("(" + ",\n".join(printed) + ",)", mode="eval") if printed else None
    return 0 if tree is None else sum(isinstance(node, _OPERATIONS) for node in ast.walk(tree))


def body_lines(printer, replacements, indent="    "):
    """Assignment lines ``_x3 = ...`` for the cse replacements."""
    return [f"{indent}{lhs} = {print_expr(printer, rhs)}" for lhs, rhs in replacements]


def nested_literal(items, shape):
    """A nested list literal of the printed `items` (row-major) for an array of `shape`."""
    if len(shape) == 0:
        return items[0]
    if len(shape) == 1:
        return "[" + ", ".join(items) + "]"
    step = len(items) // shape[0] if shape[0] else 0
    return (
        "["
        + ", ".join(
            nested_literal(items[i * step : (i + 1) * step], shape[1:]) for i in range(shape[0])
        )
        + "]"
    )


class _VectorisedMath:
    """Stand-in for ``math`` in the vectorised namespace: ``math.f`` becomes a numpy.vectorize.

    sympy's scipy printer still prints a few functions as ``math.<name>``; on arrays they need
    element-wise evaluation.  Slow, but correct and rare.
    """

    def __getattr__(self, name):
        attribute = getattr(math, name)
        if callable(attribute):
            return np.vectorize(attribute, otypes=[float])
        return attribute


def namespace(source, vectorised):
    """Globals for executing generated `source`: only the modules it mentions."""
    ns = {"numpy": np, "functools": functools, "math": _VectorisedMath() if vectorised else math}
    if "scipy." in source:
        import scipy.special  # heavy: imported only when an expression needs it

        ns["scipy"] = scipy
    return ns


def exec_function(source, function_name, filename, vectorised):
    """Compile `source` once and return the function it defines."""
    ns = namespace(source, vectorised)
    exec(compile(source, filename, "exec"), ns)  # noqa: S102 - our own generated code
    return ns[function_name]


# Compile-time handling of arguments and expressions, shared by compile.py's entry points.


def _normalise_args(args):
    """Return ``(groups, sizes)``: a tuple of symbol tuples and 0 (scalar) or k (vector) each."""
    if isinstance(args, (sympy.Basic, str)) or not hasattr(args, "__iter__"):
        raise ArgumentTypeError(
            f"`args` must be a sequence of Symbols or of sequences of Symbols; got "
            f"{type(args).__name__} {args!r}. Wrap a single symbol in a list: [x]."
        )
    groups, sizes = [], []
    for k, item in enumerate(args):
        if isinstance(item, sympy.Symbol):
            groups.append((item,))
            sizes.append(0)
            continue
        if isinstance(item, (str, sympy.Basic)) and not isinstance(item, sympy.MatrixBase):
            raise ArgumentTypeError(
                f"`args[{k}]` must be a sympy Symbol or a sequence of Symbols; got "
                f"{type(item).__name__} {item!r}. Substitute a Symbol for it first."
            )
        try:
            members = tuple(item)
        except TypeError:
            raise ArgumentTypeError(
                f"`args[{k}]` must be a sympy Symbol or a sequence of Symbols; got "
                f"{type(item).__name__} {item!r}."
            ) from None
        if not members:
            raise ArgumentError(
                f"`args[{k}]` is an empty sequence; a vector argument needs >= 1 Symbol."
            )
        for member in members:
            if not isinstance(member, sympy.Symbol):
                raise ArgumentTypeError(
                    f"`args[{k}]` must contain only sympy Symbols; got {type(member).__name__} "
                    f"{member!r}. Substitute a Symbol for it first."
                )
        groups.append(members)
        sizes.append(len(members))
    flat = [s for group in groups for s in group]
    seen = set()
    for s in flat:
        if s in seen:
            raise ArgumentError(f"`args` list the symbol {s} twice; each symbol must appear once.")
        seen.add(s)
    return tuple(groups), tuple(sizes)


def _flatten_exprs(exprs, flat):
    """Append the scalar expressions of `exprs` to `flat`; return the template of its structure.

    Templates: ``("scalar", i)``, ``("array", shape, start)``, ``("tuple", children)``,
    ``("list", children)``.
    """
    if isinstance(exprs, (sympy.MatrixBase, NDimArray)):
        shape = tuple(int(n) for n in exprs.shape)
        start = len(flat)
        items = list(exprs) if isinstance(exprs, sympy.MatrixBase) else list(exprs._array)
        flat.extend(sympy.sympify(e) for e in items)
        return ("array", shape, start)
    if isinstance(exprs, np.ndarray):
        start = len(flat)
        flat.extend(sympy.sympify(e) for e in exprs.ravel())
        return ("array", exprs.shape, start)
    if isinstance(exprs, (tuple, list)):
        kind = "tuple" if isinstance(exprs, tuple) else "list"
        return (kind, tuple(_flatten_exprs(e, flat) for e in exprs))
    if isinstance(exprs, (sympy.Basic, int, float)):
        flat.append(sympy.sympify(exprs))
        return ("scalar", len(flat) - 1)
    raise ArgumentTypeError(
        "`exprs` must be a sympy expression, a sympy Matrix or Array, or a (nested) tuple or "
        f"list of those; got {type(exprs).__name__}."
    )


def _check_exprs(flat, symbols):
    """Raise CompilationError unless `flat` are real expressions of `symbols` only."""
    for e in flat:
        if isinstance(e, sympy.logic.boolalg.Boolean) and not isinstance(e, sympy.Expr):
            raise CompilationError(
                f"`exprs` must be numeric; got the condition {e}. Use Piecewise((1, cond), "
                "(0, True)) for an indicator."
            )
        if not isinstance(e, sympy.Expr):
            raise CompilationError(
                f"`exprs` must be numeric expressions; got {type(e).__name__} {e}."
            )
    free, functions, imaginary = _scan(flat)
    if functions:
        listed = ", ".join(sorted(map(str, functions)))
        raise CompilationError(
            f"`exprs` contain {listed} which are not plain Symbols; substitute Symbols for the "
            "functions of time and their derivatives first (e.g. with "
            "sympy.physics.mechanics.msubs or xreplace)."
        )
    if imaginary:
        raise CompilationError(
            "`exprs` contain the imaginary unit I; only real expressions compile."
        )
    missing = free - set(symbols)
    if missing:
        names = sorted(s.name for s in missing)
        verb = "are" if len(names) > 1 else "is"
        raise CompilationError(
            f"`exprs` depend on {', '.join(names)} which {verb} not in `args`; pass them as "
            "arguments or substitute values first."
        )


def _scan(flat):
    """``(free symbols, functions of time and derivatives, whether I occurs)`` of `flat`, in
    one walk over its distinct subexpressions.

    Derived equations are DAGs: the same subexpression is shared by many entries, and sympy's
    ``atoms``, ``has`` and ``free_symbols`` walk them as trees (every path again: 17 s of the
    compilation of a 3D chain of 4 links on ball joints); this walk visits each distinct node
    once.
    """
    seen, free, functions, imaginary = set(), set(), set(), False
    stack = list(flat)
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if e.is_Symbol:
            free.add(e)
        elif e is sympy.I:
            imaginary = True
        elif isinstance(e, (AppliedUndef, sympy.Derivative)):
            functions.add(e)
            stack.extend(e.args)
        elif getattr(e, "bound_symbols", None):
            free |= e.free_symbols
        else:
            stack.extend(e.args)
    return free, functions, imaginary


def _check_name(name):
    if not isinstance(name, str) or not name.isidentifier() or name.startswith("_"):
        raise ArgumentError(
            f"`name` must be a Python identifier not starting with '_'; got {name!r}."
        )


class _Prepared:
    """The compile-time pieces shared by both generated paths."""

    __slots__ = ("labels", "math_reduced", "math_replacements", "names", "n_ops",
                 "printed_names", "reduced", "replacements", "sizes", "symbols")

    def __init__(self, flat, args, use_cse):
        groups, sizes = _normalise_args(args)
        symbols = [s for group in groups for s in group]
        _check_exprs(flat, symbols)
        names = variable_names(symbols)
        # a symbol prints under another name when its own is not usable (a Dummy, a name that
        # is no identifier, a name taken twice): the printers rename it, not the expressions
        self.printed_names = {
            s: n for s, n in zip(symbols, names, strict=True)
            if n != s.name or isinstance(s, sympy.Dummy)
        }
        # the cse and the printing of both paths in one pass (replacements and reduced
        # expressions as Code, which print_expr passes through)
        self.replacements, self.reduced = generate(
            flat, use_cse, _MathPrinter(self.printed_names), self.array_printer())
        self.math_replacements = [code.math for _, code in self.replacements]
        self.math_reduced = [code.math for code in self.reduced]
        # counted as the code was written, by the rule of count_operations
        self.n_ops = (sum(code.ops for _, code in self.replacements)
                      + sum(code.ops for code in self.reduced))
        self.sizes = sizes
        self.symbols = tuple(groups)
        self.names = names
        self.labels = tuple(
            g[0].name if size == 0 else "[" + ", ".join(s.name for s in g) + "]"
            for g, size in zip(groups, sizes, strict=True)
        )

    def array_printer(self):
        """The printer of the vectorised path, with the names of the arguments."""
        return _ArrayPrinter(self.printed_names)

    def math_body(self):
        """Assignment lines of the cse replacements for the single-state path."""
        return [f"    {lhs} = {rhs}" for (lhs, _), rhs in
                zip(self.replacements, self.math_replacements, strict=True)]

    def signatures(self):
        """Parameter lists of the single-state and vectorised functions, and the unpack lines."""
        single, batched, unpack = [], [], []
        position = 0
        for k, size in enumerate(self.sizes):
            if size == 0:
                single.append(self.names[position])
                batched.append(self.names[position])
                position += 1
            else:
                members = self.names[position : position + size]
                position += size
                single.extend(members)
                batched.append(f"_v{k}")
                unpack.append(f"    {', '.join(members)}{',' if size == 1 else ''} = _v{k}")
        return single, batched + ["_batch"], unpack


def _describe(template):
    kind = template[0]
    if kind == "scalar":
        return "()"
    if kind == "array":
        return str(template[1])
    inner = ", ".join(_describe(c) for c in template[1])
    if kind == "tuple":
        return f"({inner}{',' if len(template[1]) == 1 else ''})"
    return f"[{inner}]"


def _output_code(template, reduced, math_reduced, printer_array):
    """Return ``(single_return, batched_lines, batched_return)`` for the output `template`;
    `math_reduced` are the reduced expressions printed for the single-state path."""
    counter = [0]
    batched_lines = []

    def single(t):
        kind = t[0]
        if kind == "scalar":
            return f"float({math_reduced[t[1]]})"
        if kind == "array":
            shape, start = t[1], t[2]
            size = int(np.prod(shape, dtype=int))
            if size == 0:
                return f"numpy.zeros({shape})"
            items = math_reduced[start : start + size]
            return f"numpy.array({nested_literal(items, shape)}, dtype=float)"
        parts = [single(c) for c in t[1]]
        if kind == "tuple":
            return "(" + ", ".join(parts) + ("," if len(parts) == 1 else "") + ")"
        return "[" + ", ".join(parts) + "]"

    def batched(t):
        kind = t[0]
        if kind in ("scalar", "array"):
            out = f"_o{counter[0]}"
            counter[0] += 1
            if kind == "scalar":
                batched_lines.append(f"    {out} = numpy.empty(_batch)")
                printed = print_expr(printer_array, reduced[t[1]])
                batched_lines.append(f"    {out}[...] = {printed}")
                return out
            shape, start = t[1], t[2]
            batched_lines.append(f"    {out} = numpy.empty({shape} + _batch)")
            for flat_index, index in enumerate(np.ndindex(*shape)):
                printed = print_expr(printer_array, reduced[start + flat_index])
                batched_lines.append(f"    {out}[{', '.join(map(str, index))}] = {printed}")
            return out
        parts = [batched(c) for c in t[1]]
        if kind == "tuple":
            return "(" + ", ".join(parts) + ("," if len(parts) == 1 else "") + ")"
        return "[" + ", ".join(parts) + "]"

    return single(template), batched_lines, batched(template)


def pivot_tolerance(n):
    """Relative size ``n * eps`` under which the pivot of a symmetric positive definite system
    is rounding noise (see :func:`rigidmech._core.compile.compile_linear_solve`, Notes).

    The j-th Cholesky pivot p_j = a_jj - sum_k l_jk^2 is a difference of a_jj and j squares
    whose sum does not exceed a_jj: its rounding error is about (j + 1) eps a_jj (Higham,
    *Accuracy and Stability of Numerical Algorithms*, 2nd ed., thm. 10.3). A pivot
    p_j <= n eps a_jj is therefore indistinguishable from zero, and then the matrix scaled to a
    unit diagonal has an eigenvalue <= n eps (p_j = 1 / (B^-1)_jj for its leading j x j block
    B, and eigenvalues interlace): singular to working precision, the solution has no correct
    digit. Relative to each pivot's own diagonal entry, the test does not change when a
    coordinate is rescaled (M -> D M D), so a heavy and a very light degree of freedom in one
    system are not mistaken for a singular matrix.

    Examples
    --------
    >>> pivot_tolerance(2) == 2 * 2.0**-52
    True
    """
    return n * 2.0**-52


def _cholesky_steps(n, indent, check_pivot, inverse_sqrt):
    """The factorisation and the two triangular solves of an unrolled Cholesky, shared by the
    scalar and the batched code: locals ``_a{j}_{i}`` (j <= i) and ``_b{i}`` in, ``_z{i}`` out.
    ``check_pivot`` is the line that follows each pivot ``_p``, formatted with ``j`` (the
    pivot's index) and ``tol`` (:func:`pivot_tolerance`); ``inverse_sqrt`` formats
    1/sqrt(_p)."""
    lines = []
    tol = repr(pivot_tolerance(n))
    for j in range(n):
        pivot = f"_a{j}_{j}" + "".join(f" - _l{j}_{k}*_l{j}_{k}" for k in range(j))
        lines.append(f"{indent}_p = {pivot}")
        lines.append(f"{indent}{check_pivot.format(j=j, tol=tol)}")
        lines.append(f"{indent}_r{j} = {inverse_sqrt}")
        for i in range(j + 1, n):
            rest = "".join(f" - _l{i}_{k}*_l{j}_{k}" for k in range(j))
            lines.append(f"{indent}_l{i}_{j} = (_a{j}_{i}{rest})*_r{j}")
    for i in range(n):
        rest = "".join(f" - _l{i}_{k}*_y{k}" for k in range(i))
        lines.append(f"{indent}_y{i} = (_b{i}{rest})*_r{i}")
    for i in reversed(range(n)):
        rest = "".join(f" - _l{k}_{i}*_z{k}" for k in range(i + 1, n))
        lines.append(f"{indent}_z{i} = (_y{i}{rest})*_r{i}")
    return lines


def _cholesky_lines(n, head=(), keep=None):
    """Unrolled Cholesky solve of the symmetric system in locals ``_a{j}_{i}`` (j <= i), ``_b{i}``.

    A non-finite entry (the sum of the entries is then inf or nan, so ``s - s != 0``) or a pivot
    that is not > n eps times its diagonal entry (not positive definite, or singular to working
    precision: :func:`pivot_tolerance`) raises ArithmeticError, caught by the generated code,
    which then hands A and b to the caller's checked solve. The solution is returned as an
    array, after the locals named in `head` and cut to its first `keep` entries if given (the
    first-order form of :meth:`~rigidmech._core.compile.CompiledLinearSolve.first_order`).
    """
    entries = " + ".join(f"_a{j}_{i}" for j in range(n) for i in range(j, n))
    lines = [
        "    try:",
        f"        _s = {entries}",
        "        if not _s - _s == 0.0: raise ArithmeticError",
    ]
    lines += _cholesky_steps(n, "        ", "if not _p > {tol}*_a{j}_{j}: raise ArithmeticError",
                             "1.0/math.sqrt(_p)")
    result = [*head, *(f"_z{i}" for i in range(n if keep is None else keep))]
    lines.append("        return numpy.array([" + ", ".join(result) + "])")
    lines.append("    except ArithmeticError:")
    lines.append("        pass")
    return lines


def _batched_cholesky_lines(n):
    """Unrolled Cholesky solve over arrays (one system per batch element) of the symmetric
    system in locals ``_a{j}_{i}`` (j <= i), ``_b{i}``; returns x, shape (n,) + batch, written
    into the generated function's parameter ``_out`` when one is given (the rows of the
    compiled right-hand side's output), else into a fresh array.

    LAPACK's batched ``numpy.linalg.solve`` costs about 4.6 us per 12x12 system; these n^3/6
    whole-array operations cost a fraction of that for batches of hundreds of states. A pivot
    that is not > n eps times its diagonal entry everywhere (:func:`pivot_tolerance`), or a
    non-finite entry of A or x, leaves the unrolled path: the caller then builds A and b and
    goes through its checked solve (``_out`` then holds no result).

    Every whole-array operation costs about a microsecond of call overhead at the widths of
    an ensemble (hundreds of columns), as much as its arithmetic, so the checks are
    gathered: the pivot tests into one boolean array, reduced once at the end (the same
    comparisons as the single-state path); the finiteness of A and x into one sum (finite
    only if every term is: a nan or an infinity propagates; an overflow of the sum itself
    only sends the batch to the checked solve); the solution rows are written in place.
    """
    entries = " + ".join(f"_a{j}_{i}" for j in range(n) for i in range(j, n))
    lines = [f"    _x = numpy.empty(({n},) + _batch) if _out is None else _out",
             "    _ok = numpy.True_"]
    for line in _cholesky_steps(n, "    ", "_ok = _ok & (_p > {tol}*_a{j}_{j})",
                                "1.0/numpy.sqrt(numpy.abs(_p))"):
        if line.startswith("    _z"):  # the back substitution: each row also into _x
            target, value = line.split(" = ", 1)
            line = f"{target} = _x[{target[6:]}] = {value}"
        lines.append(line)
    lines.append(f"    _s = ({entries} + _x.sum(axis=0)).sum()")
    lines.append("    if _ok.all() and _s - _s == 0.0:")
    lines.append("        return _x")
    return lines
