"""Butcher tableaux of explicit Runge-Kutta methods, as immutable data (book, ch. 26.2).

A Runge-Kutta method with ``s`` stages advances ``y' = f(t, y)`` by one step ``h`` as

.. math::

    k_i = f\\Big(t + c_i h,\\; y + h \\sum_{j<i} a_{ij} k_j\\Big), \\qquad
    y_{1} = y + h \\sum_i b_i k_i .

The book (ch. 26.2.2) presents Euler's method and the classical fourth-order Runge-Kutta
method; the same machinery runs any explicit tableau. The method has order ``p`` when
``sum_i b_i Phi_i(tau) = 1 / gamma(tau)`` for every rooted tree ``tau`` with at most ``p``
vertices (Butcher's order conditions; Hairer, Norsett, Wanner I, Sec. II.2):
:meth:`ButcherTableau.order_residuals` evaluates them, and :func:`rooted_trees` enumerates
the trees.
"""

from __future__ import annotations

from fractions import Fraction
from functools import cache

import numpy as np

from rigidmech._core.errors import ArgumentError

from . import _dop853_coefficients as _d853

__all__ = [
    "ButcherTableau",
    "rooted_trees",
    "tree_density",
    "EULER",
    "HEUN",
    "MIDPOINT",
    "RK4",
    "RK38",
    "DOPRI5",
    "DOP853",
    "ALL",
]


def _readonly(a) -> np.ndarray:
    out = np.array(a, dtype=float, copy=True)
    out.setflags(write=False)
    return out


@cache
def rooted_trees(order: int) -> tuple:
    """All rooted trees with exactly `order` vertices, in a canonical nested-tuple form.

    A tree is the sorted tuple of the subtrees hanging from its root; the one-vertex tree is
    ``()``.

    Examples
    --------
    >>> [len(rooted_trees(p)) for p in range(1, 9)]   # OEIS A000081
    [1, 1, 2, 4, 9, 20, 48, 115]
    >>> rooted_trees(3)        # the tall tree [[tau]] and the cherry [tau, tau]
    ((((),),), ((), ()))
    """
    if order < 1:
        raise ArgumentError(f"`order` must be an int >= 1; got {order!r}.")
    if order == 1:
        return ((),)
    found = set()

    def grow(tree):
        yield tuple(sorted(tree + ((),)))  # a new leaf on the root
        for i, child in enumerate(tree):
            for new in grow(child):
                yield tuple(sorted(tree[:i] + (new,) + tree[i + 1 :]))

    for t in rooted_trees(order - 1):
        found.update(grow(t))
    return tuple(sorted(found, key=repr))


def _size(tree) -> int:
    return 1 + sum(_size(c) for c in tree)


def _tree_str(tree) -> str:
    return "(" + ",".join(_tree_str(c) for c in tree) + ")"


def tree_density(tree) -> int:
    """The density ``gamma(tree)``: its order times the densities of its subtrees.

    Examples
    --------
    >>> tree_density(((), ()))      # the "cherry" [tau, tau]: 3
    3
    >>> tree_density((((),),))      # the tall tree [[tau]]: 6
    6
    """
    g = _size(tree)
    for c in tree:
        g *= tree_density(c)
    return g


class ButcherTableau:
    """An explicit Runge-Kutta method as data: ``A``, ``b``, ``c``, its order and an optional
    embedded weight vector.

    Parameters
    ----------
    name : str
    A : array_like, shape (s, s)
        Strictly lower triangular stage matrix.
    b : array_like, shape (s,)
        Weights of the main method.
    c : array_like, shape (s,)
        Nodes; must equal the row sums of `A`.
    order : int
        Claimed order of `b`.
    b_embedded : array_like, shape (s,), optional
        Weights of an embedded method of order `order_embedded` (error estimation).
    order_embedded : int, optional

    Raises
    ------
    ArgumentError
        On inconsistent shapes, a non strictly lower triangular `A`, or an order < 1.

    Notes
    -----
    The arrays are read-only copies; a tableau never changes. ``==`` compares the arrays
    exactly.

    Examples
    --------
    >>> RK4.order, RK4.stages
    (4, 4)
    >>> float(abs(RK4.order_residuals(4)).max()) < 1e-15
    True
    >>> RK4
    ButcherTableau('rk4', stages=4, order=4)
    """

    __slots__ = ("name", "A", "b", "c", "order", "b_embedded", "order_embedded")

    def __init__(self, name, A, b, c, order, b_embedded=None, order_embedded=None):
        A, b, c = _readonly(A), _readonly(b), _readonly(c)
        s = len(b)
        if A.shape != (s, s) or c.shape != (s,) or b.ndim != 1:
            raise ArgumentError(
                f"`A`, `b`, `c` must have shapes (s, s), (s,), (s,); got {A.shape}, {b.shape}, "
                f"{c.shape}."
            )
        if np.any(np.triu(A) != 0):
            raise ArgumentError(
                "`A` must be strictly lower triangular for an explicit method; got nonzero "
                "entries on or above the diagonal."
            )
        if not isinstance(order, int) or order < 1:
            raise ArgumentError(f"`order` must be an int >= 1; got {order!r}.")
        if b_embedded is not None:
            b_embedded = _readonly(b_embedded)
            if b_embedded.shape != (s,):
                raise ArgumentError(
                    f"`b_embedded` must have shape ({s},); got {b_embedded.shape}."
                )
        for k, v in dict(name=name, A=A, b=b, c=c, order=order, b_embedded=b_embedded,
                         order_embedded=order_embedded).items():
            object.__setattr__(self, k, v)

    def __setattr__(self, key, value):
        raise AttributeError(f"ButcherTableau is immutable; cannot set {key!r}.")

    @property
    def stages(self) -> int:
        """Number of stages ``s``."""
        return len(self.b)

    def __repr__(self) -> str:
        return f"ButcherTableau({self.name!r}, stages={self.stages}, order={self.order})"

    def __eq__(self, other):
        if not isinstance(other, ButcherTableau):
            return NotImplemented
        same = (self.name, self.order, self.order_embedded) == (
            other.name, other.order, other.order_embedded)
        arrays = all(
            np.array_equal(x, y) for x, y in ((self.A, other.A), (self.b, other.b),
                                              (self.c, other.c)))
        emb = (self.b_embedded is None and other.b_embedded is None) or (
            self.b_embedded is not None and other.b_embedded is not None
            and np.array_equal(self.b_embedded, other.b_embedded))
        return same and arrays and emb

    def __hash__(self):
        return hash((self.name, self.order, self.A.tobytes(), self.b.tobytes()))

    def order_residuals(self, order: int, weights=None) -> np.ndarray:
        """Residuals ``b . Phi(tau) - 1/gamma(tau)`` of every tree with at most `order` vertices.

        Parameters
        ----------
        order : int
        weights : array_like, shape (s,), optional
            Weights to test instead of `b` (e.g. the embedded ones).

        Returns
        -------
        ndarray
            One residual per tree, trees ordered by size.

        Notes
        -----
        The elementary weight of ``tau = [tau_1, ..., tau_m]`` is the stage vector
        ``Phi(tau) = prod_k A Phi(tau_k)`` (component-wise), with ``Phi(leaf) = 1``; this form
        does not assume ``c = A 1``, checked separately by :meth:`row_sum_defect`.

        Examples
        --------
        >>> float(abs(HEUN.order_residuals(2)).max())
        0.0
        >>> float(abs(HEUN.order_residuals(3)).max()) > 0.01     # Heun has order 2 only
        True
        """
        w = self.b if weights is None else np.asarray(weights, dtype=float)
        ones = np.ones(self.stages)
        memo = {}

        def phi(tree):
            if tree not in memo:
                v = ones.copy()
                for child in tree:
                    v = v * (self.A @ phi(child))
                memo[tree] = v
            return memo[tree]

        out = []
        for p in range(1, order + 1):
            for tree in rooted_trees(p):
                out.append(float(w @ phi(tree)) - float(Fraction(1, tree_density(tree))))
        return np.array(out)

    def verify(self, tol: float = 1e-12) -> None:
        """Check the row sums and the order conditions up to the claimed order(s).

        Parameters
        ----------
        tol : float
            Largest residual accepted.

        Raises
        ------
        ArgumentError
            Naming the first violated identity: a row sum, or the tree and its residual.

        Examples
        --------
        >>> DOP853.verify()
        >>> ButcherTableau("bad", [[0, 0], [1, 0]], [0.5, 0.5], [0, 1], order=3).verify()
        Traceback (most recent call last):
        ...
        rigidmech._core.errors.ArgumentError: `order` = 3 of tableau 'bad' is not reached: ...
        """
        if self.row_sum_defect() > tol:
            raise ArgumentError(
                f"`c` of tableau {self.name!r} must equal the row sums of `A`; they differ by "
                f"{self.row_sum_defect():.3g}."
            )
        checks = [("order", self.order, self.b)]
        if self.b_embedded is not None and self.order_embedded is not None:
            checks.append(("order_embedded", self.order_embedded, self.b_embedded))
        for label, order, weights in checks:
            res = self.order_residuals(order, weights)
            bad = np.flatnonzero(np.abs(res) > tol)
            if bad.size:
                trees = [t for p in range(1, order + 1) for t in rooted_trees(p)]
                tree = trees[bad[0]]
                raise ArgumentError(
                    f"`{label}` = {order} of tableau {self.name!r} is not reached: the "
                    f"condition of tree {_tree_str(tree)} (order {_size(tree)}) has residual "
                    f"{res[bad[0]]:.3g}."
                )

    def row_sum_defect(self) -> float:
        """Largest ``|sum_j a_ij - c_i|`` (zero for a consistent tableau).

        Examples
        --------
        >>> DOP853.row_sum_defect() < 1e-14
        True
        """
        return float(np.max(np.abs(self.A.sum(axis=1) - self.c)))


EULER = ButcherTableau("euler", [[0.0]], [1.0], [0.0], order=1)
HEUN = ButcherTableau("heun", [[0, 0], [1, 0]], [0.5, 0.5], [0, 1], order=2)
MIDPOINT = ButcherTableau("midpoint", [[0, 0], [0.5, 0]], [0, 1], [0, 0.5], order=2)
RK4 = ButcherTableau(
    "rk4",
    [[0, 0, 0, 0], [0.5, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, 1, 0]],
    [1 / 6, 1 / 3, 1 / 3, 1 / 6],
    [0, 0.5, 0.5, 1],
    order=4,
)
RK38 = ButcherTableau(
    "rk38",
    [[0, 0, 0, 0], [1 / 3, 0, 0, 0], [-1 / 3, 1, 0, 0], [1, -1, 1, 0]],
    [1 / 8, 3 / 8, 3 / 8, 1 / 8],
    [0, 1 / 3, 2 / 3, 1],
    order=4,
)

# Dormand & Prince (1980), 5(4) with FSAL: the 7th stage is f(t + h, y1). Coefficients as in
# scipy.integrate._ivp.rk.RK45 and HNW I, Table II.5.2.
_DP5_A = np.zeros((7, 7))
_DP5_A[1, :1] = [1 / 5]
_DP5_A[2, :2] = [3 / 40, 9 / 40]
_DP5_A[3, :3] = [44 / 45, -56 / 15, 32 / 9]
_DP5_A[4, :4] = [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729]
_DP5_A[5, :5] = [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656]
_DP5_B = np.array([35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0])
_DP5_A[6] = _DP5_B
#: Error weights b - b_embedded (scipy's RK45.E).
DOPRI5_E = _readonly(
    [-71 / 57600, 0, 71 / 16695, -71 / 1920, 17253 / 339200, -22 / 525, 1 / 40])
#: Shampine's dense output of Dormand-Prince 5(4) (scipy's RK45.P), shape (7, 4).
DOPRI5_P = _readonly([
    [1, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432],
    [0, 0, 0, 0],
    [0, 131558114200 / 32700410799, -68118460800 / 10900136933, 87487479700 / 32700410799],
    [0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072],
    [0, 127303824393 / 49829197408, -318862633887 / 49829197408, 701980252875 / 199316789632],
    [0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844],
    [0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423],
])
DOPRI5 = ButcherTableau(
    "dopri5", _DP5_A, _DP5_B, [0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1, 1], order=5,
    b_embedded=_DP5_B - DOPRI5_E, order_embedded=4,
)

_n = _d853.N_STAGES
#: DOP853's error weights of its 5th- and 3rd-order estimators (13 entries: 12 stages + FSAL).
DOP853_E5 = _readonly(_d853.E5)
DOP853_E3 = _readonly(_d853.E3)
#: The three extra stages of DOP853's dense output (rows 13-15 of the extended tableau).
DOP853_A_EXTRA = _readonly(_d853.A[_n + 1:])
DOP853_C_EXTRA = _readonly(_d853.C[_n + 1:])
#: Coefficients of the 4 upper terms of DOP853's 7th-order dense output, shape (4, 16).
DOP853_D = _readonly(_d853.D)
DOP853 = ButcherTableau(
    "dop853", _d853.A[:_n, :_n], _d853.B, _d853.C[:_n], order=8,
    b_embedded=_d853.B - _d853.E5[:_n], order_embedded=5,
)

# Bogacki & Shampine (1989), 3(2) with FSAL: the 4th stage is f(t + h, y1) (scipy's RK23).
_BS_B = [2 / 9, 1 / 3, 4 / 9, 0]
#: Error weights b - b_embedded of Bogacki-Shampine 3(2) (b_embedded of order 2).
BS32_E = _readonly([2 / 9 - 7 / 24, 1 / 3 - 1 / 4, 4 / 9 - 1 / 3, -1 / 8])
BS32 = ButcherTableau(
    "bs32", [[0, 0, 0, 0], [1 / 2, 0, 0, 0], [0, 3 / 4, 0, 0], _BS_B], _BS_B,
    [0, 1 / 2, 3 / 4, 1], order=3, b_embedded=[7 / 24, 1 / 4, 1 / 3, 1 / 8], order_embedded=2,
)

#: Every tableau of this module, by name.
ALL = {t.name: t for t in (EULER, HEUN, MIDPOINT, RK4, RK38, DOPRI5, DOP853, BS32)}
