"""Private code generation for :mod:`rigidmech._core.compile`: the unrolled, sparse solution of
one saddle-point system, the augmented equations of a constrained system,

    [[M, A^T], [A, 0]] (x, lam) = (f, b),    M (n x n) symmetric positive definite,

on the single-state path (Python floats), by the range-space (Schur complement) method:
M = L D L^T, X = M^-1 [f, A^T], S = A M^-1 A^T = L_S D_S L_S^T, S lam = A M^-1 f - b,
x = M^-1 f - M^-1 A^T lam. Every product with an entry that is zero in the symbolic matrix
(a mass matrix of bodies on separate branches, a constraint row that involves few
coordinates) is left out of the generated code, and so is the fill-in it would cause: for
the seven-body squeezer (n = 7, m = 6) this is a fraction of the 13 x 13 LU of the whole
matrix, and it needs no numpy array until the result.

Why hand-rolled: LAPACK through scipy or numpy costs several microseconds of call overhead
per routine for a 13 x 13 system (and the general path's checks, equilibration, LU, the
condition estimate and the triangular solves, four calls), more than the whole elimination
in Python floats at these sizes (benchmarks/squeezer.py).

When the fast path is taken: every pivot of the two eliminations (D and D_S, eliminated in
order without pivoting) is more than 1/:data:`SADDLE_PIVOT_FACTOR` of its diagonal entry
(M_jj, S_jj), and the result is finite. Otherwise the generated code hands the whole matrix
to the caller's general path (LU of the equilibrated matrix with its singularity test),
which solves it or refuses it: a singular configuration is decided there only.
"""

import re

__all__: list[str] = []

#: The unrolled range-space solve is used when every pivot of the eliminations of M and of
#: S = A M^-1 A^T is more than 1/SADDLE_PIVOT_FACTOR of its diagonal entry (about 1e-4:
#: ``pivot * 10001 > diagonal``). Elimination without pivoting amplifies rounding by about
#: the inverse of the smallest such ratio (the growth of a Cholesky-like elimination), and
#: forming S squares the conditioning of the constraint rows: near a singular configuration
#: of a loop, where some pivot of S is small against its diagonal, the LU of the whole
#: equilibrated matrix is the more accurate and is used instead. 10001 = 100^2 + 1, so that
#: the test at the boundary is exact in floating point (rows (1, 0) and (100, 1) of A with
#: M = I give S = [[1, 100], [100, 10001]] and the pivot 1).
SADDLE_PIVOT_FACTOR = 10001.0


_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")


class _Lines:
    """The generated lines, every local assigned once: a right-hand side that is a bare local
    is not copied (its name is used), and one already assigned is not computed again (the
    name that holds it is used) -- rows of A that agree on some columns (constraints
    through the same body) then share their partial products."""

    def __init__(self, indent):
        self.indent, self.lines, self.memo = indent, [], {}

    def emit(self, name, expr):
        """Assign `expr` to `name` unless it is a local or already held; return the name
        that holds it."""
        if _IDENTIFIER.fullmatch(expr):
            return expr
        held = self.memo.get(expr)
        if held is None:
            self.lines.append(f"{self.indent}{name} = {expr}")
            held = self.memo[expr] = name
        return held

    def add(self, line):
        self.lines.append(f"{self.indent}{line}")


def _dot(pairs):
    """Printed sum of products of the pairs of locals (None factors left out), or None."""
    terms = [f"{a}*{b}" for a, b in pairs if a is not None and b is not None]
    return " + ".join(terms) if terms else None


def _minus(base, terms):
    """``base - (terms)``: each part may be None (a structural zero)."""
    if terms is None:
        return base
    if base is None:
        return f"-({terms})"
    return f"{base} - ({terms})"


def _ldl(n, a, prefix, out):
    """Unrolled sparse L D L^T of the symmetric matrix whose entries (i >= j) are
    ``a[(i, j)]`` (locals, or absent for structural zeros), written to `out`: the table of
    L's strict lower entries and the names of 1/d_j. Each pivot is tested against its
    diagonal entry."""
    L, W, inv = {}, {}, []
    factor = repr(SADDLE_PIVOT_FACTOR)
    for j in range(n):
        diag = a.get((j, j))
        d = _minus(diag, _dot((L.get((j, k)), W.get((j, k))) for k in range(j)))
        d = out.emit(f"_{prefix}d{j}", d) if d is not None else "0.0"
        out.add(f"if not {d}*{factor} > {diag or '0.0'}: raise ArithmeticError")
        inv.append(out.emit(f"_{prefix}i{j}", f"1.0/{d}"))
        for i in range(j + 1, n):
            w = _minus(a.get((i, j)), _dot((L.get((i, k)), W.get((j, k))) for k in range(j)))
            if w is None:
                continue
            W[i, j] = out.emit(f"_{prefix}w{i}_{j}", w)
            L[i, j] = out.emit(f"_{prefix}l{i}_{j}", f"{W[i, j]}*{inv[j]}")
    return L, inv


def _ldl_solve(n, L, inv, rhs, name, out):
    """Solve L D L^T x = rhs (a list of n locals or None): L y = rhs, then L^T x = D^-1 y,
    written to `out`; returns x, the locals (None for the structural zeros of x)."""
    y = []
    for i in range(n):
        v = _minus(rhs[i], _dot((L.get((i, k)), y[k]) for k in range(i)))
        y.append(None if v is None else out.emit(f"{name}y{i}", v))
    x = [None] * n
    for i in reversed(range(n)):
        z = None if y[i] is None else f"{y[i]}*{inv[i]}"
        v = _minus(z, _dot((L.get((k, i)), x[k]) for k in range(i + 1, n)))
        if v is not None:
            x[i] = out.emit(f"{name}{i}", v)
    return x


def saddle_lines(n, m, entry, rhs, indent="    ", head=(), keep=None):
    """The unrolled range-space solve (module docstring) of the saddle-point system of size
    n + m whose matrix entries are the locals ``entry[(i, j)]`` (absent: a structural zero;
    M given by its entries i >= j < n, A by its rows n..n+m-1, columns < n; entries equal
    by construction may share a local) and right-hand side the locals ``rhs[k]``. The lines
    end by returning the solution (x, lam) as a numpy array, or raise ArithmeticError (a
    pivot too small against its diagonal entry, a non-finite result): the caller catches it
    and takes its general path. With `head` (names of locals) and `keep`, the array
    returned is (head, the first `keep` entries of the solution) instead (the first-order
    form of :meth:`~rigidmech._core.compile.CompiledLinearSolve.first_order`)."""
    out = _Lines(indent)
    M = {(i, j): entry[i, j] for i in range(n) for j in range(i + 1) if (i, j) in entry}
    L, inv = _ldl(n, M, "m", out)
    A = [[entry.get((n + r, c)) for c in range(n)] for r in range(m)]
    X = [_ldl_solve(n, L, inv, A[r], f"_x{r}_", out) for r in range(m)]
    xf = _ldl_solve(n, L, inv, rhs[:n], "_xf", out)
    S = {}
    for r in range(m):
        for s in range(r + 1):
            v = _dot(zip(A[r], X[s], strict=True))
            if v is not None:
                S[r, s] = out.emit(f"_s{r}_{s}", v)
    g = []
    for r in range(m):
        v = _minus(_dot(zip(A[r], xf, strict=True)), rhs[n + r])
        g.append(None if v is None else out.emit(f"_g{r}", v))
    LS, invS = _ldl(m, S, "s", out)
    lam = _ldl_solve(m, LS, invS, g, "_lam", out)
    result = []
    for i in range(n):
        v = _minus(xf[i], _dot((X[r][i], lam[r]) for r in range(m)))
        result.append(v if v is not None else "0.0")
    result += [v if v is not None else "0.0" for v in lam]
    out.add(f"_out = [{', '.join([*head, *result])}]")
    out.add("_s = sum(_out)")
    out.add("if not _s - _s == 0.0: raise ArithmeticError")
    out.add("return numpy.array(_out)" if keep is None else
            f"return numpy.array(_out[:{len(head) + keep}])")
    return out.lines
