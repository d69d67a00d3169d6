"""Degree of mobility and degree of hyperstaticity of a mechanism (book, ch. 13.2, 14.2).

**Method.** Both numbers are ranks of linear equations written on the graph of connections
(:class:`~rigidmech.systems.Mechanism`), evaluated at a *generic configuration*: every
parameter of situation and every constant symbol replaced by a random number (seeded,
reproducible), or by the values given.

* **Kinematics** (ch. 13.2.5). Each connection allows the relative motion
  ``allowed_motion(label)``: a kinematic torsor linear in its N_c,k free components (its
  degrees of freedom). Going round each independent loop of the graph the relative motions
  compose to zero, :math:`\\sum \\pm\\{\\mathcal V(j/i)\\} = \\{0\\}`: six scalar equations per
  loop (three in a planar problem: the rotation about the normal and the two velocity
  components in the plane), all reduced at the reference's origin. With r_c the rank of these
  equations, the degree of mobility is

  .. math:: m = N_c - r_c,\\qquad N_c = \\sum_k N_{c,k}

  (plus six, or three, for each group of bodies not connected to the ground).
* **Statics** (ch. 14.2). The action of each perfect connection has N_s,k unknown
  components (``action_torsor(label)``); the equilibrium of each body gives six equations
  (three in a plane). With r_s the rank of these equations in the unknowns, the degree of
  hyperstaticity is h = N_s - r_s, the number of unknowns that statics cannot determine. By
  the duality of the two sets of equations (the power of a perfect connection is zero), it is
  the book's formula

  .. math:: h = N_s - 6 N_b + m \\quad (\\text{3D}),\\qquad h = N_s - 3 N_b + m
            \\quad (\\text{planar}),

  and both routes are computed (they agree unless the configuration is singular). The
  unknowns that the null space of the equilibrium equations touches are reported as
  undetermined; the others are determined by statics (the isostatic part).

In a planar problem (``plane=R0.k``) only the components in the plane count: a pivot of axis
k has 1 kinematic and 2 static unknowns instead of 1 and 5.
"""

from __future__ import annotations

import random

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.rules import numeric_rank
from .._core.symbolic import complex_values
from ..torsors import Torsor
from ..vectors import Vector

__all__ = ["Mobility", "analyse", "GenericValues", "numeric_rank"]


class Mobility:
    """Degrees of mobility and hyperstaticity of a mechanism (ch. 13.2, 14.2).

    Attributes
    ----------
    mobility : int
        m, the number of independent motions the connections allow.
    hyperstaticity : int
        h, the number of connection unknowns statics leaves undetermined.
    loops : int
        Number of independent loops of the graph.
    kinematic_unknowns, static_unknowns : int
        N_c and N_s.
    bodies : int
        N_b, the moving bodies.
    planar : bool
    undetermined : tuple of sympy.Symbol
        The unknowns not determined by statics (empty for an isostatic mechanism).

    Examples
    --------
    >>> import rigidmech as rm
    >>> from rigidmech.systems import Mechanism
    >>> R0 = rm.Frame("R0"); th = rm.coordinates("theta")
    >>> shaft = rm.Body("shaft", frame=R0.rotated("R1", about=R0.k, angle=th))
    >>> g = (Mechanism(R0)
    ...      .with_connection(R0, shaft, rm.joints.Spherical(at=R0.origin), label="A")
    ...      .with_connection(R0, shaft, rm.joints.LinearAnnular(
    ...          at=R0.point("B", 0, 0, 1), axis=R0.k), label="B"))
    >>> r = g.mobility()
    >>> r.mobility, r.hyperstaticity, r.undetermined
    (1, 0, ())
    """

    __slots__ = ("mobility", "hyperstaticity", "loops", "kinematic_unknowns",
                 "static_unknowns", "bodies", "planar", "undetermined", "statics_rank",
                 "kinematics_rank")

    def __init__(self, **values):
        for k in self.__slots__:
            object.__setattr__(self, k, values[k])

    def __setattr__(self, key, value):
        raise AttributeError("Mobility is immutable")

    @property
    def isostatic(self) -> bool:
        """True when h = 0: statics determines every connection unknown."""
        return self.hyperstaticity == 0

    def __str__(self):
        eq = 3 if self.planar else 6
        lines = [
            f"mobility m = {self.mobility} (N_c = {self.kinematic_unknowns} kinematic "
            f"unknowns, rank {self.kinematics_rank} of the closure equations of "
            f"{self.loops} loop(s))",
            f"hyperstaticity h = {self.hyperstaticity} = N_s - {eq} N_b + m = "
            f"{self.static_unknowns} - {eq}*{self.bodies} + {self.mobility}"
            + (" (isostatic)" if self.isostatic else ""),
        ]
        if self.undetermined:
            lines.append("undetermined by statics: "
                         + ", ".join(str(u) for u in self.undetermined))
        return "\n".join(lines)

    def __repr__(self):
        return (f"Mobility(mobility={self.mobility}, hyperstaticity={self.hyperstaticity}, "
                f"loops={self.loops}, planar={self.planar})")


def _plane_basis(plane, reference):
    if isinstance(plane, Vector) and len(plane.parts) == 1:
        frame, c = plane.parts[0]
        nz = [n for n in range(3) if c[n] != 0]
        if len(nz) == 1 and c[nz[0]] in (1, -1):
            e = frame.basis
            n = nz[0]
            return e[(n + 1) % 3], e[(n + 2) % 3], e[n]
    raise ArgumentTypeError(
        f"`plane` must be the unit normal of the plane as a basis vector of a frame "
        f"(e.g. R0.k), or None for a spatial problem; got {plane!r}.")


def _components(T: Torsor, O, basis, planar):
    """(resultant, moment at O) components: 6 in the basis, or 3 for a plane."""
    m = T.moment_at(O)
    if planar:
        e1, e2, n = basis
        return [T.resultant.dot(n), m.dot(e1), m.dot(e2)], [T.resultant.dot(e1),
                                                            T.resultant.dot(e2), m.dot(n)]
    R, M = list(T.resultant.components(basis)), list(m.components(basis))
    return R + M, R + M


class GenericValues:
    """Numbers for an expression at a generic configuration (book, ch. 13.2): the values
    given, and seeded random ones for every other symbol, coordinate and derivative.

    One object keeps the values it drew, so every expression evaluated through it sees the
    same configuration; ranks computed from such numbers are the generic ranks (a rank lost
    at one configuration only is found with probability zero).

    Parameters
    ----------
    values : mapping, optional
        Values of symbols or coordinates (by object or by name).
    seed : int
        Seed of the random values.

    Examples
    --------
    >>> import sympy as sp
    >>> a, b = sp.symbols("a b")
    >>> numbers = GenericValues({a: 2.0}, seed=0)
    >>> numbers(a * b) == 2.0 * numbers(b)
    True
    """

    def __init__(self, values, seed):
        self._given = {} if values is None else dict(values)
        # the standard library's generator, not numpy's: importing numpy.random (~10 ms) is
        # a quarter of the derivation of a small closed-loop model
        self._rng = random.Random(seed)
        self._rule = {}

    def __call__(self, expr):
        expr = sp.sympify(expr)
        if expr.is_Number:
            return float(expr)
        for d in expr.atoms(sp.Derivative):
            self._rule.setdefault(d, sp.Float(self._rng.uniform(-1, 1)))
        for a in expr.atoms(sp.core.function.AppliedUndef):
            if a not in self._rule:
                self._rule[a] = sp.Float(self._given.get(a, self._rng.uniform(0.3, 1.3)))
        for s in expr.free_symbols:
            if s not in self._rule:
                self._rule[s] = sp.Float(self._given.get(s, self._given.get(
                    getattr(s, "name", None), self._rng.uniform(0.6, 1.6))))
        try:  # one double-precision walk (evalf only for a function it does not know)
            value = complex_values([expr], {a: float(v) for a, v in self._rule.items()})[0]
        except (TypeError, ValueError):
            value = None
        if value is None or value.imag != 0:
            got = expr.xreplace(self._rule)
            raise ArgumentError(
                f"`values`: could not evaluate {expr} at the generic configuration "
                f"(got {got}).")
        return value.real


def _matrix(rows, symbols, numbers):
    A = np.zeros((len(rows), len(symbols)))
    for i, e in enumerate(rows):
        e = sp.expand(e)
        for j, s in enumerate(symbols):
            c = e.coeff(s)
            if c != 0:
                A[i, j] = numbers(c)
    return A


# numeric_rank: the one rank rule (rigidmech._core.rules), of the mobility analysis and of
# every decision on the rank of a constraint Jacobian


def analyse(mechanism, plane=None, values=None, *, seed: int = 0) -> Mobility:
    """The degree of mobility and of hyperstaticity of ``mechanism`` (see the module notes
    for the method).

    Parameters
    ----------
    mechanism : Mechanism
    plane : Vector, optional
        The normal of the plane of a planar problem (``R0.k``); None (default) for 3D.
    values : dict, optional
        Values of parameters of situation or constants (by symbol or name) for the
        configuration; the others are random numbers (generic configuration).
    seed : int
        Seed of the random configuration.

    Returns
    -------
    Mobility

    Examples
    --------
    Two pivots carry a shaft: hyperstatic of degree 5 in space.

    >>> import rigidmech as rm
    >>> from rigidmech.systems import Mechanism
    >>> R0 = rm.Frame("R0"); th = rm.coordinates("theta")
    >>> shaft = rm.Body("shaft", frame=R0.rotated("R1", about=R0.k, angle=th))
    >>> g = (Mechanism(R0)
    ...      .with_connection(R0, shaft, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    ...      .with_connection(R0, shaft, rm.joints.Pivot(at=R0.point("B", 0, 0, 1),
    ...                                                  axis=R0.k)))
    >>> r = analyse(g)
    >>> r.mobility, r.hyperstaticity
    (1, 5)
    """
    R0 = mechanism.reference
    O = R0.origin
    planar = plane is not None
    basis = _plane_basis(plane, R0) if planar else R0
    numbers = GenericValues(values, seed)
    links = mechanism.links
    # -- kinematics: one block of columns per link --------------------------------------
    motions, kin_cols, n_c = {}, [], 0
    for link in links:
        V, free = link.connection.allowed_motion(f"m{link.label}")
        rows, _ = _components(V, O, basis, planar)
        motions[id(link)] = rows
        kin_cols.extend(free)
        n_c += numeric_rank(_matrix(rows, list(free), numbers))
    loops = mechanism.loops()
    closure = []
    for loop in loops:
        total = None
        for link, sign in loop:
            rows = [sign * r for r in motions[id(link)]]
            total = rows if total is None else [a + b for a, b in zip(total, rows,
                                                                      strict=True)]
        closure.extend(total)
    r_c = numeric_rank(_matrix(closure, kin_cols, numbers))
    # groups of bodies not connected to the ground float freely
    _, parent = mechanism._structure()
    floating = 0
    for b in mechanism.bodies:
        if parent.get(id(b)) is None:
            floating += 1
    m = n_c - r_c + floating * (3 if planar else 6)
    # -- statics: one block of six (three) equations per body ---------------------------
    torsors, unknowns, n_s = [], [], 0
    for link in links:
        T, unk = link.connection.action_torsor(link.label)
        _, rows = _components(T, O, basis, planar)
        rank = numeric_rank(_matrix(rows, list(unk), numbers))
        n_s += rank
        torsors.append((link, rows))
        unknowns.extend(unk)
    eq = []
    for body in mechanism.bodies:
        total = [sp.S.Zero] * 3 if planar else [sp.S.Zero] * 6
        for link, rows in torsors:
            if link.second is body:
                total = [a + r for a, r in zip(total, rows, strict=True)]
            elif link.first is body:
                total = [a - r for a, r in zip(total, rows, strict=True)]
        eq.extend(total)
    S = _matrix(eq, unknowns, numbers)
    r_s = numeric_rank(S)
    h = n_s - r_s
    undetermined = ()
    if h > 0 and S.size:
        _, sv, vt = np.linalg.svd(S)
        null = vt[r_s:]
        seen = np.abs(S).max(axis=0) > 0          # unknowns present in the problem
        weight = np.abs(null).max(axis=0) if len(null) else np.zeros(len(unknowns))
        undetermined = tuple(u for u, w, s in zip(unknowns, weight, seen, strict=True)
                             if s and w > 1e-9)
    return Mobility(mobility=int(m), hyperstaticity=int(h), loops=len(loops),
                    kinematic_unknowns=int(n_c), static_unknowns=int(n_s),
                    bodies=len(mechanism.bodies), planar=planar, undetermined=undetermined,
                    statics_rank=r_s, kinematics_rank=r_c)

