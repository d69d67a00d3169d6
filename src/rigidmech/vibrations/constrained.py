"""Linearisation of constrained equations of motion: closed loops and rolling (book, ch. 25.3,
25.4).

The equations :math:`M q'' = f + A^T \\lambda`, :math:`A q'' = b` (velocity constraints
:math:`c = A q' + a = 0`) are linearised on the **independent speeds** u = q'_I (the reduced
form :math:`T^T (M q'' - f) = 0` of :mod:`rigidmech.dynamics.reduced`, T the partial
velocities), about a reference state ``(q*, u*)`` with ``u'* = 0``. Everything is taken
at the point, from the values and first derivatives of M, f, A, b and c there (one pass over
the expressions), never from the symbolic reduction (whose expressions can have removable 0/0 at
special states):

* the multipliers of the reference state, :math:`A^T \\lambda^* = M q''^* - f`, where
  :math:`q''^*` has :math:`q''_I = 0` and :math:`q''_D = A_D^{-1} b`; the derivative of T
  enters only through them, since :math:`\\delta T^T A^T \\lambda^* =
  -T^T \\delta A^T \\lambda^*` (from A T = 0);
* the dependent rates and accelerations follow the constraints to first order:
  :math:`A\\,\\delta q' = -c_q\\,\\delta q` and
  :math:`A\\,\\delta q'' = \\delta b - \\delta A\\, q''^*`;
* the dependent parameters of the **holonomic** constraints follow the independent ones,
  :math:`\\Phi_q\\,\\delta q = 0`; those of the **nonholonomic** ones (the position of a
  rolling disc's contact point) are not functions of the others: the equations must not depend
  on them at the reference state (they do not when the system is invariant under their change,
  as a disc on a horizontal plane under a translation) and they leave the linear system.

The result is :math:`M\\,\\delta q_I'' + C\\,\\delta q_I' + K\\,\\delta q_I = B\\,\\delta w`
on the independent parameters, M = T^T M T. The reference state must satisfy the constraints
(``Φ(q*) = 0``, and the rates given for dependent parameters must be the ones the constraints
give) and be an equilibrium or a steady motion: the reduced residual
:math:`T^T (M q''^* - f)` vanishes, and so does its rate along the motion (the coordinates
moving at ``q'*``).

Examples
--------
A thin disc rolling upright (θ = π/2) at the spin rate Ω: the gyroscopic terms in C, the
gravity in K (heading ψ, lean θ, spin φ; the contact point's x, y eliminated):

>>> import sympy as sp
>>> import rigidmech as rm
>>> from rigidmech.kinematics import ContactKinematics
>>> from rigidmech.vibrations import linearize
>>> x, y, psi, th, phi = rm.coordinates("x y psi theta phi")
>>> m, g, r = rm.constants("m g r", positive=True)
>>> R0 = rm.Frame("R0"); A = R0.rotated("A", about=R0.k, angle=psi)
>>> B = A.rotated("B", about=A.i, angle=th); I = R0.point("I", x, y, 0)
>>> G = I.moved("G", r * B.j); D = B.rotated("D", about=B.k, angle=phi, origin=G)
>>> disc = rm.Body("disc", frame=D, mass=m, centre=G,
...                inertia=rm.inertia.disk(m, r, axis=D.k, centre=G))
>>> s = rm.System(galilean=R0)
>>> s.connect(R0, disc, rm.actions.RollingContact(ContactKinematics(D, R0, at=I, normal=R0.k)))
>>> s.act(rm.gravity(-g * R0.k))
>>> Om = sp.Symbol("Omega")
>>> lin = linearize(s.equations_of_motion(), about={"theta": sp.pi / 2},
...                 velocities={"phi": Om})
>>> lin.coordinates
(psi(t), theta(t), phi(t))
>>> lin.C
Matrix([
[                0, -Omega*m*r**2/2, 0],
[3*Omega*m*r**2/2,               0, 0],
[                0,               0, 0]])
>>> lin.K
Matrix([
[0,      0, 0],
[0, -g*m*r, 0],
[0,      0, 0]])
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError
from .._core.rules import magnitude, numeric_rank, on_constraints, vanishes
from .._core.symbolic import is_identically_zero, xreplace_shared
from ..dynamics.reduced import plain_constraints, split_coordinates
from ._jet import values_and_jacobian

__all__ = ["linearize_constrained"]


def _rates(velocities, eqs, ind, norm):
    """The rates given, by index: a dict by coordinate, a full sequence of n values, or a
    sequence of the n - m independent rates."""
    n = len(eqs.coordinates)
    if velocities is None:
        return {}
    if isinstance(velocities, dict):
        return {norm.index(k): sp.sympify(v) for k, v in velocities.items()}
    values = list(velocities) if not isinstance(velocities, sp.Basic | int | float) \
        else [velocities]
    if len(values) == n:
        return {k: sp.sympify(v) for k, v in enumerate(values)}
    if len(values) == len(ind):
        return {j: sp.sympify(v) for j, v in zip(ind, values, strict=True)}
    raise ArgumentError(
        f"`velocities` must give {n} rates (or the {len(ind)} independent ones "
        f"{[eqs.names[j] for j in ind]}, or a dict by coordinate); got {len(values)}: "
        f"{velocities!r}.")


def _holonomic_split(phi_q, dep):
    """Dependent parameters that the holonomic rows fix: p columns of Φ_q (n columns) among
    ``dep`` with an invertible block at the point (greedy, in order)."""
    p = phi_q.shape[0]
    if p == 0:
        return []
    symbols = sorted(phi_q.free_symbols, key=str)
    rng = np.random.default_rng(7)
    sub = {s: sp.Float(v) for s, v in zip(symbols, rng.uniform(0.3, 1.3, len(symbols)),
                                          strict=True)}
    num = np.array(phi_q.xreplace(sub).evalf().tolist(), dtype=complex).real
    chosen = []
    # the one rank rule (rigidmech._core.rules): relative, so that the decision does not
    # depend on the unit of length
    for j in dep:
        if numeric_rank(num[:, chosen + [j]]) == len(chosen) + 1:
            chosen.append(j)
        if len(chosen) == p:
            return chosen
    raise ArgumentError(
        "the holonomic constraints cannot be solved for dependent parameters at the "
        "reference state (their Jacobian is rank deficient there): a locked or singular "
        "configuration of the loop.")


def _invertible(X):
    if all(sp.sympify(x).is_number for x in X):
        Xn = np.array(X.evalf().tolist(), dtype=complex)
        return numeric_rank(Xn) == min(Xn.shape)   # the one rank rule
    return not is_identically_zero(X.det())


class _Point:
    """Values and first derivatives, at the reference state, of the pieces of the
    multiplier form: M, f, A, b, c = A q' + a and the holonomic Φ."""

    def __init__(self, eqs, point, variables, phi):
        _, _, _, _, M, f = eqs._symbolic()
        A, b, vel = plain_constraints(eqs)
        self.n, self.m = A.shape[1], A.shape[0]
        n, m = self.n, self.m
        blocks = [list(M), list(f), list(A), list(b), list(vel), list(phi)]
        flat = [e for blk in blocks for e in blk]
        vals, jac = values_and_jacobian(flat, point, variables)
        out, k = [], 0
        for blk in blocks:
            out.append((vals[k:k + len(blk)], jac[k:k + len(blk)]))
            k += len(blk)
        (self.M, self.dM), (self.f, self.df), (self.A, self.dA) = out[:3]
        (self.b, self.db), (self.c, self.dc), (self.phi, self.dphi) = out[3:]
        self.M = sp.Matrix(n, n, self.M)
        self.A = sp.Matrix(m, n, self.A)

    def grad(self, entries, weights, columns):
        """sum_j weights[j] * d entries[j] / d variables[columns], a row."""
        return [sp.Add(*[w * entries[j][c] for j, w in enumerate(weights) if w != 0])
                for c in columns]


def _reference(eqs, norm, about, velocities, values_of, point, ind, dep):
    """q*, the rates q'* (the dependent ones from the constraints) and the rates given."""
    q_s, u_s, _, _, _, _ = eqs._symbolic()
    A, _, vel = plain_constraints(eqs)
    q_star = values_of(about, norm, "about")
    given = _rates(velocities, eqs, ind, norm)
    at = point | dict(zip(q_s, q_star, strict=True))
    a_vec = vel.xreplace({u: 0 for u in u_s})
    vals, _ = values_and_jacobian(list(A) + list(a_vec), at, [])
    n, m = len(q_s), A.shape[0]
    A0 = sp.Matrix(m, n, vals[:m * n])
    a0 = sp.Matrix(vals[m * n:])
    if not _invertible(A0[:, dep]):
        raise ArgumentError(
            f"the constraints cannot be solved for the rates of "
            f"{[eqs.names[j] for j in dep]} at the reference state (their Jacobian block is "
            f"singular there): choose other `independent` coordinates.")
    vI = sp.Matrix([given.get(j, sp.S.Zero) for j in ind])
    vD = A0[:, dep].LUsolve(-(A0[:, ind] * vI + a0))
    rates = [None] * n
    for r, j in enumerate(ind):
        rates[j] = vI[r]
    for r, j in enumerate(dep):
        rates[j] = vD[r]
    return q_star, rates, given, at | dict(zip(u_s, rates, strict=True))


def _holds(value, scale, tol):
    """A residual on its constraint: by the rule on the constraints (at most ON_CONSTRAINTS
    of the magnitude of its terms, ``scale``) for numbers, identically otherwise."""
    value, scale = sp.sympify(value), sp.sympify(scale)
    if value.is_number and scale.is_number:
        return bool(on_constraints([abs(complex(value))], [abs(complex(scale))])[0])
    return vanishes(value, tol)


def _check_constraints(eqs, P, at, rates, given, tol, phi_rows, ind, phi):
    names = eqs.names
    q_s = eqs._symbolic()[0]
    about = {names[j]: at[q] for j, q in enumerate(q_s)}
    labels = eqs.constraints.labels
    scales = [magnitude(e).xreplace(at) for e in phi]   # the terms of each Φ at q*
    bad = [(labels[k], v) for k, v, s in zip(phi_rows, P.phi, scales, strict=True)
           if not _holds(v, s, tol)]
    if bad:
        raise ArgumentError(
            f"`about` violates the constraints: the residual Φ(q*) = "
            f"{', '.join(f'{lab}: {v}' for lab, v in bad)} is not 0 at q* = {about}. Give "
            "a configuration on the loop (solve its closure for the dependent parameters).")
    wrong = [f"{names[j]}' = {v} (the constraints give {rates[j]})"
             for j, v in given.items()
             if not _holds(sp.sympify(v) - rates[j], abs(sp.sympify(v)) + abs(rates[j]), tol)]
    if wrong:
        v = sp.Matrix([given.get(j, rates[j]) for j in range(len(rates))])
        res = list(P.A * (v - sp.Matrix(rates)))
        raise ArgumentError(
            f"`velocities` violate the constraints: residual A q'* + a = {res} "
            f"({'; '.join(wrong)}) at q* = {about}. Give only the independent rates "
            f"{[names[j] for j in ind]}: the others follow.")
    return about


def linearize_constrained(eqs, about, velocities, w, w_star, extra, *, check, tol,
                          independent, values_of, normalise):
    """Linearise constrained equations (see the module); arguments as
    :func:`rigidmech.vibrations.linearize`. Returns (independent coordinates, M, C, K, B,
    q* by name, q'* by name)."""
    norm = normalise(eqs)
    q_s, u_s, _, rule, _, _ = eqs._symbolic()
    A = plain_constraints(eqs)[0]
    ind, dep = split_coordinates(eqs, independent, A)
    n, m = A.shape[1], A.shape[0]
    k = n - m
    base = dict(zip(w, w_star, strict=True)) | extra
    q_star, rates, given, at = _reference(eqs, norm, about, velocities, values_of, base,
                                          ind, dep)
    c = eqs.constraints
    phi_rows = [r for r, p in enumerate(c.position) if p is not None]
    phi = xreplace_shared([c.position[r] for r in phi_rows], rule, {})
    nq, nu = list(range(n)), list(range(n, 2 * n))
    nw = list(range(2 * n, 2 * n + len(w)))
    P = _Point(eqs, at, list(q_s) + list(u_s) + list(w), phi)
    names = eqs.names
    about_named = dict(zip(names, q_star, strict=True))
    vel_named = dict(zip(names, rates, strict=True))
    if check:
        _check_constraints(eqs, P, at, rates, given, tol, phi_rows, ind, phi)
    AD = P.A[:, dep]

    def dep_solve(X):
        """E A_D^-1 X: the rows of the dependent parameters."""
        Y = AD.LUsolve(sp.Matrix(X))
        out = sp.zeros(n, Y.shape[1])
        for r, j in enumerate(dep):
            out[j, :] = Y[r, :]
        return out

    T = sp.zeros(n, k)
    for r, j in enumerate(ind):
        T[j, r] = 1
    TD = AD.LUsolve(-P.A[:, ind])
    for r, j in enumerate(dep):
        T[j, :] = TD[r, :]
    acc = dep_solve(sp.Matrix(P.b))                       # q''* (u'* = 0)
    R0 = P.M * acc - sp.Matrix(P.f)                       # = A^T lambda*
    lam = AD.T.LUsolve(sp.Matrix([R0[j] for j in dep]))
    rows_M = [[P.dM[i * n + j] for j in range(n)] for i in range(n)]
    rows_A = [[P.dA[r * n + i] for r in range(m)] for i in range(n)]   # A^T entries

    def R_d(cols):
        return sp.Matrix([[a - b - c for a, b, c in zip(
            P.grad(rows_M[i], list(acc), cols), [P.df[i][x] for x in cols],
            P.grad(rows_A[i], list(lam), cols), strict=True)] for i in range(n)])

    def g_d(cols):
        return sp.Matrix([[a - b for a, b in zip(
            P.grad([P.dA[r * n + j] for j in range(n)], list(acc), cols),
            [P.db[r][x] for x in cols], strict=True)] for r in range(m)])

    Rq, Rv, Rw = R_d(nq), R_d(nu), R_d(nw)
    gq, gv, gw = g_d(nq), g_d(nu), g_d(nw)
    cq = sp.Matrix([[P.dc[r][x] for x in nq] for r in range(m)])
    Vq = -dep_solve(cq)
    Mlin = T.T * P.M * T
    Clin = T.T * (Rv - P.M * dep_solve(gv)) * T
    Kfull = T.T * (Rq + Rv * Vq - P.M * dep_solve(gq + gv * Vq))
    Blin = -T.T * (Rw - P.M * dep_solve(gw)) if w else sp.zeros(k, 0)
    if check:
        from .linearize import _steady  # the one rule of both paths

        ok, moving, res, rate = _steady(list(T.T * R0), list(Kfull * sp.Matrix(rates)),
                                        rates, tol, Kfull.tolist(), q_star)
        if not ok:
            kind = "a steady motion" if moving else "an equilibrium"
            raise ArgumentError(
                f"`about` is not {kind} of the reduced equations (u'* = 0 needs f_r = 0 "
                f"and d f_r/dt = 0 along the motion): residual f_r(q*, u*) = "
                f"{[-x for x in res]}, its rate (df_r/dq) q'* = {[-x for x in rate]}, at "
                f"q* = {about_named}, q'* = {vel_named}.")
    K = _on_independent(eqs, Kfull, P, phi_rows, ind, dep, tol)
    independent = tuple(eqs.coordinates[j] for j in ind)
    return independent, Mlin, Clin, K, Blin, about_named, vel_named


def _simple(x):
    x = sp.sympify(x)
    return x if x.is_number else sp.simplify(x)


def _on_independent(eqs, Kfull, P, phi_rows, ind, dep, tol):
    """K on the independent parameters: the holonomic dependent ones follow them (δq_H =
    G δq_I), the nonholonomic dependent ones must not enter."""
    n = len(eqs.coordinates)
    k = Kfull.shape[0]
    phi_q = sp.Matrix([[P.dphi[r][j] for j in range(n)] for r in range(len(phi_rows))]) \
        if phi_rows else sp.zeros(0, n)
    hol = _holonomic_split(phi_q, dep)
    rest = [j for j in range(n) if j not in hol]
    if hol:
        G = -phi_q[:, hol].LUsolve(phi_q[:, rest])
        Kq = Kfull[:, rest] + Kfull[:, hol] * G
    else:
        Kq = Kfull[:, rest]
    names = eqs.names
    for col, j in enumerate(rest):
        if j not in ind and not all(vanishes(_simple(Kq[i, col]), tol) for i in range(k)):
            raise ArgumentError(
                f"the reduced equations depend on {names[j]} at the reference state, a "
                f"parameter whose rate is fixed by a nonholonomic constraint: it cannot be "
                f"left out of the linear system on the independent parameters "
                f"{[names[i] for i in ind]}. Linearise about a state where they are "
                "invariant under its change, or choose other `independent` ones.")
    return Kq[:, [rest.index(j) for j in ind]]
