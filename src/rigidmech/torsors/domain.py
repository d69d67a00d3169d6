"""Domains of the geometric space for fields of sliders (book, ch. 5.3.2): a curve, a surface
or a volume parametrised in a frame, its measure element and the integrals over it.

A domain is a parametrisation :math:`P(u)`, :math:`P(u, v)` or :math:`P(u, v, w)` in a frame
with parameter ranges (:class:`Domain`); its measure element :math:`|P_u|\\,du`,
:math:`|P_u\\wedge P_v|\\,du\\,dv` or :math:`|\\det J|\\,du\\,dv\\,dw` is derived from it.
Integrals are symbolic (``sympy.integrate``) with a numeric fallback (Gauss-Legendre
product rule, or ``scipy.integrate.nquad``). The torsors and measure centres of fields over a
domain are in :mod:`rigidmech.torsors.fields`, which re-exports :class:`Domain`.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, NumericalError
from ..vectors import Frame, Point, Vector

__all__ = ["Domain"]

_KINDS = {1: "curve", 2: "surface", 3: "volume"}
_METHODS = ("auto", "symbolic", "numeric", "quad")


class Domain:
    """A domain of the geometric space, parametrised in a frame: a curve, a surface or a
    volume (ch. 5.3.2).

    Parameters
    ----------
    frame : Frame
        The frame (O; i, j, k) of the parametrisation.
    position : Vector or sequence of 3 expressions
        :math:`\\mathbf{OP}(u, \\ldots)`, as a Vector or as its coordinates in ``frame``.
    *ranges : tuples (symbol, low, high)
        One (curve), two (surface) or three (volume) parameters with their ranges, in
        ``sympy.integrate``'s order: the first is integrated first, so its bounds may depend
        on the parameters after it (and only on them).
    measure : sympy expression, optional
        The measure element per du (dv, dw), when you know it. By default it is derived:
        :math:`|P_u|`, :math:`|P_u \\wedge P_v|`, :math:`|\\det(P_u, P_v, P_w)|`.

    Notes
    -----
    The derived measure is simplified with each parameter taken real, and non-negative when
    its lower bound is (non-positive when its upper bound is). Declare your constants
    positive (``constants("R h", positive=True)``) so that :math:`\\sqrt{R^2}` becomes R.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame, constants
    >>> R = constants("R", positive=True)
    >>> u = sp.Symbol("u")
    >>> R0 = Frame("R0")
    >>> wire = Domain(R0, R * sp.cos(u) * R0.i + R * sp.sin(u) * R0.j, (u, 0, sp.pi))
    >>> wire.kind, wire.measure
    ('curve', R)
    """

    __slots__ = ("_frame", "_coords", "_ranges", "_measure")

    def __init__(self, frame, position, *ranges, measure=None):
        if not isinstance(frame, Frame):
            raise ArgumentTypeError(f"`frame` must be a Frame; got {type(frame).__name__}.")
        if isinstance(position, Point):
            raise ArgumentTypeError(
                f"`position` must be the Vector OP (or 3 coordinates), not the Point "
                f"{position.name}; use {position.name} - {frame.name}.origin.")
        if isinstance(position, Vector):
            coords = tuple(position.components(frame))
        else:
            try:
                coords = tuple(sp.sympify(c) for c in position)
            except (TypeError, sp.SympifyError) as exc:
                raise ArgumentTypeError(
                    f"`position` must be a Vector or 3 coordinates; got {position!r}.") from exc
            if len(coords) != 3:
                raise ArgumentError(
                    f"`position` must have 3 coordinates; got {len(coords)}: {position!r}.")
        if not 1 <= len(ranges) <= 3:
            raise ArgumentError(
                "a domain needs 1 (curve), 2 (surface) or 3 (volume) parameter ranges; got "
                f"{len(ranges)}.")
        checked = []
        for n, rng in enumerate(ranges):
            if not (isinstance(rng, tuple | list) and len(rng) == 3):
                raise ArgumentError(
                    f"`ranges[{n}]` must be a tuple (symbol, low, high); got {rng!r}.")
            var, low, high = sp.sympify(rng[0]), sp.sympify(rng[1]), sp.sympify(rng[2])
            if not isinstance(var, sp.Symbol):
                raise ArgumentTypeError(
                    f"`ranges[{n}]` must start with a sympy Symbol; got {var!r}.")
            checked.append((var, low, high))
        variables = [v for v, _, _ in checked]
        if len(set(variables)) != len(variables):
            raise ArgumentError(f"the parameters must be distinct; got {variables}.")
        for n, (var, low, high) in enumerate(checked):
            inner = set(variables[: n + 1])
            bad = (low.free_symbols | high.free_symbols) & inner
            if bad:
                raise ArgumentError(
                    f"the bounds of `{var}` may depend only on the parameters listed after it "
                    f"(sympy.integrate's order); got bounds ({low}, {high}) using "
                    f"{sorted(map(str, bad))}.")
        self._frame = frame
        self._coords = coords
        self._ranges = tuple(checked)
        self._measure = sp.sympify(measure) if measure is not None else self._derive_measure()

    def _derive_measure(self):
        dummies = {}
        for var, low, high in self._ranges:
            assumptions = {"real": True}
            if low.is_nonnegative:
                assumptions["nonnegative"] = True
            elif high.is_nonpositive:
                assumptions["nonpositive"] = True
            dummies[var] = sp.Dummy(var.name, **assumptions)
        r = sp.Matrix(self._coords).xreplace(dummies)
        cols = [r.diff(dummies[var]) for var, _, _ in self._ranges]
        if len(cols) == 1:
            g = cols[0].dot(cols[0])
        elif len(cols) == 2:
            n = cols[0].cross(cols[1])
            g = n.dot(n)
        else:
            g = sp.Matrix.hstack(*cols).det() ** 2
        g = sp.factor(sp.trigsimp(sp.expand(g)))
        measure = sp.simplify(sp.sqrt(g)).xreplace({d: v for v, d in dummies.items()})
        return self._drop_abs(measure)

    def _drop_abs(self, measure):
        """Replace |f(u)| by f or -f when f keeps one sign over the numeric range of u."""
        bounds = {v: (low, high) for v, low, high in self._ranges}
        rules = {}
        for atom in measure.atoms(sp.Abs):
            arg = atom.args[0]
            variables = arg.free_symbols & set(bounds)
            if len(variables) != 1:
                continue
            (var,) = variables
            low, high = bounds[var]
            if not (low.is_number and high.is_number):
                continue
            interval = sp.Interval(low, high)
            try:
                if sp.solveset(arg < 0, var, interval) is sp.S.EmptySet:
                    rules[atom] = arg
                elif sp.solveset(arg > 0, var, interval) is sp.S.EmptySet:
                    rules[atom] = -arg
            except (NotImplementedError, ValueError, TypeError):
                continue
        return measure.xreplace(rules) if rules else measure

    # -- access -------------------------------------------------------------------------
    @property
    def frame(self) -> Frame:
        """The frame of the parametrisation."""
        return self._frame

    @property
    def coordinates(self) -> tuple:
        """The coordinates of P in ``frame``, functions of the parameters."""
        return self._coords

    @property
    def position(self) -> Vector:
        """The vector OP from the frame's origin, a function of the parameters."""
        return Vector.from_components(self._frame, self._coords)

    @property
    def ranges(self) -> tuple:
        """The parameter ranges ``(symbol, low, high)``, first integrated first."""
        return self._ranges

    @property
    def parameters(self) -> tuple:
        """The parameters, in the order of :attr:`ranges`."""
        return tuple(v for v, _, _ in self._ranges)

    @property
    def dimension(self) -> int:
        """1, 2 or 3."""
        return len(self._ranges)

    @property
    def kind(self) -> str:
        """'curve', 'surface' or 'volume'."""
        return _KINDS[len(self._ranges)]

    @property
    def measure(self) -> sp.Expr:
        """The measure element per unit of the parameters (length, area or volume)."""
        return self._measure

    def __eq__(self, other):
        if not isinstance(other, Domain):
            return NotImplemented
        return (self._frame == other._frame and self._coords == other._coords
                and self._ranges == other._ranges and self._measure == other._measure)

    def __hash__(self):
        return hash((Domain, self._frame, self._coords, self._ranges, self._measure))

    def __repr__(self):
        ranges = ", ".join(f"({v}, {sp.sstr(a)}, {sp.sstr(b)})" for v, a, b in self._ranges)
        coords = ", ".join(sp.sstr(c) for c in self._coords)
        return f"Domain({self._frame.name}, [{coords}], {ranges})"

    # -- integration --------------------------------------------------------------------
    def integrate(self, integrands, *, method="auto", order=32):
        """Integrals over the domain of the given expressions times the measure element.

        Parameters
        ----------
        integrands : sequence of sympy expressions
            Functions of the parameters.
        method : {'auto', 'symbolic', 'numeric', 'quad'}
            'symbolic': ``sympy.integrate``, error if it fails. 'numeric': Gauss-Legendre
            product rule with ``order`` nodes per parameter (exact for polynomials of degree
            < 2 ``order``). 'quad': ``scipy.integrate.nquad`` (adaptive, slower).
            'auto' (default): symbolic, then 'numeric' where sympy fails and the integrand
            has no free symbol besides the parameters.
        order : int
            Nodes per parameter of the Gauss-Legendre rule.

        Returns
        -------
        list of sympy expressions (floats for the numeric methods)

        Raises
        ------
        ArgumentError
            For an unknown method, or when sympy fails and symbols other than the parameters
            remain (no numeric fallback possible).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech import Frame
        >>> u = sp.Symbol("u")
        >>> segment = Domain(Frame("R0"), [u, 0, 0], (u, 0, 1))
        >>> segment.integrate([1, u**2])
        [1, 1/3]
        >>> segment.integrate([sp.exp(-u**2) * sp.cos(u)**3], method="numeric")
        [0.53525784611...]
        """
        if method not in _METHODS:
            raise ArgumentError(f"`method` must be one of {_METHODS}; got {method!r}.")
        exprs = [sp.sympify(e) * self._measure for e in integrands]
        if method in ("numeric", "quad"):
            return self._integrate_numeric(exprs, method, order)
        out = []
        for e in exprs:
            value = None
            try:
                value = sp.integrate(e, *self._ranges)
            except (NotImplementedError, ValueError, TypeError):  # sympy gave up
                value = None
            if value is None or value.has(sp.Integral):
                if method == "symbolic":
                    raise ArgumentError(
                        f"sympy could not integrate {e} over the domain; use "
                        "method='numeric' with numeric values for the symbols.")
                value = self._integrate_numeric([e], "numeric", order)[0]
            out.append(value)
        return out

    def _integrate_numeric(self, exprs, method, order):
        params = self.parameters
        extra = set()
        for e in exprs:
            extra |= e.free_symbols
        for _, low, high in self._ranges:
            extra |= low.free_symbols | high.free_symbols
        extra -= set(params)
        if extra:
            raise ArgumentError(
                "numeric integration needs numbers for every symbol but the parameters; got "
                f"{sorted(map(str, extra))}: substitute values (or use method='symbolic').")
        funcs = [sp.lambdify(params, e, modules="numpy") for e in exprs]
        bounds = [(sp.lambdify(params, low, modules="numpy"),
                   sp.lambdify(params, high, modules="numpy")) for _, low, high in self._ranges]
        if method == "quad":
            return [_nquad(f, bounds, len(params)) for f in funcs]
        return _gauss_legendre(funcs, bounds, len(params), int(order))


def _gauss_legendre(funcs, bounds, dim, order):
    """Product Gauss-Legendre rule over nested ranges (first range innermost)."""
    if order < 1:
        raise ArgumentError(f"`order` must be a positive integer; got {order}.")
    xi, wi = np.polynomial.legendre.leggauss(order)
    values = [np.zeros(1) for _ in range(dim)]  # samples of each parameter, per node
    weights = np.ones(1)
    for k in reversed(range(dim)):  # outermost first
        args = [np.repeat(v, order) for v in values]
        weights = np.repeat(weights, order)
        lo, hi = (np.broadcast_to(np.asarray(b(*args), dtype=float), weights.shape)
                  for b in bounds[k])
        half = (hi - lo) / 2
        x = np.tile(xi, weights.size // order)
        w = np.tile(wi, weights.size // order)
        args[k] = lo + half * (x + 1)
        values = args
        weights = weights * half * w
    out = []
    for f in funcs:
        with np.errstate(all="ignore"):
            y = np.broadcast_to(np.asarray(f(*values), dtype=float), weights.shape)
        total = float(weights @ y)
        if not np.isfinite(total):
            raise NumericalError(
                "the Gauss-Legendre integral is not finite: the integrand is singular at a "
                "node; use method='quad' or check the domain.")
        out.append(sp.Float(total))
    return out


def _nquad(f, bounds, dim):
    # Imported on use: scipy.integrate costs about 0.7 s to import and most sessions never
    # integrate numerically.
    import scipy.integrate

    def ranges_for(k):
        lo, hi = bounds[k]

        def rng(*outer):
            args = [0.0] * (k + 1) + list(outer)
            return float(lo(*args)), float(hi(*args))
        return rng

    value, _ = scipy.integrate.nquad(lambda *x: float(f(*x)), [ranges_for(k)
                                                                 for k in range(dim)])
    return sp.Float(value)
