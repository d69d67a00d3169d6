"""The numeric decisions made by a threshold, each by one rule defined here and used at every
site where the same decision is made (docs: "Decisions by a threshold" in the core API page).

Every rule is **relative**: a model written in millimetres, or a mechanism a thousand times
smaller, gets the same verdicts as the same model in metres.

* **On the constraints** (:func:`on_constraints`): a condition is satisfied when its residual
  is at most :data:`ON_CONSTRAINTS` (1e-9) of the magnitude of its terms -- for a position
  condition Φ(q, t) the value of :func:`magnitude` (Φ with every sum taken term by term in
  absolute value, sines and cosines counted 1), for a velocity condition A q' + a the same
  of its expression with every rate at the largest ``|q'_j|`` (:func:`rates_for_scale`). A
  circle x² + y² - r² = 0 of radius 1e-10 is judged against x² + y² + r², not against an
  absolute 1e-9. A residual that is not finite is off.
* **Rank of a Jacobian** (:func:`numeric_rank`): the number of singular values above
  :data:`RANK_RTOL` (1e-9) times the largest one, once each row and each column is scaled to
  a largest entry of 1 (:func:`equilibrated`; entries under 1e-14 of the largest are
  rounding): the same matrix with its rows or columns in other units keeps its rank.
* **A residual with its tolerance** (:func:`vanishes`): where the caller states an absolute
  tolerance (``linearize(..., tol=1e-9)``: the steadiness of a reference state, the
  stationarity of a potential, the invariance of a steady motion), a number vanishes when
  ``|x| <= tol + allowance`` (the boundary holds; ``allowance`` what the rounding of the
  reference state leaves), an expression when it is identically zero.

Examples
--------
>>> import sympy as sp, numpy as np
>>> x, y, r = sp.symbols("x y r")
>>> magnitude(x**2 + y**2 - r**2)
r**2 + x**2 + y**2
>>> bool(on_constraints(np.array([1e-28]), np.array([3e-20])))   # 1e-28 > 1e-9 * 3e-20
False
>>> numeric_rank(1e-12 * np.array([[1.0, 0.0], [0.0, 2.0]]))
2
"""

from __future__ import annotations

import numpy as np
import sympy as sp

__all__ = ["ON_CONSTRAINTS", "RANK_RTOL", "ROUNDING_FLOOR", "magnitude", "on_constraints",
           "rates_for_scale", "equilibrated", "numeric_rank", "rank_of", "vanishes"]

#: Relative tolerance of a state on the constraints: ``|residual| <= ON_CONSTRAINTS *`` (the
#: magnitude of the condition's terms).
ON_CONSTRAINTS = 1e-9

#: Relative tolerance of the rank of a Jacobian: singular values at most RANK_RTOL times the
#: largest count as zero.
RANK_RTOL = 1e-9

#: Entries of a matrix at most this fraction of its largest are rounding, before the rank:
#: a few hundred operations leave about 1e-14 of their magnitude.
ROUNDING_FLOOR = 1e-14


def magnitude(expr) -> sp.Expr:
    """The magnitude of the terms of ``expr``: every sum replaced by the sum of the
    magnitudes of its terms, every product by the product of the magnitudes of its factors,
    an integer power by the power of its base's magnitude (an even power of a real value is
    kept), a sine or cosine by 1 (its range: the rounding of a sine that vanishes, sin(pi)
    = 1.2e-16, is of that size), anything else by its absolute value. It bounds ``|expr|`` and
    is the scale against which ``expr`` = 0 is judged: for a closure condition of lengths
    and angles, the sum of the lengths of its terms (a cancellation of large terms leaves
    rounding of their size).

    Examples
    --------
    >>> a, b, L = sp.symbols("a b L", positive=True)
    >>> magnitude(L * (sp.cos(a) - sp.cos(b)))
    2*L
    >>> magnitude(sp.Integer(-3)), magnitude(sp.Symbol("x") - 1)
    (3, Abs(x) + 1)
    """
    expr = sp.sympify(expr)
    if expr.is_Add:
        return sp.Add(*(magnitude(a) for a in expr.args))
    if expr.is_Mul:
        return sp.Mul(*(magnitude(a) for a in expr.args))
    if isinstance(expr, sp.sin | sp.cos):
        return sp.S.One
    if expr.is_Pow and expr.exp.is_Integer and expr.exp > 0:
        if expr.exp.is_even and not expr.base.is_Add:  # a real value: already >= 0
            return expr
        return magnitude(expr.base) ** expr.exp
    return sp.Abs(expr)


def rates_for_scale(u) -> np.ndarray:
    """The rates at which the magnitude of a velocity condition's terms is evaluated: every
    rate at the largest ``|q'_j|``. Rates solved from the conditions (the dependent ones) carry
    rounding of that size, also where the terms that contain them are small.

    Examples
    --------
    >>> rates_for_scale([0.5, -2.0, 1e-17]).tolist()
    [2.0, 2.0, 2.0]
    """
    u = np.abs(np.asarray(u, dtype=float))
    return np.full(u.shape, u.max() if u.size else 0.0)


def on_constraints(residuals, scales) -> np.ndarray:
    """For each condition, whether it holds: ``|residual| <= ON_CONSTRAINTS * scale``, with
    ``scale`` the magnitude of its terms (:func:`magnitude`, :func:`rates_for_scale`); a
    residual that is not finite does not hold. The boundary holds.

    Examples
    --------
    >>> on_constraints(np.array([1e-9, 1.000001e-9, np.nan]), np.array([1.0, 1.0, 1.0]))
    array([ True, False, False])
    """
    r = np.abs(np.asarray(residuals, dtype=float))
    s = np.asarray(scales, dtype=float)
    return np.isfinite(r) & (r <= ON_CONSTRAINTS * s)


def equilibrated(A):
    """``A`` with each row, then each column, divided by its largest magnitude (rows and
    columns of zeros kept): the same matrix whatever the units of its rows (conditions on
    lengths or on angles) and of its columns (rates of lengths or of angles). Entries at most
    :data:`ROUNDING_FLOOR` of the largest are rounding and count as zero first (a row of
    rounding is not blown up to a row of ones).

    Examples
    --------
    >>> equilibrated(np.array([[1e-10, 2e-10], [1.0, 0.0]])).tolist()
    [[0.5, 1.0], [1.0, 0.0]]
    """
    A = np.array(A)
    top = np.abs(A).max() if A.size else 0.0
    if not top:
        return A
    A[np.abs(A) <= ROUNDING_FLOOR * top] = 0
    for axis in (1, 0):
        size = np.abs(A).max(axis=axis, keepdims=True)
        A = A / np.where(size > 0, size, 1.0)
    return A


def numeric_rank(A) -> int:
    """The rank of a numeric matrix: the number of singular values above :data:`RANK_RTOL`
    times the largest, of the matrix :func:`equilibrated` (rows and columns scaled to a
    largest magnitude of 1; 0 for an empty or a zero matrix). One rule for every decision on
    the rank of a constraint Jacobian (mobility, dependent coordinates, reduced equations,
    linearisation, regimes, singular positions); the same matrix in other units (its rows
    and columns multiplied by nonzero numbers) has the same rank.

    Examples
    --------
    >>> numeric_rank(np.array([[1.0, 2.0], [2.0, 4.0]])), numeric_rank(np.zeros((0, 3)))
    (1, 0)
    >>> numeric_rank(np.array([[1e-10, 0.0], [0.0, 1.0]]))     # rows in other units
    2
    """
    A = np.asarray(A)
    if not np.iscomplexobj(A):
        A = A.astype(float)
    if A.size == 0:
        return 0
    if not np.all(np.isfinite(A)):
        raise np.linalg.LinAlgError("the matrix has entries that are not finite")
    return rank_of(np.linalg.svd(equilibrated(A), compute_uv=False))


def rank_of(singular_values) -> int:
    """The rank that singular values (largest first) give: how many are above
    :data:`RANK_RTOL` times the largest (the boundary is not). The SVD computes them to
    about 1e-16 of the largest: a ratio within 1e-7 of the threshold is decided by its
    rounding.

    Examples
    --------
    >>> rank_of([2.0, 2e-9]), rank_of([2.0, 2.000001e-9]), rank_of([0.0, 0.0]), rank_of([])
    (1, 2, 0, 0)
    """
    s = np.asarray(singular_values, dtype=float)
    if not s.size or s[0] == 0:
        return 0
    return int(np.count_nonzero(s > RANK_RTOL * s[0]))


def vanishes(x, tol, allowance=0.0) -> bool:
    """Whether the residual ``x`` is zero, given the caller's absolute tolerance ``tol``: a
    number (real or complex) when ``|x| <= tol + allowance`` (the boundary holds;
    ``allowance`` is what the rounding of the state it is evaluated at leaves, such as
    ``rigidmech.vibrations.linearize.rounding_allowance``), an expression when it is
    identically zero (:func:`rigidmech._core.symbolic.is_identically_zero`). One rule for the
    steadiness of a reference state of a linearisation, the stationarity of a potential, the
    invariance of a steady motion and the reduced stiffness of a constrained linearisation.

    Examples
    --------
    >>> vanishes(1e-9, 1e-9), vanishes(1.000001e-9, 1e-9), vanishes(-2e-9, 1e-9, 1e-9)
    (True, False, True)
    >>> a = sp.Symbol("a")
    >>> vanishes(sp.sin(a)**2 + sp.cos(a)**2 - 1, 1e-9), vanishes(1e-30 * a, 1e-9)
    (True, False)
    """
    x = sp.sympify(x)
    if x.is_number:
        return bool(abs(complex(x)) <= tol + allowance)
    # imported here: rigidmech._core.symbolic imports this module (for magnitude)
    from .symbolic import is_identically_zero

    return is_identically_zero(x)
