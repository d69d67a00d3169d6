"""Limiting equilibrium with friction: where the equilibrium breaks, and how (book, ch. 13.1,
14.4).

A body held by contacts (:class:`~rigidmech.actions.contact_laws.ContactLaws`) is at rest while
the equations of statics have a solution that satisfies the laws of every contact: N >= 0
(one-sided contact), ``|T| <= f_s N`` (Coulomb), ``|M_r| <= delta N`` (rolling resistance, or a flat
base of half-width a: tipping), ``|M_p| <= eta N`` (pivoting). With one tangent per contact these
laws are linear inequalities, so the existence of an equilibrium at a given value of a
parameter p (a load, an angle) is a linear feasibility problem. Its **margin**

.. math:: m(p) = \\max_{x:\\ A(p)\\,x = b(p)}\\ \\min_k\\ \\frac{g_k \\cdot x}{|g_k|}

(the largest distance to the boundary of the laws, capped) is computed by linear
programming (:func:`scipy.optimize.linprog`, HiGHS); it is positive while the body stays at
rest and changes sign where the equilibrium breaks, located by a scan and Brent's method.
This works for hyperstatic contacts too (a ladder with friction at both ends, whose friction
forces statics alone does not determine).

Which happens first: the limit is computed once with all the laws and once per kind of law
(``'sliding'``, ``'tipping'``, ``'rolling'``, ``'pivoting'``, ``'lift-off'``), keeping
only that kind and N >= 0 (the other laws taken as unbreakable): the kinds whose own limit is
the overall limit are the ones that break first.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.lazy import lazy_functions
from .._core.validation import substitutions
from .errors import EquilibriumError

# lazy: import cost (scipy.optimize takes ~0.3 s; see docs/performance)
brentq, linprog = lazy_functions(globals(), "scipy.optimize", "brentq", "linprog")

__all__ = ["limiting_equilibrium", "Limit", "largest_margin"]

_CAP = 1.0


class Limit:
    """Where an equilibrium with friction breaks (see :func:`limiting_equilibrium`).

    Attributes
    ----------
    parameter : sympy.Symbol
    value : float or None
        First value of the parameter, from the start of the interval, where the equilibrium
        breaks (None: it holds over the whole interval).
    kinds : tuple of str
        What happens there: ``'sliding'``, ``'tipping'``, ``'rolling'``, ``'pivoting'`` or
        ``'lift-off'``.
    contacts : tuple of str
        Labels of the contacts whose laws are at their limit there.
    by_kind : dict
        For each kind of law, the value where it alone would break (None if never).

    Examples
    --------
    See :func:`limiting_equilibrium`.
    """

    __slots__ = ("_parameter", "_value", "_kinds", "_contacts", "_by_kind")

    def __init__(self, parameter, value, kinds, contacts, by_kind):
        self._parameter, self._value = parameter, value
        self._kinds, self._contacts, self._by_kind = tuple(kinds), tuple(contacts), dict(by_kind)

    parameter = property(lambda self: self._parameter, doc="The parameter that varies.")
    value = property(lambda self: self._value, doc="Where the equilibrium breaks first.")
    kinds = property(lambda self: self._kinds, doc="What breaks first.")
    contacts = property(lambda self: self._contacts, doc="The contacts at their limit.")
    by_kind = property(lambda self: dict(self._by_kind),
                       doc="Limit of each kind of law alone (a fresh dict).")

    def __str__(self):
        if self._value is None:
            return f"the equilibrium holds for every {self._parameter} of the interval"
        others = ", ".join(f"{k} at {v:.12g}" for k, v in self._by_kind.items()
                           if v is not None and k not in self.kinds)
        text = (f"{' and '.join(self.kinds)} starts at {self.parameter} = {self.value:.12g} "
                f"(contacts {', '.join(self.contacts)})")
        return text + (f"; alone: {others}" if others else "")

    def __repr__(self):
        return (f"Limit({self.parameter}={self.value!r}, kinds={self.kinds!r}, "
                f"contacts={self.contacts!r})")


def largest_margin(A, b, G):
    """The linear program of the limiting equilibrium at one value of its parameter: the
    largest margin t with A x = b and G x >= t (ch. 14.4), and the unknowns x that reach it.

    Parameters
    ----------
    A, b : numpy arrays, shapes (m, n) and (m,)
        The equations of statics in the unknowns x.
    G : numpy array, shape (k, n)
        The contact laws as rows g_k . x >= 0, each of unit norm.

    Returns
    -------
    (float, numpy array or None)
        t, measured in units of max|b| and capped (the program is solved with b / max|b|),
        and x (in the units of b); ``(-cap, None)`` when the equations have no solution.

    Raises
    ------
    EquilibriumError
        If the linear program fails otherwise.

    Examples
    --------
    >>> import numpy as np
    >>> t, x = largest_margin(np.array([[1.0, 1.0]]), np.array([2.0]), np.eye(2))
    >>> round(t, 9), x.round(9).tolist()
    (0.5, [1.0, 1.0])
    """
    return _lp_margin(A, b, G, want_x=True)


def _lp_margin(A, b, G, want_x=False):
    """max t s.t. A x = b, G x >= t (rows of G of unit norm), -cap <= t <= cap."""
    n = A.shape[1]
    scale = max(np.abs(b).max(initial=0.0), 1e-300)
    c = np.zeros(n + 1)
    c[-1] = -1.0
    A_eq = np.hstack([A, np.zeros((A.shape[0], 1))])
    A_ub = np.hstack([-G, np.ones((G.shape[0], 1))]) if G.size else None
    b_ub = np.zeros(G.shape[0]) if G.size else None
    res = linprog(c, A_ub=A_ub, b_ub=b_ub, A_eq=A_eq, b_eq=b / scale,
                  bounds=[(None, None)] * n + [(-_CAP, _CAP)], method="highs",
                  options={"primal_feasibility_tolerance": 1e-10,
                           "dual_feasibility_tolerance": 1e-10})
    if res.status == 2:       # the equations themselves have no solution
        return (-_CAP, None) if want_x else -_CAP
    if res.status != 0:
        raise EquilibriumError(f"the linear program of the limit failed: {res.message}")
    t = float(res.x[-1])
    return (t, res.x[:-1] * scale) if want_x else t


def limiting_equilibrium(statics, parameter, interval, *, values=None,
                         samples: int = 200) -> Limit:
    """The first value of ``parameter`` in ``interval`` where the equilibrium of ``statics``
    breaks, and how (ch. 14.4).

    Parameters
    ----------
    statics : Statics
        Bodies held by contacts (:class:`~rigidmech.actions.contact_laws.ContactLaws`) with one
        tangent each, and possibly by joints.
    parameter : sympy.Symbol
        The load or angle that varies.
    interval : (float, float)
        From the value where the bodies are at rest to the end of the search (may decrease).
    values : dict
        Numbers for every other symbol, keyed by symbol or by name (checked against the
        symbol's declaration: a negative value for a positive symbol is refused).
    samples : int
        Points of the scan that brackets the first sign change of the margin.

    Returns
    -------
    Limit

    Raises
    ------
    EquilibriumError
        If there is no equilibrium at the start of the interval.

    Notes
    -----
    The value is as accurate as the linear programs (tolerances 1e-10 on the scaled
    problem): about 1e-9 relative in practice. The scan finds the first sign change of the
    margin on ``samples`` intervals: a window of broken equilibrium narrower than one interval
    may be missed. The margin is measured relative to the given loads, which must not all
    vanish at the start of the interval. Contacts must have one tangent (plane problems):
    the laws are then linear.

    Examples
    --------
    A box of weight W and half-width a pushed by P at height h on a floor with f_s = 0.4:
    it slides at P = f_s W = 4 before it would tip at P = W a/h = 5.

    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> from rigidmech.actions import ContactLaws, Coulomb, Force
    >>> P = sp.Symbol("P")
    >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
    >>> st = rm.statics.Statics(R0)
    >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
    ...            friction=Coulomb(0.4), footprint=0.5, rolling_axis=R0.k), label="floor")
    >>> st.act(Force(on=box, vector=-10 * R0.j, at=R0.point("G", 0, 0.5, 0)))
    >>> st.act(Force(on=box, vector=P * R0.i, at=R0.point("H", -0.5, 1.0, 0)))
    >>> lim = limiting_equilibrium(st, P, (0, 10))
    >>> round(lim.value, 8), lim.kinds, round(lim.by_kind["tipping"], 8)
    (4.0, ('sliding',), 5.0)
    """
    if not all(callable(getattr(statics, m, None)) for m in ("equations",
                                                            "contact_conditions")):
        raise ArgumentTypeError(f"`statics` must be a Statics; got {type(statics).__name__}.")
    if not isinstance(parameter, sp.Symbol):
        raise ArgumentTypeError(f"`parameter` must be a sympy Symbol; got {parameter!r}.")
    try:
        p0, p1 = (float(v) for v in interval)
    except (TypeError, ValueError):
        raise ArgumentError(f"`interval` must be a pair of numbers; got {interval!r}.") from None
    if p0 == p1:
        raise ArgumentError(f"`interval` must have two different ends; got {interval!r}.")
    xs = list(statics.unknowns)
    rows = statics.equations()
    conds = statics.contact_conditions()
    subs = substitutions(values, set().union(*(e.free_symbols for _, _, e in rows),
                                             *(e.free_symbols for _, _, e in conds)))
    exprs = [e.xreplace(subs) for _, _, e in rows]
    if not conds:
        raise ArgumentError("`statics` has no contact law (ContactLaws with friction, rolling, "
                            "footprint or pivoting): nothing can break.")
    A, b = sp.linear_eq_to_matrix(exprs, xs)
    G, _ = sp.linear_eq_to_matrix([e.xreplace(subs) for _, _, e in conds], xs)
    free = (A.free_symbols | b.free_symbols | G.free_symbols) - {parameter}
    if free:
        raise ArgumentError(f"`values` must give numbers for {sorted(free, key=str)}.")
    fA, fb, fG = (sp.lambdify(parameter, M, "numpy") for M in (A, b, G))
    kinds_of = [k for k, _, _ in conds]
    labels_of = [lab for _, lab, _ in conds]

    def data(p, mask):
        An = np.array(fA(p), dtype=float).reshape(A.shape)
        bn = np.array(fb(p), dtype=float).reshape(-1)
        Gn = np.array(fG(p), dtype=float).reshape(G.shape)[mask]
        norms = np.linalg.norm(Gn, axis=1)
        return An, bn, Gn / np.where(norms > 0, norms, 1.0)[:, None]

    def margin(p, mask):
        return _lp_margin(*data(p, mask))

    grid = np.linspace(p0, p1, samples + 1)
    # The margin of all the laws at the scan's points, as far as its scan went. A subset of
    # the laws drops inequalities from the same linear program, so its margin is at least
    # this one: where all the laws hold with a positive margin, so does every subset, and the
    # subsets' scans start at the first point not known positive (the same brackets as a scan
    # from the start, without solving again the programs before them).
    held = []

    def first_root(mask):
        start = 0
        if mask is not everything:
            while start < len(held) and held[start] > 0:    # held[k]: at grid[k + 1]
                start += 1
        elif margin(grid[0], mask) <= 0:
            return "start"
        for k in range(start, samples):
            m = margin(grid[k + 1], mask)
            if mask is everything:
                held.append(m)
            if m <= 0:
                return brentq(lambda p: margin(p, mask), grid[k], grid[k + 1], xtol=1e-15,
                              rtol=1e-14)
        return None

    everything = np.ones(len(conds), dtype=bool)
    value = first_root(everything)
    if value == "start":
        raise EquilibriumError(
            f"no equilibrium at the start of `interval`, {parameter} = {p0}: the contact "
            "laws cannot all be satisfied there; start from a value where the bodies are "
            "at rest.")
    by_kind = {}
    for kind in dict.fromkeys(k for k in kinds_of if k != "lift-off"):
        mask = np.array([k in (kind, "lift-off") for k in kinds_of])
        by_kind[kind] = first_root(mask)
    if "lift-off" in kinds_of:
        by_kind["lift-off"] = first_root(np.array([k == "lift-off" for k in kinds_of]))
    if value is None:
        return Limit(parameter, None, (), (), by_kind)
    tol = 1e-7 * max(abs(value), abs(p1 - p0))
    kinds = tuple(k for k, v in by_kind.items() if v is not None and abs(v - value) <= tol)
    # contacts at their limit: slack ~ 0 in the all-laws program at the limit
    An, bn, Gn = data(value, everything)
    _, x = _lp_margin(An, bn, Gn, want_x=True)
    contacts = []
    if x is not None:
        slack = Gn @ x / max(np.abs(bn).max(initial=0.0), 1e-300)
        for k, lab, s in zip(kinds_of, labels_of, slack, strict=True):
            if k in kinds and s < 1e-6 and lab not in contacts:
                contacts.append(lab)
    return Limit(parameter, float(value), kinds, contacts, by_kind)
