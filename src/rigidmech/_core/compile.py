"""Symbolic → numeric compilation: sympy expressions become fast, vectorised Python functions.

Everything symbolic in rigidmech (equations of motion M(q) q'' = f(q, q', t), connection
actions, energies, positions of points) goes through this module once.  It knows no mechanics:
it takes sympy expressions and the symbols to use as arguments.

Each compiled function carries two code paths generated from one common-subexpression
elimination of its expressions (sympy's algorithm, :mod:`rigidmech._core._cse`; the code of
both paths written in one pass over the result, :mod:`rigidmech._core._emit`):

* a **single-state** path, used when every scalar argument is a number and every vector
  argument is 1-D of its declared length: the arguments are unpacked into Python floats and
  evaluated with the ``math`` module (Python float arithmetic costs about a tenth of numpy
  scalar arithmetic);
* a **vectorised** path for batches: a vector argument of shape ``(k,) + batch`` and scalar
  arguments broadcastable to ``batch`` give outputs of shape ``out_shape + batch`` (trailing
  batch axes, the convention of :mod:`rigidmech.ode`).

Both paths return fresh arrays on every call: never a buffer that a later call overwrites (the
pitfall of PyDy's generated code, which silently corrupts Runge-Kutta integrations).
"""

import types

import numpy as np
import sympy

from . import _codegen, _saddle
from ._codegen import (
    _batched_cholesky_lines,
    _check_name,
    _cholesky_lines,
    _describe,
    _flatten_exprs,
    _output_code,
    _Prepared,
)
from .errors import (
    ArgumentError,
    ArgumentTypeError,
    SingularMassMatrixError,
)
from .lazy import lazy_functions

# lazy: import cost (scipy.linalg takes ~0.4 s; see docs/performance); rebound on first call
_dgecon, _dgetrf, _dgetrs, _dposv = lazy_functions(
    globals(), "scipy.linalg.lapack", "dgecon", "dgetrf", "dgetrs", "dposv")

__all__ = [
    "CompiledFunction",
    "CompiledLinearSolve",
    "compile_expressions",
    "compile_linear_solve",
]

#: Largest n for which a symmetric system is solved, on the single-state path, by an unrolled
#: Cholesky factorisation generated in pure Python instead of numpy.linalg.solve.  Measured per
#: call on a random SPD matrix, numpy 2.4 / scipy 1.17 / Python 3.11 on the project's 2-core
#: machine (microseconds; "from lists" includes building the arrays from Python floats, which
#: the generated code must do anyway):
#:
#: ====  ====================  ===========================  ==================  ================
#:  n    np.linalg.solve        scipy.linalg.solve            pure-Python loop     unrolled
#:       (from lists)           (pos, check_finite=False)     Cholesky             Cholesky
#: ====  ====================  ===========================  ==================  ================
#:  2     6.9                   29.3                          5.8                  1.4
#:  5     8.4                   31.8                          18.2                 6.4
#:  8    10.3                   34.6                          39.9                 18.2
#: 12    16.1                   38.8                          81.0                 47.8
#: ====  ====================  ===========================  ==================  ================
#:
#: scipy.linalg.solve's Python-side checks make it the slowest at these sizes; the crossover
#: between the unrolled Cholesky and numpy is near n = 6.
UNROLLED_CHOLESKY_MAX_N = 6

_FALLBACK_ERRORS = (ArithmeticError, ValueError)


# --------------------------------------------------------------------------------------------
# Arguments at call time
# --------------------------------------------------------------------------------------------

_NUMBER_TYPES = (float, int, np.number)


def _single_state_values(args, sizes):
    """Flatten `args` into Python numbers if they describe one state; else return None."""
    flat = []
    for a, size in zip(args, sizes, strict=True):
        if size == 0:
            if type(a) is float:
                flat.append(a)
            elif isinstance(a, _NUMBER_TYPES) and not isinstance(a, complex):
                flat.append(float(a))
            elif isinstance(a, np.ndarray) and a.ndim == 0 and a.dtype.kind in "fiub":
                flat.append(float(a))
            else:
                return None
        elif type(a) is np.ndarray:
            if a.shape != (size,) or a.dtype.kind not in "fiub":
                return None
            flat.extend(a.tolist())
        elif isinstance(a, (list, tuple)) and len(a) == size:
            for v in a:
                if not isinstance(v, _NUMBER_TYPES) or isinstance(v, (complex, np.complexfloating)):
                    return None
            flat.extend(a)
        else:
            return None
    return flat


def _batch_arrays(args, sizes, labels, function_name):
    """Convert `args` to float arrays and return them with their broadcast batch shape."""
    if len(args) != len(sizes):
        raise ArgumentTypeError(
            f"`{function_name}` takes {len(sizes)} arguments ({', '.join(labels)}); "
            f"got {len(args)}."
        )
    arrays, batch_shapes = [], []
    for a, size, label in zip(args, sizes, labels, strict=True):
        try:
            array = np.asarray(a, dtype=float)
        except (TypeError, ValueError):
            raise ArgumentTypeError(
                f"argument `{label}` must be a real number or an array of real numbers; got "
                f"{type(a).__name__}."
            ) from None
        if size:
            if array.ndim == 0 or array.shape[0] != size:
                raise ArgumentError(
                    f"argument `{label}` must have shape ({size},) or ({size}, *batch); got "
                    f"shape {array.shape}."
                )
            batch_shapes.append(array.shape[1:])
        else:
            batch_shapes.append(array.shape)
        arrays.append(array)
    try:
        batch = np.broadcast_shapes(*batch_shapes)
    except ValueError:
        described = ", ".join(
            f"{label}: {shape}" for label, shape in zip(labels, batch_shapes, strict=True)
        )
        raise ArgumentError(
            f"the batch shapes of the arguments do not broadcast together ({described}); the "
            "batch axes trail the vector axis: a vector argument has shape (k, *batch)."
        ) from None
    return arrays, batch


def _values_at(arrays, sizes, labels, batch, index):
    """``{label: value}`` of the arguments at flat batch `index` (for error messages)."""
    position = np.unravel_index(index, batch) if batch else ()
    values = {}
    for array, size, label in zip(arrays, sizes, labels, strict=True):
        full = np.broadcast_to(array, ((size,) if size else ()) + batch)
        value = full[(slice(None),) + position] if size else full[position]
        values[label] = value.tolist() if size else float(value)
    return values


def _to_python_scalars(out):
    """Turn the 0-d arrays of a batch-less vectorised result into floats."""
    if isinstance(out, np.ndarray) and out.ndim == 0:
        return float(out)
    if isinstance(out, tuple):
        return tuple(_to_python_scalars(o) for o in out)
    if isinstance(out, list):
        return [_to_python_scalars(o) for o in out]
    return out


# --------------------------------------------------------------------------------------------
# Common machinery of compiled objects
# --------------------------------------------------------------------------------------------


class _Compiled:
    """Base of the compiled callables: immutable, picklable through their generated source."""

    __slots__ = (
        "_batched",
        "_labels",
        "_name",
        "_single",
        "_sizes",
        "args",
        "batched_source",
        "n_ops",
        "single_source",
    )

    def _init(self, **state):
        for key, value in state.items():
            object.__setattr__(self, key, value)
        object.__setattr__(
            self,
            "_single",
            _codegen.exec_function(
                self.single_source, f"{self._name}_single", f"<rigidmech {self._name}>", False
            ),
        )
        object.__setattr__(
            self,
            "_batched",
            _codegen.exec_function(
                self.batched_source, f"{self._name}_batched", f"<rigidmech {self._name}>", True
            ),
        )

    def __setattr__(self, key, value):
        raise AttributeError(f"{type(self).__name__} is immutable; cannot set `{key}`.")

    def __delattr__(self, key):
        raise AttributeError(f"{type(self).__name__} is immutable; cannot delete `{key}`.")

    def _state(self):
        names = [s for s in _Compiled.__slots__ if s not in ("_single", "_batched")]
        names += [s for s in type(self).__slots__ if not s.startswith("_")]  # _: executed code
        return {key: getattr(self, key) for key in names}

    def __reduce__(self):
        return (_restore, (type(self), self._state()))

    @property
    def name(self):
        """The name given at compile time (used in the generated source)."""
        return self._name

    @property
    def source(self):
        """The generated Python source of both code paths (single-state, then vectorised)."""
        return self.single_source + "\n\n" + self.batched_source

    @property
    def single(self):
        """The generated single-state function, without the argument handling of a call: it
        takes every argument flattened into Python floats, in order (a vector argument as its
        k entries), and returns what a call returns for one state (a
        :class:`CompiledLinearSolve`'s returns the tuple (A, b) instead when its unrolled
        solve cannot decide, and its checked solve must). For callers that have checked their
        arguments already, on a hot path; an error inside it (``ValueError``,
        ``ArithmeticError``) means: call the object instead.

        Examples
        --------
        >>> import sympy
        >>> x, y = sympy.symbols("x y")
        >>> f = compile_expressions(sympy.Matrix([x * y, x + y]), [[x, y]], name="f")
        >>> f.single(2.0, 3.0).ravel()
        array([6., 5.])
        """
        return self._single

    @property
    def batched(self):
        """The generated vectorised function, without the argument handling of a call: it
        takes each argument as a float array (a vector argument of shape ``(k, *batch)``),
        then the broadcast batch shape, and returns what a call returns for that batch (a
        :class:`CompiledLinearSolve`'s may return the stacked (A, b) instead, when its
        checked solve must decide). Call it under ``numpy.errstate(all="ignore")``.

        Examples
        --------
        >>> import numpy as np, sympy
        >>> x, y = sympy.symbols("x y")
        >>> f = compile_expressions(x * y, [[x, y]], name="f")
        >>> f.batched(np.array([[2.0, 3.0], [4.0, 5.0]]), (2,))
        array([ 8., 15.])
        """
        return self._batched

    def _args_repr(self):
        return "(" + ", ".join(self._labels) + ")"


def _restore(cls, state):
    """Rebuild a compiled object from its state (pickle support): re-executes the sources."""
    obj = cls.__new__(cls)
    obj._init(**state)
    return obj


# --------------------------------------------------------------------------------------------
# compile_expressions
# --------------------------------------------------------------------------------------------


class CompiledFunction(_Compiled):
    """A numeric function compiled from sympy expressions by :func:`compile_expressions`.

    Call it with one value per entry of ``args`` given at compile time: a number (or array of
    numbers, for a batch) for a scalar argument, a 1-D array of the declared length k (or an
    array of shape ``(k, *batch)``) for a vector argument.  The output has the structure of the
    compiled ``exprs``: a float for a scalar expression (an array of shape ``batch`` for a
    batch), an array of shape ``matrix.shape`` (``matrix.shape + batch``) for a matrix, tuples
    and lists as given.  Every call returns fresh arrays.

    Attributes
    ----------
    args : tuple of tuple of sympy.Symbol
        The argument symbols, one tuple per argument (of length 1 for a scalar argument).
    n_ops : int
        Operation count of the generated code (single-state path): arithmetic operators,
        negations and function calls of the cse replacements and the reduced expressions
        (:func:`rigidmech._core._codegen.count_operations`).
    source : str
        The generated Python source, for inspection.

    Notes
    -----
    Instances are immutable and picklable: pickling stores the generated source, unpickling
    re-executes it (no sympy work), so compiled functions can be sent to worker processes.

    Arithmetic failures on the single-state path (``math.sqrt(-1)``, ``1/0``, overflow) make
    that call fall back to the vectorised path, so both paths give the same IEEE result
    (``nan`` or ``inf``) without a warning; non-finite results are for the caller (the ODE
    solvers report them) to handle.

    Examples
    --------
    >>> import sympy
    >>> x, y = sympy.symbols("x y")
    >>> f = compile_expressions(sympy.Matrix([x * y, x + y]), [[x, y]], name="f")
    >>> f
    CompiledFunction(f([x, y]) -> (2, 1), n_ops=2)
    >>> f([2.0, 3.0]).ravel()
    array([6., 5.])
    """

    __slots__ = ("template",)

    def __call__(self, *args):
        if len(args) == len(self._sizes):
            flat = _single_state_values(args, self._sizes)
            if flat is not None:
                try:
                    return self._single(*flat)
                except _FALLBACK_ERRORS:
                    pass
        arrays, batch = _batch_arrays(args, self._sizes, self._labels, self._name)
        with np.errstate(all="ignore"):
            out = self._batched(*arrays, batch)
        return _to_python_scalars(out) if batch == () else out

    def __repr__(self):
        return (
            f"CompiledFunction({self._name}{self._args_repr()} -> {_describe(self.template)}, "
            f"n_ops={self.n_ops})"
        )


def compile_expressions(exprs, args, *, name="f", cse=True):
    """Compile sympy expressions into a fast numeric function of `args`.

    Parameters
    ----------
    exprs : sympy.Expr, sympy.Matrix, sympy.Array, or (nested) tuple / list of those
        What to compute.  The output of the compiled function has the same structure.
    args : sequence
        The arguments of the compiled function, in order.  Each item is a sympy Symbol (a
        scalar argument) or a sequence of Symbols (a vector argument, passed at call time as
        a 1-D array of that length, possibly with trailing batch axes).  Every free symbol of
        `exprs` must appear here.
    name : str, optional
        Name of the function, used in the generated source and the repr.
    cse : bool, optional
        Whether to share common subexpressions (default True).  Turn it off only for tiny
        expressions where cse costs more time than it saves.

    Returns
    -------
    CompiledFunction
        Callable as ``f(*values)``; see :class:`CompiledFunction` for the shapes.

    Raises
    ------
    CompilationError
        If `exprs` depend on symbols that are not in `args`, contain undefined functions of
        time or their derivatives, conditions, the imaginary unit, or functions without a
        numeric translation.
    ArgumentTypeError, ArgumentError
        If `args` is not a sequence of Symbols / sequences of Symbols, repeats a symbol, or
        `exprs` has an unsupported type.

    Notes
    -----
    The expressions go through a common-subexpression elimination once; the replacement list
    and the reduced expressions are written twice in the same pass, with the ``math`` module
    for the single-state path and with numpy / scipy.special for the vectorised path (sympy's
    printers' rules; a node without a rule of its own is printed by them), and compiled with
    :func:`compile`.  For a
    batch, a vector argument has shape ``(k, *batch)`` and a scalar argument any shape that
    broadcasts with the others; each output gets shape ``out_shape + batch``.

    Examples
    --------
    >>> import numpy as np
    >>> import sympy
    >>> q1, q2, g, L = sympy.symbols("q1 q2 g L")
    >>> energy = -g * L * (sympy.cos(q1) + sympy.cos(q2))
    >>> position = sympy.Matrix([L * sympy.sin(q1), -L * sympy.cos(q1)])
    >>> f = compile_expressions((energy, position), [[q1, q2], g, L], name="scene")
    >>> e, p = f([0.0, 0.0], 9.81, 2.0)
    >>> e, p.shape
    (-39.24, (2, 1))

    A batch of 5 states along a trailing axis, with one value of ``L`` per state:

    >>> e, p = f(np.zeros((2, 5)), 9.81, np.linspace(1.0, 2.0, 5))
    >>> e.shape, p.shape
    ((5,), (2, 1, 5))

    Symbols missing from `args` are named:

    >>> compile_expressions(g * L, [g])
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.CompilationError: `exprs` depend on L which is not in `args`; ...
    """
    _check_name(name)
    flat = []
    template = _flatten_exprs(exprs, flat)
    prepared = _Prepared(flat, args, cse)
    printer_array = prepared.array_printer()
    single_params, batched_params, unpack = prepared.signatures()
    single_return, batched_out_lines, batched_return = _output_code(
        template, prepared.reduced, prepared.math_reduced, printer_array
    )
    single_source = "\n".join(
        [f"def {name}_single({', '.join(single_params)}):"]
        + prepared.math_body()
        + [f"    return {single_return}"]
    )
    batched_source = "\n".join(
        [f"def {name}_batched({', '.join(batched_params)}):"]
        + unpack
        + _codegen.body_lines(printer_array, prepared.replacements)
        + batched_out_lines
        + [f"    return {batched_return}"]
    )
    obj = CompiledFunction.__new__(CompiledFunction)
    obj._init(
        _name=name,
        _labels=prepared.labels,
        _sizes=prepared.sizes,
        args=prepared.symbols,
        n_ops=prepared.n_ops,
        single_source=single_source,
        batched_source=batched_source,
        template=template,
    )
    return obj


# --------------------------------------------------------------------------------------------
# compile_linear_solve
# --------------------------------------------------------------------------------------------


def _singular_error(reason, where):
    error = SingularMassMatrixError(
        f"the matrix `A` of the linear system {reason} at {where}; the mass matrix cannot be "
        "inverted there (check the state and the parameters)."
    )
    return error


def _where(values, index=None):
    described = ", ".join(f"{label}={value}" for label, value in values.items())
    return described if index is None else f"batch index {index}, where {described}"


class CompiledLinearSolve(_Compiled):
    """The solution x of A(args) x = b(args), compiled by :func:`compile_linear_solve`.

    Called like a :class:`CompiledFunction`; returns x as a fresh array of shape ``(n,)`` for
    one state, ``(n, *batch)`` for a batch.

    Attributes
    ----------
    args : tuple of tuple of sympy.Symbol
        The argument symbols, one tuple per argument.
    n : int
        Size of the system.
    symmetric : bool
        Whether only the upper triangle of A was compiled (A symmetric positive definite, as a
        mass matrix is).
    n_ops : int
        Operation count of the generated evaluation of A and b (cse shared between them).
    source : str
        The generated Python source.
    first_order_source : str or None
        The generated source of :meth:`first_order` (None when there is none).

    Notes
    -----
    Immutable and picklable like :class:`CompiledFunction`.

    Examples
    --------
    >>> import sympy
    >>> m, k = sympy.symbols("m k", positive=True)
    >>> solve = compile_linear_solve(sympy.diag(m, 2 * m), sympy.Matrix([k, k]), [m, k],
    ...                              symmetric=True)
    >>> solve
    CompiledLinearSolve(solve(m, k) -> (2,), symmetric=True, n_ops=...)
    >>> solve(2.0, 4.0)
    array([2., 1.])
    """

    __slots__ = ("_first_order", "first_order_source", "n", "symmetric", "unrolled")

    def first_order(self, values):
        """The single-state path as the right-hand side ``f(t, y)`` of a first-order system,
        the arguments after x' bound to `values`.

        For a solve compiled with the arguments (t, x, x', c_1, ..., c_p), x and x' vectors
        of one length k <= n (the coordinates and rates of a second-order system
        x'' = (the first k entries of the solution)): ``f(t, y)``, with y = (x, x') a 1-D
        float64 array of length 2k and t a float, returns y' = (x', x'') as a fresh array,
        computed by the generated code directly (no argument handling, no array but the
        result). When its unrolled solve cannot decide (a pivot too small, a non-finite
        entry) it returns (A, b) instead: call the object then, which solves or refuses
        them. Like :attr:`single`, it checks nothing: a caller passes it what it has
        checked (an error inside it means: call the object instead).

        Parameters
        ----------
        values : sequence of float
            The values of c_1, ..., c_p, bound once.

        Returns
        -------
        callable or None
            None when the single-state path has no unrolled solve (it always hands A and b
            back: the object's call is then as fast) or the arguments are not laid out so.

        Raises
        ------
        ArgumentError
            If `values` does not hold one number per argument after x'.
        ArgumentTypeError
            If a value is not a real number.

        Examples
        --------
        >>> import numpy as np, sympy
        >>> t, x, v, m, k = sympy.symbols("t x v m k")
        >>> solve = compile_linear_solve(sympy.Matrix([[m]]), sympy.Matrix([-k * x]),
        ...                              [t, [x], [v], m, k], symmetric=True)
        >>> f = solve.first_order([2.0, 8.0])
        >>> f(0.0, np.array([1.0, 3.0]))
        array([ 3., -4.])
        """
        if self.first_order_source is None:
            return None
        template = getattr(self, "_first_order", None)
        if template is None:
            template = _codegen.exec_function(
                self.first_order_source, f"{self._name}_first_order",
                f"<rigidmech {self._name}>", False)
            object.__setattr__(self, "_first_order", template)
        count = len(self._sizes) - 3
        values = tuple(values)
        if len(values) != count:
            raise ArgumentError(
                f"`values` must hold {count} numbers, one for each of "
                f"{list(self._labels[3:])}; got {len(values)}. Pass them in that order.")
        try:
            defaults = tuple(float(v) for v in values)
        except (TypeError, ValueError):
            raise ArgumentTypeError(
                f"`values` must be real numbers; got {values!r}.") from None
        return types.FunctionType(template.__code__, template.__globals__,
                                  template.__name__, defaults or None)

    def __call__(self, *args):
        if len(args) == len(self._sizes):
            flat = _single_state_values(args, self._sizes)
            if flat is not None:
                try:
                    result = self._single(*flat)
                except _FALLBACK_ERRORS:
                    pass
                else:
                    if type(result) is not tuple:
                        return result
                    return self._solve_one(result[0], result[1], args)
        arrays, batch = _batch_arrays(args, self._sizes, self._labels, self._name)
        with np.errstate(all="ignore"):
            result = self._batched(*arrays, batch)
        if type(result) is not tuple:
            return result
        return self._solve_batch(result[0], result[1], arrays, batch)

    def _solve_one(self, A, b, args):
        x, reason = None, "is not finite"
        if np.isfinite(A).all():
            x, reason = _checked_solve(A, b, self.symmetric)
            if x is not None and (np.isfinite(x).all() or not np.isfinite(b).all()):
                return x
            reason = reason or "is not finite"
        arrays, batch = _batch_arrays(args, self._sizes, self._labels, self._name)
        where = _where(_values_at(arrays, self._sizes, self._labels, batch, 0))
        raise _singular_error(reason, where)

    def _solve_batch(self, A, b, arrays, batch):
        n = self.n
        count = int(np.prod(batch, dtype=int))
        stack_A = A.reshape(n, n, count).transpose(2, 0, 1)
        stack_b = b.reshape(n, count).T[:, :, None]
        finite_A = np.isfinite(stack_A).all(axis=(1, 2))
        bad, reason = None, "is singular"
        if not finite_A.all():
            bad, reason = int(np.argmin(finite_A)), "is not finite"
        else:
            with np.errstate(all="ignore"):
                singular = _singular_members(stack_A, self.symmetric)
                if singular.any():
                    bad = int(np.argmax(singular))
                else:
                    x = np.linalg.solve(stack_A, stack_b)[:, :, 0]
                    singular = (~np.isfinite(x).all(axis=1)
                                & np.isfinite(stack_b).all(axis=(1, 2)))
                    if singular.any():
                        bad, reason = int(np.argmax(singular)), "is not finite"
        if bad is not None:
            values = _values_at(arrays, self._sizes, self._labels, batch, bad)
            where = _where(values) if batch == () else _where(values, bad)
            raise _singular_error(reason, where)
        return x.T.reshape((n,) + batch)

    def __repr__(self):
        return (
            f"CompiledLinearSolve({self._name}{self._args_repr()} -> ({self.n},), "
            f"symmetric={self.symmetric}, n_ops={self.n_ops})"
        )


def _checked_solve(A, b, symmetric):
    """x solving A x = b for one finite A, or (None, reason) if A is singular to working
    precision.

    A symmetric positive definite A (a mass matrix) is solved by LAPACK's Cholesky (``dposv``,
    cheaper than numpy.linalg.solve) and its pivots tested against ``n eps`` times their
    diagonal entries (:func:`~rigidmech._core._codegen.pivot_tolerance`); any other A by LU
    of the equilibrated matrix, with the test of :func:`_singular_members` (LAPACK's
    ``dgecon`` estimate of the reciprocal condition number).
    """
    if symmetric:
        factor, x, info = _dposv(A, b)
        if info == 0:
            pivots = np.diagonal(factor)
            if (pivots * pivots > _codegen.pivot_tolerance(len(b)) * np.diagonal(A)).all():
                return x, None
            return None, "is singular"
    # LU of the equilibrated matrix (the test of _singular_members, by LAPACK for one state:
    # dgecon estimates the reciprocal condition number from the factors)
    rows = np.abs(A).max(axis=1)
    if not rows.all():
        return None, "is singular"
    scaled = A / rows[:, None]
    cols = np.abs(scaled).max(axis=0)
    if not cols.all():
        return None, "is singular"
    scaled = scaled / cols
    lu, pivots, info = _dgetrf(scaled)
    if info != 0:
        return None, "is singular"
    rcond, _ = _dgecon(lu, np.abs(scaled).sum(axis=0).max())
    if not rcond > _codegen.pivot_tolerance(len(b)):
        return None, "is singular"
    y, _ = _dgetrs(lu, pivots, b / rows)
    return y / cols, None


def _singular_members(stack, symmetric):
    """Boolean mask of the matrices of ``stack`` (shape (count, n, n), finite) that are
    singular to working precision.

    Symmetric positive definite members are tested by their Cholesky pivots
    (:func:`~rigidmech._core._codegen.pivot_tolerance`). Others (a symmetric matrix that is
    not positive definite, any matrix when ``symmetric`` is false) are equilibrated (rows,
    then columns, scaled to a largest entry of 1, so that the scale of an equation or of an
    unknown does not matter) and are singular when their reciprocal condition number in the
    1-norm, 1 / (|A|_1 |A^-1|_1), is at most n eps (what LAPACK's ``gecon`` estimates): LU's
    backward error is of that size, so such a matrix is within rounding of a singular one.
    """
    n = stack.shape[-1]
    tol = _codegen.pivot_tolerance(n)
    if symmetric:
        diag = np.diagonal(stack, axis1=1, axis2=2)
        try:
            factor = np.linalg.cholesky(stack)
        except np.linalg.LinAlgError:
            factor = None
        if factor is not None:
            pivots = np.diagonal(factor, axis1=1, axis2=2) ** 2
            return ~(pivots > tol * diag).all(axis=1)
    rows = np.abs(stack).max(axis=2, keepdims=True)
    scaled = stack / np.where(rows == 0, 1.0, rows)
    cols = np.abs(scaled).max(axis=1, keepdims=True)
    scaled = scaled / np.where(cols == 0, 1.0, cols)
    singular = (rows == 0).any(axis=(1, 2)) | (cols == 0).any(axis=(1, 2))
    try:
        inverse = np.linalg.inv(scaled)
    except np.linalg.LinAlgError:
        inverse = np.full_like(scaled, np.nan)
        for k in range(len(scaled)):
            try:
                inverse[k] = np.linalg.inv(scaled[k])
            except np.linalg.LinAlgError:
                pass
    norm = np.abs(scaled).sum(axis=1).max(axis=-1)
    norm_inverse = np.abs(inverse).sum(axis=1).max(axis=-1)
    return singular | ~(1.0 / (norm * norm_inverse) > tol)


def _check_saddle(A, n, symmetric):
    """Refuse a matrix that is not [[M, C^T], [C, 0]] with M of size n (entry by entry)."""
    if symmetric:
        raise ArgumentError("`saddle` and `symmetric` exclude each other: a saddle-point "
                            "matrix is symmetric but not positive definite; pass one of them.")
    size = A.rows
    if isinstance(n, bool) or not isinstance(n, int) or not 0 < n < size:
        raise ArgumentError(f"`saddle` must be the size of the leading block, an integer "
                            f"between 1 and {size - 1}; got {n!r}.")
    for i in range(size):
        for j in range(i):
            if A[i, j] != A[j, i] or (i >= n and j >= n and A[i, j] != 0):
                raise ArgumentError(
                    f"`A` is not a saddle-point matrix [[M, C^T], [C, 0]] with M of size {n}: "
                    f"entries ({i}, {j}) and ({j}, {i}) are {A[i, j]} and {A[j, i]}. Pass "
                    "saddle=None to solve it as a general matrix.")
    if any(A[i, i] != 0 for i in range(n, size)):
        raise ArgumentError(f"`A` is not a saddle-point matrix: its trailing block (from row "
                            f"{n}) is not zero. Pass saddle=None to solve it as a general "
                            "matrix.")


def compile_linear_solve(A, b, args, *, symmetric=False, name="solve", cse=True, saddle=None):
    """Compile the solution x of the linear system A x = b, with A and b functions of `args`.

    Made for equations of motion M(q) q'' = f(q, q', t): A and b are evaluated in one
    generated function (common subexpressions shared between them), then solved numerically.

    Parameters
    ----------
    A : sympy.Matrix, shape (n, n)
        The matrix of the system (the mass matrix).
    b : sympy.Matrix of shape (n, 1) or (1, n), or sequence of n expressions
        The right-hand side (the forcing).
    args : sequence
        As for :func:`compile_expressions`: Symbols (scalar arguments) and sequences of
        Symbols (vector arguments).
    symmetric : bool, optional
        Declare A symmetric positive definite (a mass matrix is): only its upper triangle is
        compiled and read, and small systems (n <= ``UNROLLED_CHOLESKY_MAX_N``) are solved on
        the single-state path by an unrolled Cholesky factorisation.  Not checked.
    name : str, optional
        Name used in the generated source and the repr.
    cse : bool, optional
        Whether to share common subexpressions (default True).
    saddle : int, optional
        Declare A the saddle-point matrix [[M, C^T], [C, 0]] of a constrained system, M its
        leading ``saddle`` x ``saddle`` block, symmetric positive definite (checked:
        A symmetric and its trailing block zero, entry by entry). The single-state path
        then solves it by an unrolled range-space elimination that leaves out the
        products with the entries that are zero in A (:mod:`rigidmech._core._saddle`),
        and hands it to the general path (LU of the equilibrated matrix, with its
        singularity test) when a pivot is at most 1/``SADDLE_PIVOT_FACTOR`` (about
        1e-4) of its diagonal entry. Not with ``symmetric``.

    Returns
    -------
    CompiledLinearSolve
        Callable as ``solve(*values)``, returning x of shape ``(n,)`` or ``(n, *batch)``.

    Raises
    ------
    CompilationError, ArgumentError, ArgumentTypeError
        As for :func:`compile_expressions`, and if A is not square or b does not match it.

    Notes
    -----
    At call time a non-finite A, or one singular to working precision, raises
    :class:`~rigidmech.errors.SingularMassMatrixError` naming the argument values (and the
    first offending batch index, for a batch); so does a solution that is not finite while b
    is. Singular to working precision means, on every path (unrolled Cholesky for one state or
    a batch, LAPACK for n > ``UNROLLED_CHOLESKY_MAX_N``): a Cholesky pivot p_j <= n eps a_jj,
    relative to its own diagonal entry (the rounding error of p_j is about (j + 1) eps a_jj,
    so such a pivot carries no digit, and the matrix scaled to a unit diagonal then has an
    eigenvalue <= n eps; the test does not depend on the units of the coordinates). A matrix
    declared symmetric that is not positive definite, or one not declared symmetric, is
    equilibrated (rows, then columns, to a largest entry of 1) and singular when its
    reciprocal condition number in the 1-norm is <= n eps. M = [[c, c], [c, c]] is refused
    for every c, whatever the rounding of its last pivot.  A batch is
    solved by one call of numpy.linalg.solve on the stack of systems (batch axes moved to the
    front and back).  The choice between numpy and the unrolled Cholesky on the single-state
    path is measured; see ``UNROLLED_CHOLESKY_MAX_N``.

    Examples
    --------
    A pendulum (mass m, length L) hinged on a cart of mass M, coordinates x and theta:

    >>> import sympy
    >>> x, th, w, g, L, m, M = sympy.symbols("x theta omega g L m M")
    >>> mass = sympy.Matrix([[M + m, m * L * sympy.cos(th)],
    ...                      [m * L * sympy.cos(th), m * L**2]])
    >>> forcing = sympy.Matrix([m * L * w**2 * sympy.sin(th), -m * g * L * sympy.sin(th)])
    >>> accel = compile_linear_solve(mass, forcing, [[x, th], w, g, L, m, M], symmetric=True)
    >>> accel([0.0, 0.5], 0.0, 9.81, 1.0, 1.0, 2.0).round(6)
    array([ 1.850984, -6.327556])

    With no mass on the cart and the pendulum vertical, the mass matrix is singular:

    >>> accel([0.0, 0.0], 0.0, 9.81, 1.0, 1.0, 0.0)
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.SingularMassMatrixError: the matrix `A` ... is singular at ...
    """
    _check_name(name)
    if not isinstance(A, sympy.MatrixBase) or A.rows != A.cols or A.rows == 0:
        shape = getattr(A, "shape", None)
        raise ArgumentError(
            f"`A` must be a square, non-empty sympy Matrix; got {type(A).__name__} of shape "
            f"{shape}."
        )
    n = A.rows
    if isinstance(b, sympy.MatrixBase):
        if b.shape not in ((n, 1), (1, n)):
            raise ArgumentError(
                f"`b` must have shape ({n}, 1) or (1, {n}) to match `A` of shape ({n}, {n}); "
                f"got {b.shape}."
            )
        b_items = list(b)
    else:
        try:
            b_items = list(b)
        except TypeError:
            raise ArgumentTypeError(
                f"`b` must be a sympy Matrix or a sequence of {n} expressions; got "
                f"{type(b).__name__}."
            ) from None
        if len(b_items) != n:
            raise ArgumentError(f"`b` must have {n} entries to match `A`; got {len(b_items)}.")
    symmetric = bool(symmetric)
    if saddle is not None:
        _check_saddle(A, saddle, symmetric)
        a_index = ([(i, j) for i in range(saddle) for j in range(i + 1)]
                   + [(i, j) for i in range(saddle, n) for j in range(saddle)])
        a_index = [ij for ij in a_index if A[ij] != 0]
    elif symmetric:
        a_index = [(j, i) for j in range(n) for i in range(j, n)]
    else:
        a_index = [(i, j) for i in range(n) for j in range(n)]
    flat = [sympy.sympify(A[i, j]) for i, j in a_index] + [sympy.sympify(e) for e in b_items]
    prepared = _Prepared(flat, args, cse)
    printer_array = prepared.array_printer()
    single_params, batched_params, unpack = prepared.signatures()
    reduced = prepared.reduced
    a_locals = [f"_a{i}_{j}" for i, j in a_index]
    b_locals = [f"_b{i}" for i in range(n)]
    entry = dict(zip(a_index, a_locals, strict=True))
    if symmetric or saddle is not None:
        entry.update({(i, j): name_ for (j, i), name_ in zip(a_index, a_locals, strict=True)})
    a_literal = _codegen.nested_literal(
        [entry.get((i, j), "0.0") for i in range(n) for j in range(n)], (n, n))
    unrolled = symmetric and n <= UNROLLED_CHOLESKY_MAX_N
    if saddle is not None:
        # entries printed alike (the same point's rows of several loops) share one local,
        # so that the elimination computes their products once
        first, printed = {}, dict(zip(a_locals, prepared.math_reduced, strict=False))
        shared = {ij: first.setdefault(printed[local], local) for ij, local in entry.items()}

        def fast(head=(), keep=None):
            return (["    try:"]
                    + _saddle.saddle_lines(saddle, n - saddle, shared, b_locals,
                                           indent="        ", head=head, keep=keep)
                    + ["    except ArithmeticError:", "        pass"])
    else:
        def fast(head=(), keep=None):
            return _cholesky_lines(n, head, keep) if unrolled else []
    body = prepared.math_body() + [
        f"    {local} = {printed}"
        for local, printed in zip(a_locals + b_locals, prepared.math_reduced, strict=True)
    ]
    handed_back = [f"    return numpy.array({a_literal}), numpy.array([{', '.join(b_locals)}])"]
    single_lines = [f"def {name}_single({', '.join(single_params)}):"] + body + fast() + handed_back
    first_order_source = None
    layout = _first_order_layout(prepared)
    if layout is not None and (saddle is not None or unrolled) and len(layout[1]) <= n:
        time_name, positions, rates, rest = layout
        first_order_source = "\n".join(
            [f"def {name}_first_order({', '.join([time_name, '_state_vector', *rest])}):",
             f"    {', '.join(positions + rates)} = _state_vector.tolist()"]
            + body + fast(rates, len(positions)) + handed_back)
    if symmetric:  # the solution written into `_out` if given (_batched_cholesky_lines)
        batched_params = batched_params + ["_out=None"]
    batched_lines = (
        [f"def {name}_batched({', '.join(batched_params)}):"]
        + unpack
        + _codegen.body_lines(printer_array, prepared.replacements)
    )
    if symmetric:
        # entries in locals, then an unrolled Cholesky over the batch (see
        # _batched_cholesky_lines); A and b are built only if that path is left
        batched_lines += [
            f"    {local} = {_codegen.print_expr(printer_array, e)}"
            for local, e in zip(a_locals + b_locals, reduced, strict=True)
        ]
        batched_lines += _batched_cholesky_lines(n)
        batched_lines += [f"    _A = numpy.empty(({n}, {n}) + _batch)",
                          f"    _B = numpy.empty(({n},) + _batch)"]
        for i, j in a_index:
            target = f"_A[{i}, {j}]" + (f" = _A[{j}, {i}]" if i != j else "")
            batched_lines.append(f"    {target} = {entry[i, j]}")
        for i in range(n):
            batched_lines.append(f"    _B[{i}] = _b{i}")
    else:
        batched_lines += [f"    _A = numpy.{'zeros' if saddle is not None else 'empty'}"
                          f"(({n}, {n}) + _batch)",
                          f"    _B = numpy.empty(({n},) + _batch)"]
        for (i, j), e in zip(a_index, reduced, strict=False):
            target = f"_A[{i}, {j}]" + (f" = _A[{j}, {i}]" if saddle is not None and i != j
                                        else "")
            batched_lines.append(f"    {target} = {_codegen.print_expr(printer_array, e)}")
        for i, e in enumerate(reduced[len(a_index) :]):
            batched_lines.append(f"    _B[{i}] = {_codegen.print_expr(printer_array, e)}")
    batched_lines.append("    return _A, _B")
    obj = CompiledLinearSolve.__new__(CompiledLinearSolve)
    obj._init(
        _name=name,
        _labels=prepared.labels,
        _sizes=prepared.sizes,
        args=prepared.symbols,
        n_ops=prepared.n_ops,
        single_source="\n".join(single_lines),
        batched_source="\n".join(batched_lines),
        n=n,
        symmetric=symmetric,
        unrolled=unrolled,
        first_order_source=first_order_source,
    )
    return obj


def _first_order_layout(prepared):
    """(name of t, names of x, names of x', names of the rest) when the arguments are
    (t, x, x', scalars...) with x and x' vectors of one length; else None."""
    sizes = prepared.sizes
    if (len(sizes) < 3 or sizes[0] != 0 or sizes[1] == 0 or sizes[2] != sizes[1]
            or any(sizes[3:])):
        return None
    k, names = sizes[1], list(prepared.names)
    return names[0], names[1:1 + k], names[1 + k:1 + 2 * k], names[1 + 2 * k:]
