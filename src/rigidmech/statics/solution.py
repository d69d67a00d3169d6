"""The solution of the equations of statics: rank, hyperstaticity, conditions (book, ch. 14.2).

:meth:`~rigidmech.statics.equilibrium.Statics.solve` hands the linear equations
A x = b of statics to a symbolic solver (independent rows by row reduction, then
``sympy.linsolve``) or a numeric one (rank by SVD, independent rows by pivoted QR, least
squares), and wraps the outcome in an :class:`Equilibrium`. A numeric system whose
condition number exceeds 1e10 is solved with a :class:`~rigidmech.errors.RigidmechWarning`:
its values are accurate to about (condition number) x 2.2e-16 only.
"""

from __future__ import annotations

import warnings

import numpy as np
import sympy as sp

from .._core.errors import RigidmechWarning
from .._core.lazy import lazy_package
from ..torsors import Torsor
from .errors import EquilibriumError

scipy = lazy_package("scipy")  # lazy: import cost of scipy.linalg (see docs/performance)

# condition number above which the numeric solution is flagged (accurate to ~1e-6 or worse)
_ILL_CONDITIONED = 1e10

__all__ = ["Equilibrium"]


def _solve_symbolic(A, b, xs, names):
    def zero(e):
        return sp.simplify(e).is_zero

    _, pivots = A.T.rref(iszerofunc=zero)
    rows = list(pivots)
    sub_A = A.extract(rows, list(range(A.cols)))
    sub_b = b.extract(rows, [0])
    solutions = sp.linsolve((sub_A, sub_b), xs)
    if not solutions:        # independent rows are always solvable: a zero test went wrong
        raise EquilibriumError(
            "no equilibrium found: the equations of statics have no solution for the symbolic "
            "data (sympy could not decide a pivot); substitute numbers with `values=`.")
    (sol,) = solutions
    full = {x: sp.simplify(v) for x, v in zip(xs, sol, strict=True)}
    params = set(xs) & set().union(*(v.free_symbols for v in full.values()))
    frees = {x for x, v in full.items() if v.free_symbols & params}
    conditions = []
    for i in range(A.rows):
        if i in rows:
            continue
        residual = sp.simplify((A.row(i) * sp.Matrix(list(sol)))[0] - b[i])
        if residual != 0:
            if residual.is_number:
                raise EquilibriumError(
                    f"no equilibrium: the equation '{names[i]}' reduces to {residual} = 0 "
                    "whatever the connection actions; the given actions cannot be balanced "
                    "(a mechanism, or a missing connection).")
            conditions.append((names[i], residual))
    return full, frees, len(rows), conditions


def _solve_numeric(A, b, xs, names):
    An = np.array(A.tolist(), dtype=float)
    bn = np.array(b.tolist(), dtype=float).reshape(-1)
    n = len(xs)
    if An.size == 0:
        return {x: 0.0 for x in xs}, set(xs), 0, []
    scale = max(np.abs(An).max(), 1e-300)
    _, _, piv = scipy.linalg.qr(An.T, pivoting=True, mode="economic")
    s = np.linalg.svd(An, compute_uv=False)
    tol = max(An.shape) * np.finfo(float).eps * 1e3 * scale
    r = int(np.sum(s > tol))
    rows = sorted(piv[:r])
    if r and s[0] > _ILL_CONDITIONED * s[r - 1]:
        warnings.warn(
            f"the equations of statics are ill-conditioned (condition number "
            f"{s[0] / s[r - 1]:.3g} > {_ILL_CONDITIONED:.0e}): the values are accurate to about "
            f"{s[0] / s[r - 1] * np.finfo(float).eps:.1g} relative only; the configuration "
            "is close to one where the connections cannot hold the loads (a near mechanism).",
            RigidmechWarning, stacklevel=4)
    x, *_ = np.linalg.lstsq(An[rows], bn[rows], rcond=None)
    bscale = max(np.abs(bn).max(), np.abs(An).max() * np.abs(x).max() if n else 0, 1e-300)
    bad = []
    for i in range(An.shape[0]):
        if i not in rows:
            res = float(An[i] @ x - bn[i])
            if abs(res) > 1e-9 * bscale:
                bad.append(f"'{names[i]}' (off by {res:.6g})")
    if bad:
        raise EquilibriumError(
            "no equilibrium: the given actions cannot be balanced by the connections; the "
            f"equations {', '.join(bad)} cannot be satisfied whatever the unknowns "
            "(a mechanism, or a missing connection).")
    if r < n:
        null = scipy.linalg.null_space(An[rows]) if r else np.eye(n)
        frees = {xs[j] for j in range(n) if np.abs(null[j]).max() > 1e-9}
    else:
        frees = set()
    return {xv: float(v) for xv, v in zip(xs, x, strict=True)}, frees, r, []


class Equilibrium:
    """The solution of a statics problem (see :meth:`Statics.solve`).

    Attributes
    ----------
    values : dict
        Value of each *determined* unknown (symbolic or float).
    undetermined : tuple
        The unknowns the equations of statics leave free (hyperstatic system).
    hyperstaticity : int
        Degree of hyperstaticity h = (number of unknowns) - rank.
    rank : int
        Rank of the equations in the unknowns.
    conditions : tuple
        ``(equation, expression)``: what the given actions must satisfy (= 0) for the
        equilibrium to exist; non-empty for a mechanism under a general symbolic load.

    Examples
    --------
    >>> import rigidmech as rm
    >>> from rigidmech.actions import ContactLaws, Force
    >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
    >>> st = rm.statics.Statics(R0)
    >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
    >>> st.act(Force(on=box, vector=-10 * R0.j, at=R0.point("G", 0, 1, 0)))
    >>> print(st.solve())
    Equilibrium of 1 body: 1 unknown, rank 1, isostatic
      N_A = 10.0
    """

    __slots__ = ("_statics", "_unknowns", "_subs", "_full", "_free", "_rank", "_conditions")

    def __init__(self, statics, unknowns, subs, full, free, rank, conditions):
        self._statics, self._unknowns, self._subs = statics, tuple(unknowns), subs
        self._full, self._free, self._rank = full, free, rank
        self._conditions = tuple(conditions)

    unknowns = property(lambda self: self._unknowns, doc="All the unknowns solved for.")
    rank = property(lambda self: self._rank, doc="Rank of the equations.")
    conditions = property(lambda self: self._conditions,
                          doc="Conditions on the given actions (mechanism).")

    @property
    def values(self) -> dict:
        """Values of the determined unknowns.

        Examples
        --------
        A bar on three supports: statics finds none of the three reactions alone.

        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); bar = rm.Body("bar", frame=R0)
        >>> st = rm.statics.Statics(R0)
        >>> for label, x in (("A", 0), ("B", 1), ("C", 2)):
        ...     st.connect(R0, bar, ContactLaws(at=R0.point(label, x, 0, 0), normal=R0.j),
        ...                label=label)
        >>> st.act(Force(on=bar, vector=-6 * R0.j, at=R0.point("G", 1, 0, 0)))
        >>> eq = st.solve()
        >>> eq.values, eq.undetermined, eq.hyperstaticity
        ({}, (N_A, N_B, N_C), 1)
        """
        return {x: v for x, v in self._full.items() if x not in self._free}

    @property
    def undetermined(self) -> tuple:
        """The unknowns left undetermined by statics (in the order of the unknowns).

        Examples
        --------
        See :attr:`values`.
        """
        return tuple(x for x in self._unknowns if x in self._free)

    @property
    def hyperstaticity(self) -> int:
        """Degree of hyperstaticity: number of unknowns minus rank.

        Examples
        --------
        See :attr:`values`.
        """
        return len(self._unknowns) - self._rank

    @property
    def is_mechanism(self) -> bool:
        """True if the equilibrium requires conditions on the given actions.

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import Force, Pivot
        >>> F = rm.constants("F", positive=True)
        >>> R0 = rm.Frame("R0"); lever = rm.Body("lever", frame=R0)
        >>> st = rm.statics.Statics(R0)
        >>> st.connect(R0, lever, Pivot(at=R0.origin, axis=R0.k), label="O")
        >>> st.act(Force(on=lever, vector=-F * R0.j, at=R0.point("A", 1, 0, 0)))
        >>> eq = st.solve()
        >>> eq.is_mechanism, eq.conditions
        (True, (('lever: moment about k', -F),))
        """
        return bool(self._conditions)

    def solution(self) -> dict:
        """One solution for every unknown: the undetermined ones are free symbols
        (symbolic path) or take the least-norm values (numeric path).

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); bar = rm.Body("bar", frame=R0)
        >>> st = rm.statics.Statics(R0)
        >>> for label, x in (("A", 0), ("B", 1), ("C", 2)):
        ...     st.connect(R0, bar, ContactLaws(at=R0.point(label, x, 0, 0), normal=R0.j),
        ...                label=label)
        >>> st.act(Force(on=bar, vector=-6 * R0.j, at=R0.point("G", 1, 0, 0)))
        >>> eq = st.solve()
        >>> {x: round(v, 12) for x, v in eq.solution().items()}      # least norm
        {N_A: 2.0, N_B: 2.0, N_C: 2.0}
        >>> st.solve(method="symbolic").solution()
        {N_A: N_C, N_B: 6 - 2*N_C, N_C: N_C}
        """
        return dict(self._full)

    def residual(self, body) -> Torsor:
        """Sum of all the action torsors on ``body`` at the solution (zero at equilibrium).

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); bar = rm.Body("bar", frame=R0)
        >>> st = rm.statics.Statics(R0)
        >>> for label, x in (("A", 0), ("B", 1), ("C", 2)):
        ...     st.connect(R0, bar, ContactLaws(at=R0.point(label, x, 0, 0), normal=R0.j),
        ...                label=label)
        >>> st.act(Force(on=bar, vector=-6 * R0.j, at=R0.point("G", 1, 0, 0)))
        >>> eq = st.solve()
        >>> R = eq.residual(bar)
        >>> R.resultant.is_close(rm.Vector.zero(), atol=1e-12), R.moment.is_close(
        ...     rm.Vector.zero(), atol=1e-12)
        (True, True)
        """
        O = self._statics.reference.origin
        sub = {**self._subs, **self._full}
        total = sum(self._statics.torsors_on(body), Torsor.zero(O)).at(O)
        return total.applyfunc(lambda e: sp.sympify(e).xreplace(sub))

    def __str__(self):
        nb = len(self._statics.bodies)
        kind = ("isostatic" if self.hyperstaticity == 0
                else f"hyperstatic of degree {self.hyperstaticity}")
        lines = [f"Equilibrium of {nb} bod{'y' if nb == 1 else 'ies'}: "
                 f"{len(self._unknowns)} unknown{'s' * (len(self._unknowns) != 1)}, "
                 f"rank {self._rank}, {kind}"]
        lines += [f"  {x} = {v}" for x, v in self.values.items()]
        if self._free:
            lines.append("  undetermined: " + ", ".join(str(x) for x in self.undetermined))
        for name, expr in self._conditions:
            lines.append(f"  condition ({name}): {expr} = 0")
        return "\n".join(lines)

    def __repr__(self):
        return (f"Equilibrium(unknowns={len(self._unknowns)}, rank={self._rank}, "
                f"hyperstaticity={self.hyperstaticity}, conditions={len(self._conditions)})")
