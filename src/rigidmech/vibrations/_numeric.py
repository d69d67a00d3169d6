"""The matrices of a :class:`~rigidmech.vibrations.linearize.LinearSystem` compiled for numbers
(book, ch. 25.4): M, C, K, B as one numpy function of the parameters left in them.

Evaluating the exact entries with ``evalf`` costs seconds per call on a large system (the
linearised Whipple bicycle: ~20 s; an entry that is zero is pushed to higher and higher precision
before it comes back as ``0.e-253``). Here the entries are prepared once
(:func:`~rigidmech._core.symbolic.fold_numbers`: constant subexpressions to Floats correctly
rounded from 64 digits, entries that vanish to exact zeros), compiled once
(:func:`~rigidmech._core.compile.compile_expressions`), then every call is float arithmetic.
"""

from __future__ import annotations

import threading

import numpy as np
import sympy as sp

from .._core.compile import compile_expressions
from .._core.errors import ArgumentError
from .._core.symbolic import fold_numbers

__all__: list[str] = []

#: One lock for every lazy compilation of a LinearSystem (a lock is not picklable, so it cannot
#: live on the instance; compilations are rare, contention is not an issue).
_LOCK = threading.Lock()


class CompiledMatrices:
    """``(M, C, K, B)`` as float arrays from the values of the parameters (by name).

    Picklable (cloudpickle as well): the compiled function is stored as its generated source.

    Examples
    --------
    >>> k, m = sp.symbols("k m")
    >>> f = CompiledMatrices.compile((sp.Matrix([[m]]), sp.zeros(1), sp.Matrix([[k]]),
    ...                               sp.zeros(1, 0)), (k, m))
    >>> [X.tolist() for X in f({"k": 4.0, "m": 2.0})]
    [[[2.0]], [[0.0]], [[4.0]], [[]]]
    """

    __slots__ = ("names", "function")

    def __init__(self, names, function):
        self.names = tuple(names)
        self.function = function

    @classmethod
    def compile(cls, matrices, parameters):
        """Fold and compile ``matrices`` (sympy matrices) as functions of ``parameters``."""
        flat = [e for X in matrices for e in X]
        folded = iter(fold_numbers(flat))
        shaped = tuple(sp.ImmutableMatrix(X.rows, X.cols, [next(folded) for _ in range(len(X))])
                       for X in matrices)
        # one scalar argument per parameter: the single-state path takes Python floats
        function = compile_expressions(shaped, list(parameters), name="linear_system")
        return cls([p.name for p in parameters], function)

    def __call__(self, params):
        """The matrices at ``params`` ({name: value}); names not among the parameters are
        ignored, a missing one raises :class:`ArgumentError`."""
        missing = [name for name in self.names if name not in params]
        if missing:
            missing = sorted(missing)
            raise ArgumentError(
                f"missing values for parameters {missing}; pass them as keywords, e.g. "
                f"{', '.join(f'{m}=1.0' for m in missing)}.")
        values = [params[name] for name in self.names]
        out = self.function(*values)
        return tuple(np.asarray(X, dtype=float) for X in out)


def compiled_matrices(system):
    """The :class:`CompiledMatrices` of a LinearSystem, compiled on first use and cached in
    its ``_cache`` (under a lock: two threads asking at once compile it once)."""
    cache = system._cache
    compiled = cache.get("compiled")
    if compiled is None:
        with _LOCK:
            compiled = cache.get("compiled")
            if compiled is None:
                compiled = CompiledMatrices.compile(
                    (system.M, system.C, system.K, system.B), system.parameters)
                cache["compiled"] = compiled
    return compiled


def state_matrix(M, C, K):
    """A = [[0, I], [-M^-1 K, -M^-1 C]] of the first-order form (one LU of M for both).

    Examples
    --------
    >>> state_matrix(np.eye(1), np.zeros((1, 1)), 4 * np.eye(1)).tolist()
    [[0.0, 1.0], [-4.0, -0.0]]
    """
    n = len(M)
    solved = np.linalg.solve(M, np.concatenate((K, C), axis=1))
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:] = -solved
    return A
